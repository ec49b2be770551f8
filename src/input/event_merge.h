/* Edge events read line by line (one request per GPIO line) merged into the one stream the kiosk
 * loop decodes in time order: the quadrature decoder needs A's and B's edges in the order they
 * happened. */
#ifndef BT_KIOSK_EVENT_MERGE_H
#define BT_KIOSK_EVENT_MERGE_H
#include <stddef.h>
#include <stdint.h>

struct line_event {
    uint64_t t_ns;  /* the edge's timestamp, ns, one clock for all lines (see debounce.h) */
    int line;       /* which line, as the caller numbers them */
    int level;      /* the level after the edge */
};

/* Merges n_streams arrays, each sorted by t_ns (oldest first; times compared modulo 2^64 as in
 * debounce.h), into out by time. Stable: at equal times stream 0 comes before stream 1, and a
 * stream's own events keep their order. Writes the out_cap earliest events when there are more,
 * never past out_cap; returns the number written. A stream may be NULL when its count is 0.
 * No working memory: each output event is found by a binary search in every stream, so the cost
 * is (events written) x n_streams x log(longest stream), fine for the tens of events one loop
 * iteration reads. */
size_t event_merge(const struct line_event *const *streams, const size_t *counts, size_t n_streams,
                   struct line_event *out, size_t out_cap);

#endif
