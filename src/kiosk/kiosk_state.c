/* The visitor's settings and how they make the scene that is drawn. */
#include "kiosk/kiosk_state.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

static double clamp(double x, double lo, double hi)
{
    return x < lo ? lo : x > hi ? hi : x;
}

/* A knob's value is a sum of detents, whose roundings can leave 1e-17 where a visitor turned back
 * to 0 (0.12 - 12 x 0.01): within KNOB_SETTLE of the range it settles on an end of the range or on
 * 0, values the scene and the HUD treat as such (a mass of 0 is flat space, "M = 0"). */
#define KNOB_SETTLE 1e-9

static double knob_settle(double x, double lo, double hi)
{
    double near = KNOB_SETTLE * (hi - lo);
    x = clamp(x, lo, hi);
    if (fabs(x - lo) <= near)
        return lo;
    if (fabs(x - hi) <= near)
        return hi;
    return lo < 0.0 && hi > 0.0 && fabs(x) <= near ? 0.0 : x;
}

double knob_turn(const struct kiosk_knob *k, double value, long counts)
{
    double v;
    switch (k->curve) {
    case KIOSK_CURVE_RAPIDITY:
        /* equal turns give equal boosts: rapidities add, speeds do not */
        v = tanh(atanh(clamp(value, -KIOSK_SPEED_MAX, KIOSK_SPEED_MAX)) + k->step * (double)counts);
        break;
    case KIOSK_CURVE_LOG: {
        double from = value > 0.0 ? value : k->min > 0.0 ? k->min : exp(k->step) * 1e-3;
        v = counts == 0 ? value : from * exp(k->step * (double)counts);
        break;
    }
    default:
        v = value + k->step * (double)counts;
        break;
    }
    return knob_settle(v, k->min, k->max);
}

double knob_position(const struct kiosk_knob *k, double p)
{
    p = clamp(p, 0.0, 1.0);
    switch (k->curve) {
    case KIOSK_CURVE_RAPIDITY:
        return tanh(atanh(k->min) + p * (atanh(k->max) - atanh(k->min)));
    case KIOSK_CURVE_LOG:
        return k->min * exp(p * log(k->max / k->min));
    default:
        return k->min + p * (k->max - k->min);
    }
}

double knob_turn_mapped(const struct knob_mapping *m, const struct scene *scene, double param, long counts)
{
    double value = param;
    if (isnan(value) && scene_get_number(scene, m->key, &value) != 0)
        value = m->min;
    return knob_settle(value + (m->max - m->min) * (double)counts / m->steps, m->min, m->max);
}

/* Field by field: padding is not part of a state, and a NAN parameter (the scene's own value)
 * equals itself here. */
static int same_value(double a, double b)
{
    return a == b || (isnan(a) && isnan(b));
}

int kiosk_state_same(const struct kiosk_state *a, const struct kiosk_state *b)
{
    return a->scene == b->scene && a->speed == b->speed && a->mass == b->mass &&
           same_value(a->speed_param, b->speed_param) && same_value(a->mass_param, b->mass_param) &&
           a->effects == b->effects && a->gravitational_shift == b->gravitational_shift &&
           a->effects_from_scene == b->effects_from_scene &&
           a->pipeline_view == b->pipeline_view;
}

void kiosk_state_reset(struct kiosk_state *st, const struct kiosk_config *c)
{
    memset(st, 0, sizeof *st);
    st->scene = c->kiosk.start_scene;
    st->speed = c->speed.start;
    st->mass = c->mass.start;
    st->speed_param = st->mass_param = NAN;
    st->effects = EFFECTS_GEOMETRY;
    st->gravitational_shift = 1;
    st->effects_from_scene = 1;
}

enum relativity_effects kiosk_state_effects(const struct kiosk_state *st, const struct scene *base)
{
    return st->effects_from_scene ? base->observer.effects : st->effects;
}

int kiosk_state_gravitational_shift(const struct kiosk_state *st, const struct scene *base)
{
    return st->effects_from_scene ? base->observer.gravitational_shift : st->gravitational_shift;
}

/* The layer after those shown (kiosk_state_action): each adds one to the light's shift. */
static void next_effects(struct kiosk_state *st, const struct scene *scene)
{
    enum relativity_effects shown = kiosk_state_effects(st, scene);
    int gravity = kiosk_state_gravitational_shift(st, scene);
    int has_mass = model_ops_of(scene->model.type)->has_mass;
    st->effects_from_scene = 0;
    if (!scene_has_black_body(scene) || (shown == EFFECTS_SEARCHLIGHT && (gravity || !has_mass))) {
        st->effects = EFFECTS_GEOMETRY;
        st->gravitational_shift = 1;
    } else if (shown == EFFECTS_GEOMETRY) {
        /* motion's shift alone first where there is a mass to add its own later */
        st->effects = EFFECTS_DOPPLER;
        st->gravitational_shift = !has_mass;
    } else {
        st->effects = EFFECTS_SEARCHLIGHT;
        st->gravitational_shift = shown == EFFECTS_SEARCHLIGHT ? 1 : gravity;
    }
}

void kiosk_state_action(struct kiosk_state *st, const struct kiosk_config *c, const struct scene *scene,
                        enum kiosk_action action)
{
    int n = c->kiosk.n_scenes;
    switch (action) {
    case KIOSK_ACTION_NEXT_SCENE:
    case KIOSK_ACTION_PREVIOUS_SCENE:
        /* the knobs keep speed and mass from scene to scene; a mapped key starts at the new scene's own */
        st->scene = (st->scene + (action == KIOSK_ACTION_NEXT_SCENE ? 1 : n - 1)) % n;
        st->effects = EFFECTS_GEOMETRY;
        st->gravitational_shift = 1;
        st->effects_from_scene = 1;        /* the new scene's own, as its file sets them */
        st->speed_param = st->mass_param = NAN;
        break;
    case KIOSK_ACTION_CYCLE_EFFECTS:
        next_effects(st, scene);
        break;
    case KIOSK_ACTION_RESET:
        kiosk_state_reset(st, c);
        break;
    case KIOSK_ACTION_PIPELINE_VIEW:
        st->pipeline_view = !st->pipeline_view;
        break;
    case KIOSK_ACTION_STAFF_MODE:
        st->staff = !st->staff;
        break;
    default:
        break;
    }
}

int kiosk_state_apply(const struct kiosk_state *st, const struct scene *base, struct scene *out,
                      struct error *err)
{
    *out = *base;
    vec3d view = v3_normalize(v3_sub(base->camera.look_at, base->camera.position));
    const struct knob_mapping *ms = &base->kiosk.speed, *mm = &base->kiosk.mass;
    if (!ms->key[0])
        out->observer.velocity = v3_scale(view, st->speed);
    out->observer.effects = kiosk_state_effects(st, base);
    out->observer.gravitational_shift = kiosk_state_gravitational_shift(st, base);
    if (!mm->key[0] && model_ops_of(out->model.type)->has_mass)
        out->model.mass = st->mass;
    const struct knob_mapping *maps[2] = {ms, mm};
    const double params[2] = {st->speed_param, st->mass_param};
    for (int i = 0; i < 2; i++) {
        if (!maps[i]->key[0] || isnan(params[i]))
            continue;
        if (scene_set_number(out, maps[i]->key, params[i], err) != 0)
            return -1;
    }
    return scene_validate(out, err);
}
