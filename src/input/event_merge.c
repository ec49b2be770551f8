/* The merge keeps no cursors (no allocation, any number of streams): the events are totally ordered
 * by (time, stream, index), and the next one out is the smallest after the last one written.
 * In a sorted stream that is found by a binary search on the time. */
#include "input/event_merge.h"

/* a before b, by the sign of their difference modulo 2^64 */
static int earlier(uint64_t a, uint64_t b)
{
    return a - b > (uint64_t)INT64_MAX;
}

/* the first index whose time is not before t (at_or_after) or after t (!at_or_after) */
static size_t search(const struct line_event *s, size_t n, uint64_t t, int at_or_after)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        int before_bound = at_or_after ? earlier(s[mid].t_ns, t) : !earlier(t, s[mid].t_ns);
        if (before_bound)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

size_t event_merge(const struct line_event *const *streams, const size_t *counts, size_t n_streams,
                   struct line_event *out, size_t out_cap)
{
    size_t written = 0;
    size_t last_stream = 0, last_index = 0;
    uint64_t last_t = 0;
    while (written < out_cap) {
        size_t best_stream = n_streams, best_index = 0;
        for (size_t s = 0; s < n_streams; s++) {
            size_t i;
            if (written == 0)
                i = 0;
            else if (s == last_stream)
                i = last_index + 1;
            else  /* at the last time, the lower streams are already out and the higher ones not */
                i = search(streams[s], counts[s], last_t, s > last_stream);
            if (i >= counts[s])
                continue;
            if (best_stream == n_streams || earlier(streams[s][i].t_ns, streams[best_stream][best_index].t_ns)) {
                best_stream = s;
                best_index = i;
            }
        }
        if (best_stream == n_streams)
            break;
        out[written++] = streams[best_stream][best_index];
        last_stream = best_stream;
        last_index = best_index;
        last_t = streams[best_stream][best_index].t_ns;
    }
    return written;
}
