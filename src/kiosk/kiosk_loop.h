/* The kiosk's loop: one poll() over every input and the screen; each turn drains every queue,
 * updates the visitor's state, draws a preview when it changed or the next refined band when it
 * did not, lays the HUD over it and presents it. Attract mode plays a tour after idle_seconds
 * without input. SIGTERM and SIGINT end the loop at the next turn (at most one frame). */
#ifndef BT_KIOSK_LOOP_H
#define BT_KIOSK_LOOP_H
#include <stdio.h>
#include "kiosk_config/kiosk_config.h"

/* The headless screen runs on a clock of its own that advances by one frame of this rate per
 * turn, so that a script gives the same frames on any machine, however slow. */
#define KIOSK_VIRTUAL_FPS 30.0
/* How long a knob's value and range stay on screen after a turn, s. */
#define KIOSK_INDICATOR_SECONDS 2.0
/* The longest a turn waits for input when there is nothing to draw, s: script events and the
 * watchdog are served at least this often. */
#define KIOSK_IDLE_WAIT_SECONDS 0.02
/* A turn of the loop at least this long is logged with what it did (a scene's load, a preview, a
 * band of refinement): input and the watchdog waited that long. */
#define KIOSK_SLOW_TURN_SECONDS 1.0

/* The start timeout asked for, before READY, for each state the warm-up draws (kiosk_warm.h):
 * a first compile of a large program by a Raspberry Pi's driver can take minutes, s. */
#define KIOSK_WARM_STATE_SECONDS 600.0

/* How often a KMS display without a connected monitor is looked at again, s. */
#define KIOSK_DISPLAY_RETRY_SECONDS 2.0

struct kiosk_run_options {
    const char *gl_backend;          /* headless: "egl", "osmesa" or "auto" */
    int force;                       /* headless: frames may replace files already there */
    int stats;                       /* --stats: the log gets each refined frame's times (as in staff mode) */
    FILE *log;
};

/* How a kiosk run ended; the values are the command's exit codes (cli/commands.h). */
enum kiosk_status {
    KIOSK_STOPPED = 0,        /* stopped by a signal, a key or the scripts' end */
    KIOSK_FAILED = 1,         /* a failure while running (GL, a device, a file) */
    KIOSK_BAD_CONFIG = 2,     /* a configuration that cannot be shown (a scene or script that does not load) */
    KIOSK_NO_SCENE = 3        /* this GPU can draw none of the scenes (each refusal is in the log): a
                                 restart would meet the same GPU, and the service does not restart */
};

/* Runs the kiosk until stopped (or, headless, until headless_frames frames are written). */
enum kiosk_status kiosk_run(const struct kiosk_config *c, const struct kiosk_run_options *o);
/* --check-inputs: every configured input's events, one line each on out, until stopped or until
 * no input can deliver more. Returns the exit code. */
int kiosk_check_inputs(const struct kiosk_config *c, FILE *out, FILE *log);

#endif
