/* Reading a GPIO source's lines: the kernel's stamped edges, merged in time order and decoded
 * (input_gpio_decode.h), a button's debounce timeout asked at every drain. */
#include "input/input_gpio_source.h"
#include <errno.h>
#include <string.h>
#include <time.h>

#define NS_PER_S 1000000000ull
/* The kernel stamps an edge in its interrupt handler and queues it from a thread: an edge stamped
 * this long before a read is in its line's queue by the time of the read. */
#define GPIO_HOLD_NS 2000000ull

static uint64_t clock_ns(clockid_t id)
{
    struct timespec ts;
    clock_gettime(id, &ts);
    return (uint64_t)ts.tv_sec * NS_PER_S + (uint64_t)ts.tv_nsec;
}

/* The pending edges of line i, without waiting, after those held from the last drain: how many
 * it has now, or -1 with errno for a line whose descriptor failed (its chip went away). */
static int read_line(struct gpio_source *s, int i)
{
    struct pollfd p = {s->api->line_event_get_fd(s->lines[i]), POLLIN, 0};
    int n = (int)s->held[i];
    while (n < GPIO_BATCH) {
        int ready = poll(&p, 1, 0);
        if (ready < 0 && errno == EINTR)
            continue;
        if (ready < 0)
            return -1;
        if (ready == 0)
            break;
        if (p.revents & (POLLERR | POLLHUP | POLLNVAL)) {
            errno = ENODEV;
            return -1;
        }
        struct gpiod_line_event ev[GPIO_BATCH];
        int got = s->api->line_event_read_multiple(s->lines[i], ev, (unsigned)(GPIO_BATCH - n));
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0)
            return -1;
        if (got == 0)
            break;  /* ready but empty: nothing to wait for in a loop that must not block */
        for (int k = 0; k < got; k++, n++) {
            s->edges[i][n].t_ns = (uint64_t)ev[k].ts.tv_sec * NS_PER_S + (uint64_t)ev[k].ts.tv_nsec;
            s->edges[i][n].line = i;
            s->edges[i][n].level = ev[k].event_type == GPIOD_LINE_EVENT_RISING_EDGE;
        }
    }
    return n;
}

/* The lines are read one after the other, so an edge of A stamped between the two reads would
 * reach the decoder a drain after a later edge of B: for an encoder, a step the wrong way. So
 * the edges of the last GPIO_HOLD_NS before the reads began wait for the next drain, by which
 * both lines' queues hold everything up to them. The edge clock is told by the first edge, and
 * its offset measured at every read when it is the realtime clock, which NTP and staff may set. */
void input_gpio_read(struct input_source *src, struct gpio_source *s, double now)
{
    uint64_t mono = clock_ns(CLOCK_MONOTONIC), real = clock_ns(CLOCK_REALTIME);
    size_t total[GPIO_MAX_LINES];
    int full = 0;
    for (int i = 0; i < s->n_lines; i++) {
        int n = read_line(s, i);
        if (n < 0) {
            input_gpio_lost(src, s, i, errno, now);
            return;
        }
        total[i] = (size_t)n;
        full |= n == GPIO_BATCH;
        if (n > 0 && !s->clock_known) {
            s->clock_realtime = input_gpio_clock_offset(s->edges[i][0].t_ns, mono, real) != 0;
            s->clock_known = 1;
        }
    }
    if (s->clock_realtime)
        s->offset_ns = (int64_t)(real - mono);
    uint64_t cutoff = (s->clock_realtime ? real : mono) - GPIO_HOLD_NS;
    const struct line_event *streams[GPIO_MAX_LINES];
    size_t counts[GPIO_MAX_LINES];
    for (int i = 0; i < s->n_lines; i++) {
        streams[i] = s->edges[i];
        /* one line waits for no other; a full batch goes whole, so that a step of the realtime
         * clock cannot hold edges back for ever */
        counts[i] = s->n_lines == 1 || full ? total[i] : input_gpio_ready(s->edges[i], total[i], cutoff);
    }
    size_t n = event_merge(streams, counts, (size_t)s->n_lines, s->merged, GPIO_MAX_LINES * GPIO_BATCH);
    struct input_event ev;
    for (size_t k = 0; k < n; k++)
        if (input_gpio_decoder_edge(&s->decoder, &s->merged[k], s->offset_ns, &ev))
            input_queue_push(&s->queue, &ev);
    for (int i = 0; i < s->n_lines; i++) {
        s->held[i] = total[i] - counts[i];
        memmove(s->edges[i], s->edges[i] + counts[i], s->held[i] * sizeof s->edges[i][0]);
    }
    if (s->clock_known && input_gpio_decoder_poll(&s->decoder, now, s->offset_ns, &ev))
        input_queue_push(&s->queue, &ev);
}
