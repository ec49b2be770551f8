/* The Schwarzschild orbit table (src/physics/orbit_table.c) against closed forms: the swept angle of
 * each kind of orbit (escaping outwards with and without a turning point, escaping after its
 * periapsis, captured, next to the critical angle) by Darwin's elliptic integral or by quadrature
 * (tests/unit/binet_closed_form.h), and what its float, interpolated form loses between rows.
 * M = 1 unless said. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "binet_closed_form.h"
#include "physics/escape.h"
#include "physics/orbit_table.h"

static const double pi = 3.14159265358979323846;

/* The 1e-9 rad, and next to the critical angle the orbit's own condition: phi_end grows
 * as -ln|psi - psi_c|, so neighbouring orbits part as 1 / |psi - psi_c| and the integrator's
 * per-step tolerance (1e-12) is magnified by it (measured: 5e-15 / |psi - psi_c| rad, which the
 * double launch angle's own rounding, 3e-16 rad, already makes 1e-9 at 3e-7 rad from psi_c). */
static double critical_bound(double distance)
{
    return 1e-9 + 1e-14 / distance;
}

static double inv_b2_of(double mass, double r_o, double psi)
{
    /* b = r_o sin psi / sqrt(1 - 2M / r_o) */
    double s = sin(psi) * r_o;
    return (1.0 - 2.0 * mass / r_o) / (s * s);
}

/* int_{ua}^{ub} du / sqrt(P(u)) where P has no root in [ua, ub] (no turning point). */
struct direct_args { double mass, inv_b2; };

static double direct_integrand(double u, void *arg)
{
    const struct direct_args *a = arg;
    return 1.0 / sqrt(binet_p_m(a->mass, a->inv_b2, u));
}

static double direct_sweep(double mass, double inv_b2, double ua, double ub)
{
    struct direct_args a = {mass, inv_b2};
    gsl_function f = {direct_integrand, &a};
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(1000);
    double result = NAN, error = NAN;
    int status = gsl_integration_qags(&f, ua, ub, 0.0, 1e-13, 1000, ws, &result, &error);
    gsl_integration_workspace_free(ws);
    assert_int_equal(status, 0);
    return result;
}

/* The closed-form swept angle from the observer to u_end for launch angle psi. */
static double exact_phi_end(double mass, double r_o, double psi, double u_end)
{
    double inv_b2 = inv_b2_of(mass, r_o, psi), u_o = 1.0 / r_o;
    double b = 1.0 / sqrt(inv_b2), b_c = 3.0 * sqrt(3.0) * mass;
    int outward = psi < 0.5 * pi;
    if (b < b_c)     /* no turning point: one monotonic stretch */
        return outward == (u_end < u_o) ? direct_sweep(mass, inv_b2, fmin(u_o, u_end), fmax(u_o, u_end)) : NAN;
    struct binet_roots r = binet_roots_m(mass, inv_b2);
    if (r_o > 3.0 * mass)   /* the turning point is a periapsis inside r_o */
        return outward ? darwin_sweep_m(mass, &r, u_end) - darwin_sweep_m(mass, &r, u_o)
                       : darwin_sweep_m(mass, &r, u_o) + darwin_sweep_m(mass, &r, u_end);
    return NAN;   /* inside the photon sphere with b > b_c: an apoapsis, not tested by this form */
}

static void test_orbits_against_closed_forms(void **state)
{
    (void)state;
    const double mass = 1.0, r_far = 60.0;
    struct { double r_o, psi; const char *what; } cases[] = {
        {10.0, 0.2, "outward, no turning point"},
        {10.0, 0.4, "outward, no turning point"},
        {10.0, 1.0, "outward, b > b_c"},
        {10.0, 1.5, "outward, nearly tangential"},
        {10.0, 2.0, "inward, periapsis"},
        {10.0, 2.5, "inward, periapsis"},
        {10.0, 3.0, "inward, captured"},
        {10.0, 3.1415, "inward, nearly radial, captured"},
        {10.0, 1e-5, "outward, nearly radial"},
        {1000.0, 0.5, "far observer"},
        {1000.0, 3.1380, "far observer, periapsis"},
        {2.5, 0.3, "inside the photon sphere, escapes"},
        {2.5, 2.0, "inside the photon sphere, captured"},
        {2.01, 0.05, "next to the horizon, escapes"},
    };
    int bad = 0;
    print_message("%8s %10s %24s %24s %10s  %s\n", "r_o/M", "psi", "phi_end (table's trace)", "closed form", "diff",
                  "orbit");
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double r_o = cases[i].r_o, psi = cases[i].psi, rf = r_o < r_far ? r_far : 2.0 * r_o;
        double u_far = 1.0 / rf, u_cap = 1.0 / (2.0 * mass * (1.0 - ORBIT_HORIZON_MARGIN));
        double phi_end;
        int captured;
        assert_int_equal(orbit_trace(mass, r_o, psi, u_far, u_cap, NULL, 0, NULL, NULL, &phi_end, &captured), 0);
        double psi_c = orbit_critical_angle(mass, r_o);
        assert_int_equal(captured, psi > psi_c);
        double exact = exact_phi_end(mass, r_o, psi, captured ? u_cap : u_far);
        double diff = phi_end - exact;
        print_message("%8g %10.6g %24.17g %24.17g %10.2e  %s\n", r_o, psi, phi_end, exact, diff, cases[i].what);
        /* the bound: the tables' orbits to 1e-9 rad of the closed forms */
        if (!isnan(exact) && !(fabs(diff) <= 1e-9)) {
            print_error("r_o %g psi %g: swept %.17g, exact %.17g\n", r_o, psi, phi_end, exact);
            bad++;
        }
    }
    assert_int_equal(bad, 0);
}

/* Points along one orbit: the swept angle at each sampled u, against the closed form. */
static void test_orbit_points_against_darwin(void **state)
{
    (void)state;
    const double mass = 1.0, r_o = 10.0, u_o = 0.1, u_far = 1.0 / 60.0;
    double psi_c = orbit_critical_angle(mass, r_o);
    const double psis[] = {2.0, psi_c - 1e-3, psi_c - 1e-6};
    int bad = 0;
    for (int c = 0; c < 3; c++) {
        double psi = psis[c], phi_end;
        int captured;
        assert_int_equal(orbit_trace(mass, r_o, psi, u_far, 1.0 / 2.0, NULL, 0, NULL, NULL, &phi_end, &captured), 0);
        enum { N = 64 };
        double at[N], u[N], du[N];
        for (int i = 0; i < N; i++)
            at[i] = phi_end * (i + 0.5) / N;
        assert_int_equal(orbit_trace(mass, r_o, psi, u_far, 1.0 / 2.0, at, N, u, du, &phi_end, &captured), 0);
        struct binet_roots r = binet_roots_m(mass, inv_b2_of(mass, r_o, psi));
        double worst = 0.0;
        for (int i = 0; i < N; i++) {
            /* near the periapsis du/dphi vanishes and phi(u) is ill-conditioned: skip it there */
            if (fabs(du[i]) < 0.05 * u[i])
                continue;
            double exact = du[i] > 0.0 ? darwin_sweep_m(mass, &r, u_o) - darwin_sweep_m(mass, &r, u[i])
                                       : darwin_sweep_m(mass, &r, u_o) + darwin_sweep_m(mass, &r, u[i]);
            worst = fmax(worst, fabs(exact - at[i]));
        }
        print_message("psi_c - psi = %.3g: phi_end %.12g, worst point off Darwin's orbit by %.2e rad\n", psi_c - psi,
                      phi_end, worst);
        /* the resampling between the integrator's steps keeps the integration's 1e-9 */
        if (!(worst <= critical_bound(psi_c - psi)))
            bad++;
    }
    assert_int_equal(bad, 0);
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static struct orbit_table_params params(double mass, double r_o, double r_far, int rows, int columns)
{
    struct orbit_table_params p = {mass, r_o, r_far, rows, columns, INFINITY, 1, 0.0};
    return p;
}

static void test_table_rows_exact(void **state)
{
    (void)state;
    struct orbit_table t;
    struct error err;
    struct orbit_table_params p = params(1.0, 10.0, 60.0, 256, 64);
    assert_int_equal(orbit_table_build(&t, &p, &err), 0);
    print_message("table 2 x 256 rows x 64 columns built in %.1f ms\n", 1e3 * t.build_seconds);
    int bad = 0;
    for (int row = 0; row < t.height; row += 17) {
        int captured = row >= p.rows_per_side;
        double phi_end = t.phi_over_sin[row] * sin(t.psi[row]);
        double exact = exact_phi_end(1.0, 10.0, t.psi[row], captured ? t.u_capture : t.u_far);
        if (!isnan(exact) && !(fabs(phi_end - exact) <= critical_bound(fabs(t.psi[row] - t.psi_c)))) {
            print_error("row %d psi %.17g: %.17g, exact %.17g\n", row, t.psi[row], phi_end, exact);
            bad++;
        }
        /* the first sample is the observer, the last the orbit's end */
        assert_true(fabs(t.u[(size_t)row * p.columns] - 0.1) < 1e-15);
        double u_end = t.u[(size_t)row * p.columns + p.columns - 1];
        assert_true(fabs(u_end - (captured ? t.u_capture : t.u_far)) < 1e-12 * u_end);
    }
    assert_int_equal(bad, 0);
    orbit_table_free(&t);
}

/* What the float table loses between its rows and columns, as the shader interpolates it: the
 * swept angle and the point reached at s = 1/3 and at the end, for launch angles between rows. */
static void interpolation_error(double mass, double r_o, int rows, int columns, double *phi_p99, double *pos_p99,
                                double *seconds)
{
    struct orbit_table t;
    struct error err;
    struct orbit_table_params p = params(mass, r_o, fmax(60.0, 2.0 * r_o) * mass, rows, columns);
    assert_int_equal(orbit_table_build(&t, &p, &err), 0);
    *seconds = t.build_seconds;
    enum { N = 400 };
    double ephi[N], epos[N];
    srand(7);
    for (int i = 0; i < N; i++) {
        double psi = (i + (double)rand() / RAND_MAX) / N * pi;
        double phi_end;
        int segments, captured;
        struct orbit_point q;
        double at = 0.0, u_exact, du_exact, phi_exact;
        assert_int_equal(orbit_trace(mass, r_o, psi, t.u_far, t.u_capture, NULL, 0, NULL, NULL, &phi_exact, &captured), 0);
        at = phi_exact / 3.0;
        assert_int_equal(orbit_trace(mass, r_o, psi, t.u_far, t.u_capture, &at, 1, &u_exact, &du_exact, &phi_exact,
                                     &captured), 0);
        orbit_table_eval(&t, psi, 1.0 / 3.0, &q, &phi_end, &segments);
        ephi[i] = fabs(phi_end - phi_exact);
        /* distance between the two points of the orbit plane, relative to the radius */
        double x0 = cos(at) / u_exact, y0 = sin(at) / u_exact, x1 = cos(q.phi) / q.u, y1 = sin(q.phi) / q.u;
        epos[i] = hypot(x1 - x0, y1 - y0) * u_exact;
    }
    qsort(ephi, N, sizeof *ephi, cmp);
    qsort(epos, N, sizeof *epos, cmp);
    *phi_p99 = ephi[(int)(0.99 * N)];
    *pos_p99 = epos[(int)(0.99 * N)];
    orbit_table_free(&t);
}


static void test_table_interpolation(void **state)
{
    (void)state;
    const double observers[] = {2.01, 2.5, 5.0, 10.0, 75.0, 1000.0};
    print_message("%8s %12s %12s %10s\n", "r_o/M", "phi_end p99", "point p99", "build ms");
    for (int i = 0; i < 6; i++) {
        double phi99, pos99, seconds;
        interpolation_error(1.0, observers[i], 1024, 256, &phi99, &pos99, &seconds);
        print_message("%8g %12.2e %12.2e %10.1f\n", observers[i], phi99, pos99, 1e3 * seconds);
        /* measured 1e-7 to 2e-7 (the float texels' own rounding: phi_end is stored as a float);
         * 1e-5 rad is the target for exit directions, and the table keeps well inside it */
        assert_true(phi99 <= 2e-6);
        assert_true(pos99 <= 2e-6);
    }
}

/* The angle swept on to infinity (physics/escape.h), from the observer itself and from a table's
 * rows, against the closed forms with u_end = 0: outwards with and without a periapsis, inwards
 * past one, nearly tangential, next to the critical angle; light that falls in has none. */
static void test_sweep_to_infinity(void **state)
{
    (void)state;
    const double mass = 1.0;
    struct { double r_o, psi; } cases[] = {
        {10.0, 0.2}, {10.0, 1.0}, {10.0, 1.5}, {10.0, 2.0}, {10.0, 2.5}, {1000.0, 0.5}, {1000.0, 3.13},
        {30.0, 1.5707}, {2.5, 0.3}, {2.01, 0.05}, {50.0, 3.0}, {10.0, 1e-5},
    };
    int bad = 0;
    print_message("%8s %10s %24s %24s %10s\n", "r_o/M", "psi", "escape_sweep", "closed form", "diff");
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double r_o = cases[i].r_o, psi = cases[i].psi, u = 1.0 / r_o;
        double w = -u * sqrt(1.0 - 2.0 * mass * u) * cos(psi) / sin(psi);
        double sweep = escape_sweep(mass, u, w), exact = exact_phi_end(mass, r_o, psi, 0.0);
        print_message("%8g %10.6g %24.17g %24.17g %10.2e\n", r_o, psi, sweep, exact, sweep - exact);
        if (isnan(exact) || !(fabs(sweep - exact) <= 1e-11 * fmax(1.0, exact))) {
            print_error("r_o %g psi %g: swept %.17g, exact %.17g\n", r_o, psi, sweep, exact);
            bad++;
        }
    }
    assert_int_equal(bad, 0);
    /* falling in: inwards with b < b_c, and outwards inside the photon sphere's barrier */
    assert_true(escape_sweep(mass, 0.1, 0.5) < 0.0);
    assert_true(escape_sweep(mass, 1.0 / 2.2, 0.01) < 0.0);
    /* flat space: the straight line's own angle */
    assert_true(fabs(escape_sweep(0.0, 0.1, -0.1 / tan(0.7)) - 0.7) < 1e-14);
    /* the table's rows: phi_end to r_far and on, against the closed form to infinity */
    struct orbit_table t;
    struct error err;
    struct orbit_table_params p = params(mass, 10.0, 60.0, 256, 64);
    assert_int_equal(orbit_table_build(&t, &p, &err), 0);
    for (int row = 0; row < p.rows_per_side; row += 7) {
        double phi = t.phi_infinity_over_sin[row] * sin(t.psi[row]), exact = exact_phi_end(mass, 10.0, t.psi[row], 0.0);
        if (!(fabs(phi - exact) <= critical_bound(fabs(t.psi[row] - t.psi_c)))) {
            print_error("row %d psi %.17g: to infinity %.17g, exact %.17g\n", row, t.psi[row], phi, exact);
            bad++;
        }
    }
    assert_int_equal(bad, 0);
    orbit_table_free(&t);
}

/* Each row's chord schedule against its own orbit, traced directly (not through the table or the
 * schedule's own sampling): the largest distance of the orbit from its n chords, measured at 32
 * points a chord, stays within the chord tolerance. Slack 2%: the schedule measures 7 points a
 * chord and the table keeps its chord ends in float. On both sides of the critical angle, for an
 * observer near the photon sphere and one far out, and with a clear radius (only points outside
 * it count). */
static void test_chord_schedule_holds_tolerance(void **state)
{
    (void)state;
    static const struct { double r_o, clear; } cases[] = {{10.0, 0.0}, {3.2, 0.0}, {40.0, 4.0}};
    enum { inner = 32 };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        struct orbit_table t;
        struct error err;
        struct orbit_table_params p = params(1.0, cases[c].r_o, 60.0 + cases[c].r_o, 64, 64);
        p.chord_tolerance = 1e-3;
        p.max_segments = 1000;
        p.clear_radius = cases[c].clear;
        assert_int_equal(orbit_table_build(&t, &p, &err), 0);
        double worst = 0.0;
        long chords = 0;
        for (int row = 3; row < t.height; row += 7) {
            double psi = t.psi[row], phi_end = t.phi_over_sin[row] * sin(psi);
            int n = t.segments[row];
            assert_true(n >= 1 && n < p.max_segments);
            chords += n;
            size_t count = (size_t)n * inner + 1;
            double *phi = malloc(count * sizeof *phi), *u = malloc(count * sizeof *u), *du = malloc(count * sizeof *du);
            assert_non_null(phi);
            assert_non_null(u);
            assert_non_null(du);
            for (int k = 0; k < n; k++) {
                double s_a = orbit_table_chord_end(&t, psi, k, n), s_b = orbit_table_chord_end(&t, psi, k + 1, n);
                for (int j = 0; j < inner; j++)
                    phi[(size_t)k * inner + j] = fmin(phi_end * (s_a + (s_b - s_a) * j / inner), phi_end);
            }
            phi[count - 1] = phi_end;
            double traced_end;
            int captured;
            assert_int_equal(orbit_trace(1.0, cases[c].r_o, psi, t.u_far, t.u_capture, phi, (int)count, u, du,
                                         &traced_end, &captured), 0);
            for (int k = 0; k < n; k++) {
                size_t a = (size_t)k * inner, b = a + inner;
                double ax = cos(phi[a]) / u[a], ay = sin(phi[a]) / u[a];
                double dx = cos(phi[b]) / u[b] - ax, dy = sin(phi[b]) / u[b] - ay, len = hypot(dx, dy);
                for (size_t j = a + 1; j < b; j++) {
                    if (p.clear_radius > 0.0 && 1.0 / u[j] < p.clear_radius)
                        continue;
                    double x = cos(phi[j]) / u[j] - ax, y = sin(phi[j]) / u[j] - ay;
                    worst = fmax(worst, fabs(x * dy - y * dx) / len);
                }
            }
            free(phi);
            free(u);
            free(du);
        }
        print_message("r_o %g, clear radius %g: %ld chords of %d rows, farthest from the orbit %.3g (tolerance %g); "
                      "built in %.1f ms\n", cases[c].r_o, cases[c].clear, chords, (t.height - 3 + 6) / 7, worst,
                      p.chord_tolerance, 1e3 * t.build_seconds);
        assert_true(worst <= 1.02 * p.chord_tolerance);
        assert_true(worst >= 0.3 * p.chord_tolerance);   /* not needlessly many chords */
        orbit_table_free(&t);
    }
}

static void test_refuses_bad_parameters(void **state)
{
    (void)state;
    struct orbit_table t;
    struct error err;
    struct orbit_table_params p = params(1.0, 1.5, 60.0, 16, 16);   /* inside the horizon */
    assert_int_equal(orbit_table_build(&t, &p, &err), -1);
    p = params(0.0, 10.0, 60.0, 16, 16);
    assert_int_equal(orbit_table_build(&t, &p, &err), -1);
    p = params(1.0, 10.0, 5.0, 16, 16);                             /* r_far inside the observer */
    assert_int_equal(orbit_table_build(&t, &p, &err), -1);
    assert_int_equal(err.status, ERROR_RUNTIME);
    assert_non_null(strstr(err.message, "orbit table: needs M > 0"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_orbits_against_closed_forms),
        cmocka_unit_test(test_orbit_points_against_darwin),
        cmocka_unit_test(test_table_rows_exact),
        cmocka_unit_test(test_sweep_to_infinity),
        cmocka_unit_test(test_table_interpolation),
        cmocka_unit_test(test_chord_schedule_holds_tolerance),
        cmocka_unit_test(test_refuses_bad_parameters),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
