/* The pipelines side by side: the paper's multipass scheme (with the scene's own acceleration
 * settings) against the fused segment pass and the single pass, and the multipass scheme on the packed
 * path (render.precision = packed: a GPU without float textures), every model at its scene's own size
 * and default quality: seconds per frame, passes per frame, milliseconds per pass, and whether they
 * agree. */
#include <string.h>
#include "bench/bench.h"
#include "results/compare.h"

struct pipeline_case {
    const char *scene;
    const char *label;
    int integrated;               /* 1: Schwarzschild integrated with rk4 instead of its exact orbits */
    int flow;                     /* one of the models without a closed form: the 3x target */
    enum orbit_walk_choice walk;  /* exact orbits: where the single pass walks (render.orbit_walk) */
};

static const struct pipeline_case cases[] = {
    {"lorenz", "lorenz", 0, 1, ORBIT_WALK_AUTO},
    {"rossler", "rossler", 0, 1, ORBIT_WALK_AUTO},
    {"potential", "potential", 0, 1, ORBIT_WALK_AUTO},
    {"refraction", "refraction", 0, 1, ORBIT_WALK_AUTO},
    {"schwarzschild", "schwarzschild, rk4", 1, 0, ORBIT_WALK_AUTO},
    {"schwarzschild", "schwarzschild, exact orbits", 0, 0, ORBIT_WALK_INLINE},
    {"schwarzschild", "schwarzschild, exact orbits, walk separate", 0, 0, ORBIT_WALK_SEPARATE},
    {"neutron_star", "neutron_star, exact orbits", 0, 0, ORBIT_WALK_INLINE},
    {"neutron_star", "neutron_star, exact orbits, walk separate", 0, 0, ORBIT_WALK_SEPARATE},
    {"demo", "demo, exact orbits", 0, 0, ORBIT_WALK_AUTO},
    {"test", "test (flat)", 0, 0, ORBIT_WALK_AUTO},
};
#define N_CASES (int)(sizeof cases / sizeof cases[0])
#define FLOW_TARGET_SPEEDUP 3.0

/* The pipelines of a row, in the table's order, and their ray state's precision. */
#define ROW_PIPELINES 4
static const enum pipeline_choice row_pipelines[ROW_PIPELINES] = {PIPELINE_MULTIPASS, PIPELINE_FUSED, PIPELINE_SINGLE,
                                                                  PIPELINE_MULTIPASS};
static const enum precision_choice row_precision[ROW_PIPELINES] = {PRECISION_AUTO, PRECISION_AUTO, PRECISION_AUTO,
                                                                   PRECISION_PACKED};
static const char *const row_names[ROW_PIPELINES] = {"multipass", "fused", "single", "packed"};
const int bench_pipelines_count = N_CASES * ROW_PIPELINES;

/* The pipelines section, each case's scene loaded into S. */
static int pipelines_on(struct bench *b, struct scene *s, struct error *e)
{
    FILE *csv = bench_data_file(b, "pipelines.csv", e);
    if (!csv)
        return -1;
    fprintf(csv, "scene,pipeline,width,height,median_s,passes,ms_per_pass,outcome_pct\n");
    fprintf(b->md, "## Pipelines: the paper's scheme, the fused segment pass and the single pass\n\nEach scene at "
                   "its own size and settings, drawn by the paper's multipass scheme (`render.pipeline = multipass`, "
                   "with the scene's early-z, unrolling and batches), by one fused pass a segment (`fused`: "
                   "integration, intersection and termination in one pass with four draw buffers; not for exact "
                   "orbits, which run their own stage: –) and by the single pass (`single`: the whole ray in one "
                   "fragment-shader loop, docs/PIPELINE.md; on exact orbits with the walk in the frame's pass, "
                   "`render.orbit_walk = inline`, or in a pass of its own, `separate`, a GPU's default); then the multipass scheme "
                   "on the packed path (`render.precision = packed`: the ray state's 32-bit floats packed into RGBA8 "
                   "texels, four fragments a ray, one target a pass, as a GPU without float textures draws; "
                   "docs/HARDWARE.md). Seconds per frame, median of %d runs; passes per "
                   "frame and the mean milliseconds per pass; the share of pixels whose outcome differs from the "
                   "multipass scheme's (0: the same rays; tests/unit/test_acceleration.c proves them "
                   "bit-identical, tests/render/limits.sh the packed path's).\n\n"
                   "| scene | size | multipass (s) | passes | ms per pass | fused (s) | passes | ms per pass | "
                   "single (s) | passes | ms per pass | packed (s) | passes | ms per pass | speed-up fused / single | "
                   "differing pixels fused / single / packed |\n"
                   "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n", b->runs);
    int met = 1;
    double worst = 1e30;
    for (int k = 0; k < N_CASES; k++) {
        struct bench_timing t[ROW_PIPELINES];
        struct dump d[ROW_PIPELINES];
        int ran[ROW_PIPELINES] = {0};
        double differ[ROW_PIPELINES] = {0.0};
        int rc = 0;
        for (int p = 0; p < ROW_PIPELINES && rc == 0; p++) {
            if (bench_load_scene(s, cases[k].scene, b->quick ? 32 : 0, b->quick ? 24 : 0, e) != 0) {
                rc = -1;
                break;
            }
            if (cases[k].integrated)
                s->render.method = METHOD_RK4;
            if (cases[k].walk != ORBIT_WALK_AUTO)
                s->render.orbit_walk = cases[k].walk;
            /* exact orbits have no fused pass */
            if (row_pipelines[p] == PIPELINE_FUSED && s->render.method == METHOD_ORBIT_TABLE) {
                b->done++;
                continue;
            }
            s->render.pipeline = row_pipelines[p];
            s->render.precision = row_precision[p];
            if (row_precision[p] == PRECISION_PACKED)
                s->render.mrt = MRT_AUTO;
            bench_progress(b, "pipelines: %s, %s", cases[k].label, row_names[p]);
            rc = bench_time(b, s, b->runs, &t[p], &d[p], e);
            ran[p] = rc == 0;
            b->done++;
        }
        for (int p = 1; p < ROW_PIPELINES && rc == 0; p++) {
            struct compare_result c;
            if (ran[p] && (rc = compare_dumps(&d[p], &d[0], &c, e)) == 0)
                differ[p] = 100.0 * c.outcome_fraction;
        }
        for (int p = 0; p < ROW_PIPELINES; p++)
            if (ran[p])
                dump_free(&d[p]);
        if (rc != 0)
            return -1;
        char cell[ROW_PIPELINES][64], speedup[64], differing[64];
        for (int p = 0; p < ROW_PIPELINES; p++) {
            if (!ran[p]) {
                snprintf(cell[p], sizeof cell[p], "– | – | –");
                continue;
            }
            double ms = 1e3 * t[p].median / (double)(t[p].passes > 0 ? t[p].passes : 1);
            snprintf(cell[p], sizeof cell[p], "%.3f | %ld | %.2f", t[p].median, t[p].passes, ms);
            fprintf(csv, "%s,%s,%d,%d,%.4f,%ld,%.3f,%.4f\n", cases[k].label, row_names[p], s->render.width,
                    s->render.height, t[p].median, t[p].passes, ms, differ[p]);
        }
        double single_speedup = t[0].median / t[2].median;
        if (ran[1]) {
            snprintf(speedup, sizeof speedup, "%.2f / %.2f", t[0].median / t[1].median, single_speedup);
            snprintf(differing, sizeof differing, "%.2f%% / %.2f%% / %.2f%%", differ[1], differ[2], differ[3]);
        } else {
            snprintf(speedup, sizeof speedup, "– / %.2f", single_speedup);
            snprintf(differing, sizeof differing, "– / %.2f%% / %.2f%%", differ[2], differ[3]);
        }
        if (cases[k].flow) {
            met &= single_speedup >= FLOW_TARGET_SPEEDUP;
            worst = single_speedup < worst ? single_speedup : worst;
        }
        fprintf(b->md, "| %s | %dx%d | %s | %s | %s | %s | %s | %s |\n", cases[k].label, s->render.width,
                s->render.height, cell[0], cell[1], cell[2], cell[3], speedup, differing);
    }
    fclose(csv);
    fprintf(b->md, "\nTarget: the single pass at least %.0fx faster than the multipass scheme for lorenz, rossler, "
                   "potential and refraction: **%s** (smallest speed-up %.2f).\n\n", FLOW_TARGET_SPEEDUP,
            met ? "met" : "missed", worst);
    return 0;
}

int bench_pipelines(struct bench *b, struct error *e)
{
    return bench_with_scene(b, pipelines_on, e);
}
