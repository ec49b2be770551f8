/* A ring, so that taking a few events from the front costs no moving of the rest. */
#include "input/input_queue.h"

void input_queue_clear(struct input_queue *q)
{
    q->head = 0;
    q->count = 0;
}

int input_queue_room(const struct input_queue *q)
{
    return INPUT_QUEUE_CAP - q->count;
}

int input_queue_push(struct input_queue *q, const struct input_event *e)
{
    if (q->count >= INPUT_QUEUE_CAP)
        return -1;
    q->events[(q->head + q->count) % INPUT_QUEUE_CAP] = *e;
    q->count++;
    return 0;
}

int input_queue_take(struct input_queue *q, struct input_event *out, int max)
{
    int n = 0;
    while (n < max && q->count > 0) {
        out[n++] = q->events[q->head];
        q->head = (q->head + 1) % INPUT_QUEUE_CAP;
        q->count--;
    }
    return n;
}
