/* Input events to state changes, by the configuration's mappings. */
#include "kiosk/kiosk_events.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

static const char *source_name(const struct kiosk_config *c, int source)
{
    return source >= 0 && source < c->n_inputs ? c->inputs[source].name : "";
}

/* The knob's mapping in this scene ([kiosk] of the scene file), NULL where it keeps its meaning. */
static const struct knob_mapping *mapping(const struct scene *scene, enum input_knob knob)
{
    if (!scene)
        return NULL;
    const struct knob_mapping *m = knob == INPUT_KNOB_SPEED ? &scene->kiosk.speed : &scene->kiosk.mass;
    return m->key[0] ? m : NULL;
}

static void turn(const struct kiosk_config *c, struct kiosk_state *st, const struct scene *scene,
                 enum input_knob knob, long counts, struct event_outcome *out)
{
    const struct knob_mapping *m = mapping(scene, knob);
    double *value = m ? (knob == INPUT_KNOB_SPEED ? &st->speed_param : &st->mass_param)
                      : (knob == INPUT_KNOB_SPEED ? &st->speed : &st->mass);
    double was = *value;
    *value = m ? knob_turn_mapped(m, scene, *value, counts)
               : knob_turn(knob == INPUT_KNOB_SPEED ? &c->speed : &c->mass, *value, counts);
    out->changed = !(*value == was);
    out->knob = knob == INPUT_KNOB_SPEED ? HUD_KNOB_SPEED : HUD_KNOB_MASS;
}

static void position(const struct kiosk_config *c, struct kiosk_state *st, const struct scene *scene,
                     enum input_knob knob, double p, struct event_outcome *out)
{
    const struct knob_mapping *m = mapping(scene, knob);
    double *value = m ? (knob == INPUT_KNOB_SPEED ? &st->speed_param : &st->mass_param)
                      : (knob == INPUT_KNOB_SPEED ? &st->speed : &st->mass);
    double was = *value;
    p = p < 0.0 ? 0.0 : p > 1.0 ? 1.0 : p;
    *value = m ? m->min + p * (m->max - m->min) : knob_position(knob == INPUT_KNOB_SPEED ? &c->speed : &c->mass, p);
    out->changed = !(*value == was);
    out->knob = knob == INPUT_KNOB_SPEED ? HUD_KNOB_SPEED : HUD_KNOB_MASS;
}

static void action(const struct kiosk_config *c, struct kiosk_state *st, const struct scene *scene,
                   enum kiosk_action a, struct event_outcome *out)
{
    struct kiosk_state was = *st;
    kiosk_state_action(st, c, scene, a);
    out->changed = !kiosk_state_same(&was, st);
}

/* The knob a device turns, by the names in [speed] and [mass]; -1 for none. */
static int knob_of(const struct kiosk_config *c, int source)
{
    const char *name = source_name(c, source);
    if (!*name)
        return -1;
    if (strcmp(c->speed.input, name) == 0)
        return INPUT_KNOB_SPEED;
    if (strcmp(c->mass.input, name) == 0)
        return INPUT_KNOB_MASS;
    return -1;
}

void kiosk_event_apply(const struct kiosk_config *c, struct kiosk_state *st, const struct scene *scene,
                       const struct input_event *ev, struct event_outcome *out)
{
    memset(out, 0, sizeof *out);
    switch (ev->kind) {
    case INPUT_TURN:
    case INPUT_POSITION: {
        int knob = knob_of(c, ev->source);
        if (knob < 0)
            return;
        out->visitor = 1;
        if (ev->kind == INPUT_TURN)
            turn(c, st, scene, (enum input_knob)knob, ev->counts, out);
        else
            position(c, st, scene, (enum input_knob)knob, ev->position, out);
        return;
    }
    case INPUT_PRESS: {
        const char *name = source_name(c, ev->source);
        for (int b = 0; b < c->n_buttons; b++) {
            const struct kiosk_button *btn = &c->buttons[b];
            if (strcmp(btn->input, name) == 0 && (btn->bit < 0 || btn->bit == ev->bit)) {
                out->visitor = 1;
                action(c, st, scene, btn->action, out);
                return;
            }
        }
        return;
    }
    case INPUT_KNOB:
        out->visitor = 1;
        turn(c, st, scene, ev->knob, ev->counts, out);
        return;
    case INPUT_ACTION:
        out->visitor = 1;
        action(c, st, scene, ev->action, out);
        return;
    case INPUT_FRAME:
        out->frame = 1;
        return;
    case INPUT_QUIT:
        out->quit = 1;
        return;
    case INPUT_RELEASE:
        return;
    }
}

void kiosk_event_describe(const struct kiosk_config *c, const struct input_event *ev, char *line, size_t len)
{
    const char *name = ev->source >= 0 ? source_name(c, ev->source) : "screen";
    static const char *const knobs[] = {"speed", "mass"};
    switch (ev->kind) {
    case INPUT_TURN:
        snprintf(line, len, "%.3f input %s: turn %+ld", ev->t, name, ev->counts);
        break;
    case INPUT_POSITION:
        snprintf(line, len, "%.3f input %s: position %.4f", ev->t, name, ev->position);
        break;
    case INPUT_PRESS:
    case INPUT_RELEASE:
        if (ev->bit >= 0)
            snprintf(line, len, "%.3f input %s: button bit %d %s", ev->t, name, ev->bit,
                     ev->kind == INPUT_PRESS ? "pressed" : "released");
        else
            snprintf(line, len, "%.3f input %s: button %s", ev->t, name,
                     ev->kind == INPUT_PRESS ? "pressed" : "released");
        break;
    case INPUT_KNOB:
        snprintf(line, len, "%.3f input %s: turn %s %+ld", ev->t, name, knobs[ev->knob], ev->counts);
        break;
    case INPUT_ACTION:
        snprintf(line, len, "%.3f input %s: press %s", ev->t, name, kiosk_action_name(ev->action));
        break;
    case INPUT_FRAME:
        snprintf(line, len, "%.3f input %s: frame", ev->t, name);
        break;
    case INPUT_QUIT:
        snprintf(line, len, "%.3f input %s: stop", ev->t, name);
        break;
    }
}
