/* The configured screen back-end, or the first that opens here. Nothing is logged: the caller
 * decides what to say about the back-ends that were passed over. */
#include "display/screen.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SCREEN_REASON_LEN 512

/* Adds "; NAME: REASON" to err (NAME once, where the reason does not start with it). */
static void add_reason(char *err, size_t errlen, const char *name, const char *reason)
{
    size_t used = strnlen(err, errlen), n = strlen(name);
    int named = strncmp(reason, name, n) == 0 && reason[n] == ':';
    if (used + 1 < errlen)
        snprintf(err + used, errlen - used, "%s%s%s%s", used ? "; " : "", named ? "" : name, named ? "" : ": ",
                 reason);
}

/* auto: kms, then x11 where an X display is named, then headless. When one opens, err keeps why
 * those before it did not ("" when the first opened), for the log; when none does, err has all. */
static struct screen *open_auto(const struct kiosk_display *d, int width, int height, const char *gl_backend, char *err,
                                size_t errlen)
{
    char why[SCREEN_REASON_LEN] = "";
    if (errlen)
        err[0] = '\0';
    struct screen *s = screen_open_kms(d, why, sizeof why);
    if (s)
        return s;
    add_reason(err, errlen, "kms", why);
    const char *display = getenv("DISPLAY");
    if (display && *display) {
        why[0] = '\0';
        s = screen_open_x11(d, width, height, why, sizeof why);
        if (s)
            return s;
        add_reason(err, errlen, "x11", why);
    } else {
        add_reason(err, errlen, "x11", "DISPLAY is not set");
    }
    why[0] = '\0';
    s = screen_open_headless(width, height, gl_backend, why, sizeof why);
    if (s)
        return s;
    add_reason(err, errlen, "headless", why);
    return NULL;
}

struct screen *screen_open(const struct kiosk_display *d, int width, int height, const char *gl_backend, char *err,
                           size_t errlen)
{
    switch (d->backend) {
    case KIOSK_BACKEND_KMS: return screen_open_kms(d, err, errlen);
    case KIOSK_BACKEND_X11: return screen_open_x11(d, width, height, err, errlen);
    case KIOSK_BACKEND_HEADLESS: return screen_open_headless(width, height, gl_backend, err, errlen);
    case KIOSK_BACKEND_AUTO: return open_auto(d, width, height, gl_backend, err, errlen);
    }
    snprintf(err, errlen, "unknown display back-end %d", (int)d->backend);
    return NULL;
}

void screen_close(struct screen *s)
{
    if (s)
        s->close(s);
}
