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

static struct gl_context *with_api(struct gl_context *ctx, struct error *e)
{
    if (!ctx)
        return NULL;
    const char *missing = gl_api_load(ctx->get_proc);
    if (missing) {
        error_set(e, ERROR_RUNTIME, NULL, "%s: the GL entry point %s is missing", ctx->backend, missing);
        ctx->destroy(ctx);
        return NULL;
    }
    current = ctx;
    return ctx;
}

struct gl_context *gl_context_create(const char *name, struct error *e)
{
    if (strcmp(name, "egl") == 0)
        return with_api(init_egl_surfaceless(e), e);
    if (strcmp(name, "osmesa") == 0)
        return with_api(init_osmesa(e), e);
    if (strcmp(name, "auto") == 0) {
        struct error egl_err;
        struct gl_context *ctx = with_api(init_egl_surfaceless(&egl_err), &egl_err);
        if (ctx)
            return ctx;
        struct error os_err;
        ctx = with_api(init_osmesa(&os_err), &os_err);
        if (ctx)
            return ctx;
        /* each reason cut at 255 characters, so that both fit in one message */
        error_set(e, ERROR_RUNTIME, NULL, "no headless GL back-end works: %.255s; %.255s", egl_err.message,
                  os_err.message);
        return NULL;
    }
    error_set(e, ERROR_INPUT, NULL, "unknown back-end '%s' (expected egl, osmesa or auto)", name);
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
