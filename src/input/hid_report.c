/* HID reports are little-endian and two's complement whatever the host: values are assembled byte
 * by byte and sign-extended by arithmetic, without relying on the host's byte order or on the
 * implementation-defined conversion of large unsigned values to signed types. */
#include "input/hid_report.h"

#include <limits.h>
#include <stdarg.h>
#include <stdio.h>

#define POWERMATE_MIN_LEN 2
#define POWERMATE_BUTTON_BIT 0x01
#define BITS_PER_BYTE 8

/* the value of an n-bit two's-complement number given by its bits */
static int64_t sign_extend(uint64_t value, int bits)
{
    uint64_t sign = (uint64_t)1 << (bits - 1);
    return value & sign ? (int64_t)(value - sign) - (int64_t)sign : (int64_t)value;
}

int powermate_decode(const uint8_t *report, size_t len, struct knob_reading *out)
{
    if (report == NULL || len < POWERMATE_MIN_LEN)
        return -1;
    out->has_delta = 1;
    out->delta = (long)sign_extend(report[1], BITS_PER_BYTE);
    out->has_position = 0;
    out->position = 0.0;
    out->buttons = report[0] & POWERMATE_BUTTON_BIT;
    return 1;
}

/* a field of `size` bytes at `offset` lies inside the report and off its id byte */
static int field_fits(const struct hid_layout *l, size_t offset, size_t size)
{
    size_t first = l->report_id != 0 ? 1 : 0;
    return offset >= first && offset <= l->report_len && size <= l->report_len - offset;
}

/* why a field does not fit: the id byte, or the report's end */
static const char *misfit(const struct hid_layout *l, size_t offset)
{
    return l->report_id != 0 && offset == 0 ? "on the report id byte" : "past the end of the report";
}

/* The layout's refusal, in e where the caller wants one (e may be NULL): -1. */
__attribute__((format(printf, 2, 3)))
static int refuse(struct error *e, const char *fmt, ...)
{
    if (e != NULL) {
        char message[sizeof e->message];
        va_list args;
        va_start(args, fmt);
        vsnprintf(message, sizeof message, fmt, args);
        va_end(args);
        error_set(e, ERROR_INPUT, NULL, "%s", message);
    }
    return -1;
}

static int axis_check(const struct hid_layout *l, struct error *e)
{
    const struct hid_axis *x = &l->axis;
    if (x->kind == HID_AXIS_NONE)
        return 0;
    if (x->kind != HID_AXIS_RELATIVE && x->kind != HID_AXIS_ABSOLUTE)
        return refuse(e, "axis.kind %d: not none, relative or absolute", (int)x->kind);
    if (x->size != 1 && x->size != 2 && x->size != 4)
        return refuse(e, "axis.size %d: must be 1, 2 or 4 bytes", x->size);
    if (!field_fits(l, x->offset, (size_t)x->size))
        return refuse(e, "axis.offset %zu, size %d: %s (report_len %zu)", x->offset,
                      x->size, misfit(l, x->offset), l->report_len);
#if LONG_MAX < UINT32_MAX
    /* an unsigned 4-byte delta does not fit the reading's long on this host */
    if (x->kind == HID_AXIS_RELATIVE && x->size == 4 && !x->is_signed)
        return refuse(e, "axis.is_signed: an unsigned 4-byte delta does not fit a long");
#endif
    if (x->kind == HID_AXIS_ABSOLUTE && x->logical_min >= x->logical_max)
        return refuse(e, "axis.logical_min %lld: not below axis.logical_max %lld",
                      (long long)x->logical_min, (long long)x->logical_max);
    return 0;
}

int hid_layout_check(const struct hid_layout *l, struct error *e)
{
    if (e != NULL)
        error_clear(e);
    if (l->report_len == 0 || (l->report_id != 0 && l->report_len < 2))
        return refuse(e, "report_len %zu: no room for a field", l->report_len);
    if (axis_check(l, e) != 0)
        return -1;
    if (l->n_buttons < 0 || l->n_buttons > HID_MAX_BUTTONS)
        return refuse(e, "n_buttons %d: 0 to %d", l->n_buttons, HID_MAX_BUTTONS);
    for (int i = 0; i < l->n_buttons; i++) {
        const struct hid_button_bit *b = &l->buttons[i];
        if (!field_fits(l, b->offset, 1))
            return refuse(e, "buttons[%d].offset %zu: %s (report_len %zu)", i, b->offset,
                          misfit(l, b->offset), l->report_len);
        if (b->bit < 0 || b->bit >= BITS_PER_BYTE)
            return refuse(e, "buttons[%d].bit %d: must be 0..7", i, b->bit);
    }
    return 0;
}

static uint64_t little_endian(const uint8_t *bytes, int size)
{
    uint64_t v = 0;
    for (int i = size - 1; i >= 0; i--)
        v = v << BITS_PER_BYTE | bytes[i];
    return v;
}

static double clamp01(double x)
{
    return x < 0.0 ? 0.0 : x > 1.0 ? 1.0 : x;
}

int hid_decode(const struct hid_layout *l, const uint8_t *report, size_t len, struct knob_reading *out)
{
    if (report == NULL || hid_layout_check(l, NULL) != 0)
        return -1;
    if (l->report_id != 0 && len >= 1 && report[0] != l->report_id)
        return 0;
    if (len < l->report_len)
        return -1;
    struct knob_reading r = {0, 0, 0, 0.0, 0u};
    const struct hid_axis *x = &l->axis;
    if (x->kind != HID_AXIS_NONE) {
        uint64_t bits = little_endian(report + x->offset, x->size);
        int64_t v = x->is_signed ? sign_extend(bits, x->size * BITS_PER_BYTE) : (int64_t)bits;
        if (x->kind == HID_AXIS_RELATIVE) {
            r.has_delta = 1;
            r.delta = (long)v;
        } else {
            r.has_position = 1;
            r.position = clamp01(((double)v - (double)x->logical_min) /
                                 ((double)x->logical_max - (double)x->logical_min));
        }
    }
    for (int i = 0; i < l->n_buttons; i++)
        if (report[l->buttons[i].offset] >> l->buttons[i].bit & 1u)
            r.buttons |= 1u << i;
    *out = r;
    return 1;
}

long counter_delta(uint32_t previous, uint32_t current, int bits)
{
    if (bits < 1 || bits > 32)
        return 0;
    uint64_t modulus = (uint64_t)1 << bits;
    uint64_t forward = ((uint64_t)current - previous) & (modulus - 1);
    return (long)sign_extend(forward, bits);
}
