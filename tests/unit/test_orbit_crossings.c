/* Flat objects through the mass on exact orbits (render/orbit_crossings.c,
 * shaders_es/stage_orbit_crossings.glsl): each object met where the orbit crosses its plane, instead
 * of chord by chord. When the renderer takes it; the orbit table's longest orbit within the
 * shader's crossings; and the pictures against the double-precision CPU reference, at least as
 * close as the chord walk they replace, on hard views: a disk reaching into the horizon, three
 * planes at angles through the mass, a camera at 3.6 M whose rays wind about the photon sphere,
 * a disk seen edge on, an observer moving at 0.6 c. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "hard_cases.h"
#include "physics/orbit_table.h"
#include "render/stages.h"

/* shaders_es/stage_orbit_crossings.glsl's MAX_PLANE_CROSSINGS: the half-turns it looks at */
#define MAX_PLANE_CROSSINGS 16

/* M = 1 at the origin, bound 50 about it, camera at `camera` looking at the mass. */
static void crossing_hole(struct scene *s, vec3d camera, double fov, int width, int height)
{
    scene_defaults(s);
    snprintf(s->name, sizeof s->name, "orbit_crossings");
    s->model.type = MODEL_SCHWARZSCHILD;
    s->model.mass = 1.0;
    s->model.center = v3(0.0, 0.0, 0.0);
    s->render.bound_radius = 50.0;
    s->render.method = METHOD_ORBIT_TABLE;
    s->render.step_control = STEP_FIXED;
    /* the reference's budget (lambda = step x steps x segments) lets every ray end */
    s->render.step_size = 0.1;
    s->render.steps_per_segment = 1000;
    s->render.segments = 100;
    s->render.width = width;
    s->render.height = height;
    s->camera.position = camera;
    s->camera.look_at = v3(0.0, 0.0, 0.0);
    s->camera.up = v3(0.0, 1.0, 0.0);
    s->camera.fov_deg = fov;
}

static struct object *crossing_disk(struct scene *s, vec3d normal, double inner, double outer)
{
    struct object *disk = hc_add_object(s, PRIM_DISK, "disk");
    disk->center = v3(0.0, 0.0, 0.0);
    disk->normal = normal;
    disk->inner_radius = inner;
    disk->radius = outer;
    disk->material.checker = 10;
    return disk;
}

/* A disk tilted through the mass and reaching into the horizon, a wall across it and a sail in a
 * third plane: every crossing order, coplanar lines where two planes meet, rays that fall in. */
static void three_planes(struct scene *s)
{
    crossing_hole(s, v3(3.0, 4.0, 20.0), 40.0, 160, 120);
    crossing_disk(s, v3(0.2, 1.0, 0.1), 0.0, 12.0);
    struct object *wall = hc_add_object(s, PRIM_RECT, "wall");
    wall->center = v3(0.0, 0.0, 0.0);
    wall->axis_u = v3(0.0, 8.0, 0.0);
    wall->axis_v = v3(0.0, 0.0, -8.0);
    wall->material.checker = 6;
    struct object *sail = hc_add_object(s, PRIM_TRIANGLE, "sail");
    sail->vertex[0] = v3(0.0, 0.0, 0.0);
    sail->vertex[1] = v3(10.0, 10.0, 0.0);
    sail->vertex[2] = v3(-10.0, 6.0, 0.0);
    hc_validate(s);
}

static int takes_crossings(const struct scene *s)
{
    struct error e;
    struct renderer *r = renderer_create(hc_context(), s, &e);
    if (!r)
        fail_msg("renderer: %s", e.message);
    int crossings = orbit_crossings_apply(r);
    renderer_destroy(r);
    return crossings;
}

/* ---- 1. when the renderer meets objects at their planes' crossings ---- */

static void test_when_taken(void **state)
{
    (void)state;
    static struct scene s;
    three_planes(&s);
    assert_true(takes_crossings(&s));
    /* a sphere, even about the mass, is not flat: the chord walk */
    three_planes(&s);
    struct object *ball = hc_add_object(&s, PRIM_SPHERE, "ball");
    ball->center = v3(0.0, 0.0, 0.0);
    ball->radius = 3.0;
    assert_false(takes_crossings(&s));
    /* a plane that misses the mass by 1e-6 */
    three_planes(&s);
    s.objects[0].center = v3(0.0, 1e-6, 0.0);
    assert_false(takes_crossings(&s));
    /* the same plane, its disk's centre moved within it: still through the mass */
    three_planes(&s);
    s.objects[1].center = v3(0.0, 2.0, 3.0);
    assert_true(takes_crossings(&s));
    /* a bounding sphere not about the mass: an orbit could leave it before a crossing */
    three_planes(&s);
    s.render.bound_center = v3(0.0, 0.0, 1e-3);
    assert_false(takes_crossings(&s));
    /* an object reaching out of the bounding sphere */
    three_planes(&s);
    s.objects[0].radius = 60.0;
    assert_false(takes_crossings(&s));
    /* integrated rays never */
    three_planes(&s);
    s.render.method = METHOD_RK4;
    assert_false(takes_crossings(&s));
}

/* ---- 2. no orbit of the table winds past the shader's crossings ---- */

static void test_longest_orbit(void **state)
{
    (void)state;
    static const double observers[] = {2.01, 2.5, 3.0, 3.6, 10.0, 1e3, 1e4};
    double longest_half_turns = 0.0;
    for (size_t k = 0; k < sizeof observers / sizeof observers[0]; k++) {
        static struct scene s;
        crossing_hole(&s, v3(0.0, 0.0, observers[k]), 40.0, 16, 16);
        s.render.bound_radius = 2.0 * observers[k] + 10.0;
        crossing_disk(&s, v3(0.0, 1.0, 0.0), 3.0, 4.0);
        struct orbit_table_params p;
        orbit_table_params_for(&s, &p);
        struct orbit_table t;
        struct error e;
        if (orbit_table_build(&t, &p, &e) != 0)
            fail_msg("table: %s", e.message);
        for (int row = 0; row < t.height; row++) {
            double phi_end = t.phi_over_sin[row] * sin(t.psi[row]);
            longest_half_turns = fmax(longest_half_turns, phi_end / 3.14159265358979323846);
        }
        orbit_table_free(&t);
    }
    print_message("the longest orbit of the tables sweeps %.2f half-turns (the shader looks at %d)\n",
                  longest_half_turns, MAX_PLANE_CROSSINGS);
    /* the shader interpolates phi_end between rows (Catmull-Rom overshoots by a fraction of a row's
     * difference): a half-turn of room is far more than that */
    assert_true(longest_half_turns <= MAX_PLANE_CROSSINGS - 1);
}

/* ---- 3. against the reference, and against the chord walk ---- */

/* The scene drawn with crossings and with the chord walk (the bounding sphere moved off the mass by
 * 1e-9 of its radius: too little to move any ray, enough to refuse crossings), both against the
 * CPU reference. */
static void expect_no_worse_than_walk(const char *what, struct scene *s)
{
    assert_true(takes_crossings(s));
    struct cpu_image cpu;
    struct hc_gpu fast, walk;
    hc_render_both(s, s->render.width, s->render.height, &cpu, &fast);
    static struct scene walked;
    walked = *s;
    walked.render.bound_center = v3(0.0, 0.0, 1e-9 * s->render.bound_radius);
    assert_false(takes_crossings(&walked));
    hc_gpu_render(&walked, &walk);
    struct compare_result on_planes, on_chords;
    hc_compare(&fast.dump, &cpu.dump, &on_planes);
    hc_compare(&walk.dump, &cpu.dump, &on_chords);
    print_message("%-28s crossings: %ld differ, hit p99 %.2e max %.2e of size, sky p99 %.2e rad; "
                  "chord walk: %ld differ, hit p99 %.2e max %.2e\n", what, on_planes.outcomes.differ,
                  on_planes.hit_relative.p99, on_planes.hit_relative.max, on_planes.sky_angle.p99,
                  on_chords.outcomes.differ, on_chords.hit_relative.p99, on_chords.hit_relative.max);
    assert_int_equal(hc_gpu_nonfinite(&fast), 0);
    /* the orbit's own point at each crossing, where the walk took a chord's and found it again on
     * the orbit: no outcome may differ from the reference where the walk's do not, by more than
     * one pixel in 10^4 (an edge crossed within a float rounding of the orbit) */
    assert_true(on_planes.outcomes.differ <= on_chords.outcomes.differ + s->render.width * s->render.height / 10000);
    /* hits on the orbit to a float rounding of the table's point and the chord across it (about
     * 1e-6 of the size measured): the shipped scenes' [quality] hit bound, and never looser than
     * the walk's, beyond float noise */
    assert_true(on_planes.hit_relative.p99 <= 1e-4);
    assert_true(on_planes.hit_relative.p99 <= on_chords.hit_relative.p99 + 1e-6);
    /* the sky along the same table's direction at infinity as the walk's */
    assert_true(on_planes.sky_angle.count == 0 || on_planes.sky_angle.p99 <= 1e-5);
    cpu_image_free(&cpu);
    hc_gpu_free(&fast);
    hc_gpu_free(&walk);
}

static void test_three_planes(void **state)
{
    (void)state;
    static struct scene s;
    three_planes(&s);
    expect_no_worse_than_walk("three planes", &s);
}

static void test_winding_rays(void **state)
{
    (void)state;
    static struct scene s;
    /* at 3.6 M, just outside the photon sphere, a 90-degree view: rays that circle the hole
     * several times before they cross the disk or fall in */
    crossing_hole(&s, v3(0.0, 0.5, 3.6), 90.0, 160, 120);
    crossing_disk(&s, v3(0.0, 1.0, 0.0), 2.5, 8.0);
    hc_validate(&s);
    expect_no_worse_than_walk("camera at 3.6 M", &s);
}

static void test_edge_on(void **state)
{
    (void)state;
    static struct scene s;
    /* the camera in the disk's plane: the orbits that stay in it cross nothing */
    crossing_hole(&s, v3(0.0, 0.0, 25.0), 30.0, 160, 120);
    crossing_disk(&s, v3(0.0, 1.0, 0.0), 3.0, 14.0);
    hc_validate(&s);
    expect_no_worse_than_walk("edge on", &s);
}

static void test_moving_observer(void **state)
{
    (void)state;
    static struct scene s;
    crossing_hole(&s, v3(0.0, 3.0, 20.0), 50.0, 160, 120);
    s.observer.velocity = v3(0.0, 0.0, -0.6);
    crossing_disk(&s, v3(0.0, 1.0, 0.0), 4.0, 14.0);
    hc_validate(&s);
    expect_no_worse_than_walk("observer at 0.6 c", &s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_when_taken),
        cmocka_unit_test(test_longest_orbit),
        cmocka_unit_test(test_three_planes),
        cmocka_unit_test(test_winding_rays),
        cmocka_unit_test(test_edge_on),
        cmocka_unit_test(test_moving_observer),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
