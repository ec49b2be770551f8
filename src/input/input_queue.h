/* Decoded events a device source holds until the loop has room for them. One read of a device can
 * give more events than the loop asked for (a report with a turn and several buttons, a burst of
 * encoder edges), and input.h promises that what does not fit is kept for the next call. */
#ifndef BT_KIOSK_INPUT_QUEUE_H
#define BT_KIOSK_INPUT_QUEUE_H
#include "input/input.h"

/* Enough for one batch of either device source: 2 GPIO lines x 64 edges, one event each, and a
 * debounce poll; or many times the 9 events of one HID report. */
#define INPUT_QUEUE_CAP 160

struct input_queue {
    struct input_event events[INPUT_QUEUE_CAP];
    int head;                        /* index of the oldest event */
    int count;
};

void input_queue_clear(struct input_queue *q);
int input_queue_room(const struct input_queue *q);
/* Appends e; returns -1, dropping it, when the queue is full (the sources check the room first). */
int input_queue_push(struct input_queue *q, const struct input_event *e);
/* Moves the oldest events, at most max, to out; returns how many. */
int input_queue_take(struct input_queue *q, struct input_event *out, int max);

#endif
