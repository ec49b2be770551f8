/* Photon orbits of Schwarzschild space tabulated for a static observer (orbit_table.h). */
#include "io/clock.h"
#include "io/parallel.h"
#include "physics/orbit_table.h"
#include "physics/dormand_prince.h"
#include "physics/escape.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double pi = 3.14159265358979323846;

/* Largest step in phi: the quintic Hermite resampling between accepted steps stays below the
 * integration tolerance with it (rad). */
#define ORBIT_STEP_MAX 0.05
/* An orbit that has not ended after this many steps or this much angle is refused (it would be
 * a critical orbit, which the row spacing keeps out). */
#define ORBIT_MAX_STEPS 200000
#define ORBIT_MAX_SWEEP 2000.0
/* threads that build the rows */
#define ORBIT_MAX_THREADS 8

/* ---- Binet's equation in phi: y = (u, w = du/dphi), y' = (w, 3 M u^2 - u) ---- */

static double binet_accel(double mass, double u)
{
    return 3.0 * mass * u * u - u;
}

/* One Dormand-Prince 5(4) step of size h: the fifth-order state and its error estimate. */
static void binet_step(double mass, double u, double w, double h, double *u1, double *w1, double *eu, double *ew)
{
    double ku[7], kw[7];
    const double (*a)[6] = dormand_prince_a;
    const double *e = dormand_prince_e;
    ku[0] = w;
    kw[0] = binet_accel(mass, u);
    for (int s = 1; s < 7; s++) {
        double us = u, ws = w;
        for (int j = 0; j < s; j++) {
            us += h * a[s - 1][j] * ku[j];
            ws += h * a[s - 1][j] * kw[j];
        }
        ku[s] = ws;
        kw[s] = binet_accel(mass, us);
        if (s == 6) {
            *u1 = us;
            *w1 = ws;
        }
    }
    *eu = 0.0;
    *ew = 0.0;
    for (int s = 0; s < 7; s++) {
        *eu += h * e[s] * ku[s];
        *ew += h * e[s] * kw[s];
    }
}

/* The same system with u as the independent variable, z = (phi, w): phi' = 1 / w,
 * w' = (3 M u^2 - u) / w. Classical RK4 substeps carry a step that crossed the orbit's end to the
 * exact end radius (Henon's trick). */
static void binet_in_u(double mass, double u0, double u_end, double *phi, double *w)
{
    const int substeps = 16;
    double du = (u_end - u0) / substeps;
    for (int i = 0; i < substeps; i++) {
        double u = u0 + i * du;
        double p = *phi, q = *w;
        double k1p = 1.0 / q, k1w = binet_accel(mass, u) / q;
        double q2 = q + 0.5 * du * k1w;
        double k2p = 1.0 / q2, k2w = binet_accel(mass, u + 0.5 * du) / q2;
        double q3 = q + 0.5 * du * k2w;
        double k3p = 1.0 / q3, k3w = binet_accel(mass, u + 0.5 * du) / q3;
        double q4 = q + du * k3w;
        double k4p = 1.0 / q4, k4w = binet_accel(mass, u + du) / q4;
        *phi = p + du / 6.0 * (k1p + 2.0 * k2p + 2.0 * k3p + k4p);
        *w = q + du / 6.0 * (k1w + 2.0 * k2w + 2.0 * k3w + k4w);
    }
}

/* The accepted steps of one orbit: knots (phi, u, w). */
struct orbit_knots {
    double *phi, *u, *w;
    double *a;                    /* u'' = binet_accel(mass, u) at each knot, for the interpolant */
    int n, cap;
    double mass;
    int hint;                     /* the step of the last evaluation: evaluations mostly move on */
    /* the interpolant of one step as a polynomial in t (knots_sag_u): its step, start, 1 / length
     * and coefficients of t^0 .. t^5 */
    int power_step;
    double power_phi, power_inv_h, power[6];
};

static int knots_push(struct orbit_knots *k, double phi, double u, double w)
{
    if (k->n == k->cap) {
        int cap = k->cap ? 2 * k->cap : 256;
        double *p = realloc(k->phi, cap * sizeof *p);
        if (p)
            k->phi = p;
        double *uu = p ? realloc(k->u, cap * sizeof *uu) : NULL;
        if (uu)
            k->u = uu;
        double *ww = uu ? realloc(k->w, cap * sizeof *ww) : NULL;
        if (ww)
            k->w = ww;
        double *aa = ww ? realloc(k->a, cap * sizeof *aa) : NULL;
        if (!aa)
            return -1;
        k->a = aa;
        k->cap = cap;
    }
    k->phi[k->n] = phi;
    k->u[k->n] = u;
    k->w[k->n] = w;
    k->a[k->n] = binet_accel(k->mass, u);
    k->n++;
    return 0;
}

static void knots_free(struct orbit_knots *k)
{
    free(k->phi);
    free(k->u);
    free(k->w);
    free(k->a);
    memset(k, 0, sizeof *k);
}

/* The knots' step [lo, lo + 1] that holds phi, or -1 (below the first knot) or -2 (beyond the last). */
static int knots_locate(struct orbit_knots *k, double phi)
{
    int lo = 0, hi = k->n - 1;
    if (phi <= k->phi[0])
        return -1;
    if (phi >= k->phi[hi])
        return -2;
    int last = k->hint;
    if (last >= 0 && last + 1 < k->n && k->phi[last] <= phi && phi < k->phi[last + 1]) {
        lo = last;
        hi = last + 1;
    } else if (last >= 0 && last + 2 < k->n && k->phi[last + 1] <= phi && phi < k->phi[last + 2]) {
        lo = last + 1;
        hi = last + 2;
    }
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (k->phi[mid] <= phi)
            lo = mid;
        else
            hi = mid;
    }
    k->hint = lo;
    return lo;
}

/* u at phi in step lo: quintic Hermite through the knots' u, u' and u'' = 3 M u^2 - u, which
 * keeps the integration's order between the steps. */
static double knots_u(const struct orbit_knots *k, int lo, double phi, double *t_out)
{
    int hi = lo + 1;
    double h = k->phi[hi] - k->phi[lo];
    double t = (phi - k->phi[lo]) / h, t2 = t * t, t3 = t2 * t, t4 = t3 * t, t5 = t4 * t;
    double h0 = 1 - 10 * t3 + 15 * t4 - 6 * t5, h1 = t - 6 * t3 + 8 * t4 - 3 * t5,
           h2 = 0.5 * (t2 - 3 * t3 + 3 * t4 - t5), h3 = 10 * t3 - 15 * t4 + 6 * t5, h4 = -4 * t3 + 7 * t4 - 3 * t5,
           h5 = 0.5 * (t3 - 2 * t4 + t5);
    *t_out = t;
    return h0 * k->u[lo] + h1 * h * k->w[lo] + h2 * h * h * k->a[lo] + h3 * k->u[hi] + h4 * h * k->w[hi] +
           h5 * h * h * k->a[hi];
}

/* u alone at phi, knots_u's interpolant written as a polynomial in t and evaluated by Horner's
 * rule, its coefficients kept from one call to the next in the same step: what the chords' sag
 * measures, many points a step (not the table's samples, which knots_eval gives). The same
 * quintic; its roundings differ from knots_u's by parts in 1e16. */
static double knots_sag_u(struct orbit_knots *k, double phi)
{
    int lo = knots_locate(k, phi);
    if (lo < 0)
        return lo == -1 ? k->u[0] : k->u[k->n - 1];
    if (lo != k->power_step) {
        int hi = lo + 1;
        double h = k->phi[hi] - k->phi[lo];
        double u0 = k->u[lo], w0 = h * k->w[lo], a0 = h * h * k->a[lo];
        double u1 = k->u[hi], w1 = h * k->w[hi], a1 = h * h * k->a[hi];
        double *c = k->power;
        c[0] = u0;
        c[1] = w0;
        c[2] = 0.5 * a0;
        c[3] = 10.0 * (u1 - u0) - 6.0 * w0 - 4.0 * w1 - 1.5 * a0 + 0.5 * a1;
        c[4] = 15.0 * (u0 - u1) + 8.0 * w0 + 7.0 * w1 + 1.5 * a0 - a1;
        c[5] = 6.0 * (u1 - u0) - 3.0 * (w0 + w1) - 0.5 * (a0 - a1);
        k->power_step = lo;
        k->power_phi = k->phi[lo];
        k->power_inv_h = 1.0 / h;
    }
    const double *c = k->power;
    double t = (phi - k->power_phi) * k->power_inv_h;
    return ((((c[5] * t + c[4]) * t + c[3]) * t + c[2]) * t + c[1]) * t + c[0];
}

/* u and du/dphi at phi (knots_u, and the interpolant's derivative). */
static void knots_eval(struct orbit_knots *k, double phi, double *u, double *w)
{
    int lo = knots_locate(k, phi);
    if (lo < 0) {
        int at = lo == -1 ? 0 : k->n - 1;
        *u = k->u[at];
        *w = k->w[at];
        return;
    }
    int hi = lo + 1;
    double h = k->phi[hi] - k->phi[lo], t;
    *u = knots_u(k, lo, phi, &t);
    double t2 = t * t, t3 = t2 * t, t4 = t3 * t;
    double d0 = -30 * t2 + 60 * t3 - 30 * t4, d1 = 1 - 18 * t2 + 32 * t3 - 15 * t4,
           d2 = 0.5 * (2 * t - 9 * t2 + 12 * t3 - 5 * t4), d3 = 30 * t2 - 60 * t3 + 30 * t4,
           d4 = -12 * t2 + 28 * t3 - 15 * t4, d5 = 0.5 * (3 * t2 - 8 * t3 + 5 * t4);
    *w = (d0 * k->u[lo] + d1 * h * k->w[lo] + d2 * h * h * k->a[lo] + d3 * k->u[hi] + d4 * h * k->w[hi] +
          d5 * h * h * k->a[hi]) / h;
}

/* Integrate the orbit of launch angle psi to its end; knots hold every accepted step, the last
 * one exactly at the end. */
static int trace_knots(double mass, double r_observer, double psi, double u_far, double u_capture,
                       struct orbit_knots *k, int *captured)
{
    memset(k, 0, sizeof *k);
    k->mass = mass;
    k->power_step = -1;
    double u = 1.0 / r_observer;
    double w = -u * sqrt(1.0 - 2.0 * mass * u) * cos(psi) / sin(psi);
    double phi = 0.0;
    double atol_u = ORBIT_RTOL * u_far, atol_w = ORBIT_RTOL * (fabs(w) + u);
    double h = fmin(0.01, 0.01 * u / fmax(fabs(w), 1e-300));
    if (knots_push(k, phi, u, w) != 0)
        return -1;
    for (int step = 0; step < ORBIT_MAX_STEPS && phi < ORBIT_MAX_SWEEP; step++) {
        double u1, w1, eu, ew;
        binet_step(mass, u, w, h, &u1, &w1, &eu, &ew);
        double err = fmax(fabs(eu) / (atol_u + ORBIT_RTOL * fmax(fabs(u), fabs(u1))),
                          fabs(ew) / (atol_w + ORBIT_RTOL * fmax(fabs(w), fabs(w1))));
        if (!(err == err) || !isfinite(u1) || !isfinite(w1)) {
            h *= 0.2;
            continue;
        }
        double factor = err > 0.0 ? 0.9 * pow(err, -0.2) : 5.0;
        factor = fmin(5.0, fmax(0.2, factor));
        if (err > 1.0) {
            h *= factor;
            continue;
        }
        int escapes = w1 < 0.0 && u1 <= u_far;
        int falls = u1 >= u_capture;
        if ((escapes || falls) && (w > 0.0) == (w1 > 0.0)) {
            /* the end lies inside this step, on a monotonic stretch: finish it in u */
            double phi_end = phi, w_end = w;
            binet_in_u(mass, u, escapes ? u_far : u_capture, &phi_end, &w_end);
            *captured = falls;
            return knots_push(k, phi_end, escapes ? u_far : u_capture, w_end);
        }
        phi += h;
        u = u1;
        w = w1;
        if (knots_push(k, phi, u, w) != 0)
            return -1;
        h = fmin(h * factor, ORBIT_STEP_MAX);
    }
    knots_free(k);
    return -1;
}

int orbit_trace(double mass, double r_observer, double psi, double u_far, double u_capture, const double *phi_at,
                int n_at, double *u_at, double *du_at, double *phi_end, int *captured)
{
    struct orbit_knots k;
    if (trace_knots(mass, r_observer, psi, u_far, u_capture, &k, captured) != 0)
        return -1;
    *phi_end = k.phi[k.n - 1];
    for (int i = 0; i < n_at; i++)
        knots_eval(&k, phi_at[i], &u_at[i], &du_at[i]);
    knots_free(&k);
    return 0;
}

/* ---- rows ---- */

/* Row coordinate of distance d from the critical angle: logarithmic next to it, where phi_end
 * diverges as -ln d, and even far from it, where the orbits change evenly with psi. */
static double row_coordinate(double d, double epsilon)
{
    return log(d / epsilon) + d / ORBIT_EVEN_SCALE;
}

/* Its inverse, by Newton's method in ln d (the coordinate is convex and increasing in ln d). */
static double row_distance(double coordinate, double epsilon)
{
    double x = fmin(coordinate + log(epsilon), log(ORBIT_EVEN_SCALE * coordinate + 1e-300));
    for (int i = 0; i < 100; i++) {
        double g = row_coordinate(exp(x), epsilon) - coordinate, dg = 1.0 + exp(x) / ORBIT_EVEN_SCALE;
        double next = x - g / dg;
        if (fabs(next - x) < 1e-15 * fmax(1.0, fabs(x)))
            return exp(next);
        x = next;
    }
    return exp(x);
}

static double row_angle(const struct orbit_table *t, enum orbit_side side, int i)
{
    double frac = (double)i / (t->p.rows_per_side - 1);
    double d = row_distance(frac * t->log_span[side], t->epsilon[side]);
    return side == ORBIT_ESCAPES ? t->psi_c - d : t->psi_c + d;
}

double orbit_table_row(const struct orbit_table *t, double psi, enum orbit_side *side)
{
    *side = psi < t->psi_c ? ORBIT_ESCAPES : ORBIT_CAPTURED;
    double d = fabs(psi - t->psi_c);
    double frac = row_coordinate(fmax(d, t->epsilon[*side]), t->epsilon[*side]) / t->log_span[*side];
    frac = fmin(fmax(frac, 0.0), 1.0);
    return frac * (t->p.rows_per_side - 1);
}

/* The chord schedule. A chord of length L across a stretch of curvature kappa strays about
 * kappa L^2 / 8 from it, so pieces of equal sigma = int sqrt(kappa) dl stray about equally. For
 * r = 1/u(phi), kappa = 3 M u^5 / (u^2 + u'^2)^(3/2) and dl = sqrt(u^2 + u'^2) / u^2 dphi, so
 * dsigma/dphi = sqrt(3 M u) (u^2 + u'^2)^(-1/4). */
#define SIGMA_SUBSAMPLES 2
/* Inside the clear radius chords need not follow the orbit, but a chord's ends must not jump
 * across a dip into it either: a tenth of the weight keeps a few chords there. */
#define SIGMA_CLEAR_WEIGHT 0.1

/* warp[m], m = 0 .. ORBIT_WARP_SAMPLES - 1: the fraction s of the orbit where sigma reaches
 * m / (ORBIT_WARP_SAMPLES - 1) of its total; the identity where the orbit does not bend. */
static double row_warp(struct orbit_knots *k, double mass, double clear_radius, int columns, double *warp)
{
    int n = SIGMA_SUBSAMPLES * (columns - 1);
    double phi_end = k->phi[k->n - 1], u_clear = clear_radius > 0.0 ? 1.0 / clear_radius : INFINITY;
    double *sigma = malloc((size_t)(n + 1) * sizeof *sigma);
    if (!sigma)
        return -1.0;
    sigma[0] = 0.0;
    double prev_rate = 0.0;
    for (int i = 0; i <= n; i++) {
        double u, w;
        knots_eval(k, phi_end * i / n, &u, &w);
        double rate = sqrt(3.0 * mass * u) / sqrt(sqrt(u * u + w * w)) * (u < u_clear ? 1.0 : SIGMA_CLEAR_WEIGHT);
        if (i > 0)
            sigma[i] = sigma[i - 1] + 0.5 * (rate + prev_rate) * phi_end / n;
        prev_rate = rate;
    }
    double total = sigma[n];
    for (int m = 0, i = 0; m < ORBIT_WARP_SAMPLES; m++) {
        double target = total * m / (ORBIT_WARP_SAMPLES - 1);
        if (!(total > 0.0)) {
            warp[m] = (double)m / (ORBIT_WARP_SAMPLES - 1);
            continue;
        }
        while (i < n && sigma[i + 1] < target)
            i++;
        double span = i < n ? sigma[i + 1] - sigma[i] : 0.0;
        double f = span > 0.0 ? (target - sigma[i]) / span : 0.0;
        warp[m] = fmin(1.0, (i + fmin(fmax(f, 0.0), 1.0)) / n);
    }
    warp[0] = 0.0;
    warp[ORBIT_WARP_SAMPLES - 1] = 1.0;
    free(sigma);
    return total;
}

/* The fraction s where chord k of n ends, as the shader reads it: linear in the warp samples. */
static double warp_at(const double *warp, double x)
{
    double c = fmin(fmax(x, 0.0), 1.0) * (ORBIT_WARP_SAMPLES - 1);
    int m = (int)floor(c);
    if (m > ORBIT_WARP_SAMPLES - 2)
        m = ORBIT_WARP_SAMPLES - 2;
    return warp[m] + (c - m) * (warp[m + 1] - warp[m]);
}

/* Largest distance of the orbit from its n chords, from points between the chords' exact ends;
 * a chord whose two ends lie inside the clear radius stays inside it, where nothing can be met,
 * and does not count. (Every point of a chord with an end outside counts: the orbit runs outside
 * between that end and the first point inside, and strays from the chord there too.) Each chord is measured
 * in the plane turned so that its start lies on the x axis: the points' angles from there are
 * multiples of one small angle, whose cosines and sines follow by turning (one sincos a chord,
 * not eight). */
static double chord_sag(struct orbit_knots *k, const double *warp, int n, double clear_radius)
{
    enum { inner = 8 };
    double u_clear = clear_radius > 0.0 ? 1.0 / clear_radius : INFINITY;
    double phi_end = k->phi[k->n - 1], worst = 0.0;
    /* each chord starts where the one before ended: that end is evaluated once */
    double pb = phi_end * warp_at(warp, 0.0), ub = knots_sag_u(k, pb);
    for (int p = 0; p < n; p++) {
        double pa = pb, ua = ub;
        pb = phi_end * warp_at(warp, (double)(p + 1) / n);
        /* the points between the ends first, in the order of phi: the knots' search then moves on
         * from where it was rather than starting again */
        double u_between[inner];
        for (int j = 1; j < inner; j++)
            u_between[j] = knots_sag_u(k, pa + (pb - pa) * j / inner);
        ub = knots_sag_u(k, pb);
        if (ua > u_clear && ub > u_clear)
            continue;
        double turn_c = cos((pb - pa) / inner), turn_s = sin((pb - pa) / inner);
        double c[inner + 1], sn[inner + 1];
        c[0] = 1.0;
        sn[0] = 0.0;
        for (int j = 1; j <= inner; j++) {
            c[j] = c[j - 1] * turn_c - sn[j - 1] * turn_s;
            sn[j] = sn[j - 1] * turn_c + c[j - 1] * turn_s;
        }
        double ax = 1.0 / ua, dx = c[inner] / ub - ax, dy = sn[inner] / ub, len = sqrt(dx * dx + dy * dy);
        for (int j = 1; j < inner; j++) {
            double u = u_between[j];
            double x = c[j] / u - ax, y = sn[j] / u;
            worst = fmax(worst, len > 0.0 ? fabs(x * dy - y * dx) / len : sqrt(x * x + y * y));
        }
    }
    return worst;
}

/* The fewest chords of equal sigma that stray at most chord_tolerance: from the estimate
 * sigma / sqrt(8 tolerance), raised until the measured distance keeps within it. */
static int row_segments(const struct orbit_table *t, struct orbit_knots *k, const double *warp, double sigma)
{
    if (!isfinite(t->p.chord_tolerance))
        return 1;
    double estimate = ceil(sigma / sqrt(8.0 * t->p.chord_tolerance));
    int n = estimate < 1.0 ? 1 : estimate > t->p.max_segments ? t->p.max_segments : (int)estimate;
    for (;;) {
        double sag = chord_sag(k, warp, n, t->p.clear_radius);
        if (!(sag > t->p.chord_tolerance) || n >= t->p.max_segments)
            break;
        /* a chord's sag falls as the square of its count: aim there, and at least a quarter more */
        double aim = ceil(n * sqrt(sag / t->p.chord_tolerance) * 1.05), more = n + n / 4 + 1;
        double next = aim > more ? aim : more;
        n = next > t->p.max_segments ? t->p.max_segments : (int)next;
    }
    return n;
}

/* One row: its orbit traced, sampled, its chord schedule. 0, or -1 with e. */
static int build_row(struct orbit_table *t, int row, double *phi_s, struct error *e)
{
    const struct orbit_table_params *p = &t->p;
    int cols = p->columns;
    enum orbit_side side = row < p->rows_per_side ? ORBIT_ESCAPES : ORBIT_CAPTURED;
    double psi = row_angle(t, side, row % p->rows_per_side);
    struct orbit_knots k;
    int captured = -1;
    if (trace_knots(p->mass, p->r_observer, psi, t->u_far, t->u_capture, &k, &captured) != 0 ||
        captured != (side == ORBIT_CAPTURED)) {
        if (captured >= 0)
            knots_free(&k);
        return error_set(e, ERROR_RUNTIME, NULL, "orbit table: the orbit launched at %.17g rad (critical %.17g, "
                         "M = %.17g, r_o = %.17g) did not end as its side of the critical angle says", psi, t->psi_c,
                         p->mass, p->r_observer);
    }
    double phi_end = k.phi[k.n - 1];
    double *u = t->u + (size_t)row * cols, *du = t->du_ds + (size_t)row * cols;
    for (int j = 0; j < cols; j++) {
        phi_s[j] = phi_end * j / (cols - 1);
        double w;
        knots_eval(&k, phi_s[j], &u[j], &w);
        du[j] = w * phi_end;
        float *texel = t->texels + ((size_t)row * t->width + j) * 4;
        texel[0] = (float)u[j];
        texel[1] = (float)du[j];
    }
    /* each texel also holds the next sample's pair: the shader's cubic reads one texel, not two */
    for (int j = 0; j + 1 < cols; j++) {
        float *texel = t->texels + ((size_t)row * t->width + j) * 4;
        texel[2] = texel[4];
        texel[3] = texel[5];
    }
    t->psi[row] = psi;
    t->phi_over_sin[row] = phi_end / sin(psi);
    double warp[ORBIT_WARP_SAMPLES];
    double sigma = row_warp(&k, p->mass, p->clear_radius, cols, warp);
    if (sigma < 0.0) {
        knots_free(&k);
        return error_set(e, ERROR_RUNTIME, NULL, "orbit table: out of memory");
    }
    for (int m = 0; m < ORBIT_WARP_SAMPLES; m++) {
        float *texel = t->texels + ((size_t)row * t->width + cols + 1 + m) * 4;
        texel[0] = (float)warp[m];
        texel[1] = m + 1 < ORBIT_WARP_SAMPLES ? (float)warp[m + 1] : (float)warp[m];
    }
    t->segments[row] = row_segments(t, &k, warp, sigma);
    /* escaping: on from r_far to infinity, where the sky is (physics/escape.h) */
    double sweep = side == ORBIT_ESCAPES ? escape_sweep(p->mass, k.u[k.n - 1], k.w[k.n - 1]) : 0.0;
    t->phi_infinity_over_sin[row] = sweep >= 0.0 ? (phi_end + sweep) / sin(psi) : t->phi_over_sin[row];
    float *last = t->texels + ((size_t)row * t->width + cols) * 4;
    last[0] = (float)t->phi_over_sin[row];
    last[1] = (float)t->segments[row];
    last[2] = (float)t->phi_infinity_over_sin[row];
    last[3] = (float)psi;
    knots_free(&k);
    return 0;
}

/* The table's rows on the cores: each part's status and error. */
struct row_parts {
    struct orbit_table *t;
    int status[ORBIT_MAX_THREADS];
    struct error e[ORBIT_MAX_THREADS];
};

/* Rows part, part + parts, ... of the table. */
static void build_rows(void *arg, int part, int parts)
{
    struct row_parts *w = arg;
    double *phi_s = malloc((size_t)w->t->p.columns * sizeof *phi_s);
    w->status[part] = phi_s ? 0 : -1;
    if (!phi_s)
        error_set(&w->e[part], ERROR_RUNTIME, NULL, "orbit table: out of memory");
    for (int row = part; row < w->t->height && w->status[part] == 0; row += parts)
        w->status[part] = build_row(w->t, row, phi_s, &w->e[part]);
    free(phi_s);
}

/* Rows closer to psi_c than this many of its double roundings would not be launched at angles
 * of their own (psi_c + d rounds back to psi_c, or to too few values): the nearest row is at
 * least this far, and a side needs ORBIT_SIDE_ROUNDINGS of them to be tabulated at all. */
#define ORBIT_ROW_ROUNDINGS 64.0
#define ORBIT_SIDE_ROUNDINGS (4.0 * ORBIT_ROW_ROUNDINGS)

/* The outermost rows (psi_min, psi_max), each side's extent (psi_c to its outermost row) and
 * epsilon; 0, or -1 where a side is too narrow for rows of their own in double precision. */
static int table_sides(double psi_c, double outer[2], double extent[2], double epsilon[2])
{
    double rounding = nextafter(psi_c, 4.0) - psi_c;
    outer[0] = fmin(ORBIT_RADIAL_GAP, 0.5 * psi_c);
    outer[1] = fmax(pi - ORBIT_RADIAL_GAP, 0.5 * (psi_c + pi));
    extent[0] = psi_c - outer[0];
    extent[1] = outer[1] - psi_c;
    int ok = 1;
    for (int side = 0; side < 2; side++) {
        /* a small mass's capture cone (or an observer next to the horizon's escape cone) is narrower
         * than epsilon: its rows then start a thousandth of its width from psi_c */
        epsilon[side] = fmax(fmin(ORBIT_CRITICAL_EPSILON, 1e-3 * extent[side]), ORBIT_ROW_ROUNDINGS * rounding);
        ok = ok && extent[side] >= ORBIT_SIDE_ROUNDINGS * rounding && epsilon[side] > 0.0;
    }
    return ok ? 0 : -1;
}

int orbit_table_resolves(double mass, double r_observer)
{
    double outer[2], extent[2], epsilon[2];
    return mass > 0.0 && r_observer > 2.0 * mass &&
           table_sides(orbit_critical_angle(mass, r_observer), outer, extent, epsilon) == 0;
}

int orbit_table_build(struct orbit_table *t, const struct orbit_table_params *p, struct error *e)
{
    double t0 = clock_seconds();
    memset(t, 0, sizeof *t);
    t->p = *p;
    if (!(p->mass > 0.0) || !(p->r_observer > 2.0 * p->mass) || !(p->r_far > p->r_observer) ||
        p->rows_per_side < 4 || p->columns < 4 || p->max_segments < 1 || !(p->chord_tolerance > 0.0))
        return error_set(e, ERROR_RUNTIME, NULL,
                         "orbit table: needs M > 0, 2M < r_o < r_far, 4 rows and columns, a chord tolerance > 0");
    t->psi_c = orbit_critical_angle(p->mass, p->r_observer);
    t->critical_from_axis = orbit_critical_from_axis(p->mass, p->r_observer, &t->critical_inward);
    double outer[2], extent[2];
    int sides = table_sides(t->psi_c, outer, extent, t->epsilon);
    t->psi_min = outer[0];
    t->psi_max = outer[1];
    if (sides != 0)
        return error_set(e, ERROR_RUNTIME, NULL, "orbit table: the observer at r = %.17g (M = %.17g) leaves too few "
                         "launch angles in double precision on one side of the critical angle %.17g (the renderer "
                         "takes such a mass's rays as straight: orbit_table_resolves)", p->r_observer, p->mass,
                         t->psi_c);
    for (int side = 0; side < 2; side++)
        t->log_span[side] = row_coordinate(extent[side], t->epsilon[side]);
    t->u_observer = 1.0 / p->r_observer;
    t->u_far = 1.0 / p->r_far;
    t->u_capture = 1.0 / (2.0 * p->mass * (1.0 - ORBIT_HORIZON_MARGIN));
    int rows = 2 * p->rows_per_side, cols = p->columns;
    t->width = cols + 1 + ORBIT_WARP_SAMPLES;
    t->height = rows;
    t->texels = calloc((size_t)t->width * rows * 4, sizeof *t->texels);
    t->u = calloc((size_t)rows * cols, sizeof *t->u);
    t->du_ds = calloc((size_t)rows * cols, sizeof *t->du_ds);
    t->phi_over_sin = calloc(rows, sizeof *t->phi_over_sin);
    t->phi_infinity_over_sin = calloc(rows, sizeof *t->phi_infinity_over_sin);
    t->psi = calloc(rows, sizeof *t->psi);
    t->segments = calloc(rows, sizeof *t->segments);
    if (!t->texels || !t->u || !t->du_ds || !t->phi_over_sin || !t->phi_infinity_over_sin || !t->psi || !t->segments) {
        orbit_table_free(t);
        return error_set(e, ERROR_RUNTIME, NULL, "orbit table: out of memory");
    }
    /* the rows are independent: one thread per core, at most ORBIT_MAX_THREADS */
    struct row_parts *w = malloc(sizeof *w);
    if (!w) {
        orbit_table_free(t);
        return error_set(e, ERROR_RUNTIME, NULL, "orbit table: out of memory");
    }
    w->t = t;
    int parts = parallel_parts(rows, ORBIT_MAX_THREADS), status = 0;
    parallel_run(parts, build_rows, w);
    for (int i = 0; i < parts && status == 0; i++)
        if (w->status[i] != 0) {
            status = -1;
            *e = w->e[i];
        }
    free(w);
    if (status != 0) {
        orbit_table_free(t);
        return -1;
    }
    for (int row = 0; row < rows; row++)
        if (t->segments[row] > t->max_segments)
            t->max_segments = t->segments[row];
    /* each chord-schedule texel also holds the next row's pair (the last row of a side its own):
     * the shader interpolates between two rows from one texel, not two */
    for (int row = 0; row < rows; row++) {
        int next = (row + 1) % p->rows_per_side == 0 ? row : row + 1;
        for (int m = 0; m < ORBIT_WARP_SAMPLES; m++) {
            float *texel = t->texels + ((size_t)row * t->width + p->columns + 1 + m) * 4;
            const float *below = t->texels + ((size_t)next * t->width + p->columns + 1 + m) * 4;
            texel[2] = below[0];
            texel[3] = below[1];
        }
    }
    t->build_seconds = clock_seconds() - t0;
    return 0;
}

void orbit_table_free_cpu_arrays(struct orbit_table *t)
{
    free(t->u);
    free(t->du_ds);
    free(t->phi_over_sin);
    free(t->phi_infinity_over_sin);
    free(t->psi);
    free(t->segments);
    t->u = t->du_ds = t->phi_over_sin = t->phi_infinity_over_sin = t->psi = NULL;
    t->segments = NULL;
}

void orbit_table_free(struct orbit_table *t)
{
    orbit_table_free_cpu_arrays(t);
    free(t->texels);
    memset(t, 0, sizeof *t);
}

/* Catmull-Rom weights of rows i-1 .. i+2 at fraction f past row i. */
static void catmull_rom(double f, double wgt[4])
{
    double f2 = f * f, f3 = f2 * f;
    wgt[0] = 0.5 * (-f3 + 2 * f2 - f);
    wgt[1] = 0.5 * (3 * f3 - 5 * f2 + 2);
    wgt[2] = 0.5 * (-3 * f3 + 4 * f2 + f);
    wgt[3] = 0.5 * (f3 - f2);
}

/* The rows about launch angle psi: its side, the row i at or below it (0 .. rows - 2) and its
 * fraction f towards row i + 1. */
static int row_stencil(const struct orbit_table *t, double psi, enum orbit_side *side, double *f)
{
    int rps = t->p.rows_per_side;
    double q = orbit_table_row(t, psi, side);
    int i = (int)floor(q);
    if (i > rps - 2)
        i = rps - 2;
    *f = q - i;
    return i;
}

void orbit_table_eval(const struct orbit_table *t, double psi, double s, struct orbit_point *out, double *phi_end,
                      int *segments)
{
    enum orbit_side side;
    int rps = t->p.rows_per_side, cols = t->p.columns;
    double f, wr[4];
    int i = row_stencil(t, psi, &side, &f);
    catmull_rom(f, wr);
    double c = fmin(fmax(s, 0.0), 1.0) * (cols - 1);
    int j = (int)floor(c);
    if (j > cols - 2)
        j = cols - 2;
    double g = c - j, g2 = g * g, g3 = g2 * g, dj = 1.0 / (cols - 1);
    double h00 = 2 * g3 - 3 * g2 + 1, h10 = g3 - 2 * g2 + g, h01 = -2 * g3 + 3 * g2, h11 = g3 - g2;
    double d00 = 6 * g2 - 6 * g, d10 = 3 * g2 - 4 * g + 1, d01 = -6 * g2 + 6 * g, d11 = 3 * g2 - 2 * g;
    double u = 0.0, du = 0.0, phi_sin = 0.0;
    for (int m = 0; m < 4; m++) {
        int r = i - 1 + m;
        r = r < 0 ? 0 : r > rps - 1 ? rps - 1 : r;
        int row = side * rps + r;
        const float *a = t->texels + ((size_t)row * t->width + j) * 4, *b = a + 4;
        const float *last = t->texels + ((size_t)row * t->width + cols) * 4;
        double ur = h00 * a[0] + h10 * dj * a[1] + h01 * b[0] + h11 * dj * b[1];
        double dr = (d00 * a[0] + d10 * dj * a[1] + d01 * b[0] + d11 * dj * b[1]) / dj;
        u += wr[m] * ur;
        du += wr[m] * dr;
        phi_sin += wr[m] * last[0];
    }
    int n0 = t->segments[side * rps + i], n1 = t->segments[side * rps + i + 1];
    *segments = n0 > n1 ? n0 : n1;
    *phi_end = phi_sin * sin(psi);
    out->u = u;
    out->phi = s * *phi_end;
    out->du_dphi = *phi_end > 0.0 ? du / *phi_end : 0.0;
}

double orbit_table_chord_end(const struct orbit_table *t, double psi, int k, int n)
{
    enum orbit_side side;
    int rps = t->p.rows_per_side, cols = t->p.columns;
    double f, ends[2];
    int i = row_stencil(t, psi, &side, &f);
    for (int m = 0; m < 2; m++) {
        double warp[ORBIT_WARP_SAMPLES];
        const float *texel = t->texels + ((size_t)(side * rps + i + m) * t->width + cols + 1) * 4;
        for (int j = 0; j < ORBIT_WARP_SAMPLES; j++)
            warp[j] = texel[4 * j];
        ends[m] = warp_at(warp, (double)k / n);
    }
    return k >= n ? 1.0 : (1.0 - f) * ends[0] + f * ends[1];
}
