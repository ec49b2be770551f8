/* The pipelines side by side: the paper's multipass scheme (with the scene's own acceleration
 * settings) against the single pass, every model at its scene's own size and default quality:
 * seconds per frame, passes per frame, milliseconds per pass, and whether the two agree. */
#include <string.h>
#include "bench/bench.h"
#include "ref/compare.h"

struct pipeline_case {
    const char *scene;
    const char *label;
    int integrated;               /* 1: Schwarzschild integrated with rk4 instead of its exact orbits */
    int flow;                     /* one of the models without a closed form: the 3x target */
};

static const struct pipeline_case cases[] = {
    {"lorenz", "lorenz", 0, 1},
    {"rossler", "rossler", 0, 1},
    {"potential", "potential", 0, 1},
    {"refraction", "refraction", 0, 1},
    {"schwarzschild", "schwarzschild, rk4", 1, 0},
    {"schwarzschild", "schwarzschild, exact orbits", 0, 0},
    {"demo", "demo, exact orbits", 0, 0},
    {"test", "test (flat)", 0, 0},
};
#define N_CASES (int)(sizeof cases / sizeof cases[0])
#define FLOW_TARGET_SPEEDUP 3.0

int bench_pipelines(struct bench *b, char *err, size_t errlen)
{
    FILE *csv = bench_data_file(b, "pipelines.csv", err, errlen);
    if (!csv)
        return -1;
    fprintf(csv, "scene,pipeline,width,height,median_s,passes,ms_per_pass,outcome_pct\n");
    fprintf(b->md, "## Pipelines: the paper's scheme and the single pass\n\nEach scene at its own size and "
                   "settings, drawn by the paper's multipass scheme (`render.pipeline = multipass`, with the "
                   "scene's early-z, unrolling and batches) and by the single pass (`render.pipeline = single`: "
                   "the whole ray in one fragment-shader loop, docs/PIPELINE.md). Seconds per frame, median of "
                   "%d runs; passes per frame and the mean milliseconds per pass; the share of pixels whose "
                   "outcome differs between the two (0: the same rays; tests/unit/test_acceleration.c proves "
                   "them bit-identical).\n\n"
                   "| scene | size | multipass (s) | passes | ms per pass | single (s) | passes | ms per pass | "
                   "speed-up | differing pixels |\n|---|---|---|---|---|---|---|---|---|---|\n", b->runs);
    int met = 1;
    double worst = 1e30;
    for (int k = 0; k < N_CASES; k++) {
        struct bench_timing t[2];
        struct dump d[2];
        static struct scene s;
        for (int p = 0; p < 2; p++) {
            if (bench_load_scene(&s, cases[k].scene, b->quick ? 32 : 0, b->quick ? 24 : 0, err, errlen) != 0)
                return -1;
            if (cases[k].integrated)
                s.render.method = METHOD_RK4;
            s.render.pipeline = p ? PIPELINE_SINGLE : PIPELINE_MULTIPASS;
            bench_progress(b, "pipelines: %s, %s", cases[k].label, p ? "single pass" : "multipass");
            if (bench_time(b, &s, b->runs, &t[p], &d[p], err, errlen) != 0) {
                if (p)
                    dump_free(&d[0]);
                return -1;
            }
            b->done++;
        }
        struct compare_result c;
        int rc = compare_dumps(&d[1], &d[0], &c, err, errlen);
        dump_free(&d[0]);
        dump_free(&d[1]);
        if (rc != 0)
            return -1;
        double ms[2];
        for (int p = 0; p < 2; p++) {
            ms[p] = 1e3 * t[p].median / (double)(t[p].passes > 0 ? t[p].passes : 1);
            fprintf(csv, "%s,%s,%d,%d,%.4f,%ld,%.3f,%.4f\n", cases[k].label, p ? "single" : "multipass",
                    s.render.width, s.render.height, t[p].median, t[p].passes, ms[p], 100.0 * c.outcome_fraction);
        }
        double speedup = t[0].median / t[1].median;
        if (cases[k].flow) {
            met &= speedup >= FLOW_TARGET_SPEEDUP;
            worst = speedup < worst ? speedup : worst;
        }
        fprintf(b->md, "| %s | %dx%d | %.3f | %ld | %.2f | %.3f | %ld | %.1f | %.2f | %.2f%% |\n", cases[k].label,
                s.render.width, s.render.height, t[0].median, t[0].passes, ms[0], t[1].median, t[1].passes, ms[1],
                speedup, 100.0 * c.outcome_fraction);
    }
    fclose(csv);
    fprintf(b->md, "\nTarget: the single pass at least %.0fx faster than the multipass scheme for lorenz, rossler, "
                   "potential and refraction: **%s** (smallest speed-up %.2f).\n\n", FLOW_TARGET_SPEEDUP,
            met ? "met" : "missed", worst);
    return 0;
}
