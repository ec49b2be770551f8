#include "render/raystate.h"
#include "gl/readback.h"
#include "gl/texture.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int raystate_init(struct raystate *rs, const struct render_path *path, int width, int height,
                  char *err, size_t errlen)
{
    const struct float_format *f = path->format;
    memset(rs, 0, sizeof *rs);
    rs->width = width;
    rs->height = height;
    for (int i = 0; i < 3; i++)
        rs->position[i] = texture_create_nearest(f->internal_format, f->format, f->type, width, height);
    for (int i = 0; i < 2; i++) {
        rs->velocity[i] = texture_create_nearest(f->internal_format, f->format, f->type, width, height);
        rs->hit[i] = texture_create_nearest(f->internal_format, f->format, f->type, width, height);
        rs->image[i] = texture_create_nearest(f->internal_format, f->format, f->type, width, height);
    }
    GLuint *results[4] = {&rs->result_position, &rs->result_velocity, &rs->result_hit, &rs->result_image};
    for (int i = 0; i < 4; i++)
        *results[i] = texture_create_nearest(f->internal_format, f->format, f->type, width, height);
    rs->final_color = texture_create_nearest(GL_RGBA, GL_RGBA, GL_UNSIGNED_BYTE, width, height);
    /* 16 bits are plenty: the buffer holds only 0 (terminated) and 1, and the quads sit at 0 and 0.5 */
    glGenRenderbuffers(1, &rs->depth);
    glBindRenderbuffer(GL_RENDERBUFFER, rs->depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT16, width, height);
    return gl_check("allocating the ray-state textures", err, errlen);
}

void raystate_release(struct raystate *rs)
{
    for (int i = 0; i < rs->n_fbos; i++)
        glDeleteFramebuffers(1, &rs->fbos[i].fbo);
    glDeleteTextures(3, rs->position);
    glDeleteTextures(2, rs->velocity);
    glDeleteTextures(2, rs->hit);
    glDeleteTextures(2, rs->image);
    GLuint results[4] = {rs->result_position, rs->result_velocity, rs->result_hit, rs->result_image};
    glDeleteTextures(4, results);
    glDeleteTextures(1, &rs->final_color);
    glDeleteRenderbuffers(1, &rs->depth);
    memset(rs, 0, sizeof *rs);
}

GLuint raystate_fbo(struct raystate *rs, GLuint target0, GLuint target1, char *err, size_t errlen)
{
    for (int i = 0; i < rs->n_fbos; i++)
        if (rs->fbos[i].target0 == target0 && rs->fbos[i].target1 == target1)
            return rs->fbos[i].fbo;
    if (rs->n_fbos == RAYSTATE_MAX_FBOS) {
        snprintf(err, errlen, "internal: more than %d framebuffer combinations", RAYSTATE_MAX_FBOS);
        return 0;
    }
    GLuint fbo;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target0, 0);
    if (target1) {
        static const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, target1, 0);
        glDrawBuffers(2, both);    /* draw-buffer state belongs to the framebuffer: set once */
    }
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rs->depth);
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        glDeleteFramebuffers(1, &fbo);
        snprintf(err, errlen, "a ray-state framebuffer is incomplete (status 0x%04x)", status);
        return 0;
    }
    rs->fbos[rs->n_fbos].target0 = target0;
    rs->fbos[rs->n_fbos].target1 = target1;
    rs->fbos[rs->n_fbos].fbo = fbo;
    rs->n_fbos++;
    return fbo;
}

int raystate_read(struct raystate *rs, GLuint texture, float *out, char *err, size_t errlen)
{
    int w = rs->width, h = rs->height;
    GLuint fbo = raystate_fbo(rs, texture, 0, err, errlen);
    if (!fbo)
        return -1;
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    float *rows = malloc((size_t)w * h * 4 * sizeof *rows);
    if (!rows) {
        snprintf(err, errlen, "out of memory reading the ray state back");
        return -1;
    }
    if (read_float_pixels(0, 0, w, h, rows) != 0) {
        free(rows);
        snprintf(err, errlen, "the ray state cannot be read back as floats");
        return -1;
    }
    /* GL rows run bottom-up; images and dumps run top-down */
    for (int y = 0; y < h; y++)
        memcpy(out + (size_t)(h - 1 - y) * w * 4, rows + (size_t)y * w * 4, (size_t)w * 4 * sizeof *out);
    free(rows);
    return 0;
}
