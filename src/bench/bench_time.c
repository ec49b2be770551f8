/* Timing one configuration: warm-up, then the median of several frames on one GL context. */
#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "io/clock.h"
#include "bench/bench.h"
#include "render/frame.h"
#include "render/renderer.h"

void bench_progress(struct bench *b, const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "[%d/%d] ", b->done, b->total);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, " (%.0f s)\n", clock_seconds() - b->started);
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int bench_time(struct bench *b, const struct scene *s, int runs, struct bench_timing *t, struct dump *d,
               struct error *e)
{
    struct renderer *r = renderer_create(b->ctx, s, e);
    if (!r)
        return -1;
    double times[64];
    runs = runs < 1 ? 1 : runs < 64 ? runs : 64;
    /* the frame as a display draws it, the image alone; the dump's state is traced after the timed run */
    renderer_set_reads(r, RENDER_READ_IMAGE);
    int rc = 0;
    for (int k = 0; k <= runs && rc == 0; k++) {
        rc = renderer_run(r, s, 0, 0, s->render.width, s->render.height, NULL, NULL, e);
        struct render_result res;
        if (rc == 0 && k > 0)
            rc = renderer_read(r, &res, d && k == runs, e);
        if (rc == 0 && k > 0) {
            times[k - 1] = res.seconds;
            t->passes = res.passes;
            if (d && k == runs && result_to_dump(&res, s, renderer_path(r)->name, d) != 0)
                rc = error_set(e, ERROR_RUNTIME, NULL, "out of memory");
            render_result_free(&res);
        }
    }
    snprintf(t->path, sizeof t->path, "%s", renderer_path(r)->name);
    renderer_destroy(r);
    if (rc != 0)
        return -1;
    t->median = bench_median(times, runs);
    t->min = times[0];
    t->max = times[runs - 1];
    return 0;
}

double bench_median(double *times, int n)
{
    qsort(times, (size_t)n, sizeof times[0], by_value);
    return n % 2 ? times[n / 2] : 0.5 * (times[n / 2 - 1] + times[n / 2]);
}

FILE *bench_data_file(struct bench *b, const char *name, struct error *e)
{
    char path[BENCH_PATH_LEN + 64];
    snprintf(path, sizeof path, "%s/%s", b->data_dir, name);
    errno = 0;
    FILE *f = fopen(path, "w");
    if (!f)
        error_set(e, error_status_of_errno(errno), NULL, "cannot write %s", path);
    return f;
}
