/* The CPU limit of the benchmark: its float step follows the double model_step of src/physics for every
 * curved model with the scenes' parameters, and its measurement counts, times and refuses as promised. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "bench/cpu_limit.h"
#include "fixture.h"

/* One float step against one double step from the same state, relative to |x| and |v|: the float
 * result is the exact one rounded once (2^-24 = 6e-8, measured 5e-8 to 6e-8 on every model here) plus
 * the increment's own roundings, which h scales down. 1e-6 is 16 such roundings; a wrong operation (a
 * sign, a factor, a swapped component, RK4's stages mixed up) is an error of h |f| or h^3 |f'| at least,
 * which is more for the scenes' forces and steps. */
#define FLOAT_STEP_TOL 1e-6
/* Float against double over STEPS_COMPARED steps, relative to the distance from the model's centre
 * (position) and to |v| (velocity): the one-step errors add up, coherently at worst, to below 1e-5
 * over 100 steps (measured 3e-7 to 9e-6 across the models here); 1e-4 leaves room for the bending
 * near a mass to amplify them. */
#define FLOAT_PATH_TOL 1e-4
#define STEPS_COMPARED 100
/* The force must have changed v by this many tolerances, or agreement would prove nothing. */
#define MIN_BENDING_IN_TOLERANCES 100.0


/* assets/scenes/demo.scene and neutron_star.scene */
static struct model schwarzschild_demo(void)
{
    struct model m = fixture_model(MODEL_SCHWARZSCHILD);
    m.mass = 1.0;
    return m;
}

/* assets/scenes/schwarzschild.scene */
static struct model schwarzschild_small(void)
{
    struct model m = fixture_model(MODEL_SCHWARZSCHILD);
    m.center = v3(0.0, 0.3, 4.0);
    m.mass = 0.12;
    return m;
}

/* assets/scenes/lorenz.scene */
static struct model lorenz(void)
{
    struct model m = fixture_model(MODEL_LORENZ);
    m.sigma = 10.0;
    m.rho = 28.0;
    m.beta = 8.0 / 3.0;
    m.scale = 10.0;
    m.strength = 0.004;
    return m;
}

/* assets/scenes/rossler.scene */
static struct model rossler(void)
{
    struct model m = fixture_model(MODEL_ROSSLER);
    m.ross_a = 0.375;
    m.ross_b = 2.0;
    m.ross_c = 4.0;
    m.scale = 10.0;
    m.strength = 0.03;
    return m;
}

/* assets/scenes/potential.scene */
static struct model yukawa(void)
{
    struct model m = fixture_model(MODEL_POTENTIAL);
    m.center = v3(0.0, 0.2, 2.5);
    m.profile = PROFILE_YUKAWA;
    m.zeta = -1.5;
    m.mu = 0.2;
    return m;
}

/* The scene defaults of the polynomial profile: strength 1, range 5. */
static struct model polynomial(void)
{
    struct model m = fixture_model(MODEL_POTENTIAL);
    m.profile = PROFILE_POLYNOMIAL;
    m.strength = 1.0;
    m.radius = 5.0;
    return m;
}

/* assets/scenes/refraction.scene */
static struct model refraction(void)
{
    struct model m = fixture_model(MODEL_REFRACTION);
    m.center = v3(0.0, 0.0, 3.0);
    m.amplitude = 0.15;
    m.shell_radius = 1.8;
    m.shell_width = 0.8;
    m.noise_amplitude = 0.6;
    m.noise_frequency = 3.0;
    return m;
}

static vec3d from_float(const float a[3]) { return v3(a[0], a[1], a[2]); }
static void to_float(vec3d a, float out[3])
{
    out[0] = (float)a.x;
    out[1] = (float)a.y;
    out[2] = (float)a.z;
}

/* One ray from camera along dir (the model's initial velocity), integrated in float by cpu_limit_step
 * and in double by model_step from the same float-representable start, compared after every step;
 * each float step is also compared with a double step from the float state. */
static void check_float_path(const char *what, const struct model *m, enum integration_method method, double h,
                             vec3d camera, vec3d dir)
{
    float xf[3], vf[3];
    to_float(camera, xf);
    to_float(model_initial_velocity(m, camera, v3_normalize(dir)), vf);
    vec3d x = from_float(xf), v = from_float(vf), v_start = v;
    for (int i = 0; i < STEPS_COMPARED; i++) {
        vec3d x_local = from_float(xf), v_local = from_float(vf);
        model_step(m, method, h, &x_local, &v_local);
        model_step(m, method, h, &x, &v);
        cpu_limit_step(m, method, (float)h, xf, vf);
        double x_step_error = v3_len(v3_sub(from_float(xf), x_local)) / v3_len(x_local);
        double v_step_error = v3_len(v3_sub(from_float(vf), v_local)) / v3_len(v_local);
        if (!(x_step_error <= FLOAT_STEP_TOL && v_step_error <= FLOAT_STEP_TOL)) {
            print_error("%s %s, step %d alone: relative error of x %.3g, of v %.3g (tolerance %g)\n", what,
                        method_name(method), i + 1, x_step_error, v_step_error, FLOAT_STEP_TOL);
            fail();
        }
        double x_error = v3_len(v3_sub(from_float(xf), x)) / v3_len(v3_sub(x, m->center));
        double v_error = v3_len(v3_sub(from_float(vf), v)) / v3_len(v);
        if (!(x_error <= FLOAT_PATH_TOL && v_error <= FLOAT_PATH_TOL)) {
            print_error("%s %s, step %d: relative error of x %.3g, of v %.3g (tolerance %g)\n", what,
                        method_name(method), i + 1, x_error, v_error, FLOAT_PATH_TOL);
            fail();
        }
    }
    double bending = v3_len(v3_sub(v, v_start)) / v3_len(v_start);
    if (!(bending > MIN_BENDING_IN_TOLERANCES * FLOAT_PATH_TOL)) {
        print_error("%s %s: v changed by only %.3g: the ray missed the force\n", what, method_name(method), bending);
        fail();
    }
}

static void check_both_methods(const char *what, const struct model *m, double h, vec3d camera, vec3d dir)
{
    check_float_path(what, m, METHOD_EULER, h, camera, dir);
    check_float_path(what, m, METHOD_RK4, h, camera, dir);
}

/* ---- the float step against the double model ---- */

static void test_schwarzschild_step(void **state)
{
    (void)state;
    struct model demo = schwarzschild_demo();
    /* impact parameter 15 sin(atan 0.45) = 6.2, just outside the shadow's edge 3 sqrt(3) = 5.2 */
    check_both_methods("schwarzschild M=1", &demo, 0.15, v3(0, 0, 15), v3(0.45, 0, -1));
    struct model small = schwarzschild_small();
    /* passes about 0.7 from the mass, outside its shadow's edge 0.62 */
    check_both_methods("schwarzschild M=0.12", &small, 0.05, v3(0, 1.5, 9), v3(0.13, -0.24, -1));
}

static void test_lorenz_step(void **state)
{
    (void)state;
    struct model m = lorenz();
    check_both_methods("lorenz", &m, 0.05, v3(0, 1.5, 9), v3(0.1, -0.1, -1));
}

static void test_rossler_step(void **state)
{
    (void)state;
    struct model m = rossler();
    check_both_methods("rossler", &m, 0.05, v3(0, 1.5, 9), v3(0.1, -0.1, -1));
}

static void test_potential_step(void **state)
{
    (void)state;
    struct model y = yukawa();
    check_both_methods("yukawa", &y, 0.05, v3(0, 1.5, 9), v3(0.1, -0.1, -1));
    struct model p = polynomial();
    check_both_methods("polynomial", &p, 0.05, v3(0, 1.5, 9), v3(0.1, -0.1, -1));
}

static void test_refraction_step(void **state)
{
    (void)state;
    struct model m = refraction();
    check_both_methods("refraction", &m, 0.05, v3(0, 1.5, 9), v3(0.05, -0.15, -1));
}

static void test_flat_step_changes_nothing(void **state)
{
    (void)state;
    struct model m = fixture_model(MODEL_FLAT);
    float x[3] = {1, 2, 3}, v[3] = {0, 0, -1};
    cpu_limit_step(&m, METHOD_RK4, 0.1f, x, v);
    assert_true(x[0] == 1.0f && x[1] == 2.0f && x[2] == 3.0f);
    assert_true(v[0] == 0.0f && v[1] == 0.0f && v[2] == -1.0f);
}

/* ---- the measurement ---- */

/* Not a multiple of the 16-ray cache line, so the last slice is partial. */
#define TINY_RAYS 37
#define TINY_STEPS_PER_CALL 3
#define TINY_SECONDS 0.02

static void check_tiny_measure(const char *what, const struct model *m, enum integration_method method)
{
    struct cpu_limit_result r;
    struct error err;
    if (cpu_limit_measure(m, method, TINY_RAYS, TINY_STEPS_PER_CALL, 2, TINY_SECONDS, &r, &err) != 0)
        fail_msg("%s %s: %s", what, method_name(method), err.message);
    assert_true(r.sweeps >= 1);
    assert_true(r.steps == (long long)TINY_RAYS * TINY_STEPS_PER_CALL * r.sweeps);
    assert_true(r.seconds >= TINY_SECONDS);
    assert_true(r.steps_per_second > 0.0);
    assert_true(fabs(r.steps_per_second - (double)r.steps / r.seconds) <= 1e-9 * r.steps_per_second);
    assert_true(r.threads >= 1 && r.threads <= 2);
    /* rays start 10 to 20 from the centre and stop at the bounding sphere 1e4 away */
    assert_true(isfinite(r.checksum) && r.checksum > 0.0);
}

static void test_measure_counts_steps(void **state)
{
    (void)state;
    const struct model models[] = {schwarzschild_demo(), schwarzschild_small(), lorenz(), rossler(),
                                   yukawa(), polynomial(), refraction()};
    for (size_t i = 0; i < sizeof models / sizeof models[0]; i++) {
        check_tiny_measure(model_name(models[i].type), &models[i], METHOD_EULER);
        check_tiny_measure(model_name(models[i].type), &models[i], METHOD_RK4);
    }
}

/* With no time asked for, exactly one counted sweep follows the warm-up: the final state is then
 * fixed, and how the rays are split between threads must not change it. */
static void test_measure_independent_of_threads(void **state)
{
    (void)state;
    struct model m = schwarzschild_demo();
    struct cpu_limit_result one, three;
    struct error err;
    assert_int_equal(cpu_limit_measure(&m, METHOD_RK4, 1000, 5, 1, 0.0, &one, &err), 0);
    assert_int_equal(cpu_limit_measure(&m, METHOD_RK4, 1000, 5, 3, 0.0, &three, &err), 0);
    assert_true(one.sweeps == 1 && three.sweeps == 1);
    assert_int_equal(one.threads, 1);
    assert_int_equal(three.threads, 3);
    assert_true(one.checksum == three.checksum);
}

static void test_measure_refuses(void **state)
{
    (void)state;
    struct cpu_limit_result r;
    struct error err;
    struct model flat = fixture_model(MODEL_FLAT);
    assert_int_equal(cpu_limit_measure(&flat, METHOD_RK4, 100, 1, 1, 0.0, &r, &err), -1);
    assert_non_null(strstr(err.message, "flat"));
    assert_int_equal(err.status, ERROR_RUNTIME);
    struct model m = schwarzschild_demo();
    error_clear(&err);
    assert_int_equal(cpu_limit_measure(&m, METHOD_RK4, 0, 1, 1, 0.0, &r, &err), -1);
    assert_true(err.message[0] != '\0');
    error_clear(&err);
    assert_int_equal(cpu_limit_measure(&m, METHOD_RK4, 100, 0, 1, 0.0, &r, &err), -1);
    assert_true(err.message[0] != '\0');
    error_clear(&err);
    assert_int_equal(cpu_limit_measure(&m, METHOD_RK4, 100, 1, 1, -1.0, &r, &err), -1);
    assert_true(err.message[0] != '\0');
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_schwarzschild_step),
        cmocka_unit_test(test_lorenz_step),
        cmocka_unit_test(test_rossler_step),
        cmocka_unit_test(test_potential_step),
        cmocka_unit_test(test_refraction_step),
        cmocka_unit_test(test_flat_step_changes_nothing),
        cmocka_unit_test(test_measure_counts_steps),
        cmocka_unit_test(test_measure_independent_of_threads),
        cmocka_unit_test(test_measure_refuses),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
