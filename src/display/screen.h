/* Where the kiosk's frames go, behind one interface: a KMS display with no window system, a
 * window under X11, or PNG files (headless). Each back-end makes its own GL context (EGL on GBM,
 * EGL on X11, EGL surfaceless or OSMesa) and says which framebuffer a frame is drawn into. */
#ifndef BT_KIOSK_SCREEN_H
#define BT_KIOSK_SCREEN_H
#include <stddef.h>
#include <stdio.h>
#include "gl/context.h"
#include "gl/gl_api.h"
#include "input/input.h"
#include "io/error.h"
#include "display/display_settings.h"

struct screen {
    const char *name;                /* "kms", "x11" or "headless" */
    struct gl_context *gl;           /* current on this thread while the screen is open */
    int width, height;               /* pixels of the framebuffer a frame fills */
    GLuint framebuffer;              /* draw a frame into this (0: the window's or display's own) */
    /* The descriptor to poll for the screen's own events (window system, page flips), -1 for none. */
    int (*fd)(struct screen *s);
    /* The screen's events without blocking (keys of a window, a window closed: INPUT_QUIT), at
     * most max; returns how many. NULL where there are none. */
    int (*events)(struct screen *s, double now, struct input_event *out, int max);
    /* Show what was drawn into framebuffer: swap, page flip (waiting for vertical blank when the
     * configuration asks), or nothing (headless). 0, or -1 with e (ERROR_RUNTIME). */
    int (*present)(struct screen *s, struct error *e);
    /* Puts the display back as it was (the console's mode), frees the context. */
    void (*close)(struct screen *s);
    void *priv;
    /* Set by the back-end: what it wants said once it is open (the KMS screen's console handling),
     * "" for nothing; and that it lost its picture (a console switch back), so that the loop draws
     * and presents a frame at its next turn, which clears it. */
    char note[256];
    int redraw;
    /* Set by the loop: where the back-end says what happens later (a console switch), or NULL. */
    FILE *log;
};

/* Each returns NULL with e when the back-end cannot open here; the message names the back-end or
 * the device. What the configuration names and the machine refuses or lacks (its DRM device, the
 * connector, the mode) is the user's (ERROR_INPUT), the rest the machine's (ERROR_RUNTIME).
 * gl_backend (headless only): "egl", "osmesa" or "auto". */
struct screen *screen_open_headless(int width, int height, const char *gl_backend, struct error *e);
/* The headless screen's framebuffer on a context the caller keeps (the bench's): width x height,
 * RGBA8; screen_close leaves the context open. */
struct screen *screen_open_offscreen(struct gl_context *gl, int width, int height, struct error *e);
struct screen *screen_open_x11(const struct kiosk_display *d, int width, int height, struct error *e);
struct screen *screen_open_kms(const struct kiosk_display *d, struct error *e);
/* The configured back-end; auto tries kms, then x11 (when DISPLAY is set), then headless. With auto,
 * e->message keeps why the back-ends passed over did not open ("" when the first did) once one
 * opens (e->status ERROR_NONE), and all the reasons when none does (ERROR_RUNTIME). */
struct screen *screen_open(const struct kiosk_display *d, int width, int height, const char *gl_backend,
                           struct error *e);
void screen_close(struct screen *s);

#endif
