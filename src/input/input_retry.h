/* When an absent device is looked for again, and what the log says about it. An unattended kiosk
 * whose knob was unplugged must neither fill its log with the same complaint every frame nor spend
 * its frames enumerating USB: each absence is said once, and the device is looked for at most
 * every INPUT_RETRY_SECONDS until it is back, which is said once too. */
#ifndef BT_KIOSK_INPUT_RETRY_H
#define BT_KIOSK_INPUT_RETRY_H
#include "input/input.h"

/* Why a device cannot be used. A change of reason while it stays absent is news worth a line
 * (it was plugged in, but cannot be opened); the same reason again is not. */
enum input_absence {
    INPUT_ABSENT_GONE,               /* not there: not found, or disconnected */
    INPUT_ABSENT_REFUSED,            /* there, but could not be opened (permissions, in use) */
};

struct input_retry {
    double last_try;                 /* s, loop clock: when the device was last looked for */
    int logged;                      /* the absence going on has its line in the log */
    enum input_absence logged_reason;
};

/* A schedule whose last look was at `now`: the next is due INPUT_RETRY_SECONDS later. */
void input_retry_init(struct input_retry *r, double now);

/* Whether the device may be looked for at `now`: INPUT_RETRY_SECONDS after the last look, or at
 * once when `now` lies before it (a clock that started again; waiting for the old time could take
 * forever). Pure: nothing is recorded. */
int input_retry_due(const struct input_retry *r, double now);

/* input_retry_due(), and when it says yes, `now` recorded as the last look. */
int input_retry_take(struct input_retry *r, double now);

/* The device is absent for `reason`: one line "input NAME: <what>; looking for it every 1.5 s"
 * (or "trying again" for a refusal) in src->log, unless this absence, for this reason, is already
 * there. */
void input_retry_absent(struct input_retry *r, const struct input_source *src, enum input_absence reason,
                        const char *fmt, ...) __attribute__((format(printf, 4, 5)));

/* The device is back (or there from the start): one line "input NAME: <what>", and the next
 * absence will be said again. */
void input_retry_present(struct input_retry *r, const struct input_source *src, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#endif
