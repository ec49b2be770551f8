/* Newtonian gravity for light (model.type = newtonian, Soldner 1801) against its closed forms: the
 * CPU reference's rays are hyperbolas about the mass, deflected by exactly 2 atan(M / b) between
 * their asymptotes (2M/b in the weak field: half of general relativity's 4M/b, which the same
 * reference gives in Schwarzschild space), and absorbed by the dark star of radius 2M below
 * b = 2 sqrt(2) M. Then the GPU against the reference on the shipped scene. M = 1 throughout. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "hard_cases.h"

static const double mass = 1.0;

/* Rays start at distance `start` from the mass, inside a bounding sphere twice that. */
static void empty_space(struct scene *s, enum model_type type, double start)
{
    scene_defaults(s);
    s->model.type = type;
    s->model.mass = mass;
    s->model.center = v3(0.0, 0.0, 0.0);
    s->n_objects = 0;
    s->render.bound_center = v3(0.0, 0.0, 0.0);
    s->render.bound_radius = 2.0 * start;
    s->render.method = METHOD_RK4;
    s->render.step_size = 1.0;              /* ref_trace's first trial step */
    s->render.steps_per_segment = 1000;
    s->render.segments = 100000;
    s->camera.position = v3(0.0, 0.0, start);
    s->camera.look_at = v3(0.0, 0.0, 0.0);
    hc_validate(s);
}

/* rtol is the reference's default; atol, by default rtol times the bounding radius (here 2e7 M),
 * is taken at the scale of the bend, M. */
static struct ref_options options(const struct scene *s)
{
    struct ref_options o;
    ref_options_default(&o, s);
    o.atol = REF_DEFAULT_RTOL * mass;
    return o;
}

struct conic_check {
    vec3d e;           /* eccentricity vector */
    double p;          /* semi-latus rectum h^2 / M */
    double worst;      /* largest |r + e.y - p| / (r (1 + |e|)) over the samples */
    long samples;
};

static void on_conic(void *arg, double lambda, vec3d x, vec3d v)
{
    (void)lambda;
    (void)v;
    struct conic_check *c = arg;
    /* a conic about the focus at the mass: r (1 + e cos nu) = p, e cos nu r = e . y */
    double r = v3_len(x);
    /* relative to r (1 + |e|): a position off the orbit by a fraction of r moves e . y by |e| times
     * that (a nearly straight ray has a large e) */
    c->worst = fmax(c->worst, fabs(r + v3_dot(c->e, x) - c->p) / (r * (1.0 + v3_len(c->e))));
    c->samples++;
}

/* The ray launched from distance `start` towards the point b beside the mass, traced by the
 * reference: its outcome, and the angle between its launch direction and its direction at infinity. */
static double deflection(enum model_type type, double start, double b, int32_t *outcome, struct conic_check *conic)
{
    static struct scene s;
    empty_space(&s, type, start);
    vec3d dir = v3_normalize(v3(b, 0.0, -start));
    vec3d x0 = s.camera.position;
    vec3d v0 = model_initial_velocity(&s.model, x0, dir);
    struct ref_options o = options(&s);
    struct ref_ray ray;
    if (conic) {
        vec3d h = v3_cross(x0, v0);
        conic->e = v3_sub(v3_scale(v3_cross(v0, h), 1.0 / mass), v3_scale(x0, 1.0 / v3_len(x0)));
        conic->p = v3_dot(h, h) / mass;
        conic->worst = 0.0;
        conic->samples = 0;
    }
    ref_trace(&s, &o, x0, v0, &ray, conic ? 0.05 : 0.0, conic ? on_conic : NULL, conic);
    *outcome = ray.outcome;
    vec3d out = v3_normalize(ray.velocity);
    return atan2(v3_len(v3_cross(dir, out)), v3_dot(dir, out));
}

/* The same angle from the conic alone: the launch point and velocity give h, the energy 1/2 (the
 * speed is c far away) and e = sqrt(1 + h^2 / M^2), p = h^2 / M; the launch is at the true anomaly
 * nu_0 < 0 with cos nu_0 = (p / r_0 - 1) / e, moving along (-sin nu_0, e + cos nu_0) in the frame
 * of periapsis, and the ray leaves along (-1/e, sqrt(1 - 1/e^2)). */
static double conic_deflection(double start, double b)
{
    vec3d dir = v3_normalize(v3(b, 0.0, -start));
    double speed = sqrt(1.0 + 2.0 * mass / start);
    double h = start * speed * v3_len(v3_cross(v3(0.0, 0.0, 1.0), dir));
    double e = sqrt(1.0 + h * h / (mass * mass));
    double p = h * h / mass;
    double cos0 = (p / start - 1.0) / e;
    double sin0 = -sqrt(1.0 - cos0 * cos0);
    double in_x = -sin0, in_y = e + cos0;
    double out_x = -1.0 / e, out_y = sqrt(1.0 - 1.0 / (e * e));
    return atan2(in_x * out_y - in_y * out_x, in_x * out_x + in_y * out_y);
}

static void test_deflection_closed_form(void **state)
{
    (void)state;
    static const double bs[] = {3.0, 5.0, 10.0, 100.0, 1000.0};
    const double start = 1e4;
    for (size_t k = 0; k < sizeof bs / sizeof bs[0]; k++) {
        int32_t outcome;
        struct conic_check conic;
        double got = deflection(MODEL_NEWTONIAN, start, bs[k], &outcome, &conic);
        double want = conic_deflection(start, bs[k]);
        print_message("b = %-5g M: deflection %.12f, the hyperbola's %.12f (%.1e), from infinity 2 atan(M/b) %.6f; "
                      "%ld points on the hyperbola within %.1e of p\n", bs[k], got, want, got - want,
                      2.0 * atan(mass / bs[k]), conic.samples, conic.worst);
        assert_int_equal(outcome, DUMP_SKY);
        /* the reference's tolerance, 1e-10 a step, over the bend: measured within 1e-9 */
        assert_true(fabs(got - want) <= 1e-8);
        /* every point of the path on the conic of its start: an orbit of the inverse-square force */
        assert_true(conic.samples > 10);
        /* to the integration's tolerance (1e-10 a step; measured within 2e-10) */
        assert_true(conic.worst <= 1e-8);
    }
}

static void test_half_of_einstein(void **state)
{
    (void)state;
    int32_t outcome;
    /* from 1e7 M, where the rest of the pull is negligible: the whole deflection */
    double b = 1e4, start = 1e7;
    double newton = deflection(MODEL_NEWTONIAN, start, b, &outcome, NULL);
    double einstein = deflection(MODEL_SCHWARZSCHILD, start, b, &outcome, NULL);
    print_message("b = 1e4 M: Newtonian %.9e rad (2M/b = %.9e), Schwarzschild %.6e rad (4M/b = %.6e): %.5f times\n",
                  newton, 2.0 * mass / b, einstein, 4.0 * mass / b, einstein / newton);
    /* the weak field, 2M/b: its next order, (M/b)^2 / 3, is 3e-9; the reference's tolerance over the
     * path of 2e7 M and the pull left beyond 1e7 M (M b / r^2), about 1e-7 measured */
    assert_true(fabs(newton / (2.0 * mass / b) - 1.0) <= 1e-6);
    /* general relativity bends twice as much, to its next order (15 pi / 16) M/b */
    assert_true(fabs(einstein / newton - 2.0) <= 2.0 * 15.0 * 3.14159265358979 / 16.0 * mass / b * 1.1);
}

static void test_dark_star(void **state)
{
    (void)state;
    /* below b = 2 sqrt(2) M the hyperbola's periapsis, b^2 / (M (1 + sqrt(1 + b^2/M^2))), is inside
     * the dark star's radius 2M */
    double critical = 2.0 * sqrt(2.0) * mass;
    int32_t inside, outside;
    /* from 1e7 M the launch line's distance is the impact parameter to 1e-14 */
    deflection(MODEL_NEWTONIAN, 1e7, critical * (1.0 - 1e-6), &inside, NULL);
    deflection(MODEL_NEWTONIAN, 1e7, critical * (1.0 + 1e-6), &outside, NULL);
    print_message("b = 2 sqrt(2) M -+ 1e-6: %s, %s\n", dump_outcome_name(inside), dump_outcome_name(outside));
    assert_int_equal(inside, DUMP_CAPTURED);
    assert_int_equal(outside, DUMP_SKY);
}

static void test_gpu_against_reference(void **state)
{
    (void)state;
    static struct scene s;
    hc_load(&s, "newtonian", 160, 120, NULL);
    struct cpu_image cpu;
    struct hc_gpu g;
    hc_render_both(&s, 160, 120, &cpu, &g);
    struct compare_result cr;
    hc_compare(&g.dump, &cpu.dump, &cr);
    print_message("newtonian.scene at 160x120: %ld outcomes differ, hit p99 %.2e of size, sky p99 %.2e rad\n",
                  cr.outcomes.differ, cr.hit_relative.p99, cr.sky_angle.p99);
    assert_true(cr.sky_angle.count > 1000 && cr.hit_relative.count > 1000);
    /* the scene's [quality] */
    assert_true(100.0 * cr.outcome_fraction <= s.quality.differing_percent);
    assert_true(cr.hit_relative.p99 <= s.quality.hit_p99);
    assert_true(cr.sky_angle.p99 <= s.quality.exit_p99);
    cpu_image_free(&cpu);
    hc_gpu_free(&g);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_deflection_closed_form),
        cmocka_unit_test(test_half_of_einstein),
        cmocka_unit_test(test_dark_star),
        cmocka_unit_test(test_gpu_against_reference),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
