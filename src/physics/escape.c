/* Where light goes once it has left the scene (escape.h). */
#include "physics/escape.h"
#include <math.h>

static const double pi = 3.14159265358979323846;

/* Gauss-Legendre, 16 nodes on [-1, 1]: the positive half (the rule is symmetric). */
static const double gl_node[8] = {0.98940093499164994, 0.9445750230732326,  0.86563120238783176,
                                  0.755404408355003,   0.61787624440264377, 0.45801677765722737,
                                  0.28160355077925892, 0.095012509837637441};
static const double gl_weight[8] = {0.027152459411754058, 0.062253523938647776, 0.095158511682492897,
                                    0.12462897125553395,  0.14959598881657682,  0.16915651939500256,
                                    0.18260341504492361,  0.18945061045506847};

/* The integrands: in theta past a periapsis u_t, in u without one (inverse impact parameter p). */
struct integrand {
    double mass, u_t, p2;
    int in_theta;
};

static double integrand_at(const struct integrand *f, double t)
{
    if (f->in_theta) {
        double s = sin(t);
        return 1.0 / sqrt(1.0 - 2.0 * f->mass * f->u_t * (1.0 + s + s * s) / (1.0 + s));
    }
    return 1.0 / sqrt(f->p2 - t * t + 2.0 * f->mass * t * t * t);
}

static double panels(const struct integrand *f, double a, double b, int n)
{
    double sum = 0.0, h = (b - a) / n;
    for (int k = 0; k < n; k++) {
        double mid = a + (k + 0.5) * h, half = 0.5 * h;
        for (int i = 0; i < 8; i++)
            sum += gl_weight[i] * half * (integrand_at(f, mid - half * gl_node[i]) + integrand_at(f, mid + half * gl_node[i]));
    }
    return sum;
}

/* int_a^b of the integrand: panels doubled until two agree to 1e-14 (the integrands are smooth;
 * they peak only next to the critical impact parameter). */
static double integrate(const struct integrand *f, double a, double b)
{
    if (!(b > a))
        return 0.0;
    double prev = panels(f, a, b, 1);
    for (int n = 2; n <= 4096; n *= 2) {
        double cur = panels(f, a, b, n);
        if (fabs(cur - prev) <= 1e-14 * fabs(cur))
            return cur;
        prev = cur;
    }
    return prev;
}

double escape_sweep(double mass, double u, double w)
{
    double p2 = w * w + u * u - 2.0 * mass * u * u * u;
    if (!(p2 > 0.0) || !(u >= 0.0))
        return -1.0;
    double p = sqrt(p2), b_c = 3.0 * sqrt(3.0) * mass;
    int outwards = w <= 0.0;
    if (mass > 0.0 && 1.0 / p <= b_c) {
        /* no turning point: outwards it escapes through a monotonic stretch, inwards it falls in */
        if (!outwards)
            return -1.0;
        struct integrand f = {mass, 0.0, p2, 0};
        return integrate(&f, 0.0, u);
    }
    /* the periapsis u_t: the root of u^2 - 2 M u^3 = p^2 between p and 1 / (3M), by bisection */
    double lo = p, hi = mass > 0.0 ? 1.0 / (3.0 * mass) : p;
    for (int i = 0; i < 200 && hi > lo; i++) {
        double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi)
            break;
        if (mid * mid - 2.0 * mass * mid * mid * mid < p2)
            lo = mid;
        else
            hi = mid;
    }
    double u_t = mass > 0.0 ? hi : p;
    /* beyond the barrier (inside the photon sphere): turned back into the horizon */
    if (u > u_t * (1.0 + 1e-12))
        return -1.0;
    struct integrand f = {mass, u_t, p2, 1};
    double theta = asin(fmin(u / u_t, 1.0));
    double from_here = integrate(&f, 0.0, theta);
    return outwards ? from_here : 2.0 * integrate(&f, 0.0, 0.5 * pi) - from_here;
}

int escape_direction(double mass, vec3d centre, vec3d x, vec3d v, vec3d *out)
{
    vec3d d = v3_normalize(v), y = v3_sub(x, centre);
    *out = d;
    double r = v3_len(y);
    if (!(mass > 0.0) || !(r > 0.0))
        return 0;
    vec3d radial = v3_scale(y, 1.0 / r);
    double along = v3_dot(d, radial);
    vec3d across = v3_sub(d, v3_scale(radial, along));
    double across_len = v3_len(across);
    if (!(across_len > 0.0))
        return 0;
    double u = 1.0 / r, w = -u * along / across_len;
    double sweep = escape_sweep(mass, u, w);
    if (sweep < 0.0)
        return 0;
    vec3d around = v3_scale(across, 1.0 / across_len);
    *out = v3_add(v3_scale(radial, cos(sweep)), v3_scale(around, sin(sweep)));
    return 1;
}
