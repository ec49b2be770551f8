/* Debouncing as "the last edge is at least stable_ns old": the line's level since that edge is
 * then the settled one. Times are compared as serial numbers modulo 2^64 (see debounce.h). */
#include "input/debounce.h"

/* a before b, by the sign of their difference modulo 2^64 */
static int earlier(uint64_t a, uint64_t b)
{
    return a - b > (uint64_t)INT64_MAX;
}

/* the raw level has held from the last edge up to t_ns for the whole window */
static int held_until(const struct debounce *d, uint64_t t_ns)
{
    return !earlier(t_ns, d->last_edge_ns) && t_ns - d->last_edge_ns >= d->stable_ns;
}

/* takes the raw level as settled, when it is a change, and says which */
static int settle(struct debounce *d, enum button_event *event)
{
    if (d->raw == d->settled)
        return 0;
    d->settled = d->raw;
    *event = d->settled == d->active_level ? BUTTON_PRESS : BUTTON_RELEASE;
    return 1;
}

int debounce_init(struct debounce *d, uint64_t stable_ns, int active_level, int initial_level)
{
    if (stable_ns > (uint64_t)INT64_MAX)
        return -1;
    d->stable_ns = stable_ns;
    d->active_level = active_level != 0;
    d->settled = initial_level != 0;
    d->raw = d->settled;
    d->has_edge = 0;
    d->last_edge_ns = 0;
    d->rejected = 0;
    return 0;
}

int debounce_edge(struct debounce *d, int level, uint64_t t_ns, enum button_event *event)
{
    if (d->has_edge && earlier(t_ns, d->last_edge_ns)) {
        d->rejected++;
        return -1;
    }
    int settled = d->has_edge && held_until(d, t_ns) ? settle(d, event) : 0;
    d->raw = level != 0;
    d->last_edge_ns = t_ns;
    d->has_edge = 1;
    return settled;
}

int debounce_poll(struct debounce *d, uint64_t now_ns, enum button_event *event)
{
    if (!d->has_edge || !held_until(d, now_ns))
        return 0;
    return settle(d, event);
}
