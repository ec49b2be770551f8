/* accuracy_report: every scene in a directory on the GPU path in several configurations and on
 * the CPU reference, compared pixel by pixel; writes a Markdown report (docs/ACCURACY.md via
 * `make accuracy`). Every number in the report is computed here. */
#include "cli/measure.h"
#include "results/compare.h"
#include "results/quality.h"
#include "render/frame.h"
#include <glob.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/utsname.h>
#include <time.h>

/* The default configuration of a scene, and variations that show what each knob costs and buys. */
enum variation { VAR_DEFAULT, VAR_FP16, VAR_OTHER_METHOD, VAR_SHORT_SEGMENTS, VAR_TIGHT_CHORDS, VAR_CPU_LOOSE, VAR_COUNT };

static const char *const variation_names[VAR_COUNT] = {
    "scene default", "fp16 ray state", "other method", "segments 1/5 as long", "chords within 1/10 the tolerance",
    "CPU rtol 1e-6"};

/* Apply a variation to s; 0 when it does not apply to this scene. */
static int vary(struct scene *s, enum variation v)
{
    struct render_settings *r = &s->render;
    int flat = !model_ops_of(s->model.type)->integrates, orbit = r->method == METHOD_ORBIT_TABLE;
    switch (v) {
    case VAR_FP16:
        /* the orbit table needs 32-bit floats */
        r->precision = PRECISION_FP16;
        return !orbit;
    case VAR_OTHER_METHOD:
        /* exact orbits against the integration they replace (rk4 at the scene's step) */
        r->method = r->method == METHOD_RK4 ? METHOD_EULER : METHOD_RK4;
        /* the embedded error estimate belongs to dopri5: the other method takes fixed steps (step
         * doubling cannot meet a tolerance below the fp32 rounding of positions) */
        if (r->step_control == STEP_EMBEDDED)
            r->step_control = STEP_FIXED;
        return !flat;
    case VAR_SHORT_SEGMENTS:
        /* same steps, five times as many segments: only the chord of each segment changes */
        if (flat || orbit || r->steps_per_segment % 5 != 0)
            return 0;
        r->steps_per_segment /= 5;
        if (r->segments > 0)      /* segments derived from the path follow the shorter ones */
            r->segments *= 5;
        while (r->steps_per_segment % r->steps_per_pass != 0)
            r->steps_per_pass--;
        return 1;
    case VAR_TIGHT_CHORDS:
        /* exact orbits: only the chords of each segment, and so the hits, change */
        r->chord_tolerance /= 10.0;
        return orbit && !flat;
    case VAR_DEFAULT:
    case VAR_CPU_LOOSE:
    default:
        return 1;
    }
}

static void fmt_stat(char *out, size_t n, double value)
{
    if (value != value)
        snprintf(out, n, "–");
    else
        snprintf(out, n, "%.3g", value);
}

static void write_header(FILE *f)
{
    fprintf(f, "| scene | configuration | engine | method | step | steps/segment | segments | K | time (s) | "
               "outcome differs | hit error / size: mean | p99 | max | sky angle (rad): mean | p99 | PSNR (dB) |\n"
               "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
}

static void write_row(FILE *f, const struct scene *s, const char *variation, const struct measured *m,
                      const struct compare_result *c)
{
    const struct render_settings *r = &s->render;
    char hm[32], hp[32], hx[32], sm[32], sp[32], psnr[32], k[16];
    fmt_stat(hm, sizeof hm, c->hit_relative.mean);
    fmt_stat(hp, sizeof hp, c->hit_relative.p99);
    fmt_stat(hx, sizeof hx, c->hit_relative.max);
    fmt_stat(sm, sizeof sm, c->sky_angle.mean);
    fmt_stat(sp, sizeof sp, c->sky_angle.p99);
    if (c->image_identical)
        snprintf(psnr, sizeof psnr, "identical");
    else
        snprintf(psnr, sizeof psnr, "%.1f", c->psnr_db);
    int cpu = strncmp(m->engine, "cpu", 3) == 0, flat = !model_ops_of(s->model.type)->integrates;
    snprintf(k, sizeof k, cpu || flat ? "–" : "%d", r->steps_per_pass);
    char step[32], per_segment[16], segments[32];
    int orbit = !cpu && !flat && r->method == METHOD_ORBIT_TABLE;
    if (orbit)
        snprintf(k, sizeof k, "–");
    snprintf(step, sizeof step, cpu || flat ? "–" : orbit ? "chord %g" : "%g", orbit ? r->chord_tolerance : r->step_size);
    snprintf(per_segment, sizeof per_segment, cpu || flat || orbit ? "–" : "%d", r->steps_per_segment);
    snprintf(segments, sizeof segments, cpu || flat ? "–" : orbit ? "<= %d chords" : "%d", orbit ? r->max_chords : render_segments(r));
    static const char *const control[] = {"", " doubling", " embedded"};
    char method[48];
    snprintf(method, sizeof method, "%s%s", cpu ? "dopri5" : flat ? "straight" : method_name(r->method),
             cpu || flat ? "" : control[r->step_control]);
    fprintf(f, "| %s | %s | %s | %s | %s | %s | %s | %s | %.3f | %.3f%% | %s | %s | %s | %s | %s | %s |\n", s->name,
            variation, m->engine, method, step, per_segment,
            segments, k, m->seconds, 100.0 * c->outcome_fraction, hm, hp, hx, sm, sp, psnr);
}

/* The [quality] each scene states, held against its default row: a table written after the main one. */
static char quality_rows[16384];

static void note_quality(const struct scene *s, const struct compare_result *c, int size_given)
{
    char report[512] = "", cell[600];
    size_t used = strlen(quality_rows);
    int missed = quality_check(&s->quality, c, report, sizeof report);
    if (missed < 0)
        snprintf(cell, sizeof cell, "states none | – |");
    else if (size_given)
        snprintf(cell, sizeof cell, "stated for its own size, not checked at this one | – |");
    else {
        for (char *p = report; *p; p++)
            if (*p == '\n')
                *p = p[1] ? ';' : ' ';
        snprintf(cell, sizeof cell, "%s| %s |", report, missed ? "**MISSED**" : "met");
    }
    snprintf(quality_rows + used, sizeof quality_rows - used, "| %s | %s\n", s->name, cell);
}

/* One configuration of a scene against the reference; 0 or -1 (message printed). */
static int report_variation(FILE *f, struct scene *s, enum variation v, const struct cpu_render_options *ref_opt,
                            const struct measured *ref, char *device, size_t device_len, int size_given)
{
    struct error e;
    struct measured m;
    int rc;
    if (v == VAR_CPU_LOOSE) {
        struct cpu_render_options loose = *ref_opt;
        loose.ref.rtol = 1e-6;
        loose.ref.atol = 1e-6 * s->render.bound_radius;
        rc = measure_cpu(s, &loose, &m, &e);
    } else {
        rc = measure_gpu(s, "auto", 1, PROGRESS_NONE, 0, &m, &e);
    }
    if (rc != 0) {
        fprintf(stderr, "%s (%s): %s\n", s->path, variation_names[v], e.message);
        return -1;
    }
    if (v == VAR_DEFAULT)
        snprintf(device, device_len, "%s", m.device);
    struct compare_result c;
    rc = compare_dumps(&m.dump, &ref->dump, &c, &e);
    if (rc != 0)
        fprintf(stderr, "%s: %s\n", s->path, e.message);
    else
        write_row(f, s, variation_names[v], &m, &c);
    if (rc == 0 && v == VAR_DEFAULT)
        note_quality(s, &c, size_given);
    measured_free(&m);
    return rc;
}

/* The reference of the scene at PATH (loaded into BASE) and every variation of it (in S) against it. */
static int report_scene_on(struct scene *base, struct scene *s, FILE *f, const char *path, int width, int height,
                           char *gpu_device, char *cpu_device, size_t device_len)
{
    struct error serr;
    if (scene_load(base, path, &serr) != 0) {
        error_print(&serr, NULL, stderr);
        return -1;
    }
    if (width) {
        base->render.width = width;
        base->render.height = height;
    }
    struct cpu_render_options ref_opt = {.progress = 0};
    ref_options_default(&ref_opt.ref, base);
    fprintf(stderr, "accuracy: %s: reference\n", base->name);
    struct measured ref;
    struct error e;
    if (measure_cpu(base, &ref_opt, &ref, &e) != 0) {
        fprintf(stderr, "%s: CPU reference: %s\n", path, e.message);
        return -1;
    }
    snprintf(cpu_device, device_len, "%s", ref.device);
    fprintf(f, "| %s | reference (%dx%d) | %s | dopri5 | – | – | – | – | %.3f | – | – | – | – | – | – | – |\n",
            base->name, base->render.width, base->render.height, ref.engine, ref.seconds);
    int rc = 0;
    for (int v = 0; v < VAR_COUNT && rc == 0; v++) {
        *s = *base;
        if (!vary(s, v))
            continue;
        fprintf(stderr, "accuracy: %s: %s\n", base->name, variation_names[v]);
        struct error verr;
        if (scene_validate(s, &verr) != 0) {
            fprintf(stderr, "%s (%s): %s\n", path, variation_names[v], verr.message);
            rc = -1;
            break;
        }
        rc = report_variation(f, s, v, &ref_opt, &ref, gpu_device, device_len, width != 0);
    }
    measured_free(&ref);
    return rc;
}

static int report_scene(FILE *f, const char *path, int width, int height, char *gpu_device, char *cpu_device,
                        size_t device_len)
{
    struct error e;
    struct scene *base = scene_new(&e), *s = base ? scene_new(&e) : NULL;
    int rc = -1;
    if (s)
        rc = report_scene_on(base, s, f, path, width, height, gpu_device, cpu_device, device_len);
    else
        fprintf(stderr, "%s: %s\n", path, e.message);
    scene_free(s);
    scene_free(base);
    return rc;
}

static void write_preamble(FILE *f, const char *dir, int width, int height)
{
    fprintf(f, "# Accuracy: every scene against the CPU reference\n\n"
               "Written by `make accuracy` (src/tools/accuracy_report.c); every number below comes from that\n"
               "run. Each scene in %s/ is rendered by the CPU reference (Dormand-Prince 5(4), rtol 1e-10,\n"
               "crossings located on the dense output) and by the configurations below; each row compares\n"
               "one configuration with the reference pixel by pixel (metrics defined in docs/ERRORS.md).\n"
               "Image size: %s. Hit errors are relative to the size of the object hit; sky angles are\n"
               "between the final ray directions. GPU time is the passes with glFinish; CPU time is wall\n"
               "time on all threads (a single GPU run: it includes building the orbit table). Times on a\n"
               "shared machine are noisy: compare rows of one run. A scene on exact orbits (method\n"
               "orbit_table) integrates nothing: its step column gives its chord tolerance, its segments\n"
               "column its chord limit, and its \"other method\" row the RK4 integration it replaces.\n\n",
            dir, width ? "as given on the command line" : "each scene's own render.width x height");
    (void)height;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: accuracy_report SCENE_DIR OUT.md [WxH]\n");
        return 2;
    }
    int width = 0, height = 0;
    if (argc > 3 && (sscanf(argv[3], "%dx%d", &width, &height) != 2 || width < 1 || height < 1)) {
        fprintf(stderr, "accuracy_report: size: expected WxH, got '%s'\n", argv[3]);
        return 2;
    }
    char pattern[1024];
    snprintf(pattern, sizeof pattern, "%s/*.scene", argv[1]);
    glob_t g;
    if (glob(pattern, 0, NULL, &g) != 0 || g.gl_pathc == 0) {
        fprintf(stderr, "accuracy_report: no scenes match %s\n", pattern);
        return 2;
    }
    char tmp[1100];
    snprintf(tmp, sizeof tmp, "%s.tmp", argv[2]);
    FILE *f = fopen(tmp, "w");
    if (!f) {
        fprintf(stderr, "accuracy_report: cannot write %s\n", tmp);
        globfree(&g);
        return 1;
    }
    write_preamble(f, argv[1], width, height);
    write_header(f);
    char gpu_device[160] = "", cpu_device[160] = "";
    int rc = 0;
    for (size_t i = 0; i < g.gl_pathc && rc == 0; i++)
        rc = report_scene(f, g.gl_pathv[i], width, height, gpu_device, cpu_device, sizeof gpu_device);
    fprintf(f, "\nEach scene's [quality] (what its file says its own settings reach, docs/SCENES.md) held "
               "against its scene default row:\n\n| scene | measured against stated | result |\n|---|---|---|\n%s",
            quality_rows);
    struct utsname u;
    uname(&u);
    time_t now = time(NULL);
    char date[32];
    strftime(date, sizeof date, "%Y-%m-%d", gmtime(&now));
    fprintf(f, "\nMachine: %s %s, GPU engine: %s, CPU reference: %s. Run on %s.\n", u.sysname, u.machine,
            gpu_device, cpu_device, date);
    globfree(&g);
    if (fclose(f) != 0 || rc != 0) {
        remove(tmp);
        fprintf(stderr, "accuracy_report: failed; %s left unchanged\n", argv[2]);
        return 1;
    }
    if (rename(tmp, argv[2]) != 0) {
        fprintf(stderr, "accuracy_report: cannot replace %s\n", argv[2]);
        return 1;
    }
    printf("%s\n", argv[2]);
    return 0;
}
