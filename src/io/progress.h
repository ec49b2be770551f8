/* Progress of a long render on stderr (both engines): bentray's own words and numbers, never text
 * the user wrote, so it goes to the real stderr, past the filter that escapes control characters
 * (io/stderr_filter.h). On a terminal each report rewrites one line in place (a carriage return);
 * in a log or a pipe each is a line of its own, fewer of them. */
#ifndef BT_PROGRESS_H
#define BT_PROGRESS_H

enum progress_mode {
    PROGRESS_NONE,       /* nothing (--quiet, tests, the bench) */
    PROGRESS_AUTO,       /* once the render has run PROGRESS_AFTER_S */
    PROGRESS_ALWAYS      /* from the start, every report (--progress) */
};

#define PROGRESS_AFTER_S 1.0
#define PROGRESS_TERMINAL_EVERY_S 0.5   /* at most this often on a terminal */
#define PROGRESS_LOG_EVERY_S 5.0        /* and in a log, with PROGRESS_AUTO */

struct progress {
    enum progress_mode mode;
    double start;        /* clock_seconds() when the work began */
    double last;         /* when the last line was shown */
    int terminal;        /* stderr is a terminal */
    int shown;           /* a line was shown */
};

void progress_begin(struct progress *p, enum progress_mode mode);
/* Report done (0..1) of the work with a label ("gpu: sample 1/4, 300/720 rows"): shown with the
 * elapsed time and the time left when the mode and the clock say so; always when final. */
void progress_report(struct progress *p, const char *label, double done, int final);
/* End the line on a terminal, if one was shown. */
void progress_end(struct progress *p);

#endif
