#include "io/clock.h"
#include <time.h>

double clock_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double started;

void clock_mark_start(void)
{
    started = clock_seconds();
}

double clock_since_start(void)
{
    return started > 0.0 ? clock_seconds() - started : 0.0;
}
