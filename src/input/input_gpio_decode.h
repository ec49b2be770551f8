/* A GPIO input's edges, merged in time order, to the loop's events: an encoder's quadrature
 * edges to one INPUT_TURN per detent, a button's edges and debounce timeouts to INPUT_PRESS and
 * INPUT_RELEASE. The part of the GPIO source that needs no device.
 *
 * Two clocks meet here. Edges carry the kernel's timestamps (libgpiod v1: CLOCK_MONOTONIC since
 * Linux 5.7, CLOCK_REALTIME before), and the debounce works on them alone, so that bounce is
 * judged by when the edges happened, not by when the loop read them. The loop's clock
 * (clock_seconds, CLOCK_MONOTONIC) stamps the events and asks for the debounce timeouts.
 * offset_ns is the edge clock minus the loop clock, in ns (0 when they are the same clock). */
#ifndef BT_KIOSK_INPUT_GPIO_DECODE_H
#define BT_KIOSK_INPUT_GPIO_DECODE_H
#include <stdint.h>
#include "input/debounce.h"
#include "input/event_merge.h"
#include "input/input.h"
#include "input/quadrature.h"

/* line numbers in struct line_event */
#define INPUT_GPIO_LINE_A 0          /* encoder */
#define INPUT_GPIO_LINE_B 1          /* encoder */
#define INPUT_GPIO_LINE_BUTTON 0     /* button */

struct input_gpio_decoder {
    int is_encoder;
    int source;                      /* the input's index, for the events */
    struct quadrature q;             /* encoder */
    int a, b;                        /* encoder: the lines' levels after the last edge */
    struct debounce d;               /* button */
};

/* The lines' levels at start (the knob at rest on a detent). Returns -1 for a counts_per_detent
 * other than 1, 2 or 4. */
int input_gpio_decoder_encoder(struct input_gpio_decoder *g, int source, int counts_per_detent, int a, int b);

/* The line's level at start, taken as settled. active_low: the line reads 0 while pressed.
 * Returns -1 for a debounce_ms below 0. */
int input_gpio_decoder_button(struct input_gpio_decoder *g, int source, int debounce_ms, int active_low,
                              int level);

/* One edge, in time order with the others (event_merge). Returns 1 with *out written (a detent
 * completed; a button level that had settled before this edge ended it), else 0. Edges of a
 * line the decoder does not have are ignored. */
int input_gpio_decoder_edge(struct input_gpio_decoder *g, const struct line_event *e, int64_t offset_ns,
                            struct input_event *out);

/* A button's debounce timeout at `now` on the loop's clock: 1 with *out written when the line has
 * settled to a new level, else 0. Encoders never have one. */
int input_gpio_decoder_poll(struct input_gpio_decoder *g, double now, int64_t offset_ns,
                            struct input_event *out);

/* How many of a line's edges, in time order, were stamped at or before cutoff_ns (times compared
 * modulo 2^64, as in debounce.h): the ones that may be decoded now, the rest waiting until every
 * line has been read past them. */
size_t input_gpio_ready(const struct line_event *edges, size_t n, uint64_t cutoff_ns);

/* Loop time (s) of an edge time, and edge time of a loop time (times before the loop clock's
 * origin are taken as 0). */
double input_gpio_loop_time(uint64_t edge_ns, int64_t offset_ns);
uint64_t input_gpio_edge_time(double loop_s, int64_t offset_ns);

/* Which clock stamped an edge read just now, told by which of the two clocks it lies nearer:
 * returns offset_ns, 0 for CLOCK_MONOTONIC (the loop's), realtime_ns - monotonic_ns for
 * CLOCK_REALTIME. The two lie decades apart on any machine with a set clock, and an edge is
 * read within moments of happening. */
int64_t input_gpio_clock_offset(uint64_t edge_ns, uint64_t monotonic_ns, uint64_t realtime_ns);

#endif
