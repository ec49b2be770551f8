/* The log lines are written whole and flushed at once: the kiosk's log may be a file that staff
 * read while the kiosk runs, and a line must not wait in a buffer for the next one. */
#include "input/input_retry.h"
#include <stdarg.h>

void input_retry_init(struct input_retry *r, double now)
{
    r->last_try = now;
    r->logged = 0;
    r->logged_reason = INPUT_ABSENT_GONE;
}

int input_retry_due(const struct input_retry *r, double now)
{
    return now < r->last_try || now - r->last_try >= INPUT_RETRY_SECONDS;
}

int input_retry_take(struct input_retry *r, double now)
{
    if (!input_retry_due(r, now))
        return 0;
    r->last_try = now;
    return 1;
}

static void log_line(const struct input_source *src, const char *suffix, const char *fmt, va_list args)
{
    if (src->log == NULL)
        return;
    fprintf(src->log, "input %s: ", src->cfg->name);
    vfprintf(src->log, fmt, args);
    fprintf(src->log, "%s\n", suffix);
    fflush(src->log);
}

void input_retry_absent(struct input_retry *r, const struct input_source *src, enum input_absence reason,
                        const char *fmt, ...)
{
    if (r->logged && r->logged_reason == reason)
        return;
    char suffix[64];
    snprintf(suffix, sizeof suffix, "; %s every %g s",
             reason == INPUT_ABSENT_GONE ? "looking for it" : "trying again", INPUT_RETRY_SECONDS);
    va_list args;
    va_start(args, fmt);
    log_line(src, suffix, fmt, args);
    va_end(args);
    r->logged = 1;
    r->logged_reason = reason;
}

void input_retry_present(struct input_retry *r, const struct input_source *src, const char *fmt, ...)
{
    va_list args;
    va_start(args, fmt);
    log_line(src, "", fmt, args);
    va_end(args);
    r->logged = 0;
}
