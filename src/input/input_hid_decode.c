/* Positions are sent on change only: a report carries the axis whatever made the device send it
 * (often a button), and an unchanged position counted as a turn of the knob would keep the kiosk
 * out of attract mode and its frame in preview. */
#include "input/input_hid_decode.h"
#include <string.h>

int input_hid_layout(const struct kiosk_input *in, struct hid_layout *layout, struct error *e)
{
    memset(layout, 0, sizeof *layout);
    layout->report_id = (uint8_t)in->report_id;
    layout->report_len = in->report_length > 0 ? (size_t)in->report_length : 0;
    layout->axis.kind = in->axis_mode == KIOSK_AXIS_ABSOLUTE ? HID_AXIS_ABSOLUTE : HID_AXIS_RELATIVE;
    layout->axis.offset = in->axis_offset > 0 ? (size_t)in->axis_offset : 0;
    layout->axis.size = in->axis_size;
    layout->axis.is_signed = in->axis_signed;
    layout->axis.logical_min = in->axis_min;
    layout->axis.logical_max = in->axis_max;
    layout->n_buttons = in->buttons;
    for (int i = 0; i < in->buttons && i < HID_MAX_BUTTONS; i++) {
        layout->buttons[i].offset = in->button_offset > 0 ? (size_t)in->button_offset : 0;
        layout->buttons[i].bit = i;
    }
    return hid_layout_check(layout, e);
}

void input_hid_state_reset(struct input_hid_state *s)
{
    s->buttons = 0;
    s->has_position = 0;
    s->position = 0.0;
}

int input_hid_events(struct input_hid_state *s, const struct knob_reading *r, int n_buttons, int single_button,
                     int source, double t, struct input_event *out)
{
    int n = 0;
    if (r->has_delta && r->delta != 0) {
        out[n] = input_event_at(INPUT_TURN, source, t);
        out[n++].counts = r->delta;
    }
    if (r->has_position && (!s->has_position || r->position != s->position)) {
        out[n] = input_event_at(INPUT_POSITION, source, t);
        out[n++].position = r->position;
        s->has_position = 1;
        s->position = r->position;
    }
    if (n_buttons > HID_MAX_BUTTONS)
        n_buttons = HID_MAX_BUTTONS;
    for (int i = 0; i < n_buttons; i++) {
        unsigned mask = 1u << i;
        if ((r->buttons & mask) == (s->buttons & mask))
            continue;
        out[n] = input_event_at(r->buttons & mask ? INPUT_PRESS : INPUT_RELEASE, source, t);
        out[n++].bit = single_button ? -1 : i;
        s->buttons ^= mask;
    }
    return n;
}
