/* A frame in bands of rows, for progress on long renders: each band is its own run of the renderer
 * (renderer_run with an origin), its image and ray state copied into the whole frame's. Rays are
 * independent, so the result is the whole frame's bit for bit (tests/unit/test_progress.c). */
#ifndef BT_FRAME_BANDS_H
#define BT_FRAME_BANDS_H
#include "io/progress.h"
#include "render/renderer.h"

/* With progress, a band is sized to take about this long (from the rows before it). */
#define FRAME_BAND_SECONDS 0.25
/* Without --progress, only a render of at least this many pixels times samples is drawn in bands
 * (and can show progress): smaller ones are one run per sample, their passes as the scheme has them. */
#define FRAME_BAND_MIN_PIXELS 250000L
/* ... or whose rays may take at least this many integration steps (or chords) in all: about a
 * second of llvmpipe on two cores (docs/BENCH.md, the machine's limit). */
#define FRAME_BAND_MIN_RAY_STEPS 3e8

/* Whether a render of s drawing pixel_samples rays in all is drawn in bands without --progress
 * (FRAME_BAND_MIN_PIXELS or FRAME_BAND_MIN_RAY_STEPS reached). */
int frame_bands_wanted(const struct scene *s, long pixel_samples);

struct frame_progress {
    struct progress line;
    int banded;              /* draw in bands (else one run, and no progress) */
    int run, runs;           /* the whole-image run going on (a sample, or the centre's state), 0-based */
    int samples;             /* render.samples, for the label */
    int sample;              /* the sample of this run, 0-based; -1: the centre's state */
};

/* The image of s (its render.width x height, rays started (dx, dy) pixels off their centres) into
 * out, with the ray state when reads: in one run (p NULL or not banded), else in bands sized
 * to FRAME_BAND_SECONDS, reporting each. 0, or -1 with e. */
int frame_run_image(struct renderer *r, const struct scene *s, double dx, double dy, struct render_result *out,
                    enum render_read reads, struct frame_progress *p, struct error *e);
/* The same in bands of about rows_wanted rows, top first, no progress. Either way each band's
 * lower edge lies on an even row (counted from the bottom, as GL does), one more or less than
 * asked where it must, so that the 2x2 groups of pixels the GPU takes derivatives over (its star
 * pass) lie within one band and a banded frame is the whole frame's bit for bit. */
int frame_run_bands(struct renderer *r, const struct scene *s, int rows_wanted, struct render_result *out,
                    enum render_read reads, struct error *e);

#endif
