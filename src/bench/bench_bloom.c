/* Bloom (render.bloom, results/bloom.h): what it adds to a frame, demo.scene's view at the kiosk's
 * 1280x720 and at 1920x1080, one ray a pixel: the frame read as floats instead of bytes (the GPU's
 * own cost of it) and the bloom itself on one CPU core. */
#include <stdlib.h>
#include "bench/bench.h"
#include "render/frame.h"
#include "render/renderer.h"
#include "results/bloom.h"

/* Median GPU seconds (the frame, read as floats where bloom is on) and bloom seconds of runs frames
 * after a warm-up. */
static int time_bloom(struct bench *b, const struct scene *s, int runs, double *gpu, double *bloom,
                      struct error *e)
{
    struct renderer *r = renderer_create(b->ctx, s, e);
    if (!r)
        return -1;
    double g[64], t[64];
    runs = runs < 1 ? 1 : runs < 64 ? runs : 64;
    int rc = 0;
    for (int k = 0; k <= runs && rc == 0; k++) {
        struct render_result res;
        rc = frame_run_samples(r, s, &res, 0, PROGRESS_NONE, e);
        if (rc != 0)
            break;
        if (k > 0) {
            g[k - 1] = res.seconds;
            t[k - 1] = res.bloom_seconds;
        }
        render_result_free(&res);
    }
    renderer_destroy(r);
    if (rc != 0)
        return -1;
    *gpu = bench_median(g, runs);
    *bloom = bench_median(t, runs);
    return 0;
}

static const int bloom_sizes[][2] = {{1280, 720}, {1920, 1080}};

/* The bloom section, its scene loaded into S. */
static int bloom_on(struct bench *b, struct scene *s, struct error *e)
{
    if (bench_load_scene(s, "demo", 0, 0, e) != 0)
        return -1;
    FILE *csv = bench_data_file(b, "bloom.csv", e);
    if (!csv)
        return -1;
    fprintf(csv, "width,height,bloom,gpu_seconds,bloom_seconds\n");
    s->render.samples = 1;
    double strength = s->render.bloom > 0.0 ? s->render.bloom : 0.15;
    fprintf(b->md, "## Bloom\n\n`render.bloom` (docs/SCENES.md, src/results/bloom.h): demo.scene's view, one ray a "
                   "pixel, without bloom and with `bloom = %g`, `bloom_radius = %g`. With it the GPU's frame is read "
                   "as floats (its colour drawn in a pass of its own) and the bloom runs on one CPU core after it; "
                   "median seconds per frame of %d runs.\n\n| size | GPU frame without | GPU frame as floats | bloom "
                   "on the CPU | total with bloom | ratio |\n|---|---|---|---|---|---|\n",
            strength, s->render.bloom_radius, b->runs);
    int rc = 0;
    double bloom_720 = 0.0;
    for (int k = 0; k < (b->quick ? 1 : 2) && rc == 0; k++) {
        s->render.width = b->quick ? 64 : bloom_sizes[k][0];
        s->render.height = b->quick ? 36 : bloom_sizes[k][1];
        double plain, unused, gpu, bloom;
        bench_progress(b, "bloom: demo at %dx%d without", s->render.width, s->render.height);
        s->render.bloom = 0.0;
        rc = time_bloom(b, s, b->runs, &plain, &unused, e);
        b->done++;
        bench_progress(b, "bloom: demo at %dx%d with bloom %g", s->render.width, s->render.height, strength);
        s->render.bloom = strength;
        if (rc == 0)
            rc = time_bloom(b, s, b->runs, &gpu, &bloom, e);
        b->done++;
        if (rc != 0)
            break;
        bloom_720 = k == 0 ? bloom : bloom_720;
        fprintf(b->md, "| %dx%d | %.3f | %.3f | %.3f | %.3f | %.2f |\n", s->render.width, s->render.height, plain, gpu,
                bloom, gpu + bloom, plain > 0.0 ? (gpu + bloom) / plain : 0.0);
        fprintf(csv, "%d,%d,0,%.5f,0\n%d,%d,%g,%.5f,%.5f\n", s->render.width, s->render.height, plain,
                s->render.width, s->render.height, strength, gpu, bloom);
    }
    if (rc == 0)
        fprintf(b->md, "\nEach of the bloom's %d Gaussians is drawn on an image of a pyramid where it is one to "
                       "two pixels wide, so it costs about the same whatever the image shows and whatever "
                       "`bloom_radius`: the full image is read and written a few times for each. On a Raspberry Pi 4 "
                       "(an estimate: its Cortex-A72 is 2-4 times slower per core than this machine's) the first "
                       "size's %.0f ms would be about %.0f-%.0f ms. The kiosk draws no bloom.\n\n",
                BLOOM_LEVELS, 1e3 * bloom_720, 2e3 * bloom_720, 4e3 * bloom_720);
    fclose(csv);
    return rc;
}

int bench_bloom(struct bench *b, struct error *e)
{
    return bench_with_scene(b, bloom_on, e);
}
