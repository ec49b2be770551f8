/* Apart from input.c, which opens the devices, so that the decoders that need no device (and
 * their tests) do not bring the sources with them. */
#include "input/input.h"
#include <string.h>

struct input_event input_event_at(enum input_event_kind kind, int source, double t)
{
    struct input_event e;
    memset(&e, 0, sizeof e);
    e.t = t;
    e.kind = kind;
    e.source = source;
    e.bit = -1;
    return e;
}
