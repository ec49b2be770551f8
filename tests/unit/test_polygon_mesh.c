/* The polygon method's meshes: every vertex on the primitive, with the normal and texture
 * coordinates the ray tracer computes at that point (src/ref/surface.c, the shader's twin), and
 * indices that stay in range; and on the GPU, the method's error against the traced image falls
 * as the square of the mesh's edge length, while it leaves scenes without moving objects alone. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include "hard_cases.h"
#include "ref/surface.h"
#include "render/polygon_mesh.h"

/* float vertices: 1e-6 of the object's size */
#define VERTEX_TOL 1e-5

static void check_mesh(const struct object *o, int n, int want_triangles)
{
    struct polygon_mesh m;
    assert_int_equal(polygon_mesh_build(o, n, &m), 0);
    assert_int_equal(m.n_indices, 3 * want_triangles);
    struct surface sf;
    surface_init(&sf, o);
    for (int i = 0; i < m.n_indices; i++)
        assert_true(m.indices[i] < m.n_vertices);
    for (int i = 0; i < m.n_vertices; i++) {
        const struct mesh_vertex *v = &m.vertices[i];
        vec3d p = v3(v->rest[0], v->rest[1], v->rest[2]);
        assert_true(fabs(surface_value(&sf, p)) <= VERTEX_TOL * (o->type == PRIM_SPHERE ? 2.0 * o->radius : 1.0));
        vec3d normal;
        double uv[2];
        surface_shading(&sf, p, &normal, uv);
        vec3d mn = v3(v->normal[0], v->normal[1], v->normal[2]);
        assert_true(v3_len(v3_sub(normal, mn)) <= 1e-5 || v3_len(v3_add(normal, mn)) <= 1e-5);
        /* the seam of a sphere or disk: u = 0 and u = 1 (or v) are the same meridian */
        for (int k = 0; k < 2; k++) {
            double d = fabs(uv[k] - v->uv[k]);
            int seam = (o->type == PRIM_SPHERE && k == 0) || (o->type == PRIM_DISK && k == 1);
            int pole = o->type == PRIM_SPHERE && k == 0 && (v->uv[1] < 1e-6 || v->uv[1] > 1.0 - 1e-6);
            /* a sphere's v is acos(n . pole) / pi: at the poles float vertices (6e-8) move it by up to
             * sqrt(2 * 6e-8) / pi = 1e-4 */
            double tol = o->type == PRIM_SPHERE && k == 1 ? 2e-4 : 1e-5;
            if (!(d <= tol || (seam && fabs(d - 1.0) <= tol) || pole))
                fail_msg("%s vertex %d: uv[%d] %g, the ray tracer's %g", o->name, i, k, v->uv[k], uv[k]);
        }
    }
    polygon_mesh_free(&m);
}

static void test_meshes_lie_on_their_primitives(void **state)
{
    (void)state;
    struct object o;
    scene_object_defaults(&o, "ball");
    o.center = v3(0.5, -1, 2);
    o.radius = 1.5;
    o.pole = v3(0.2, 1, 0.1);
    check_mesh(&o, 8, 2 * 8 * 2 * 8);
    scene_object_defaults(&o, "card");
    o.type = PRIM_RECT;
    o.center = v3(0, 1, 0);
    o.axis_u = v3(2, 0, 0);
    o.axis_v = v3(0, 0.5, 0.5);
    check_mesh(&o, 5, 2 * 25);
    scene_object_defaults(&o, "ring");
    o.type = PRIM_DISK;
    o.center = v3(1, 0, 0);
    o.normal = v3(0.3, 1, 0);
    o.radius = 3;
    o.inner_radius = 1;
    check_mesh(&o, 6, 2 * 6 * 2 * 6);
    scene_object_defaults(&o, "sail");
    o.type = PRIM_TRIANGLE;
    o.vertex[0] = v3(0, 0, 0), o.vertex[1] = v3(2, 0, 1), o.vertex[2] = v3(0, 3, 0);
    check_mesh(&o, 7, 7 * 7);
    /* the largest subdivision still fits 16-bit indices */
    scene_object_defaults(&o, "ball");
    struct polygon_mesh m;
    assert_int_equal(polygon_mesh_build(&o, SCENE_MAX_SUBDIVISION, &m), 0);
    assert_true(m.n_vertices <= 65536);
    polygon_mesh_free(&m);
}

/* The approaching cube drawn as polygons: its error against the traced reference shrinks about
 * 16-fold per 4-fold finer mesh (a straight chord of a hyperbola), and at 64 segments per edge
 * it is below 1e-3 of the face's size with at most 0.02% of pixels changing outcome. */
static void test_polygon_error_falls_with_the_mesh(void **state)
{
    (void)state;
    static const int subdivisions[] = {4, 16, 64};
    double p99[3];
    struct cpu_image cpu;
    static struct scene s;
    hc_load(&s, "cube_approach", 160, 120, NULL);
    hc_cpu_render(&s, &cpu);
    for (int k = 0; k < 3; k++) {
        char sub[64];
        snprintf(sub, sizeof sub, "render.polygon_subdivision=%d", subdivisions[k]);
        const char *const sets[] = {"render.moving_objects=polygons", sub, NULL};
        hc_load(&s, "cube_approach", 160, 120, sets);
        struct hc_gpu g;
        hc_gpu_render(&s, &g);
        struct compare_result r;
        hc_compare(&g.dump, &cpu.dump, &r);
        p99[k] = r.hit_relative.p99;
        print_message("polygons, %2d segments per edge: hit p99 %.2e of size, %.3f%% outcomes differ\n",
                      subdivisions[k], p99[k], 100.0 * r.outcome_fraction);
        if (k == 2) {
            assert_true(p99[k] <= 1e-3);
            assert_true(r.outcome_fraction <= 2e-4);
        }
        hc_gpu_free(&g);
    }
    assert_true(p99[0] > 8.0 * p99[1]);
    assert_true(p99[1] > 8.0 * p99[2]);
    cpu_image_free(&cpu);
}

/* Without moving objects the choice changes nothing: the same bits. */
static void test_polygons_leave_rest_alone(void **state)
{
    (void)state;
    static const char *const polygons[] = {"render.moving_objects=polygons", NULL};
    static struct scene a, b;
    hc_load(&a, "test", 48, 36, NULL);
    hc_load(&b, "test", 48, 36, polygons);
    struct hc_gpu ga, gb;
    hc_gpu_render(&a, &ga);
    hc_gpu_render(&b, &gb);
    assert_memory_equal(ga.res.rgba, gb.res.rgba, 4 * 48 * 36);
    assert_memory_equal(ga.res.hit, gb.res.hit, 4 * 48 * 36 * sizeof(float));
    hc_gpu_free(&ga);
    hc_gpu_free(&gb);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_meshes_lie_on_their_primitives),
        cmocka_unit_test(test_polygon_error_falls_with_the_mesh),
        cmocka_unit_test(test_polygons_leave_rest_alone),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
