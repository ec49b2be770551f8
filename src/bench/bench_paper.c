/* The paper's own measurements, repeated: Table 1 (four models, 10 spheres, 30 segments, 300 steps)
 * and Figure 5 (Schwarzschild, 50 segments, 500 steps, 1 to 20 spheres), without and with the
 * acceleration techniques. */
#include <math.h>
#include <string.h>
#include "bench/bench.h"
#include "results/compare.h"
#include "ref/engine_cpu.h"

#define T1_MODELS 4
static const char *const t1_scene[T1_MODELS] = {"lorenz", "potential", "refraction", "schwarzschild"};
static const char *const t1_title[T1_MODELS] = {"Lorenz system", "Potential field", "Varying index of refraction",
                                                "Schwarzschild"};
/* Weiskopf, Schafhitzel, Ertl 2004, Table 1: seconds per frame on a Radeon 9700 */
static const double t1_paper[T1_MODELS][2] = {{3.87, 3.13}, {4.22, 1.16}, {3.35, 2.42}, {4.91, 3.79}};
#define T1_TARGET_SECONDS 0.4
/* The path of Table 1's rays in each model: the budget each scene had when the table was first
 * measured (segments x steps x step), kept so that its workload stays the same from run to run. */
static const double t1_path[T1_MODELS] = {30.0, 40.0, 40.0, 40.0};

static int table1_scene(struct bench *b, struct scene *s, int k, int w, int h, struct error *e)
{
    if (bench_load_scene(s, t1_scene[k], w, h, e) != 0)
        return -1;
    bench_spheres(s, b->quick ? 2 : 10);
    bench_paper_steps(s, 30, 300, t1_path[k]);
    return 0;
}

/* Outcome differences and exit-direction p99 of the configuration (made in S) against the reference,
 * at a quarter of the size (the reference at 800x600 would take minutes per model). */
static int table1_errors(struct bench *b, const struct scene *base, struct scene *s, const struct dump *ref,
                         enum bench_accel a, struct compare_result *c, struct error *e)
{
    *s = *base;
    bench_apply_accel(s, a);
    struct bench_timing t;
    struct dump d;
    /* the error does not depend on the run: one frame */
    int rc = bench_time(b, s, 1, &t, &d, e);
    if (rc != 0)
        return -1;
    rc = compare_dumps(&d, ref, c, e);
    dump_free(&d);
    return rc;
}

/* The Table 1 section: each model's scene loaded into S, at a quarter of its size into SMALL, and
 * each configuration made in RUN. */
static int table1_on(struct bench *b, struct scene *s, struct scene *small, struct scene *run, struct error *e)
{
    FILE *csv = bench_data_file(b, "table1.csv", e);
    if (!csv)
        return -1;
    fprintf(csv, "model,acceleration,median_s,min_s,max_s,passes,outcome_pct,sky_p99_rad\n");
    fprintf(b->md, "## The paper's Table 1\n\n%dx%d, %d spheres, 30 segments, 300 integration steps (Euler, the "
                   "paper's integrator), over a path of %g (Lorenz) and %g (the others): each scene's budget when "
                   "this table was first measured, kept so that the work stays the same. Columns: **none** is the paper's "
                   "original scheme (one step per pass, one object per pass, every ray in every pass); **paper** "
                   "adds the paper's acceleration techniques, early ray termination through the early-z test and "
                   "step doubling (tolerance 1%% of the fixed step); **all** adds a whole segment per pass and "
                   "all objects in one pass; **single** runs the same settings as one pass per frame "
                   "(`render.pipeline = single`, docs/PIPELINE.md), **fused** as one pass per segment "
                   "(`render.pipeline = fused`). Seconds per frame, median of %d runs. The error columns compare "
                   "each configuration with the CPU reference at %dx%d: the share of pixels whose outcome "
                   "differs, and the 99th percentile of the exit-direction error of sky pixels.\n\n",
            b->width, b->height, b->quick ? 2 : 10, t1_path[0], t1_path[1], b->runs, b->width / 4, b->height / 4);
    fprintf(b->md, "| model | none (s) | paper (s) | speed-up | all (s) | speed-up | fused (s) | speed-up | single (s) | "
                   "speed-up | passes all / fused / single | Radeon 9700 none / with (s) | paper's speed-up | differing "
                   "pixels none / paper / all / fused / single | exit p99 none / paper / all / fused / single (rad) |\n"
                   "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    int met_time = 1, met_speedup = 1;
    for (int k = 0; k < T1_MODELS; k++) {
        if (table1_scene(b, s, k, b->width, b->height, e) != 0 ||
            table1_scene(b, small, k, b->width / 4, b->height / 4, e) != 0)
            return -1;
        struct cpu_image ref;
        struct cpu_render_options o = {.threads = 0, .progress = 0};
        ref_options_default(&o.ref, small);
        bench_progress(b, "table 1: %s, CPU reference at %dx%d", t1_scene[k], small->render.width,
                       small->render.height);
        if (cpu_render(small, &o, &ref, e) != 0)
            return -1;
        struct bench_timing t[ACCEL_COUNT];
        struct compare_result c[ACCEL_COUNT];
        for (int a = 0; a < ACCEL_COUNT; a++) {
            *run = *s;
            bench_apply_accel(run, (enum bench_accel)a);
            bench_progress(b, "table 1: %s, acceleration %s", t1_scene[k], bench_accel_names[a]);
            if (bench_time(b, run, b->runs, &t[a], NULL, e) != 0 ||
                table1_errors(b, small, run, &ref.dump, (enum bench_accel)a, &c[a], e) != 0) {
                cpu_image_free(&ref);
                return -1;
            }
            b->done++;
            fprintf(csv, "%s,%s,%.4f,%.4f,%.4f,%ld,%.4f,%.3g\n", t1_scene[k], bench_accel_names[a], t[a].median,
                    t[a].min, t[a].max, t[a].passes, 100.0 * c[a].outcome_fraction, c[a].sky_angle.p99);
        }
        cpu_image_free(&ref);
        double paper_speedup = t1_paper[k][0] / t1_paper[k][1];
        double speedup = t[ACCEL_NONE].median / t[ACCEL_ALL].median;
        double fastest = t[ACCEL_ALL].median;
        for (int a = ACCEL_SINGLE; a <= ACCEL_FUSED; a++)
            fastest = t[a].median < fastest ? t[a].median : fastest;
        met_time &= fastest <= T1_TARGET_SECONDS;
        met_speedup &= speedup >= paper_speedup;
        const int all = ACCEL_ALL, fused = ACCEL_FUSED, single = ACCEL_SINGLE;
        fprintf(b->md, "| %s | %.3f | %.3f | %.2f | %.3f | %.2f | %.3f | %.2f | %.3f | %.2f | %ld / %ld / %ld | %.2f / %.2f | "
                       "%.2f | %.2f%% / %.2f%% / %.2f%% / %.2f%% / %.2f%% | %.2g / %.2g / %.2g / %.2g / %.2g |\n",
                t1_title[k], t[0].median, t[1].median, t[0].median / t[1].median, t[all].median, speedup,
                t[fused].median, t[0].median / t[fused].median, t[single].median, t[0].median / t[single].median,
                t[all].passes, t[fused].passes, t[single].passes, t1_paper[k][0], t1_paper[k][1], paper_speedup,
                100.0 * c[0].outcome_fraction, 100.0 * c[1].outcome_fraction, 100.0 * c[all].outcome_fraction,
                100.0 * c[fused].outcome_fraction, 100.0 * c[single].outcome_fraction, c[0].sky_angle.p99,
                c[1].sky_angle.p99, c[all].sky_angle.p99, c[fused].sky_angle.p99, c[single].sky_angle.p99);
    }
    fclose(csv);
    fprintf(b->md, "\nTarget: on the fastest path (all, fused or single) at most %.1f s per frame for every model: **%s**. "
                   "Speed-up (none to all) at least the paper's for every model: **%s**.\n\n",
            T1_TARGET_SECONDS, met_time ? "met" : "missed", met_speedup ? "met" : "missed");
    return 0;
}

int bench_table1(struct bench *b, struct error *e)
{
    struct scene *s = scene_new(e), *small = s ? scene_new(e) : NULL, *run = small ? scene_new(e) : NULL;
    int rc = run ? table1_on(b, s, small, run, e) : -1;
    scene_free(run);
    scene_free(small);
    scene_free(s);
    return rc;
}

/* The Figure 5 section, each frame's scene loaded into S. */
static int figure5_on(struct bench *b, struct scene *s, struct error *e)
{
    static const int counts_full[] = {1, 5, 10, 20}, counts_quick[] = {1, 2};
    const int *counts = b->quick ? counts_quick : counts_full;
    int n = b->quick ? 2 : 4;
    FILE *csv = bench_data_file(b, "figure5.csv", e);
    if (!csv)
        return -1;
    fprintf(csv, "spheres,none_s,paper_s,all_s,single_s,fused_s\n");
    fprintf(b->md, "## The paper's Figure 5\n\nSchwarzschild, %dx%d, 50 segments, 500 steps (Euler), 1 to 20 "
                   "spheres; seconds per frame (median of %d runs) without acceleration, with the paper's, "
                   "with all, with all in the single pass, and with all in one fused pass a segment. Plot: "
                   "`bench/figure5.png`.\n\n| spheres | none (s) | paper (s) | all (s) | single (s) | fused (s) |\n"
                   "|---|---|---|---|---|---|\n", b->width, b->height, b->runs);
    for (int i = 0; i < n; i++) {
        double sec[ACCEL_COUNT];
        for (int a = 0; a < ACCEL_COUNT; a++) {
            if (bench_load_scene(s, "schwarzschild", b->width, b->height, e) != 0)
                return -1;
            bench_spheres(s, counts[i]);
            bench_paper_steps(s, 50, 500, render_path_budget(&s->render));
            bench_apply_accel(s, (enum bench_accel)a);
            struct bench_timing t;
            bench_progress(b, "figure 5: %d spheres, acceleration %s", counts[i], bench_accel_names[a]);
            if (bench_time(b, s, b->runs, &t, NULL, e) != 0)
                return -1;
            b->done++;
            sec[a] = t.median;
        }
        fprintf(csv, "%d,%.4f,%.4f,%.4f,%.4f,%.4f\n", counts[i], sec[0], sec[1], sec[2], sec[3], sec[4]);
        fprintf(b->md, "| %d | %.3f | %.3f | %.3f | %.3f | %.3f |\n", counts[i], sec[0], sec[1], sec[2], sec[3], sec[4]);
    }
    fclose(csv);
    fprintf(b->md, "\n");
    FILE *gp = bench_data_file(b, "figure5.gp", e);
    if (!gp)
        return -1;
    fprintf(gp, "set terminal pngcairo size 800,500\nset output 'figure5.png'\nset datafile separator ','\n"
                "set key autotitle columnhead left top\nset xlabel 'spheres'\nset ylabel 'seconds per frame'\n"
                "set title 'Schwarzschild, %dx%d, 50 segments, 500 steps (the paper, Figure 5)'\n"
                "plot 'figure5.csv' using 1:2 with linespoints title 'no acceleration', "
                "'' using 1:3 with linespoints title 'early-z + step doubling', "
                "'' using 1:4 with linespoints title 'all techniques', "
                "'' using 1:5 with linespoints title 'all, single pass', "
                "'' using 1:6 with linespoints title 'all, one fused pass a segment'\n", b->width, b->height);
    fclose(gp);
    return 0;
}

int bench_figure5(struct bench *b, struct error *e)
{
    return bench_with_scene(b, figure5_on, e);
}
