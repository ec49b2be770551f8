/* Headless EGL on Mesa's surfaceless platform: no window system, render into FBOs only (the one
 * EGL module, gl/egl.h, does the work). */
#include "gl/context.h"
#include "gl/egl.h"
#include <EGL/eglext.h>
#include <stdio.h>

#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif

struct gl_context *init_egl_surfaceless(struct error *e)
{
    static const struct egl_platform surfaceless = {
        EGL_PLATFORM_SURFACELESS_MESA, "surfaceless", "the surfaceless display", "EGL_MESA_platform_surfaceless",
        NULL, "install Mesa's EGL (libegl-mesa0) or use --backend osmesa"};
    struct gl_context *ctx = egl_open(&surfaceless, EGL_DEFAULT_DISPLAY, "headless EGL", "surfaceless", e);
    if (!ctx)
        return NULL;
    static const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT, EGL_NONE};
    EGLConfig config = NULL;
    EGLint n = 0;
    int have_config = eglChooseConfig(egl_display(ctx), config_attribs, &config, 1, &n) && n > 0;
    if (egl_attach_surfaceless(ctx, have_config ? config : EGL_NO_CONFIG_KHR, e) != 0) {
        ctx->destroy(ctx);
        return NULL;
    }
    return ctx;
}
