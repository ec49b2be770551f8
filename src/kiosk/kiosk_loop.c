/* The kiosk's loop. */
#include "io/clock.h"
#include "kiosk/kiosk_loop.h"
#include "io/output_file.h"
#include <dirent.h>
#include "io/image_cache.h"
#include "io/png_io.h"
#include "kiosk/hud.h"
#include "kiosk/kiosk_events.h"
#include "kiosk/kiosk_images.h"
#include "kiosk/kiosk_view.h"
#include "kiosk/kiosk_tune.h"
#include "kiosk/kiosk_warm.h"
#include "kiosk_config/kiosk_config_keys.h"
#include "render/orbit_store.h"
#include "display/screen.h"
#include "input/script_player.h"
#include "kiosk/service.h"
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#define KIOSK_MAX_EVENTS 256         /* drained per turn; the rest waits for the next turn */
/* The arguments of "%s%s%s" that write a struct error as "WHERE: MESSAGE" (MESSAGE alone where it
 * names no place), as the log says every failure. */
#define ERROR_TEXT(e) (e)->where, (e)->where[0] ? ": " : "", (e)->message

static volatile sig_atomic_t stop_requested;

static void on_stop_signal(int sig)
{
    (void)sig;
    stop_requested = 1;
}

static void set_action(int sig, void (*handler)(int))
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = handler;
    sigemptyset(&sa.sa_mask);
    sigaction(sig, &sa, NULL);
}

/* No SA_RESTART: a signal cuts poll() short, so the loop sees it at once. SIGHUP (the terminal or
 * session went away) stops as cleanly as SIGTERM. A reader that went away (a closed log pipe) is a
 * failed write, not the end of the exhibit, and the user signals mean nothing here: ignored, except
 * that the KMS screen on a virtual terminal takes them for its console switches (vt_switch.h). */
static void catch_stop_signals(void)
{
    stop_requested = 0;
    set_action(SIGTERM, on_stop_signal);
    set_action(SIGINT, on_stop_signal);
    set_action(SIGHUP, on_stop_signal);
    set_action(SIGPIPE, SIG_IGN);
    set_action(SIGUSR1, SIG_IGN);
    set_action(SIGUSR2, SIG_IGN);
}

struct kiosk {
    const struct kiosk_config *cfg;  /* &shown */
    struct kiosk_config shown;       /* the configuration, less the scenes this GPU cannot draw */
    const struct kiosk_run_options *opt;
    FILE *log;
    struct screen *screen;
    struct kiosk_view view;
    int have_view;
    struct input_source *inputs[KIOSK_MAX_INPUTS];
    struct kiosk_state state;
    struct scene *scenes;            /* every scene file, read and checked once at start */
    struct scene *trial;             /* a scene a state is tried on before it is taken */
    int virtual_clock;
    long long turn;                  /* turns of the loop so far */
    double now;
    /* attract mode */
    struct script tour;
    struct script_player tour_player;
    int attract;
    double last_input;
    /* HUD */
    struct hud_font *font;
    unsigned char *hud_rgba;
    int hud_width, hud_height;       /* of hud_rgba: the screen's size when it was made */
    char hud_text[HUD_MAX_LINES * HUD_LINE_LEN + 128];
    enum hud_knob indicator;
    double indicator_until;
    char notice[HUD_LINE_LEN];
    double notice_until;
    int draws_this_second, draws_last_second;
    double second_start;
    /* the frame times of the picture being refined (--stats, staff mode): its previews since the
     * last refined frame, the bands' time, from the last change of state to the refined frame; then
     * the anti-aliasing's bands and their time */
    struct frame_times {
        int previews, bands, sample_bands;
        double preview_seconds, preview_longest, band_seconds, changed_at, sample_seconds;
    } times;
    /* headless frames */
    int frames_written;
    long long drawn;                 /* previews and bands drawn */
    long compiled_ahead;             /* programs compiled before the first frame */
};

static double kiosk_now(const struct kiosk *k)
{
    return k->virtual_clock ? (double)k->turn / KIOSK_VIRTUAL_FPS : clock_seconds();
}

/* The black hole's shadow (mass M) as a share of the view's height, as a visitor sees it: the
 * static observer's angular diameter, aberrated by the camera's velocity towards the hole (the part
 * along the direction to it, as though the hole were ahead: tan(a'/2) = sqrt((1 - b) / (1 + b))
 * tan(a/2)). A figure for the HUD's words, not a measurement. */
static double shadow_share(const struct scene *s, double mass, vec3d velocity)
{
    const double pi = 3.14159265358979323846;
    double across = scene_shadow_diameter_deg_at(s, mass);
    if (across <= 0.0 || across >= 360.0)
        return across <= 0.0 ? 0.0 : 360.0 / s->camera.fov_deg;
    vec3d to_hole = v3_normalize(v3_sub(s->model.center, s->camera.position));
    double beta = v3_dot(velocity, to_hole);
    beta = beta > 0.999999 ? 0.999999 : beta < -0.999999 ? -0.999999 : beta;
    double half = 0.5 * across * pi / 180.0;
    double seen = 2.0 * atan(sqrt((1.0 - beta) / (1.0 + beta)) * tan(half)) * 180.0 / pi;
    return seen / s->camera.fov_deg;
}

/* The scene's view of the knobs and what the HUD says about them. */
static void hud_view_of(struct kiosk *k, struct hud_view *v)
{
    const struct scene *s = &k->scenes[k->state.scene];
    memset(v, 0, sizeof *v);
    v->staff = k->state.staff;
    v->title = s->kiosk.title[0] ? s->kiosk.title : s->name;
    v->caption = s->kiosk.caption;
    v->name = s->name;
    v->explanation = s->description;
    v->has_speed = 1;
    v->speed = k->state.speed;
    v->has_mass = model_ops_of(s->model.type)->has_mass;
    v->mass = k->state.mass;
    v->camera_distance = v3_len(v3_sub(s->camera.position, s->model.center));
    v->effects = scene_has_black_body(s) ? (int)kiosk_state_effects(&k->state, s) : -1;
    v->fps = kiosk_view_refined(&k->view) && k->draws_last_second == 0 ? -1.0 : k->draws_last_second;
    v->refining = !kiosk_view_refined(&k->view);
    /* knobs the scene maps to its own keys show those instead of speed and mass; a mass knob mapped
     * to the black hole's own mass is the black hole's */
    const struct knob_mapping *ms = &s->kiosk.speed, *mm = &s->kiosk.mass;
    v->speed_label = ms->label;
    v->mass_label = mm->label;
    v->speed_range[0] = ms->min;
    v->speed_range[1] = ms->max;
    v->mass_range[0] = mm->min;
    v->mass_range[1] = mm->max;
    /* a mass knob mapped to the black hole's mass, without words of its own, shows the shadow */
    int hole_mapped = v->has_mass && strcmp(mm->key, "model.mass") == 0 && !mm->label[0];
    if (hole_mapped)
        v->mass = knob_turn_mapped(mm, s, k->state.mass_param, 0);
    /* gravity's shift named only where there is a mass to shift the light: the hole's mass as drawn
     * (a knob mapped to another key leaves the scene's own) */
    double drawn_mass = !mm->key[0] || hole_mapped ? v->mass : s->model.mass;
    v->gravitational_shift = v->has_mass && drawn_mass > 0.0 && kiosk_state_gravitational_shift(&k->state, s);
    vec3d view = v3_normalize(v3_sub(s->camera.look_at, s->camera.position));
    vec3d velocity = ms->key[0] ? s->observer.velocity : v3_scale(view, k->state.speed);
    v->shadow_share = shadow_share(s, v->mass, velocity);
    if (ms->key[0]) {
        v->has_speed = 0;
        v->speed_key = ms->key;
        v->speed_param = knob_turn_mapped(ms, s, k->state.speed_param, 0);
    }
    if (mm->key[0] && !hole_mapped) {
        v->has_mass = 0;
        v->mass_key = mm->key;
        v->mass_param = knob_turn_mapped(mm, s, k->state.mass_param, 0);
    }
    if (k->now < k->indicator_until) {
        v->indicator = k->indicator;
        int speed = k->indicator == HUD_KNOB_SPEED;
        const struct knob_mapping *m = speed ? ms : mm;
        const struct kiosk_knob *knob = speed ? &k->cfg->speed : &k->cfg->mass;
        double mapped = speed ? v->speed_param : hole_mapped ? v->mass : v->mass_param;
        v->indicator_value = m->key[0] ? mapped : speed ? k->state.speed : k->state.mass;
        v->indicator_min = m->key[0] ? m->min : knob->min;
        v->indicator_max = m->key[0] ? m->max : knob->max;
    }
    v->notice = k->now < k->notice_until ? k->notice
              : k->attract              ? "touch a knob or a button to take over"
                                        : NULL;
    /* the pipeline view labels its panels instead (hud.c) */
    v->pipeline_view = k->state.pipeline_view;
    struct renderer_textures t;
    renderer_textures(k->view.renderer, &t);
    v->orbit_table = t.orbit_table != 0;
    v->fixed_steps = kiosk_state_budget(&k->view.live) > 0.0;
    v->far_steps = v->fixed_steps && scene_far_steps(&k->view.live);
    compositor_letterbox(&k->view.comp, k->screen->width, k->screen->height, &v->canvas_x, &v->canvas_y,
                         &v->canvas_w, &v->canvas_h);
}

/* Redraws the HUD image when its text changed; returns 1 when it did. */
static int update_hud(struct kiosk *k, struct error *e, int *failed)
{
    *failed = 0;
    if (!k->font)
        return 0;
    int w = k->screen->width, h = k->screen->height;
    if (w != k->hud_width || h != k->hud_height) {
        /* a window can be resized: the HUD is drawn at the screen's size */
        unsigned char *grown = realloc(k->hud_rgba, (size_t)w * h * 4);
        if (!grown) {
            error_set(e, ERROR_RUNTIME, NULL, "out of memory for the HUD at %dx%d", w, h);
            *failed = 1;
            return 0;
        }
        k->hud_rgba = grown;
        k->hud_width = w;
        k->hud_height = h;
        k->hud_text[0] = '\0';
    }
    struct hud_view v;
    hud_view_of(k, &v);
    char lines[HUD_MAX_LINES][HUD_LINE_LEN];
    int n = hud_lines(&v, lines, HUD_MAX_LINES);
    char text[sizeof k->hud_text];
    /* the indicator is drawn but not in the text (and its value not always): its coming and going
     * and its bar must redraw the HUD too, and so must a new size and the pipeline view, which
     * labels its panels instead of the lines */
    size_t used = (size_t)snprintf(text, sizeof text, "%dx%d indicator %d %.17g pipeline %d\n", w, h,
                                   (int)v.indicator, v.indicator == HUD_KNOB_NONE ? 0.0 : v.indicator_value,
                                   v.pipeline_view);
    for (int i = 0; i < n && used < sizeof text; i++)
        used += (size_t)snprintf(text + used, sizeof text - used, "%s\n", lines[i]);
    if (strcmp(text, k->hud_text) == 0)
        return 0;
    memcpy(k->hud_text, text, sizeof text);
    hud_draw(k->font, k->hud_rgba, w, h, &v);
    if (compositor_set_hud(&k->view.comp, k->hud_rgba, w, h, e) != 0)
        *failed = 1;
    return 1;
}

static int write_frame(struct kiosk *k, struct error *e)
{
    const struct screen *s = k->screen;
    char path[KIOSK_PATH_LEN + 32];
    snprintf(path, sizeof path, "%s/frame_%04d.png", k->cfg->display.headless_out, k->frames_written + 1);
    unsigned char *rgba = malloc((size_t)s->width * s->height * 4);
    if (!rgba)
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory writing %s", path);
    int rc = compositor_read_screen(s, rgba, e);
    if (rc == 0)
        rc = png_write_rgba8(path, s->width, s->height, rgba, k->opt->force, PNG_COMPRESSION_FAST, e);
    free(rgba);
    if (rc == 0)
        k->frames_written++;
    return rc;
}

static void notice(struct kiosk *k, const char *what, const char *why)
{
    snprintf(k->notice, sizeof k->notice, "%.30s: %.120s", what, why);
    k->notice_until = k->now + KIOSK_INDICATOR_SECONDS;
}

/* A state its scene cannot show (the mass puts the camera inside the horizon) is not taken: the
 * knob stops there and the HUD says why. A new scene where the knobs' values do not fit is shown
 * with the knobs back at their start, which preflight() made sure every scene takes. Returns 1
 * when the state was taken (as proposed or so corrected). */
static int take_state(struct kiosk *k, const struct kiosk_state *asked)
{
    struct kiosk_state corrected = *asked;
    const struct kiosk_state *proposed = &corrected;
    /* the pipeline view shows every ray's final state, which the image-only path cannot read back */
    if (corrected.pipeline_view && !k->state.pipeline_view && k->view.renderer &&
        !renderer_state_sampled(k->view.renderer)) {
        corrected.pipeline_view = 0;
        notice(k, "no pipeline view", "it shows the rays' state, and this GPU renders into no float texture");
        if (k->log) {
            fprintf(k->log, "bentray kiosk: no pipeline view: it shows the rays' state, and this GPU renders into no "
                    "float texture (render path %s)\n", renderer_path(k->view.renderer)->name);
            fflush(k->log);
        }
        if (kiosk_state_same(&corrected, &k->state))
            return 0;
    }
    struct error serr;
    if (kiosk_state_apply(proposed, &k->scenes[proposed->scene], k->trial, &serr) == 0) {
        k->state = *proposed;
        return 1;
    }
    if (proposed->scene == k->state.scene) {
        notice(k, "limit", serr.message);
        return 0;
    }
    struct kiosk_state fresh;
    kiosk_state_reset(&fresh, k->cfg);
    fresh.scene = proposed->scene;
    notice(k, "knobs back to their start", serr.message);
    k->state = fresh;
    return 1;
}

/* One event for the state as it is now (its scene's knob mappings and black bodies). A turn of
 * several detents that would cross a limit goes as far as the limit, detent by detent. */
static void apply_event(struct kiosk *k, const struct input_event *ev, struct event_outcome *out, int *changed)
{
    struct kiosk_state proposed = k->state;
    kiosk_event_apply(k->cfg, &proposed, &k->scenes[proposed.scene], ev, out);
    /* staff mode changes the HUD and the log, not the picture: taken whatever the picture does */
    k->state.staff = proposed.staff;
    if (!out->changed)
        return;
    if (take_state(k, &proposed)) {
        *changed = 1;
        return;
    }
    long counts = ev->kind == INPUT_TURN || ev->kind == INPUT_KNOB ? ev->counts : 0;
    struct input_event one = *ev;
    one.counts = counts > 0 ? 1 : -1;
    for (long i = 1; i < labs(counts); i++) {
        struct event_outcome step;
        proposed = k->state;
        kiosk_event_apply(k->cfg, &proposed, &k->scenes[proposed.scene], &one, &step);
        if (!step.changed || !take_state(k, &proposed))
            break;
        *changed = 1;
    }
}

/* Applies the events of one turn; returns 1 when the picture must change. */
static int handle_events(struct kiosk *k, const struct input_event *ev, int n, int *frames, int *quit)
{
    int changed = 0;
    for (int i = 0; i < n; i++) {
        struct event_outcome out;
        if (ev[i].kind == INPUT_FRAME || ev[i].kind == INPUT_QUIT || ev[i].kind == INPUT_RELEASE) {
            *frames += ev[i].kind == INPUT_FRAME;
            *quit |= ev[i].kind == INPUT_QUIT;
            continue;
        }
        if (k->attract) {
            /* a visitor takes over at once, from the start, with what they did */
            k->attract = 0;
            kiosk_state_reset(&k->state, k->cfg);
            changed = 1;
            fprintf(k->log, "attract mode ends: input\n");
        }
        apply_event(k, &ev[i], &out, &changed);
        if (!out.visitor)
            continue;
        k->last_input = k->now;
        if (out.knob != HUD_KNOB_NONE) {
            k->indicator = out.knob;
            k->indicator_until = k->now + KIOSK_INDICATOR_SECONDS;
        }
    }
    return changed;
}

static int gather_events(struct kiosk *k, struct input_event *ev, int max)
{
    int n = 0;
    if (k->screen->events)
        n += k->screen->events(k->screen, k->now, ev + n, max - n);
    for (int i = 0; i < k->cfg->n_inputs; i++)
        if (k->inputs[i])
            n += k->inputs[i]->drain(k->inputs[i], k->now, ev + n, max - n);
    return n;
}

/* The tour's own events move the state as a visitor's would, but are not a visitor; each pass
 * through the tour starts from the start state, so that its relative turns do not add up. */
static int play_tour(struct kiosk *k, int *frames)
{
    if (!k->attract)
        return 0;
    struct input_event ev[KIOSK_MAX_EVENTS];
    long wraps = k->tour_player.wraps;
    int n = script_player_due(&k->tour_player, k->now, -1, ev, KIOSK_MAX_EVENTS);
    int changed = 0;
    if (k->tour_player.wraps != wraps) {
        kiosk_state_reset(&k->state, k->cfg);
        changed = 1;
    }
    for (int i = 0; i < n; i++) {
        struct event_outcome out;
        if (ev[i].kind == INPUT_FRAME)
            (*frames)++;
        else
            apply_event(k, &ev[i], &out, &changed);
    }
    return changed;
}

static void wait_for_input(struct kiosk *k, double seconds)
{
    struct pollfd fds[1 + KIOSK_MAX_INPUTS * INPUT_MAX_FDS];
    int n = 0;
    int sfd = k->screen->fd ? k->screen->fd(k->screen) : -1;
    if (sfd >= 0)
        fds[n++] = (struct pollfd){.fd = sfd, .events = POLLIN};
    for (int i = 0; i < k->cfg->n_inputs; i++)
        if (k->inputs[i] && k->inputs[i]->fds)
            n += k->inputs[i]->fds(k->inputs[i], fds + n, INPUT_MAX_FDS);
    poll(fds, (nfds_t)n, (int)(seconds * 1000.0));
}

static int scripts_pending(const struct kiosk *k)
{
    for (int i = 0; i < k->cfg->n_inputs; i++)
        if (k->cfg->inputs[i].type == KIOSK_INPUT_SCRIPT && k->inputs[i] && !k->inputs[i]->finished)
            return 1;
    return k->attract;
}

static void start_attract(struct kiosk *k)
{
    k->attract = 1;
    kiosk_state_reset(&k->state, k->cfg);
    script_player_start(&k->tour_player, &k->tour, k->now, 1);
    fprintf(k->log, "attract mode: no input for %d s, playing the tour\n", k->cfg->kiosk.idle_seconds);
}

/* Frame times (--stats, staff mode): a preview drawn after a change of state, from `started`. */
static void count_preview(struct kiosk *k, double started)
{
    struct frame_times *t = &k->times;
    double took = clock_seconds() - started;
    if (t->previews == 0 && t->bands == 0)
        t->changed_at = started;
    t->previews++;
    t->preview_seconds += took;
    t->preview_longest = took > t->preview_longest ? took : t->preview_longest;
    t->bands = 0;
    t->band_seconds = 0.0;
    t->sample_bands = 0;              /* an anti-aliasing the change stopped */
    t->sample_seconds = 0.0;
}

/* A band of the refinement (or a tile of a preview) drawn from `started`; once the frame is
 * refined, its times go to the log where asked for, and the count starts again. A band of the
 * anti-aliasing (sample: drawn after the frame was refined) is counted apart, and logged once the
 * last sample is drawn. */
static void count_band(struct kiosk *k, double started, int sample)
{
    struct frame_times *t = &k->times;
    double now = clock_seconds();
    int log = k->opt->stats || k->state.staff;
    if (sample) {
        t->sample_bands++;
        t->sample_seconds += now - started;
        if (!kiosk_view_done(&k->view))
            return;
        if (log) {
            fprintf(k->log, "frame times: %s: anti-aliased with %d rays a pixel in %d bands, %.3f s of drawing, "
                    "%.3f s after the refined frame\n", k->scenes[k->state.scene].name, k->view.samples.n,
                    t->sample_bands, t->sample_seconds, now - t->changed_at);
            fflush(k->log);
        }
        memset(t, 0, sizeof *t);
        return;
    }
    if (t->previews == 0 && t->bands == 0)
        t->changed_at = started;
    t->bands++;
    t->band_seconds += now - started;
    if (!kiosk_view_refined(&k->view))
        return;
    if (log) {
        fprintf(k->log, "frame times: %s: %d preview%s at %dx%d, %.1f ms each on average, %.1f ms the longest; "
                "refined %dx%d in %d bands, %.3f s of drawing, %.3f s after the last change\n",
                k->scenes[k->state.scene].name, t->previews, t->previews == 1 ? "" : "s", k->view.preview_width, k->view.preview_height,
                t->previews ? 1e3 * t->preview_seconds / t->previews : 0.0, 1e3 * t->preview_longest,
                k->cfg->kiosk.width, k->cfg->kiosk.height, t->bands, t->band_seconds, now - t->changed_at);
        fflush(k->log);
    }
    memset(t, 0, sizeof *t);
    t->changed_at = now;                 /* the anti-aliasing's time counts from the refined frame */
}

/* One turn of the loop; 1 to go on, 0 to stop, -1 on failure (e). */
static int kiosk_turn(struct kiosk *k, struct error *e)
{
    double started = clock_seconds();
    const char *did = "reading inputs";
    k->now = kiosk_now(k);
    struct input_event ev[KIOSK_MAX_EVENTS];
    int n = gather_events(k, ev, KIOSK_MAX_EVENTS);
    int frames = 0, quit = 0;
    int changed = play_tour(k, &frames);
    changed |= handle_events(k, ev, n, &frames, &quit);
    if (quit || stop_requested)
        return 0;
    if (k->cfg->attract.enabled && !k->attract && k->now - k->last_input >= k->cfg->kiosk.idle_seconds) {
        start_attract(k);
        changed = 1;
    }
    /* the view knows which scene it holds: a change of scene (or none loaded yet) loads it */
    int loading = k->view.scene_index != k->state.scene;
    if (loading) {
        did = "loading the scene, then drawing its preview";
        if (kiosk_view_load(&k->view, k->state.scene, &k->scenes[k->state.scene], e) != 0)
            return -1;
        changed = 1;
    }
    int drew = 0;
    double draw_started = clock_seconds();
    if (changed) {
        did = loading ? did : "drawing a preview";
        if (kiosk_view_preview(&k->view, &k->state, e) != 0)
            return -1;
        drew = 1;
        count_preview(k, draw_started);
    } else if (!kiosk_view_done(&k->view)) {
        int sample = kiosk_view_refined(&k->view);
        did = kiosk_view_preview_pending(&k->view) ? "drawing a tile of the preview"
              : sample ? "anti-aliasing the frame" : "refining the frame";
        if (kiosk_view_refine(&k->view, e) != 0)
            return -1;
        drew = 1;
        count_band(k, draw_started, sample);
    }
    k->draws_this_second += drew;
    k->drawn += drew;
    if (k->now - k->second_start >= 1.0) {
        k->draws_last_second = k->draws_this_second;
        k->draws_this_second = 0;
        k->second_start = k->now;
    }
    int hud_failed;
    int hud_changed = update_hud(k, e, &hud_failed);
    if (hud_failed)
        return -1;
    if (drew || hud_changed || k->turn == 0 || k->screen->redraw) {
        k->screen->redraw = 0;
        if (compositor_draw(&k->view.comp, k->screen, e) != 0 || k->screen->present(k->screen, e) != 0)
            return -1;
        if (k->turn == 0)
            service_ready();
    }
    /* frames are files of the headless screen only: a script's 'frame' means nothing on a display */
    int limit = k->cfg->display.headless_frames;
    for (int f = 0; f < frames && k->virtual_clock; f++) {
        if (write_frame(k, e) != 0)
            return -1;
        if (limit > 0 && k->frames_written >= limit)
            return 0;
    }
    if (k->virtual_clock && limit > 0 && !scripts_pending(k) && !k->cfg->attract.enabled) {
        fprintf(k->log, "bentray kiosk: the scripts have ended after %d of the %d frames asked for\n",
                k->frames_written, limit);
        return 0;
    }
    /* a turn that keeps signals, input and the watchdog waiting long says what it did: the journal
     * then explains a watchdog restart on a machine too slow for the scene */
    double took = clock_seconds() - started;
    if (took >= KIOSK_SLOW_TURN_SECONDS && !k->virtual_clock)
        fprintf(k->log, "bentray kiosk: one turn of the loop took %.1f s (%s of %s)\n", took, did,
                k->scenes[k->state.scene].name);
    service_watchdog();
    k->turn++;
    if (!drew && kiosk_view_done(&k->view) && (!k->virtual_clock || !scripts_pending(k)))
        wait_for_input(k, KIOSK_IDLE_WAIT_SECONDS);
    return 1;
}

/* Every image a scene shows (its textures, the six faces of its sky), decoded now and kept for the
 * whole run (io/image_cache.h): a file changed or cut short on disk later does not reach the
 * kiosk, and a scene change reads no file. A file that does not decode is named with the scene
 * file's line of the key that named it, its place (the image's message cut at 399 characters),
 * and the image's status. */
static int keep_scene_images(const struct scene *s, struct error *e)
{
    int w, h, owned;
    const unsigned char *rgba;
    struct error fe;
    char where[SCENE_PATH_LEN + 16];
    for (int i = 0; i < s->n_textures; i++)
        if (image_read(s->textures[i], SCENE_MAX_TEXTURE_SIZE, &w, &h, &rgba, &owned, &fe) != 0) {
            snprintf(where, sizeof where, "%s:%d", s->path, s->texture_line[i]);
            return error_set(e, fe.status, where, "texture: %.399s", fe.message);
        }
    for (int f = 0; s->sky.type == SKY_CUBEMAP && f < SCENE_CUBEMAP_FACES; f++) {
        char path[SCENE_PATH_LEN + 16];
        scene_cubemap_face_path(s->sky.cubemap, f, path, sizeof path);
        if (image_read(path, SCENE_MAX_TEXTURE_SIZE, &w, &h, &rgba, &owned, &fe) != 0) {
            snprintf(where, sizeof where, "%s:%d", s->path, s->cubemap_line);
            return error_set(e, fe.status, where, "cubemap: %.399s", fe.message);
        }
    }
    return 0;
}

/* Everything a run needs that a person could have got wrong, checked before anything is shown:
 * the scene files, the scripts, the font, where headless frames go. 0, or -1 with e. */
/* A font the file names must be one, refused at start at its line as a missing file is (the default
 * font, named by no line, only leaves the HUD out where it is missing: open_hud). The font opened
 * here is the HUD's. 0, or -1 with e. */
static int check_font(struct kiosk *k, struct error *e)
{
    const struct kiosk_config *c = k->cfg;
    int line = kiosk_key_line(c, KSEC_KIOSK, 0, "font");
    if (!c->kiosk.hud || line == 0)
        return 0;
    struct error why;
    k->font = hud_font_open(c->kiosk.font, &why);
    if (k->font || why.status != ERROR_INPUT)
        return 0;
    char where[KIOSK_PATH_LEN + 16];
    snprintf(where, sizeof where, "%s:%d", c->path, line);
    return error_set(e, ERROR_INPUT, where, "[kiosk] font = %s: %s", c->kiosk.font, why.message);
}

static int preflight(struct kiosk *k, struct error *e)
{
    const struct kiosk_config *c = k->cfg;
    k->scenes = calloc((size_t)c->kiosk.n_scenes, sizeof *k->scenes);
    if (!k->scenes)
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory for %d scenes", c->kiosk.n_scenes);
    k->trial = scene_new(e);
    if (!k->trial)
        return -1;
    for (int i = 0; i < c->kiosk.n_scenes; i++) {
        struct error serr;
        if (scene_load(&k->scenes[i], c->kiosk.scenes[i], e) != 0)
            return -1;
        if (k->scenes[i].render.samples > 1 && k->log)
            fprintf(k->log, "%s: render.samples = %d is for bentray render's images; the kiosk traces one ray a "
                            "pixel, its refined frame at the screen's own resolution\n", c->kiosk.scenes[i],
                    k->scenes[i].render.samples);
        if (k->scenes[i].render.bloom > 0.0 && k->log)
            fprintf(k->log, "%s: render.bloom = %g is for bentray render's images; the kiosk draws its frames "
                            "without it\n", c->kiosk.scenes[i], k->scenes[i].render.bloom);
        /* a scene on exact orbits builds its table again at each mass detent, on the render thread
         * where no table was built ahead: a table too large to build ahead would hold the loop (and
         * the watchdog) for seconds at every detent */
        if (k->scenes[i].render.method == METHOD_ORBIT_TABLE) {
            struct orbit_table_params p;
            orbit_table_params_for(&k->scenes[i], &p);
            size_t bytes = orbit_store_table_bytes(&p);
            if (bytes > ORBIT_STORE_AHEAD_MAX_BYTES)
                return error_set(e, ERROR_INPUT, c->kiosk.scenes[i], "render.orbit_rows = %d and render.orbit_columns "
                                 "= %d make an orbit table of %.1f MB, which the kiosk would build again at every "
                                 "mass detent, on its loop, for longer than the watchdog may allow: at most %.0f MB "
                                 "in the kiosk (fewer rows or columns)", k->scenes[i].render.orbit_rows,
                                 k->scenes[i].render.orbit_columns, bytes / 1048576.0,
                                 ORBIT_STORE_AHEAD_MAX_BYTES / 1048576.0);
        }
        /* every scene must take the knobs' start values: reset and a scene change fall back to them */
        struct scene *trial = k->trial;
        struct kiosk_state start;
        kiosk_state_reset(&start, c);
        start.scene = i;
        if (kiosk_state_apply(&start, &k->scenes[i], trial, &serr) != 0)
            return error_set(e, ERROR_INPUT, c->path, "the knobs' start values (speed %g c, mass %g) do not fit %s: "
                             "%.512s", c->speed.start, c->mass.start, c->kiosk.scenes[i], serr.message);
        /* a black hole whose mass the [mass] knob sets directly (no [kiosk] mass_key): at the knob's
         * largest mass its shadow spans at most the share of the view a scene's [kiosk] may reach */
        const struct scene *sc = &k->scenes[i];
        if (model_ops_of(sc->model.type)->has_mass && sc->kiosk.mass.key[0] == '\0') {
            *trial = *sc;
            trial->model.mass = c->mass.max;
            double across = scene_shadow_diameter_deg(trial);
            double limit = SCENE_KIOSK_SHADOW_MAX_FRACTION * sc->camera.fov_deg;
            if (across > limit) {
                char what[96];
                if (across >= 360.0)
                    snprintf(what, sizeof what, "swallow the camera");
                else
                    snprintf(what, sizeof what, "cast a shadow %.0f degrees across, over %.0f%% of the view's height",
                             across, 100.0 * SCENE_KIOSK_SHADOW_MAX_FRACTION);
                return error_set(e, ERROR_INPUT, c->path, "[mass] max = %g would make the black hole of %s %s: give "
                                 "the scene a [kiosk] section (mass_key = model.mass, mass_min, mass_max at most "
                                 "%.3g, mass_steps; docs/SCENES.md) or lower [mass] max", c->mass.max,
                                 c->kiosk.scenes[i], what, scene_mass_for_shadow(sc, limit));
            }
        }
    }
    if (kiosk_image_memory_check(c, k->scenes, e) != 0)
        return -1;
    image_cache_keep(1);
    for (int i = 0; i < c->kiosk.n_scenes; i++)
        if (keep_scene_images(&k->scenes[i], e) != 0)
            return -1;
    static struct script sc;
    for (int i = 0; i < c->n_inputs; i++)
        if (c->inputs[i].type == KIOSK_INPUT_SCRIPT && script_load(&sc, c->inputs[i].path, e) != 0)
            return -1;
    if (c->attract.enabled && script_load(&k->tour, c->attract.script, e) != 0)
        return -1;
    return check_font(k, e);
}

/* The directory headless frames go to: named, there, a directory, and without a frame of an
 * earlier run (unless --force). 0, or -1 with e, the configuration file its place; a directory
 * that cannot be looked at has its status from error_status_of_errno. */
static int headless_preflight(const struct kiosk *k, struct error *e)
{
    const struct kiosk_display *d = &k->cfg->display;
    struct stat st;
    if (d->headless_out[0] == '\0')
        return error_set(e, ERROR_INPUT, k->cfg->path,
                         "[display] headless_out: the headless screen needs a directory for its frames");
    if (stat(d->headless_out, &st) != 0) {
        int en = errno;
        return error_set(e, error_status_of_errno(en), k->cfg->path, "[display] headless_out: %s: %s",
                         d->headless_out, strerror(en));
    }
    if (!S_ISDIR(st.st_mode))
        return error_set(e, ERROR_INPUT, k->cfg->path, "[display] headless_out: %s is not a directory",
                         d->headless_out);
    /* any frame of an earlier run, not only the first: a stray frame_0007.png would otherwise
     * stop the kiosk at its seventh frame */
    DIR *dir = opendir(d->headless_out);
    if (!dir) {
        int en = errno;
        return error_set(e, error_status_of_errno(en), k->cfg->path, "[display] headless_out: %s: %s",
                         d->headless_out, strerror(en));
    }
    int rc = 0;
    for (struct dirent *de; rc == 0 && (de = readdir(dir));) {
        unsigned number;
        int end = 0;
        if (sscanf(de->d_name, "frame_%u.png%n", &number, &end) != 1 || end == 0 || de->d_name[end] != '\0')
            continue;
        char path[KIOSK_PATH_LEN + 300];
        snprintf(path, sizeof path, "%s/%s", d->headless_out, de->d_name);
        struct error why;
        /* the reason cut at 599 characters, as it always was */
        if (output_check(path, k->opt->force, &why) != 0)
            rc = error_set(e, why.status, NULL, "[display] headless_out: %.599s: a frame of an earlier run",
                           why.message);
    }
    closedir(dir);
    return rc;
}

/* The screen. A KMS display with nothing plugged in is waited for (the monitor may be switched on
 * after the kiosk), logged once; auto says which back-ends it passed over. NULL with e. */
static struct screen *open_screen(struct kiosk *k, struct error *e)
{
    const struct kiosk_config *c = k->cfg;
    int logged = 0;
    for (;;) {
        error_clear(e);
        struct screen *s = screen_open(&c->display, c->kiosk.width, c->kiosk.height, k->opt->gl_backend, e);
        if (s) {
            if (c->display.backend == KIOSK_BACKEND_AUTO && (e->where[0] || e->message[0]))
                fprintf(k->log, "bentray kiosk: display %s (passed over: %s%s%s)\n", s->name, ERROR_TEXT(e));
            if (logged)
                fprintf(k->log, "bentray kiosk: display connected\n");
            return s;
        }
        if (c->display.backend != KIOSK_BACKEND_KMS || !strstr(e->message, "no connected connector") || stop_requested)
            return NULL;
        if (!logged++)
            fprintf(k->log, "bentray kiosk: %s%s%s; trying again every %.0f s\n", ERROR_TEXT(e),
                    KIOSK_DISPLAY_RETRY_SECONDS);
        /* before READY the service manager counts start-up time, not the watchdog: ask for more */
        service_extend_timeout(3.0 * KIOSK_DISPLAY_RETRY_SECONDS);
        service_status("waiting for a monitor: %s%s%s", ERROR_TEXT(e));
        struct timespec wait = {(time_t)KIOSK_DISPLAY_RETRY_SECONDS, 0};
        nanosleep(&wait, NULL);
    }
}

static void free_scenes(struct kiosk *k)
{
    hud_font_close(k->font);
    k->font = NULL;
    free(k->scenes);
    scene_free(k->trial);
}

static void kiosk_close(struct kiosk *k)
{
    for (int i = 0; i < k->cfg->n_inputs; i++)
        input_close(k->inputs[i]);
    if (k->have_view)
        kiosk_view_release(&k->view);
    free(k->hud_rgba);
    free_scenes(k);
    image_cache_release();
    if (k->screen)
        screen_close(k->screen);
}

/* Between two states of the warm-up (or two scenes of the preview tuning): the service manager's
 * start timeout extended for the next (a first compile on a slow GPU may take minutes), and a
 * signal stops it. */
static int between_warm_states(void *arg)
{
    (void)arg;
    service_extend_timeout(KIOSK_WARM_STATE_SECONDS);
    return stop_requested != 0;
}

/* The GPU's name, as its driver gives it. */
static const char *gpu_name(void)
{
    const GLubyte *name = glGetString(GL_RENDERER);
    return name ? (const char *)name : "(unknown)";
}

/* The scenes marked in drop left out of the kiosk (k->shown, k->scenes), each said in the log with
 * why; the start scene follows its scene, or becomes the first one left. */
static void drop_scenes(struct kiosk *k, const int *drop, char (*why)[KIOSK_REFUSAL_LEN])
{
    struct kiosk_config *c = &k->shown;
    char start[KIOSK_PATH_LEN];
    snprintf(start, sizeof start, "%s", c->kiosk.scenes[c->kiosk.start_scene]);
    int kept = 0, start_kept = -1, left = 0;
    for (int i = 0; i < c->kiosk.n_scenes; i++)
        left += !drop[i];
    for (int i = 0; i < c->kiosk.n_scenes; i++) {
        if (drop[i]) {
            fprintf(k->log, "bentray kiosk: %s: this GPU (%s) cannot draw it: %s%s\n", c->kiosk.scenes[i], gpu_name(),
                    why[i], left ? "; the kiosk shows the other scenes" : "");
            continue;
        }
        if (i == c->kiosk.start_scene)
            start_kept = kept;
        if (kept != i) {
            memmove(c->kiosk.scenes[kept], c->kiosk.scenes[i], sizeof c->kiosk.scenes[kept]);
            k->scenes[kept] = k->scenes[i];
        }
        kept++;
    }
    if (start_kept < 0 && kept > 0)
        fprintf(k->log, "bentray kiosk: the start scene %s cannot be drawn; the kiosk starts with %s\n", start,
                c->kiosk.scenes[0]);
    c->kiosk.n_scenes = kept;
    c->kiosk.start_scene = start_kept < 0 ? 0 : start_kept;
    kiosk_view_unload(&k->view);
}

/* Each scene's renderer made once on this GPU: the log says its render path, and a scene the GPU
 * refuses (a path, a precision or a loop length it lacks) is left out. The number of scenes left. */
static int refuse_scenes(struct kiosk *k)
{
    static int drop[KIOSK_MAX_SCENES];
    static char why[KIOSK_MAX_SCENES][KIOSK_REFUSAL_LEN];
    int any = 0;
    for (int i = 0; i < k->shown.kiosk.n_scenes; i++) {
        struct error refusal;
        error_clear(&refusal);
        drop[i] = kiosk_view_load(&k->view, i, &k->scenes[i], &refusal) != 0;
        if (drop[i])
            error_format(&refusal, why[i], sizeof why[i]);
        else
            fprintf(k->log, "bentray kiosk: %s: %s\n", k->shown.kiosk.scenes[i],
                    renderer_path(k->view.renderer)->description);
        any |= drop[i];
    }
    if (any)
        drop_scenes(k, drop, why);
    /* as it was before: the compile-ahead starts from an empty cache */
    kiosk_view_forget_programs(&k->view);
    return k->shown.kiosk.n_scenes;
}

/* Every program of every scene compiled before the first frame (kiosk_warm.h), as compile_ahead
 * says. 0, or -1 with e. */
static int compile_ahead(struct kiosk *k, struct error *e)
{
    int ahead = k->cfg->kiosk.compile_ahead;
    if (ahead == KIOSK_AHEAD_OFF || (ahead == KIOSK_AHEAD_AUTO && k->virtual_clock))
        return 0;
    service_status("compiling the shader programs of %d scenes", k->cfg->kiosk.n_scenes);
    static struct kiosk_warm_report w;
    if (kiosk_warm(&k->view, k->cfg, k->scenes, between_warm_states, NULL, &w, e) != 0)
        return -1;
    for (int i = 0; i < k->shown.kiosk.n_scenes; i++)
        if (w.failed[i]) {
            drop_scenes(k, w.failed, w.why);
            break;
        }
    k->compiled_ahead = w.programs;
    service_status("%ld shader programs compiled ahead for %d scenes in %.1f s", w.programs, w.scenes, w.seconds);
    fprintf(k->log, "bentray kiosk: %ld shader programs compiled ahead for %d scenes in %.1f s (%d states drawn%s)\n",
            w.programs, w.scenes, w.seconds, w.states, w.refused ? ", some refused by their scene" : "");
    return 0;
}

static int open_hud(struct kiosk *k)
{
    if (!k->cfg->kiosk.hud)
        return 0;
    struct error e;
    if (!k->font)
        k->font = hud_font_open(k->cfg->kiosk.font, &e);
    if (!k->font) {
        fprintf(k->log, "HUD: %s%s%s; the kiosk runs without it\n", ERROR_TEXT(&e));
        return 0;
    }
    k->hud_width = k->screen->width;
    k->hud_height = k->screen->height;
    k->hud_rgba = malloc((size_t)k->hud_width * k->hud_height * 4);
    return k->hud_rgba ? 0 : -1;
}

enum kiosk_status kiosk_run(const struct kiosk_config *c, const struct kiosk_run_options *o)
{
    static struct kiosk k;
    memset(&k, 0, sizeof k);
    k.shown = *c;
    k.cfg = c = &k.shown;
    k.opt = o;
    k.log = o->log;
    /* the run's status is its own (enum kiosk_status), whatever the status of its error */
    struct error e;
    error_clear(&e);
    if (preflight(&k, &e) != 0) {
        fprintf(k.log, "bentray kiosk: %s%s%s\n", ERROR_TEXT(&e));
        free_scenes(&k);
        return KIOSK_BAD_CONFIG;
    }
    int headless = c->display.backend == KIOSK_BACKEND_HEADLESS;
    if (headless && headless_preflight(&k, &e) != 0) {
        fprintf(k.log, "bentray kiosk: %s%s%s\n", ERROR_TEXT(&e));
        free_scenes(&k);
        return KIOSK_BAD_CONFIG;
    }
    catch_stop_signals();
    k.screen = open_screen(&k, &e);
    if (!k.screen) {
        fprintf(k.log, "bentray kiosk: no screen: %s%s%s\n", ERROR_TEXT(&e));
        free_scenes(&k);
        return stop_requested ? KIOSK_STOPPED : KIOSK_FAILED;
    }
    k.virtual_clock = strcmp(k.screen->name, "headless") == 0;
    if (k.virtual_clock && !headless && headless_preflight(&k, &e) != 0) {
        fprintf(k.log, "bentray kiosk: %s%s%s\n", ERROR_TEXT(&e));
        kiosk_close(&k);
        return KIOSK_BAD_CONFIG;
    }
    fprintf(k.log, "bentray kiosk: %s screen %dx%d (%s), frames %dx%d, previews %dx%d\n", k.screen->name,
            k.screen->width, k.screen->height, k.screen->gl->platform_version, c->kiosk.width, c->kiosk.height,
            c->kiosk.preview_width, c->kiosk.preview_height);
    if (k.screen->note[0])
        fprintf(k.log, "bentray kiosk: %s\n", k.screen->note);
    k.screen->log = k.log;
    enum kiosk_status rc = KIOSK_STOPPED;
    if (kiosk_view_init(&k.view, c, k.screen->gl, &e) != 0) {
        fprintf(k.log, "bentray kiosk: %s%s%s\n", ERROR_TEXT(&e));
        kiosk_close(&k);
        return KIOSK_FAILED;
    }
    k.have_view = 1;
    if (open_hud(&k) != 0) {
        fprintf(k.log, "bentray kiosk: out of memory for the HUD\n");
        kiosk_close(&k);
        return KIOSK_FAILED;
    }
    /* the scenes this GPU cannot draw left out, then the programs, then each scene's preview size
     * for the preview rate (a display's only: the headless screen's runs are the same on any
     * machine) */
    int given = c->kiosk.n_scenes;
    int none = refuse_scenes(&k) == 0;
    int failed = !none && compile_ahead(&k, &e) != 0;
    none = none || (!failed && c->kiosk.n_scenes == 0);
    if (none) {
        fprintf(k.log, "bentray kiosk: this GPU (%s) can draw none of the %d scenes; stopped (exit %d: the service "
                "does not start it again)\n", gpu_name(), given, KIOSK_NO_SCENE);
        kiosk_close(&k);
        return KIOSK_NO_SCENE;
    }
    if (failed ||
        (!k.virtual_clock && !stop_requested && kiosk_tune_previews(&k.view, c, k.scenes, between_warm_states, NULL, k.log, &e) != 0)) {
        fprintf(k.log, "bentray kiosk: %s%s%s\n", ERROR_TEXT(&e));
        kiosk_close(&k);
        return KIOSK_FAILED;
    }
    k.now = kiosk_now(&k);
    k.last_input = k.now;
    k.second_start = k.now;
    for (int i = 0; i < c->n_inputs; i++) {
        k.inputs[i] = input_open(&c->inputs[i], i, k.log, k.now);
        if (!k.inputs[i])
            fprintf(k.log, "input %s: out of memory; left out\n", c->inputs[i].name);
    }
    /* the first turn loads the start scene into the view (none is loaded yet) and draws it */
    kiosk_state_reset(&k.state, c);
    for (;;) {
        int r = kiosk_turn(&k, &e);
        if (r < 0) {
            fprintf(k.log, "bentray kiosk: %s%s%s\n", ERROR_TEXT(&e));
            rc = KIOSK_FAILED;
            break;
        }
        if (r == 0)
            break;
    }
    service_stopping();
    fprintf(k.log, "bentray kiosk: stopped after %lld turns of the loop, %lld frames drawn, %ld shader programs "
            "compiled%s\n", k.turn, k.drawn, k.view.programs_ready ? k.view.programs.built - k.compiled_ahead : 0L,
            stop_requested ? " (signal)" : "");
    kiosk_close(&k);
    return rc;
}

int kiosk_check_inputs(const struct kiosk_config *c, FILE *out, FILE *log)
{
    struct input_source *inputs[KIOSK_MAX_INPUTS] = {0};
    catch_stop_signals();
    double now = clock_seconds();
    for (int i = 0; i < c->n_inputs; i++) {
        inputs[i] = input_open(&c->inputs[i], i, log, now);
        if (inputs[i] && inputs[i]->present)
            fprintf(out, "input %s (%s): ready\n", c->inputs[i].name, kiosk_input_type_name(c->inputs[i].type));
    }
    fflush(out);
    int rc = 0;
    while (!stop_requested) {
        now = clock_seconds();
        struct input_event ev[KIOSK_MAX_EVENTS];
        int n = 0, open = 0, quit = 0;
        struct pollfd fds[KIOSK_MAX_INPUTS * INPUT_MAX_FDS];
        int nfds = 0;
        for (int i = 0; i < c->n_inputs; i++) {
            if (!inputs[i])
                continue;
            n += inputs[i]->drain(inputs[i], now, ev + n, KIOSK_MAX_EVENTS - n);
            open += !inputs[i]->finished;
            nfds += inputs[i]->fds(inputs[i], fds + nfds, INPUT_MAX_FDS);
        }
        for (int i = 0; i < n; i++) {
            char line[256];
            kiosk_event_describe(c, &ev[i], line, sizeof line);
            fprintf(out, "%s\n", line);
            quit |= ev[i].kind == INPUT_QUIT;
        }
        fflush(out);
        if (quit || open == 0)
            break;
        poll(fds, (nfds_t)nfds, (int)(KIOSK_IDLE_WAIT_SECONDS * 1000.0));
    }
    for (int i = 0; i < c->n_inputs; i++)
        input_close(inputs[i]);
    return rc;
}
