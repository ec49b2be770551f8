/* Messages quote what the user wrote (a scene value, a file name, a script line). A control
 * character in it (an escape sequence, a carriage return, a bell) must not reach the terminal or
 * the journal raw: it could rewrite the screen or hide the message. */
#ifndef BT_STDERR_FILTER_H
#define BT_STDERR_FILTER_H

/* From here on, everything written to stderr has its control characters other than newline and
 * tab shown as \xNN; unbuffered, as stderr is. 0, or -1 where the stream could not be made (stderr
 * is then left as it was). */
int stderr_escape_controls(void);

#endif
