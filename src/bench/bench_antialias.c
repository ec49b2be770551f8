/* Anti-aliasing (render.samples): the cost of N rays a pixel against the error left, for a scene
 * with edges, a lensed disk and a shadow (demo.scene), against 64 rays a pixel. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "bench/bench.h"
#include "io/sample_average.h"
#include "render/frame.h"
#include "render/renderer.h"

#define AA_REFERENCE_SAMPLES 64

static const int aa_counts[] = {1, 2, 4, 9, 16};
#define AA_COUNTS (int)(sizeof aa_counts / sizeof aa_counts[0])



/* The image of s with its samples, runs times after a warm-up: the median seconds and the last image. */
static int time_samples(struct bench *b, const struct scene *s, int runs, double *median, unsigned char **rgba,
                        struct error *e)
{
    struct renderer *r = renderer_create(b->ctx, s, e);
    if (!r)
        return -1;
    double times[64];
    runs = runs < 1 ? 1 : runs < 64 ? runs : 64;
    int rc = 0;
    *rgba = NULL;
    for (int k = 0; k <= runs && rc == 0; k++) {
        struct render_result res;
        rc = frame_run_samples(r, s, &res, 0, PROGRESS_NONE, e);
        if (rc != 0)
            break;
        if (k > 0)
            times[k - 1] = res.seconds;
        free(*rgba);
        *rgba = res.rgba;
        res.rgba = NULL;
        render_result_free(&res);
    }
    renderer_destroy(r);
    if (rc != 0) {
        free(*rgba);
        *rgba = NULL;
        return -1;
    }
    *median = bench_median(times, runs);
    return 0;
}

/* The anti-aliasing section, its scene loaded into S. */
static int antialias_on(struct bench *b, struct scene *s, struct error *e)
{
    if (bench_load_scene(s, "demo", b->quick ? 32 : 0, b->quick ? 24 : 0, e) != 0)
        return -1;
    FILE *csv = bench_data_file(b, "antialias.csv", e);
    if (!csv)
        return -1;
    size_t pixels = (size_t)s->render.width * s->render.height;
    fprintf(csv, "samples,seconds,rms_linear\n");
    s->render.samples = b->quick ? 4 : AA_REFERENCE_SAMPLES;
    bench_progress(b, "antialias: demo at %d samples a pixel (the reference)", s->render.samples);
    double t_ref;
    unsigned char *reference;
    if (time_samples(b, s, 1, &t_ref, &reference, e) != 0) {
        fclose(csv);
        return -1;
    }
    b->done++;
    fprintf(b->md, "## Anti-aliasing\n\n`render.samples = N` (docs/SCENES.md): demo.scene at %dx%d, N rays a pixel on "
                   "the shared pattern, each a whole frame, averaged in linear light. Error: the root mean square "
                   "difference from the image at %d samples a pixel, in linear light (0 to 1) over the colour "
                   "channels; median seconds per image of %d runs.\n\n| samples | seconds | ratio to 1 | rms error "
                   "| error ratio to 1 |\n|---|---|---|---|---|\n", s->render.width, s->render.height,
            s->render.samples, b->runs);
    double t1 = 0.0, e1 = 0.0;
    int rc = 0;
    for (int k = 0; k < (b->quick ? 2 : AA_COUNTS) && rc == 0; k++) {
        s->render.samples = aa_counts[k];
        bench_progress(b, "antialias: demo at %d samples a pixel", aa_counts[k]);
        double t;
        unsigned char *image;
        rc = time_samples(b, s, b->runs, &t, &image, e);
        if (rc != 0)
            break;
        b->done++;
        double rms = image_rms_linear(image, reference, pixels);
        free(image);
        if (k == 0) {
            t1 = t;
            e1 = rms;
        }
        fprintf(b->md, "| %d | %.3f | %.2f | %.5f | %.2f |\n", aa_counts[k], t, t / t1, rms, e1 > 0.0 ? rms / e1 : 0.0);
        fprintf(csv, "%d,%.5f,%.6f\n", aa_counts[k], t, rms);
    }
    fprintf(b->md, "\n");
    free(reference);
    fclose(csv);
    return rc;
}

int bench_antialias(struct bench *b, struct error *e)
{
    return bench_with_scene(b, antialias_on, e);
}
