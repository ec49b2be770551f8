/* Steps that grow away from the objects (render.far_step): the bounds they grow from hold every
 * object, whatever their number; the rays finish in fewer segments and hit what they hit with steps
 * of `step` (or step_max) throughout, at the same points; a far step within the near one changes no
 * bit; a ray's budget stays its path; and a far step across the scene is refused. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include "hard_cases.h"
#include "render/far_reach.h"

#define W 64
#define H 48
#define PI 3.14159265358979323846

/* The shader's far_reach (stage_integrate.glsl) in double: a lower bound of p's distance from
 * every object. */
static double reach_of(const float ball[][4], const float normal[][4], int n, vec3d p)
{
    double reach = 1e30;
    for (int k = 0; k < n; k++) {
        vec3d from = v3_sub(p, v3(ball[k][0], ball[k][1], ball[k][2]));
        double from_ball = v3_len(from) - ball[k][3];
        double from_plane = fabs(v3_dot(from, v3(normal[k][0], normal[k][1], normal[k][2])));
        reach = fmin(reach, fmax(from_ball, from_plane));
    }
    return reach;
}

/* Points of object o: a sphere's surface, a flat object's area (a grid over it). */
static int object_points(const struct object *o, vec3d *out, int most)
{
    int n = 0;
    for (int i = 0; i <= 8; i++)
        for (int j = 0; j <= 8 && n < most; j++) {
            double a = i / 8.0, b = j / 8.0;
            switch (o->type) {
            case PRIM_SPHERE: {
                double theta = PI * a, phi = 2.0 * PI * b;
                vec3d d = v3(sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi));
                out[n++] = v3_axpy(o->radius, d, o->center);
                break;
            }
            case PRIM_RECT:
                out[n++] = v3_add(o->center, v3_add(v3_scale(o->axis_u, 2.0 * a - 1.0), v3_scale(o->axis_v, 2.0 * b - 1.0)));
                break;
            case PRIM_TRIANGLE:
                if (a + b <= 1.0)
                    out[n++] = v3_add(o->vertex[0], v3_add(v3_scale(v3_sub(o->vertex[1], o->vertex[0]), a),
                                                           v3_scale(v3_sub(o->vertex[2], o->vertex[0]), b)));
                break;
            default: {
                /* a disk: rings about its centre in its plane */
                vec3d u = v3_normalize(v3_cross(o->normal, fabs(o->normal.x) < 0.9 ? v3(1, 0, 0) : v3(0, 1, 0)));
                vec3d v = v3_cross(o->normal, u);
                double phi = 2.0 * PI * b;
                out[n++] = v3_add(o->center, v3_scale(v3_add(v3_scale(u, cos(phi)), v3_scale(v, sin(phi))), a * o->radius));
                break;
            }
            }
        }
    return n;
}

/* The packed bounds against points of every object, seen from points all over the scene: the
 * reach is never more than a point's distance from any object (to float roundings of the bounds),
 * with each object alone, with every count of bounds from 1 to FAR_REACH_MAX (objects merged), for
 * the committed scenes with objects and one of 40 objects of every kind. */
static void test_reach_is_a_lower_bound(void **state)
{
    (void)state;
    static const char *const names[] = {"lorenz", "demo", "test", "potential"};
    static struct scene many;
    fixture_load_scene(&many, "test", W, H, NULL);
    many.n_objects = 0;
    for (int i = 0; i < 40; i++) {
        enum primitive_type types[] = {PRIM_SPHERE, PRIM_RECT, PRIM_TRIANGLE, PRIM_DISK};
        struct object *o = hc_add_object(&many, types[i % 4], "o");
        o->center = v3(7.0 * sin(1.3 * i), 3.0 * cos(0.7 * i), 5.0 * sin(0.4 * i + 1.0));
        o->radius = 0.2 + 0.1 * (i % 5);
        o->normal = v3_normalize(v3(sin(i), 1.0, cos(2.0 * i)));
        o->axis_u = v3(0.5 + 0.1 * (i % 3), 0.0, 0.0);
        o->axis_v = v3(0.0, 0.3, 0.4);
        for (int v = 0; v < 3; v++)
            o->vertex[v] = v3_add(o->center, v3(0.3 * (v == 0) - 0.2 * (v == 2), 0.4 * (v == 1), 0.1 * v));
    }
    for (size_t k = 0; k <= sizeof names / sizeof names[0]; k++) {
        static struct scene s;
        if (k < sizeof names / sizeof names[0])
            fixture_load_scene(&s, names[k], W, H, NULL);
        else
            s = many;
        for (int most = 1; most <= FAR_REACH_MAX; most++) {
            float ball[FAR_REACH_MAX][4], normal[FAR_REACH_MAX][4];
            int n = far_reach_pack(&s, most, ball, normal);
            assert_int_equal(n, s.n_objects < most ? s.n_objects : most);
            long checked = 0;
            double worst = -1e30;
            for (int i = 0; i < s.n_objects; i++) {
                vec3d points[81];
                int m = object_points(&s.objects[i], points, 81);
                for (int a = 0; a < 216; a++) {
                    vec3d p = v3(-15.0 + 6.0 * (a % 6), -15.0 + 6.0 * (a / 6 % 6), -15.0 + 6.0 * (a / 36));
                    double reach = reach_of(ball, normal, n, p);
                    for (int j = 0; j < m; j++) {
                        double d = v3_len(v3_sub(p, points[j]));
                        /* float bounds: a few roundings of coordinates of 20 */
                        worst = fmax(worst, reach - d);
                        assert_true(reach <= d + 1e-5);
                        checked++;
                    }
                }
            }
            print_message("%s, %d bounds of %d objects: %ld distances, reach at most %.2g beyond\n",
                          k < sizeof names / sizeof names[0] ? names[k] : "40 objects", n, s.n_objects, checked, worst);
        }
    }
}

/* A flat object kept alone keeps its plane (its unit normal), and a sphere has none. */
static void test_flat_bounds_keep_their_plane(void **state)
{
    (void)state;
    static struct scene s;
    fixture_load_scene(&s, "lorenz", W, H, NULL);
    float ball[FAR_REACH_MAX][4], normal[FAR_REACH_MAX][4];
    int n = far_reach_pack(&s, s.n_objects, ball, normal);
    assert_int_equal(n, s.n_objects < FAR_REACH_MAX ? s.n_objects : FAR_REACH_MAX);
    int planes = 0;
    for (int k = 0; k < n; k++) {
        double len = v3_len(v3(normal[k][0], normal[k][1], normal[k][2]));
        assert_true(len == 0.0 || fabs(len - 1.0) < 1e-6);
        planes += len > 0.0;
    }
    /* the floor (a rectangle, the largest object) is never merged: its plane stays */
    assert_true(planes >= 1);
    static struct scene none;
    fixture_load_scene(&none, "lorenz", W, H, NULL);
    none.n_objects = 0;
    assert_int_equal(far_reach_pack(&none, FAR_REACH_MAX, ball, normal), 0);
}

/* Outcomes and hits of a against b: differing outcomes at most `differ` of the pixels; hits on the
 * same object at p99 at most `hit` of its size apart, and at most `hit_max` (a grazing ray's hit
 * moves along the surface by far more than the ray moves). */
static void assert_close_rays(const struct hc_gpu *a, const struct hc_gpu *b, double differ, double hit,
                              double hit_max, const char *what)
{
    struct compare_result c;
    struct error e;
    if (compare_dumps(&a->dump, &b->dump, &c, &e) != 0)
        fail_msg("%s: %s", what, e.message);
    print_message("%s: %ld of %ld outcomes differ, hits p99 %.3g max %.3g of size, exits p99 %.3g rad\n", what,
                  c.outcomes.differ, c.pixels, c.hit_relative.p99, c.hit_relative.max, c.sky_angle.p99);
    assert_true(c.outcome_fraction <= differ);
    assert_true(c.hit_relative.count > 0);
    assert_true(c.hit_relative.p99 <= hit);
    assert_true(c.hit_relative.max <= hit_max);
}

/* lorenz with far steps against steps of 0.5 throughout: the same objects hit at the same points
 * (the steps near an object are the same), the sky in nearly the same directions, and every ray
 * done in fewer segments, so the multipass scheme's early stop ends the frame in fewer passes. Also
 * at the knobs' far end (rho 50, strength 0.01), and with the kiosk preview's longer steps. */
static void test_far_steps_finish_sooner(void **state)
{
    (void)state;
    static const struct {
        const char *sets[4];
    } cases[] = {
        {{NULL}},
        {{"model.rho=50", "model.strength=0.01", NULL}},
        {{"render.step=1", "render.max_path=90", NULL}},
        /* adaptive steps, bounded by step_max near the objects: far steps raise that bound */
        {{"render.step_control=doubling", "render.step_max=0.5", "render.tolerance=1e-3", NULL}},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        static struct scene s;
        struct hc_gpu near, far;
        hc_load(&s, "lorenz", W, H, cases[k].sets);
        s.render.pipeline = PIPELINE_MULTIPASS;
        double far_step = s.render.far_step;
        assert_true(far_step > s.render.step_size);
        hc_gpu_render(&s, &far);
        s.render.far_step = 0.0;
        hc_gpu_render(&s, &near);
        char what[160];
        snprintf(what, sizeof what, "lorenz %s%s: far steps %g, %ld passes against %ld", cases[k].sets[0] ? cases[k].sets[0] : "",
                 cases[k].sets[0] && cases[k].sets[1] ? " ..." : "", far_step, far.res.passes, near.res.passes);
        /* lorenz's [quality] asks hits within 1% of an object's size at p99 of the reference: far
         * steps against steps of `step` throughout stay within that bound too (measured 0.1%, 0.5%
         * at the knobs' far end), and their largest move (1.6%, on a grazing ray) within twice the
         * largest of steps of 0.5 against the reference (2.4%, `bentray error`) */
        assert_close_rays(&far, &near, 0.002, s.quality.hit_p99, 0.05, what);
        assert_true(far.res.passes < near.res.passes);
        hc_gpu_free(&near);
        hc_gpu_free(&far);
    }
}

/* A far step no longer than the step near the objects (fixed: `step`; adaptive: step_max) grows
 * nothing: the rays of far_step = 0, bit for bit. */
static void test_far_step_within_the_near_step(void **state)
{
    (void)state;
    static const struct {
        const char *sets[4];
    } cases[] = {
        {{"render.far_step=0.5", NULL}},
        {{"render.far_step=0.3", NULL}},
        {{"render.step_control=doubling", "render.step_max=2", "render.max_path=20", NULL}},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        static struct scene s;
        struct hc_gpu a, b;
        hc_load(&s, "lorenz", W, H, cases[k].sets);
        assert_true(s.render.far_step > 0.0);
        assert_false(scene_far_steps(&s));
        hc_gpu_render(&s, &a);
        s.render.far_step = 0.0;
        hc_gpu_render(&s, &b);
        assert_int_equal(memcmp(a.res.image, b.res.image, sizeof(float) * 4 * W * H), 0);
        assert_int_equal(memcmp(a.res.position, b.res.position, sizeof(float) * 4 * W * H), 0);
        assert_int_equal(memcmp(a.res.velocity, b.res.velocity, sizeof(float) * 4 * W * H), 0);
        hc_gpu_free(&a);
        hc_gpu_free(&b);
    }
}

/* A path budget that most rays spend: with far steps the state carries the path, and no ray goes
 * beyond the budget (the last step is cut to it), as adaptive steps; the unfinished rays stand where
 * those of steps of 0.5 throughout stand, to the error of the longer steps. */
static void test_far_steps_keep_the_path_budget(void **state)
{
    (void)state;
    static struct scene s;
    static const char *const sets[] = {"render.max_path=6", NULL};
    hc_load(&s, "lorenz", W, H, sets);
    double budget = render_path_budget(&s.render);
    struct hc_gpu far, near;
    hc_gpu_render(&s, &far);
    s.render.far_step = 0.0;
    hc_gpu_render(&s, &near);
    long unfinished = 0;
    double apart = 0.0;
    for (int i = 0; i < W * H; i++) {
        if (far.dump.records[i].outcome != DUMP_UNFINISHED)
            continue;
        unfinished++;
        /* the state's w: the path travelled */
        assert_true(fabs(far.res.position[4 * i + 3] - budget) <= 1e-5 * budget);
        if (near.dump.records[i].outcome == DUMP_UNFINISHED)
            apart = fmax(apart, v3_len(v3_sub(hc_gpu_x(&far, i), hc_gpu_x(&near, i))));
    }
    print_message("budget %g: %ld rays unfinished, at most %.3g from where steps of %g leave them\n", budget,
                  unfinished, apart, s.render.step_size);
    assert_true(unfinished > W * H / 4);
    assert_true(apart < 1e-3);
    hc_gpu_free(&far);
    hc_gpu_free(&near);
}

/* A far step across the bounding sphere is refused, with the key's name and why; a negative one by
 * the key's range; where nothing is integrated it does not apply. */
static void test_far_step_refused(void **state)
{
    (void)state;
    static struct scene s;
    struct error e;
    assert_int_equal(scene_load(&s, "assets/scenes/lorenz.scene", &e), 0);
    assert_int_equal(scene_set(&s, "render.far_step=30", &e), 0);
    assert_int_equal(scene_validate(&s, &e), -1);
    assert_int_equal(e.status, ERROR_INPUT);
    print_message("%s: %s\n", e.where, e.message);
    assert_non_null(strstr(e.where, "lorenz.scene"));
    assert_non_null(strstr(e.message, "render.far_step (30) must be shorter than the bounding sphere's radius"));
    assert_int_equal(scene_set(&s, "render.far_step=-1", &e), -1);
    print_message("%s: %s\n", e.where, e.message);
    assert_non_null(strstr(e.message, "far_step"));
    /* like `step`, it does not apply where nothing is integrated: exact orbits, flat space */
    static const char *const flat[] = {"model.type=flat", NULL};
    hc_load(&s, "lorenz", W, H, flat);
    assert_false(scene_far_steps(&s));
    /* a field switched off: straight rays, one segment each, counted as one step in the dump */
    static const char *const off[] = {"model.strength=0", NULL};
    hc_load(&s, "lorenz", W, H, off);
    assert_true(s.render.far_step > s.render.step_size);
    assert_false(scene_far_steps(&s));
    struct hc_gpu g;
    hc_gpu_render(&s, &g);
    assert_int_equal(g.dump.records[0].steps, 1);
    hc_gpu_free(&g);
    static const char *const orbits[] = {"render.far_step=2", NULL};
    hc_load(&s, "schwarzschild", W, H, orbits);
    assert_false(scene_far_steps(&s));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_reach_is_a_lower_bound),
        cmocka_unit_test(test_flat_bounds_keep_their_plane),
        cmocka_unit_test(test_far_steps_finish_sooner),
        cmocka_unit_test(test_far_step_within_the_near_step),
        cmocka_unit_test(test_far_steps_keep_the_path_budget),
        cmocka_unit_test(test_far_step_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
