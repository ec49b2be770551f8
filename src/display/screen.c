/* The configured screen back-end, or the first that opens here. Nothing is logged: the caller
 * decides what to say about the back-ends that were passed over. */
#include "display/screen.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Each back-end's reason is cut to this many bytes, its terminator included. */
#define SCREEN_REASON_LEN 512

/* Adds "; NAME: REASON" to e's message (NAME once, where the reason does not start with it). */
static void add_reason(struct error *e, const char *name, const char *reason)
{
    size_t used = strnlen(e->message, sizeof e->message), n = strlen(name);
    int named = strncmp(reason, name, n) == 0 && reason[n] == ':';
    if (used + 1 < sizeof e->message)
        snprintf(e->message + used, sizeof e->message - used, "%s%s%s%.*s", used ? "; " : "", named ? "" : name,
                 named ? "" : ": ", SCREEN_REASON_LEN - 1, reason);
}

/* auto: kms, then x11 where an X display is named, then headless. When one opens, e's message keeps
 * why those before it did not ("" when the first opened), for the log; when none does, it has all. */
static struct screen *open_auto(const struct kiosk_display *d, int width, int height, const char *gl_backend,
                                struct error *e)
{
    struct error why;
    error_clear(e);
    error_clear(&why);
    struct screen *s = screen_open_kms(d, &why);
    if (s)
        return s;
    add_reason(e, "kms", why.message);
    const char *display = getenv("DISPLAY");
    if (display && *display) {
        error_clear(&why);
        s = screen_open_x11(d, width, height, &why);
        if (s)
            return s;
        add_reason(e, "x11", why.message);
    } else {
        add_reason(e, "x11", "DISPLAY is not set");
    }
    error_clear(&why);
    s = screen_open_headless(width, height, gl_backend, &why);
    if (s)
        return s;
    add_reason(e, "headless", why.message);
    e->status = ERROR_RUNTIME;
    return NULL;
}

struct screen *screen_open(const struct kiosk_display *d, int width, int height, const char *gl_backend,
                           struct error *e)
{
    switch (d->backend) {
    case KIOSK_BACKEND_KMS: return screen_open_kms(d, e);
    case KIOSK_BACKEND_X11: return screen_open_x11(d, width, height, e);
    case KIOSK_BACKEND_HEADLESS: return screen_open_headless(width, height, gl_backend, e);
    case KIOSK_BACKEND_AUTO: return open_auto(d, width, height, gl_backend, e);
    }
    error_set(e, ERROR_RUNTIME, NULL, "unknown display back-end %d", (int)d->backend);
    return NULL;
}

void screen_close(struct screen *s)
{
    if (s)
        s->close(s);
}
