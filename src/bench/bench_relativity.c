/* Relativity: what the observer's effects cost over the static frame, and moving objects traced per
 * pixel against the paper's polygon method, each configuration timed and compared with the CPU
 * reference (which always traces rays). */
#include <math.h>
#include "bench/bench.h"
#include "results/compare.h"
#include "ref/engine_cpu.h"

static const int subdivisions[] = {1, 4, 16, 64};
#define N_SUBDIVISIONS (int)(sizeof subdivisions / sizeof subdivisions[0])

static int time_against(struct bench *b, const struct scene *s, const struct cpu_image *ref, const char *what,
                        struct bench_timing *t, struct compare_result *cr, struct error *e)
{
    struct dump d;
    bench_progress(b, "%s", what);
    int rc = bench_time(b, s, b->runs, t, &d, e);
    if (rc == 0) {
        rc = compare_dumps(&d, &ref->dump, cr, e);
        dump_free(&d);
    }
    b->done++;
    return rc;
}

static int reference(const struct scene *s, struct cpu_image *ref, struct error *e)
{
    struct cpu_render_options o = {.threads = 0, .progress = 0};
    ref_options_default(&o.ref, s);
    return cpu_render(s, &o, ref, e);
}

/* The approaching cube: BASE as loaded, S as each row varies it. */
static int moving_objects(struct bench *b, FILE *csv, struct scene *base, struct scene *s, struct error *e)
{
    if (bench_load_scene(base, "cube_approach", b->quick ? 32 : b->width, b->quick ? 24 : b->height, e) != 0)
        return -1;
    struct cpu_image ref;
    bench_progress(b, "moving objects: CPU reference");
    if (reference(base, &ref, e) != 0)
        return -1;
    fprintf(b->md, "### Moving objects: rays against polygons\n\nThe approaching cube (cube_approach, 0.95 c) at "
                   "%dx%d: traced per pixel in its rest frame, and drawn by the polygon method with N segments per "
                   "edge of each face; median seconds per frame of %d runs and the error against the CPU "
                   "reference.\n\n| method | seconds | differing pixels | hit p99 (of size) |\n|---|---|---|---|\n",
            base->render.width, base->render.height, b->runs);
    int n = b->quick ? 2 : N_SUBDIVISIONS + 1;
    for (int k = 0; k < n; k++) {
        *s = *base;
        char what[64];
        if (k == 0) {
            snprintf(what, sizeof what, "rays");
        } else {
            s->render.moving_objects = MOVING_POLYGONS;
            s->render.polygon_subdivision = subdivisions[k - 1];
            snprintf(what, sizeof what, "polygons, N = %d", subdivisions[k - 1]);
        }
        struct bench_timing t;
        struct compare_result cr;
        if (time_against(b, s, &ref, what, &t, &cr, e) != 0) {
            cpu_image_free(&ref);
            return -1;
        }
        fprintf(b->md, "| %s | %.4f | %.3f%% | %.2g |\n", what, t.median, 100.0 * cr.outcome_fraction,
                cr.hit_relative.p99);
        fprintf(csv, "\"cube_approach\",\"%s\",%.5f,%.4f,%.4g\n", what, t.median, 100.0 * cr.outcome_fraction,
                cr.hit_relative.p99);
    }
    cpu_image_free(&ref);
    fprintf(b->md, "\n");
    return 0;
}

/* The same frame with every effect off, at rest, and with the scene's own observer: the cost of
 * aberration and colour. */
static int effects(struct bench *b, FILE *csv, struct scene *moving, struct scene *rest, struct error *e)
{
    static const char *const scenes[] = {"starflight", "blackhole_flight"};
    fprintf(b->md, "### What the observer's effects cost\n\nEach scene at %dx%d at rest with `effects = "
                   "geometry` (the static renderer), and as the scene file has it; median seconds per frame.\n\n"
                   "| scene | at rest, geometry | moving, with its effects | ratio |\n|---|---|---|---|\n",
            b->quick ? 32 : b->width, b->quick ? 24 : b->height);
    for (int k = 0; k < (b->quick ? 1 : 2); k++) {
        if (bench_load_scene(moving, scenes[k], b->quick ? 32 : b->width, b->quick ? 24 : b->height, e) != 0)
            return -1;
        *rest = *moving;
        rest->observer.velocity = v3(0.0, 0.0, 0.0);
        rest->observer.effects = EFFECTS_GEOMETRY;
        struct bench_timing t_rest, t_moving;
        bench_progress(b, "effects: %s at rest", scenes[k]);
        if (bench_time(b, rest, b->runs, &t_rest, NULL, e) != 0)
            return -1;
        b->done++;
        bench_progress(b, "effects: %s moving", scenes[k]);
        if (bench_time(b, moving, b->runs, &t_moving, NULL, e) != 0)
            return -1;
        b->done++;
        fprintf(b->md, "| %s | %.4f | %.4f | %.2f |\n", scenes[k], t_rest.median, t_moving.median,
                t_moving.median / t_rest.median);
        fprintf(csv, "\"%s\",\"effects off\",%.5f,,\n\"%s\",\"effects on\",%.5f,,\n", scenes[k], t_rest.median,
                scenes[k], t_moving.median);
    }
    fprintf(b->md, "\n");
    return 0;
}

int bench_relativity(struct bench *b, struct error *e)
{
    FILE *csv = bench_data_file(b, "relativity.csv", e);
    if (!csv)
        return -1;
    fprintf(csv, "scene,configuration,seconds,outcome_pct,hit_p99_rel\n");
    fprintf(b->md, "## Relativity\n\n");
    struct scene *s1 = scene_new(e), *s2 = s1 ? scene_new(e) : NULL;
    int rc = !s2 || moving_objects(b, csv, s1, s2, e) != 0 || effects(b, csv, s1, s2, e) != 0 ? -1 : 0;
    scene_free(s2);
    scene_free(s1);
    fclose(csv);
    return rc;
}
