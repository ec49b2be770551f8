/* The kiosk's responsiveness: how many previews a second each knob gets, what the orbit tables
 * cost the render thread per detent, the first frame after a scene change, and how long the refined
 * frame takes once the knobs rest, for each scene of a kiosk configuration (--config; the shipped
 * kiosk/kiosk.conf by default), measured through the kiosk's own view, events and compositor on the
 * bench's context. Targets: at least 30 previews a second at the preview size (a turning knob that
 * the picture follows without visible lag) and a refined frame within 0.5 s, on this machine and, at
 * an eighth of its speed, on a Raspberry Pi 4 (docs/BENCH.md says what that eighth rests on). */
#include "io/clock.h"
#include "bench/bench.h"
#include "kiosk/kiosk_events.h"
#include "kiosk/kiosk_view.h"
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define KIOSK_TARGET_PREVIEW_FPS 30.0
#define KIOSK_TARGET_REFINED_SECONDS 0.5
/* the exhibit's budget: a Raspberry Pi 4's V3D sustains 8-16 GFLOPS on these shaders against about
 * 70 for this machine's llvmpipe (docs/BENCH.md, the CPU limit): frames must take an eighth here */
#define KIOSK_PI4_SPEED_FRACTION 0.125
#define KIOSK_BENCH_PREVIEWS 8       /* knob detents timed per knob and scene */
#define KIOSK_BENCH_RUN 4            /* ... in runs of this many, the knobs in turn */
/* a visitor's turn: detents this far apart, so that the tables built ahead have the time they get
 * in front of the exhibit */
#define KIOSK_DETENT_SECONDS 0.1

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

struct kiosk_timing {
    double first_frame;              /* s from the scene's switch to its first preview on screen */
    double preview_median[2];        /* s per preview, on screen: speed knob, mass knob */
    double table_ms[2];              /* render-thread ms per detent building or waiting for orbit tables */
    double refined;                  /* s from the knob at rest to the refined frame on screen */
    int bands;
    double antialiased;              /* s from the refined frame to the last sample on screen */
};

static double median(double *x, int n)
{
    qsort(x, (size_t)n, sizeof x[0], cmp_double);
    return x[n / 2];
}

/* One preview of st drawn and on screen (a preview in tiles: its last tile). */
static int show_preview(struct kiosk_view *v, const struct kiosk_state *st, struct screen *screen, struct error *e)
{
    if (kiosk_view_preview(v, st, e) != 0 || compositor_draw(&v->comp, screen, e) != 0)
        return -1;
    while (kiosk_view_preview_pending(v))
        if (kiosk_view_refine(v, e) != 0 || compositor_draw(&v->comp, screen, e) != 0)
            return -1;
    glFinish();
    return 0;
}

/* KIOSK_BENCH_PREVIEWS detents of each knob, as the kiosk's events turn it (the scene's own mapping
 * where it has one), KIOSK_DETENT_SECONDS apart: one up, one down, in turn (the other way first where
 * the knob's end stops it), so that each knob is timed about the same view, and what differs between
 * the two knobs is their own work (a table, an upload), not a larger shadow or a faster camera that
 * a sweep of one of them would show. Each knob from the scene's start view; the two take turns in
 * runs of KIOSK_BENCH_RUN detents (a visitor turns one knob at a time; a run of each knob in each
 * half of the time, so that a loaded machine's slow moment does not fall on one knob alone). */
static int time_knobs(struct kiosk_view *v, const struct kiosk_config *c, int scene, struct screen *screen,
                      double preview[2], double table_ms[2], struct error *e)
{
    double times[2][KIOSK_BENCH_PREVIEWS], tables[2][KIOSK_BENCH_PREVIEWS];
    struct kiosk_state st[2];
    long direction[2] = {1, 1};
    for (int knob = 0; knob < 2; knob++) {
        kiosk_state_reset(&st[knob], c);
        st[knob].scene = scene;
    }
    int n[2] = {0, 0};
    for (int turn = 0; turn < 2 * KIOSK_BENCH_PREVIEWS; turn++) {
        int knob = (turn / KIOSK_BENCH_RUN) % 2, i = n[knob]++;
        struct input_event ev = {.kind = INPUT_KNOB, .knob = (enum input_knob)knob, .counts = direction[knob],
                                 .bit = -1};
        struct event_outcome o = {0};
        struct kiosk_state was = st[knob];
        kiosk_event_apply(c, &st[knob], &v->base, &ev, &o);
        if (!o.changed) {
            st[knob] = was;
            direction[knob] = -direction[knob];
            ev.counts = direction[knob];
            kiosk_event_apply(c, &st[knob], &v->base, &ev, &o);
        }
        direction[knob] = -direction[knob];
        double paced = clock_seconds() + KIOSK_DETENT_SECONDS;
        double built = renderer_orbit_build_seconds(v->renderer);
        double t0 = clock_seconds();
        if (show_preview(v, &st[knob], screen, e) != 0)
            return -1;
        times[knob][i] = clock_seconds() - t0;
        tables[knob][i] = 1e3 * (renderer_orbit_build_seconds(v->renderer) - built);
        double rest = paced - clock_seconds();
        if (rest > 0.0) {
            struct timespec ts = {(time_t)rest, (long)((rest - (double)(time_t)rest) * 1e9)};
            nanosleep(&ts, NULL);
        }
    }
    for (int knob = 0; knob < 2; knob++) {
        preview[knob] = median(times[knob], KIOSK_BENCH_PREVIEWS);
        table_ms[knob] = median(tables[knob], KIOSK_BENCH_PREVIEWS);
    }
    return 0;
}

static int time_scene(struct kiosk_view *v, const struct kiosk_config *c, struct screen *screen, int scene,
                      struct kiosk_timing *t, struct error *e)
{
    struct kiosk_state st;
    kiosk_state_reset(&st, c);
    st.scene = scene;
    /* a scene switch reads the scene, makes its renderer and draws the first preview, whose programs
     * Mesa's shader cache may hold from an earlier run */
    double t0 = clock_seconds();
    if (kiosk_view_load(v, scene, NULL, e) != 0 || show_preview(v, &st, screen, e) != 0)
        return -1;
    t->first_frame = clock_seconds() - t0;
    /* the first band of a refinement compiles the refined frame's programs: not timed */
    if (kiosk_view_refine(v, e) != 0)
        return -1;
    /* each knob from the scene's start view, the two in turn */
    if (time_knobs(v, c, scene, screen, t->preview_median, t->table_ms, e) != 0)
        return -1;
    /* the first band of a refinement makes the band-sized ray state; that is part of the wait */
    t0 = clock_seconds();
    t->bands = 0;
    while (!kiosk_view_refined(v)) {
        if (kiosk_view_refine(v, e) != 0 || compositor_draw(&v->comp, screen, e) != 0)
            return -1;
        t->bands++;
    }
    glFinish();
    t->refined = clock_seconds() - t0;
    t0 = clock_seconds();
    while (!kiosk_view_done(v))
        if (kiosk_view_refine(v, e) != 0 || compositor_draw(&v->comp, screen, e) != 0)
            return -1;
    glFinish();
    t->antialiased = clock_seconds() - t0;
    return 0;
}

static const char *verdict(int met) { return met ? "met" : "MISSED"; }

int bench_kiosk(struct bench *b, struct error *e)
{
    static struct kiosk_config c;
    char path[BENCH_PATH_LEN];
    if (b->kiosk_config[0])
        snprintf(path, sizeof path, "%s", b->kiosk_config);
    else if (kiosk_config_default_path(path, sizeof path, e) != 0)
        return -1;
    if (kiosk_config_load(&c, path, e) != 0 || kiosk_config_check(&c, e) != 0)
        return -1;
    /* the report names the configuration from the working directory where it lies below it */
    char cwd[BENCH_PATH_LEN];
    const char *shown = path;
    size_t cwd_len = getcwd(cwd, sizeof cwd) ? strlen(cwd) : 0;
    if (cwd_len > 0 && strncmp(path, cwd, cwd_len) == 0 && path[cwd_len] == '/')
        shown = path + cwd_len + 1;
    if (b->quick) {
        c.kiosk.preview_width = 32;
        c.kiosk.preview_height = 18;
        c.kiosk.width = 64;
        c.kiosk.height = 36;
    }
    int n = b->quick ? 1 : c.kiosk.n_scenes;
    b->total += n;
    static struct kiosk_view v;
    struct screen *screen;
    if (kiosk_view_init(&v, &c, b->ctx, e) != 0)
        return -1;
    /* a screen of the refined frame's size on the bench's context, as the headless kiosk has */
    screen = screen_open_offscreen(b->ctx, c.kiosk.width, c.kiosk.height, e);
    if (!screen) {
        kiosk_view_release(&v);
        return -1;
    }
    /* bentray bench --kiosk without --out: the table alone, on standard output */
    FILE *csv = b->data_dir[0] ? bench_data_file(b, "kiosk.csv", e) : fopen("/dev/null", "w");
    if (!csv && !b->data_dir[0])
        error_set(e, ERROR_RUNTIME, NULL, "cannot write /dev/null");
    if (!csv) {
        screen_close(screen);
        kiosk_view_release(&v);
        return -1;
    }
    fprintf(csv, "scene,first_frame_seconds,speed_preview_seconds,mass_preview_seconds,speed_table_ms,"
                 "mass_table_ms,refined_seconds,bands,antialiased_seconds\n");
    double pi4_fps = KIOSK_TARGET_PREVIEW_FPS / KIOSK_PI4_SPEED_FRACTION;
    double pi4_refined = KIOSK_TARGET_REFINED_SECONDS * KIOSK_PI4_SPEED_FRACTION;
    fprintf(b->md, "## Kiosk: previews and refined frames\n\n`bentray bench --kiosk --config %s`: each scene "
                   "through the kiosk's own view, events and compositor (src/kiosk/kiosk_view.c). First frame: from "
                   "the switch to the scene to its first preview on screen. Then %d detents of each knob, %.1f s "
                   "apart as a visitor turns it (the scene's own mapping where it has one), from the scene's start "
                   "view, one up and one down in turn, so that both knobs are timed about the same view, the two "
                   "knobs in turn in runs of %d detents: the median preview at "
                   "%dx%d, put on a %dx%d screen, and the median milliseconds per detent that the render thread "
                   "spent building orbit tables or waiting for the worker that builds them ahead (0 for scenes "
                   "without a table). Then the time from the knobs at rest to the refined %dx%d frame on screen, "
                   "in bands of %d rows, and from there to its anti-aliased frame, %d rays a pixel (`refine_samples`: "
                   "the frame traced again that many times, no target).\n\n"
                   "Targets: %.0f previews a second and the refined frame within %.2f s here; the Raspberry Pi 4 "
                   "budget is the same targets at %.3f of this machine's speed, so %.0f previews a second and "
                   "%.3f s here (a Pi 4's V3D sustains 8-16 GFLOPS on these shaders against about 70 for this "
                   "llvmpipe: an estimate from the peak rate and the CPU limit below, not a measurement). The Pi 4 "
                   "columns are that estimate: the slower knob's previews a second and the refined frame's seconds "
                   "here at that speed, and whether they hold the targets there (previews of this size: on a GPU that "
                   "slow the kiosk previews smaller, down to the size that holds `preview_rate`, and says so in its "
                   "log; the refined frame keeps its size).\n\n"
                   "| scene | first frame s | speed previews/s | mass previews/s | mass/speed | table ms per mass "
                   "detent | refined s | bands | previews here | refined here | Pi 4 previews/s, estimate | Pi 4 refined s, "
                   "estimate | "
                   "anti-aliased s |\n"
                   "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
            shown, KIOSK_BENCH_PREVIEWS, KIOSK_DETENT_SECONDS, KIOSK_BENCH_RUN, c.kiosk.preview_width, c.kiosk.preview_height,
            c.kiosk.width, c.kiosk.height, c.kiosk.width, c.kiosk.height, v.band_rows, c.kiosk.refine_samples,
            KIOSK_TARGET_PREVIEW_FPS,
            KIOSK_TARGET_REFINED_SECONDS, KIOSK_PI4_SPEED_FRACTION, pi4_fps, pi4_refined);
    int rc = 0;
    for (int i = 0; i < n && rc == 0; i++) {
        const char *name = strrchr(c.kiosk.scenes[i], '/');
        name = name ? name + 1 : c.kiosk.scenes[i];
        bench_progress(b, "kiosk: %s", name);
        struct kiosk_timing t;
        rc = time_scene(&v, &c, screen, i, &t, e);
        b->done++;
        if (rc != 0)
            break;
        double speed_fps = 1.0 / t.preview_median[INPUT_KNOB_SPEED], mass_fps = 1.0 / t.preview_median[INPUT_KNOB_MASS];
        double slower = speed_fps < mass_fps ? speed_fps : mass_fps;
        /* on a Pi 4, at KIOSK_PI4_SPEED_FRACTION of this machine's speed, against the targets */
        double pi4_previews = slower * KIOSK_PI4_SPEED_FRACTION, pi4_seconds = t.refined / KIOSK_PI4_SPEED_FRACTION;
        fprintf(b->md, "| %s | %.3f | %.1f | %.1f | %.2f | %.2f | %.3f | %d | %s | %s | %.1f %s | %.2f %s | %.3f |\n",
                name, t.first_frame, speed_fps, mass_fps, mass_fps / speed_fps, t.table_ms[INPUT_KNOB_MASS], t.refined,
                t.bands, verdict(slower >= KIOSK_TARGET_PREVIEW_FPS), verdict(t.refined <= KIOSK_TARGET_REFINED_SECONDS),
                pi4_previews, verdict(slower >= pi4_fps), pi4_seconds, verdict(t.refined <= pi4_refined),
                t.antialiased);
        fprintf(csv, "\"%s\",%.4f,%.5f,%.5f,%.3f,%.3f,%.4f,%d,%.4f\n", name, t.first_frame,
                t.preview_median[INPUT_KNOB_SPEED], t.preview_median[INPUT_KNOB_MASS], t.table_ms[INPUT_KNOB_SPEED],
                t.table_ms[INPUT_KNOB_MASS], t.refined, t.bands, t.antialiased);
    }
    fprintf(b->md, "\n");
    fclose(csv);
    screen_close(screen);
    kiosk_view_release(&v);
    return rc;
}
