/* Anti-aliasing (render.samples): the cost of N rays a pixel against the error left, for a scene
 * with edges, a lensed disk and a shadow (demo.scene), against 64 rays a pixel. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "bench/bench.h"
#include "io/sample_average.h"

#define AA_REFERENCE_SAMPLES 64

static const int aa_counts[] = {1, 2, 4, 9, 16};
#define AA_COUNTS (int)(sizeof aa_counts / sizeof aa_counts[0])



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
    struct frame_times t_ref;
    unsigned char *reference;
    if (bench_frame_times(b, s, 1, &t_ref, &reference, e) != 0) {
        fclose(csv);
        return -1;
    }
    b->done++;
    fprintf(b->md, "## Anti-aliasing\n\n`render.samples = N` (docs/SCENES.md): demo.scene at %dx%d, N rays a pixel on "
                   "the shared pattern, each a whole frame, averaged in linear light. Error: the root mean square "
                   "difference from the image at %d samples a pixel, in linear light (0 to 1) over the colour "
                   "channels; median seconds per image of %d runs (the GPU's frames, and the stars of the sky "
                   "where the CPU draws them).\n\n| samples | seconds | ratio to 1 | rms error "
                   "| error ratio to 1 |\n|---|---|---|---|---|\n", s->render.width, s->render.height,
            s->render.samples, b->runs);
    double t1 = 0.0, e1 = 0.0;
    int rc = 0;
    for (int k = 0; k < (b->quick ? 2 : AA_COUNTS) && rc == 0; k++) {
        s->render.samples = aa_counts[k];
        bench_progress(b, "antialias: demo at %d samples a pixel", aa_counts[k]);
        struct frame_times times;
        unsigned char *image;
        rc = bench_frame_times(b, s, b->runs, &times, &image, e);
        if (rc != 0)
            break;
        double t = times.gpu + times.stars + times.bloom;
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
