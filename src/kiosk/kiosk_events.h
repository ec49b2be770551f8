/* What one input event does to the visitor's state, through the configuration's mappings: a
 * device's turn moves the knob it is wired to, a press triggers the button's action. Pure. */
#ifndef BT_KIOSK_EVENTS_H
#define BT_KIOSK_EVENTS_H
#include "kiosk/hud.h"
#include "input/input.h"
#include "kiosk/kiosk_state.h"

struct event_outcome {
    int changed;                     /* the state is different */
    int visitor;                     /* a person (or a script acting as one) did something */
    int quit;                        /* stop the kiosk */
    int frame;                       /* a script asks for the frame shown now */
    enum hud_knob knob;              /* the knob that moved, for the HUD's indicator */
};

/* Applies ev to st (scene: the scene shown, for what its effects allow). */
void kiosk_event_apply(const struct kiosk_config *c, struct kiosk_state *st, const struct scene *scene,
                       const struct input_event *ev, struct event_outcome *out);
/* One line describing the event, for --check-inputs and the log. */
void kiosk_event_describe(const struct kiosk_config *c, const struct input_event *ev, char *line, size_t len);

#endif
