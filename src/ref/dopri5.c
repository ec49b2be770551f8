#include "ref/dopri5.h"
#include "physics/dormand_prince.h"
#include <math.h>
#include <string.h>

/* dense output (CONTD5) */
static const double D1 = -12715105075.0 / 11282082432.0, D3 = 87487479700.0 / 32700410799.0,
                    D4 = -10690763975.0 / 1880347072.0, D5 = 701980252875.0 / 199316789632.0,
                    D6 = -1453857185.0 / 822651844.0, D7 = 69997945.0 / 29380423.0;

/* Step-size controller: safety factor and the limits of one change (Hairer's defaults). */
static const double SAFETY = 0.9, GROW_MAX = 5.0, SHRINK_MAX = 0.2;

static void derivative(const struct model *m, const double *y, double *dy)
{
    vec3d a = model_accel(m, v3(y[0], y[1], y[2]), v3(y[3], y[4], y[5]));
    dy[0] = y[3];
    dy[1] = y[4];
    dy[2] = y[5];
    dy[3] = a.x;
    dy[4] = a.y;
    dy[5] = a.z;
}

void dopri5_init(struct dopri5 *d, const struct model *m, double rtol, double atol_x, double atol_v, vec3d x, vec3d v,
                 double h)
{
    memset(d, 0, sizeof *d);
    d->model = m;
    d->rtol = rtol;
    for (int c = 0; c < 6; c++)
        d->atol[c] = c < 3 ? atol_x : atol_v;
    double y[6] = {x.x, x.y, x.z, v.x, v.y, v.z};
    memcpy(d->y, y, sizeof y);
    derivative(m, d->y, d->dy);
    d->h = h;
}

/* y + h * sum(a_i k_i) for the stage coefficients given. */
static void stage(double *out, const double *y, double h, const double *a, double (*k)[6], int n)
{
    for (int c = 0; c < 6; c++) {
        double s = 0.0;
        for (int i = 0; i < n; i++)
            s += a[i] * k[i][c];
        out[c] = y[c] + h * s;
    }
}

/* One attempt of size h: the new state in y1, its derivative in k[6], the scaled error norm returned
 * (infinite when a stage is not finite). */
static double attempt(const struct dopri5 *d, double h, double (*k)[6], double *y1)
{
    const struct model *m = d->model;
    double ys[6];
    memcpy(k[0], d->dy, sizeof k[0]);
    for (int s = 1; s <= 5; s++) {
        stage(ys, d->y, h, dormand_prince_a[s - 1], k, s);
        derivative(m, ys, k[s]);
    }
    stage(y1, d->y, h, dormand_prince_a[5], k, 6);
    derivative(m, y1, k[6]);
    double sum = 0.0;
    for (int c = 0; c < 6; c++) {
        const double *w = dormand_prince_e;   /* its second weight is 0 */
        double e = h * (w[0] * k[0][c] + w[2] * k[2][c] + w[3] * k[3][c] + w[4] * k[4][c] + w[5] * k[5][c] +
                        w[6] * k[6][c]);
        double scale = d->atol[c] + d->rtol * fmax(fabs(d->y[c]), fabs(y1[c]));
        sum += (e / scale) * (e / scale);
        if (!isfinite(y1[c]) || !isfinite(k[6][c]))
            return INFINITY;
    }
    double err = sqrt(sum / 6.0);
    return isfinite(err) ? err : INFINITY;
}

static void keep_dense_output(struct dopri5 *d, double h, double (*k)[6], const double *y1)
{
    for (int c = 0; c < 6; c++) {
        double diff = y1[c] - d->y[c];
        double bspl = h * k[0][c] - diff;
        d->cont[0][c] = d->y[c];
        d->cont[1][c] = diff;
        d->cont[2][c] = bspl;
        d->cont[3][c] = diff - h * k[6][c] - bspl;
        d->cont[4][c] = h * (D1 * k[0][c] + D3 * k[2][c] + D4 * k[3][c] + D5 * k[4][c] + D6 * k[5][c] +
                             D7 * k[6][c]);
    }
    d->lambda_old = d->lambda;
    d->h_old = h;
}

int dopri5_step(struct dopri5 *d, double h_max, double h_min, long max_tries)
{
    double k[7][6], y1[6];
    int rejected_last = 0;
    for (long tries = 0; tries < max_tries; tries++) {
        double h = fmin(d->h, h_max);
        /* the last step to a stopping point may be shorter than h_min; only the controller's wish may not */
        if (h < h_min && h < h_max)
            return -1;
        double err = attempt(d, h, k, y1);
        if (err <= 1.0) {
            keep_dense_output(d, h, k, y1);
            memcpy(d->y, y1, sizeof y1);
            memcpy(d->dy, k[6], sizeof k[6]);
            d->lambda += h;
            d->steps++;
            double grow = err > 0.0 ? SAFETY * pow(err, -0.2) : GROW_MAX;
            grow = fmin(GROW_MAX, fmax(SHRINK_MAX, grow));
            if (rejected_last)
                grow = fmin(grow, 1.0);
            /* a step clipped by h_max says nothing about the size the controller wants */
            d->h = h < d->h ? fmax(d->h, h * grow) : h * grow;
            return 0;
        }
        d->rejected++;
        rejected_last = 1;
        double shrink = isfinite(err) ? fmax(SHRINK_MAX, SAFETY * pow(err, -0.2)) : 0.1;
        d->h = h * shrink;
    }
    return -1;
}

void dopri5_dense(const struct dopri5 *d, double theta, vec3d *x, vec3d *v)
{
    double t1 = 1.0 - theta, y[6];
    for (int c = 0; c < 6; c++)
        y[c] = d->cont[0][c] +
               theta * (d->cont[1][c] + t1 * (d->cont[2][c] + theta * (d->cont[3][c] + t1 * d->cont[4][c])));
    *x = v3(y[0], y[1], y[2]);
    if (v)
        *v = v3(y[3], y[4], y[5]);
}

vec3d dopri5_dense_x(const struct dopri5 *d, double theta)
{
    vec3d x;
    dopri5_dense(d, theta, &x, NULL);
    return x;
}
