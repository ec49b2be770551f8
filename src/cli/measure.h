/* One scene through either engine into a per-pixel dump with its time: what `bentray error` and
 * the accuracy report compare. */
#ifndef BT_MEASURE_H
#define BT_MEASURE_H
#include "io/progress.h"
#include "ref/engine_cpu.h"
#include "scene/scene.h"

/* The rays' outcomes counted, and the pixels that read as black: what a summary and its warnings
 * say. */
struct outcome_counts {
    long objects, sky, captured, unfinished, failed;
    long dark;              /* pixels whose brightest channel is at most OUTCOME_DARK_CHANNEL */
};
/* A pixel whose brightest channel is at most this reads as black on a screen. */
#define OUTCOME_DARK_CHANNEL 16

struct measured {
    struct dump dump;       /* per-pixel records with colours; on the GPU without need_state, only its
                             * header (size, scene, engine): no records */
    struct outcome_counts counts;
    unsigned char *rgba;    /* the image (owned) */
    float *color;           /* the same unclamped, RGBA floats, when asked for (hdr); else NULL */
    double seconds;         /* GPU: the passes, glFinish included; CPU: wall time of the render */
    double compile_seconds; /* GPU: of seconds, compiling the shaders (render_result); CPU: 0 */
    long work;              /* GPU: quads drawn; CPU: accepted integration steps */
    char engine[40];        /* "gpu fp32+mrt", "cpu dopri5 rtol 1e-10" */
    char device[160];       /* GL renderer and back-end, or the CPU thread count */
    char how[1280];          /* one line for people: path, device, time, work */
    long nonfinite;         /* GPU: non-finite values in the ray state (should be 0) */
};

/* 0, or -1 with e (its status tells a user error, exit 2, from a runtime failure, 1). */
/* need_state: the dump's every record; else the rays' outcomes counted only (what a summary says:
 * a single-pass frame then runs once, not twice, and no per-pixel records are made). progress: whether a long render reports its
 * rows and samples on stderr (io/progress.h). */
int measure_gpu(const struct scene *s, const char *backend, int need_state, enum progress_mode progress, int hdr,
                struct measured *m, struct error *e);
/* The CPU reference: 0, or -1 with cpu_render's error and its status (a texture that cannot be
 * read: ERROR_INPUT where the file is refused or bad, ERROR_RUNTIME where the machine fails, as
 * out of memory is). */
int measure_cpu(const struct scene *s, const struct cpu_render_options *o, struct measured *m, struct error *e);
void measured_free(struct measured *m);

#endif
