/* Scripted input: a file of timestamped events that the kiosk replays as if a visitor made them
 * (tests, the attract mode's tour). One event per line, times in seconds from the script's start,
 * never decreasing; '#' or ';' starts a comment line:
 *     0.5  turn speed +3        knob counts (detents), signed
 *     1.0  turn mass -2
 *     2.0  press next_scene     an action: next_scene, previous_scene, cycle_effects, reset,
 *                               pipeline_view
 *     2.5  frame                headless: write the frame shown now
 * Refused with FILE:LINE: unknown words, a time that goes back, NaN, negative times or times beyond
 * SCRIPT_MAX_SECONDS, counts beyond +-1000 in one event, more than SCRIPT_MAX_EVENTS events,
 * trailing text. Any file that is not a regular file (a FIFO) is refused at once. */
#ifndef BT_SCRIPT_H
#define BT_SCRIPT_H
#include <stddef.h>
#include "io/error.h"
#include "input/input_settings.h"

#define SCRIPT_MAX_EVENTS 4096
#define SCRIPT_MAX_BYTES (4L << 20)   /* a script file: events and comments */
#define SCRIPT_MAX_COUNTS 1000       /* detents in one event: more is a typo */
#define SCRIPT_MAX_SECONDS 86400.0   /* an event's time: a day; later is a typo the kiosk would wait for */

enum script_kind { SCRIPT_TURN, SCRIPT_PRESS, SCRIPT_FRAME };
enum script_knob { SCRIPT_KNOB_SPEED, SCRIPT_KNOB_MASS };

struct script_event {
    double t;                        /* s from the start */
    enum script_kind kind;
    enum script_knob knob;           /* SCRIPT_TURN */
    long counts;                     /* SCRIPT_TURN */
    enum kiosk_action action;        /* SCRIPT_PRESS */
    int line;                        /* in the file, for messages */
};

struct script {
    struct script_event events[SCRIPT_MAX_EVENTS];
    int n;
};

/* 0, or -1 with e: where "FILE:LINE" and what is wrong (ERROR_INPUT), or where FILE alone when the
 * file cannot be read (error_status_of_errno: a missing or refused file, a FIFO or one too large
 * is the user's, no memory or an I/O error the machine's). */
int script_load(struct script *sc, const char *path, struct error *e);

#endif
