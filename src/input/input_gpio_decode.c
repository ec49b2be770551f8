/* Times are kept as uint64_t ns on the edge clock and differences taken modulo 2^64, as the
 * decoders do (debounce.h); only the events' stamps are turned into the loop's seconds. */
#include "input/input_gpio_decode.h"
#include <string.h>

#define NS_PER_S 1e9
#define NS_PER_MS 1000000ull

int input_gpio_decoder_encoder(struct input_gpio_decoder *g, int source, int counts_per_detent, int a, int b)
{
    memset(g, 0, sizeof *g);
    if (quadrature_init(&g->q, counts_per_detent, a, b) != 0)
        return -1;
    g->is_encoder = 1;
    g->source = source;
    g->a = a != 0;
    g->b = b != 0;
    return 0;
}

int input_gpio_decoder_button(struct input_gpio_decoder *g, int source, int debounce_ms, int active_low,
                              int level)
{
    memset(g, 0, sizeof *g);
    if (debounce_ms < 0 || debounce_init(&g->d, (uint64_t)debounce_ms * NS_PER_MS, !active_low, level) != 0)
        return -1;
    g->source = source;
    return 0;
}

/* the event of a settled button level, stamped when it had held for the whole window */
static void button_event(const struct input_gpio_decoder *g, enum button_event which, uint64_t settled_ns,
                         int64_t offset_ns, struct input_event *out)
{
    *out = input_event_at(which == BUTTON_PRESS ? INPUT_PRESS : INPUT_RELEASE, g->source,
                          input_gpio_loop_time(settled_ns, offset_ns));
}

int input_gpio_decoder_edge(struct input_gpio_decoder *g, const struct line_event *e, int64_t offset_ns,
                            struct input_event *out)
{
    if (g->is_encoder) {
        if (e->line == INPUT_GPIO_LINE_A)
            g->a = e->level != 0;
        else if (e->line == INPUT_GPIO_LINE_B)
            g->b = e->level != 0;
        else
            return 0;
        int detent = quadrature_edge(&g->q, g->a, g->b);
        if (detent == 0)
            return 0;
        *out = input_event_at(INPUT_TURN, g->source, input_gpio_loop_time(e->t_ns, offset_ns));
        out->counts = detent;
        return 1;
    }
    if (e->line != INPUT_GPIO_LINE_BUTTON)
        return 0;
    /* read before the edge moves it: the level that settled did so a window after that edge */
    uint64_t settled_ns = g->d.last_edge_ns + g->d.stable_ns;
    enum button_event which = BUTTON_NONE;
    if (debounce_edge(&g->d, e->level, e->t_ns, &which) != 1)
        return 0;
    button_event(g, which, settled_ns, offset_ns, out);
    return 1;
}

int input_gpio_decoder_poll(struct input_gpio_decoder *g, double now, int64_t offset_ns, struct input_event *out)
{
    enum button_event which = BUTTON_NONE;
    if (g->is_encoder || debounce_poll(&g->d, input_gpio_edge_time(now, offset_ns), &which) != 1)
        return 0;
    button_event(g, which, g->d.last_edge_ns + g->d.stable_ns, offset_ns, out);
    return 1;
}

size_t input_gpio_ready(const struct line_event *edges, size_t n, uint64_t cutoff_ns)
{
    size_t ready = 0;
    while (ready < n && cutoff_ns - edges[ready].t_ns <= (uint64_t)INT64_MAX)
        ready++;
    return ready;
}

double input_gpio_loop_time(uint64_t edge_ns, int64_t offset_ns)
{
    uint64_t loop_ns = edge_ns - (uint64_t)offset_ns;
    /* a loop time before the clock's origin reads as a negative difference */
    return loop_ns > (uint64_t)INT64_MAX ? -(double)(UINT64_MAX - loop_ns) / NS_PER_S - 1.0 / NS_PER_S
                                         : (double)loop_ns / NS_PER_S;
}

uint64_t input_gpio_edge_time(double loop_s, int64_t offset_ns)
{
    uint64_t loop_ns = loop_s > 0.0 ? (uint64_t)(loop_s * NS_PER_S + 0.5) : 0;
    return loop_ns + (uint64_t)offset_ns;
}

int64_t input_gpio_clock_offset(uint64_t edge_ns, uint64_t monotonic_ns, uint64_t realtime_ns)
{
    uint64_t to_mono = edge_ns > monotonic_ns ? edge_ns - monotonic_ns : monotonic_ns - edge_ns;
    uint64_t to_real = edge_ns > realtime_ns ? edge_ns - realtime_ns : realtime_ns - edge_ns;
    return to_mono <= to_real ? 0 : (int64_t)(realtime_ns - monotonic_ns);
}
