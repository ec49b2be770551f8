/* Timing one configuration: warm-up, then the median of several frames on one GL context. */
#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "io/clock.h"
#include "io/output_file.h"
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

int bench_frame_times(struct bench *b, const struct scene *s, int runs, struct frame_times *t, unsigned char **rgba,
                      struct error *e)
{
    struct renderer *r = renderer_create(b->ctx, s, e);
    if (!r)
        return -1;
    double gpu[64], stars[64], bloom[64];
    runs = runs < 1 ? 1 : runs < 64 ? runs : 64;
    int rc = 0;
    if (rgba)
        *rgba = NULL;
    for (int k = 0; k <= runs && rc == 0; k++) {
        struct render_result res;
        rc = frame_run_samples(r, s, &res, 0, PROGRESS_NONE, e);
        if (rc != 0)
            break;
        if (k > 0) {
            gpu[k - 1] = res.seconds;
            stars[k - 1] = res.sky_seconds;
            bloom[k - 1] = res.bloom_seconds;
        }
        if (rgba) {
            free(*rgba);
            *rgba = res.rgba;
            res.rgba = NULL;
        }
        render_result_free(&res);
    }
    renderer_destroy(r);
    if (rc != 0) {
        if (rgba) {
            free(*rgba);
            *rgba = NULL;
        }
        return -1;
    }
    t->gpu = bench_median(gpu, runs);
    t->stars = bench_median(stars, runs);
    t->bloom = bench_median(bloom, runs);
    return 0;
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
            rc = renderer_read(r, &res, d && k == runs ? RENDER_READ_STATE : RENDER_READ_IMAGE, e);
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

FILE *bench_file(struct bench *b, const char *path, struct error *e)
{
    if (b->n_files == BENCH_MAX_FILES) {
        error_set(e, ERROR_RUNTIME, NULL, "internal: more than %d report files", BENCH_MAX_FILES);
        return NULL;
    }
    struct bench_file *f = &b->files[b->n_files];
    memset(f, 0, sizeof *f);
    snprintf(f->path, sizeof f->path, "%s", path);
    /* refused now, before the section's work, as a write would be (a directory at the path) */
    if (output_check(f->path, 1, e) != 0) {
        if (strncmp(e->message, "cannot write ", 13) != 0) {
            char why[sizeof e->message];
            snprintf(why, sizeof why, "%s", e->message);
            error_set(e, e->status, NULL, "cannot write %s (%s)", f->path, why);
        }
        return NULL;
    }
    f->fp = open_memstream(&f->text, &f->len);
    if (!f->fp) {
        error_set(e, ERROR_RUNTIME, NULL, "cannot write %s: out of memory", f->path);
        return NULL;
    }
    b->n_files++;
    return f->fp;
}

FILE *bench_data_file(struct bench *b, const char *name, struct error *e)
{
    char path[BENCH_PATH_LEN + 64];
    snprintf(path, sizeof path, "%s/%s", b->data_dir, name);
    return bench_file(b, path, e);
}

void bench_files_drop(struct bench *b)
{
    for (int i = 0; i < b->n_files; i++)
        free(b->files[i].text);
    b->n_files = 0;
}

int bench_files_write(struct bench *b, struct error *e)
{
    int rc = 0;
    for (int i = 0; i < b->n_files && rc == 0; i++) {
        struct bench_file *f = &b->files[i];
        struct output_file o;
        /* a section's file left open by a failure is not part of a finished report */
        if (!f->text) {
            rc = error_set(e, ERROR_RUNTIME, NULL, "internal: %s was not closed", f->path);
            break;
        }
        if (output_open(&o, f->path, 1, e) != 0)
            rc = -1;
        else if (fwrite(f->text, 1, f->len, o.fp) != f->len) {
            error_set(e, ERROR_RUNTIME, NULL, "cannot write %s", f->path);
            output_abort(&o);
            rc = -1;
        } else if (output_commit(&o, e) != 0)
            rc = -1;
    }
    bench_files_drop(b);
    return rc;
}
