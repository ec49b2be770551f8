/* The orbit tables a visitor's next turns will ask for, built while the exhibit shows this one: a
 * mass detent then costs an upload, not a table (render/orbit_store.h). */
#include "kiosk/kiosk_view.h"
#include "kiosk/kiosk_events.h"
#include "physics/orbit_table.h"
#include "render/orbit_store.h"
#include <math.h>

/* Appends p unless the list has it; 1 when added. */
static int add_unique(struct orbit_table_params *list, int *n, const struct orbit_table_params *p)
{
    for (int i = 0; i < *n; i++)
        if (orbit_params_same(&list[i], p))
            return 0;
    list[(*n)++] = *p;
    return 1;
}

/* The state counts detents from st on one knob; 0 where the knob's end stops it short. */
static int turned(const struct kiosk_view *v, const struct kiosk_state *st, enum input_knob knob, long counts,
                  struct kiosk_state *out)
{
    *out = *st;
    struct input_event ev = {.kind = INPUT_KNOB, .knob = knob, .counts = counts, .bit = -1};
    struct event_outcome o = {0};
    kiosk_event_apply(v->cfg, out, &v->base, &ev, &o);
    if (!o.changed)
        return 0;
    /* one detent less must differ too, else the end was reached before */
    struct kiosk_state shorter = *st;
    ev.counts = counts > 0 ? counts - 1 : counts + 1;
    if (ev.counts != 0) {
        kiosk_event_apply(v->cfg, &shorter, &v->base, &ev, &o);
        if (shorter.mass == out->mass && shorter.speed == out->speed && shorter.mass_param == out->mass_param &&
            shorter.speed_param == out->speed_param)
            return 0;
    }
    return 1;
}

int kiosk_view_prefetch(struct kiosk_view *v, const struct kiosk_state *st, struct error *e)
{
    if (v->prefetch_off || !scene_on_exact_orbits(&v->full))
        return 0;
    struct orbit_table_params now;
    orbit_table_params_for(&v->full, &now);
    if (v->prefetched && orbit_params_same(&now, &v->prefetched_for))
        return 0;
    struct scene *full = scene_new(e), *preview = scene_new(e);
    if (!full || !preview) {
        scene_free(full);
        scene_free(preview);
        return -1;
    }
    /* the refined table of this state first (the refinement asks for it as soon as the knob rests),
     * then each knob's detents outwards, previews before the refined tables of the next detents */
    struct orbit_table_params list[2 * (2 * KIOSK_PREFETCH_DETENTS + 2) + 1];
    int n = 0;
    add_unique(list, &n, &now);
    struct orbit_table_params refined_next[8];
    int n_refined = 0;
    for (int d = 1; d <= KIOSK_PREFETCH_DETENTS; d++)
        for (int knob = INPUT_KNOB_SPEED; knob <= INPUT_KNOB_MASS; knob++)
            for (int sign = -1; sign <= 1; sign += 2) {
                struct kiosk_state next;
                struct error ignored;
                if (!turned(v, st, (enum input_knob)knob, sign * d, &next) ||
                    kiosk_state_apply(&next, &v->base, full, &ignored) != 0 || !scene_on_exact_orbits(full))
                    continue;
                struct orbit_table_params p;
                kiosk_preview_scene(full, v->preview_width, v->preview_height, preview);
                orbit_table_params_for(preview, &p);
                add_unique(list, &n, &p);
                if (d == 1) {
                    orbit_table_params_for(full, &p);
                    add_unique(refined_next, &n_refined, &p);
                }
            }
    /* previews of every detent the window holds come first: a turning knob needs them at once */
    for (int i = 0; i < n_refined; i++)
        add_unique(list, &n, &refined_next[i]);
    scene_free(full);
    scene_free(preview);
    if (renderer_orbit_prefetch(v->renderer, list, n, e) != 0)
        return -1;
    v->prefetched = 1;
    v->prefetched_for = now;
    return 0;
}
