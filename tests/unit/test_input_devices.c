/* The device input sources without their devices: a PowerMate, HID or GPIO input whose device is
 * absent gives a source that is not present, says so in one log line naming the input, delivers
 * nothing and says nothing more while the device stays away; the retry schedule looks for it at
 * most every INPUT_RETRY_SECONDS. Then the same sources on back-ends of this file's making (a
 * PowerMate, an HID box, GPIO lines behind pipes) that come, report, go and come back; and the
 * pure parts the sources are built on (HID readings to events with button changes, GPIO edges to
 * detents and debounced presses, the edge clock). */
#include <errno.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include <cmocka.h>
#include "io/clock.h"
#include "kiosk_config/kiosk_config.h"
#include "input/input.h"
#include "input/input_gpio.h"
#include "input/input_gpio_decode.h"
#include "input/input_hid.h"
#include "input/input_hid_decode.h"
#include "input/input_queue.h"
#include "input/input_retry.h"

#define MS 1000000ull
/* USB ids no device has: 0xffff is reserved as a vendor id. */
#define ABSENT_VID 0xffff
#define ABSENT_PID 0xfffe
#define ABSENT_CHIP "bentray-test-no-such-chip"

/* ---------------------------------------------------------------- a log in memory */

struct memlog {
    FILE *f;
    char *text;
    size_t len;
};

static void memlog_open(struct memlog *m)
{
    m->text = NULL;
    m->len = 0;
    m->f = open_memstream(&m->text, &m->len);
    assert_non_null(m->f);
}

static int memlog_lines(struct memlog *m)
{
    fflush(m->f);
    int lines = 0;
    for (size_t i = 0; i < m->len; i++)
        lines += m->text[i] == '\n';
    return lines;
}

static void memlog_close(struct memlog *m)
{
    fclose(m->f);
    free(m->text);
}

/* ---------------------------------------------------------------- absent devices */

static struct kiosk_config *config_with(enum kiosk_input_type type, const char *name)
{
    struct kiosk_config *c = calloc(1, sizeof *c);
    assert_non_null(c);
    kiosk_config_defaults(c);
    struct kiosk_input *in = &c->inputs[0];
    memset(in, 0, sizeof *in);
    snprintf(in->name, sizeof in->name, "%s", name);
    in->type = type;
    in->vid = ABSENT_VID;
    in->pid = ABSENT_PID;
    in->report_length = 4;
    in->axis_offset = 1;
    in->axis_size = 1;
    in->axis_signed = 1;
    in->button_offset = 2;
    in->buttons = 4;
    snprintf(in->chip, sizeof in->chip, "%s", ABSENT_CHIP);
    in->line_a = 17;
    in->line_b = 27;
    in->counts_per_detent = 4;
    in->line = -1;
    snprintf(in->line_name, sizeof in->line_name, "BUTTON_NEXT");
    in->active_low = 1;
    in->debounce_ms = 20;
    c->n_inputs = 1;
    return c;
}

/* Opens input 0 with its device absent and drains it at times within and beyond the retry
 * interval: one line naming the input and `what`, at open only; no events, no descriptors. */
static void check_absent(enum kiosk_input_type type, const char *name, const char *what)
{
    struct kiosk_config *c = config_with(type, name);
    struct memlog log;
    memlog_open(&log);
    const double t0 = 100.0;
    struct input_source *src = type == KIOSK_INPUT_GPIO_ENCODER || type == KIOSK_INPUT_GPIO_BUTTON
                                   ? input_open_gpio(&c->inputs[0], 0, log.f, t0)
                                   : input_open_hid(&c->inputs[0], 0, log.f, t0);
    assert_non_null(src);
    assert_int_equal(src->present, 0);
    assert_int_equal(src->index, 0);
    assert_int_equal(memlog_lines(&log), 1);
    char prefix[96];
    snprintf(prefix, sizeof prefix, "input %s: ", name);
    assert_memory_equal(log.text, prefix, strlen(prefix));
    assert_non_null(strstr(log.text, what));
    assert_non_null(strstr(log.text, "every 1.5 s"));

    const double later[] = {0.0, 0.1, 1.0, 1.49, 1.5, 1.6, 3.0, 3.1, 10.0, 10.2, 60.0};
    struct input_event ev[8];
    struct pollfd fds[INPUT_MAX_FDS];
    for (size_t i = 0; i < sizeof later / sizeof later[0]; i++) {
        assert_int_equal(src->drain(src, t0 + later[i], ev, 8), 0);
        assert_int_equal(src->fds(src, fds, INPUT_MAX_FDS), 0);
        assert_int_equal(src->present, 0);
    }
    assert_int_equal(memlog_lines(&log), 1);
    input_close(src);
    memlog_close(&log);
    free(c);
}

static void test_powermate_absent(void **state)
{
    (void)state;
    check_absent(KIOSK_INPUT_POWERMATE, "speed_knob", "PowerMate ffff:fffe not found");
}

static void test_hid_absent(void **state)
{
    (void)state;
    check_absent(KIOSK_INPUT_HID, "box", "HID device ffff:fffe not found");
}

static void test_gpio_encoder_absent(void **state)
{
    (void)state;
    check_absent(KIOSK_INPUT_GPIO_ENCODER, "mass_knob", "GPIO chip " ABSENT_CHIP " not found");
}

static void test_gpio_button_absent(void **state)
{
    (void)state;
    check_absent(KIOSK_INPUT_GPIO_BUTTON, "next_button", "GPIO chip " ABSENT_CHIP " not found");
}

/* hidapi is started by the first HID source and stopped by the last: two open at once, closed in
 * either order, and a third after them (valgrind checks nothing of libusb stays behind). */
static void test_hid_sources_share_hidapi(void **state)
{
    (void)state;
    struct kiosk_config *c = config_with(KIOSK_INPUT_POWERMATE, "knob");
    c->inputs[1] = c->inputs[0];
    c->inputs[1].type = KIOSK_INPUT_HID;
    c->n_inputs = 2;
    struct memlog log;
    memlog_open(&log);
    struct input_source *a = input_open_hid(&c->inputs[0], 0, log.f, 0.0);
    struct input_source *b = input_open_hid(&c->inputs[1], 1, log.f, 0.0);
    assert_non_null(a);
    assert_non_null(b);
    assert_int_equal(b->index, 1);
    input_close(a);
    struct input_event ev[4];
    assert_int_equal(b->drain(b, 2.0, ev, 4), 0);
    input_close(b);
    struct input_source *again = input_open_hid(&c->inputs[0], 0, log.f, 5.0);
    assert_non_null(again);
    input_close(again);
    assert_int_equal(memlog_lines(&log), 3);
    memlog_close(&log);
    free(c);
}

/* ---------------------------------------------------------------- a HID device of our own */

/* hidapi's handle is opaque; this file's one device completes it. */
struct hid_device_ {
    int unused;
};

struct fake_hid {
    int plugged;                     /* enumeration finds it */
    int openable;                    /* it can be opened (permissions, not held elsewhere) */
    int open;
    int unplugged_while_open;        /* reads fail, as hidapi-libusb's after a disconnect */
    int inits, exits, enumerations, opens, closes;
    unsigned char reports[8][8];
    size_t lens[8];
    int n_reports, next_report;
};

static struct fake_hid fake_hid;
static hid_device fake_hid_device;
static struct hid_device_info fake_hid_info;
static int fake_hid_users;
static char fake_hid_path[] = "fake-usb-1-1";

static int fake_hid_init(void)
{
    fake_hid.inits++;
    return 0;
}

static int fake_hid_exit(void)
{
    fake_hid.exits++;
    return 0;
}

static struct hid_device_info *fake_hid_enumerate(unsigned short vid, unsigned short pid)
{
    fake_hid.enumerations++;
    if (!fake_hid.plugged || vid != 0x077d || pid != 0x0410)
        return NULL;
    memset(&fake_hid_info, 0, sizeof fake_hid_info);
    fake_hid_info.path = fake_hid_path;
    return &fake_hid_info;
}

static void fake_hid_free_enumeration(struct hid_device_info *devs)
{
    assert_true(devs == NULL || devs == &fake_hid_info);
}

static hid_device *fake_hid_open_path(const char *path)
{
    assert_string_equal(path, fake_hid_path);
    if (!fake_hid.openable || fake_hid.open)
        return NULL;
    fake_hid.open = 1;
    fake_hid.opens++;
    fake_hid.unplugged_while_open = 0;
    return &fake_hid_device;
}

static int fake_hid_set_nonblocking(hid_device *dev, int nonblock)
{
    assert_ptr_equal(dev, &fake_hid_device);
    assert_int_equal(nonblock, 1);
    return 0;
}

static int fake_hid_read_timeout(hid_device *dev, unsigned char *data, size_t length, int milliseconds)
{
    assert_ptr_equal(dev, &fake_hid_device);
    assert_true(fake_hid.open);
    assert_int_equal(milliseconds, 0);   /* never waits */
    if (fake_hid.unplugged_while_open)
        return -1;
    if (fake_hid.next_report >= fake_hid.n_reports)
        return 0;
    int i = fake_hid.next_report++;
    size_t n = fake_hid.lens[i] < length ? fake_hid.lens[i] : length;
    memcpy(data, fake_hid.reports[i], n);
    return (int)n;
}

static void fake_hid_close(hid_device *dev)
{
    assert_ptr_equal(dev, &fake_hid_device);
    assert_true(fake_hid.open);
    fake_hid.open = 0;
    fake_hid.closes++;
}

static const struct input_hid_api fake_hid_api = {
    &fake_hid_users, fake_hid_init, fake_hid_exit, fake_hid_enumerate, fake_hid_free_enumeration,
    fake_hid_open_path, fake_hid_set_nonblocking, fake_hid_read_timeout, fake_hid_close,
};

static void fake_hid_report(const unsigned char *bytes, size_t len)
{
    assert_true(fake_hid.n_reports < 8 && len <= 8);
    memcpy(fake_hid.reports[fake_hid.n_reports], bytes, len);
    fake_hid.lens[fake_hid.n_reports++] = len;
}

/* Everything drain() has now, at `now`, however many calls that takes with room for `max`. */
static int drain_all(struct input_source *src, double now, struct input_event *out, int cap, int max)
{
    int n = 0;
    for (;;) {
        int room = cap - n < max ? cap - n : max;
        int got = src->drain(src, now, out + n, room);
        assert_true(got >= 0 && got <= room);
        n += got;
        if (got < room || n == cap)
            return n;
    }
}

/* A PowerMate that is plugged in late, turned and pressed, unplugged, refused, and plugged in
 * again: the source looks for it on the retry schedule only, logs each change once, delivers its
 * events in order whatever room the loop gives, and stops hidapi after the last source. */
static void test_powermate_lifecycle(void **state)
{
    (void)state;
    memset(&fake_hid, 0, sizeof fake_hid);
    struct kiosk_config *c = config_with(KIOSK_INPUT_POWERMATE, "speed_knob");
    c->inputs[0].vid = 0x077d;
    c->inputs[0].pid = 0x0410;
    struct memlog log;
    memlog_open(&log);
    struct input_event ev[16];
    struct input_source *src = input_open_hid_api(&c->inputs[0], 0, log.f, 0.0, &fake_hid_api);
    assert_non_null(src);
    assert_int_equal(src->present, 0);
    assert_int_equal(fake_hid.inits, 1);
    assert_int_equal(fake_hid.enumerations, 1);
    assert_int_equal(memlog_lines(&log), 1);
    assert_string_equal(log.text, "input speed_knob: PowerMate 077d:0410 not found; looking for it every 1.5 s\n");

    /* looked for at 1.5 s, not before; still absent, nothing more said */
    assert_int_equal(src->drain(src, 0.5, ev, 16), 0);
    assert_int_equal(src->drain(src, 1.4, ev, 16), 0);
    assert_int_equal(fake_hid.enumerations, 1);
    assert_int_equal(src->drain(src, 1.5, ev, 16), 0);
    assert_int_equal(fake_hid.enumerations, 2);
    assert_int_equal(memlog_lines(&log), 1);

    /* plugged in with three reports waiting: turned 2, pressed, released while turned back 1 */
    fake_hid.plugged = fake_hid.openable = 1;
    fake_hid_report((const unsigned char[]){0x00, 0x02, 0, 0, 0, 0}, 6);
    fake_hid_report((const unsigned char[]){0x01, 0x00, 0, 0, 0, 0}, 6);
    fake_hid_report((const unsigned char[]){0x00, 0xff, 0, 0, 0, 0}, 6);
    fake_hid_report((const unsigned char[]){0x01}, 1);   /* too short: nothing */
    assert_int_equal(src->drain(src, 2.9, ev, 16), 0);
    assert_int_equal(fake_hid.enumerations, 2);
    assert_int_equal(src->drain(src, 3.0, ev, 2), 2);    /* room for two: the rest waits */
    assert_int_equal(src->present, 1);
    assert_int_equal(memlog_lines(&log), 2);
    assert_non_null(strstr(log.text, "\ninput speed_knob: PowerMate 077d:0410 connected\n"));
    assert_int_equal(ev[0].kind, INPUT_TURN);
    assert_int_equal(ev[0].counts, 2);
    assert_int_equal(ev[0].source, 0);
    assert_float_equal(ev[0].t, 3.0, 0.0);
    assert_int_equal(ev[1].kind, INPUT_PRESS);
    assert_int_equal(ev[1].bit, -1);
    assert_int_equal(src->drain(src, 3.1, ev, 1), 1);
    assert_int_equal(ev[0].kind, INPUT_TURN);
    assert_int_equal(ev[0].counts, -1);
    assert_int_equal(src->drain(src, 3.1, ev, 16), 1);
    assert_int_equal(ev[0].kind, INPUT_RELEASE);
    assert_int_equal(ev[0].bit, -1);
    assert_int_equal(src->drain(src, 3.2, ev, 16), 0);
    struct pollfd fds[INPUT_MAX_FDS];
    assert_int_equal(src->fds(src, fds, INPUT_MAX_FDS), 0);

    /* unplugged: said once, closed, looked for again 1.5 s later */
    fake_hid.unplugged_while_open = 1;
    fake_hid.plugged = 0;
    assert_int_equal(src->drain(src, 4.0, ev, 16), 0);
    assert_int_equal(src->present, 0);
    assert_int_equal(fake_hid.closes, 1);
    assert_int_equal(memlog_lines(&log), 3);
    assert_non_null(strstr(log.text, "\ninput speed_knob: PowerMate 077d:0410 disconnected (reading failed); "
                                     "looking for it every 1.5 s\n"));
    int enumerations = fake_hid.enumerations;
    for (double t = 4.1; t < 5.45; t += 0.1)
        assert_int_equal(src->drain(src, t, ev, 16), 0);
    assert_int_equal(fake_hid.enumerations, enumerations);
    assert_int_equal(src->drain(src, 5.5, ev, 16), 0);
    assert_int_equal(fake_hid.enumerations, enumerations + 1);
    assert_int_equal(memlog_lines(&log), 3);

    /* there again but not to be opened: news, once */
    fake_hid.plugged = 1;
    fake_hid.openable = 0;
    assert_int_equal(src->drain(src, 7.0, ev, 16), 0);
    assert_int_equal(src->drain(src, 8.5, ev, 16), 0);
    assert_int_equal(memlog_lines(&log), 4);
    assert_non_null(strstr(log.text, "PowerMate 077d:0410 found but could not be opened"));

    /* opened at last; a press held over the unplugging is a new press */
    fake_hid.openable = 1;
    fake_hid_report((const unsigned char[]){0x01, 0x00, 0, 0, 0, 0}, 6);
    assert_int_equal(drain_all(src, 10.0, ev, 16, 16), 1);
    assert_int_equal(ev[0].kind, INPUT_PRESS);
    assert_int_equal(src->present, 1);
    assert_int_equal(memlog_lines(&log), 5);
    assert_int_equal(fake_hid.exits, 0);
    input_close(src);
    assert_int_equal(fake_hid.closes, fake_hid.opens);
    assert_int_equal(fake_hid.inits, 1);
    assert_int_equal(fake_hid.exits, 1);
    memlog_close(&log);
    free(c);
}

/* A generic HID box with numbered reports: its layout from the configuration, reports of another
 * id passed over, each button bit pressed and released as itself. */
static void test_hid_box_reports(void **state)
{
    (void)state;
    memset(&fake_hid, 0, sizeof fake_hid);
    fake_hid.plugged = fake_hid.openable = 1;
    struct kiosk_config *c = config_with(KIOSK_INPUT_HID, "box");
    struct kiosk_input *in = &c->inputs[0];
    in->vid = 0x077d;   /* the fake's ids */
    in->pid = 0x0410;
    in->report_id = 2;
    in->report_length = 3;
    in->axis_offset = 1;
    in->button_offset = 2;
    in->buttons = 2;
    fake_hid_report((const unsigned char[]){2, 0x05, 0x01}, 3);
    fake_hid_report((const unsigned char[]){3, 0x7f, 0x03}, 3);
    fake_hid_report((const unsigned char[]){2, 0x00, 0x02}, 3);
    struct memlog log;
    memlog_open(&log);
    struct input_source *src = input_open_hid_api(&c->inputs[0], 0, log.f, 0.0, &fake_hid_api);
    assert_non_null(src);
    assert_int_equal(src->present, 1);
    assert_string_equal(log.text, "input box: HID device 077d:0410 connected\n");
    struct input_event ev[16];
    assert_int_equal(drain_all(src, 0.02, ev, 16, 3), 4);
    assert_int_equal(ev[0].kind, INPUT_TURN);
    assert_int_equal(ev[0].counts, 5);
    assert_int_equal(ev[1].kind, INPUT_PRESS);
    assert_int_equal(ev[1].bit, 0);
    assert_int_equal(ev[2].kind, INPUT_RELEASE);
    assert_int_equal(ev[2].bit, 0);
    assert_int_equal(ev[3].kind, INPUT_PRESS);
    assert_int_equal(ev[3].bit, 1);
    input_close(src);
    assert_int_equal(fake_hid.exits, 1);
    memlog_close(&log);
    free(c);
}

/* ---------------------------------------------------------------- GPIO lines of our own */

/* libgpiod's chip and line are opaque; this file's completes them. A line's event descriptor is
 * a pipe holding one byte while edges wait, and hung up when its chip goes away. */
struct gpiod_chip {
    int unused;
};

struct gpiod_line {
    int pipe[2];
    int signalled;
    struct gpiod_line_event queued[64];
    int n_queued, next;
};

struct fake_gpio {
    int chip_present;
    int line_missing;
    int busy;
    int open;
    int opens, closes, requests;
    int levels[2];
};

static struct fake_gpio fake_gpio;
static struct gpiod_chip fake_chip;
static struct gpiod_line fake_lines[2];

static struct gpiod_chip *fake_chip_open_lookup(const char *descr)
{
    assert_string_equal(descr, "fakechip");
    if (!fake_gpio.chip_present) {
        errno = ENOENT;
        return NULL;
    }
    assert_false(fake_gpio.open);
    for (int i = 0; i < 2; i++) {
        memset(&fake_lines[i], 0, sizeof fake_lines[i]);
        assert_int_equal(pipe(fake_lines[i].pipe), 0);
    }
    fake_gpio.open = 1;
    fake_gpio.opens++;
    return &fake_chip;
}

static void fake_chip_close(struct gpiod_chip *chip)
{
    assert_ptr_equal(chip, &fake_chip);
    for (int i = 0; i < 2; i++)
        for (int k = 0; k < 2; k++)
            if (fake_lines[i].pipe[k] >= 0)
                close(fake_lines[i].pipe[k]);
    fake_gpio.open = 0;
    fake_gpio.closes++;
}

static struct gpiod_line *fake_chip_get_line(struct gpiod_chip *chip, unsigned int offset)
{
    assert_ptr_equal(chip, &fake_chip);
    if (fake_gpio.line_missing || (offset != 17 && offset != 27 && offset != 22)) {
        errno = EINVAL;
        return NULL;
    }
    return &fake_lines[offset == 27];
}

static struct gpiod_line *fake_chip_find_line(struct gpiod_chip *chip, const char *name)
{
    assert_ptr_equal(chip, &fake_chip);
    int b = strcmp(name, "KNOB_B") == 0;
    if (fake_gpio.line_missing || (!b && strcmp(name, "KNOB_A") != 0 && strcmp(name, "BUTTON_NEXT") != 0)) {
        errno = ENOENT;
        return NULL;
    }
    return &fake_lines[b];
}

static int fake_line_request(struct gpiod_line *line, const char *consumer)
{
    (void)line;
    assert_string_equal(consumer, "bentray");
    if (fake_gpio.busy) {
        errno = EBUSY;
        return -1;
    }
    fake_gpio.requests++;
    return 0;
}

static const char *fake_line_consumer(struct gpiod_line *line)
{
    (void)line;
    return fake_gpio.busy ? "gpio-keys" : NULL;
}

static int fake_line_get_value(struct gpiod_line *line)
{
    return fake_gpio.levels[line == &fake_lines[1]];
}

static int fake_line_event_get_fd(struct gpiod_line *line)
{
    return line->pipe[0];
}

static int fake_line_event_read_multiple(struct gpiod_line *line, struct gpiod_line_event *events, unsigned int num)
{
    int n = 0;
    while ((unsigned)n < num && line->next < line->n_queued)
        events[n++] = line->queued[line->next++];
    if (line->next == line->n_queued && line->signalled) {
        char byte;
        assert_int_equal(read(line->pipe[0], &byte, 1), 1);
        line->signalled = 0;
    }
    return n;
}

static const struct input_gpio_api fake_gpio_api = {
    fake_chip_open_lookup, fake_chip_close, fake_chip_get_line, fake_chip_find_line, fake_line_request,
    fake_line_consumer, fake_line_get_value, fake_line_event_get_fd, fake_line_event_read_multiple,
};

static uint64_t now_ns(clockid_t id)
{
    struct timespec ts;
    clock_gettime(id, &ts);
    return (uint64_t)ts.tv_sec * 1000000000ull + (uint64_t)ts.tv_nsec;
}

static double seconds(uint64_t ns)
{
    return (double)ns / 1e9;
}

/* An edge of line i to `level`, stamped t_ns on the kernel's clock. */
static void fake_edge(int i, int level, uint64_t t_ns)
{
    struct gpiod_line *line = &fake_lines[i];
    assert_true(line->n_queued < 64);
    struct gpiod_line_event *e = &line->queued[line->n_queued++];
    e->ts.tv_sec = (time_t)(t_ns / 1000000000ull);
    e->ts.tv_nsec = (long)(t_ns % 1000000000ull);
    e->event_type = level ? GPIOD_LINE_EVENT_RISING_EDGE : GPIOD_LINE_EVENT_FALLING_EDGE;
    if (!line->signalled) {
        assert_int_equal(write(line->pipe[1], "e", 1), 1);
        line->signalled = 1;
    }
}

/* The chip goes away under the open lines: their descriptors hang up. */
static void fake_chip_unplug(void)
{
    fake_gpio.chip_present = 0;
    for (int i = 0; i < 2; i++) {
        close(fake_lines[i].pipe[1]);
        fake_lines[i].pipe[1] = -1;
    }
}

static struct kiosk_config *fake_gpio_config(enum kiosk_input_type type, const char *name)
{
    struct kiosk_config *c = config_with(type, name);
    struct kiosk_input *in = &c->inputs[0];
    snprintf(in->chip, sizeof in->chip, "fakechip");
    if (type == KIOSK_INPUT_GPIO_ENCODER) {
        in->line_a = in->line_b = -1;
        snprintf(in->line_a_name, sizeof in->line_a_name, "KNOB_A");
        snprintf(in->line_b_name, sizeof in->line_b_name, "KNOB_B");
    }
    return c;
}

/* An encoder whose chip comes late, whose line is first missing and then held by another
 * program, turned both ways once it is there, with edges too recent to be sure of held back a
 * drain, and whose chip then goes away. */
static void test_gpio_encoder_lifecycle(void **state)
{
    (void)state;
    memset(&fake_gpio, 0, sizeof fake_gpio);
    struct kiosk_config *c = fake_gpio_config(KIOSK_INPUT_GPIO_ENCODER, "mass_knob");
    struct memlog log;
    memlog_open(&log);
    struct input_event ev[16];
    struct pollfd fds[INPUT_MAX_FDS];
    struct input_source *src = input_open_gpio_api(&c->inputs[0], 0, log.f, 0.0, &fake_gpio_api);
    assert_non_null(src);
    assert_int_equal(src->present, 0);
    assert_string_equal(log.text, "input mass_knob: GPIO chip fakechip not found; looking for it every 1.5 s\n");
    assert_int_equal(src->fds(src, fds, INPUT_MAX_FDS), 0);

    /* the chip, without the line: still not found, not said again; then held by another program */
    fake_gpio.chip_present = 1;
    fake_gpio.line_missing = 1;
    assert_int_equal(src->drain(src, 1.0, ev, 16), 0);
    assert_int_equal(fake_gpio.opens, 0);
    assert_int_equal(src->drain(src, 1.5, ev, 16), 0);
    assert_int_equal(fake_gpio.opens, 1);
    assert_int_equal(fake_gpio.closes, 1);
    assert_int_equal(memlog_lines(&log), 1);
    fake_gpio.line_missing = 0;
    fake_gpio.busy = 1;
    assert_int_equal(src->drain(src, 3.0, ev, 16), 0);
    assert_int_equal(src->drain(src, 4.5, ev, 16), 0);
    assert_int_equal(memlog_lines(&log), 2);
    assert_non_null(strstr(log.text, "\ninput mass_knob: line KNOB_A of GPIO chip fakechip could not be "
                                     "requested: Device or resource busy, held by gpio-keys; trying again "
                                     "every 1.5 s\n"));
    fake_gpio.busy = 0;
    assert_int_equal(src->drain(src, 6.0, ev, 16), 0);
    assert_int_equal(src->present, 1);
    assert_int_equal(fake_gpio.requests, 2);
    assert_int_equal(memlog_lines(&log), 3);
    assert_non_null(strstr(log.text, "\ninput mass_knob: GPIO chip fakechip line KNOB_A and line KNOB_B "
                                     "connected\n"));
    assert_int_equal(src->fds(src, fds, INPUT_MAX_FDS), 2);
    assert_int_equal(fds[0].fd, fake_lines[0].pipe[0]);
    assert_int_equal(fds[1].fd, fake_lines[1].pipe[0]);
    assert_int_equal(fds[0].events, POLLIN);
    assert_int_equal(src->fds(src, fds, 1), 1);

    /* one detent clockwise (A leads B), then one counter-clockwise, a second ago */
    uint64_t t = now_ns(CLOCK_MONOTONIC) - 1000 * MS;
    fake_edge(0, 1, t + 10 * MS);
    fake_edge(1, 1, t + 12 * MS);
    fake_edge(0, 0, t + 14 * MS);
    fake_edge(1, 0, t + 16 * MS);
    fake_edge(1, 1, t + 30 * MS);
    fake_edge(0, 1, t + 32 * MS);
    fake_edge(1, 0, t + 34 * MS);
    fake_edge(0, 0, t + 36 * MS);
    double loop_now = seconds(t) + 1.0;
    assert_int_equal(drain_all(src, loop_now, ev, 16, 16), 2);
    assert_int_equal(ev[0].kind, INPUT_TURN);
    assert_int_equal(ev[0].counts, +1);
    assert_float_equal(ev[0].t, seconds(t + 16 * MS), 1e-6);
    assert_int_equal(ev[1].kind, INPUT_TURN);
    assert_int_equal(ev[1].counts, -1);
    assert_float_equal(ev[1].t, seconds(t + 36 * MS), 1e-6);

    /* edges stamped after the reads began wait for a later drain, then count (far enough ahead
     * that a slow run under valgrind still reads them before their time) */
    t = now_ns(CLOCK_MONOTONIC) + 300 * MS;
    fake_edge(0, 1, t);
    fake_edge(1, 1, t + 1 * MS);
    fake_edge(0, 0, t + 2 * MS);
    fake_edge(1, 0, t + 3 * MS);
    assert_int_equal(src->drain(src, clock_seconds(), ev, 16), 0);
    struct timespec pause = {0, 350 * 1000000L};
    nanosleep(&pause, NULL);
    assert_int_equal(src->drain(src, clock_seconds(), ev, 16), 1);
    assert_int_equal(ev[0].counts, +1);

    /* the chip goes away: said once, let go, looked for on the schedule */
    fake_chip_unplug();
    assert_int_equal(src->drain(src, 20.0, ev, 16), 0);
    assert_int_equal(src->present, 0);
    assert_int_equal(fake_gpio.closes, fake_gpio.opens);
    assert_int_equal(memlog_lines(&log), 4);
    assert_non_null(strstr(log.text, "\ninput mass_knob: disconnected (reading line KNOB_A of GPIO chip "
                                     "fakechip failed: No such device); looking for it every 1.5 s\n"));
    assert_int_equal(src->fds(src, fds, INPUT_MAX_FDS), 0);
    for (double now = 20.5; now < 26.0; now += 0.5)
        assert_int_equal(src->drain(src, now, ev, 16), 0);
    assert_int_equal(memlog_lines(&log), 4);
    input_close(src);
    assert_int_equal(fake_gpio.closes, fake_gpio.opens);
    memlog_close(&log);
    free(c);
}

/* A button to ground with a 20 ms debounce: a bouncy press counts once the line has been stable,
 * at the drain that sees it so, stamped when it settled; a release likewise. */
static void check_button(clockid_t kernel_clock)
{
    memset(&fake_gpio, 0, sizeof fake_gpio);
    fake_gpio.chip_present = 1;
    fake_gpio.levels[0] = 1;   /* released: pulled up */
    struct kiosk_config *c = fake_gpio_config(KIOSK_INPUT_GPIO_BUTTON, "next_button");
    struct memlog log;
    memlog_open(&log);
    struct input_event ev[16];
    uint64_t mono = now_ns(CLOCK_MONOTONIC) - 1000 * MS;
    uint64_t t = kernel_clock == CLOCK_MONOTONIC ? mono : now_ns(CLOCK_REALTIME) - 1000 * MS;
    double loop0 = seconds(mono);
    struct input_source *src = input_open_gpio_api(&c->inputs[0], 0, log.f, loop0, &fake_gpio_api);
    assert_non_null(src);
    assert_int_equal(src->present, 1);
    assert_string_equal(log.text, "input next_button: GPIO chip fakechip line BUTTON_NEXT connected\n");
    fake_edge(0, 0, t + 100 * MS);
    fake_edge(0, 1, t + 101 * MS);
    fake_edge(0, 0, t + 102 * MS);
    assert_int_equal(src->drain(src, loop0 + 0.110, ev, 16), 0);
    assert_int_equal(src->drain(src, loop0 + 0.121, ev, 16), 0);
    assert_int_equal(src->drain(src, loop0 + 0.123, ev, 16), 1);
    assert_int_equal(ev[0].kind, INPUT_PRESS);
    assert_int_equal(ev[0].bit, -1);
    assert_float_equal(ev[0].t, loop0 + 0.122, 2e-3);
    assert_int_equal(src->drain(src, loop0 + 0.200, ev, 16), 0);
    fake_edge(0, 1, t + 300 * MS);
    assert_int_equal(src->drain(src, loop0 + 0.310, ev, 16), 0);
    assert_int_equal(src->drain(src, loop0 + 0.330, ev, 16), 1);
    assert_int_equal(ev[0].kind, INPUT_RELEASE);
    assert_float_equal(ev[0].t, loop0 + 0.320, 2e-3);
    assert_int_equal(memlog_lines(&log), 1);
    input_close(src);
    assert_int_equal(fake_gpio.closes, 1);
    memlog_close(&log);
    free(c);
}

static void test_gpio_button_monotonic_stamps(void **state)
{
    (void)state;
    check_button(CLOCK_MONOTONIC);
}

/* Kernels before 5.7 stamp edges with the realtime clock: the same presses, on the loop's clock. */
static void test_gpio_button_realtime_stamps(void **state)
{
    (void)state;
    check_button(CLOCK_REALTIME);
}

/* ---------------------------------------------------------------- retry schedule and log */

/* Drained every 10 ms for 30 s: the device is looked for every INPUT_RETRY_SECONDS, never sooner,
 * and no later than the first drain after that. */
static void test_retry_schedule(void **state)
{
    (void)state;
    struct input_retry r;
    input_retry_init(&r, 10.0);
    double last = 10.0;
    int tries = 0;
    for (int k = 1001; k <= 4000; k++) {
        double now = k / 100.0;
        if (!input_retry_take(&r, now))
            continue;
        assert_true(now - last >= INPUT_RETRY_SECONDS - 1e-9);
        assert_true(now - last <= INPUT_RETRY_SECONDS + 0.01 + 1e-9);
        last = now;
        tries++;
    }
    assert_int_equal(tries, (int)(30.0 / INPUT_RETRY_SECONDS));
    /* due says so without recording it */
    input_retry_init(&r, 0.0);
    assert_false(input_retry_due(&r, 1.4));
    assert_true(input_retry_due(&r, 1.5));
    assert_true(input_retry_due(&r, 1.5));
    assert_true(input_retry_take(&r, 1.5));
    assert_false(input_retry_due(&r, 2.0));
    /* a clock that started again is not waited for */
    assert_true(input_retry_take(&r, 0.2));
    assert_false(input_retry_take(&r, 0.3));
}

static void test_retry_logs_each_absence_once(void **state)
{
    (void)state;
    struct kiosk_input in;
    memset(&in, 0, sizeof in);
    snprintf(in.name, sizeof in.name, "knob");
    struct memlog log;
    memlog_open(&log);
    struct input_source src;
    memset(&src, 0, sizeof src);
    src.cfg = &in;
    src.log = log.f;
    struct input_retry r;
    input_retry_init(&r, 0.0);
    input_retry_absent(&r, &src, INPUT_ABSENT_GONE, "PowerMate %04x:%04x not found", 0x077d, 0x0410);
    assert_int_equal(memlog_lines(&log), 1);
    assert_string_equal(log.text, "input knob: PowerMate 077d:0410 not found; looking for it every 1.5 s\n");
    input_retry_absent(&r, &src, INPUT_ABSENT_GONE, "PowerMate not found");
    input_retry_absent(&r, &src, INPUT_ABSENT_GONE, "disconnected");
    assert_int_equal(memlog_lines(&log), 1);
    /* plugged in but not usable: news */
    input_retry_absent(&r, &src, INPUT_ABSENT_REFUSED, "found but could not be opened");
    input_retry_absent(&r, &src, INPUT_ABSENT_REFUSED, "found but could not be opened");
    assert_int_equal(memlog_lines(&log), 2);
    assert_non_null(strstr(log.text, "could not be opened; trying again every 1.5 s\n"));
    input_retry_present(&r, &src, "connected");
    assert_int_equal(memlog_lines(&log), 3);
    assert_non_null(strstr(log.text, "\ninput knob: connected\n"));
    /* gone again after being back: a new absence */
    input_retry_absent(&r, &src, INPUT_ABSENT_GONE, "disconnected");
    input_retry_absent(&r, &src, INPUT_ABSENT_GONE, "not found");
    assert_int_equal(memlog_lines(&log), 4);
    /* no log at all is no failure */
    src.log = NULL;
    input_retry_absent(&r, &src, INPUT_ABSENT_REFUSED, "refused");
    memlog_close(&log);
}

/* ---------------------------------------------------------------- queue */

static void test_queue_keeps_what_does_not_fit(void **state)
{
    (void)state;
    struct input_queue *q = malloc(sizeof *q);
    assert_non_null(q);
    input_queue_clear(q);
    struct input_event e, out[INPUT_QUEUE_CAP];
    memset(&e, 0, sizeof e);
    for (int round = 0; round < 3; round++) {  /* across the ring's wrap */
        for (int i = 0; i < INPUT_QUEUE_CAP - 1; i++) {
            e.counts = i;
            assert_int_equal(input_queue_push(q, &e), 0);
        }
        assert_int_equal(input_queue_room(q), 1);
        assert_int_equal(input_queue_take(q, out, 3), 3);
        assert_int_equal(out[0].counts, 0);
        assert_int_equal(out[2].counts, 2);
        assert_int_equal(input_queue_take(q, out, INPUT_QUEUE_CAP), INPUT_QUEUE_CAP - 4);
        assert_int_equal(out[0].counts, 3);
        assert_int_equal(out[INPUT_QUEUE_CAP - 5].counts, INPUT_QUEUE_CAP - 2);
        assert_int_equal(input_queue_take(q, out, 4), 0);
    }
    for (int i = 0; i < INPUT_QUEUE_CAP; i++)
        assert_int_equal(input_queue_push(q, &e), 0);
    assert_int_equal(input_queue_push(q, &e), -1);
    free(q);
}

/* ---------------------------------------------------------------- HID readings to events */

/* The configuration's layout decodes the report the configuration describes. */
static void test_hid_layout_from_config(void **state)
{
    (void)state;
    struct kiosk_input in;
    memset(&in, 0, sizeof in);
    in.type = KIOSK_INPUT_HID;
    in.report_id = 3;
    in.report_length = 5;
    in.axis_offset = 1;
    in.axis_size = 2;
    in.axis_signed = 0;
    in.axis_mode = KIOSK_AXIS_ABSOLUTE;
    in.axis_min = 0;
    in.axis_max = 1000;
    in.button_offset = 3;
    in.buttons = 4;
    struct hid_layout l;
    struct error why;
    assert_int_equal(input_hid_layout(&in, &l, &why), 0);
    const uint8_t report[5] = {3, 0xf4, 0x01, 0xf5, 0};   /* 500; bits 0, 2 (and 4..7, not buttons) */
    struct knob_reading r;
    assert_int_equal(hid_decode(&l, report, sizeof report, &r), 1);
    assert_true(r.has_position);
    assert_float_equal(r.position, 0.5, 1e-12);
    assert_int_equal(r.buttons, 0x5u);
    const uint8_t other[5] = {4, 0, 0, 0, 0};
    assert_int_equal(hid_decode(&l, other, sizeof other, &r), 0);

    /* relative, signed, no report id */
    in.report_id = 0;
    in.axis_offset = 0;
    in.axis_size = 1;
    in.axis_signed = 1;
    in.axis_mode = KIOSK_AXIS_RELATIVE;
    in.axis_min = in.axis_max = 0;
    assert_int_equal(input_hid_layout(&in, &l, &why), 0);
    const uint8_t turn[5] = {0xfe, 0, 0, 0x02, 0};
    assert_int_equal(hid_decode(&l, turn, sizeof turn, &r), 1);
    assert_true(r.has_delta);
    assert_int_equal(r.delta, -2);
    assert_int_equal(r.buttons, 0x2u);

    /* what hid_layout_check refuses is refused with its reason */
    in.axis_size = 3;
    assert_int_equal(input_hid_layout(&in, &l, &why), -1);
    assert_non_null(strstr(why.message, "axis.size"));
}

static struct knob_reading reading(long delta, unsigned buttons)
{
    struct knob_reading r = {1, delta, 0, 0.0, buttons};
    return r;
}

static void test_hid_events_buttons(void **state)
{
    (void)state;
    struct input_hid_state s;
    input_hid_state_reset(&s);
    struct input_event ev[INPUT_HID_EVENTS_PER_READING];

    struct knob_reading r = reading(3, 0x5u);
    assert_int_equal(input_hid_events(&s, &r, 4, 0, 7, 2.5, ev), 3);
    assert_int_equal(ev[0].kind, INPUT_TURN);
    assert_int_equal(ev[0].counts, 3);
    assert_int_equal(ev[0].source, 7);
    assert_float_equal(ev[0].t, 2.5, 0.0);
    assert_int_equal(ev[0].bit, -1);
    assert_int_equal(ev[1].kind, INPUT_PRESS);
    assert_int_equal(ev[1].bit, 0);
    assert_int_equal(ev[2].kind, INPUT_PRESS);
    assert_int_equal(ev[2].bit, 2);

    /* held buttons are no news; a release is; no turn without a delta */
    r = reading(0, 0x4u);
    assert_int_equal(input_hid_events(&s, &r, 4, 0, 7, 2.6, ev), 1);
    assert_int_equal(ev[0].kind, INPUT_RELEASE);
    assert_int_equal(ev[0].bit, 0);
    assert_int_equal(input_hid_events(&s, &r, 4, 0, 7, 2.7, ev), 0);

    /* bits beyond the configured buttons are not buttons */
    r = reading(-1, 0x4u | 0x10u);
    assert_int_equal(input_hid_events(&s, &r, 4, 0, 7, 2.8, ev), 1);
    assert_int_equal(ev[0].kind, INPUT_TURN);
    assert_int_equal(ev[0].counts, -1);

    /* every button at once, both ways */
    r = reading(0, 0xffu);
    assert_int_equal(input_hid_events(&s, &r, 8, 0, 7, 2.9, ev), 7);
    r = reading(5, 0u);
    assert_int_equal(input_hid_events(&s, &r, 8, 0, 7, 3.0, ev), INPUT_HID_EVENTS_PER_READING);
    for (int i = 1; i < INPUT_HID_EVENTS_PER_READING; i++) {
        assert_int_equal(ev[i].kind, INPUT_RELEASE);
        assert_int_equal(ev[i].bit, i - 1);
    }
}

/* The PowerMate's one button: press and release with bit -1, from its own reports. */
static void test_powermate_press_release(void **state)
{
    (void)state;
    struct input_hid_state s;
    input_hid_state_reset(&s);
    struct input_event ev[INPUT_HID_EVENTS_PER_READING];
    struct knob_reading r;
    const uint8_t pressed_turned[6] = {0x01, 0xfd, 0, 0, 0, 0};
    const uint8_t released[6] = {0x00, 0x00, 0, 0, 0, 0};
    assert_int_equal(powermate_decode(pressed_turned, 6, &r), 1);
    assert_int_equal(input_hid_events(&s, &r, 1, 1, 0, 1.0, ev), 2);
    assert_int_equal(ev[0].kind, INPUT_TURN);
    assert_int_equal(ev[0].counts, -3);
    assert_int_equal(ev[1].kind, INPUT_PRESS);
    assert_int_equal(ev[1].bit, -1);
    assert_int_equal(powermate_decode(released, 6, &r), 1);
    assert_int_equal(input_hid_events(&s, &r, 1, 1, 0, 1.1, ev), 1);
    assert_int_equal(ev[0].kind, INPUT_RELEASE);
    assert_int_equal(ev[0].bit, -1);
    /* a device opened again starts from nothing down */
    assert_int_equal(powermate_decode(pressed_turned, 6, &r), 1);
    assert_int_equal(input_hid_events(&s, &r, 1, 1, 0, 1.2, ev), 2);
    input_hid_state_reset(&s);
    assert_int_equal(input_hid_events(&s, &r, 1, 1, 0, 1.3, ev), 2);
    assert_int_equal(ev[1].kind, INPUT_PRESS);
}

/* An absolute knob: its position is sent when it is new, not with every report. */
static void test_hid_events_position(void **state)
{
    (void)state;
    struct input_hid_state s;
    input_hid_state_reset(&s);
    struct input_event ev[INPUT_HID_EVENTS_PER_READING];
    struct knob_reading r = {0, 0, 1, 0.25, 0u};
    assert_int_equal(input_hid_events(&s, &r, 2, 0, 1, 0.0, ev), 1);
    assert_int_equal(ev[0].kind, INPUT_POSITION);
    assert_float_equal(ev[0].position, 0.25, 0.0);
    r.buttons = 0x2u;
    assert_int_equal(input_hid_events(&s, &r, 2, 0, 1, 0.1, ev), 1);
    assert_int_equal(ev[0].kind, INPUT_PRESS);
    assert_int_equal(ev[0].bit, 1);
    r.position = 0.0;
    assert_int_equal(input_hid_events(&s, &r, 2, 0, 1, 0.2, ev), 1);
    assert_int_equal(ev[0].kind, INPUT_POSITION);
    assert_float_equal(ev[0].position, 0.0, 0.0);
    input_hid_state_reset(&s);
    assert_int_equal(input_hid_events(&s, &r, 2, 0, 1, 0.3, ev), 2);   /* position and press again */
}

/* ---------------------------------------------------------------- GPIO edges to events */

/* The edges of a sequence of encoder states "AB AB ...", one every 2 ms from start_ns, split
 * into the two lines' streams as the kernel delivers them, then merged in time order. */
static size_t encoder_edges(const char *states, uint64_t start_ns, struct line_event *merged, size_t cap)
{
    struct line_event a[32], b[32];
    size_t na = 0, nb = 0;
    int prev_a = 0, prev_b = 0;
    uint64_t t = start_ns;
    for (const char *p = states; p[0] != '\0' && p[1] != '\0'; p += p[2] == ' ' ? 3 : 2) {
        int la = p[0] == '1', lb = p[1] == '1';
        if (la != prev_a)
            a[na++] = (struct line_event){t, INPUT_GPIO_LINE_A, la};
        if (lb != prev_b)
            b[nb++] = (struct line_event){t + (la != prev_a ? 1 : 0), INPUT_GPIO_LINE_B, lb};
        prev_a = la;
        prev_b = lb;
        t += 2 * MS;
        if (p[2] == '\0')
            break;
    }
    const struct line_event *streams[2] = {a, b};
    const size_t counts[2] = {na, nb};
    return event_merge(streams, counts, 2, merged, cap);
}

static void test_gpio_encoder_detents(void **state)
{
    (void)state;
    struct input_gpio_decoder g;
    struct line_event edges[64];
    struct input_event ev;
    const int64_t offset = 0;
    assert_int_equal(input_gpio_decoder_encoder(&g, 3, 4, 0, 0), 0);
    /* A leads B: clockwise, one detent at the cycle's last edge */
    size_t n = encoder_edges("10 11 01 00", 1000 * MS, edges, 64);
    assert_int_equal(n, 4);
    int turns = 0;
    for (size_t i = 0; i < n; i++) {
        int got = input_gpio_decoder_edge(&g, &edges[i], offset, &ev);
        assert_int_equal(got, i == 3);
        if (got) {
            turns++;
            assert_int_equal(ev.kind, INPUT_TURN);
            assert_int_equal(ev.counts, +1);
            assert_int_equal(ev.source, 3);
            assert_int_equal(ev.bit, -1);
            assert_float_equal(ev.t, 1.006, 1e-9);
        }
    }
    assert_int_equal(turns, 1);
    /* B leads A: counter-clockwise, two detents */
    n = encoder_edges("01 11 10 00 01 11 10 00", 2000 * MS, edges, 64);
    long sum = 0;
    for (size_t i = 0; i < n; i++)
        if (input_gpio_decoder_edge(&g, &edges[i], offset, &ev))
            sum += ev.counts;
    assert_int_equal(sum, -2);
    /* jitter on one line about a detent: nothing */
    n = encoder_edges("10 00 10 00", 3000 * MS, edges, 64);
    for (size_t i = 0; i < n; i++)
        assert_int_equal(input_gpio_decoder_edge(&g, &edges[i], offset, &ev), 0);
    /* one count per detent: an event per edge */
    assert_int_equal(input_gpio_decoder_encoder(&g, 3, 1, 0, 0), 0);
    n = encoder_edges("10 11 01 00", 4000 * MS, edges, 64);
    for (size_t i = 0; i < n; i++)
        assert_int_equal(input_gpio_decoder_edge(&g, &edges[i], offset, &ev), 1);
    assert_int_equal(input_gpio_decoder_poll(&g, 100.0, offset, &ev), 0);
    assert_int_equal(input_gpio_decoder_encoder(&g, 3, 3, 0, 0), -1);
}

/* A button wired to ground (active low), 20 ms debounce, its edges on a clock 5 s ahead of the
 * loop's: presses and releases once the line has been stable, stamped on the loop's clock. */
static void test_gpio_button_debounce(void **state)
{
    (void)state;
    struct input_gpio_decoder g;
    struct input_event ev;
    const int64_t offset = 5000 * (int64_t)MS;
    assert_int_equal(input_gpio_decoder_button(&g, 2, 20, 1, 1), 0);
    const struct line_event bouncy[] = {
        {5100 * MS, INPUT_GPIO_LINE_BUTTON, 0},
        {5101 * MS, INPUT_GPIO_LINE_BUTTON, 1},
        {5102 * MS, INPUT_GPIO_LINE_BUTTON, 0},
    };
    for (size_t i = 0; i < 3; i++)
        assert_int_equal(input_gpio_decoder_edge(&g, &bouncy[i], offset, &ev), 0);
    assert_int_equal(input_gpio_decoder_poll(&g, 0.110, offset, &ev), 0);  /* 8 ms stable */
    assert_int_equal(input_gpio_decoder_poll(&g, 0.122, offset, &ev), 1);
    assert_int_equal(ev.kind, INPUT_PRESS);
    assert_int_equal(ev.bit, -1);
    assert_int_equal(ev.source, 2);
    assert_float_equal(ev.t, 0.122, 1e-9);
    assert_int_equal(input_gpio_decoder_poll(&g, 0.200, offset, &ev), 0);  /* once */

    /* a 5 ms glitch while held is no release */
    const struct line_event glitch[] = {
        {5300 * MS, INPUT_GPIO_LINE_BUTTON, 1},
        {5305 * MS, INPUT_GPIO_LINE_BUTTON, 0},
    };
    for (size_t i = 0; i < 2; i++)
        assert_int_equal(input_gpio_decoder_edge(&g, &glitch[i], offset, &ev), 0);
    assert_int_equal(input_gpio_decoder_poll(&g, 0.400, offset, &ev), 0);

    /* a release that settled while nobody polled is told by the next edge, stamped when it settled */
    const struct line_event release = {5500 * MS, INPUT_GPIO_LINE_BUTTON, 1};
    const struct line_event press = {5700 * MS, INPUT_GPIO_LINE_BUTTON, 0};
    assert_int_equal(input_gpio_decoder_edge(&g, &release, offset, &ev), 0);
    assert_int_equal(input_gpio_decoder_edge(&g, &press, offset, &ev), 1);
    assert_int_equal(ev.kind, INPUT_RELEASE);
    assert_float_equal(ev.t, 0.520, 1e-9);
    assert_int_equal(input_gpio_decoder_poll(&g, 0.719, offset, &ev), 0);
    assert_int_equal(input_gpio_decoder_poll(&g, 0.720, offset, &ev), 1);
    assert_int_equal(ev.kind, INPUT_PRESS);

    /* an edge older than the last one is refused, and a loop time before the edge asks nothing */
    const struct line_event old = {5600 * MS, INPUT_GPIO_LINE_BUTTON, 1};
    assert_int_equal(input_gpio_decoder_edge(&g, &old, offset, &ev), 0);
    assert_int_equal(g.d.rejected, 1);
    const struct line_event late = {6000 * MS, INPUT_GPIO_LINE_BUTTON, 1};
    assert_int_equal(input_gpio_decoder_edge(&g, &late, offset, &ev), 0);
    assert_int_equal(input_gpio_decoder_poll(&g, 0.5, offset, &ev), 0);
    assert_int_equal(input_gpio_decoder_poll(&g, 1.020, offset, &ev), 1);
    assert_int_equal(ev.kind, INPUT_RELEASE);

    /* active high: the pressed level is 1 */
    assert_int_equal(input_gpio_decoder_button(&g, 2, 20, 0, 0), 0);
    const struct line_event up = {1000 * MS, INPUT_GPIO_LINE_BUTTON, 1};
    assert_int_equal(input_gpio_decoder_edge(&g, &up, 0, &ev), 0);
    assert_int_equal(input_gpio_decoder_poll(&g, 1.020, 0, &ev), 1);
    assert_int_equal(ev.kind, INPUT_PRESS);
    assert_int_equal(input_gpio_decoder_button(&g, 2, -1, 0, 0), -1);
}

/* Edges newer than the cutoff wait: only the oldest ones, up to it, are ready (across the wrap of
 * the 64-bit count too). */
static void test_gpio_ready(void **state)
{
    (void)state;
    const struct line_event edges[4] = {
        {100 * MS, 0, 1}, {200 * MS, 0, 0}, {300 * MS, 0, 1}, {400 * MS, 0, 0},
    };
    assert_int_equal(input_gpio_ready(edges, 4, 50 * MS), 0);
    assert_int_equal(input_gpio_ready(edges, 4, 100 * MS), 1);
    assert_int_equal(input_gpio_ready(edges, 4, 299 * MS), 2);
    assert_int_equal(input_gpio_ready(edges, 4, 400 * MS), 4);
    assert_int_equal(input_gpio_ready(edges, 2, 400 * MS), 2);
    assert_int_equal(input_gpio_ready(edges, 0, 400 * MS), 0);
    const struct line_event wrap[3] = {
        {UINT64_MAX - 5 * MS, 1, 1}, {UINT64_MAX, 1, 0}, {3 * MS, 1, 1},
    };
    assert_int_equal(input_gpio_ready(wrap, 3, 1 * MS), 2);
    assert_int_equal(input_gpio_ready(wrap, 3, UINT64_MAX - 6 * MS), 0);
    assert_int_equal(input_gpio_ready(wrap, 3, 3 * MS), 3);
}

static void test_gpio_clock(void **state)
{
    (void)state;
    const uint64_t mono = 86400ull * 1000000000ull;               /* up one day */
    const uint64_t real = 1700000000ull * 1000000000ull;          /* 2023 */
    assert_int_equal(input_gpio_clock_offset(mono - 3 * MS, mono, real), 0);
    assert_int_equal(input_gpio_clock_offset(real - 3 * MS, mono, real), (int64_t)(real - mono));
    int64_t offset = (int64_t)(real - mono);
    assert_float_equal(input_gpio_loop_time(real + 500 * MS, offset), 86400.5, 1e-6);
    assert_true(input_gpio_edge_time(86400.5, offset) == real + 500 * MS);
    assert_true(input_gpio_edge_time(2.0, 0) == 2000 * MS);
    assert_true(input_gpio_edge_time(-1.0, 0) == 0);
    assert_float_equal(input_gpio_loop_time(1 * MS, 3 * (int64_t)MS), -0.002, 1e-12);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_powermate_absent),
        cmocka_unit_test(test_hid_absent),
        cmocka_unit_test(test_gpio_encoder_absent),
        cmocka_unit_test(test_gpio_button_absent),
        cmocka_unit_test(test_hid_sources_share_hidapi),
        cmocka_unit_test(test_powermate_lifecycle),
        cmocka_unit_test(test_hid_box_reports),
        cmocka_unit_test(test_gpio_encoder_lifecycle),
        cmocka_unit_test(test_gpio_button_monotonic_stamps),
        cmocka_unit_test(test_gpio_button_realtime_stamps),
        cmocka_unit_test(test_retry_schedule),
        cmocka_unit_test(test_retry_logs_each_absence_once),
        cmocka_unit_test(test_queue_keeps_what_does_not_fit),
        cmocka_unit_test(test_hid_layout_from_config),
        cmocka_unit_test(test_hid_events_buttons),
        cmocka_unit_test(test_powermate_press_release),
        cmocka_unit_test(test_hid_events_position),
        cmocka_unit_test(test_gpio_encoder_detents),
        cmocka_unit_test(test_gpio_button_debounce),
        cmocka_unit_test(test_gpio_ready),
        cmocka_unit_test(test_gpio_clock),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
