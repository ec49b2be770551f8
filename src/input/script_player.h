/* Replays a loaded script against a clock: the events whose time has come, as input events. Used
 * by the script input and by the attract mode's tour, which starts over when it ends. */
#ifndef BT_KIOSK_SCRIPT_PLAYER_H
#define BT_KIOSK_SCRIPT_PLAYER_H
#include "input/input.h"
#include "input/script.h"

struct script_player {
    const struct script *script;
    double start;                    /* the clock's reading at the script's time 0 */
    int next;                        /* index of the next event due */
    int loop;                        /* start over after the last event (the attract tour) */
    long wraps;                      /* times it started over */
};

void script_player_start(struct script_player *p, const struct script *sc, double now, int loop);
/* The events due by now, at most max, as input events from source; returns how many. A looping
 * player starts over only at the beginning of a call, so that the events of one call all belong
 * to one pass through the script (the caller sees wraps change and can start that pass afresh);
 * passes missed while the caller was away are skipped, not replayed in a burst. */
int script_player_due(struct script_player *p, double now, int source, struct input_event *out, int max);
/* Every event has been replayed (never for a looping player). */
int script_player_done(const struct script_player *p);

#endif
