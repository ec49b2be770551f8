/* A GL context behind one small interface, in the style of kmscube's init_*() back-ends.
 * Rendering code sees only this struct; it never knows which back-end made the context. */
#ifndef BT_CONTEXT_H
#define BT_CONTEXT_H
#include <stddef.h>
#include "io/error.h"

enum shading_dialect {
    DIALECT_GLSL_ES_100,   /* GLES2/3 contexts: shaders_es/ as written */
    DIALECT_GLSL_130       /* desktop GL (OSMesa): the same source behind a generated preamble */
};

struct gl_context {
    const char *backend;            /* "egl" or "osmesa" */
    enum shading_dialect dialect;
    int is_es;                      /* GLES API (else desktop GL) */
    char platform_version[64];      /* "EGL 1.5 (surfaceless)" or "OSMesa 22.3.6" */
    void *(*get_proc)(const char *name);
    void (*destroy)(struct gl_context *ctx);
    void *priv;
    /* the full-screen pass quad of this context (src/gl/quad.c): its buffer and how many users
     * (probe, renderers, compositor) share it */
    unsigned quad_buffer;
    int quad_users;
};

/* The context whose GL entry points are loaded, made current by gl_context_create or a screen
 * (gl_context_now_current); NULL when none is. One context is current at a time. */
struct gl_context *gl_context_current(void);
void gl_context_now_current(struct gl_context *ctx);

/* Each returns NULL with E filled (ERROR_RUNTIME) when the back-end is unavailable. */
struct gl_context *init_egl_surfaceless(struct error *e);
struct gl_context *init_osmesa(struct error *e);

/* name: "egl", "osmesa" or "auto" (EGL first, then OSMesa). Loads the GL entry points too. NULL
 * with E filled: ERROR_INPUT for a name that is none of these, else ERROR_RUNTIME. */
struct gl_context *gl_context_create(const char *name, struct error *e);
void gl_context_destroy(struct gl_context *ctx);
/* Whether this build has the back-end at all. */
int gl_backend_built(const char *name);

#endif
