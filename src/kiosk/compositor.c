/* Canvas, bands, letterbox and HUD: the kiosk's frames assembled on the GPU. */
#include "kiosk/compositor.h"
#include "gl/caps.h"
#include "gl/quad.h"
#include "gl/shader.h"
#include "gl/texture.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The canvas and the HUD, 8-bit RGBA; each blit() sets the filter its scale needs. */
static GLuint linear_texture(int width, int height)
{
    return texture_create(GL_RGBA, GL_RGBA, GL_UNSIGNED_BYTE, width, height, GL_LINEAR);
}

int compositor_init(struct compositor *c, const struct gl_context *gl, int width, int height, struct error *e)
{
    memset(c, 0, sizeof *c);
    c->width = width;
    c->height = height;
    /* the probe also takes this compositor's share of the pass quadrilateral (gl/quad.h) */
    struct gl_caps caps;
    if (gl_caps_probe(&caps, gl, e) != 0) {
        quad_release();
        return -1;
    }
    c->has_quad = 1;
    c->framebuffer_blit = caps.framebuffer_blit;
    static const char *const vertex[] = {"kiosk_vertex.glsl", NULL};
    static const char *const blit[] = {"kiosk_blit.glsl", NULL};
    static const char *const pipeline[] = {"kiosk_pipeline.glsl", NULL};
    c->blit = shader_program_build(&caps.shader, "", vertex, blit, e);
    c->pipeline = c->blit ? shader_program_build(&caps.shader, "", vertex, pipeline, e) : 0;
    if (!c->pipeline) {
        compositor_release(c);
        return -1;
    }
    c->canvas = linear_texture(width, height);
    glGenFramebuffers(1, &c->canvas_fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, c->canvas_fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, c->canvas, 0);
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        error_set(e, ERROR_RUNTIME, NULL, "the %dx%d RGBA8 canvas framebuffer is incomplete (status 0x%x)", width,
                  height, status);
        compositor_release(c);
        return -1;
    }
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    if (gl_check("making the compositor", e) != 0) {
        compositor_release(c);
        return -1;
    }
    return 0;
}

void compositor_release(struct compositor *c)
{
    if (c->preview_fbo)
        glDeleteFramebuffers(1, &c->preview_fbo);
    if (c->preview)
        glDeleteTextures(1, &c->preview);
    if (c->canvas_fbo)
        glDeleteFramebuffers(1, &c->canvas_fbo);
    if (c->canvas)
        glDeleteTextures(1, &c->canvas);
    if (c->hud)
        glDeleteTextures(1, &c->hud);
    if (c->blit)
        glDeleteProgram(c->blit);
    if (c->pipeline)
        glDeleteProgram(c->pipeline);
    if (c->has_quad)
        quad_release();
    memset(c, 0, sizeof *c);
}

static void set_uv_rect(GLuint program, float u0, float v0, float du, float dv)
{
    glUniform4f(glGetUniformLocation(program, "u_uv_rect"), u0, v0, du, dv);
}

static void bind_sampler(GLuint program, const char *name, int unit, GLuint tex)
{
    glActiveTexture(GL_TEXTURE0 + (GLenum)unit);
    glBindTexture(GL_TEXTURE_2D, tex);
    glUniform1i(glGetUniformLocation(program, name), unit);
}

/* tex drawn with the blit program into the bound framebuffer's viewport, filtered as asked */
static void blit(struct compositor *c, GLuint tex, GLint filter, float u0, float v0, float du, float dv)
{
    glUseProgram(c->blit);
    quad_bind();
    bind_sampler(c->blit, "u_image", 0, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    set_uv_rect(c->blit, u0, v0, du, dv);
    quad_draw(c->blit, 0.0f);
}

static void to_canvas(struct compositor *c, int x, int y, int w, int h)
{
    glBindFramebuffer(GL_FRAMEBUFFER, c->canvas_fbo);
    glViewport(x, y, w, h);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
}

int compositor_put_preview(struct compositor *c, GLuint image, struct error *e)
{
    to_canvas(c, 0, 0, c->width, c->height);
    blit(c, image, GL_LINEAR, 0, 0, 1, 1);
    /* the renderer's image keeps its own nearest filtering: its passes read it texel for texel */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return gl_check("drawing the preview into the canvas", e);
}

/* A weight below 1: the canvas keeps 1 - weight of what it holds (GL's constant blend colour,
 * GLES 2 core). */
static void blend_weight(float weight)
{
    if (weight >= 1.0f)
        return;
    glEnable(GL_BLEND);
    glBlendColor(0.0f, 0.0f, 0.0f, weight);
    glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
}

int compositor_put_band(struct compositor *c, GLuint image, int band_height, int y0, int rows, float weight,
                        struct error *e)
{
    to_canvas(c, 0, y0, c->width, rows);
    blend_weight(weight);
    blit(c, image, GL_NEAREST, 0, 0, 1, (float)rows / (float)band_height);
    glDisable(GL_BLEND);
    return gl_check("drawing a refined band into the canvas", e);
}

int compositor_put_tile(struct compositor *c, GLuint image, int tex_w, int tex_h, int x0, int y0, int w, int h,
                        float weight, struct error *e)
{
    to_canvas(c, x0, y0, w, h);
    blend_weight(weight);
    blit(c, image, GL_NEAREST, 0, 0, (float)w / (float)tex_w, (float)h / (float)tex_h);
    glDisable(GL_BLEND);
    return gl_check("drawing a refined tile into the canvas", e);
}

int compositor_put_preview_tile(struct compositor *c, GLuint image, int tex_w, int tex_h, int x0, int y0, int w,
                                int h, int pw, int ph, struct error *e)
{
    if (!c->preview || c->preview_width != pw || c->preview_height != ph) {
        if (c->preview_fbo)
            glDeleteFramebuffers(1, &c->preview_fbo);
        if (c->preview)
            glDeleteTextures(1, &c->preview);
        c->preview = linear_texture(pw, ph);
        glGenFramebuffers(1, &c->preview_fbo);
        glBindFramebuffer(GL_FRAMEBUFFER, c->preview_fbo);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, c->preview, 0);
        c->preview_width = pw;
        c->preview_height = ph;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, c->preview_fbo);
    glViewport(x0, y0, w, h);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    blit(c, image, GL_NEAREST, 0, 0, (float)w / (float)tex_w, (float)h / (float)tex_h);
    return gl_check("drawing a preview tile", e);
}

int compositor_show_preview(struct compositor *c, struct error *e)
{
    if (!c->preview)
        return 0;
    return compositor_put_preview(c, c->preview, e);
}

/* A rectangle of the canvas (x, y from the top-left corner) as the viewport (GL's rows bottom-up). */
static void canvas_viewport(const struct compositor *c, int x, int y, int w, int h)
{
    glViewport(x, c->height - y - h, w, h);
}

/* Panel k's viewport on the canvas. */
static void panel_viewport(const struct compositor *c, int k)
{
    int x, y, w, h;
    pipeline_panel_rect(c->width, c->height, k, &x, &y, &w, &h);
    canvas_viewport(c, x, y, w, h);
}

int compositor_put_pipeline(struct compositor *c, const struct renderer_textures *t, double bound_radius,
                            int segments, double step, double steps_budget, struct error *e)
{
    to_canvas(c, 0, 0, c->width, c->height);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    /* top row: image, positions, directions; bottom row: segment index, step size, outcome */
    panel_viewport(c, 0);
    blit(c, t->image, GL_NEAREST, 0, 0, 1, 1);
    GLuint p = c->pipeline;
    glUseProgram(p);
    bind_sampler(p, "u_position", 0, t->position);
    bind_sampler(p, "u_velocity", 1, t->velocity);
    bind_sampler(p, "u_hit", 2, t->hit);
    bind_sampler(p, "u_outcome", 3, t->outcome);
    set_uv_rect(p, 0, 0, 1, 1);
    glUniform1f(glGetUniformLocation(p, "u_bound_radius"), (float)bound_radius);
    glUniform1f(glGetUniformLocation(p, "u_segments"), (float)(segments > 0 ? segments : 1));
    glUniform1f(glGetUniformLocation(p, "u_step"), (float)step);
    glUniform1f(glGetUniformLocation(p, "u_steps_budget"), (float)steps_budget);
    /* exact orbits: the step-size panel shows the orbit table instead */
    bind_sampler(p, "u_orbit_table", 4, t->orbit_table);
    glActiveTexture(GL_TEXTURE0);
    glUniform2f(glGetUniformLocation(p, "u_orbit_size"), (float)t->orbit_width, (float)t->orbit_height);
    glUniform1f(glGetUniformLocation(p, "u_orbit_columns"), (float)t->orbit_columns);
    glUniform1f(glGetUniformLocation(p, "u_orbit_rows"), t->orbit_table ? (float)t->orbit_rows_per_side : 0.0f);
    glUniform1f(glGetUniformLocation(p, "u_orbit_u_capture"), (float)t->orbit_u_capture);
    for (int k = 0; k < 5; k++) {
        panel_viewport(c, k + 1);
        glUniform1f(glGetUniformLocation(p, "u_panel"), (float)k);
        quad_draw(p, 0.0f);
    }
    /* the colour scales under the segment-of-the-hit and step-size (orbit table) panels, the
     * legend under the outcome panel (the HUD names their ends and colours) */
    for (int k = 3; k < 6; k++) {
        int x, y, w, h;
        if (pipeline_legend_rect(c->width, c->height, k, &x, &y, &w, &h) != 0)
            continue;
        canvas_viewport(c, x, y, w, h);
        glUniform1f(glGetUniformLocation(p, "u_panel"), k == 5 ? 6.0f : 5.0f);
        quad_draw(p, 0.0f);
    }
    return gl_check("drawing the pipeline view", e);
}

int compositor_set_hud(struct compositor *c, const unsigned char *rgba, int width, int height, struct error *e)
{
    if (!rgba) {
        c->hud_valid = 0;
        return 0;
    }
    if (!c->hud || c->hud_width != width || c->hud_height != height) {
        if (c->hud)
            glDeleteTextures(1, &c->hud);
        c->hud = linear_texture(width, height);
        c->hud_width = width;
        c->hud_height = height;
    }
    glBindTexture(GL_TEXTURE_2D, c->hud);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    c->hud_valid = 1;
    /* most of the HUD is clear: only its rows with something on them are blended over the frame */
    int top = height, bottom = -1;
    for (int y = 0; y < height; y++) {
        const unsigned char *row = rgba + 4 * (size_t)y * width;
        int clear = 1;
        for (int x = 0; x < width && clear; x++)
            clear = row[4 * x + 3] == 0;
        if (!clear) {
            top = y < top ? y : top;
            bottom = y;
        }
    }
    c->hud_top = bottom < 0 ? 0 : top;
    c->hud_rows = bottom < 0 ? 0 : bottom - top + 1;
    if (gl_fault("hud_whole")) {
        c->hud_top = 0;
        c->hud_rows = height;
    }
    return gl_check("uploading the HUD", e);
}

void compositor_letterbox(const struct compositor *c, int sw, int sh, int *x, int *y, int *w, int *h)
{
    double scale_x = (double)sw / c->width, scale_y = (double)sh / c->height;
    double scale = scale_x < scale_y ? scale_x : scale_y;
    *w = (int)(c->width * scale + 0.5);
    *h = (int)(c->height * scale + 0.5);
    *x = (sw - *w) / 2;
    /* GL's viewport leaves (sh - h) / 2 rows below the canvas: the rest lie above it */
    *y = sh - *h - (sh - *h) / 2;
}

/* The canvas on a screen of its own size, copied texel for texel (glBlitFramebuffer): 1, or 0
 * where the copy is not available, or this screen refused it (a GL error: then never again). */
static int copy_canvas(struct compositor *c, const struct screen *s)
{
    if (!c->framebuffer_blit || s->width != c->width || s->height != c->height)
        return 0;
    while (glGetError() != GL_NO_ERROR) {
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, c->canvas_fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, s->framebuffer);
    glBlitFramebuffer(0, 0, c->width, c->height, 0, 0, c->width, c->height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, s->framebuffer);
    if (glGetError() == GL_NO_ERROR)
        return 1;
    /* a screen whose framebuffer the copy cannot take (multisampled, say): drawn from now on */
    c->framebuffer_blit = 0;
    return 0;
}

int compositor_draw(struct compositor *c, const struct screen *s, struct error *e)
{
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    if (!copy_canvas(c, s)) {
        glBindFramebuffer(GL_FRAMEBUFFER, s->framebuffer);
        glViewport(0, 0, s->width, s->height);
        glClearColor(0, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        /* letterbox: the canvas keeps its aspect ratio, centred */
        int x, y, w, h;
        compositor_letterbox(c, s->width, s->height, &x, &y, &w, &h);
        glViewport(x, (s->height - h) / 2, w, h);
        blit(c, c->canvas, w == c->width && h == c->height ? GL_NEAREST : GL_LINEAR, 0, 0, 1, 1);
    }
    if (c->hud_valid && c->hud_rows > 0) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        int same_size = c->hud_width == s->width && c->hud_height == s->height;
        if (same_size && c->hud_rows < c->hud_height) {
            /* texel for texel, only the HUD's rows with something on them (its rows are top-down:
             * flipped): the pixels of the whole HUD blended, where alpha 0 keeps the frame */
            int H = c->hud_height, lo = c->hud_top, n = c->hud_rows;
            glViewport(0, H - lo - n, s->width, n);
            blit(c, c->hud, GL_NEAREST, 0, (float)(lo + n) / (float)H, 1, -(float)n / (float)H);
        } else {
            glViewport(0, 0, s->width, s->height);
            blit(c, c->hud, same_size ? GL_NEAREST : GL_LINEAR, 0, 1, 1, -1);
        }
        glDisable(GL_BLEND);
    }
    return gl_check("drawing the frame on the screen", e);
}

int compositor_read_screen(const struct screen *s, unsigned char *rgba, struct error *e)
{
    size_t row = (size_t)s->width * 4;
    unsigned char *rows = malloc(row * (size_t)s->height);
    if (!rows) {
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory reading the screen back");
    }
    glBindFramebuffer(GL_FRAMEBUFFER, s->framebuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, s->width, s->height, GL_RGBA, GL_UNSIGNED_BYTE, rows);
    for (int y = 0; y < s->height; y++)
        memcpy(rgba + (size_t)(s->height - 1 - y) * row, rows + (size_t)y * row, row);
    free(rows);
    return gl_check("reading the screen back", e);
}
