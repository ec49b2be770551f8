#include "gl/caps.h"
#include "gl/packing.h"
#include "gl/quad.h"
#include "gl/readback.h"
#include "gl/texture.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PROBE_SIZE 4

int extension_list_has(const char *list, const char *token)
{
    size_t n = strlen(token);
    for (const char *p = list; p && (p = strstr(p, token)) != NULL; p += n) {
        int starts = (p == list || p[-1] == ' ');
        int ends = (p[n] == ' ' || p[n] == '\0');
        if (starts && ends)
            return 1;
    }
    return 0;
}

int gl_has_extension(const char *name)
{
    return extension_list_has((const char *)glGetString(GL_EXTENSIONS), name);
}

int gl_fault(const char *name)
{
    const char *list = getenv("BT_FAULT");
    size_t n = strlen(name);
    if (!list || n == 0)
        return 0;
    for (const char *p = list; (p = strstr(p, name)) != NULL; p += n) {
        int starts = p == list || p[-1] == ',' || p[-1] == ' ';
        int ends = p[n] == ',' || p[n] == ' ' || p[n] == '\0';
        if (starts && ends)
            return 1;
    }
    return 0;
}

const char *gl_framebuffer_status_name(GLenum status)
{
    switch (status) {
    case GL_FRAMEBUFFER_COMPLETE: return "GL_FRAMEBUFFER_COMPLETE";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS: return "GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    case 0: return "no status (the check itself failed)";
    default: return "an unknown framebuffer status";
    }
}

static void copy_string(char *dst, size_t n, GLenum name)
{
    const GLubyte *s = glGetString(name);
    snprintf(dst, n, "%s", s ? (const char *)s : "(unknown)");
}

static void parse_version(struct gl_caps *c)
{
    const char *v = c->version;
    if (strncmp(v, "OpenGL ES ", 10) == 0)
        v += 10;
    if (sscanf(v, "%d.%d", &c->major, &c->minor) != 2)
        c->major = c->minor = 0;
}

static void add_format(struct gl_caps *c, const char *name, GLint internal, GLenum format, GLenum type, int fp32)
{
    struct float_format *f = &c->formats[c->n_formats++];
    f->name = name;
    f->internal_format = internal;
    f->format = format;
    f->type = type;
    f->is_fp32 = fp32;
}

/* Candidates in order of preference. ES2 has no sized float formats; its unsized GL_RGBA/GL_FLOAT
 * is listed so that `bentray info` shows it failing rather than silently skipping it. */
static void list_candidates(struct gl_caps *c)
{
    if (!c->is_es || c->major >= 3) {
        add_format(c, "RGBA32F", GL_RGBA32F, GL_RGBA, GL_FLOAT, 1);
        add_format(c, "RGBA16F", GL_RGBA16F, GL_RGBA, c->is_es ? GL_HALF_FLOAT : GL_FLOAT, 0);
        return;
    }
    add_format(c, "RGBA/FLOAT (OES_texture_float)", GL_RGBA, GL_RGBA, GL_FLOAT, 1);
    add_format(c, "RGBA/HALF_FLOAT_OES (OES_texture_half_float)", GL_RGBA, GL_RGBA, GL_HALF_FLOAT_OES, 0);
}

static GLuint make_target(const struct float_format *f, GLuint *fbo)
{
    GLuint tex = texture_create_nearest(f->internal_format, f->format, f->type, PROBE_SIZE, PROBE_SIZE);
    glGenFramebuffers(1, fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, *fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    return tex;
}

static void set_probe(GLuint prog, const float v[4], int use_source)
{
    glUseProgram(prog);
    glUniform4f(glGetUniformLocation(prog, "u_value"), v[0], v[1], v[2], v[3]);
    glUniform1f(glGetUniformLocation(prog, "u_use_source"), use_source ? 1.0f : 0.0f);
    glUniform1i(glGetUniformLocation(prog, "u_source"), 0);
}

static int close_to(const float *got, const float *want, float tol)
{
    for (int i = 0; i < 4; i++)
        if (!(fabsf(got[i] - want[i]) <= tol * fmaxf(1.0f, fabsf(want[i]))))
            return 0;
    return 1;
}

/* Render a value into texture A, sample A into B adding a second value, read B back. The values
 * need the format's precision: 1 + 2^-20 (fp32) or 1 + 2^-10 (fp16), negative and > 1 (not unorm). */
static void probe_format(struct float_format *f, GLuint prog)
{
    const float fp32_a[4] = {1.0f + 0x1p-20f, -3.25f, 65537.0f, 0.5f};
    const float fp16_a[4] = {1.0f + 0x1p-10f, -3.25f, 1000.5f, 0.5f};
    const float *a = f->is_fp32 ? fp32_a : fp16_a;
    const float b[4] = {f->is_fp32 ? 0x1p-20f : 0x1p-10f, 0.0f, 1.0f, 0.25f};
    float want[4], got[4 * PROBE_SIZE * PROBE_SIZE];
    for (int i = 0; i < 4; i++)
        want[i] = a[i] + b[i];

    while (glGetError() != GL_NO_ERROR) {
    }
    GLuint fbo_a, fbo_b;
    GLuint tex_a = make_target(f, &fbo_a);
    GLuint tex_b = make_target(f, &fbo_b);
    GLenum status_a, status_b;
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_a);
    status_a = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_b);
    status_b = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    GLenum gl_err = glGetError();
    if (gl_fault(f->is_fp32 ? "float_render" : "half_float_render")) {
        snprintf(f->why, sizeof f->why, "not a render target (BT_FAULT=%s)",
                 f->is_fp32 ? "float_render" : "half_float_render");
    } else if (gl_err != GL_NO_ERROR) {
        snprintf(f->why, sizeof f->why, "texture creation fails (%s)", gl_error_name(gl_err));
    } else if (status_a != GL_FRAMEBUFFER_COMPLETE || status_b != GL_FRAMEBUFFER_COMPLETE) {
        GLenum status = status_a != GL_FRAMEBUFFER_COMPLETE ? status_a : status_b;
        snprintf(f->why, sizeof f->why, "not a render target (%s, 0x%04x)", gl_framebuffer_status_name(status),
                 status);
    } else {
        glViewport(0, 0, PROBE_SIZE, PROBE_SIZE);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_a);
        set_probe(prog, a, 0);
        quad_draw(prog, 0.0f);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_b);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, tex_a);
        set_probe(prog, b, 1);
        quad_draw(prog, 0.0f);
        if (read_float_pixels(0, 0, PROBE_SIZE, PROBE_SIZE, got) != 0)
            snprintf(f->why, sizeof f->why, "renders, but cannot be read back as floats");
        else if (!close_to(got, want, f->is_fp32 ? 0x1p-23f : 0x1p-12f))
            snprintf(f->why, sizeof f->why, "loses precision: wrote %.9g %.9g %.9g %.9g, read %.9g %.9g %.9g %.9g",
                     want[0], want[1], want[2], want[3], got[0], got[1], got[2], got[3]);
        else if ((gl_err = glGetError()) != GL_NO_ERROR)
            snprintf(f->why, sizeof f->why, "rendering fails (%s)", gl_error_name(gl_err));
        else
            f->works = 1;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo_a);
    glDeleteFramebuffers(1, &fbo_b);
    glDeleteTextures(1, &tex_a);
    glDeleteTextures(1, &tex_b);
    while (glGetError() != GL_NO_ERROR) {
    }
}

/* Two draw buffers written by one pass, each read back: GL_MAX_DRAW_BUFFERS alone can lie. */
static void probe_mrt(struct gl_caps *c, const struct float_format *f)
{
    static const char *const vs[] = {"quad_vertex.glsl", NULL};
    static const char *const fs[] = {"probe_fragment.glsl", NULL};
    /* without a float format that renders, the targets the image-only path writes: RGBA8 */
    static const struct float_format rgba8 = {"RGBA8", GL_RGBA, GL_RGBA, GL_UNSIGNED_BYTE, 0, 1, ""};
    int bytes = f == NULL;
    if (bytes)
        f = &rgba8;
    if (c->max_draw_buffers < 2 || !bt_gl.DrawBuffers) {
        snprintf(c->mrt_why, sizeof c->mrt_why, "GL_MAX_DRAW_BUFFERS is %d%s", c->max_draw_buffers,
                 bt_gl.DrawBuffers ? "" : " and glDrawBuffers is missing");
        return;
    }
    if (c->is_es && c->major < 3 && !gl_has_extension("GL_EXT_draw_buffers")) {
        snprintf(c->mrt_why, sizeof c->mrt_why, "GL_EXT_draw_buffers is missing");
        return;
    }
    struct shader_target t = c->shader;
    t.draw_buffers_ext = c->is_es;
    struct error err;
    GLuint prog = shader_program_build(&t, "#define PROBE_MRT 1\n", vs, fs, &err);
    if (!prog) {
        snprintf(c->mrt_why, sizeof c->mrt_why, "a shader writing gl_FragData[1] does not compile");
        return;
    }
    GLuint fbo, fbo1;
    GLuint tex0 = make_target(f, &fbo);
    GLuint tex1 = make_target(f, &fbo1);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, tex1, 0);
    static const GLenum bufs[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, bufs);
    const float v[4] = {1.5f, -2.0f, 3.0f, 0.25f}, want[4] = {3.0f, -4.0f, 6.0f, 0.5f};
    /* in 8 bits: values in [0, 1], the second target twice the first */
    const float v8[4] = {0.25f, 0.125f, 0.375f, 0.25f}, want8[4] = {0.5f, 0.25f, 0.75f, 0.5f};
    float got[4 * PROBE_SIZE * PROBE_SIZE];
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        snprintf(c->mrt_why, sizeof c->mrt_why, "a framebuffer with two %s attachments is incomplete",
                 bytes ? "RGBA8" : "float");
    } else {
        glViewport(0, 0, PROBE_SIZE, PROBE_SIZE);
        set_probe(prog, bytes ? v8 : v, 0);
        quad_draw(prog, 0.0f);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo1);
        int read = 0;
        if (bytes) {
            unsigned char b[4 * PROBE_SIZE * PROBE_SIZE];
            glPixelStorei(GL_PACK_ALIGNMENT, 1);
            glReadPixels(0, 0, PROBE_SIZE, PROBE_SIZE, GL_RGBA, GL_UNSIGNED_BYTE, b);
            for (int i = 0; i < 4; i++)
                got[i] = b[i] / 255.0f;
        } else {
            read = read_float_pixels(0, 0, PROBE_SIZE, PROBE_SIZE, got);
        }
        if (read != 0 || !close_to(got, bytes ? want8 : want, bytes ? 1.0f / 255.0f : 1e-3f))
            snprintf(c->mrt_why, sizeof c->mrt_why, "the second draw buffer is not written");
        else
            c->mrt_works = glGetError() == GL_NO_ERROR;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    glDeleteFramebuffers(1, &fbo1);
    glDeleteTextures(1, &tex0);
    glDeleteTextures(1, &tex1);
    glDeleteProgram(prog);
    while (glGetError() != GL_NO_ERROR) {
    }
}

/* probe_fragment.glsl with `defines`, drawn with u_value v into an RGBA8 target of PROBE_SIZE
 * pixels, its first pixel read back into got: 0, or -1 where it does not compile or the target is
 * incomplete (got left alone). */
static int probe_draw_rgba8(const struct gl_caps *c, const char *defines, const float v[4], unsigned char got[4])
{
    static const char *const vs[] = {"quad_vertex.glsl", NULL};
    static const char *const fs[] = {"probe_fragment.glsl", NULL};
    struct error err;
    GLuint prog = shader_program_build(&c->shader, defines, vs, fs, &err);
    if (!prog)
        return -1;
    GLuint tex, fbo;
    int complete = texture_rgba8_target(PROBE_SIZE, PROBE_SIZE, &tex, &fbo);
    if (complete) {
        glViewport(0, 0, PROBE_SIZE, PROBE_SIZE);
        set_probe(prog, v, 0);
        quad_draw(prog, 0.0f);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, got);
    }
    texture_rgba8_target_release(tex, fbo);
    glDeleteProgram(prog);
    while (glGetError() != GL_NO_ERROR) {
    }
    return complete ? 0 : -1;
}

/* A product that 32-bit floats get right and 16-bit ones do not, drawn with the precision the
 * renderer's shaders declare into an RGBA8 target and read back (probe_fragment.glsl). */
static void probe_arithmetic(struct gl_caps *c)
{
    const float one_plus = 1.0f + 1.0f / 4096.0f, v[4] = {one_plus, one_plus, 1024.0f, 0.0f};
    unsigned char got[4] = {0, 0, 0, 0};
    if (probe_draw_rgba8(c, "#define PROBE_ARITHMETIC 1\n", v, got) != 0) {
        snprintf(c->fragment_fp32_why, sizeof c->fragment_fp32_why, "the arithmetic probe does not compile");
        return;
    }
    /* 0.5005 is 128 of 255; fp16 gives 0 */
    c->fragment_fp32 = got[0] >= 120 && got[0] <= 136 && !gl_fault("fp16_alu");
    if (!c->fragment_fp32)
        snprintf(c->fragment_fp32_why, sizeof c->fragment_fp32_why, "(1 + 2^-12)^2 - 1 came out as %.4f x 2^-10, "
                 "not 0.5005 x 2^-10: the fragment shaders compute in 16-bit floats or less%s",
                 got[0] / 255.0, gl_fault("fp16_alu") ? " (BT_FAULT=fp16_alu)" : "");
}

/* The most turns a fragment-shader loop runs: CAPS_LOOP_TURNS_PROBED asked for, and what one
 * really ran read back (llvmpipe stops every loop after 65535). Only where long loops run at all. */
static void probe_loops(struct gl_caps *c)
{
    c->loop_turns = c->long_loops ? CAPS_LOOP_TURNS_PROBED : 0;
    if (!c->long_loops)
        return;
    char defines[64];
    snprintf(defines, sizeof defines, "#define PROBE_LOOPS 1\n#define PROBE_LOOP_TURNS %ld\n",
             CAPS_LOOP_TURNS_PROBED + 1);
    const float v[4] = {(float)CAPS_LOOP_TURNS_PROBED, 0.3f, 0.0f, 0.0f};
    unsigned char got[4] = {0, 0, 0, 0};
    if (probe_draw_rgba8(c, defines, v, got) != 0) {
        c->loop_turns = 0;
        return;
    }
    long turns = got[0] + 256L * got[1] + 65536L * got[2];
    c->loop_turns = turns < CAPS_LOOP_TURNS_PROBED ? turns : CAPS_LOOP_TURNS_PROBED;
    if (gl_fault("loop_limit"))
        c->loop_turns = 4096;          /* a GPU that ends loops early, as llvmpipe does at 65535 */
}

/* Samples that pass the depth test of one draw of the quad at depth 0.5 (NDC z 0) over a depth
 * buffer cleared to `depth`, counted by an occlusion query of the context's kind. */
static GLuint query_draw(const struct gl_caps *c, GLuint prog, GLuint query, float depth)
{
    GLuint passed = 0;
    glDepthMask(GL_TRUE);           /* a clear writes depth only where the mask lets it */
    glClearDepthf(depth);
    glClear(GL_DEPTH_BUFFER_BIT);
    glDepthMask(GL_FALSE);          /* the draw counts fragments; it writes no depth */
    glBeginQuery(c->query_target, query);
    quad_draw(prog, 0.0f);
    glEndQuery(c->query_target);
    glGetQueryObjectuiv(query, GL_QUERY_RESULT, &passed);
    return passed;
}

/* An occlusion query around a draw that the depth test passes, and around one it rejects: the
 * first must count, the second not (the multipass scheme stops on that zero). */
static void probe_query(struct gl_caps *c, GLuint prog)
{
    int api = c->is_es ? c->major >= 3 || gl_has_extension("GL_EXT_occlusion_query_boolean") : c->major >= 2;
    if (!api || !bt_gl.GenQueries || !bt_gl.BeginQuery || !bt_gl.EndQuery || !bt_gl.GetQueryObjectuiv ||
        !bt_gl.DeleteQueries) {
        snprintf(c->query_why, sizeof c->query_why, "%s", c->is_es ? "neither OpenGL ES 3 nor GL_EXT_occlusion_query_boolean"
                                                                  : "OpenGL below 2.0");
        return;
    }
    if (gl_fault("occlusion_query")) {
        snprintf(c->query_why, sizeof c->query_why, "BT_FAULT=occlusion_query");
        return;
    }
    c->query_target = c->is_es ? GL_ANY_SAMPLES_PASSED_CONSERVATIVE : 0x8914 /* GL_SAMPLES_PASSED */;
    GLuint tex, depth, fbo, query;
    tex = texture_create_nearest(GL_RGBA, GL_RGBA, GL_UNSIGNED_BYTE, PROBE_SIZE, PROBE_SIZE);
    glGenRenderbuffers(1, &depth);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT16, PROBE_SIZE, PROBE_SIZE);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    glGenQueries(1, &query);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        snprintf(c->query_why, sizeof c->query_why, "a framebuffer with a depth buffer is incomplete");
    } else {
        const float v[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        glViewport(0, 0, PROBE_SIZE, PROBE_SIZE);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        set_probe(prog, v, 0);
        GLuint open = query_draw(c, prog, query, 1.0f), closed = query_draw(c, prog, query, 0.0f);
        glDisable(GL_DEPTH_TEST);
        glDepthMask(GL_TRUE);
        glClearDepthf(1.0f);
        if (glGetError() != GL_NO_ERROR)
            snprintf(c->query_why, sizeof c->query_why, "an occlusion query raises a GL error");
        else if (open == 0 || closed != 0)
            snprintf(c->query_why, sizeof c->query_why, "an occlusion query counts %u where the depth test passes "
                     "and %u where it fails", open, closed);
        else
            c->occlusion_query = 1;
    }
    glDeleteQueries(1, &query);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    glDeleteRenderbuffers(1, &depth);
    glDeleteTextures(1, &tex);
    while (glGetError() != GL_NO_ERROR) {
    }
}

static GLuint probe_blit_target(GLuint *fbo, float r, float g, float b)
{
    GLuint tex = texture_create_nearest(GL_RGBA, GL_RGBA, GL_UNSIGNED_BYTE, PROBE_SIZE, PROBE_SIZE);
    glGenFramebuffers(1, fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, *fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    glViewport(0, 0, PROBE_SIZE, PROBE_SIZE);
    glClearColor(r, g, b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    return tex;
}

/* A blit of the left half of one framebuffer into another: that half must arrive byte for byte
 * and the other stay as it was. */
static void probe_blit(struct gl_caps *c)
{
    if (c->major < 3 || !bt_gl.BlitFramebuffer) {
        snprintf(c->blit_why, sizeof c->blit_why, "%s", c->is_es ? "OpenGL ES below 3.0" : "OpenGL below 3.0");
        return;
    }
    if (gl_fault("framebuffer_blit")) {
        snprintf(c->blit_why, sizeof c->blit_why, "BT_FAULT=framebuffer_blit");
        return;
    }
    GLuint from_fbo, to_fbo;
    GLuint from = probe_blit_target(&from_fbo, 1.0f, 0.0f, 0.0f);
    GLuint to = probe_blit_target(&to_fbo, 0.0f, 0.0f, 1.0f);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, from_fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, to_fbo);
    const int half = PROBE_SIZE / 2;
    glBlitFramebuffer(0, 0, half, PROBE_SIZE, 0, 0, half, PROBE_SIZE, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, to_fbo);
    unsigned char got[4 * PROBE_SIZE * PROBE_SIZE];
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, PROBE_SIZE, PROBE_SIZE, GL_RGBA, GL_UNSIGNED_BYTE, got);
    int wrong = 0;
    for (int y = 0; y < PROBE_SIZE; y++)
        for (int x = 0; x < PROBE_SIZE; x++) {
            const unsigned char *p = got + 4 * (y * PROBE_SIZE + x);
            int red = x < half;
            wrong += p[0] != (red ? 255 : 0) || p[1] != 0 || p[2] != (red ? 0 : 255) || p[3] != 255;
        }
    if (glGetError() != GL_NO_ERROR)
        snprintf(c->blit_why, sizeof c->blit_why, "glBlitFramebuffer raises a GL error");
    else if (wrong)
        snprintf(c->blit_why, sizeof c->blit_why, "glBlitFramebuffer copies %d of %d pixels wrong", wrong,
                 PROBE_SIZE * PROBE_SIZE);
    else
        c->framebuffer_blit = 1;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &from_fbo);
    glDeleteFramebuffers(1, &to_fbo);
    glDeleteTextures(1, &from);
    glDeleteTextures(1, &to);
    while (glGetError() != GL_NO_ERROR) {
    }
}

int gl_caps_probe(struct gl_caps *c, const struct gl_context *ctx, struct error *e)
{
    static const char *const vs[] = {"quad_vertex.glsl", NULL};
    static const char *const fs[] = {"probe_fragment.glsl", NULL};
    memset(c, 0, sizeof *c);
    c->backend = ctx->backend;
    snprintf(c->platform_version, sizeof c->platform_version, "%s", ctx->platform_version);
    c->is_es = ctx->is_es;
    copy_string(c->version, sizeof c->version, GL_VERSION);
    copy_string(c->renderer, sizeof c->renderer, GL_RENDERER);
    copy_string(c->vendor, sizeof c->vendor, GL_VENDOR);
    copy_string(c->glsl_version, sizeof c->glsl_version, GL_SHADING_LANGUAGE_VERSION);
    parse_version(c);
    c->cpu_rasterizer = (strstr(c->renderer, "llvmpipe") || strstr(c->renderer, "softpipe") ||
                         strstr(c->renderer, "swrast") || strstr(c->renderer, "SwiftShader")) &&
                        !gl_fault("gpu_rasterizer");
    /* GLSL ES 3.00 (and desktop GLSL) runs loops of any length; GLSL ES 1.00's appendix A lets a
     * GLES2 device refuse or cut a long fragment loop, so the single pass is not taken there
     * unless forced (render.pipeline = single) */
    c->long_loops = !c->is_es || c->major >= 3;
    snprintf(c->long_loops_why, sizeof c->long_loops_why,
             c->long_loops ? "%s %d.%d runs long fragment-shader loops"
                           : "%s %d.%d need not run long fragment-shader loops (GLSL ES 1.00, appendix A)",
             c->is_es ? "OpenGL ES" : "OpenGL", c->major, c->minor);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &c->max_texture_size);
    c->max_draw_buffers = 1;
    if (!c->is_es || c->major >= 3 || gl_has_extension("GL_EXT_draw_buffers"))
        glGetIntegerv(GL_MAX_DRAW_BUFFERS, &c->max_draw_buffers);
    /* the batch of objects per intersection pass is bounded by these two */
    glGetIntegerv(GL_MAX_FRAGMENT_UNIFORM_VECTORS, &c->max_fragment_uniform_vectors);
    if (c->max_fragment_uniform_vectors <= 0) {
        GLint components = 0;
        while (glGetError() != GL_NO_ERROR) {
        }
        glGetIntegerv(0x8B49 /* GL_MAX_FRAGMENT_UNIFORM_COMPONENTS, desktop GL */, &components);
        c->max_fragment_uniform_vectors = components > 0 ? components / 4 : 16; /* 16: the GLES2 minimum */
    }
    glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &c->max_texture_units);
    if (c->max_texture_units <= 0)
        c->max_texture_units = 8;                                               /* the GLES2 minimum */
    GLint range[2] = {0, 0}, precision = 0;
    glGetShaderPrecisionFormat(GL_FRAGMENT_SHADER, GL_HIGH_FLOAT, range, &precision);
    if (gl_fault("no_highp"))
        precision = 0;                 /* a GPU that reports no highp: the shaders declare mediump */
    c->fragment_highp_bits = precision;
    c->fragment_highp = precision > 0;
    while (glGetError() != GL_NO_ERROR) {
    }
    c->shader.dialect = ctx->dialect;
    c->shader.fragment_highp = c->fragment_highp;
    c->shader.draw_buffers_ext = 0;
    /* dFdx and dFdy: core in desktop GLSL 1.30, OES_standard_derivatives for GLSL ES 1.00 */
    c->derivatives = (!c->is_es || gl_has_extension("GL_OES_standard_derivatives")) && !gl_fault("no_derivatives");
    c->shader.derivatives_ext = c->is_es && c->derivatives;

    if (quad_init() != 0)
        return error_set(e, ERROR_RUNTIME, NULL, "cannot create the vertex buffer of the full-screen quad");
    GLuint prog = shader_program_build(&c->shader, NULL, vs, fs, e);
    if (!prog)
        return -1;
    list_candidates(c);
    for (int i = 0; i < c->n_formats; i++)
        probe_format(&c->formats[i], prog);
    probe_query(c, prog);
    probe_blit(c);
    probe_arithmetic(c);
    probe_loops(c);
    glDeleteProgram(prog);
    /* the packing, where the packed path may be taken: no 32-bit float format renders and no long
     * loops run (bentray info probes it everywhere) */
    c->packing = 0;
    snprintf(c->packing_why, sizeof c->packing_why, "not probed: %s",
             caps_format(c, 1) ? "a 32-bit float format renders" : "long loops run (the single pass)");
    if (!caps_format(c, 1) && !c->long_loops)
        probe_packing(c);
    const struct float_format *best = caps_format(c, 1);
    probe_mrt(c, best ? best : caps_format(c, 0));
    return 0;
}

const struct float_format *caps_format(const struct gl_caps *c, int fp32)
{
    for (int i = 0; i < c->n_formats; i++)
        if (c->formats[i].works && c->formats[i].is_fp32 == fp32)
            return &c->formats[i];
    return NULL;
}
