/* EGL drawing into a window system's window: the part the KMS and X11 screens share, from the
 * platform display to an ES2 context current on the window and the GL entry points loaded. It
 * comes in two steps because X11 must make its window between them, in the visual of the config
 * it chose; how the config is chosen and what the window is stay with each screen. */
#ifndef BT_KIOSK_SCREEN_EGL_H
#define BT_KIOSK_SCREEN_EGL_H
#include <EGL/egl.h>
#include <stddef.h>
#include "gl/context.h"

/* A window system as EGL names it. */
struct screen_egl_platform {
    EGLenum platform;                /* EGL_PLATFORM_X11_KHR, EGL_PLATFORM_GBM_KHR */
    const char *name;                /* "X11", "GBM": "EGL has no X11 platform" */
    const char *display_name;        /* "the X display", "GBM": "cannot initialise EGL on the X display" */
    const char *extension;           /* the client extension that offers it, named in the message */
    const char *other_extension;     /* the same under another vendor's name, taken as well */
};

/* The platform's display on native_display, initialised, the ES API bound: a context (backend
 * "egl", GLSL ES 1.00) with no surface yet, whose platform_version is "EGL 1.5 (version_label)".
 * who begins this context's messages ("x11", the card's path) and must outlive it. NULL with err. */
struct gl_context *screen_egl_open(const struct screen_egl_platform *p, void *native_display, const char *who,
                                   const char *version_label, char *err, size_t errlen);

/* The display screen_egl_open initialised, for choosing a config on it. */
EGLDisplay screen_egl_display(const struct gl_context *ctx);

/* A window surface on native_window (what eglCreatePlatformWindowSurfaceEXT takes) in config, an
 * ES2 context current on it, the GL entry points loaded (gl_api_load). 0, or -1 with err; either
 * way ctx->destroy() frees it all. */
int screen_egl_attach(struct gl_context *ctx, EGLConfig config, void *native_window, char *err, size_t errlen);

/* Shows what was drawn: eglSwapBuffers. 0, or -1 with err. */
int screen_egl_swap(struct gl_context *ctx, char *err, size_t errlen);

#endif
