#include "io/clock.h"
#include "render/frame_bands.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The whole frame's image, empty; its ray state's arrays come with the first band
 * (band_arrays_alloc). */
static int frame_alloc(struct render_result *out, int w, int h, int hdr, struct error *e)
{
    size_t n = (size_t)w * h;
    memset(out, 0, sizeof *out);
    out->width = w;
    out->height = h;
    out->rgba = malloc(4 * n);
    int ok = out->rgba != NULL;
    if (ok && hdr)
        ok = (out->color = malloc(4 * n * sizeof(float))) != NULL;
    if (!ok) {
        render_result_free(out);
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory for a %dx%d frame", w, h);
    }
    return 0;
}

/* The whole frame's arrays of what the band brought back (the ray state's floats, or the outcome
 * codes of a frame that drew its colour itself), where full has none yet. 0, or -1 with e. */
static int band_arrays_alloc(struct render_result *full, const struct render_result *band, struct error *e)
{
    size_t n = (size_t)full->width * full->height;
    const float *from[4] = {band->position, band->velocity, band->hit, band->image};
    float **to[4] = {&full->position, &full->velocity, &full->hit, &full->image};
    int ok = 1;
    for (int k = 0; k < 4 && ok; k++)
        if (from[k] && !*to[k])
            ok = (*to[k] = malloc(4 * n * sizeof(float))) != NULL;
    if (ok && band->outcome && !full->outcome)
        ok = (full->outcome = malloc(n ? n : 1)) != NULL;
    if (!ok)
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory for a %dx%d frame", full->width, full->height);
    return 0;
}

/* The rows of the band from image row `top` (rows wanted, at least 1): its lower edge on an even
 * row of the frame as GL counts them from the bottom (h - top - rows), so that no 2x2 group of
 * pixels straddles two bands; the GPU's stars take their footprints from derivatives across such
 * groups, and a band's pixels are then the whole frame's whatever the bands. */
static int band_rows(int top, int rows, int h)
{
    rows = rows < 1 ? 1 : rows > h - top ? h - top : rows;
    if (top + rows < h && (h - top - rows) % 2 != 0)
        rows += rows > 1 ? -1 : 1;
    return rows;
}

/* Image rows [top, top + rows), top row first, in one run, copied into the whole frame. */
static int run_rows(struct renderer *r, const struct scene *s, int top, int rows, struct render_result *full,
                    enum render_read reads, struct error *e)
{
    int w = s->render.width, h = s->render.height;
    struct render_result band;
    memset(&band, 0, sizeof band);
    if (renderer_run(r, s, 0, h - top - rows, w, rows, NULL, NULL, e) != 0 ||
        renderer_read(r, &band, reads, e) != 0 || band_arrays_alloc(full, &band, e) != 0) {
        render_result_free(&band);
        return -1;
    }
    size_t at = (size_t)top * w * 4, count = (size_t)rows * w * 4;
    memcpy(full->rgba + at, band.rgba, count);
    if (full->color && band.color)
        memcpy(full->color + at, band.color, count * sizeof(float));
    float *from[4] = {band.position, band.velocity, band.hit, band.image};
    float *to[4] = {full->position, full->velocity, full->hit, full->image};
    for (int k = 0; k < 4; k++)
        if (to[k] && from[k])
            memcpy(to[k] + at, from[k], count * sizeof(float));
    if (full->outcome && band.outcome)
        memcpy(full->outcome + at / 4, band.outcome, count / 4);
    full->outcome_nonfinite += band.outcome_nonfinite;
    full->seconds += band.seconds;
    full->compile_seconds += band.compile_seconds;
    full->passes += band.passes;
    render_result_free(&band);
    return 0;
}

static void report(struct frame_progress *p, int rows_done, int rows)
{
    char label[96], sample[48] = "";
    if (p->sample < 0)
        snprintf(sample, sizeof sample, "pixel centres, ");
    else if (p->samples > 1)
        snprintf(sample, sizeof sample, "sample %d/%d, ", p->sample + 1, p->samples);
    snprintf(label, sizeof label, "gpu: %s%d/%d rows", sample, rows_done, rows);
    double done = (p->run + (double)rows_done / rows) / (p->runs > 0 ? p->runs : 1);
    progress_report(&p->line, label, done, p->run + 1 == p->runs && rows_done == rows);
}

int frame_run_image(struct renderer *r, const struct scene *s, double dx, double dy, struct render_result *out,
                    enum render_read reads, struct frame_progress *p, struct error *e)
{
    int w = s->render.width, h = s->render.height, rc = 0;
    renderer_set_subpixel(r, dx, dy);
    renderer_set_reads(r, reads);
    if (!p || !p->banded) {
        memset(out, 0, sizeof *out);
        rc = renderer_run(r, s, 0, 0, w, h, NULL, NULL, e) == 0 && renderer_read(r, out, reads, e) == 0 ? 0 : -1;
    } else if ((rc = frame_alloc(out, w, h, renderer_hdr(r), e)) == 0) {
        /* a first band of a thirty-second of the image tells how long a row takes */
        int rows = h / 32 > 0 ? h / 32 : 1;
        for (int top = 0; top < h && rc == 0;) {
            rows = band_rows(top, rows, h);
            double t0 = clock_seconds();
            rc = run_rows(r, s, top, rows, out, reads, e);
            double per_row = (clock_seconds() - t0) / rows;
            top += rows;
            report(p, top, h);
            double next = per_row > 0.0 ? FRAME_BAND_SECONDS / per_row : h;
            rows = next < 1.0 ? 1 : next > h ? h : (int)next;
        }
        if (rc != 0)
            render_result_free(out);
    }
    renderer_set_subpixel(r, 0.0, 0.0);
    return rc;
}

int frame_run_bands(struct renderer *r, const struct scene *s, int rows_wanted, struct render_result *out,
                    enum render_read reads, struct error *e)
{
    int h = s->render.height, rc = frame_alloc(out, s->render.width, h, renderer_hdr(r), e);
    renderer_set_reads(r, reads);
    for (int top = 0, rows; top < h && rc == 0; top += rows) {
        rows = band_rows(top, rows_wanted, h);
        rc = run_rows(r, s, top, rows, out, reads, e);
    }
    if (rc != 0)
        render_result_free(out);
    return rc;
}
