/* Encoders and buttons on GPIO lines, through libgpiod's v1 API: each line is requested for
 * both edges, the loop polls the lines' event descriptors, and drain() reads what the kernel has
 * stamped, merges the lines in time order and decodes (input_gpio_decode.h). Lines are requested
 * without libgpiod's active-low flag: the debounce is told which level is pressed, so that the
 * levels in the log and the decoders are the wires' own. */
#include "input/input_gpio_source.h"
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#define GPIO_CONSUMER "bentray"

const struct input_gpio_api input_gpio_libgpiod = {
    gpiod_chip_open_lookup, gpiod_chip_close, gpiod_chip_get_line, gpiod_chip_find_line,
    gpiod_line_request_both_edges_events, gpiod_line_consumer, gpiod_line_get_value,
    gpiod_line_event_get_fd, gpiod_line_event_read_multiple,
};

/* Line i as the configuration gives it: its offset, or -1 and *name. */
static int line_offset(const struct kiosk_input *in, int i, const char **name)
{
    if (in->type == KIOSK_INPUT_GPIO_BUTTON) {
        *name = in->line_name;
        return in->line;
    }
    *name = i == 0 ? in->line_a_name : in->line_b_name;
    return i == 0 ? in->line_a : in->line_b;
}

/* "line 17" or "line KNOB_MASS_A", for the log */
static void line_label(const struct kiosk_input *in, int i, char *out, size_t len)
{
    const char *name;
    int offset = line_offset(in, i, &name);
    if (offset >= 0)
        snprintf(out, len, "line %d", offset);
    else
        snprintf(out, len, "line %s", name);
}

static struct gpiod_line *find_line(const struct gpio_source *s, const struct kiosk_input *in, int i)
{
    const char *name;
    int offset = line_offset(in, i, &name);
    return offset >= 0 ? s->api->chip_get_line(s->chip, (unsigned)offset) : s->api->chip_find_line(s->chip, name);
}

static void gpio_source_release(struct gpio_source *s)
{
    if (s->chip != NULL)
        s->api->chip_close(s->chip);  /* releases the requested lines too */
    s->chip = NULL;
    s->n_lines = 0;
}

/* Requests line i; 0, or -1 with the reason logged. */
static int request_line(struct input_source *src, struct gpio_source *s, int i)
{
    const struct kiosk_input *in = src->cfg;
    char label[KIOSK_NAME_LEN + 8];
    line_label(in, i, label, sizeof label);
    struct gpiod_line *line = find_line(s, in, i);
    if (line == NULL) {
        input_retry_absent(&s->retry, src, INPUT_ABSENT_GONE, "%s not found on GPIO chip %s", label, in->chip);
        return -1;
    }
    if (s->api->line_request_both_edges_events(line, GPIO_CONSUMER) != 0) {
        int err = errno;
        const char *holder = s->api->line_consumer(line);
        input_retry_absent(&s->retry, src, INPUT_ABSENT_REFUSED, "%s of GPIO chip %s could not be requested: "
                           "%s%s%s", label, in->chip, strerror(err), holder ? ", held by " : "",
                           holder ? holder : "");
        return -1;
    }
    s->lines[s->n_lines++] = line;
    return 0;
}

/* Opens the chip, requests the lines and starts the decoder at their present levels: present and
 * "connected" logged, or absent with the reason logged (once). */
static int gpio_source_open(struct input_source *src, struct gpio_source *s)
{
    const struct kiosk_input *in = src->cfg;
    int is_encoder = in->type == KIOSK_INPUT_GPIO_ENCODER;
    s->chip = s->api->chip_open_lookup(in->chip);
    if (s->chip == NULL) {
        int err = errno;
        if (err == ENOENT)
            input_retry_absent(&s->retry, src, INPUT_ABSENT_GONE, "GPIO chip %s not found", in->chip);
        else
            input_retry_absent(&s->retry, src, INPUT_ABSENT_REFUSED, "GPIO chip %s could not be opened: %s%s",
                               in->chip, strerror(err), err == EACCES ? " (the kiosk's user needs access "
                               "to its /dev node, usually as a member of the gpio group)" : "");
        return -1;
    }
    for (int i = 0; i < (is_encoder ? 2 : 1); i++) {
        if (request_line(src, s, i) != 0) {
            gpio_source_release(s);
            return -1;
        }
    }
    int level[GPIO_MAX_LINES] = {0, 0};
    for (int i = 0; i < s->n_lines; i++)
        level[i] = s->api->line_get_value(s->lines[i]) > 0;
    int rc = is_encoder ? input_gpio_decoder_encoder(&s->decoder, src->index, in->counts_per_detent, level[0],
                                                     level[1])
                        : input_gpio_decoder_button(&s->decoder, src->index, in->debounce_ms, in->active_low,
                                                    level[0]);
    if (rc != 0) {
        gpio_source_release(s);
        input_retry_absent(&s->retry, src, INPUT_ABSENT_REFUSED, "counts_per_detent %d or debounce_ms %d is "
                           "not usable", in->counts_per_detent, in->debounce_ms);
        return -1;
    }
    s->clock_known = 0;
    s->clock_realtime = 0;
    s->offset_ns = 0;
    memset(s->held, 0, sizeof s->held);
    src->present = 1;
    char a[KIOSK_NAME_LEN + 8], b[KIOSK_NAME_LEN + 8];
    line_label(in, 0, a, sizeof a);
    line_label(in, 1, b, sizeof b);
    input_retry_present(&s->retry, src, "GPIO chip %s %s%s%s connected", in->chip, a, is_encoder ? " and " : "",
                        is_encoder ? b : "");
    return 0;
}

void input_gpio_lost(struct input_source *src, struct gpio_source *s, int line, int err, double now)
{
    char label[KIOSK_NAME_LEN + 8];
    line_label(src->cfg, line, label, sizeof label);
    gpio_source_release(s);
    src->present = 0;
    input_retry_init(&s->retry, now);
    input_retry_absent(&s->retry, src, INPUT_ABSENT_GONE, "disconnected (reading %s of GPIO chip %s failed: %s)",
                       label, src->cfg->chip, strerror(err));
}

static int gpio_source_fds(struct input_source *src, struct pollfd *out, int max)
{
    struct gpio_source *s = src->priv;
    int n = 0;
    for (int i = 0; src->present && i < s->n_lines && n < max; i++, n++) {
        out[n].fd = s->api->line_event_get_fd(s->lines[i]);
        out[n].events = POLLIN;
        out[n].revents = 0;
    }
    return n;
}

static int gpio_source_drain(struct input_source *src, double now, struct input_event *out, int max)
{
    struct gpio_source *s = src->priv;
    int n = input_queue_take(&s->queue, out, max);
    if (s->queue.count > 0)
        return n;
    if (s->chip == NULL && (!input_retry_take(&s->retry, now) || gpio_source_open(src, s) != 0))
        return n;
    input_gpio_read(src, s, now);
    return n + input_queue_take(&s->queue, out + n, max - n);
}

static void gpio_source_close(struct input_source *src)
{
    struct gpio_source *s = src->priv;
    gpio_source_release(s);
    free(s);
    src->priv = NULL;
}

struct input_source *input_open_gpio(const struct kiosk_input *in, int index, FILE *log, double now)
{
    return input_open_gpio_api(in, index, log, now, &input_gpio_libgpiod);
}

struct input_source *input_open_gpio_api(const struct kiosk_input *in, int index, FILE *log, double now,
                                         const struct input_gpio_api *api)
{
    if (in->type != KIOSK_INPUT_GPIO_ENCODER && in->type != KIOSK_INPUT_GPIO_BUTTON)
        return NULL;
    struct input_source *src = input_source_new(in, index, log, sizeof(struct gpio_source), gpio_source_fds,
                                                gpio_source_drain, gpio_source_close);
    if (src == NULL)
        return NULL;
    struct gpio_source *s = src->priv;
    s->api = api;
    input_queue_clear(&s->queue);
    input_retry_init(&s->retry, now);
    gpio_source_open(src, s);
    return src;
}
