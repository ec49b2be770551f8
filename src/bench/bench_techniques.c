/* One technique at a time: unrolled steps (K per pass), objects per pass, the early-z test, and
 * the GL path's integration throughput against a plain C kernel on all cores. */
#include <string.h>
#include "bench/bench.h"
#include "bench/cpu_limit.h"

/* The paper's Table 1 Schwarzschild frame (10 spheres, 300 Euler steps); segments of 60 steps, so
 * that K = 1, 4, 10, 30 and 60 all divide a segment. */
static int technique_scene(struct bench *b, struct scene *s, int segments, struct error *e)
{
    if (bench_load_scene(s, "schwarzschild", b->width, b->height, e) != 0)
        return -1;
    bench_spheres(s, b->quick ? 2 : 10);
    bench_paper_steps(s, segments, 300, render_path_budget(&s->render));
    bench_apply_accel(s, ACCEL_NONE);
    return 0;
}

static int time_one(struct bench *b, const struct scene *s, const char *what, struct bench_timing *t, struct error *e)
{
    bench_progress(b, "%s", what);
    int rc = bench_time(b, s, b->runs, t, NULL, e);
    b->done++;
    return rc;
}

#define UNROLL_TARGET 8.0

/* Time the technique scene for each value of one integer setting; the speed-up over the first. */
struct sweep {
    const char *csv, *column, *what;   /* CSV file, its first column, the progress label */
    const int *values;
    int n, segments;
    void (*apply)(struct scene *s, int value);
};

static int sweep_on(struct bench *b, const struct sweep *w, struct scene *s, double *speedup, struct error *e)
{
    FILE *csv = bench_data_file(b, w->csv, e);
    if (!csv)
        return -1;
    fprintf(csv, "%s,median_s,passes,speedup\n", w->column);
    fprintf(b->md, "| %s | seconds | passes | speed-up over %d |\n|---|---|---|---|\n", w->column, w->values[0]);
    double base = 0.0;
    for (int i = 0; i < w->n; i++) {
        if (technique_scene(b, s, w->segments, e) != 0) {
            fclose(csv);
            return -1;
        }
        w->apply(s, w->values[i]);
        char what[96];
        snprintf(what, sizeof what, "%s %d", w->what, w->values[i]);
        struct bench_timing t;
        if (time_one(b, s, what, &t, e) != 0) {
            fclose(csv);
            return -1;
        }
        base = i == 0 ? t.median : base;
        speedup[i] = base / t.median;
        fprintf(csv, "%d,%.4f,%ld,%.3f\n", w->values[i], t.median, t.passes, speedup[i]);
        fprintf(b->md, "| %d | %.3f | %ld | %.2f |\n", w->values[i], t.median, t.passes, speedup[i]);
    }
    fclose(csv);
    return 0;
}

static int run_sweep(struct bench *b, const struct sweep *w, double *speedup, struct error *e)
{
    struct scene *s = scene_new(e);
    if (!s)
        return -1;
    int rc = sweep_on(b, w, s, speedup, e);
    scene_free(s);
    return rc;
}

static void apply_unroll(struct scene *s, int k)
{
    s->render.steps_per_pass = k;
    s->render.batch = SCENE_MAX_BATCH;
}

static void apply_batch(struct scene *s, int batch)
{
    s->render.steps_per_pass = 10;
    s->render.early_z = 1;
    s->render.batch = batch;
}

int bench_unrolling(struct bench *b, struct error *e)
{
    static const int ks[] = {1, 4, 10, 30, 60};
    const struct sweep w = {"unrolling.csv", "K", "unrolling: K =", ks, 5, 5, apply_unroll};
    double speedup[5];
    fprintf(b->md, "## Unrolled integration\n\nK integration steps per pass (K = 1 is the paper's scheme); the "
                   "Table 1 Schwarzschild frame, 5 segments of 60 steps, all objects in one pass, early-z off. "
                   "Unrolling is exact: the rays are the same for every K (tests/unit/test_acceleration.c).\n\n");
    if (run_sweep(b, &w, speedup, e) != 0)
        return -1;
    fprintf(b->md, "\nTarget: K = 10 at least %.0f times faster than K = 1: **%s** (%.2f).\n\n", UNROLL_TARGET,
            speedup[2] >= UNROLL_TARGET ? "met" : "missed", speedup[2]);
    return 0;
}

int bench_batching(struct bench *b, struct error *e)
{
    static const int batches[] = {1, 2, 5, 10};
    const struct sweep w = {"batching.csv", "objects per pass", "batching: objects per pass", batches, 4, 30,
                            apply_batch};
    double speedup[4];
    fprintf(b->md, "## Objects per pass\n\nThe Table 1 Schwarzschild frame (10 spheres, 30 segments of 10 steps, "
                   "K = 10, early-z on); batch 1 is the paper's one pass per object. Exact for every batch size.\n\n");
    if (run_sweep(b, &w, speedup, e) != 0)
        return -1;
    fprintf(b->md, "\n");
    return 0;
}

/* The early-z section, each case's scene loaded into S. */
static int early_z_on(struct bench *b, struct scene *s, struct error *e)
{
    FILE *csv = bench_data_file(b, "early_z.csv", e);
    if (!csv)
        return -1;
    fprintf(csv, "case,early_z,termination_interval,median_s,passes\n");
    fprintf(b->md, "## Early ray termination\n\nThe heavy passes draw at depth 0.5 with GL_LESS; a cheap pass "
                   "every `termination_interval` segments retires finished rays (depth 0). K = 1, one object "
                   "per pass. **Retired**: a sphere around the camera ends every ray in the first segment, so "
                   "all later passes run over retired rays: the ratio is what a pass over retired rays costs "
                   "relative to a normal one. **Table 1**: the Schwarzschild frame of Table 1.\n\n"
                   "| case | early-z | termination interval | seconds | passes |\n|---|---|---|---|---|\n");
    struct { const char *name; int enclosed, early_z, interval; } cases[] = {
        {"retired", 1, 0, 1}, {"retired", 1, 1, 1}, {"Table 1", 0, 0, 1}, {"Table 1", 0, 1, 1},
        {"Table 1", 0, 1, 3}, {"Table 1", 0, 1, 10},
    };
    double retired[2] = {0, 0};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        if (technique_scene(b, s, 30, e) != 0)
            return -1;
        if (cases[i].enclosed) {
            s->objects[0].center = s->camera.position;
            s->objects[0].radius = 0.05 * v3_len(v3_sub(s->camera.look_at, s->camera.position));
        }
        s->render.early_z = cases[i].early_z;
        s->render.termination_interval = cases[i].interval;
        char what[96];
        snprintf(what, sizeof what, "early-z: %s, early_z %d, interval %d", cases[i].name, cases[i].early_z,
                 cases[i].interval);
        struct bench_timing t;
        if (time_one(b, s, what, &t, e) != 0)
            return -1;
        if (cases[i].enclosed)
            retired[cases[i].early_z] = t.median;
        fprintf(csv, "%s,%d,%d,%.4f,%ld\n", cases[i].name, cases[i].early_z, cases[i].interval, t.median, t.passes);
        fprintf(b->md, "| %s | %s | %d | %.3f | %ld |\n", cases[i].name, cases[i].early_z ? "on" : "off",
                cases[i].interval, t.median, t.passes);
    }
    fclose(csv);
    fprintf(b->md, "\nA frame whose rays are all retired after the first segment costs %.2f of the same frame "
                   "without early-z.\n\n", retired[1] / retired[0]);
    return 0;
}

int bench_early_z(struct bench *b, struct error *e)
{
    return bench_with_scene(b, early_z_on, e);
}

/* GL integration steps per second: no objects, a bounding sphere no ray leaves, fixed RK4 steps,
 * 60 per pass; against the C kernel doing the same float arithmetic on every core. */
static int limit_on(struct bench *b, struct scene *s, struct error *e)
{
    if (bench_load_scene(s, "schwarzschild", b->width, b->height, e) != 0)
        return -1;
    s->n_objects = 0;
    s->render.method = METHOD_RK4;
    s->render.step_control = STEP_FIXED;
    s->render.bound_radius = 1e4;
    s->render.segments = b->quick ? 1 : 10;
    s->render.steps_per_segment = 60;
    s->render.steps_per_pass = 60;
    s->render.early_z = 0;
    struct bench_timing t;
    if (time_one(b, s, "limit: GL integration throughput", &t, e) != 0)
        return -1;
    double gl_rate = (double)s->render.width * s->render.height * s->render.segments * s->render.steps_per_segment /
                     t.median;
    struct cpu_limit_result c;
    bench_progress(b, "limit: C kernel on every core");
    if (cpu_limit_measure(&s->model, METHOD_RK4, 65536, 60, 0, b->quick ? 0.05 : 2.0, &c, e) != 0)
        return -1;
    b->done++;
    FILE *csv = bench_data_file(b, "limit.csv", e);
    if (!csv)
        return -1;
    fprintf(csv, "path,steps_per_second\ngl,%.4g\nc_kernel,%.4g\n", gl_rate, c.steps_per_second);
    fclose(csv);
    double fraction = gl_rate / c.steps_per_second;
    fprintf(b->md, "## The machine's limit\n\nSchwarzschild RK4 steps per second. GL: %dx%d rays, %d steps each, "
                   "no objects, the frame's time (median of %d) includes its few non-integration passes. C: the same "
                   "float arithmetic (src/bench/cpu_limit.c), vectorised by the compiler, %d threads.\n\n"
                   "| path | steps per second |\n|---|---|\n| GL (%s) | %.3g |\n| C kernel | %.3g |\n\n"
                   "The GL path reaches %.3f of the C kernel. Target: at least 0.5: **%s**.\n\n",
            s->render.width, s->render.height, s->render.segments * s->render.steps_per_segment, b->runs, c.threads,
            b->renderer, gl_rate, c.steps_per_second, fraction, fraction >= 0.5 ? "met" : "missed");
    return 0;
}

int bench_limit(struct bench *b, struct error *e)
{
    return bench_with_scene(b, limit_on, e);
}
