/* object_bound: the ball that holds each primitive (every point of it inside, the farthest on its
 * surface) and a flat primitive's plane, against points sampled on the primitives themselves. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "scene/object_bound.h"

/* The largest distance of the points from the bound's centre, and of the points from its plane,
 * against the radius: every point inside (to roundings) and the farthest on the sphere. */
static void check_holds(const struct object_bound *b, const vec3d *points, int n)
{
    double farthest = 0.0, off_plane = 0.0;
    for (int i = 0; i < n; i++) {
        farthest = fmax(farthest, v3_len(v3_sub(points[i], b->centre)));
        off_plane = fmax(off_plane, fabs(v3_dot(b->normal, v3_sub(points[i], b->centre))));
    }
    assert_true(farthest <= b->radius * (1.0 + 1e-12));
    assert_true(farthest >= b->radius * (1.0 - 1e-12));
    if (b->flat) {
        assert_true(fabs(v3_len(b->normal) - 1.0) < 1e-12);
        assert_true(off_plane <= 1e-12 * b->radius);
    }
}

static void test_rect_corners(void **state)
{
    (void)state;
    struct object o;
    memset(&o, 0, sizeof o);
    o.type = PRIM_RECT;
    o.center = v3(1.0, -2.0, 0.5);
    o.axis_u = v3(3.0, 0.0, 0.0);
    o.axis_v = v3(0.0, 1.0, -1.0);
    struct object_bound b;
    object_bound(&o, &b);
    vec3d corners[4];
    for (int k = 0; k < 4; k++)
        corners[k] = v3_add(o.center, v3_add(v3_scale(o.axis_u, k & 1 ? 1.0 : -1.0),
                                              v3_scale(o.axis_v, k & 2 ? 1.0 : -1.0)));
    assert_true(b.flat);
    check_holds(&b, corners, 4);
    /* axes a little off orthogonal (within what validation allows): both half-diagonals counted */
    o.axis_v = v3(1e-4, 1.0, -1.0);
    object_bound(&o, &b);
    for (int k = 0; k < 4; k++)
        corners[k] = v3_add(o.center, v3_add(v3_scale(o.axis_u, k & 1 ? 1.0 : -1.0),
                                              v3_scale(o.axis_v, k & 2 ? 1.0 : -1.0)));
    check_holds(&b, corners, 4);
}

static void test_triangle_and_round_ones(void **state)
{
    (void)state;
    struct object o;
    struct object_bound b;
    memset(&o, 0, sizeof o);
    o.type = PRIM_TRIANGLE;
    o.vertex[0] = v3(0.0, 0.0, 0.0);
    o.vertex[1] = v3(4.0, 0.0, 0.0);
    o.vertex[2] = v3(0.0, 1.0, 2.0);
    object_bound(&o, &b);
    assert_true(b.flat);
    check_holds(&b, o.vertex, 3);
    assert_true(v3_len(v3_sub(b.centre, v3(4.0 / 3.0, 1.0 / 3.0, 2.0 / 3.0))) < 1e-12);
    /* a degenerate triangle has no plane: normal 0, not NaN */
    o.vertex[2] = v3(8.0, 0.0, 0.0);
    object_bound(&o, &b);
    assert_true(v3_len(b.normal) == 0.0);
    assert_true(b.radius > 0.0);
    memset(&o, 0, sizeof o);
    o.type = PRIM_SPHERE;
    o.center = v3(1.0, 2.0, 3.0);
    o.radius = 0.5;
    object_bound(&o, &b);
    assert_false(b.flat);
    assert_true(b.radius == 0.5 && v3_len(b.normal) == 0.0);
    o.type = PRIM_DISK;
    o.normal = v3(0.0, 2.0, 0.0);
    o.radius = 3.0;
    object_bound(&o, &b);
    assert_true(b.flat && b.radius == 3.0);
    assert_true(fabs(b.normal.y - 1.0) < 1e-15);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rect_corners),
        cmocka_unit_test(test_triangle_and_round_ones),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
