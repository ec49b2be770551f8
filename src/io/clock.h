/* The one clock of timings and timeouts: CLOCK_MONOTONIC in seconds (never steps with the wall clock). */
#ifndef BT_CLOCK_H
#define BT_CLOCK_H

double clock_seconds(void);

#endif
