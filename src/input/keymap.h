/* The keyboard's fixed mapping (service and development), the same for a terminal and for an X11
 * window:
 *     Up / Down or w / s      speed knob +1 / -1 detent
 *     Right / Left or d / a   mass knob +1 / -1 detent
 *     n / p                   next / previous scene
 *     e                       cycle effects
 *     r                       reset
 *     v                       pipeline view
 *     q / Escape              stop the kiosk */
#ifndef BT_KIOSK_KEYMAP_H
#define BT_KIOSK_KEYMAP_H
#include "input/input.h"

enum key_code { KEY_CODE_CHAR, KEY_CODE_UP, KEY_CODE_DOWN, KEY_CODE_LEFT, KEY_CODE_RIGHT, KEY_CODE_ESCAPE };

/* The event of one key press (code, and ch for KEY_CODE_CHAR); 0 for an unmapped key, 1 with *ev
 * filled (its t and source set by the caller). */
int keymap_event(enum key_code code, int ch, struct input_event *ev);
/* One line per key, for --help and the log. */
extern const char *const keymap_help;

#endif
