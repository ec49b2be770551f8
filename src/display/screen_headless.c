/* The headless screen: a framebuffer object of the refined frame's size on a context without a
 * window (EGL surfaceless or OSMesa). Frames are read back and written as PNG by the loop when a
 * script asks (compositor_read_screen); presenting is only waiting for the GPU. */
#include "display/screen.h"
#include <stdio.h>
#include <stdlib.h>

struct headless {
    GLuint color;                    /* renderbuffer, RGBA8 */
    GLuint fbo;
    int owns_gl;                     /* the context was made for this screen */
};

static int headless_fd(struct screen *s)
{
    (void)s;
    return -1;
}

static int headless_present(struct screen *s, struct error *e)
{
    (void)s;
    glFinish();
    return gl_check("presenting a headless frame", e);
}

static void headless_close(struct screen *s)
{
    struct headless *h = s->priv;
    int owns_gl = h && h->owns_gl;
    if (h) {
        glDeleteFramebuffers(1, &h->fbo);
        glDeleteRenderbuffers(1, &h->color);
        free(h);
    }
    if (owns_gl)
        gl_context_destroy(s->gl);
    free(s);
}

/* The screen on gl, which it owns (closes with it) or not. */
static struct screen *offscreen(struct gl_context *gl, int owns_gl, int width, int height, struct error *e)
{
    struct screen *s = calloc(1, sizeof *s);
    struct headless *h = calloc(1, sizeof *h);
    if (!s || !h) {
        free(s);
        free(h);
        error_set(e, ERROR_RUNTIME, NULL, "out of memory");
        return NULL;
    }
    s->name = "headless";
    s->gl = gl;
    s->width = width;
    s->height = height;
    s->fd = headless_fd;
    s->present = headless_present;
    s->close = headless_close;
    s->priv = h;
    h->owns_gl = owns_gl;
    glGenRenderbuffers(1, &h->color);
    glBindRenderbuffer(GL_RENDERBUFFER, h->color);
    /* RGBA8 renderbuffers are core in ES 3 and in desktop GL; ES 2 has them through OES_rgb8_rgba8 */
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8_OES, width, height);
    glGenFramebuffers(1, &h->fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, h->fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, h->color);
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        error_set(e, ERROR_RUNTIME, NULL, "headless screen: the %dx%d RGBA8 framebuffer is incomplete (status 0x%x)",
                  width, height, status);
        screen_close(s);
        return NULL;
    }
    s->framebuffer = h->fbo;
    return s;
}

struct screen *screen_open_offscreen(struct gl_context *gl, int width, int height, struct error *e)
{
    return offscreen(gl, 0, width, height, e);
}

struct screen *screen_open_headless(int width, int height, const char *gl_backend, struct error *e)
{
    struct gl_context *gl = gl_context_create(gl_backend, e);
    if (!gl)
        return NULL;
    struct screen *s = offscreen(gl, 1, width, height, e);
    if (!s)
        gl_context_destroy(gl);
    return s;
}
