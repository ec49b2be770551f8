/* HID input reports (as read from /dev/hidraw*) of the kiosk's knobs, decoded into one reading:
 * the Griffin PowerMate, and any other device described by a layout of where its axis and
 * buttons lie. */
#ifndef BT_KIOSK_HID_REPORT_H
#define BT_KIOSK_HID_REPORT_H
#include <stddef.h>
#include <stdint.h>
#include "io/error.h"

struct knob_reading {
    int has_delta;
    long delta;         /* a relative axis: counts turned since the last report, clockwise > 0
                           as the device reports it */
    int has_position;
    double position;    /* an absolute axis: 0 at the logical minimum, 1 at the maximum */
    unsigned buttons;   /* bit i set: button i is down */
};

/* PowerMate: byte 0 bit 0 is the button, byte 1 the rotation since the last report as a signed
 * byte (two's complement). Returns 1 with *out written, -1 for a report shorter than 2 bytes. */
int powermate_decode(const uint8_t *report, size_t len, struct knob_reading *out);

#define HID_MAX_BUTTONS 8

enum hid_axis_kind {
    HID_AXIS_NONE = 0,      /* buttons only */
    HID_AXIS_RELATIVE,      /* the value is a delta */
    HID_AXIS_ABSOLUTE,      /* the value is a position in [logical_min, logical_max] */
};

/* Offsets are byte positions in the report as read, the report id byte (when there is one) being
 * byte 0. */
struct hid_axis {
    enum hid_axis_kind kind;
    size_t offset;
    int size;               /* 1, 2 or 4 bytes, little-endian (as HID sends them) */
    int is_signed;          /* two's complement */
    int64_t logical_min;    /* absolute axes: mapped to 0 */
    int64_t logical_max;    /* absolute axes: mapped to 1; values beyond the range are clamped */
};

struct hid_button_bit {
    size_t offset;
    int bit;                /* 0 is the least significant */
};

struct hid_layout {
    uint8_t report_id;      /* 0: the device sends reports without an id byte */
    size_t report_len;      /* bytes in a report, the id byte included */
    struct hid_axis axis;
    int n_buttons;          /* 0 to HID_MAX_BUTTONS: button i sets bit i of the reading */
    struct hid_button_bit buttons[HID_MAX_BUTTONS];
};

/* Returns 0 for a usable layout; else -1 with a message naming the field in e (ERROR_INPUT, no
 * place; e may be NULL where no message is wanted): an axis size other than 1, 2 or 4, a field
 * beyond report_len or on the report id byte, a bit outside 0..7, logical_min >= logical_max on an
 * absolute axis. */
int hid_layout_check(const struct hid_layout *l, struct error *e);

/* Decodes one report. Returns 1 with *out written; 0 when the report starts with another report id
 * (another of the device's reports: not for this layout); -1 when it is shorter than report_len or
 * the layout fails hid_layout_check. Never reads past len; *out is written only on 1. */
int hid_decode(const struct hid_layout *l, const uint8_t *report, size_t len, struct knob_reading *out);

/* An absolute axis that wraps (a position counter of `bits` bits, 1 to 32): the shortest signed
 * difference from previous to current modulo 2^bits, bits above `bits` ignored. So on 8 bits
 * 250 -> 3 is +9 and 3 -> 250 is -9. The tie, half a turn of the counter, is negative (-2^(bits-1)),
 * as the difference read as a two's-complement number of `bits` bits; between polls the kiosk must
 * see less than half the counter's range go by. Returns 0 for bits outside 1..32. */
long counter_delta(uint32_t previous, uint32_t current, int bits);

#endif
