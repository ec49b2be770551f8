/* A push button's line, debounced over timestamped edges. A level counts only once the line has
 * held it for stable_ns; shorter excursions are bounce and glitches.
 *
 * Time: nanoseconds as uint64_t, the edge timestamps and the polling times from one and the same
 * clock (libgpiod v1 stamps edges with CLOCK_MONOTONIC since Linux 5.7, CLOCK_REALTIME before:
 * read "now" from that clock). Differences are taken modulo 2^64, so the decoder is right across
 * a wrap of the 64-bit count, as long as the times compared lie less than 2^63 ns (292 years)
 * apart. A source that counts in fewer bits (a 32-bit hardware counter) must be widened to a
 * running 64-bit count before it comes here: its wrap is a jump of 2^32 ns back, not a wrap. */
#ifndef BT_KIOSK_DEBOUNCE_H
#define BT_KIOSK_DEBOUNCE_H
#include <stdint.h>

enum button_event {
    BUTTON_NONE = 0,
    BUTTON_PRESS,
    BUTTON_RELEASE,
};

struct debounce {
    uint64_t stable_ns;     /* how long a level must hold to count */
    int active_level;       /* the level of a pressed button: 0 with the usual pull-up wiring */
    int settled;            /* the level last reported (or the one at init) */
    int raw;                /* the level since the last recorded edge */
    int has_edge;           /* last_edge_ns holds a time */
    uint64_t last_edge_ns;
    uint64_t rejected;      /* edges older than the last recorded one */
};

/* initial_level: the line's level read at start, taken as settled. Any non-zero level is high.
 * Returns -1, leaving d untouched, for stable_ns of 2^63 ns or more (beyond the ordering of times). */
int debounce_init(struct debounce *d, uint64_t stable_ns, int active_level, int initial_level);

/* An edge to `level` at t_ns. Returns -1 and counts it in `rejected` when t_ns is older than the
 * last recorded edge (the level is not recorded); else 0, or 1 when the edge ends a level that had
 * already held for stable_ns without a poll having seen it: then *event says which (a press held
 * while the loop was busy is not lost). Every edge restarts the window, whatever its level. */
int debounce_edge(struct debounce *d, int level, uint64_t t_ns, enum button_event *event);

/* Asks at now_ns whether the line has settled to a new level: returns 1 and writes *event once
 * now_ns - last edge >= stable_ns and the level differs from the last reported one, else 0
 * (also when now_ns lies before the last edge). Each change is reported once; the loop calls this
 * every iteration with the current time of the edges' clock. */
int debounce_poll(struct debounce *d, uint64_t now_ns, enum button_event *event);

#endif
