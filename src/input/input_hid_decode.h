/* From a HID input's configuration to its report layout, and from decoded readings to the loop's
 * events: the part of the HID source that needs no device. */
#ifndef BT_KIOSK_INPUT_HID_DECODE_H
#define BT_KIOSK_INPUT_HID_DECODE_H
#include "input/hid_report.h"
#include "input/input.h"

/* The most events one reading gives: a turn or a position, and every button changed. */
#define INPUT_HID_EVENTS_PER_READING (1 + HID_MAX_BUTTONS)

/* The layout of an [input NAME] of type hid: its axis, and its `buttons` bits counted up from bit
 * 0 of byte button_offset (so bit i of the reading is the configuration's bit i). Returns 0, or -1
 * with the reason in e for a layout hid_layout_check refuses, which a checked configuration does
 * not give. */
int input_hid_layout(const struct kiosk_input *in, struct hid_layout *layout, struct error *e);

/* What the previous readings left: the buttons down, the last position sent. */
struct input_hid_state {
    unsigned buttons;
    int has_position;
    double position;
};

/* Nothing down, no position yet: the state of a device just opened. */
void input_hid_state_reset(struct input_hid_state *s);

/* The events of one reading, at time t from source `source`: INPUT_TURN for a non-zero delta,
 * INPUT_POSITION for the first position and every change of it, then INPUT_PRESS or INPUT_RELEASE
 * for each of the n_buttons bits that changed, lowest bit first, with bit = that bit, or -1 for
 * a single_button device (the PowerMate). Writes at most INPUT_HID_EVENTS_PER_READING events to
 * out (its room); returns how many. */
int input_hid_events(struct input_hid_state *s, const struct knob_reading *r, int n_buttons, int single_button,
                     int source, double t, struct input_event *out);

#endif
