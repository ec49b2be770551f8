/* The kiosk's responsiveness: how many previews a second a turning knob gets, and how long the
 * refined frame takes once the knob rests, for each scene of the example configuration
 * (kiosk/kiosk.conf), measured through the kiosk's own view and compositor on the bench's context.
 * Targets: at least 30 previews a second at 320x180 (a turning knob that the picture follows
 * without visible lag), a refined 1280x720 frame within 0.5 s. */
#include "io/clock.h"
#include "bench/bench.h"
#include "kiosk/kiosk_view.h"
#include <stdlib.h>
#include <string.h>

#define KIOSK_CONFIG "kiosk/kiosk.conf"
#define KIOSK_TARGET_PREVIEW_FPS 30.0
#define KIOSK_TARGET_REFINED_SECONDS 0.5
#define KIOSK_BENCH_PREVIEWS 8       /* knob detents timed per scene */

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

struct kiosk_timing {
    double preview_median;           /* s per preview, on screen */
    double refined;                  /* s from the knob at rest to the refined frame on screen */
    int bands;
};

static int time_scene(struct kiosk_view *v, const struct kiosk_config *c, struct screen *screen, int scene,
                      struct kiosk_timing *t, struct error *e)
{
    if (kiosk_view_load(v, scene, NULL, e) != 0)
        return -1;
    struct kiosk_state st;
    kiosk_state_reset(&st, c);
    st.scene = scene;
    /* the first preview and the first band of a refinement compile the scene's programs (without
     * a warm shader cache, a second or more on llvmpipe): not timed */
    if (kiosk_view_preview(v, &st, e) != 0)
        return -1;
    while (kiosk_view_preview_pending(v))
        if (kiosk_view_refine(v, e) != 0)
            return -1;
    if (kiosk_view_refine(v, e) != 0)
        return -1;
    double times[KIOSK_BENCH_PREVIEWS];
    for (int i = 0; i < KIOSK_BENCH_PREVIEWS; i++) {
        st.speed = knob_turn(&c->speed, st.speed, 1);
        double t0 = clock_seconds();
        if (kiosk_view_preview(v, &st, e) != 0 || compositor_draw(&v->comp, screen, e) != 0)
            return -1;
        /* a preview drawn in tiles is on screen once its last tile is */
        while (kiosk_view_preview_pending(v))
            if (kiosk_view_refine(v, e) != 0 || compositor_draw(&v->comp, screen, e) != 0)
                return -1;
        glFinish();
        times[i] = clock_seconds() - t0;
    }
    qsort(times, KIOSK_BENCH_PREVIEWS, sizeof times[0], cmp_double);
    t->preview_median = times[KIOSK_BENCH_PREVIEWS / 2];
    /* the first band of a refinement makes the band-sized ray state; that is part of the wait */
    double t0 = clock_seconds();
    t->bands = 0;
    while (!kiosk_view_refined(v)) {
        if (kiosk_view_refine(v, e) != 0 || compositor_draw(&v->comp, screen, e) != 0)
            return -1;
        t->bands++;
    }
    glFinish();
    t->refined = clock_seconds() - t0;
    return 0;
}

int bench_kiosk(struct bench *b, struct error *e)
{
    static struct kiosk_config c;
    if (kiosk_config_load(&c, KIOSK_CONFIG, e) != 0 || kiosk_config_check(&c, e) != 0)
        return -1;
    if (b->quick) {
        c.kiosk.preview_width = 32;
        c.kiosk.preview_height = 18;
        c.kiosk.width = 64;
        c.kiosk.height = 36;
    }
    int n = b->quick ? 1 : c.kiosk.n_scenes;
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
    fprintf(csv, "scene,preview_seconds,previews_per_second,refined_seconds,bands\n");
    fprintf(b->md, "## Kiosk: previews and refined frames\n\n`bentray bench --kiosk`: the scenes of `%s` "
                   "through the kiosk's own view and compositor (src/kiosk/kiosk_view.c): the median of %d "
                   "previews at %dx%d, each after one detent of the speed knob and put on a %dx%d screen; then "
                   "the time from the knob at rest to the refined %dx%d frame on screen, in bands of %d rows. "
                   "Targets: at least %.0f previews a second, the refined frame within %.1f s.\n\n"
                   "| scene | preview s | previews/s | target | refined s | bands | target |\n"
                   "|---|---|---|---|---|---|---|\n",
            KIOSK_CONFIG, KIOSK_BENCH_PREVIEWS, c.kiosk.preview_width, c.kiosk.preview_height, c.kiosk.width,
            c.kiosk.height, c.kiosk.width, c.kiosk.height, v.band_rows, KIOSK_TARGET_PREVIEW_FPS,
            KIOSK_TARGET_REFINED_SECONDS);
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
        double fps = 1.0 / t.preview_median;
        fprintf(b->md, "| %s | %.3f | %.1f | %s | %.2f | %d | %s |\n", name, t.preview_median, fps,
                fps >= KIOSK_TARGET_PREVIEW_FPS ? "met" : "MISSED", t.refined, t.bands,
                t.refined <= KIOSK_TARGET_REFINED_SECONDS ? "met" : "MISSED");
        fprintf(csv, "\"%s\",%.5f,%.2f,%.4f,%d\n", name, t.preview_median, fps, t.refined, t.bands);
    }
    fprintf(b->md, "\n");
    fclose(csv);
    screen_close(screen);
    kiosk_view_release(&v);
    return rc;
}
