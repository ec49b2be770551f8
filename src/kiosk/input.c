/* Opening an input source by its configured type, and the loop's clock. */
#include "kiosk/input.h"
#include <stdlib.h>
#include <time.h>

double input_clock(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

struct input_source *input_open(const struct kiosk_config *c, int index, FILE *log, double now)
{
    switch (c->inputs[index].type) {
    case KIOSK_INPUT_POWERMATE:
    case KIOSK_INPUT_HID:
        return input_open_hid(c, index, log, now);
    case KIOSK_INPUT_GPIO_ENCODER:
    case KIOSK_INPUT_GPIO_BUTTON:
        return input_open_gpio(c, index, log, now);
    case KIOSK_INPUT_KEYBOARD:
        return input_open_keyboard(c, index, log, now);
    case KIOSK_INPUT_SCRIPT:
        return input_open_script(c, index, log, now);
    default:
        return NULL;
    }
}

void input_close(struct input_source *src)
{
    if (!src)
        return;
    if (src->close)
        src->close(src);
    free(src);
}
