/* A rotary encoder on two GPIO lines A and B: quadrature (Gray code) edges to detents.
 * The lines' levels are packed as ab = (A << 1) | B. Clockwise is the direction in which A leads B
 * (the usual datasheet convention), one cycle 00 -> 10 -> 11 -> 01 -> 00, and counts +1;
 * counter-clockwise runs 00 -> 01 -> 11 -> 10 -> 00 and counts -1. A knob wired the other way
 * round is fixed by swapping its A and B lines, not here. */
#ifndef BT_KIOSK_QUADRATURE_H
#define BT_KIOSK_QUADRATURE_H
#include <stdint.h>

struct quadrature {
    uint8_t ab;             /* the lines' levels after the last edge, (A << 1) | B */
    int accumulated;        /* quarter steps since the last detent, always within +-(counts_per_detent - 1) */
    int counts_per_detent;  /* 1, 2 or 4 Gray transitions per mechanical click */
    int64_t detents;        /* running total; wraps modulo 2^64 instead of overflowing */
    uint64_t invalid;       /* edges where both lines changed at once: a missed edge */
};

/* Starts at the lines' present levels (any non-zero level is high). Call it with the knob at rest
 * on a detent: detents are counted from this position, every counts_per_detent transitions.
 * Returns -1, and leaves q untouched, for a counts_per_detent other than 1, 2 or 4. */
int quadrature_init(struct quadrature *q, int counts_per_detent, int a, int b);

/* The lines' levels after an edge on either of them. Returns the detents this edge completes:
 * +1 (clockwise), -1 or 0. A step back before a detent is complete takes its count back, so
 * jitter about a position emits nothing. Both lines changed at once means an edge was missed and
 * the direction is unknown: the edge is counted in `invalid`, the count does not move, and the
 * new levels are taken as the state so that the next edge is read against the lines' truth.
 * Levels equal to the last ones (an edge that bounced back before it was read) count nothing. */
int quadrature_edge(struct quadrature *q, int a, int b);

/* Detents turned since the total read `earlier_total`: right across the wrap of the total, as
 * long as fewer than 2^63 detents lie between. */
int64_t quadrature_detents_since(const struct quadrature *q, int64_t earlier_total);

#endif
