/* Closed forms of the Schwarzschild photon orbit for the tests: u = 1/r obeys
 * (du/dphi)^2 = P(u) = 1/b^2 - u^2 + 2 M u^3. Darwin's elliptic-integral form of the swept angle
 * (evaluated with GSL) and an adaptive quadrature of the same integral that shares nothing with it
 * but the turning point. */
#ifndef BT_TEST_BINET_CLOSED_FORM_H
#define BT_TEST_BINET_CLOSED_FORM_H
#include <math.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_ellint.h>

static const double binet_pi = 3.14159265358979323846;

static inline double binet_p_m(double hole_mass, double inv_b2, double u)
{
    return inv_b2 - u * u + 2.0 * hole_mass * u * u * u;
}

/* Roots u1 < 0 < u2 < u3 of P for b > 3 sqrt(3) M (the ray turns at u2), with their differences
 * from closed forms so that none is formed by cancellation near the critical impact parameter.
 * Trigonometric solution: sin(theta / 2) = 3 sqrt(3) M / b, u_k = (1 + 2 cos(theta/3 - 2 pi k/3)) / 6M. */
struct binet_roots { double u1, u2, u3, d32, d21, d31; };

static inline struct binet_roots binet_roots_m(double hole_mass, double inv_b2)
{
    double s2 = 27.0 * hole_mass * hole_mass * inv_b2;
    double theta = 2.0 * atan2(sqrt(s2), sqrt(1.0 - s2));
    double rest = 2.0 * atan2(sqrt(1.0 - s2), sqrt(s2));   /* pi - theta without cancellation */
    double t = theta / 6.0, k = 2.0 / (3.0 * hole_mass), d = 1.0 / (sqrt(3.0) * hole_mass);
    struct binet_roots r;
    r.u3 = k * sin(binet_pi / 3.0 + t) * sin(binet_pi / 3.0 - t);
    r.u2 = k * sin(t) * sin(2.0 * binet_pi / 3.0 - t);
    r.u1 = -k * sin(t) * sin(2.0 * binet_pi / 3.0 + t);
    r.d32 = d * sin(rest / 3.0);
    r.d21 = d * sin(theta / 3.0);
    r.d31 = d * sin(theta / 3.0 + binet_pi / 3.0);
    return r;
}

/* Darwin: phi swept from radius 1/u to the turning point,
 * int_u^u2 dt / sqrt(2M (t - u1)(u2 - t)(u3 - t)) = (2 / sqrt(2M (u3 - u1))) F(varphi, k) with
 * k^2 = (u2 - u1)/(u3 - u1), sin^2 varphi = (u3 - u1)(u2 - u) / ((u2 - u1)(u3 - u)) and
 * cos^2 varphi = (u3 - u2)(u - u1) / ((u2 - u1)(u3 - u)) (Byrd & Friedman 233.00). */
static inline double darwin_sweep_m(double hole_mass, const struct binet_roots *r, double u)
{
    double varphi = atan2(sqrt(r->d31 * (r->u2 - u)), sqrt(r->d32 * (u - r->u1)));
    double k = sqrt(r->d21 / r->d31);
    return 2.0 / sqrt(2.0 * hole_mass * r->d31) * gsl_sf_ellint_F(varphi, k, GSL_PREC_DOUBLE);
}

/* The same integral by adaptive quadrature, sharing nothing with the elliptic reduction but the
 * turning point: t = u2 - (u2 - u) w^2 and P(t) = (u2 - t) g(t) with
 * g(t) = t + u2 - 2M (t^2 + t u2 + u2^2) (as P(u2) = 0) leave a smooth integrand on [0, 1]. */
struct quad_args { double u, u2, hole_mass; };

static inline double sweep_integrand(double w, void *arg)
{
    const struct quad_args *a = arg;
    double hole_mass = a->hole_mass;
    double t = a->u2 - (a->u2 - a->u) * w * w;
    double g = t + a->u2 - 2.0 * hole_mass * (t * t + t * a->u2 + a->u2 * a->u2);
    return 2.0 * sqrt(a->u2 - a->u) / sqrt(g);
}

static inline double quadrature_sweep_m(double hole_mass, double u2, double u)
{
    struct quad_args a = {u, u2, hole_mass};
    gsl_function f = {sweep_integrand, &a};
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(1000);
    double result = NAN, error = NAN;
    int status = gsl_integration_qags(&f, 0.0, 1.0, 0.0, 1e-13, 1000, ws, &result, &error);
    gsl_integration_workspace_free(ws);
    return status == 0 ? result : NAN;
}

#endif
