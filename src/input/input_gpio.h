/* The GPIO source's back-end: the libgpiod v1 calls it makes, as a table, so that the source can
 * be driven by lines of the tests' own making (edges, a chip that goes away) where the machine
 * has no GPIO. input_open_gpio() uses input_gpio_libgpiod. */
#ifndef BT_KIOSK_INPUT_GPIO_H
#define BT_KIOSK_INPUT_GPIO_H
#include <gpiod.h>
#include "input/input.h"

struct input_gpio_api {
    struct gpiod_chip *(*chip_open_lookup)(const char *descr);
    void (*chip_close)(struct gpiod_chip *chip);     /* releases the chip's requested lines too */
    struct gpiod_line *(*chip_get_line)(struct gpiod_chip *chip, unsigned int offset);
    struct gpiod_line *(*chip_find_line)(struct gpiod_chip *chip, const char *name);
    int (*line_request_both_edges_events)(struct gpiod_line *line, const char *consumer);
    const char *(*line_consumer)(struct gpiod_line *line);
    int (*line_get_value)(struct gpiod_line *line);
    int (*line_event_get_fd)(struct gpiod_line *line);
    int (*line_event_read_multiple)(struct gpiod_line *line, struct gpiod_line_event *events, unsigned int num);
};

/* libgpiod 1.6 (the kernel's v1 GPIO character device interface). */
extern const struct input_gpio_api input_gpio_libgpiod;

/* input_open_gpio() on the back-end `api`, which must outlive the source. */
struct input_source *input_open_gpio_api(const struct kiosk_input *in, int index, FILE *log, double now,
                                         const struct input_gpio_api *api);

#endif
