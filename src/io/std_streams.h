/* The standard streams as the process found them: a descriptor 0, 1 or 2 that was closed is opened
 * on /dev/null at start, so that no file bentray opens later takes its number (a PNG meant for a
 * file written to the terminal's stderr, say), and its closing is remembered. */
#ifndef BT_STD_STREAMS_H
#define BT_STD_STREAMS_H

/* Call first thing in main. */
void std_streams_guard(void);
/* Standard output was closed when the process started (`--out -` then has nowhere to go). */
int std_stdout_closed(void);

#endif
