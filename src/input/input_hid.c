/* The PowerMate and other HID knobs, read through hidapi's libusb back-end. Through hidraw the
 * PowerMate is out of reach: the kernel's powermate driver claims it as an input device, and
 * libusb detaches that driver when the device is opened. hidapi-libusb reads in a thread of its
 * own and offers no descriptor to poll, so fds() gives none and drain(), called every frame,
 * takes what the thread has queued without waiting. */
#include "input/input_hid.h"
#include "input/input_hid_decode.h"
#include "input/input_queue.h"
#include "input/input_retry.h"
#include <stdlib.h>

/* Bytes asked for per read: a full-speed interrupt report is at most 64, a high-speed one 1024. */
#define HID_READ_BYTES 1024

struct hid_source {
    const struct input_hid_api *api;
    int is_powermate;
    struct hid_layout layout;        /* hid: where the axis and the buttons lie */
    int layout_ok;                   /* hid: the layout passed hid_layout_check */
    char layout_why[sizeof ((struct error *)0)->message];
    int n_buttons;
    hid_device *dev;                 /* NULL while absent */
    struct input_hid_state state;
    struct input_retry retry;
    struct input_queue queue;
};

/* Sources holding hidapi: libusb's context lives from the first open to the last close, so that
 * hid_exit frees it once nothing reads. The kiosk opens and drains its sources on one thread. */
static int libusb_users;

const struct input_hid_api input_hid_libusb = {
    &libusb_users, hid_init, hid_exit, hid_enumerate, hid_free_enumeration, hid_open_path,
    hid_set_nonblocking, hid_read_timeout, hid_close,
};

static const char *device_kind(const struct hid_source *s)
{
    return s->is_powermate ? "PowerMate" : "HID device";
}

/* Looks for the device now: present and "connected" logged, or absent with its reason logged
 * (once). hid_open would open the first device with these ids even when another input already
 * holds it; every match is tried instead, so that two PowerMates serve two inputs. Which input
 * gets which follows the order of enumeration: the configuration cannot tell them apart. */
static int hid_source_open(struct input_source *src, struct hid_source *s)
{
    const struct kiosk_input *in = src->cfg;
    if (!s->is_powermate && !s->layout_ok) {
        input_retry_absent(&s->retry, src, INPUT_ABSENT_REFUSED, "the report layout is not usable (%s)",
                           s->layout_why);
        return -1;
    }
    struct hid_device_info *found = s->api->enumerate((unsigned short)in->vid, (unsigned short)in->pid);
    for (const struct hid_device_info *d = found; d != NULL && s->dev == NULL; d = d->next)
        s->dev = s->api->open_path(d->path);
    int any_found = found != NULL;
    s->api->free_enumeration(found);
    if (s->dev == NULL) {
        if (any_found)
            input_retry_absent(&s->retry, src, INPUT_ABSENT_REFUSED,
                               "%s %04x:%04x found but could not be opened (held by another input or "
                               "program, or no permission: the kiosk's user needs its /dev/bus/usb node, "
                               "see kiosk/99-bentray.rules)", device_kind(s), in->vid, in->pid);
        else
            input_retry_absent(&s->retry, src, INPUT_ABSENT_GONE, "%s %04x:%04x not found",
                               device_kind(s), in->vid, in->pid);
        return -1;
    }
    s->api->set_nonblocking(s->dev, 1);
    input_hid_state_reset(&s->state);
    src->present = 1;
    input_retry_present(&s->retry, src, "%s %04x:%04x connected", device_kind(s), in->vid, in->pid);
    return 0;
}

/* The device stopped answering (unplugged): closed, said once, looked for again from now on.
 * Buttons held at that moment are forgotten without a release: the loop acts on presses only,
 * and the device starts from "nothing down" when it is back. */
static void hid_source_lost(struct input_source *src, struct hid_source *s, double now)
{
    const struct kiosk_input *in = src->cfg;
    s->api->close(s->dev);
    s->dev = NULL;
    src->present = 0;
    input_retry_init(&s->retry, now);
    input_retry_absent(&s->retry, src, INPUT_ABSENT_GONE, "%s %04x:%04x disconnected (reading failed)",
                       device_kind(s), in->vid, in->pid);
}

/* Reads reports while the queue has room for the events of one more. */
static void hid_source_read(struct input_source *src, struct hid_source *s, double now)
{
    unsigned char report[HID_READ_BYTES];
    while (s->dev != NULL && input_queue_room(&s->queue) >= INPUT_HID_EVENTS_PER_READING) {
        int got = s->api->read_timeout(s->dev, report, sizeof report, 0);
        if (got == 0)
            return;
        if (got < 0) {
            hid_source_lost(src, s, now);
            return;
        }
        struct knob_reading r;
        int rc = s->is_powermate ? powermate_decode(report, (size_t)got, &r)
                                 : hid_decode(&s->layout, report, (size_t)got, &r);
        if (rc != 1)
            continue;   /* another report of the device, or a short one: nothing of the knob's */
        struct input_event ev[INPUT_HID_EVENTS_PER_READING];
        int n = input_hid_events(&s->state, &r, s->n_buttons, s->is_powermate, src->index, now, ev);
        for (int i = 0; i < n; i++)
            input_queue_push(&s->queue, &ev[i]);
    }
}

static int hid_source_fds(struct input_source *src, struct pollfd *out, int max)
{
    (void)src, (void)out, (void)max;
    return 0;
}

static int hid_source_drain(struct input_source *src, double now, struct input_event *out, int max)
{
    struct hid_source *s = src->priv;
    int n = input_queue_take(&s->queue, out, max);
    if (s->queue.count > 0)
        return n;
    if (s->dev == NULL && (!input_retry_take(&s->retry, now) || hid_source_open(src, s) != 0))
        return n;
    hid_source_read(src, s, now);
    return n + input_queue_take(&s->queue, out + n, max - n);
}

static void hid_source_close(struct input_source *src)
{
    struct hid_source *s = src->priv;
    const struct input_hid_api *api = s->api;
    if (s->dev != NULL)
        api->close(s->dev);
    free(s);
    src->priv = NULL;
    if (--*api->users == 0)
        api->exit();
}

struct input_source *input_open_hid(const struct kiosk_input *in, int index, FILE *log, double now)
{
    return input_open_hid_api(in, index, log, now, &input_hid_libusb);
}

struct input_source *input_open_hid_api(const struct kiosk_input *in, int index, FILE *log, double now,
                                        const struct input_hid_api *api)
{
    if (in->type != KIOSK_INPUT_POWERMATE && in->type != KIOSK_INPUT_HID)
        return NULL;
    struct input_source *src = input_source_new(in, index, log, sizeof(struct hid_source), hid_source_fds,
                                                hid_source_drain, hid_source_close);
    if (src == NULL)
        return NULL;
    struct hid_source *s = src->priv;
    s->api = api;
    s->is_powermate = in->type == KIOSK_INPUT_POWERMATE;
    s->n_buttons = s->is_powermate ? 1 : in->buttons;
    if (!s->is_powermate) {
        struct error refused;
        s->layout_ok = input_hid_layout(in, &s->layout, &refused) == 0;
        if (!s->layout_ok)
            snprintf(s->layout_why, sizeof s->layout_why, "%s", refused.message);
    }
    input_queue_clear(&s->queue);
    input_retry_init(&s->retry, now);
    /* a failure here is not fatal: hidapi's enumeration tries hid_init again at every look */
    if ((*api->users)++ == 0)
        api->init();
    hid_source_open(src, s);
    return src;
}
