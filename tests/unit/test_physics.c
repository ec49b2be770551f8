/* Force laws, integrators and segment intersections of src/physics against hand-computed values,
 * numerical derivatives and known results of general relativity. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "physics/intersect.h"
#include "physics/model.h"
#include "fixture.h"

/* Formulas evaluated once in double: only a few roundings separate them from hand values. */
#define ROUNDING_TOL 1e-12
/* pi is not in strict C11. */
static const double pi = 3.14159265358979323846;

static void assert_near(double got, double want, double tol, const char *what)
{
    if (!(fabs(got - want) <= tol)) {
        print_error("%s: got %.17g, want %.17g (tolerance %g)\n", what, got, want, tol);
        fail();
    }
}

static void assert_vec_near(vec3d got, vec3d want, double tol, const char *what)
{
    assert_near(got.x, want.x, tol, what);
    assert_near(got.y, want.y, tol, what);
    assert_near(got.z, want.z, tol, what);
}


static struct model schwarzschild(double mass)
{
    struct model m = fixture_model(MODEL_SCHWARZSCHILD);
    m.mass = mass;
    return m;
}

/* ---- names ---- */

static void test_names(void **state)
{
    (void)state;
    assert_string_equal(model_name(MODEL_FLAT), "flat");
    assert_string_equal(model_name(MODEL_LORENZ), "lorenz");
    assert_string_equal(model_name(MODEL_ROSSLER), "rossler");
    assert_string_equal(model_name(MODEL_POTENTIAL), "potential");
    assert_string_equal(model_name(MODEL_REFRACTION), "refraction");
    assert_string_equal(model_name(MODEL_SCHWARZSCHILD), "schwarzschild");
    assert_string_equal(method_name(METHOD_EULER), "euler");
    assert_string_equal(method_name(METHOD_RK4), "rk4");
}

/* ---- force laws at hand-computed points ---- */

static void test_flat(void **state)
{
    (void)state;
    struct model m = fixture_model(MODEL_FLAT);
    vec3d dir = v3(0.6, 0.0, 0.8);
    assert_vec_near(model_accel(&m, v3(3, -2, 7), v3(1, 2, 3)), v3(0, 0, 0), 0.0, "flat force");
    assert_vec_near(model_initial_velocity(&m, v3(3, -2, 7), dir), dir, 0.0, "flat velocity");
    assert_true(model_capture_radius(&m) == 0.0);
    assert_true(model_refraction_index(&m, v3(1, 1, 1)) == 1.0);
}

static void test_lorenz_value(void **state)
{
    (void)state;
    struct model m = fixture_model(MODEL_LORENZ);
    m.center = v3(1, 2, 3);
    m.scale = 2.0;
    m.strength = 0.5;
    m.sigma = 10.0;
    m.rho = 28.0;
    m.beta = 8.0 / 3.0;
    /* u = (1, 2, 3): F = (10 (2 - 1), 1 (28 - 3) - 2, 1 * 2 - 8) = (10, 23, -6). */
    vec3d x = v3_add(m.center, v3(2, 4, 6));
    vec3d f = model_accel(&m, x, v3(5, 5, 5));
    assert_vec_near(f, v3(5.0, 11.5, -3.0), ROUNDING_TOL, "lorenz force");
    assert_vec_near(model_initial_velocity(&m, x, v3(0, 1, 0)), v3(0, 1, 0), 0.0, "lorenz velocity");
}

static void test_rossler_value(void **state)
{
    (void)state;
    struct model m = fixture_model(MODEL_ROSSLER);
    m.center = v3(-1, 0, 1);
    m.scale = 0.5;
    m.strength = 2.0;
    m.ross_a = 3.0 / 8.0;
    m.ross_b = 2.0;
    m.ross_c = 4.0;
    /* u = (1, 2, 3): F = (-(2 + 3), 1 + 0.75, 2 + 3 (1 - 4)) = (-5, 1.75, -7). */
    vec3d f = model_accel(&m, v3_add(m.center, v3(0.5, 1.0, 1.5)), v3(0, 0, 0));
    assert_vec_near(f, v3(-10.0, 3.5, -14.0), ROUNDING_TOL, "rossler force");
}

static struct model yukawa(double zeta, double mu)
{
    struct model m = fixture_model(MODEL_POTENTIAL);
    m.profile = PROFILE_YUKAWA;
    m.zeta = zeta;
    m.mu = mu;
    return m;
}

static void test_yukawa_value_and_sign(void **state)
{
    (void)state;
    struct model m = yukawa(2.0, 0.5);
    m.center = v3(1, 1, 1);
    /* r = 2: f = 2 e^-1 (1/4 + 1/4) outward = e^-1 outward. */
    vec3d f = model_accel(&m, v3(1, 1, 3), v3(0, 0, 0));
    assert_vec_near(f, v3(0, 0, exp(-1.0)), ROUNDING_TOL, "yukawa force");
    struct model attract = yukawa(-2.0, 0.5);
    attract.center = m.center;
    assert_true(model_accel(&attract, v3(1, 1, 3), v3(0, 0, 0)).z < 0.0);
    /* The centre itself has no direction: zero, not NaN. */
    assert_vec_near(model_accel(&m, m.center, v3(0, 0, 0)), v3(0, 0, 0), 0.0, "yukawa centre");
}

static double yukawa_potential(const struct model *m, vec3d x)
{
    double r = v3_len(v3_sub(x, m->center));
    return m->zeta * exp(-m->mu * r) / r;
}

static void test_yukawa_is_minus_gradient(void **state)
{
    (void)state;
    struct model m = yukawa(-1.3, 0.7);
    m.center = v3(0.2, -0.1, 0.4);
    /* Central differences: truncation ~ dx^2 V''' ~ 1e-10, rounding ~ eps V / dx ~ 1e-11. */
    const double dx = 1e-5, tol = 1e-7;
    vec3d points[3] = {v3(1.0, 0.5, -0.3), v3(-2.0, 1.0, 0.7), v3(0.3, 0.1, 0.9)};
    for (int i = 0; i < 3; i++) {
        vec3d x = points[i];
        vec3d ex = v3(dx, 0, 0), ey = v3(0, dx, 0), ez = v3(0, 0, dx);
        vec3d grad = v3((yukawa_potential(&m, v3_add(x, ex)) - yukawa_potential(&m, v3_sub(x, ex))) / (2 * dx),
                        (yukawa_potential(&m, v3_add(x, ey)) - yukawa_potential(&m, v3_sub(x, ey))) / (2 * dx),
                        (yukawa_potential(&m, v3_add(x, ez)) - yukawa_potential(&m, v3_sub(x, ez))) / (2 * dx));
        assert_vec_near(model_accel(&m, x, v3(0, 0, 0)), v3_scale(grad, -1.0), tol, "yukawa -grad V");
    }
}

static void test_polynomial_profile(void **state)
{
    (void)state;
    struct model m = fixture_model(MODEL_POTENTIAL);
    m.profile = PROFILE_POLYNOMIAL;
    m.strength = 3.0;
    m.radius = 2.0;
    m.center = v3(0, 1, 0);
    /* r = 1 = R/2: xi = 2/8 - 3/4 + 1 = 1/2, f = -3 * 1/2 outward. */
    assert_vec_near(model_accel(&m, v3(1, 1, 0), v3(0, 0, 0)), v3(-1.5, 0, 0), ROUNDING_TOL, "xi(R/2)");
    /* xi(R) = 0 and nothing beyond R, so the field switches off continuously. */
    assert_vec_near(model_accel(&m, v3(0, 3, 0), v3(0, 0, 0)), v3(0, 0, 0), ROUNDING_TOL, "xi(R)");
    assert_vec_near(model_accel(&m, v3(0, 1, 5), v3(0, 0, 0)), v3(0, 0, 0), 0.0, "beyond R");
    /* Near the centre xi -> 1: the force tends to -strength along the way out. */
    assert_vec_near(model_accel(&m, v3(0, 1, 1e-6), v3(0, 0, 0)), v3(0, 0, -3.0), 1e-10, "xi(0)");
    assert_vec_near(model_accel(&m, m.center, v3(0, 0, 0)), v3(0, 0, 0), 0.0, "centre");
}

static struct model explosion(void)
{
    struct model m = fixture_model(MODEL_REFRACTION);
    m.center = v3(0.5, -0.2, 0.1);
    m.amplitude = 0.3;
    m.shell_radius = 2.0;
    m.shell_width = 0.8;
    m.noise_amplitude = 0.4;
    m.noise_frequency = 3.0;
    return m;
}

static void test_refraction_value(void **state)
{
    (void)state;
    struct model m = explosion();
    m.noise_amplitude = 0.0;
    m.shell_width = 1.0;
    m.amplitude = 0.1;
    /* r = 3, one shell width out: s = e^-1, n = 1 + 0.1 e^-1, dn/dr = 0.1 * (-2) e^-1. */
    vec3d x = v3_add(m.center, v3(0, 3, 0));
    double n = 1.0 + 0.1 * exp(-1.0);
    assert_near(model_refraction_index(&m, x), n, ROUNDING_TOL, "n on the shell flank");
    assert_vec_near(model_accel(&m, x, v3(1, 0, 0)), v3(0, n * -0.2 * exp(-1.0), 0), ROUNDING_TOL, "n grad n");
    /* |dx/dsigma| = n: a ray starts with speed n. */
    assert_vec_near(model_initial_velocity(&m, x, v3(0, 0, 1)), v3(0, 0, n), ROUNDING_TOL, "speed n");
    /* At the shell's peak the radial slope vanishes and only the noise could bend: it is off here. */
    assert_vec_near(model_accel(&m, v3_add(m.center, v3(2, 0, 0)), v3(1, 0, 0)), v3(0, 0, 0), ROUNDING_TOL,
                    "shell peak");
}

static void test_refraction_is_n_grad_n(void **state)
{
    (void)state;
    struct model m = explosion();
    /* Central differences of n (order 1): truncation ~ dx^2 n''' ~ 1e-9 with frequency 3,
     * rounding ~ eps / dx ~ 1e-11. */
    const double dx = 1e-5, tol = 1e-7;
    vec3d points[4] = {v3(2.0, 0.5, -0.3), v3(-1.0, 1.0, 0.7), v3(0.3, 2.1, 0.9), v3(0.6, -0.1, 0.1)};
    for (int i = 0; i < 4; i++) {
        vec3d x = points[i];
        vec3d ex = v3(dx, 0, 0), ey = v3(0, dx, 0), ez = v3(0, 0, dx);
        vec3d grad = v3((model_refraction_index(&m, v3_add(x, ex)) - model_refraction_index(&m, v3_sub(x, ex))) / (2 * dx),
                        (model_refraction_index(&m, v3_add(x, ey)) - model_refraction_index(&m, v3_sub(x, ey))) / (2 * dx),
                        (model_refraction_index(&m, v3_add(x, ez)) - model_refraction_index(&m, v3_sub(x, ez))) / (2 * dx));
        double n = model_refraction_index(&m, x);
        assert_true(n > 1.0 - m.amplitude * (1.0 + m.noise_amplitude));
        assert_vec_near(model_accel(&m, x, v3(0, 0, 1)), v3_scale(grad, n), tol, "n grad n");
    }
    /* The shell's cone point at the centre: finite, not NaN. */
    assert_true(v3_isfinite(model_accel(&m, m.center, v3(0, 0, 1))));
}

/* ---- Schwarzschild ---- */

static void test_schwarzschild_value(void **state)
{
    (void)state;
    struct model m = schwarzschild(1.0);
    m.center = v3(0, 0, 1);
    /* y = (10, 0, 0), h = 10: f = -3 * 100 * y / 10^5 = (-0.03, 0, 0), whatever the radial velocity. */
    vec3d x = v3(10, 0, 1);
    assert_vec_near(model_accel(&m, x, v3(0, 1, 0)), v3(-0.03, 0, 0), ROUNDING_TOL, "tangential");
    assert_vec_near(model_accel(&m, x, v3(7, 1, 0)), v3(-0.03, 0, 0), ROUNDING_TOL, "with radial part");
    /* A radial ray feels nothing: h = 0. */
    assert_vec_near(model_accel(&m, x, v3(-1, 0, 0)), v3(0, 0, 0), ROUNDING_TOL, "radial");
    assert_true(model_capture_radius(&m) == 2.0);
    assert_vec_near(model_accel(&m, m.center, v3(0, 1, 0)), v3(0, 0, 0), 0.0, "centre");
}

/* Integrates a ray coming in along +x at height b until it falls below the horizon, or has passed
 * the hole and reached |x| >= far. Returns 1 when captured. */
static int shoot_ray(const struct model *m, double b, double far, double h, vec3d *x_out, vec3d *v_out)
{
    vec3d x = v3(-far, b, 0.0), v = v3(1.0, 0.0, 0.0);
    double horizon = model_capture_radius(m);
    for (long i = 0; i < 100000000L; i++) {
        model_step(m, METHOD_RK4, h, &x, &v);
        if (v3_len(x) < horizon) {
            *x_out = x;
            *v_out = v;
            return 1;
        }
        if (v3_len(x) >= far && v3_dot(x, v) > 0.0)
            break;
    }
    *x_out = x;
    *v_out = v;
    return 0;
}

static void test_schwarzschild_conserves_h(void **state)
{
    (void)state;
    struct model m = schwarzschild(1.0);
    /* b = 5.4 M, just outside the photon sphere's critical 5.196 M: the ray swings tightly
     * around r ~ 3.6 M, the hardest place for the integrator. */
    vec3d x = v3(-200.0, 5.4, 0.0), v = v3(1.0, 0.0, 0.0);
    double h0 = v3_len(v3_cross(x, v));
    double worst = 0.0;
    for (int i = 0; i < 40000; i++) {
        model_step(&m, METHOD_RK4, 0.01, &x, &v);
        double drift = fabs(v3_len(v3_cross(x, v)) - h0) / h0;
        worst = fmax(worst, drift);
    }
    /* A central force keeps h exactly; RK4 loses it only through its truncation error, measured at
     * 5e-14 here. 1e-10 leaves room for other compilers yet catches any non-central force term. */
    if (!(worst < 1e-10)) {
        print_error("relative drift of h %g\n", worst);
        fail();
    }
    assert_true(v3_len(x) > 100.0);   /* it did escape and travel on */
}

static double deflection_angle(double mass, double b)
{
    struct model m = schwarzschild(mass);
    vec3d x, v;
    /* Step 0.05 M: RK4 global error ~ (0.05)^4 ~ 1e-5 relative on the ~20 M long bend. */
    int captured = shoot_ray(&m, b, 1e4, 0.05 * mass, &x, &v);
    assert_false(captured);
    return -atan2(v.y, v.x);
}

static void test_schwarzschild_weak_deflection(void **state)
{
    (void)state;
    /* alpha = 4 M/b + (15 pi/4)(M/b)^2 + (128/3)(M/b)^3 + ... with all terms positive. Starting and
     * ending at 10^4 M misses only ~3 M b^3 / (4 x^4) < 1e-9 of it at these b. */
    const double mass = 1.0;
    double e = 0.01;
    double alpha = deflection_angle(mass, mass / e);
    double second_order = 4.0 * e + 15.0 * pi / 4.0 * e * e;
    double third_term = 128.0 / 3.0 * e * e * e;
    /* At b = 100 M the remainder after second order is about the third-order term (4.3e-5);
     * the second-order term itself (1.2e-3) must be resolved. */
    assert_near(alpha, second_order, 2.0 * third_term, "deflection at b = 100 M");
    assert_true(fabs(alpha - 4.0 * e) > 10.0 * third_term);

    e = 0.1;
    alpha = deflection_angle(mass, mass / e);
    second_order = 4.0 * e + 15.0 * pi / 4.0 * e * e;
    third_term = 128.0 / 3.0 * e * e * e;
    /* At b = 10 M the terms shrink by about 2.5 each, so the remainder lies between the third-order
     * term and twice it (exact value 0.5904 vs 0.5178). */
    assert_true(alpha > second_order + third_term);
    assert_true(alpha < second_order + 2.0 * third_term);
}

/* Exact deflection from the Binet orbit integral, independent of any ray integrator:
 * alpha = 2 int_0^u0 du / sqrt(1/b^2 - u^2 + 2 M u^3) - pi, u0 = 1 / closest approach. */
static double binet_deflection(double mass, double b)
{
    double lo = 0.0, hi = 1.0 / (3.0 * mass);   /* the turning point lies outside the photon sphere */
    for (int i = 0; i < 200; i++) {
        double mid = 0.5 * (lo + hi);
        if (1.0 / (b * b) - mid * mid + 2.0 * mass * mid * mid * mid > 0.0)
            lo = mid;
        else
            hi = mid;
    }
    double u0 = lo;
    /* u = u0 (1 - s^2) removes the inverse square-root singularity at the turning point; the
     * integrand is then smooth and the midpoint rule converges as 1/N^2. */
    const int nodes = 200000;
    double sum = 0.0;
    for (int i = 0; i < nodes; i++) {
        double s = (i + 0.5) / nodes;
        double u = u0 * (1.0 - s * s);
        sum += 2.0 * u0 * s / sqrt(1.0 / (b * b) - u * u + 2.0 * mass * u * u * u);
    }
    return 2.0 * sum / nodes - pi;
}

static void test_schwarzschild_exact_deflection(void **state)
{
    (void)state;
    /* RK4 at h = 0.05 M and the quadrature both sit near 1e-9 here; 1e-6 rad is far below the
     * 0.04 rad that the 3M u^2 law would be off by with a wrong constant. */
    const double impact[3] = {6.0, 10.0, 30.0};
    for (int i = 0; i < 3; i++)
        assert_near(deflection_angle(1.0, impact[i]), binet_deflection(1.0, impact[i]), 1e-6, "deflection");
}

static void test_schwarzschild_shadow_edge(void **state)
{
    (void)state;
    struct model m = schwarzschild(1.0);
    double critical = 3.0 * sqrt(3.0);
    vec3d x, v;
    /* 0.5 % either side of the photon sphere's critical impact parameter. */
    assert_true(shoot_ray(&m, 0.995 * critical, 100.0, 0.005, &x, &v));
    assert_false(shoot_ray(&m, 1.005 * critical, 100.0, 0.005, &x, &v));
    assert_true(v3_len(x) >= 100.0);
    /* Scaling check: the same geometry with M = 2 and b doubled. */
    struct model heavy = schwarzschild(2.0);
    assert_true(shoot_ray(&heavy, 2.0 * 0.995 * critical, 200.0, 0.01, &x, &v));
    assert_false(shoot_ray(&heavy, 2.0 * 1.005 * critical, 200.0, 0.01, &x, &v));
}

static void test_schwarzschild_initial_velocity(void **state)
{
    (void)state;
    struct model m = schwarzschild(1.0);
    m.center = v3(1, 2, 3);
    vec3d outward = v3(0, 0, 1);
    double r = 5.0;
    vec3d x = v3_axpy(r, outward, m.center);
    /* Purely radial and purely tangential directions are not turned. */
    assert_vec_near(model_initial_velocity(&m, x, v3(0, 0, -1)), v3(0, 0, -1), ROUNDING_TOL, "radial");
    assert_vec_near(model_initial_velocity(&m, x, v3(0.6, 0.8, 0)), v3(0.6, 0.8, 0), ROUNDING_TOL, "tangential");
    /* An oblique one has its radial part scaled by sqrt(1 - 2M/r) and is then normalised. */
    double psi = 0.7;   /* angle from the outward direction */
    vec3d dir = v3(sin(psi), 0, cos(psi));
    double k = sqrt(1.0 - 2.0 / r);
    vec3d want = v3_normalize(v3(sin(psi), 0, k * cos(psi)));
    vec3d got = model_initial_velocity(&m, x, dir);
    assert_vec_near(got, want, ROUNDING_TOL, "oblique");
    /* Its Binet invariant 1/b^2 = |v|^2/h^2 - 2M/r^3 gives the observer's b = r sin psi / sqrt(1 - 2M/r). */
    vec3d y = v3_sub(x, m.center);
    double h = v3_len(v3_cross(y, got));
    double b = 1.0 / sqrt(v3_dot(got, got) / (h * h) - 2.0 / (r * r * r));
    assert_near(b, r * sin(psi) / k, 1e-10, "impact parameter");
    /* No mass, or inside the horizon: the direction is returned unchanged. */
    struct model flat = schwarzschild(0.0);
    assert_vec_near(model_initial_velocity(&flat, x, dir), dir, 0.0, "M = 0");
    assert_vec_near(model_initial_velocity(&m, v3_axpy(1.5, outward, m.center), dir), dir, 0.0, "inside 2M");
}

static void test_schwarzschild_mass_to_zero(void **state)
{
    (void)state;
    struct model m = schwarzschild(1e-12);
    vec3d dir = v3_normalize(v3(1, 2, -0.5));
    /* Every term is proportional to M (or M/r for the velocity): ~1e-12 of the flat values. */
    assert_true(v3_len(model_accel(&m, v3(3, 0, 0), v3(0, 1, 0))) < 1e-12);
    assert_vec_near(model_initial_velocity(&m, v3(3, 1, 0), dir), dir, 1e-12, "velocity at M -> 0");
    assert_near(model_capture_radius(&m), 0.0, 1e-11, "horizon at M -> 0");
}

/* ---- integrators ---- */

static void test_euler_is_eq2(void **state)
{
    (void)state;
    struct model m = fixture_model(MODEL_LORENZ);
    m.sigma = 10.0;
    m.rho = 28.0;
    m.beta = 8.0 / 3.0;
    vec3d x = v3(1, 2, 3), v = v3(0.5, -1, 2);
    vec3d f = model_accel(&m, x, v);
    double h = 0.1;
    model_step(&m, METHOD_EULER, h, &x, &v);
    /* Both updates read the old state; x1 must not use v1 nor v1 use x1. */
    assert_vec_near(x, v3(1.05, 1.9, 3.2), ROUNDING_TOL, "x1");
    assert_vec_near(v, v3_axpy(h, f, v3(0.5, -1, 2)), ROUNDING_TOL, "v1");
}

/* Position after integrating a bound Yukawa orbit to time 4 with step h. */
static vec3d yukawa_orbit(enum integration_method method, double h)
{
    struct model m = yukawa(-1.0, 0.2);
    vec3d x = v3(2.0, 0.0, 0.3), v = v3(0.0, 0.6, 0.1);
    int steps = (int)lround(4.0 / h);
    for (int i = 0; i < steps; i++)
        model_step(&m, method, h, &x, &v);
    return x;
}

static double convergence_ratio(enum integration_method method, double h)
{
    vec3d exact = yukawa_orbit(METHOD_RK4, h / 64.0);
    double coarse = v3_len(v3_sub(yukawa_orbit(method, h), exact));
    double fine = v3_len(v3_sub(yukawa_orbit(method, h / 2.0), exact));
    return coarse / fine;
}

static void test_convergence_order(void **state)
{
    (void)state;
    /* Halving h divides the error by 2^order; the factor 1.5 allows for the next-order term at
     * these step sizes, far from the neighbouring orders' 8 and 32 (RK4) or 1 and 4 (Euler). */
    double rk4 = convergence_ratio(METHOD_RK4, 0.1);
    double euler = convergence_ratio(METHOD_EULER, 0.005);
    if (!(rk4 > 16.0 / 1.5 && rk4 < 16.0 * 1.5) || !(euler > 2.0 / 1.5 && euler < 2.0 * 1.5)) {
        print_error("error ratios on halving h: rk4 %g (want ~16), euler %g (want ~2)\n", rk4, euler);
        fail();
    }
}

/* ---- intersections ---- */

static void test_sphere(void **state)
{
    (void)state;
    vec3d c = v3(1, 1, 1);
    double t = -1.0;
    /* From outside through the centre: enters at distance 2 of 6. */
    assert_true(intersect_sphere(v3(-2, 1, 1), v3(4, 1, 1), c, 1.0, &t));
    assert_near(t, 1.0 / 3.0, ROUNDING_TOL, "entry");
    /* Passing at distance 1.5 > radius. */
    assert_false(intersect_sphere(v3(-2, 2.5, 1), v3(4, 2.5, 1), c, 1.0, &t));
    /* Too short to reach it. */
    assert_false(intersect_sphere(v3(-2, 1, 1), v3(-0.5, 1, 1), c, 1.0, &t));
    /* Grazing: the line touches at its midpoint (discriminant exactly 0). */
    assert_true(intersect_sphere(v3(-2, 2, 1), v3(4, 2, 1), c, 1.0, &t));
    assert_near(t, 0.5, ROUNDING_TOL, "tangent");
    assert_false(intersect_sphere(v3(-2, 2 + 1e-9, 1), v3(4, 2 + 1e-9, 1), c, 1.0, &t));
    /* Starting inside: the hit is where it leaves. */
    assert_true(intersect_sphere(c, v3(4, 1, 1), c, 1.0, &t));
    assert_near(t, 1.0 / 3.0, ROUNDING_TOL, "exit");
    /* Wholly inside, and a point segment on the surface: no crossing. */
    assert_false(intersect_sphere(c, v3(1.5, 1, 1), c, 1.0, &t));
    assert_false(intersect_sphere(v3(2, 1, 1), v3(2, 1, 1), c, 1.0, &t));
    /* A small sphere far along a long segment keeps its entry to relative precision. */
    assert_true(intersect_sphere(v3(0, 0, 0), v3(2e4, 0, 0), v3(1e4, 0, 0), 1e-3, &t));
    /* half_b^2 - dd C would cancel 16 digits down to 3 here and miss by ~1e-9. */
    assert_near(t, (1e4 - 1e-3) / 2e4, 1e-13, "far small sphere");
}

static void test_triangle(void **state)
{
    (void)state;
    vec3d p0 = v3(0, 0, 1), p1 = v3(2, 0, 1), p2 = v3(0, 2, 1);
    double t = -1, bu = -1, bv = -1;
    assert_true(intersect_triangle(v3(0.5, 0.5, 0), v3(0.5, 0.5, 4), p0, p1, p2, &t, &bu, &bv));
    assert_near(t, 0.25, ROUNDING_TOL, "t");
    assert_near(bu, 0.25, ROUNDING_TOL, "u");
    assert_near(bv, 0.25, ROUNDING_TOL, "v");
    /* From the back side too: no culling. */
    assert_true(intersect_triangle(v3(1.5, 0.25, 2), v3(1.5, 0.25, 0), p0, p1, p2, &t, &bu, &bv));
    assert_near(t, 0.5, ROUNDING_TOL, "t back");
    assert_near(bu, 0.75, ROUNDING_TOL, "u back");
    /* Outside the hypotenuse u + v > 1. */
    assert_false(intersect_triangle(v3(1.1, 1.1, 0), v3(1.1, 1.1, 4), p0, p1, p2, &t, &bu, &bv));
    /* Ends before the plane. */
    assert_false(intersect_triangle(v3(0.5, 0.5, 0), v3(0.5, 0.5, 0.9), p0, p1, p2, &t, &bu, &bv));
    /* Parallel: in the plane across the triangle, and above it. */
    assert_false(intersect_triangle(v3(-1, 0.5, 1), v3(3, 0.5, 1), p0, p1, p2, &t, &bu, &bv));
    assert_false(intersect_triangle(v3(-1, 0.5, 1.5), v3(3, 0.5, 1.5), p0, p1, p2, &t, &bu, &bv));
    /* Degenerate: collinear corners and a repeated corner have no area. */
    assert_false(intersect_triangle(v3(0.5, 0, 0), v3(0.5, 0, 4), p0, p1, v3(4, 0, 1), &t, &bu, &bv));
    assert_false(intersect_triangle(v3(0.5, 0, 0), v3(0.5, 0, 4), p0, p1, p1, &t, &bu, &bv));
}

static void test_disk(void **state)
{
    (void)state;
    vec3d c = v3(0, 0, 2), n = v3(0, 0, 3);   /* normal need not be unit */
    double t = -1;
    /* On the ring. */
    assert_true(intersect_disk(v3(1.5, 0, 0), v3(1.5, 0, 4), c, n, 1.0, 2.0, &t));
    assert_near(t, 0.5, ROUNDING_TOL, "ring");
    /* Through the hole and outside the rim. */
    assert_false(intersect_disk(v3(0.5, 0, 0), v3(0.5, 0, 4), c, n, 1.0, 2.0, &t));
    assert_false(intersect_disk(v3(2.5, 0, 0), v3(2.5, 0, 4), c, n, 1.0, 2.0, &t));
    /* Both edges of the annulus belong to it. */
    assert_true(intersect_disk(v3(1, 0, 0), v3(1, 0, 4), c, n, 1.0, 2.0, &t));
    assert_true(intersect_disk(v3(0, -2, 0), v3(0, -2, 4), c, n, 1.0, 2.0, &t));
    /* A full disk has no hole; a parallel segment and one ending short never hit. */
    assert_true(intersect_disk(v3(0, 0, 0), v3(0, 0, 4), c, n, 0.0, 2.0, &t));
    assert_false(intersect_disk(v3(-3, 0, 2), v3(3, 0, 2), c, n, 0.0, 2.0, &t));
    assert_false(intersect_disk(v3(1.5, 0, 0), v3(1.5, 0, 1.9), c, n, 1.0, 2.0, &t));
    /* Oblique crossing. */
    assert_true(intersect_disk(v3(-1, 0, 0), v3(3, 0, 4), c, n, 0.5, 2.0, &t));
    assert_near(t, 0.5, ROUNDING_TOL, "oblique");
}

static void test_rect(void **state)
{
    (void)state;
    vec3d c = v3(1, 0, 0), eu = v3(0, 2, 0), ev = v3(0, 0, 0.5);
    double t = -1, su = -9, sv = -9;
    assert_true(intersect_rect(v3(0, 1, 0.25), v3(4, 1, 0.25), c, eu, ev, &t, &su, &sv));
    assert_near(t, 0.25, ROUNDING_TOL, "t");
    assert_near(su, 0.5, ROUNDING_TOL, "s_u");
    assert_near(sv, 0.5, ROUNDING_TOL, "s_v");
    /* Edges and corner belong to it; just beyond each edge does not. */
    assert_true(intersect_rect(v3(0, 2, -0.5), v3(2, 2, -0.5), c, eu, ev, &t, &su, &sv));
    assert_near(su, 1.0, ROUNDING_TOL, "corner s_u");
    assert_near(sv, -1.0, ROUNDING_TOL, "corner s_v");
    assert_false(intersect_rect(v3(0, 2.001, 0), v3(2, 2.001, 0), c, eu, ev, &t, &su, &sv));
    assert_false(intersect_rect(v3(0, -2.001, 0), v3(2, -2.001, 0), c, eu, ev, &t, &su, &sv));
    assert_false(intersect_rect(v3(0, 0, 0.501), v3(2, 0, 0.501), c, eu, ev, &t, &su, &sv));
    assert_false(intersect_rect(v3(0, 0, -0.501), v3(2, 0, -0.501), c, eu, ev, &t, &su, &sv));
    /* Parallel to the plane, and too short. */
    assert_false(intersect_rect(v3(1, -3, 0), v3(1, 3, 0), c, eu, ev, &t, &su, &sv));
    assert_false(intersect_rect(v3(0, 0, 0), v3(0.99, 0, 0), c, eu, ev, &t, &su, &sv));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_names),
        cmocka_unit_test(test_flat),
        cmocka_unit_test(test_lorenz_value),
        cmocka_unit_test(test_rossler_value),
        cmocka_unit_test(test_yukawa_value_and_sign),
        cmocka_unit_test(test_yukawa_is_minus_gradient),
        cmocka_unit_test(test_polynomial_profile),
        cmocka_unit_test(test_refraction_value),
        cmocka_unit_test(test_refraction_is_n_grad_n),
        cmocka_unit_test(test_schwarzschild_value),
        cmocka_unit_test(test_schwarzschild_conserves_h),
        cmocka_unit_test(test_schwarzschild_weak_deflection),
        cmocka_unit_test(test_schwarzschild_exact_deflection),
        cmocka_unit_test(test_schwarzschild_shadow_edge),
        cmocka_unit_test(test_schwarzschild_initial_velocity),
        cmocka_unit_test(test_schwarzschild_mass_to_zero),
        cmocka_unit_test(test_euler_is_eq2),
        cmocka_unit_test(test_convergence_order),
        cmocka_unit_test(test_sphere),
        cmocka_unit_test(test_triangle),
        cmocka_unit_test(test_disk),
        cmocka_unit_test(test_rect),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
