/* The CPU reference locates crossings on the curve, not on its steps: an object that a single
 * adaptive step jumps over is still hit, the hit lies on the surface, and the hit does not move
 * when the tolerance (and with it every step size) changes. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "results/dump.h"
#include "ref/reference.h"
#include "scene/scene.h"
#include "scene/scene_keys.h"

/* A weak attractive 1/r potential around the origin: rays are gently curved, so Dormand-Prince
 * takes steps several units long, far longer than the small objects placed on their way. */
static void weak_field_scene(struct scene *s)
{
    scene_defaults(s);
    s->model.type = MODEL_POTENTIAL;
    s->model.profile = PROFILE_YUKAWA;
    s->model.zeta = -0.02;
    s->model.mu = 0.0;
    s->model.center = v3(0.0, -3.0, 0.0);
    s->render.bound_radius = 100.0;
    s->render.segments = 1000;
}

static void add_sphere(struct scene *s, vec3d c, double r)
{
    struct object *o = &s->objects[s->n_objects++];
    scene_object_defaults(o, "sphere");
    o->type = PRIM_SPHERE;
    o->center = c;
    o->radius = r;
}

static void add_triangle(struct scene *s, vec3d a, vec3d b, vec3d c)
{
    struct object *o = &s->objects[s->n_objects++];
    scene_object_defaults(o, "triangle");
    o->type = PRIM_TRIANGLE;
    o->vertex[0] = a;
    o->vertex[1] = b;
    o->vertex[2] = c;
}

static struct ref_ray trace(const struct scene *s, double rtol, vec3d x0, vec3d dir)
{
    struct ref_options o;
    ref_options_default(&o, s);
    o.atol *= rtol / o.rtol;
    o.rtol = rtol;
    struct ref_ray ray;
    ref_trace(s, &o, x0, dir, &ray, 0.0, NULL, NULL);
    return ray;
}

/* Mean step length of a ray: what a step-based intersection would see as one segment. */
static double mean_step(const struct ref_ray *r)
{
    return r->lambda / (double)r->steps;
}

static void test_small_sphere_inside_one_step(void **state)
{
    (void)state;
    static struct scene s;
    weak_field_scene(&s);
    /* first, without the object: how long are the steps along this ray? */
    vec3d x0 = v3(0.0, 0.0, 40.0), dir = v3(0.0, 0.0, -1.0);
    struct ref_ray free_ray = trace(&s, 1e-8, x0, dir);
    assert_int_equal(free_ray.outcome, DUMP_SKY);
    double step = mean_step(&free_ray);
    print_message("mean step along the free ray: %.3g units (rtol 1e-8)\n", step);
    /* a sphere ten times smaller than a step, right on the ray's path: both ends of the step that
     * carries it lie outside, so only the search along the curve can find it */
    double radius = step / 10.0;
    assert_true(radius > 0.0);
    add_sphere(&s, v3(0.0, 0.0, 5.0), radius);
    struct ref_ray ray = trace(&s, 1e-8, x0, dir);
    assert_int_equal(ray.outcome, 0);
    /* the hit is on the surface to the dense output's accuracy: 1e-6 of the radius is ~1e3 times
     * the tolerance, and far below anything a picture can show */
    double off = fabs(v3_len(v3_sub(ray.hit, s.objects[0].center)) - radius);
    print_message("sphere radius %.3g, hit off the surface by %.3g\n", radius, off);
    assert_true(off <= 1e-6 * radius);
}

static void test_triangle_crossing_on_its_plane(void **state)
{
    (void)state;
    static struct scene s;
    weak_field_scene(&s);
    /* a triangle whose plane the ray crosses once, somewhere inside a long step */
    vec3d x0 = v3(0.0, 0.0, 40.0), dir = v3(0.0, 0.0, -1.0);
    add_triangle(&s, v3(-1.0, -1.0, 0.0), v3(1.0, -1.0, 0.0), v3(0.0, 1.0, 0.0));
    struct ref_ray ray = trace(&s, 1e-8, x0, dir);
    assert_int_equal(ray.outcome, 0);
    /* on the plane z = 0 to double rounding of the bisection on the dense output */
    print_message("triangle hit at z = %.3g after %ld steps\n", ray.hit.z, ray.steps);
    assert_true(fabs(ray.hit.z) <= 1e-9);
}

static void test_hit_independent_of_tolerance(void **state)
{
    (void)state;
    static struct scene s;
    weak_field_scene(&s);
    add_sphere(&s, v3(0.5, 0.0, 0.0), 1.0);
    add_triangle(&s, v3(-5.0, -5.0, -3.0), v3(5.0, -5.0, -3.0), v3(0.0, 5.0, -3.0));
    vec3d x0 = v3(0.0, 0.0, 40.0);
    /* rays that hit the sphere, and rays that pass it and hit the triangle */
    const double aims[][2] = {{0.0, 0.0}, {0.01, 0.005}, {0.04, 0.0}, {-0.02, 0.03}};
    for (size_t k = 0; k < sizeof aims / sizeof aims[0]; k++) {
        vec3d dir = v3_normalize(v3(aims[k][0], aims[k][1], -1.0));
        struct ref_ray tight = trace(&s, 1e-12, x0, dir);
        struct ref_ray loose = trace(&s, 1e-6, x0, dir);
        assert_int_equal(tight.outcome, loose.outcome);
        assert_true(tight.outcome >= 0);
        double moved = v3_len(v3_sub(tight.hit, loose.hit));
        print_message("aim %zu: object %d, steps %ld (1e-12) vs %ld (1e-6), hit moved %.3g\n", k, tight.outcome,
                      tight.steps, loose.steps, moved);
        /* the steps differ by a large factor, the hit only by the integration error of the looser
         * tolerance: at most 1e-6 relative of a 40-unit position per step, over fewer than twenty
         * steps, gives 1e-3; the bound is ten times tighter because the errors of an error-controlled
         * pair do not all add up (measured: about 1e-8) */
        assert_true(tight.steps > 2 * loose.steps);
        assert_true(moved <= 1e-4);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_small_sphere_inside_one_step),
        cmocka_unit_test(test_triangle_crossing_on_its_plane),
        cmocka_unit_test(test_hit_independent_of_tolerance),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
