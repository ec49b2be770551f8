/* The kiosk's programs compiled before its first frame (kiosk_warm.h). */
#include "kiosk/kiosk_warm.h"
#include <stdlib.h>
#include <string.h>
#include "io/clock.h"
#include "kiosk/kiosk_events.h"

/* The states drawn per scene: each knob at rest (0), at its lower end (-1) and its upper end (+1),
 * in pairs, with the scene's own effects and after one, two and three presses of the button (a
 * moving observer's programs differ with the effects; the button's four layers around a mass hold
 * each of the three programs within three presses of any start, gravity's shift being a uniform),
 * then the pipeline view at rest. */
static const int knob_ends[][2] = {{0, 0}, {-1, 0}, {1, 0}, {0, -1}, {0, 1}, {-1, -1}, {-1, 1}, {1, -1}, {1, 1}};
#define KNOB_PAIRS (int)(sizeof knob_ends / sizeof knob_ends[0])
#define EFFECTS 4
#define WARM_STATES (KNOB_PAIRS * EFFECTS + 1)

static void turn_knob(const struct kiosk_config *c, struct kiosk_state *st, const struct scene *scene,
                      enum input_knob knob, int end)
{
    if (end == 0)
        return;
    struct input_event ev = {.kind = INPUT_KNOB, .source = -1, .bit = -1, .knob = knob,
                             .counts = end * KIOSK_WARM_DETENTS};
    struct event_outcome out;
    kiosk_event_apply(c, st, scene, &ev, &out);
}

static void press(const struct kiosk_config *c, struct kiosk_state *st, const struct scene *scene,
                  enum kiosk_action action)
{
    struct input_event ev = {.kind = INPUT_ACTION, .source = -1, .bit = -1, .action = action};
    struct event_outcome out;
    kiosk_event_apply(c, st, scene, &ev, &out);
}

/* State k of scene i (k < WARM_STATES). */
static void warm_state(const struct kiosk_config *c, const struct scene *scene, int i, int k, struct kiosk_state *st)
{
    kiosk_state_reset(st, c);
    st->scene = i;
    if (k == KNOB_PAIRS * EFFECTS) {
        press(c, st, scene, KIOSK_ACTION_PIPELINE_VIEW);
        return;
    }
    for (int n = 0; n < k / KNOB_PAIRS; n++)
        press(c, st, scene, KIOSK_ACTION_CYCLE_EFFECTS);
    turn_knob(c, st, scene, INPUT_KNOB_SPEED, knob_ends[k % KNOB_PAIRS][0]);
    turn_knob(c, st, scene, INPUT_KNOB_MASS, knob_ends[k % KNOB_PAIRS][1]);
}

/* What decides the programs a state draws with, for telling states apart: its effects as drawn,
 * whether the scene's own or chosen (gravity's shift is a uniform, the same programs either way). */
static struct kiosk_state programs_key(const struct kiosk_state *st, const struct scene *scene)
{
    struct kiosk_state key = *st;
    key.effects = kiosk_state_effects(st, scene);
    key.gravitational_shift = 1;
    key.effects_from_scene = 0;
    return key;
}

/* The preview of st and the first band of its refinement (the pipeline view is not refined). */
static int draw_state(struct kiosk_view *v, const struct kiosk_state *st, struct error *e)
{
    if (kiosk_view_preview(v, st, e) != 0)
        return -1;
    while (kiosk_view_preview_pending(v))
        if (kiosk_view_refine(v, e) != 0)
            return -1;
    return kiosk_view_refined(v) ? 0 : kiosk_view_refine(v, e);
}

/* Every state of every scene drawn in v (a view of warm_sizes' configuration). */
static int warm_scenes(struct kiosk_view *v, const struct kiosk_config *c, const struct scene *scenes,
                       int (*between)(void *arg), void *arg, struct kiosk_warm_report *out, struct error *e)
{
    struct scene *trial = scene_new(e);
    if (!trial)
        return -1;
    int stop = 0;
    for (int i = 0; i < c->kiosk.n_scenes && !stop; i++) {
        struct kiosk_state done[WARM_STATES];
        int n_done = 0;
        struct error why;
        error_clear(&why);
        int failed = kiosk_view_load(v, i, &scenes[i], &why) != 0;
        out->scenes += !failed;
        for (int k = 0; k < WARM_STATES && !failed; k++) {
            struct kiosk_state st;
            warm_state(c, &scenes[i], i, k, &st);
            struct kiosk_state key = programs_key(&st, &scenes[i]);
            int seen = 0;
            for (int j = 0; j < n_done && !seen; j++)
                seen = kiosk_state_same(&done[j], &key);
            if (seen)
                continue;
            done[n_done++] = key;
            if (between && between(arg)) {
                stop = 1;
                break;
            }
            struct error refusal;
            if (kiosk_state_apply(&st, &scenes[i], trial, &refusal) != 0) {
                out->refused++;
                continue;
            }
            failed = draw_state(v, &st, &why) != 0;
            out->states += !failed;
        }
        if (failed) {
            out->failed[i] = 1;
            error_format(&why, out->why[i], sizeof out->why[i]);
            kiosk_view_unload(v);
        }
    }
    scene_free(trial);
    return 0;
}

int kiosk_warm(struct kiosk_view *v, const struct kiosk_config *c, const struct scene *scenes,
               int (*between)(void *arg), void *arg, struct kiosk_warm_report *out, struct error *e)
{
    memset(out, 0, sizeof *out);
    double started = clock_seconds();
    kiosk_view_unload(v);
    if (v->programs_ready)
        return 0;                    /* compiled already */
    /* the programs follow from the scenes and states, never from the sizes (which make tiles and
     * bands only): a view of KIOSK_WARM_SIZE pixels compiles them as the screen's would */
    struct kiosk_config *small = malloc(sizeof *small);
    if (!small)
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory");
    *small = *c;
    small->kiosk.width = small->kiosk.height = KIOSK_WARM_SIZE;
    small->kiosk.preview_width = small->kiosk.preview_height = KIOSK_WARM_SIZE;
    struct kiosk_view *w = malloc(sizeof *w);
    int rc = w ? kiosk_view_init(w, small, v->gl, e) : error_set(e, ERROR_RUNTIME, NULL, "out of memory");
    if (rc == 0) {
        w->prefetch_off = 1;
        rc = warm_scenes(w, small, scenes, between, arg, out, e);
        kiosk_view_unload(w);
        /* the programs go to the screen's view, which has none yet */
        v->programs = w->programs;
        v->programs_ready = w->programs_ready;
        w->programs_ready = 0;
        kiosk_view_release(w);
    }
    free(w);
    free(small);
    out->programs = v->programs_ready ? v->programs.built : 0;
    out->seconds = clock_seconds() - started;
    return rc;
}
