/* Previews that hold the kiosk's preview rate on this GPU.
 *
 * A preview of the configured size that takes longer than 1 / preview_rate s here would make a
 * turning knob lag: on a Raspberry Pi a 320 x 180 preview of a black hole can take ten times what
 * it takes on a desktop. So at start, after the programs are compiled (kiosk_warm.h), each scene
 * draws its preview at rest KIOSK_TUNE_FRAMES times; where the median is over the budget, the
 * preview shrinks (both sides by the same factor, to at least KIOSK_TUNE_MIN_SIDE pixels) and is
 * measured again, up to KIOSK_TUNE_ROUNDS times. The preview is upscaled to the screen with a
 * linear filter; the refined frame keeps its size and quality, and its bands follow the preview's
 * size (as many steps as one preview, at most KIOSK_MAX_BANDS bands), so that input still waits
 * about one preview. Each scene's
 * choice is logged. The headless screen never tunes: its runs are the same on any machine. */
#ifndef BT_KIOSK_TUNE_H
#define BT_KIOSK_TUNE_H
#include <stdio.h>
#include "kiosk/kiosk_view.h"

#define KIOSK_TUNE_FRAMES 3
#define KIOSK_TUNE_ROUNDS 4
#define KIOSK_TUNE_MIN_SIDE 16
/* The share of the budget a tuned preview aims at: the time of one preview varies with the state. */
#define KIOSK_TUNE_MARGIN 0.8
/* BT_FAULT=slow_previews: previews measured this many times slower, as on a slow GPU, and at least
 * KIOSK_TUNE_SLOW_PIXEL seconds a pixel (50 thousand preview rays a second), so that a preview that
 * is fast even a hundred times over on a fast machine (a flat sky) is still slow there. */
#define KIOSK_TUNE_SLOW_FACTOR 100.0
#define KIOSK_TUNE_SLOW_PIXEL 20e-6

/* Tunes every scene's preview size in v (v: the screen's view; left with no scene loaded) for c's
 * preview_rate, logging each scene's choice to log. `between` (if any) is called with arg before
 * each scene, and a nonzero answer stops the tuning there (a signal). 0, or -1 with e: a scene's
 * or the renderer's failure, as the loop would meet it. */
int kiosk_tune_previews(struct kiosk_view *v, const struct kiosk_config *c, const struct scene *scenes,
                        int (*between)(void *arg), void *arg, FILE *log, struct error *e);

#endif
