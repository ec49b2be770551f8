/* Replaying a script against the loop's clock. */
#include "input/script_player.h"
#include <math.h>
#include <string.h>

/* A tour that ends with its last event would restart at once; this pause closes the loop. */
#define SCRIPT_LOOP_PAUSE_SECONDS 2.0

void script_player_start(struct script_player *p, const struct script *sc, double now, int loop)
{
    p->script = sc;
    p->start = now;
    p->next = 0;
    p->loop = loop;
    p->wraps = 0;
}

static void to_input(const struct script_event *se, double t, int source, struct input_event *ev)
{
    memset(ev, 0, sizeof *ev);
    ev->t = t;
    ev->source = source;
    ev->bit = -1;
    switch (se->kind) {
    case SCRIPT_TURN:
        ev->kind = INPUT_KNOB;
        ev->knob = se->knob == SCRIPT_KNOB_SPEED ? INPUT_KNOB_SPEED : INPUT_KNOB_MASS;
        ev->counts = se->counts;
        break;
    case SCRIPT_PRESS:
        ev->kind = INPUT_ACTION;
        ev->action = se->action;
        break;
    case SCRIPT_FRAME:
        ev->kind = INPUT_FRAME;
        break;
    }
}

int script_player_due(struct script_player *p, double now, int source, struct input_event *out, int max)
{
    const struct script *sc = p->script;
    int n = 0;
    while (n < max && sc && sc->n > 0) {
        if (p->next == sc->n) {
            if (!p->loop || n > 0)
                break;
            double length = sc->events[sc->n - 1].t + SCRIPT_LOOP_PAUSE_SECONDS;
            if (now < p->start + length)
                break;
            p->start += length * floor((now - p->start) / length);
            p->next = 0;
            p->wraps++;
        }
        const struct script_event *se = &sc->events[p->next];
        if (p->start + se->t > now)
            break;
        to_input(se, p->start + se->t, source, &out[n++]);
        p->next++;
    }
    return n;
}

int script_player_done(const struct script_player *p)
{
    return !p->loop && (!p->script || p->next >= p->script->n);
}
