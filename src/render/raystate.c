#include "render/raystate.h"
#include "gl/packing.h"
#include "gl/readback.h"
#include "gl/texture.h"
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Whether TEXTURE is one of the ray state's RGBA8 textures (the rest hold the path's floats). */
static int byte_texture(const struct raystate *rs, GLuint texture)
{
    return texture == rs->final_color || texture == rs->outcome_codes || texture == rs->orbit_walk[0] ||
           texture == rs->orbit_walk[1];
}

/* Colour targets in use: the first nonzero ones. */
static int target_count(const GLuint target[RAYSTATE_MAX_TARGETS])
{
    int n = 1;
    while (n < RAYSTATE_MAX_TARGETS && target[n])
        n++;
    return n;
}

/* A framebuffer with the colour targets and the shared depth buffer; *status tells whether it is
 * complete. */
static GLuint make_fbo(struct raystate *rs, const GLuint target[RAYSTATE_MAX_TARGETS], GLenum *status)
{
    static const GLenum buffers[RAYSTATE_MAX_TARGETS] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1,
                                                         GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3};
    int n = target_count(target);
    GLuint fbo;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    for (int i = 0; i < n; i++)
        glFramebufferTexture2D(GL_FRAMEBUFFER, buffers[i], GL_TEXTURE_2D, target[i], 0);
    if (n > 1)
        glDrawBuffers(n, buffers);    /* draw-buffer state belongs to the framebuffer: set once */
    /* on the packed path the depth buffer is the float textures' size: an 8-bit target has none */
    if (!(rs->packed && byte_texture(rs, target[0])))
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rs->depth);
    /* the presentation image and the walk's state are 8-bit: only the float targets are the render
     * path's concern */
    *status = render_path_framebuffer_status(byte_texture(rs, target[0]) ? NULL : rs->format, n);
    return fbo;
}

/* Every colour target given its memory, before its framebuffer is made. 0, or -1 with e. */
static int targets_storage(struct raystate *rs, const GLuint target[RAYSTATE_MAX_TARGETS], struct error *e)
{
    int n = target_count(target);
    for (int i = 0; i < n; i++)
        if (raystate_storage(rs, target[i], e) != 0)
            return -1;
    return 0;
}

/* What was attached, in which render path, and what to try instead (the GPU's failure). */
static void incomplete_message(const struct raystate *rs, const GLuint target[RAYSTATE_MAX_TARGETS], GLenum status,
                               struct error *e)
{
    int float_target = !byte_texture(rs, target[0]);
    int n = target_count(target);
    char count[16] = "";
    if (n > 1)
        snprintf(count, sizeof count, "%d x ", n);
    const char *format = float_target ? rs->format->name : "RGBA8";
    error_set(e, ERROR_RUNTIME, NULL, "render path %s: a ray-state framebuffer (%s%s colour, 16-bit depth, %dx%d) is "
              "incomplete: %s (0x%04x)%s%s%s", rs->path_name, count, format, rs->width,
              rs->height, gl_framebuffer_status_name(status), status,
              float_target && rs->format->is_fp32 ? "; try --precision fp16" : "",
              float_target && rs->mrt ? (rs->format->is_fp32 ? " or --no-mrt" : "; try --no-mrt") : "",
              float_target ? " (bentray info lists the formats that work)" : "");
}

int raystate_init(struct raystate *rs, const struct render_path *path, int width, int height, struct error *e)
{
    const struct float_format *f = path->format;
    memset(rs, 0, sizeof *rs);
    rs->width = width;
    rs->height = height;
    /* names only: each texture gets its memory when a pass first needs it (raystate_storage) */
    for (int i = 0; i < 3; i++)
        rs->position[i] = texture_name_nearest();
    for (int i = 0; i < 2; i++) {
        rs->velocity[i] = texture_name_nearest();
        rs->hit[i] = texture_name_nearest();
        rs->image[i] = texture_name_nearest();
        rs->hit_found[i] = texture_name_nearest();
        rs->hit_chord[i] = texture_name_nearest();
    }
    GLuint *results[4] = {&rs->result_position, &rs->result_velocity, &rs->result_hit, &rs->result_image};
    for (int i = 0; i < 4; i++)
        *results[i] = texture_name_nearest();
    rs->final_color = texture_name_nearest();
    rs->outcome_codes = texture_name_nearest();
    for (int i = 0; i < 2; i++)
        rs->orbit_walk[i] = texture_name_nearest();
    /* 16 bits are plenty: the buffer holds only 0 (terminated) and 1, and the quads sit at 0 and 0.5 */
    glGenRenderbuffers(1, &rs->depth);
    glBindRenderbuffer(GL_RENDERBUFFER, rs->depth);
    rs->packed = path->packed;
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT16, rs->packed ? 2 * width : width,
                          rs->packed ? 2 * height : height);
    rs->format = f;
    rs->path_name = path->name;
    rs->mrt = path->mrt;
    /* the targets every path's rays end in (the results the sky stage reads): their format checked
     * now rather than when the first pass needs them, so that a format this GPU cannot render into
     * fails here, in a framebuffer of the same formats in small, which takes no memory a frame that
     * draws its colour itself never needs (on llvmpipe, 15 MB cleared at 800x600) */
    const GLuint setup[RAYSTATE_MAX_TARGETS] = {rs->result_image, path->mrt ? rs->result_velocity : 0, 0, 0};
    GLenum status = f ? render_path_state_status(f, path->mrt) : GL_FRAMEBUFFER_COMPLETE;  /* image only: none */
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        incomplete_message(rs, setup, status, e);
        raystate_release(rs);
        return -1;
    }
    return 0;
}

/* Whether TEXTURE is one of the ray state's own (given memory by raystate_storage). */
static int own_texture(const struct raystate *rs, GLuint texture)
{
    const GLuint own[RAYSTATE_TEXTURES] = {rs->position[0],    rs->position[1],      rs->position[2],
                                           rs->velocity[0],    rs->velocity[1],      rs->hit[0],
                                           rs->hit[1],         rs->image[0],         rs->image[1],
                                           rs->result_position, rs->result_velocity, rs->result_hit,
                                           rs->result_image,   rs->final_color,      rs->outcome_codes,
                                           rs->orbit_walk[0],  rs->orbit_walk[1],    rs->hit_found[0],
                                           rs->hit_found[1],   rs->hit_chord[0],     rs->hit_chord[1]};
    for (int i = 0; i < RAYSTATE_TEXTURES; i++)
        if (texture && own[i] == texture)
            return 1;
    return 0;
}

int raystate_stored(const struct raystate *rs, GLuint texture)
{
    for (int i = 0; i < rs->n_stored; i++)
        if (rs->stored[i] == texture)
            return 1;
    return 0;
}

int raystate_storage(struct raystate *rs, GLuint texture, struct error *e)
{
    /* another texture (a scene's, the orbit table, the HDR colour) has its memory already */
    if (raystate_stored(rs, texture) || !own_texture(rs, texture))
        return 0;
    /* given in the middle of a frame's set-up: the active unit's binding is left as it was */
    GLint bound = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    const struct float_format *f = rs->format;
    if (!f && !byte_texture(rs, texture))
        return error_set(e, ERROR_RUNTIME, NULL, "render path %s: the ray state's float textures are needed, and no "
                         "float format renders on this GPU", rs->path_name);
    int w, h;
    raystate_texture_size(rs, texture, &w, &h);
    if (byte_texture(rs, texture))
        texture_define(texture, GL_RGBA, GL_RGBA, GL_UNSIGNED_BYTE, w, h);
    else
        texture_define(texture, f->internal_format, f->format, f->type, w, h);
    glBindTexture(GL_TEXTURE_2D, (GLuint)bound);
    char what[160];
    snprintf(what, sizeof what, "render path %s: allocating the ray state (a %s texture of %dx%d)", rs->path_name,
             byte_texture(rs, texture) ? "RGBA8" : f->name, w, h);
    if (gl_check(what, e) != 0)
        return -1;   /* not kept as given: a later pass tries again, and fails as clearly */
    rs->stored[rs->n_stored++] = texture;
    return 0;
}

void raystate_texture_size(const struct raystate *rs, GLuint texture, int *width, int *height)
{
    int twice = rs->packed && !byte_texture(rs, texture);
    *width = twice ? 2 * rs->width : rs->width;
    *height = twice ? 2 * rs->height : rs->height;
}

size_t raystate_bytes(const struct raystate *rs)
{
    size_t texel = rs->format ? (rs->format->is_fp32 ? 16 : 8) : 0;   /* packed: four RGBA8 texels */
    size_t texels = (size_t)rs->width * rs->height;
    size_t bytes = texels * (rs->packed ? 8 : 2);   /* the 16-bit depth buffer, four texels a ray packed */
    for (int i = 0; i < rs->n_stored; i++)
        bytes += texels * (byte_texture(rs, rs->stored[i]) ? 4 : texel);
    if (rs->hdr_color)
        bytes += texels * texel;
    return bytes;
}

GLuint raystate_hdr_color(struct raystate *rs)
{
    if (!rs->hdr_color) {
        int w = rs->packed ? 2 * rs->width : rs->width, h = rs->packed ? 2 * rs->height : rs->height;
        rs->hdr_color = texture_create_nearest(rs->format->internal_format, rs->format->format, rs->format->type, w, h);
    }
    return rs->hdr_color;
}

void raystate_release(struct raystate *rs)
{
    for (int i = 0; i < rs->n_fbos; i++)
        glDeleteFramebuffers(1, &rs->fbos[i].fbo);
    glDeleteTextures(3, rs->position);
    glDeleteTextures(2, rs->velocity);
    glDeleteTextures(2, rs->hit);
    glDeleteTextures(2, rs->image);
    glDeleteTextures(2, rs->hit_found);
    glDeleteTextures(2, rs->hit_chord);
    GLuint results[4] = {rs->result_position, rs->result_velocity, rs->result_hit, rs->result_image};
    glDeleteTextures(4, results);
    glDeleteTextures(1, &rs->final_color);
    glDeleteTextures(1, &rs->outcome_codes);
    glDeleteTextures(2, rs->orbit_walk);
    if (rs->hdr_color)
        glDeleteTextures(1, &rs->hdr_color);
    glDeleteRenderbuffers(1, &rs->depth);
    memset(rs, 0, sizeof *rs);
}

GLuint raystate_fbo(struct raystate *rs, GLuint target0, GLuint target1, struct error *e)
{
    const GLuint target[RAYSTATE_MAX_TARGETS] = {target0, target1, 0, 0};
    return raystate_fbo_targets(rs, target, e);
}

GLuint raystate_fbo_targets(struct raystate *rs, const GLuint target[RAYSTATE_MAX_TARGETS], struct error *e)
{
    for (int i = 0; i < rs->n_fbos; i++)
        if (memcmp(rs->fbos[i].target, target, sizeof rs->fbos[i].target) == 0)
            return rs->fbos[i].fbo;
    if (rs->n_fbos == RAYSTATE_MAX_FBOS) {
        error_set(e, ERROR_RUNTIME, NULL, "internal: more than %d framebuffer combinations", RAYSTATE_MAX_FBOS);
        return 0;
    }
    if (targets_storage(rs, target, e) != 0)
        return 0;
    GLenum status;
    GLuint fbo = make_fbo(rs, target, &status);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteFramebuffers(1, &fbo);
        incomplete_message(rs, target, status, e);
        return 0;
    }
    memcpy(rs->fbos[rs->n_fbos].target, target, sizeof rs->fbos[rs->n_fbos].target);
    rs->fbos[rs->n_fbos].fbo = fbo;
    rs->n_fbos++;
    return fbo;
}

/* A packed float texture read back: each texel's four floats from its 2x2 block of RGBA8 texels,
 * their bytes high first (shaders_es/common.glsl, pack_float), GL's row order. */
static int read_packed(struct raystate *rs, float *out, struct error *e)
{
    int w = rs->width, h = rs->height;
    unsigned char *bytes = malloc((size_t)16 * w * h);
    if (!bytes)
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory reading the packed ray state back");
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, 2 * w, 2 * h, GL_RGBA, GL_UNSIGNED_BYTE, bytes);
    packed_to_floats(bytes, w, h, out);
    free(bytes);
    return gl_check("reading the packed ray state back", e);
}

int raystate_read(struct raystate *rs, GLuint texture, float *out, struct error *e)
{
    int w = rs->width, h = rs->height;
    GLuint fbo = raystate_fbo(rs, texture, 0, e);
    if (!fbo)
        return -1;
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    if (rs->packed) {
        if (read_packed(rs, out, e) != 0)
            return -1;
    } else if (read_float_pixels(0, 0, w, h, out) != 0)
        return error_set(e, ERROR_RUNTIME, NULL, "the ray state cannot be read back as floats");
    /* GL rows run bottom-up; images and dumps run top-down */
    if (rows_flip(out, (size_t)w * 4 * sizeof *out, h) != 0)
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory reading the ray state back");
    return 0;
}

int raystate_read_bytes(struct raystate *rs, GLuint texture, unsigned char *rgba_bottom_up, const char *what,
                        struct error *e)
{
    GLuint fbo = raystate_fbo(rs, texture, 0, e);
    if (!fbo)
        return -1;
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, rs->width, rs->height, GL_RGBA, GL_UNSIGNED_BYTE, rgba_bottom_up);
    return gl_check(what, e);
}
