#include "gl/context.h"
#include "gl/gl_api.h"
#include <stdio.h>
#include <string.h>

int gl_backend_built(const char *name)
{
    if (strcmp(name, "egl") == 0)
        return 1;
#ifdef HAVE_OSMESA
    if (strcmp(name, "osmesa") == 0)
        return 1;
#endif
    return 0;
}

static struct gl_context *current;

struct gl_context *gl_context_current(void) { return current; }
void gl_context_now_current(struct gl_context *ctx) { current = ctx; }

static struct gl_context *with_api(struct gl_context *ctx, char *err, size_t errlen)
{
    if (!ctx)
        return NULL;
    const char *missing = gl_api_load(ctx->get_proc);
    if (missing) {
        snprintf(err, errlen, "%s: the GL entry point %s is missing", ctx->backend, missing);
        ctx->destroy(ctx);
        return NULL;
    }
    current = ctx;
    return ctx;
}

struct gl_context *gl_context_create(const char *name, char *err, size_t errlen)
{
    if (strcmp(name, "egl") == 0)
        return with_api(init_egl_surfaceless(err, errlen), err, errlen);
    if (strcmp(name, "osmesa") == 0)
        return with_api(init_osmesa(err, errlen), err, errlen);
    if (strcmp(name, "auto") == 0) {
        char egl_err[256];
        struct gl_context *ctx = with_api(init_egl_surfaceless(egl_err, sizeof egl_err), egl_err, sizeof egl_err);
        if (ctx)
            return ctx;
        char os_err[256];
        ctx = with_api(init_osmesa(os_err, sizeof os_err), os_err, sizeof os_err);
        if (ctx)
            return ctx;
        snprintf(err, errlen, "no headless GL back-end works: %s; %s", egl_err, os_err);
        return NULL;
    }
    snprintf(err, errlen, "unknown back-end '%s' (expected egl, osmesa or auto)", name);
    return NULL;
}

void gl_context_destroy(struct gl_context *ctx)
{
    if (!ctx)
        return;
    if (current == ctx)
        current = NULL;     /* its quad goes with it */
    ctx->destroy(ctx);
}
