/* The context owns the EGL display, context and surface, so that each screen's close frees them
 * with ctx->destroy() before the window or the GBM surface they draw into. */
#include "gl/egl.h"
#include "gl/caps.h"
#include "gl/gl_api.h"
#include <EGL/eglext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct egl_state {
    EGLDisplay display;
    EGLContext context;
    EGLSurface surface;
    PFNEGLCREATEPLATFORMWINDOWSURFACEEXTPROC create_window_surface;   /* NULL where EGL lacks it */
    const char *who;
};

static void *egl_get_proc(const char *name)
{
    void *p;
    __eglMustCastToProperFunctionPointerType f = eglGetProcAddress(name);
    memcpy(&p, &f, sizeof p);
    return p;
}

static void egl_destroy(struct gl_context *ctx)
{
    struct egl_state *egl = ctx->priv;
    if (egl) {
        if (egl->display != EGL_NO_DISPLAY) {
            eglMakeCurrent(egl->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            if (egl->surface != EGL_NO_SURFACE)
                eglDestroySurface(egl->display, egl->surface);
            if (egl->context != EGL_NO_CONTEXT)
                eglDestroyContext(egl->display, egl->context);
            eglTerminate(egl->display);
        }
        free(egl);
    }
    free(ctx);
}

struct gl_context *egl_open(const struct egl_platform *p, void *native_display, const char *who,
                            const char *version_label, struct error *e)
{
    const char *client_ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!client_ext || !(extension_list_has(client_ext, p->extension) ||
                         (p->other_extension && extension_list_has(client_ext, p->other_extension)))) {
        error_set(e, ERROR_RUNTIME, NULL, "%s: EGL has no %s platform (%s); %s", who, p->name, p->extension,
                  p->install_hint);
        return NULL;
    }
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    PFNEGLCREATEPLATFORMWINDOWSURFACEEXTPROC create_window_surface =
        (PFNEGLCREATEPLATFORMWINDOWSURFACEEXTPROC)eglGetProcAddress("eglCreatePlatformWindowSurfaceEXT");
    if (!get_platform_display) {
        error_set(e, ERROR_RUNTIME, NULL, "%s: EGL lacks eglGetPlatformDisplayEXT", who);
        return NULL;
    }
    struct gl_context *ctx = calloc(1, sizeof *ctx);
    struct egl_state *egl = calloc(1, sizeof *egl);
    if (!ctx || !egl) {
        free(ctx);
        free(egl);
        error_set(e, ERROR_RUNTIME, NULL, "%s: out of memory", who);
        return NULL;
    }
    egl->display = EGL_NO_DISPLAY;
    egl->context = EGL_NO_CONTEXT;
    egl->surface = EGL_NO_SURFACE;
    egl->create_window_surface = create_window_surface;
    egl->who = who;
    ctx->backend = "egl";
    ctx->dialect = DIALECT_GLSL_ES_100;
    ctx->is_es = 1;
    ctx->get_proc = egl_get_proc;
    ctx->destroy = egl_destroy;
    ctx->priv = egl;

    EGLint major = 0, minor = 0;
    egl->display = get_platform_display(p->platform, native_display, NULL);
    if (egl->display == EGL_NO_DISPLAY || !eglInitialize(egl->display, &major, &minor)) {
        error_set(e, ERROR_RUNTIME, NULL, "%s: cannot initialise EGL on %s (EGL error 0x%x)", who, p->display_name,
                  eglGetError());
        egl->display = EGL_NO_DISPLAY;
        goto fail;
    }
    snprintf(ctx->platform_version, sizeof ctx->platform_version, "EGL %d.%d (%s)", major, minor, version_label);
    if (!eglBindAPI(EGL_OPENGL_ES_API)) {
        error_set(e, ERROR_RUNTIME, NULL, "%s: the OpenGL ES API is not available in EGL", who);
        goto fail;
    }
    return ctx;

fail:
    egl_destroy(ctx);
    return NULL;
}

EGLDisplay egl_display(const struct gl_context *ctx)
{
    const struct egl_state *egl = ctx->priv;
    return egl->display;
}

/* An ES2 context in config, current on the state's surface (or none), the GL entry points loaded. */
static int make_current(struct gl_context *ctx, EGLConfig config, const char *on_what, struct error *e)
{
    struct egl_state *egl = ctx->priv;
    /* Drivers may give a higher compatible version than ES2 (llvmpipe gives 3.2). */
    static const EGLint ctx_attribs[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};
    egl->context = eglCreateContext(egl->display, config, EGL_NO_CONTEXT, ctx_attribs);
    if (egl->context == EGL_NO_CONTEXT)
        return error_set(e, ERROR_RUNTIME, NULL, "%s: cannot create an OpenGL ES 2 context (EGL error 0x%x)",
                         egl->who, eglGetError());
    if (!eglMakeCurrent(egl->display, egl->surface, egl->surface, egl->context))
        return error_set(e, ERROR_RUNTIME, NULL, "%s: cannot make the context current %s (EGL error 0x%x)",
                         egl->who, on_what, eglGetError());
    const char *missing = gl_api_load(ctx->get_proc);
    if (missing)
        return error_set(e, ERROR_RUNTIME, NULL, "%s: the GL entry point %s is missing", egl->who, missing);
    gl_context_now_current(ctx);
    return 0;
}

int egl_attach_window(struct gl_context *ctx, EGLConfig config, void *native_window, struct error *e)
{
    struct egl_state *egl = ctx->priv;
    if (!egl->create_window_surface)
        return error_set(e, ERROR_RUNTIME, NULL, "%s: EGL lacks eglCreatePlatformWindowSurfaceEXT", egl->who);
    egl->surface = egl->create_window_surface(egl->display, config, native_window, NULL);
    if (egl->surface == EGL_NO_SURFACE)
        return error_set(e, ERROR_RUNTIME, NULL, "%s: cannot create an EGL window surface (EGL error 0x%x)",
                         egl->who, eglGetError());
    return make_current(ctx, config, "on the window", e);
}

int egl_attach_surfaceless(struct gl_context *ctx, EGLConfig config, struct error *e)
{
    struct egl_state *egl = ctx->priv;
    if (!extension_list_has(eglQueryString(egl->display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context"))
        return error_set(e, ERROR_RUNTIME, NULL, "%s: EGL_KHR_surfaceless_context is missing", egl->who);
    return make_current(ctx, config, "without a surface", e);
}

int egl_swap(struct gl_context *ctx, struct error *e)
{
    struct egl_state *egl = ctx->priv;
    if (!eglSwapBuffers(egl->display, egl->surface))
        return error_set(e, ERROR_RUNTIME, NULL, "%s: eglSwapBuffers failed (EGL error 0x%x)", egl->who,
                         eglGetError());
    return 0;
}
