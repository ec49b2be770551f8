/* The GPIO source's state, shared by its connection (input_gpio.c: chip, lines, retries) and its
 * reading (input_gpio_read.c: edges to events). Not for other users. */
#ifndef BT_KIOSK_INPUT_GPIO_SOURCE_H
#define BT_KIOSK_INPUT_GPIO_SOURCE_H
#include "input/input_gpio.h"
#include "input/input_gpio_decode.h"
#include "input/input_queue.h"
#include "input/input_retry.h"

#define GPIO_MAX_LINES 2
/* Edges read per line and drain: the kernel's v1 queue holds 16 per line, so this empties it
 * several times over; the event queue has room for one event per edge (input_queue.h). */
#define GPIO_BATCH 64

struct gpio_source {
    const struct input_gpio_api *api;
    struct gpiod_chip *chip;         /* NULL while absent */
    struct gpiod_line *lines[GPIO_MAX_LINES];
    int n_lines;
    struct input_gpio_decoder decoder;
    int clock_known;                 /* an edge told which clock the kernel stamps with */
    int clock_realtime;
    int64_t offset_ns;               /* edge clock - loop clock */
    size_t held[GPIO_MAX_LINES];     /* edges kept at the front of edges[] for the next drain */
    struct input_retry retry;
    struct input_queue queue;
    struct line_event edges[GPIO_MAX_LINES][GPIO_BATCH];
    struct line_event merged[GPIO_MAX_LINES * GPIO_BATCH];
};

/* Reads every line and decodes what they have into s->queue (empty on entry); a line that fails
 * makes the source absent (input_gpio_lost). */
void input_gpio_read(struct input_source *src, struct gpio_source *s, double now);

/* Line `line` failed with errno `err`: the chip is let go, the loss logged once, and the source
 * looks for its lines again from `now`. */
void input_gpio_lost(struct input_source *src, struct gpio_source *s, int line, int err, double now);

#endif
