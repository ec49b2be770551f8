/* Headless EGL on Mesa's surfaceless platform: no window system, render into FBOs only. */
#include "gl/context.h"
#include "gl/caps.h"
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif

struct egl_priv {
    EGLDisplay display;
    EGLContext context;
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
    struct egl_priv *priv = ctx->priv;
    if (priv) {
        eglMakeCurrent(priv->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (priv->context != EGL_NO_CONTEXT)
            eglDestroyContext(priv->display, priv->context);
        eglTerminate(priv->display);
        free(priv);
    }
    free(ctx);
}

struct gl_context *init_egl_surfaceless(char *err, size_t errlen)
{
    const char *client_ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!client_ext || !extension_list_has(client_ext, "EGL_MESA_platform_surfaceless")) {
        snprintf(err, errlen, "EGL: the surfaceless platform (EGL_MESA_platform_surfaceless) is not available; "
                              "install Mesa's EGL (libegl-mesa0) or use --backend osmesa");
        return NULL;
    }
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    if (!get_platform_display) {
        snprintf(err, errlen, "EGL: eglGetPlatformDisplayEXT is missing");
        return NULL;
    }
    EGLDisplay dpy = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    EGLint major = 0, minor = 0;
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, &major, &minor)) {
        snprintf(err, errlen, "EGL: cannot initialise the surfaceless display (error 0x%x)", eglGetError());
        return NULL;
    }
    const char *dpy_ext = eglQueryString(dpy, EGL_EXTENSIONS);
    if (!extension_list_has(dpy_ext, "EGL_KHR_surfaceless_context")) {
        eglTerminate(dpy);
        snprintf(err, errlen, "EGL: EGL_KHR_surfaceless_context is missing");
        return NULL;
    }
    static const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT, EGL_NONE};
    EGLConfig config = NULL;
    EGLint n = 0;
    int have_config = eglChooseConfig(dpy, config_attribs, &config, 1, &n) && n > 0;
    if (!eglBindAPI(EGL_OPENGL_ES_API)) {
        eglTerminate(dpy);
        snprintf(err, errlen, "EGL: the OpenGL ES API is not available");
        return NULL;
    }
    /* Ask for ES2: drivers may return a higher compatible version (llvmpipe gives 3.2). */
    static const EGLint ctx_attribs[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};
    EGLContext c = eglCreateContext(dpy, have_config ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, ctx_attribs);
    if (c == EGL_NO_CONTEXT) {
        eglTerminate(dpy);
        snprintf(err, errlen, "EGL: cannot create an OpenGL ES 2 context (error 0x%x)", eglGetError());
        return NULL;
    }
    if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, c)) {
        eglDestroyContext(dpy, c);
        eglTerminate(dpy);
        snprintf(err, errlen, "EGL: cannot make the context current without a surface (error 0x%x)", eglGetError());
        return NULL;
    }
    struct gl_context *ctx = calloc(1, sizeof *ctx);
    struct egl_priv *priv = calloc(1, sizeof *priv);
    if (!ctx || !priv) {
        free(ctx);
        free(priv);
        eglDestroyContext(dpy, c);
        eglTerminate(dpy);
        snprintf(err, errlen, "EGL: out of memory");
        return NULL;
    }
    priv->display = dpy;
    priv->context = c;
    ctx->backend = "egl";
    ctx->dialect = DIALECT_GLSL_ES_100;
    ctx->is_es = 1;
    snprintf(ctx->platform_version, sizeof ctx->platform_version, "EGL %d.%d (surfaceless)", major, minor);
    ctx->get_proc = egl_get_proc;
    ctx->destroy = egl_destroy;
    ctx->priv = priv;
    return ctx;
}
