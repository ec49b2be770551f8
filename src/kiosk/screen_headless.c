/* The headless screen: a framebuffer object of the refined frame's size on a context without a
 * window (EGL surfaceless or OSMesa). Frames are read back and written as PNG by the loop when a
 * script asks (compositor_read_screen); presenting is only waiting for the GPU. */
#include "kiosk/screen.h"
#include <stdio.h>
#include <stdlib.h>

struct headless {
    GLuint color;                    /* renderbuffer, RGBA8 */
    GLuint fbo;
};

static int headless_fd(struct screen *s)
{
    (void)s;
    return -1;
}

static int headless_present(struct screen *s, char *err, size_t errlen)
{
    (void)s;
    glFinish();
    return gl_check("presenting a headless frame", err, errlen);
}

static void headless_close(struct screen *s)
{
    struct headless *h = s->priv;
    if (h) {
        glDeleteFramebuffers(1, &h->fbo);
        glDeleteRenderbuffers(1, &h->color);
        free(h);
    }
    gl_context_destroy(s->gl);
    free(s);
}

struct screen *screen_open_headless(const struct kiosk_config *c, const char *gl_backend, char *err, size_t errlen)
{
    struct screen *s = calloc(1, sizeof *s);
    struct headless *h = calloc(1, sizeof *h);
    if (!s || !h) {
        free(s);
        free(h);
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    s->gl = gl_context_create(gl_backend, err, errlen);
    if (!s->gl) {
        free(s);
        free(h);
        return NULL;
    }
    s->name = "headless";
    s->width = c->kiosk.width;
    s->height = c->kiosk.height;
    s->fd = headless_fd;
    s->present = headless_present;
    s->close = headless_close;
    s->priv = h;
    glGenRenderbuffers(1, &h->color);
    glBindRenderbuffer(GL_RENDERBUFFER, h->color);
    /* RGBA8 renderbuffers are core in ES 3 and in desktop GL; ES 2 has them through OES_rgb8_rgba8 */
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8_OES, s->width, s->height);
    glGenFramebuffers(1, &h->fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, h->fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, h->color);
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        snprintf(err, errlen, "headless screen: the %dx%d RGBA8 framebuffer is incomplete (status 0x%x)", s->width,
                 s->height, status);
        screen_close(s);
        return NULL;
    }
    s->framebuffer = h->fbo;
    return s;
}
