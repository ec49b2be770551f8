/* Opening an input source by its configured type, the parts every source is made of, and the
 * loop's clock. */
#include "input/input.h"
#include <stdlib.h>

struct input_source *input_open(const struct kiosk_input *in, int index, FILE *log, double now)
{
    switch (in->type) {
    case KIOSK_INPUT_POWERMATE:
    case KIOSK_INPUT_HID:
        return input_open_hid(in, index, log, now);
    case KIOSK_INPUT_GPIO_ENCODER:
    case KIOSK_INPUT_GPIO_BUTTON:
        return input_open_gpio(in, index, log, now);
    case KIOSK_INPUT_KEYBOARD:
        return input_open_keyboard(in, index, log, now);
    case KIOSK_INPUT_SCRIPT:
        return input_open_script(in, index, log, now);
    default:
        return NULL;
    }
}

struct input_source *input_source_new(const struct kiosk_input *in, int index, FILE *log, size_t priv_size,
                                      int (*fds)(struct input_source *src, struct pollfd *out, int max),
                                      int (*drain)(struct input_source *src, double now,
                                                   struct input_event *out, int max),
                                      void (*close)(struct input_source *src))
{
    struct input_source *src = calloc(1, sizeof *src);
    void *priv = calloc(1, priv_size);
    if (src == NULL || priv == NULL) {
        free(src);
        free(priv);
        return NULL;
    }
    src->cfg = in;
    src->index = index;
    src->log = log;
    src->fds = fds;
    src->drain = drain;
    src->close = close;
    src->priv = priv;
    return src;
}

void input_close(struct input_source *src)
{
    if (!src)
        return;
    if (src->close)
        src->close(src);
    free(src);
}
