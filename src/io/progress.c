#include "io/clock.h"
#include "io/progress.h"
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

void progress_begin(struct progress *p, enum progress_mode mode)
{
    memset(p, 0, sizeof *p);
    p->mode = mode;
    p->start = clock_seconds();
    p->terminal = isatty(STDERR_FILENO);
}

/* The text to stderr's descriptor as it is (short writes and signals retried; a failure is dropped:
 * progress is never worth an error). */
static void put(const char *text, size_t n)
{
    while (n > 0) {
        ssize_t w = write(STDERR_FILENO, text, n);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return;
        text += w;
        n -= (size_t)w;
    }
}

void progress_report(struct progress *p, const char *label, double done, int final)
{
    if (p->mode == PROGRESS_NONE)
        return;
    double now = clock_seconds(), elapsed = now - p->start;
    if (p->mode == PROGRESS_AUTO && elapsed < PROGRESS_AFTER_S)
        return;
    double every = p->terminal ? PROGRESS_TERMINAL_EVERY_S : p->mode == PROGRESS_AUTO ? PROGRESS_LOG_EVERY_S : 0.0;
    if (p->shown && !final && now - p->last < every)
        return;
    char line[256];
    done = done < 0.0 ? 0.0 : done > 1.0 ? 1.0 : done;
    int n = snprintf(line, sizeof line, "%s%s (%.0f%%), %.1f s, about %.0f s left%s", p->terminal ? "\r" : "",
                     label, 100.0 * done, elapsed, done > 0.0 ? elapsed * (1.0 - done) / done : 0.0,
                     p->terminal ? "   " : "\n");
    if (n > 0)
        put(line, (size_t)n < sizeof line ? (size_t)n : sizeof line - 1);
    p->shown = 1;
    p->last = now;
}

void progress_end(struct progress *p)
{
    if (p->shown && p->terminal)
        put("\n", 1);
    p->shown = 0;
}
