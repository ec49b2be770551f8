/* Error metrics between a dump under test and a reference dump (docs/ERRORS.md). */
#include "results/compare.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

int compare_dump_check(const struct dump *d, struct error *e)
{
    for (int i = 0; i < d->n_objects; i++) {
        /* relative hit errors divide by the size: it must be a length */
        if (!(isfinite(d->object_size[i]) && d->object_size[i] > 0.0f))
            return error_set(e, ERROR_INPUT, NULL, "object %d has size %g; sizes must be finite and positive", i,
                             (double)d->object_size[i]);
    }
    long n = (long)d->width * d->height;
    for (long i = 0; i < n; i++) {
        int32_t o = d->records[i].outcome;
        if (o < DUMP_FAILED || o >= d->n_objects)
            return error_set(e, ERROR_INPUT, NULL,
                             "pixel (%ld, %ld) has outcome %d, outside %d..%d (the dump lists %d objects)",
                             i % d->width, i / d->width, (int)o, DUMP_FAILED, d->n_objects - 1, d->n_objects);
    }
    return 0;
}

static int check_compatible(const struct dump *a, const struct dump *b, struct error *e)
{
    if (a->width != b->width || a->height != b->height)
        return error_set(e, ERROR_INPUT, NULL, "size %dx%d differs from the reference's %dx%d", a->width, a->height,
                         b->width, b->height);
    if (strcmp(a->scene, b->scene) != 0)
        return error_set(e, ERROR_INPUT, NULL, "scene '%s' differs from the reference's '%s'", a->scene, b->scene);
    if (a->n_objects != b->n_objects)
        return error_set(e, ERROR_INPUT, NULL, "%d objects, the reference has %d", a->n_objects, b->n_objects);
    return 0;
}

/* First category that fits, so that the categories partition the differing pixels. */
static void classify(int32_t oa, int32_t ob, struct compare_outcomes *o)
{
    if (oa == ob)
        return;
    o->differ++;
    if (oa == DUMP_FAILED)
        o->failed_a++;
    else if (ob == DUMP_FAILED)
        o->failed_b++;
    else if (oa == DUMP_CAPTURED || ob == DUMP_CAPTURED)
        o->captured_vs_escaped++;
    else if (oa >= 0 && ob >= 0)
        o->other_object++;
    else if (oa >= 0 || ob >= 0)
        o->object_vs_sky++;
    else
        o->unfinished++; /* what is left: sky against unfinished */
}

static double distance(const float *p, const float *q)
{
    double dx = (double)p[0] - q[0], dy = (double)p[1] - q[1], dz = (double)p[2] - q[2];
    return sqrt(dx * dx + dy * dy + dz * dz);
}

/* atan2(|u x v|, u . v) keeps full relative precision for tiny angles, where acos(u . v) loses
 * everything below ~1e-8 rad (cos is flat there), and needs no normalisation. The products of
 * floats are exact in double. */
static double angle_between(const float *u, const float *v)
{
    double cx = (double)u[1] * v[2] - (double)u[2] * v[1];
    double cy = (double)u[2] * v[0] - (double)u[0] * v[2];
    double cz = (double)u[0] * v[1] - (double)u[1] * v[0];
    double dot = (double)u[0] * v[0] + (double)u[1] * v[1] + (double)u[2] * v[2];
    return atan2(sqrt(cx * cx + cy * cy + cz * cz), dot);
}

enum error_kind { ERROR_HIT, ERROR_HIT_RELATIVE, ERROR_SKY_ANGLE };

/* The error of kind k at one pixel; 0 when the error does not apply to this pixel. */
static int pixel_error(const struct dump_record *ra, const struct dump_record *rb, const struct dump *b,
                       enum error_kind k, double *e)
{
    if (k == ERROR_SKY_ANGLE) {
        if (ra->outcome != DUMP_SKY || rb->outcome != DUMP_SKY)
            return 0;
        *e = angle_between(ra->direction, rb->direction);
        return 1;
    }
    if (ra->outcome < 0 || ra->outcome != rb->outcome)
        return 0;
    *e = distance(ra->hit, rb->hit);
    if (k == ERROR_HIT_RELATIVE)
        *e /= b->object_size[rb->outcome];
    return 1;
}

static int by_value(const void *x, const void *y)
{
    double p = *(const double *)x, q = *(const double *)y;
    return (p > q) - (p < q);
}

/* Nearest rank (1-based) of the percent-th percentile of n values: ceil(percent * n / 100),
 * in integers so that 99 * n / 100 is not rounded the wrong way. */
static long nearest_rank(long percent, long n)
{
    return (long)(((long long)percent * n + 99) / 100);
}

/* Statistics of v[0..n), sorted in place. */
static void stats_of(double *v, long n, struct compare_stats *s)
{
    s->count = n;
    if (n == 0) {
        s->mean = s->p99 = s->max = NAN;
        return;
    }
    double sum = 0.0;
    for (long i = 0; i < n; i++)
        sum += v[i];
    qsort(v, (size_t)n, sizeof *v, by_value);
    s->mean = sum / (double)n;
    s->p99 = v[nearest_rank(99, n) - 1];
    s->max = v[n - 1];
}

/* Gather the finite errors of kind k into buf (one slot per pixel) and summarise them. */
static void measure(const struct dump *a, const struct dump *b, enum error_kind k, double *buf,
                    struct compare_stats *s)
{
    long pixels = (long)a->width * a->height, n = 0, non_finite = 0;
    for (long i = 0; i < pixels; i++) {
        double e;
        if (!pixel_error(&a->records[i], &b->records[i], b, k, &e))
            continue;
        if (isfinite(e))
            buf[n++] = e;
        else
            non_finite++;
    }
    stats_of(buf, n, s);
    s->non_finite = non_finite;
}

/* PSNR and mean absolute difference over R, G, B. Sums of 8-bit differences are exact in
 * 64-bit integers for any dump size allowed (DUMP_MAX_PIXELS). */
static void image_metrics(const struct dump *a, const struct dump *b, struct compare_result *r)
{
    long long abs_sum[3] = {0, 0, 0}, sq_sum = 0;
    for (long i = 0; i < r->pixels; i++) {
        for (int c = 0; c < 3; c++) {
            int d = (int)a->records[i].rgba[c] - (int)b->records[i].rgba[c];
            abs_sum[c] += d < 0 ? -d : d;
            sq_sum += d * d;
        }
    }
    double mse = (double)sq_sum / (3.0 * (double)r->pixels);
    r->image_identical = sq_sum == 0;
    r->psnr_db = sq_sum == 0 ? INFINITY : 10.0 * log10(255.0 * 255.0 / mse);
    for (int c = 0; c < 3; c++)
        r->mean_abs_diff[c] = (double)abs_sum[c] / (double)r->pixels;
}

static void copy_name(char dst[32], const char src[32])
{
    memcpy(dst, src, 32);
    dst[31] = '\0';
}

static int check_both(const struct dump *a, const struct dump *b, struct error *e)
{
    struct error why;
    if (compare_dump_check(a, &why) != 0)
        return error_set(e, why.status, NULL, "dump under test: %s", why.message);
    if (compare_dump_check(b, &why) != 0)
        return error_set(e, why.status, NULL, "reference dump: %s", why.message);
    return check_compatible(a, b, e);
}

int compare_dumps(const struct dump *a, const struct dump *b, struct compare_result *r, struct error *e)
{
    memset(r, 0, sizeof *r);
    if (check_both(a, b, e) != 0)
        return -1;
    copy_name(r->scene, b->scene);
    copy_name(r->engine_a, a->engine);
    copy_name(r->engine_b, b->engine);
    r->width = b->width;
    r->height = b->height;
    r->pixels = (long)b->width * b->height;
    double *buf = malloc((size_t)r->pixels * sizeof *buf);
    if (!buf)
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory comparing %ld pixels", r->pixels);
    for (long i = 0; i < r->pixels; i++)
        classify(a->records[i].outcome, b->records[i].outcome, &r->outcomes);
    r->outcome_fraction = (double)r->outcomes.differ / (double)r->pixels;
    measure(a, b, ERROR_HIT, buf, &r->hit);
    measure(a, b, ERROR_HIT_RELATIVE, buf, &r->hit_relative);
    measure(a, b, ERROR_SKY_ANGLE, buf, &r->sky_angle);
    free(buf);
    image_metrics(a, b, r);
    return 0;
}
