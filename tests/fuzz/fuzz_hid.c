/* libFuzzer harness: the HID report decoders (src/input/hid_report.h), fed what a knob, a worn-out
 * button box or a layout typed into the kiosk's configuration may send them.
 *
 * Input, little-endian, missing bytes read as 0:
 *   counter_delta:   previous (4), current (4), bits (1, signed)
 *   layout:          report_id (1), report_len (1), flags (1), axis kind (1), axis offset (1),
 *                    axis size (1, signed), is_signed (1), logical_min (8), logical_max (8),
 *                    n_buttons (1), then for each of the HID_MAX_BUTTONS buttons offset (1), bit (1);
 *                    flags: bit 0 report_len = SIZE_MAX - byte, bit 1 likewise the axis offset,
 *                    bit 2 a button offset, bits 3 and 4 logical_min and logical_max only 16-bit
 *   (1):             a byte the corpus carries, unused (it sized a message buffer)
 *   the report:      the rest, as read from /dev/hidraw (the decoders are given exactly these bytes)
 *
 * hid_layout_check() runs on every layout (with an error and without, one answer; a refusal carries
 * a message of the input's kind, ERROR_INPUT); hid_decode() only on
 * layouts it accepts, and its reading is checked against the bytes: the result code the header
 * promises, a relative value that is the field as the layout reads it, a position in [0, 1], button
 * bits as in the report and none beyond n_buttons. powermate_decode() gets the report too, and
 * counter_delta() is checked against its definition (the shortest difference modulo 2^bits). */
#include <limits.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include "input/hid_report.h"

#include "fuzz_bytes.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);


/* the int64_t with these two's-complement bits, without an implementation-defined conversion */
static int64_t as_signed(uint64_t u, int bits)
{
    uint64_t sign = (uint64_t)1 << (bits - 1);
    uint64_t mask = bits == 64 ? UINT64_MAX : ((uint64_t)1 << bits) - 1;
    u &= mask;
    return u & sign ? -(int64_t)(~u & mask) - 1 : (int64_t)u;
}

static void fuzz_counter_delta(struct bytes *in)
{
    uint32_t previous = (uint32_t)take(in, 4), current = (uint32_t)take(in, 4);
    int bits = (int)as_signed(take(in, 1), 8);
    long d = counter_delta(previous, current, bits);
    if (bits < 1 || bits > 32) {
        if (d != 0)
            __builtin_trap();
        return;
    }
    int64_t half = (int64_t)1 << (bits - 1);
    uint64_t mask = bits == 32 ? UINT32_MAX : ((uint64_t)1 << bits) - 1;
    if (d < -half || d > half - 1)
        __builtin_trap();
    if ((((uint64_t)previous + (uint64_t)(int64_t)d) & mask) != ((uint64_t)current & mask))
        __builtin_trap();
}

static void fuzz_powermate(const uint8_t *report, size_t len)
{
    struct knob_reading r;
    memset(&r, 0xa5, sizeof r);
    int rc = powermate_decode(report, len, &r);
    if (len < 2) {
        if (rc != -1)
            __builtin_trap();
        return;
    }
    if (rc != 1 || r.has_delta != 1 || r.has_position != 0 || r.buttons != (report[0] & 1u) ||
        r.delta != (long)as_signed(report[1], 8))
        __builtin_trap();
}

static void read_layout(struct bytes *in, struct hid_layout *l)
{
    memset(l, 0, sizeof *l);
    l->report_id = (uint8_t)take(in, 1);
    uint64_t len = take(in, 1);
    unsigned flags = (unsigned)take(in, 1);
    l->report_len = flags & 1u ? SIZE_MAX - (size_t)len : (size_t)len;
    l->axis.kind = (enum hid_axis_kind)(take(in, 1) % 4);    /* 3: not a kind */
    uint64_t offset = take(in, 1);
    l->axis.offset = flags & 2u ? SIZE_MAX - (size_t)offset : (size_t)offset;
    l->axis.size = (int)as_signed(take(in, 1), 8);
    l->axis.is_signed = (int)(take(in, 1) & 1u);
    l->axis.logical_min = flags & 8u ? as_signed(take(in, 2), 16) : as_signed(take(in, 8), 64);
    l->axis.logical_max = flags & 16u ? as_signed(take(in, 2), 16) : as_signed(take(in, 8), 64);
    l->n_buttons = (int)as_signed(take(in, 1), 8);
    for (int i = 0; i < HID_MAX_BUTTONS; i++) {
        uint64_t at = take(in, 1);
        l->buttons[i].offset = flags & 4u ? SIZE_MAX - (size_t)at : (size_t)at;
        l->buttons[i].bit = (int)as_signed(take(in, 1), 8);
    }
}

/* The axis field as the layout describes it, read here byte by byte. */
static int64_t field_value(const struct hid_layout *l, const uint8_t *report)
{
    uint64_t v = 0;
    for (int i = 0; i < l->axis.size; i++)
        v |= (uint64_t)report[l->axis.offset + (size_t)i] << (8 * i);
    return l->axis.is_signed ? as_signed(v, 8 * l->axis.size) : (int64_t)v;
}

static void fuzz_decode(const struct hid_layout *l, const uint8_t *report, size_t len)
{
    struct knob_reading r, untouched;
    memset(&r, 0x5a, sizeof r);
    untouched = r;
    int rc = hid_decode(l, report, len, &r);

    if (l->report_id != 0 && len >= 1 && report[0] != l->report_id) {
        if (rc != 0 || memcmp(&r, &untouched, sizeof r) != 0)
            __builtin_trap();
        return;
    }
    if (len < l->report_len) {
        if (rc != -1 || memcmp(&r, &untouched, sizeof r) != 0)
            __builtin_trap();
        return;
    }
    if (rc != 1)
        __builtin_trap();
    switch (l->axis.kind) {
    case HID_AXIS_NONE:
        if (r.has_delta || r.has_position)
            __builtin_trap();
        break;
    case HID_AXIS_RELATIVE:
        if (r.has_delta != 1 || r.has_position || r.delta != field_value(l, report))
            __builtin_trap();
        break;
    case HID_AXIS_ABSOLUTE:
        /* NaN fails both comparisons */
        if (r.has_position != 1 || r.has_delta || !(r.position >= 0.0 && r.position <= 1.0))
            __builtin_trap();
        {
            int64_t v = field_value(l, report);
            if ((v <= l->axis.logical_min && r.position != 0.0) ||
                (v >= l->axis.logical_max && r.position != 1.0))
                __builtin_trap();
        }
        break;
    default:
        __builtin_trap();   /* hid_layout_check accepted a kind that is none of the three */
    }
    for (int i = 0; i < HID_MAX_BUTTONS; i++) {
        unsigned bit = r.buttons >> i & 1u;
        unsigned want = i < l->n_buttons ? report[l->buttons[i].offset] >> l->buttons[i].bit & 1u : 0u;
        if (bit != want)
            __builtin_trap();
    }
    if (r.buttons >> HID_MAX_BUTTONS != 0)
        __builtin_trap();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct bytes in = {data, size};
    struct hid_layout l;

    fuzz_counter_delta(&in);
    read_layout(&in, &l);
    (void)take(&in, 1);
    /* the rest is the report: the decoders get exactly these bytes, so that ASan sees a read past */
    const uint8_t *report = in.p;
    size_t len = in.n;

    struct error why;
    int ok = hid_layout_check(&l, &why);
    if (hid_layout_check(&l, NULL) != ok)
        __builtin_trap();
    if (ok != 0 && ok != -1)
        __builtin_trap();
    if (ok != 0 && (why.message[0] == '\0' || why.status != ERROR_INPUT ||
                    memchr(why.message, '\0', sizeof why.message) == NULL))
        __builtin_trap();
    if (ok == 0 && why.status != ERROR_NONE)
        __builtin_trap();

    fuzz_powermate(report, len);
    if (ok == 0)
        fuzz_decode(&l, report, len);
    return 0;
}
