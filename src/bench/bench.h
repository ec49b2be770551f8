/* `bentray bench`: the paper's Table 1 and Figure 5, the benefit of unrolling, batching and
 * early-z, speed against error, and the machine's limit. Every figure in docs/BENCH.md is written
 * by this code: times are medians of several runs on one GL context, errors come from the
 * comparison with the CPU reference (src/results/compare.c). Never a timed test. */
#ifndef BT_BENCH_H
#define BT_BENCH_H
#include <stdio.h>
#include "gl/context.h"
#include "io/error.h"
#include "results/dump.h"
#include "scene/scene.h"

#define BENCH_PATH_LEN 512

/* A file of the report, written in memory while the bench runs and to its path only at the end,
 * when every section has succeeded (bench_files_write), through io/output_file.h: an interrupted or
 * failed bench leaves the earlier report as it was. */
struct bench_file {
    char path[BENCH_PATH_LEN + 64];
    FILE *fp;                    /* an open_memstream; its text once closed */
    char *text;
    size_t len;
};
#define BENCH_MAX_FILES 32

struct bench {
    struct gl_context *ctx;
    char renderer[160];          /* GL_RENDERER of the context */
    char backend[16];
    int runs;                    /* timed runs per configuration (after one warm-up) */
    int quick;                   /* tiny sizes: proves the command works, measures nothing */
    int width, height;           /* the paper's 800x600 unless quick */
    char out_dir[BENCH_PATH_LEN];
    char data_dir[BENCH_PATH_LEN]; /* out_dir/bench: CSV files and gnuplot scripts */
    char kiosk_config[BENCH_PATH_LEN]; /* --config; empty: the shipped one (kiosk_config_default_path) */
    FILE *md;                    /* BENCH.md being written */
    int done, total;             /* progress */
    double started;
    struct bench_file files[BENCH_MAX_FILES];
    int n_files;
};

struct bench_timing {
    double median, min, max;     /* seconds per frame */
    long passes;
    char path[16];               /* render path, "fp32+mrt" */
};

/* Progress on stderr: "[done/total] what (elapsed)". */
void bench_progress(struct bench *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Render s runs + 1 times on the bench's context (the first, which compiles the shaders, is not
 * timed); the median frame time. With d, the last frame's per-pixel dump. 0, or -1 with e: the
 * renderer's error as it is, or no memory for the dump (ERROR_RUNTIME). */
int bench_time(struct bench *b, const struct scene *s, int runs, struct bench_timing *t, struct dump *d,
               struct error *e);

/* The whole image of s (frame_run_samples: its samples, the stars and bloom drawn on the CPU), runs
 * + 1 times on a renderer of its own (the first not timed): the medians of the GPU's seconds, the
 * CPU's stars' and the bloom's; with rgba, the last image (the caller frees it). 0, or -1 with e. */
struct frame_times {
    double gpu, stars, bloom;
};
int bench_frame_times(struct bench *b, const struct scene *s, int runs, struct frame_times *t, unsigned char **rgba,
                      struct error *e);

/* The median of n times (sorted in place). */
double bench_median(double *times, int n);

/* Acceleration presets (the Table 1 columns): the paper's scheme without and with its techniques
 * and with all of the multipass scheme's; then all of them in the single pass. */
enum bench_accel { ACCEL_NONE, ACCEL_PAPER, ACCEL_ALL, ACCEL_SINGLE, ACCEL_FUSED, ACCEL_COUNT };
extern const char *const bench_accel_names[ACCEL_COUNT];
void bench_apply_accel(struct scene *s, enum bench_accel a);

/* The committed scene assets/scenes/NAME.scene at w x h (0 x 0: its own size). 0, or -1 with
 * scene_load's error (its place the scene file). */
int bench_load_scene(struct scene *s, const char *name, int w, int h, struct error *e);
/* A section that works on a scene of its own: run on one from scene_new, freed after. section's
 * result, or -1 with e where there is no memory for the scene. */
typedef int (*bench_scene_section)(struct bench *b, struct scene *s, struct error *e);
int bench_with_scene(struct bench *b, bench_scene_section section, struct error *e);
/* Replace the objects of s by n spheres in view, in a ring around the camera's look_at. */
void bench_spheres(struct scene *s, int n);
/* The paper's Table 1 / Figure 5 settings: n_segs segments, n_steps steps in all over a path of
 * `path` (the step is path / n_steps; render_path_budget keeps the scene's own). */
void bench_paper_steps(struct scene *s, int n_segs, int n_steps, double path);

/* Sections; each writes its part of BENCH.md and its CSV files. 0, or -1 with e, the error of
 * what failed passed on as it is (a scene's, the renderer's, the CPU reference's, the comparison's,
 * the kiosk's), printed as "WHERE: MESSAGE". */
int bench_table1(struct bench *b, struct error *e);
int bench_figure5(struct bench *b, struct error *e);
int bench_unrolling(struct bench *b, struct error *e);
int bench_batching(struct bench *b, struct error *e);
int bench_early_z(struct bench *b, struct error *e);
int bench_pareto(struct bench *b, struct error *e);
/* the paper's multipass scheme against the single pass, every model at its scene's own size */
int bench_pipelines(struct bench *b, struct error *e);
/* configurations bench_pareto times in all (for the progress count) */
extern const int bench_pareto_count;
/* the configurations the pipelines section times: its cases times their pipelines */
extern const int bench_pipelines_count;
int bench_limit(struct bench *b, struct error *e);
/* the observer's effects and moving objects, rays against polygons (bench_relativity.c) */
int bench_relativity(struct bench *b, struct error *e);
/* the kiosk's previews and refined frames (bench_kiosk.c) */
int bench_kiosk(struct bench *b, struct error *e);
/* the cost of render.samples against the error it leaves (bench_antialias.c) */
int bench_antialias(struct bench *b, struct error *e);
/* the cost of each addition to the image's light: the disk's emission, the tone curve, the stars,
 * the bloom (bench_light.c) */
int bench_light(struct bench *b, struct error *e);
/* the cost of the stars of the sky, drawn on the CPU (bench_stars.c) */
int bench_stars(struct bench *b, struct error *e);
/* what a fresh `bentray render` process adds to its frame (bench_wait.c) */
int bench_wait(struct bench *b, struct error *e);

/* out_dir/bench/NAME (CSV, gnuplot script) to write, in memory until bench_files_write; the caller
 * closes it with fclose. NULL with e ("cannot write PATH": a path that cannot be written, checked
 * now, ERROR_INPUT for a directory or a device there; no memory). */
FILE *bench_data_file(struct bench *b, const char *name, struct error *e);
/* The same for a path of its own (the report, BENCH.md). */
FILE *bench_file(struct bench *b, const char *path, struct error *e);
/* Every file of the report to its path, each through a temporary moved into place (data files first,
 * then the report); the files' texts freed. 0, or -1 with e (the first that failed; those before it
 * are written). */
int bench_files_write(struct bench *b, struct error *e);
/* The texts freed, nothing written. */
void bench_files_drop(struct bench *b);

#endif
