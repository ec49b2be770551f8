#include "gl/gl_api.h"
#include <stdio.h>
#include <string.h>

struct gl_api bt_gl;

const char *gl_api_load(void *(*get_proc)(const char *name))
{
    void *p;
    memset(&bt_gl, 0, sizeof bt_gl);
#define BT_GL_LOAD(ret, name, args) \
    p = get_proc("gl" #name); \
    if (!p) return "gl" #name; \
    memcpy(&bt_gl.name, &p, sizeof p);
    BT_GL_FUNCTIONS(BT_GL_LOAD)
#undef BT_GL_LOAD
#define BT_GL_LOAD_OPTIONAL(ret, name, args) \
    p = get_proc("gl" #name); \
    if (!p) p = get_proc("gl" #name "EXT"); \
    if (p) memcpy(&bt_gl.name, &p, sizeof p);
    BT_GL_OPTIONAL_FUNCTIONS(BT_GL_LOAD_OPTIONAL)
#undef BT_GL_LOAD_OPTIONAL
    return NULL;
}

const char *gl_error_name(GLenum e)
{
    switch (e) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "unknown GL error";
    }
}

int gl_check(const char *stage, struct error *e)
{
    GLenum code = glGetError();
    if (code == GL_NO_ERROR)
        return 0;
    /* drain the queue so that the next stage starts clean */
    while (glGetError() != GL_NO_ERROR) {
    }
    return error_set(e, ERROR_RUNTIME, NULL, "%s: %s (0x%04x)", stage, gl_error_name(code), code);
}
