/* The keyboard's fixed mapping. */
#include "input/keymap.h"
#include <string.h>

const char *const keymap_help =
    "keys: Up/Down or w/s speed, Right/Left or d/a mass, n/p next/previous scene, e effects,\n"
    "      r reset, v pipeline view, i staff mode, q or Escape stop\n";

static void knob(struct input_event *ev, enum input_knob k, long counts)
{
    ev->kind = INPUT_KNOB;
    ev->knob = k;
    ev->counts = counts;
}

static void action(struct input_event *ev, enum kiosk_action a)
{
    ev->kind = INPUT_ACTION;
    ev->action = a;
}

int keymap_event(enum key_code code, int ch, struct input_event *ev)
{
    memset(ev, 0, sizeof *ev);
    ev->bit = -1;
    switch (code) {
    case KEY_CODE_UP: knob(ev, INPUT_KNOB_SPEED, 1); return 1;
    case KEY_CODE_DOWN: knob(ev, INPUT_KNOB_SPEED, -1); return 1;
    case KEY_CODE_RIGHT: knob(ev, INPUT_KNOB_MASS, 1); return 1;
    case KEY_CODE_LEFT: knob(ev, INPUT_KNOB_MASS, -1); return 1;
    case KEY_CODE_ESCAPE: ev->kind = INPUT_QUIT; return 1;
    case KEY_CODE_CHAR: break;
    }
    switch (ch) {
    case 'w': knob(ev, INPUT_KNOB_SPEED, 1); return 1;
    case 's': knob(ev, INPUT_KNOB_SPEED, -1); return 1;
    case 'd': knob(ev, INPUT_KNOB_MASS, 1); return 1;
    case 'a': knob(ev, INPUT_KNOB_MASS, -1); return 1;
    case 'n': action(ev, KIOSK_ACTION_NEXT_SCENE); return 1;
    case 'p': action(ev, KIOSK_ACTION_PREVIOUS_SCENE); return 1;
    case 'e': action(ev, KIOSK_ACTION_CYCLE_EFFECTS); return 1;
    case 'r': action(ev, KIOSK_ACTION_RESET); return 1;
    case 'v': action(ev, KIOSK_ACTION_PIPELINE_VIEW); return 1;
    case 'i': action(ev, KIOSK_ACTION_STAFF_MODE); return 1;
    case 'q': ev->kind = INPUT_QUIT; return 1;
    default: return 0;
    }
}
