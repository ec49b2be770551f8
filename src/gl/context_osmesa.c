/* Off-screen Mesa: a desktop GL context in process memory. Rendering goes to FBOs; the
 * small colour buffer OSMesa needs to make a context current is never read. */
#include "gl/context.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef HAVE_OSMESA
#include <GL/osmesa.h>

struct osmesa_priv {
    OSMesaContext context;
    unsigned char buffer[4 * 4 * 4];
};

static void *osmesa_get_proc(const char *name)
{
    void *p;
    OSMESAproc f = OSMesaGetProcAddress(name);
    memcpy(&p, &f, sizeof p);
    return p;
}

static void osmesa_destroy(struct gl_context *ctx)
{
    struct osmesa_priv *priv = ctx->priv;
    if (priv) {
        OSMesaDestroyContext(priv->context);
        free(priv);
    }
    free(ctx);
}

struct gl_context *init_osmesa(struct error *e)
{
    /* Compatibility profile: GLSL 1.30 keeps gl_FragColor, gl_FragData, texture2D and
     * attribute/varying, so the GLSL ES 1.00 source needs only a preamble. */
    static const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0,
                                  OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, 0};
    OSMesaContext c = OSMesaCreateContextAttribs(attribs, NULL);
    if (!c) {
        error_set(e, ERROR_RUNTIME, NULL, "OSMesa: cannot create a compatibility-profile context");
        return NULL;
    }
    struct gl_context *ctx = calloc(1, sizeof *ctx);
    struct osmesa_priv *priv = calloc(1, sizeof *priv);
    if (!ctx || !priv) {
        free(ctx);
        free(priv);
        OSMesaDestroyContext(c);
        error_set(e, ERROR_RUNTIME, NULL, "OSMesa: out of memory");
        return NULL;
    }
    priv->context = c;
    if (!OSMesaMakeCurrent(c, priv->buffer, GL_UNSIGNED_BYTE, 4, 4)) {
        free(ctx);
        free(priv);
        OSMesaDestroyContext(c);
        error_set(e, ERROR_RUNTIME, NULL, "OSMesa: cannot make the context current");
        return NULL;
    }
    ctx->backend = "osmesa";
    ctx->dialect = DIALECT_GLSL_130;
    ctx->is_es = 0;
    snprintf(ctx->platform_version, sizeof ctx->platform_version, "OSMesa %d.%d.%d", OSMESA_MAJOR_VERSION,
             OSMESA_MINOR_VERSION, OSMESA_PATCH_VERSION);
    ctx->get_proc = osmesa_get_proc;
    ctx->destroy = osmesa_destroy;
    ctx->priv = priv;
    return ctx;
}
#else
struct gl_context *init_osmesa(struct error *e)
{
    error_set(e, ERROR_RUNTIME, NULL,
              "OSMesa: this build has no OSMesa back-end (install libosmesa6-dev and rebuild)");
    return NULL;
}
#endif
