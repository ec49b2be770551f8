/* The kiosk's inputs behind one interface: every device (PowerMate, HID, GPIO encoder or button,
 * keyboard, script) is an input_source that the loop polls and drains each frame. A source whose
 * device is absent or fails says so once in the log and keeps trying to come back (every
 * INPUT_RETRY_SECONDS); the kiosk carries on with the others. */
#ifndef BT_KIOSK_INPUT_H
#define BT_KIOSK_INPUT_H
#include <poll.h>
#include <stdio.h>
#include "input/input_settings.h"

#define INPUT_RETRY_SECONDS 1.5      /* re-enumerate an absent device this often */
#define INPUT_MAX_FDS 4              /* descriptors one source asks to be polled */

enum input_event_kind {
    INPUT_TURN,                      /* a knob device turned: counts, signed, clockwise > 0 */
    INPUT_POSITION,                  /* an absolute knob moved: position in [0, 1] */
    INPUT_PRESS,                     /* a button went down: bit (hid), -1 for single buttons */
    INPUT_RELEASE,                   /* a button came up (for --check-inputs; the loop ignores it) */
    INPUT_KNOB,                      /* keyboard, script: a knob by name (knob), counts */
    INPUT_ACTION,                    /* keyboard, script: an action directly (action) */
    INPUT_FRAME,                     /* script: write the frame shown now (headless) */
    INPUT_QUIT,                      /* keyboard 'q', a closed window: stop */
};

enum input_knob { INPUT_KNOB_SPEED, INPUT_KNOB_MASS };

struct input_event {
    double t;                        /* s, on the loop's clock (clock_seconds) */
    enum input_event_kind kind;
    int source;                      /* index of the [input NAME] in the configuration */
    long counts;                     /* INPUT_TURN, INPUT_KNOB */
    double position;                 /* INPUT_POSITION */
    int bit;                         /* INPUT_PRESS / INPUT_RELEASE of an hid input; -1 otherwise */
    enum input_knob knob;            /* INPUT_KNOB */
    enum kiosk_action action;        /* INPUT_ACTION */
};

struct input_source {
    const struct kiosk_input *cfg;
    int index;                       /* in the configuration's inputs */
    FILE *log;                       /* one line per state change of the device */
    int present;                     /* the device is open and delivering */
    int finished;                    /* will never deliver again (a script played out, input ended) */
    /* Descriptors to poll now (none while absent); returns how many were written. */
    int (*fds)(struct input_source *src, struct pollfd *out, int max);
    /* Everything the device has ready, decoded, without blocking; returns how many events were
     * written (at most max; what does not fit stays queued for the next call). now: the loop's
     * clock, for timestamps of devices without their own and for debounce timeouts. Also the
     * place where an absent device is looked for again, at most every INPUT_RETRY_SECONDS. */
    int (*drain)(struct input_source *src, double now, struct input_event *out, int max);
    void (*close)(struct input_source *src);
    void *priv;
};

/* The source for one configured input: never NULL for a valid configuration (a device that is
 * missing gives a source that is not present and retries), NULL only when out of memory. */
struct input_source *input_open(const struct kiosk_input *in, int index, FILE *log, double now);
void input_close(struct input_source *src);

/* The constructors behind input_open, one per family (input_hid.c, input_gpio.c,
 * input_keyboard.c, input_script.c). */
struct input_source *input_open_hid(const struct kiosk_input *in, int index, FILE *log, double now);
struct input_source *input_open_gpio(const struct kiosk_input *in, int index, FILE *log, double now);
struct input_source *input_open_keyboard(const struct kiosk_input *in, int index, FILE *log, double now);
struct input_source *input_open_script(const struct kiosk_input *in, int index, FILE *log, double now);

/* A source for input `index` with its family's callbacks and priv_size zeroed bytes of the
 * family's own state at src->priv (which its close frees); NULL when out of memory. */
struct input_source *input_source_new(const struct kiosk_input *in, int index, FILE *log, size_t priv_size,
                                      int (*fds)(struct input_source *src, struct pollfd *out, int max),
                                      int (*drain)(struct input_source *src, double now,
                                                   struct input_event *out, int max),
                                      void (*close)(struct input_source *src));

/* An event of `kind` from source `source` at loop time t, every other field zero and bit -1 (no
 * button bit): the kind's own field is the caller's to set. */
struct input_event input_event_at(enum input_event_kind kind, int source, double t);

/* The loop's clock: CLOCK_MONOTONIC in seconds. */

#endif
