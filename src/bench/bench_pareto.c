/* Speed against error: for each scene, configurations of method, step, adaptive tolerance,
 * precision and K, each timed and compared with the CPU reference; the Pareto front and the
 * cheapest configuration reaching each error level. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "bench/bench.h"
#include "results/compare.h"
#include "ref/engine_cpu.h"
#include "results/quality.h"
#include "results/tone.h"

struct pareto_config {
    const char *name;
    enum integration_method method;
    double step_factor;           /* step = scene step x factor, the segment length kept */
    double segment_factor;        /* segment = scene segment x factor, the step and the path kept */
    enum step_control control;
    double tolerance;
    int fp16, k1;
    int scene_method;             /* keep the scene's method (the variants of the scene default) */
    double step_max_factor;       /* adaptive: step_max = scene step x factor (0: the default, x64) */
    double chord_tolerance;       /* method orbit_table: render.chord_tolerance (0: the scene's) */
    int multipass;                /* method orbit_table: the paper's scheme instead of the single pass */
    double far_step_factor;       /* fixed steps: far_step = the step x factor (0: steps do not grow) */
};

static const struct pareto_config configs[] = {
    {"scene default", 0, 1.0, 1.0, STEP_FIXED, 0, 0, 0, 1, 0, 0, 0, 0},
    {"scene default, K = 1", 0, 1.0, 1.0, STEP_FIXED, 0, 0, 1, 1, 0, 0, 0, 0},
    {"scene default, fp16", 0, 1.0, 1.0, STEP_FIXED, 0, 1, 0, 1, 0, 0, 0, 0},
    {"euler, step x2", METHOD_EULER, 2.0, 1.0, STEP_FIXED, 0, 0, 0, 0, 0, 0, 0, 0},
    {"euler, step x1", METHOD_EULER, 1.0, 1.0, STEP_FIXED, 0, 0, 0, 0, 0, 0, 0, 0},
    {"euler, step x0.5", METHOD_EULER, 0.5, 1.0, STEP_FIXED, 0, 0, 0, 0, 0, 0, 0, 0},
    {"rk4, step x4", METHOD_RK4, 4.0, 1.0, STEP_FIXED, 0, 0, 0, 0, 0, 0, 0, 0},
    {"rk4, step x2", METHOD_RK4, 2.0, 1.0, STEP_FIXED, 0, 0, 0, 0, 0, 0, 0, 0},
    {"rk4, step x1", METHOD_RK4, 1.0, 1.0, STEP_FIXED, 0, 0, 0, 0, 0, 0, 0, 0},
    {"rk4, step x0.5", METHOD_RK4, 0.5, 1.0, STEP_FIXED, 0, 0, 0, 0, 0, 0, 0, 0},
    {"dopri5, step x4", METHOD_DOPRI5, 4.0, 1.0, STEP_FIXED, 0, 0, 0, 0, 0, 0, 0, 0},
    {"dopri5, step x2", METHOD_DOPRI5, 2.0, 1.0, STEP_FIXED, 0, 0, 0, 0, 0, 0, 0, 0},
    {"rk4, far step x2", METHOD_RK4, 1.0, 1.0, STEP_FIXED, 0, 0, 0, 0, 0, 0, 0, 2.0},
    {"rk4, far step x4", METHOD_RK4, 1.0, 1.0, STEP_FIXED, 0, 0, 0, 0, 0, 0, 0, 4.0},
    {"rk4, far step x8", METHOD_RK4, 1.0, 1.0, STEP_FIXED, 0, 0, 0, 0, 0, 0, 0, 8.0},
    {"rk4, segment x0.5", METHOD_RK4, 1.0, 0.5, STEP_FIXED, 0, 0, 0, 0, 0, 0, 0, 0},
    {"rk4, segment x0.2", METHOD_RK4, 1.0, 0.2, STEP_FIXED, 0, 0, 0, 0, 0, 0, 0, 0},
    {"rk4, step x2, segment x0.4", METHOD_RK4, 2.0, 0.4, STEP_FIXED, 0, 0, 0, 0, 0, 0, 0, 0},
    {"rk4 doubling, tol 1e-3", METHOD_RK4, 1.0, 1.0, STEP_DOUBLING, 1e-3, 0, 0, 0, 0, 0, 0, 0},
    {"rk4 doubling, tol 1e-4", METHOD_RK4, 1.0, 1.0, STEP_DOUBLING, 1e-4, 0, 0, 0, 0, 0, 0, 0},
    {"rk4 doubling, tol 1e-5", METHOD_RK4, 1.0, 1.0, STEP_DOUBLING, 1e-5, 0, 0, 0, 0, 0, 0, 0},
    {"dopri5 embedded, tol 1e-4", METHOD_DOPRI5, 1.0, 1.0, STEP_EMBEDDED, 1e-4, 0, 0, 0, 0, 0, 0, 0},
    {"dopri5 embedded, tol 1e-6", METHOD_DOPRI5, 1.0, 1.0, STEP_EMBEDDED, 1e-6, 0, 0, 0, 0, 0, 0, 0},
    {"dopri5 embedded, tol 1e-8", METHOD_DOPRI5, 1.0, 1.0, STEP_EMBEDDED, 1e-8, 0, 0, 0, 0, 0, 0, 0},
    {"dopri5 embedded, tol 1e-6, step max x4", METHOD_DOPRI5, 1.0, 1.0, STEP_EMBEDDED, 1e-6, 0, 0, 0, 4.0, 0, 0, 0},
    {"dopri5 embedded, tol 1e-8, step max x4", METHOD_DOPRI5, 1.0, 1.0, STEP_EMBEDDED, 1e-8, 0, 0, 0, 4.0, 0, 0, 0},
    /* exact orbits (Schwarzschild only; they come last, so other models take the configurations above) */
    {"orbit table, chord 1e-2", METHOD_ORBIT_TABLE, 1.0, 1.0, STEP_FIXED, 0, 0, 0, 0, 0, 1e-2, 0, 0},
    {"orbit table, chord 1e-3", METHOD_ORBIT_TABLE, 1.0, 1.0, STEP_FIXED, 0, 0, 0, 0, 0, 1e-3, 0, 0},
    {"orbit table, chord 1e-4", METHOD_ORBIT_TABLE, 1.0, 1.0, STEP_FIXED, 0, 0, 0, 0, 0, 1e-4, 0, 0},
    {"orbit table, chord 1e-3, multipass", METHOD_ORBIT_TABLE, 1.0, 1.0, STEP_FIXED, 0, 0, 0, 0, 0, 1e-3, 1, 0},
};
#define N_CONFIGS (int)(sizeof configs / sizeof configs[0])
#define N_ORBIT_CONFIGS 4

struct pareto_scene {
    const char *title, *scene;
    int sky_only, paper_size;     /* objects removed; at the bench's 800x600 instead of the scene's size */
};

static const struct pareto_scene scenes[] = {
    {"schwarzschild sky", "schwarzschild", 1, 1},
    {"schwarzschild", "schwarzschild", 0, 0},
    {"neutron_star", "neutron_star", 0, 0},
    {"lorenz", "lorenz", 0, 0},
    {"rossler", "rossler", 0, 0},
    {"potential", "potential", 0, 0},
    {"refraction", "refraction", 0, 0},
};
#define N_SCENES (int)(sizeof scenes / sizeof scenes[0])
const int bench_pareto_count = N_SCENES * N_CONFIGS;

struct pareto_point {
    double seconds, outcome_pct, sky_p99, hit_p99;
    int front;
    long passes;
    const char *not_applicable;   /* why the configuration was not run on this scene, or NULL */
    char realised[48];            /* the factors as this scene's whole steps a chord allow, where not as named */
};

/* Largest K <= 64 dividing n (a segment ends on a pass boundary). */
static int unroll_for(int n)
{
    for (int k = n < SCENE_MAX_STEPS_PER_PASS ? n : SCENE_MAX_STEPS_PER_PASS; k > 1; k--)
        if (n % k == 0)
            return k;
    return 1;
}

/* Steps a segment for a wanted (fractional) number: the nearest whole number, at least one. */
static int whole_steps(double wanted)
{
    long n = lround(wanted);
    return n < 1 ? 1 : (int)n;
}

/* The configuration's step and segment factors on r, as near as whole steps a segment allow. */
static void apply_factors(struct render_settings *r, const struct pareto_config *c)
{
    double segment = r->steps_per_segment * r->step_size;
    if (c->step_factor != 1.0) {
        r->steps_per_segment = whole_steps(r->steps_per_segment / c->step_factor);
        r->step_size = segment / r->steps_per_segment;
    }
    if (c->segment_factor != 1.0) {
        render_fix_segments(r);
        long path = (long)r->segments * r->steps_per_segment;
        r->steps_per_segment = whole_steps(r->steps_per_segment * c->segment_factor);
        r->segments = (int)((path + r->steps_per_segment - 1) / r->steps_per_segment);
    }
}

static void apply_config(struct scene *s, const struct pareto_config *c)
{
    struct render_settings *r = &s->render;
    if (!c->scene_method)
        r->method = c->method;
    apply_factors(r, c);
    if (!c->scene_method) {       /* the scene default's variants keep its step control too */
        r->step_control = c->control;
        if (c->control != STEP_FIXED)
            r->tolerance = c->tolerance;
    }
    /* fixed steps take their budget from the segments alone: where they were set above (from the
     * path of a scene whose default is adaptive), the path is theirs already */
    if (r->step_control == STEP_FIXED && r->segments > 0)
        r->max_path = 0.0;
    if (c->step_max_factor > 0)
        r->step_max = r->step_size * c->step_max_factor;
    /* the scene default's variants keep its far steps; the others grow theirs as named, or none */
    if (!c->scene_method)
        r->far_step = c->far_step_factor > 0.0 ? r->step_size * c->far_step_factor : 0.0;
    r->early_z = 1;
    r->batch = SCENE_MAX_BATCH;
    r->steps_per_pass = c->k1 ? 1 : unroll_for(r->steps_per_segment);
    if (c->fp16)
        r->precision = PRECISION_FP16;
    if (c->chord_tolerance > 0.0)
        r->chord_tolerance = c->chord_tolerance;
    if (r->method == METHOD_ORBIT_TABLE)
        r->pipeline = c->multipass ? PIPELINE_MULTIPASS : PIPELINE_AUTO;
}

/* How many of the configurations a scene's model takes: the exact-orbit ones (last in the list)
 * only for Schwarzschild. */
static int configs_of(const struct scene *base)
{
    return model_ops_of(base->model.type)->exact_orbits ? N_CONFIGS : N_CONFIGS - N_ORBIT_CONFIGS;
}

/* S = BASE in configuration C, validated; 0, or -1 with e naming the configuration and the scene. */
static int configure(struct scene *s, const struct scene *base, int c, const char *title, struct error *e)
{
    *s = *base;
    apply_config(s, &configs[c]);
    struct error why;
    if (scene_validate(s, &why) == 0)
        return 0;
    return error_set(e, ERROR_RUNTIME, NULL, "internal: configuration %s of %s: %s", configs[c].name, title,
                     why.message);
}

/* The step and segment factors that apply_factors realises on scene s: a segment holds a whole
 * number of steps, at least one, so a factor may come out otherwise than named (a step x2 of three
 * steps a chord is x1.5) or not at all (a step x2 of one step a chord keeps the step). */
static void realised_factors(const struct scene *s, const struct pareto_config *c, double *step, double *segment)
{
    struct render_settings r = s->render;
    apply_factors(&r, c);
    *step = r.step_size / s->render.step_size;
    *segment = r.steps_per_segment * r.step_size / (s->render.steps_per_segment * s->render.step_size);
}

/* Why configuration c is not run on scene s, or NULL. The orbit table needs 32-bit floats: a scene
 * on exact orbits has no fp16 variant of its default. A variant whose factor the scene's whole
 * steps a chord cannot realise at all would repeat another row. */
static const char *config_not_applicable(const struct scene *s, const struct pareto_config *c)
{
    if (c->fp16 && c->scene_method && s->render.method == METHOD_ORBIT_TABLE)
        return "the orbit table needs fp32";
    double step, segment;
    realised_factors(s, c, &step, &segment);
    if ((c->step_factor != 1.0 && step == 1.0) || (c->segment_factor != 1.0 && segment == 1.0))
        return "not with this scene's steps a chord";
    if (c->far_step_factor > 0.0 && !(s->render.step_size * step * c->far_step_factor < s->render.bound_radius))
        return "a far step across the bounding sphere";
    if (c->far_step_factor > 0.0 && s->n_objects == 0)
        return "no object to grow the steps away from";
    return NULL;
}

static int config_applies(const struct scene *s, const struct pareto_config *c)
{
    return config_not_applicable(s, c) == NULL;
}

/* The factors actually taken, where they are not those of the configuration's name (else ""). */
static void realised_note(const struct scene *s, const struct pareto_config *c, char *out, size_t len)
{
    double step, segment;
    realised_factors(s, c, &step, &segment);
    out[0] = '\0';
    if (fabs(step - c->step_factor) > 1e-2 * c->step_factor || fabs(segment - c->segment_factor) > 1e-2 * c->segment_factor)
        snprintf(out, len, " (here step x%.3g, segment x%.3g)", step, segment);
}

static double nan_as_zero(double x)
{
    return isnan(x) ? 0.0 : x;
}

/* i is dominated when another point is no slower and no less accurate in every measure, and
 * better in one. */
static void mark_front(struct pareto_point *p, int n)
{
    for (int i = 0; i < n; i++) {
        p[i].front = !isnan(p[i].seconds);
        for (int j = 0; j < n && p[i].front; j++) {
            if (j == i || isnan(p[j].seconds))
                continue;
            double a[4] = {p[j].seconds, p[j].outcome_pct, nan_as_zero(p[j].sky_p99), nan_as_zero(p[j].hit_p99)};
            double b[4] = {p[i].seconds, p[i].outcome_pct, nan_as_zero(p[i].sky_p99), nan_as_zero(p[i].hit_p99)};
            int no_worse = 1, better = 0;
            for (int k = 0; k < 4; k++) {
                no_worse &= a[k] <= b[k];
                better |= a[k] < b[k];
            }
            if (no_worse && better)
                p[i].front = 0;
        }
    }
}

/* Scene K of the table: its reference (BASE as loaded) and each configuration (S) timed against it; the
 * number of configurations, or -1 with e. */
static int measure_on(struct bench *b, int k, struct scene *base, struct scene *s, struct pareto_point *pts,
                      struct quality_bound *q, FILE *csv, struct error *e)
{
    const struct pareto_scene *ps = &scenes[k];
    int w = b->quick ? 32 : ps->paper_size ? b->width : 0, h = b->quick ? 24 : ps->paper_size ? b->height : 0;
    if (bench_load_scene(base, ps->scene, w, h, e) != 0)
        return -1;
    if (ps->sky_only)
        base->n_objects = 0;
    *q = base->quality;
    struct cpu_image ref;
    struct cpu_render_options o = {.threads = 0, .progress = 0};
    ref_options_default(&o.ref, base);
    bench_progress(b, "speed against error: %s, CPU reference at %dx%d", ps->title, base->render.width,
                   base->render.height);
    if (cpu_render(base, &o, &ref, e) != 0)
        return -1;
    int n = b->quick ? 3 : configs_of(base);
    for (int c = 0; c < n; c++) {
        if (!config_applies(base, &configs[c])) {
            pts[c] = (struct pareto_point){NAN, NAN, NAN, NAN, 0, 0, config_not_applicable(base, &configs[c]), ""};
            continue;
        }
        if (configure(s, base, c, ps->title, e) != 0) {
            cpu_image_free(&ref);
            return -1;
        }
        struct bench_timing t;
        struct dump d;
        struct compare_result cr;
        bench_progress(b, "speed against error: %s, %s", ps->title, configs[c].name);
        if (bench_time(b, s, b->runs, &t, &d, e) != 0) {
            cpu_image_free(&ref);
            return -1;
        }
        if (compare_dumps(&d, &ref.dump, &cr, e) != 0) {
            dump_free(&d);
            cpu_image_free(&ref);
            return -1;
        }
        dump_free(&d);
        b->done++;
        pts[c] = (struct pareto_point){t.median, 100.0 * cr.outcome_fraction, cr.sky_angle.p99, cr.hit_relative.p99, 0,
                                      t.passes, NULL, ""};
        realised_note(base, &configs[c], pts[c].realised, sizeof pts[c].realised);
    }
    cpu_image_free(&ref);
    mark_front(pts, n);
    for (int c = 0; c < n; c++)
        fprintf(csv, "\"%s\",\"%s\",%.5f,%.4f,%.4g,%.4g,%d\n", ps->title, configs[c].name, pts[c].seconds, pts[c].outcome_pct,
                pts[c].sky_p99, pts[c].hit_p99, pts[c].front);
    return n;
}

static int measure_scene(struct bench *b, int k, struct pareto_point *pts, struct quality_bound *q, FILE *csv,
                         struct error *e)
{
    struct scene *base = scene_new(e), *s = base ? scene_new(e) : NULL;
    int n = s ? measure_on(b, k, base, s, pts, q, csv, e) : -1;
    scene_free(s);
    scene_free(base);
    return n;
}

/* Every configuration of every scene of the table applied and validated, nothing rendered: a scene
 * whose defaults a configuration cannot be applied to is found before any timing, and by the quick
 * bench that make test runs (which times only a few). 0, or -1 with e. */
static int validate_configs(struct error *e)
{
    struct scene *base = scene_new(e), *s = base ? scene_new(e) : NULL;
    int rc = s ? 0 : -1;
    for (int k = 0; k < N_SCENES && rc == 0; k++) {
        if (bench_load_scene(base, scenes[k].scene, 0, 0, e) != 0) {
            rc = -1;
            break;
        }
        for (int c = 0; c < configs_of(base) && rc == 0; c++) {
            if (config_applies(base, &configs[c]))
                rc = configure(s, base, c, scenes[k].title, e);
        }
    }
    scene_free(s);
    scene_free(base);
    return rc;
}

static int cheapest(const struct pareto_point *p, int n, int sky, double level)
{
    int best = -1;
    for (int c = 0; c < n; c++) {
        double e = sky ? p[c].sky_p99 : p[c].outcome_pct;
        if (!(e <= level))
            continue;
        if (sky && p[c].outcome_pct > 1.0)   /* a direction error means little with many wrong outcomes */
            continue;
        if (best < 0 || p[c].seconds < p[best].seconds)
            best = c;
    }
    return best;
}

/* 1 when point p is within every bound the scene states in [quality]. */
static int meets_quality(const struct quality_bound *q, const struct pareto_point *p)
{
    struct compare_result r = {.outcome_fraction = p->outcome_pct / 100.0};
    r.sky_angle.p99 = p->sky_p99;
    r.hit_relative.p99 = p->hit_p99;
    char report[512];
    return quality_check(q, &r, report, sizeof report) == 0;
}

/* The scene's [quality]: the cheapest configuration within it, and whether the default is. */
static void print_quality_choice(struct bench *b, const struct quality_bound *q, const struct pareto_point *p, int n)
{
    if (!quality_stated(q)) {
        fprintf(b->md, "The scene file states no [quality].\n\n");
        return;
    }
    int best = -1;
    for (int c = 0; c < n; c++)
        if (!isnan(p[c].seconds) && meets_quality(q, &p[c]) && (best < 0 || p[c].seconds < p[best].seconds))
            best = c;
    fprintf(b->md, "The scene file's [quality] (differing pixels <= %g%%, exit p99 <= %g rad, hit p99 <= %g of "
                   "size; negative: not stated): its default %s it; ", q->differing_percent, q->exit_p99, q->hit_p99,
            meets_quality(q, &p[0]) ? "meets" : "**misses**");
    if (best < 0)
        fprintf(b->md, "no configuration meets it.\n\n");
    else
        fprintf(b->md, "the cheapest configuration that meets it is %s (%.4f s, the default %.4f s).\n\n",
                configs[best].name, p[best].seconds, p[0].seconds);
}

static void print_scene(struct bench *b, int k, const struct pareto_point *p, int n, const struct quality_bound *q)
{
    fprintf(b->md, "### %s\n\n| configuration | seconds | passes | differing pixels | exit p99 (rad) | hit p99 (of size) | "
                   "front |\n|---|---|---|---|---|---|---|\n", scenes[k].title);
    for (int c = 0; c < n; c++) {
        if (isnan(p[c].seconds)) {
            fprintf(b->md, "| %s | n/a (%s) | | | | | |\n", configs[c].name,
                    p[c].not_applicable ? p[c].not_applicable : "not measured");
            continue;
        }
        fprintf(b->md, "| %s%s | %.4f | %ld | %.3f%% | %.2g | %.2g | %s |\n", configs[c].name, p[c].realised,
                p[c].seconds, p[c].passes,
                p[c].outcome_pct, p[c].sky_p99, p[c].hit_p99, p[c].front ? "yes" : "" );
    }
    static const double sky_levels[] = {1e-2, 1e-3, 1e-4, 1e-5}, pct_levels[] = {1.0, 0.1};
    fprintf(b->md, "\nCheapest configuration reaching: ");
    for (int i = 0; i < 6; i++) {
        int sky = i < 4;
        double level = sky ? sky_levels[i] : pct_levels[i - 4];
        int c = cheapest(p, n, sky, level);
        char found[96] = "none";
        if (c >= 0)
            snprintf(found, sizeof found, "%s (%.4f s)", configs[c].name, p[c].seconds);
        fprintf(b->md, sky ? "exit p99 <= %g rad: %s; " : "differing pixels <= %g%%: %s", level, found);
        fprintf(b->md, "%s", i == 4 ? "; " : i == 5 ? ".\n\n" : "");
    }
    fprintf(b->md, "The scene's own default is %son the front. ", p[0].front ? "" : "not ");
    if (scenes[k].sky_only)
        fprintf(b->md, "This variant of the scene has no [quality] of its own.\n\n");
    else
        print_quality_choice(b, q, p, n);
}

/* The plot's data of one scene, sorted by time: index 2k, the configurations on the front (in all
 * three measures), as points; index 2k + 1, those that no other beats in time and exit error both,
 * the staircase of that two-measure front. */
static int by_seconds(const void *a, const void *b)
{
    const struct pareto_point *x = a, *y = b;
    return (x->seconds > y->seconds) - (x->seconds < y->seconds);
}

static void write_plot_data(FILE *dat, const char *title, const struct pareto_point *pts, int n)
{
    struct pareto_point sorted[N_CONFIGS];
    int m = 0;
    for (int c = 0; c < n; c++)
        if (pts[c].sky_p99 > 0.0 && !isnan(pts[c].seconds))
            sorted[m++] = pts[c];
    qsort(sorted, (size_t)m, sizeof sorted[0], by_seconds);
    fprintf(dat, "# %s: front in all three measures\n", title);
    for (int c = 0; c < m; c++)
        if (sorted[c].front)
            fprintf(dat, "%.5f %.4g\n", sorted[c].seconds, sorted[c].sky_p99);
    fprintf(dat, "\n\n# %s: front in time and exit error\n", title);
    double best = INFINITY;
    for (int c = 0; c < m; c++)
        if (sorted[c].sky_p99 < best) {
            best = sorted[c].sky_p99;
            fprintf(dat, "%.5f %.4g\n", sorted[c].seconds, sorted[c].sky_p99);
        }
    fprintf(dat, "\n\n");
}

#define SKY_TARGET_RAD 1e-5
#define SKY_TARGET_SECONDS 0.03
/* demo.scene's view (the disk around the hole, as the real-time peers show it), one ray a pixel, at
 * the bench's size: the image alone, warm */
#define DISK_TARGET_SECONDS 0.03

/* The disk's target line: demo.scene at the bench's size with one ray a pixel, timed as a display
 * draws it (bench_time). 0, or -1 with e. */
static int disk_target(struct bench *b, struct scene *s, struct error *e)
{
    if (bench_load_scene(s, "demo", b->width, b->height, e) != 0)
        return -1;
    s->render.samples = 1;
    bench_progress(b, "pareto: demo's view at %dx%d, one ray a pixel", b->width, b->height);
    struct bench_timing t;
    if (bench_time(b, s, b->runs, &t, NULL, e) != 0)
        return -1;
    fprintf(b->md, "Target: demo.scene's view (the disk around the hole) at %dx%d, one ray a pixel, the image "
                   "alone on a warm renderer (%s, %ld pass%s), in at most %.0f ms: **%s** (%.0f ms).\n\n",
            b->width, b->height, t.path, t.passes, t.passes == 1 ? "" : "es", 1e3 * DISK_TARGET_SECONDS,
            t.median <= DISK_TARGET_SECONDS ? "met" : "missed", 1e3 * t.median);
    /* what the image's curve costs: the same view with each channel clipped at white, gain 1 (the
     * black-body table then its own log curve: docs/RELATIVITY.md) */
    if (tone_active(&s->render)) {
        struct render_settings kept = s->render;
        s->render.tone_curve = TONE_CURVE_CLIP;
        s->render.gain = 1.0;
        bench_progress(b, "pareto: demo's view without the filmic curve");
        struct bench_timing clipped;
        int rc = bench_time(b, s, b->runs, &clipped, NULL, e);
        s->render = kept;
        if (rc != 0)
            return -1;
        fprintf(b->md, "The image's filmic curve and gain (`render.tone_curve`, `render.gain`: docs/SCENES.md) cost "
                       "%+.1f ms of that: %.1f ms with each channel clipped at white.\n\n",
                1e3 * (t.median - clipped.median), 1e3 * clipped.median);
    }
    /* what the accretion disk's light costs: the same view with its disks' matter at rest, one
     * temperature (docs/RELATIVITY.md, "An accretion disk") */
    int accreting = 0;
    for (int i = 0; i < s->n_objects; i++) {
        accreting += s->objects[i].material.accretion;
        s->objects[i].material.accretion = 0;
    }
    if (!accreting)
        return 0;
    bench_progress(b, "pareto: demo's view without the accretion disk's orbits and temperatures");
    struct bench_timing plain;
    if (bench_time(b, s, b->runs, &plain, NULL, e) != 0)
        return -1;
    fprintf(b->md, "The accretion disk's light (each point's orbit and temperature, docs/RELATIVITY.md) costs "
                   "%+.1f ms of that: %.1f ms with the disk's matter at rest at one temperature.\n\n",
            1e3 * (t.median - plain.median), 1e3 * plain.median);
    return 0;
}

int bench_pareto(struct bench *b, struct error *e)
{
    if (validate_configs(e) != 0)
        return -1;
    FILE *csv = bench_data_file(b, "pareto.csv", e);
    FILE *dat = bench_data_file(b, "pareto.dat", e);
    if (!csv || !dat) {
        if (csv)
            fclose(csv);
        return -1;
    }
    fprintf(csv, "scene,configuration,seconds,outcome_pct,sky_p99_rad,hit_p99_rel,front\n");
    fprintf(b->md, "## Speed against error\n\nEach scene at its own size (the Schwarzschild sky at %dx%d, without "
                   "objects), in every configuration below, early-z on and all objects in one pass, K = the "
                   "whole segment unless said; median seconds per frame of %d runs, and the error against the "
                   "CPU reference of the scene default: differing outcomes, the 99th percentile of the exit "
                   "direction error of sky pixels and of the hit error relative to the object's size. "
                   "\"step xF\" multiplies the step and keeps the segment length (a segment holds whole steps: where "
                   "the scene's steps a segment allow only another factor, the row says which it took, and where "
                   "they allow none, the row is n/a); \"segment xF\" multiplies the "
                   "segment and keeps the step and the path; \"step max x4\" bounds adaptive steps at 4 times the "
                   "scene's step; \"far step xF\" lets the step grow away from the objects up to F times the "
                   "step (render.far_step; the other rows take the step everywhere, the scene default takes the "
                   "scene's). \"orbit table, chord C\" (Schwarzschild only) integrates nothing: each ray "
                   "follows its exact orbit from the table, in chords within C of it, in one pass "
                   "(render.pipeline = single) or in the paper's multipass scheme. A configuration is on the "
                   "front when no other is as fast and as accurate in all three measures and better in one. "
                   "An adaptive configuration has a budget of steps, not of path; rays it leaves unfinished "
                   "count as differing. Plot: `bench/pareto.png`, time against exit error: the dots are the configurations on the "
                   "front in all three measures, the staircase joins those that no other beats in time and exit error "
                   "both.\n\n", b->width, b->height, b->runs);
    int sky_target_met = 0;
    double sky_target_seconds = NAN;
    for (int k = 0; k < N_SCENES; k++) {
        struct pareto_point pts[N_CONFIGS];
        struct quality_bound q;
        int n = measure_scene(b, k, pts, &q, csv, e);
        if (n < 0) {
            fclose(csv);
            fclose(dat);
            return -1;
        }
        print_scene(b, k, pts, n, &q);
        write_plot_data(dat, scenes[k].title, pts, n);
        if (k == 0) {
            int c = cheapest(pts, n, 1, SKY_TARGET_RAD);
            if (c >= 0) {
                sky_target_seconds = pts[c].seconds;
                sky_target_met = pts[c].seconds <= SKY_TARGET_SECONDS;
            }
        }
        if (b->quick)
            break;
    }
    fclose(csv);
    fclose(dat);
    fprintf(b->md, "Target: the Schwarzschild sky at %dx%d with exit-direction p99 at most %g rad in at most "
                   "%.0f ms: **%s** (%.0f ms).\n\n", b->width, b->height, SKY_TARGET_RAD, 1e3 * SKY_TARGET_SECONDS,
            sky_target_met ? "met" : "missed", 1e3 * sky_target_seconds);
    if (bench_with_scene(b, disk_target, e) != 0)
        return -1;
    FILE *gp = bench_data_file(b, "pareto.gp", e);
    if (!gp)
        return -1;
    /* noenhanced: scene names keep their underscores; ticks as 1e-05, not 0.0000100 */
    fprintf(gp, "set terminal pngcairo size 900,600 noenhanced\nset output 'pareto.png'\nset logscale xy\n"
                "set format x '%%g'\nset format y '%%.0e'\n"
                "set xlabel 'seconds per frame'\nset ylabel 'exit direction error, p99 (rad)'\n"
                "set title 'Speed against error'\nset key outside right\nplot ");
    for (int k = 0; k < (b->quick ? 1 : N_SCENES); k++)
        fprintf(gp, "%s'pareto.dat' index %d with points lc %d pt 7 title '%s', '' index %d with steps lc %d notitle",
                k ? ", " : "", 2 * k, k + 1, scenes[k].title, 2 * k + 1, k + 1);
    fprintf(gp, "\n");
    fclose(gp);
    return 0;
}
