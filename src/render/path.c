#include "render/path.h"
#include "gl/texture.h"
#include <stdio.h>
#include <string.h>

/* Side of the textures of the framebuffer check, texels: completeness does not depend on the
 * size below GL_MAX_TEXTURE_SIZE, which renderer_create checks against the image. */
#define PATH_CHECK_SIZE 4

static void explain_formats(const struct gl_caps *c, int fp32, char *out, size_t n)
{
    size_t used = 0;
    out[0] = '\0';
    for (int i = 0; i < c->n_formats && used < n; i++)
        if (c->formats[i].is_fp32 == fp32)
            used += snprintf(out + used, n - used, "%s%s: %s", used ? "; " : "", c->formats[i].name,
                             c->formats[i].works ? "works" : c->formats[i].why);
    if (!used)
        snprintf(out, n, "no %s format is known for this API", fp32 ? "32-bit" : "16-bit");
}

GLenum render_path_framebuffer_status(const struct float_format *f, int targets)
{
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (f && (gl_fault(f->is_fp32 ? "fbo_incomplete" : "half_fbo_incomplete") ||
              (targets > 1 && gl_fault("mrt_fbo_incomplete"))))
        return GL_FRAMEBUFFER_UNSUPPORTED;
    return status;
}

/* The ray state's framebuffer in small: one or two colour targets of format f and a 16-bit depth
 * renderbuffer, as raystate_init and raystate_fbo make them. Leaves no GL error behind. */
GLenum render_path_state_status(const struct float_format *f, int mrt)
{
    GLuint tex[2] = {0, 0}, depth, fbo;
    int n = mrt ? 2 : 1;
    while (glGetError() != GL_NO_ERROR) {
    }
    for (int i = 0; i < n; i++)
        tex[i] = texture_create_nearest(f->internal_format, f->format, f->type, PATH_CHECK_SIZE, PATH_CHECK_SIZE);
    glGenRenderbuffers(1, &depth);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT16, PATH_CHECK_SIZE, PATH_CHECK_SIZE);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[0], 0);
    if (mrt) {
        static const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, tex[1], 0);
        glDrawBuffers(2, both);
    }
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    GLenum status = render_path_framebuffer_status(f, n);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    glDeleteRenderbuffers(1, &depth);
    glDeleteTextures(n, tex);
    while (glGetError() != GL_NO_ERROR) {
    }
    return status;
}

int render_path_can_fuse(const struct gl_caps *c, int mrt) { return mrt && c->max_draw_buffers >= SEGMENT_FUSED_TARGETS; }

static const char *path_name(int fp32, int mrt)
{
    return fp32 ? (mrt ? "fp32+mrt" : "fp32") : (mrt ? "fp16+mrt" : "fp16");
}

static void describe(struct render_path *p, const char *fallback)
{
    snprintf(p->description, sizeof p->description, "%s: %s ray state, %s%s%s%s", p->name, p->format->name,
             p->mrt ? "x and v written by one pass (MRT)" : "x and v written in separate passes",
             p->fp32 ? "" : " (reduced accuracy: 16-bit floats)", fallback[0] ? " " : "", fallback);
}

/* The orbit table's format where the ray state's is not 32-bit: RGBA32F, which OpenGL ES 3 and desktop
 * OpenGL sample with NEAREST whether or not they render into it. */
static const struct float_format sampled_rgba32f = {"RGBA32F", GL_RGBA32F, GL_RGBA, GL_FLOAT, 1, 1, ""};

/* The image-only path: the single pass's colour (and outcome codes, in a second 8-bit target where
 * two draw buffers work) in 8-bit targets, the orbit table sampled as RGBA32F, which OpenGL ES 3
 * and desktop OpenGL sample with NEAREST whether or not they render into it. */
static int image_only(const struct gl_caps *c, enum mrt_choice mrt, struct render_path *p, struct error *e)
{
    if (mrt == MRT_ON && !c->mrt_works)
        return error_set(e, ERROR_INPUT, NULL, "mrt=on: multiple render targets do not work here (%s)", c->mrt_why);
    p->format = NULL;
    p->image_only = 1;
    p->fp32 = 1;
    p->mrt = mrt != MRT_OFF && c->mrt_works;
    p->table_format = &sampled_rgba32f;
    p->name = "image only";
    snprintf(p->description, sizeof p->description, "image only: no float format renders here (bentray info), so "
             "the single pass draws each frame's image%s into 8-bit targets; the rest of the ray state cannot be read",
             p->mrt ? " and its rays' outcomes" : "");
    return 0;
}

/* The packed path's textures: RGBA8, each texel one float of a 32-bit ray state (raystate.h). */
static const struct float_format packed_rgba8 = {"RGBA8 (packed floats)", GL_RGBA, GL_RGBA, GL_UNSIGNED_BYTE, 1, 1, ""};

static int packed(const struct gl_caps *c, enum mrt_choice mrt, struct render_path *p, struct error *e)
{
    if (mrt == MRT_ON)
        return error_set(e, ERROR_INPUT, NULL, "mrt=on: the packed path (no float format renders here) writes one "
                         "target a pass");
    p->format = &packed_rgba8;
    p->packed = 1;
    p->fp32 = 1;
    p->mrt = 0;
    p->table_format = &packed_rgba8;   /* the orbit table packed the same way (stage_orbit.c) */
    p->name = "packed 8-bit";
    const char *why = caps_format(c, 1)   ? "render.precision = packed"
                      : caps_format(c, 0) ? "only 16-bit floats render here, which would change rays' outcomes "
                                            "from pass to pass"
                                          : "no float format renders here (bentray info)";
    snprintf(p->description, sizeof p->description, "packed 8-bit: %s, so each 32-bit float of the ray state is "
             "packed into an RGBA8 texel (probed exact), x and v written in separate passes", why);
    return 0;
}

int render_path_choose(const struct gl_caps *c, enum precision_choice precision, enum mrt_choice mrt,
                       struct render_path *p, struct error *e)
{
    char why32[400], why16[400];
    memset(p, 0, sizeof *p);
    explain_formats(c, 1, why32, sizeof why32);
    explain_formats(c, 0, why16, sizeof why16);
    const struct float_format *f32 = caps_format(c, 1), *f16 = caps_format(c, 0);
    if (precision == PRECISION_FP32 && !f32)
        return error_set(e, ERROR_INPUT, NULL, "--precision fp32: no 32-bit float render target works here (%s)",
                         why32);
    if (precision == PRECISION_FP16 && !f16)
        return error_set(e, ERROR_INPUT, NULL, "--precision fp16: no 16-bit float render target works here (%s)",
                         why16);
    if (precision == PRECISION_PACKED) {
        if (!c->packing)
            return error_set(e, ERROR_INPUT, NULL, "--precision packed: floats do not pack into RGBA8 texels exactly "
                             "here (%s)", c->packing_why);
        return packed(c, mrt, p, e);
    }
    /* a failure of a path the scene forced is the user's request, of the automatic choice the machine's */
    enum error_status whose = precision != PRECISION_AUTO || mrt == MRT_ON ? ERROR_INPUT : ERROR_RUNTIME;
    if (!f32 && !f16) {
        if (precision == PRECISION_AUTO && c->long_loops && c->fragment_highp)
            return image_only(c, mrt, p, e);
        if (precision == PRECISION_AUTO && c->packing)
            return packed(c, mrt, p, e);
        return error_set(e, whose, NULL, "this GPU has no renderable float format for the ray state (%s; %s); "
                         "bentray needs RGBA32F or RGBA16F render targets%s, or floats packed into RGBA8 texels "
                         "exactly (%s)", why32, why16,
                         c->long_loops ? "" : ", or long fragment-shader loops (OpenGL ES 3) for the image alone",
                         c->packing_why);
    }
    if (mrt == MRT_ON && !c->mrt_works)
        return error_set(e, ERROR_INPUT, NULL, "mrt=on: multiple render targets do not work here (%s)", c->mrt_why);
    /* 16-bit floats change rays' outcomes where the ray state is stored between passes (a GPU without
     * long loops: the fused pass, the multipass scheme); packed 32-bit ones keep them. The single pass
     * keeps its rays in 32-bit registers and stores only their results. */
    if (precision == PRECISION_AUTO && !f32 && !c->long_loops && c->packing && mrt != MRT_ON)
        return packed(c, mrt, p, e);
    /* the paths in order of preference: the first that the scene allows (a forced precision or MRT
     * setting is kept), the probe found working and whose ray-state framebuffer is complete */
    static const struct { int fp32, mrt; } order[4] = {{1, 1}, {1, 0}, {0, 1}, {0, 0}};
    const struct float_format *preferred = NULL;
    int preferred_mrt = 0;
    char fallback[96] = "";
    for (int i = 0; i < 4; i++) {
        const struct float_format *f = order[i].fp32 ? f32 : f16;
        if (!f || (order[i].mrt && (mrt == MRT_OFF || !c->mrt_works)) || (!order[i].mrt && mrt == MRT_ON) ||
            (precision == PRECISION_FP32 && !order[i].fp32) || (precision == PRECISION_FP16 && order[i].fp32))
            continue;
        if (!preferred) {
            preferred = f;
            preferred_mrt = order[i].mrt;
        }
        GLenum status = render_path_state_status(f, order[i].mrt);
        if (status == GL_FRAMEBUFFER_COMPLETE) {
            p->format = f;
            p->mrt = order[i].mrt;
            break;
        }
        if (!fallback[0])
            snprintf(fallback, sizeof fallback, "(fell back from %s: %s framebuffer incomplete)",
                     path_name(preferred->is_fp32, preferred_mrt), preferred->name);
    }
    if (!preferred)
        return error_set(e, whose, NULL, "internal: no render path fits precision %d and mrt %d",
                         (int)precision, (int)mrt);
    if (!p->format) {
        /* nothing complete: the preferred path, so that its failure is the one reported */
        p->format = preferred;
        p->mrt = preferred_mrt;
        fallback[0] = '\0';
    }
    p->fp32 = p->format->is_fp32;
    p->table_format = p->fp32 ? p->format : c->long_loops ? &sampled_rgba32f : NULL;
    p->name = path_name(p->fp32, p->mrt);
    describe(p, fallback);
    return 0;
}
