/* EGL, once, for every platform bentray draws on (as glmark2 keeps one EGL for every native
 * platform): Mesa's surfaceless platform for the headless renders (gl/context_egl.c), GBM for the
 * kiosk on KMS and X11 for its window (display/screen_kms.c, display/screen_x11.c). A context comes
 * in two steps, because X11 must make its window between them in the visual of the config it
 * chose: the platform's display, initialised with the ES API bound; then an ES2 context current on
 * a window surface, or on no surface at all. How a config is chosen and what the window is stay
 * with each caller. */
#ifndef BT_GL_EGL_H
#define BT_GL_EGL_H
#include <EGL/egl.h>
#include <stddef.h>
#include "gl/context.h"

/* A platform as EGL names it. */
struct egl_platform {
    EGLenum platform;                /* EGL_PLATFORM_X11_KHR, EGL_PLATFORM_GBM_KHR, surfaceless */
    const char *name;                /* "X11", "GBM": "EGL has no X11 platform" */
    const char *display_name;        /* "the X display", "GBM": "cannot initialise EGL on the X display" */
    const char *extension;           /* the client extension that offers it, named in the message */
    const char *other_extension;     /* the same under another vendor's name, taken as well (or NULL) */
    const char *install_hint;        /* what to do when EGL lacks it, ending the message */
};

/* The platform's display on native_display, initialised, the ES API bound: a context (backend
 * "egl", GLSL ES 1.00) with no surface yet, whose platform_version is "EGL 1.5 (version_label)".
 * who begins this context's messages ("x11", the card's path, "EGL") and must outlive it. NULL
 * with E filled (ERROR_RUNTIME), as for every failure of this module. */
struct gl_context *egl_open(const struct egl_platform *p, void *native_display, const char *who,
                            const char *version_label, struct error *e);

/* The display egl_open initialised, for choosing a config on it. */
EGLDisplay egl_display(const struct gl_context *ctx);

/* A window surface on native_window (what eglCreatePlatformWindowSurfaceEXT takes) in config, an
 * ES2 context current on it, the GL entry points loaded (gl_api_load). 0, or -1 with E filled;
 * either way ctx->destroy() frees it all. */
int egl_attach_window(struct gl_context *ctx, EGLConfig config, void *native_window, struct error *e);

/* The same without a surface (EGL_KHR_surfaceless_context: rendering into FBOs only); config may
 * be EGL_NO_CONFIG_KHR. */
int egl_attach_surfaceless(struct gl_context *ctx, EGLConfig config, struct error *e);

/* Shows what was drawn: eglSwapBuffers. 0, or -1 with E filled. */
int egl_swap(struct gl_context *ctx, struct error *e);

#endif
