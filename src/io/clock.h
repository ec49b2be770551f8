/* The one clock of timings and timeouts: CLOCK_MONOTONIC in seconds (never steps with the wall clock). */
#ifndef BT_CLOCK_H
#define BT_CLOCK_H

double clock_seconds(void);
/* Marks the process's start (main calls it first); clock_since_start: seconds since then. */
void clock_mark_start(void);
double clock_since_start(void);

#endif
