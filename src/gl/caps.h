/* What the GL context can really do, proved by rendering and reading back, never taken
 * from extension strings alone. */
#ifndef BT_CAPS_H
#define BT_CAPS_H
#include "gl/context.h"
#include "gl/gl_api.h"
#include "gl/shader.h"

#define CAPS_MAX_FORMATS 4
/* Turns of a fragment-shader loop the probe asks for: more than a single-pass frame ever needs
 * (SCENE_MAX_SEGMENTS segments). */
#define CAPS_LOOP_TURNS_PROBED 200000L

struct float_format {
    const char *name;          /* "RGBA32F", "RGBA16F", ... */
    GLint internal_format;
    GLenum format, type;
    int is_fp32;               /* 32-bit mantissa class (else half float) */
    int works;                 /* renders, samples and keeps its precision */
    char why[160];             /* what failed when it does not work */
};

struct gl_caps {
    char version[160], renderer[160], vendor[160], glsl_version[160];
    const char *backend;
    char platform_version[64];
    int is_es, major, minor;
    int fragment_highp, fragment_highp_bits;
    /* the probe's arithmetic came out as 32-bit floats compute it (lima reports highp and computes
     * in fp16; a GPU without highp computes bentray's mediump shaders in fp16 or less) */
    int fragment_fp32;
    char fragment_fp32_why[160];
    /* floats unpacked from RGBA8 texels and packed again came back bit for bit (gl/packing.h) */
    int packing;
    char packing_why[160];
    int max_texture_size, max_draw_buffers;
    int derivatives;                 /* dFdx, dFdy in fragment shaders (the GPU's star pass) */
    int max_fragment_uniform_vectors, max_texture_units;
    int mrt_works;
    char mrt_why[160];
    /* the GL draws on the CPU (Mesa's llvmpipe or softpipe, swrast): its shaders' values live in
     * the CPU's caches and memory, no register file of the GPU's bounds what a loop may carry.
     * Where it is not, the single passes take their variants for a GPU's register file (the walk
     * on exact orbits in a pass of its own, the chord cull read from its uniforms);
     * BT_FAULT=gpu_rasterizer takes those on a CPU rasteriser too, for the tests. */
    int cpu_rasterizer;
    int long_loops;                  /* long fragment loops: the single-pass frame */
    /* the most turns one fragment-shader loop really runs, probed up to CAPS_LOOP_TURNS_PROBED
     * (llvmpipe ends every loop after 65535); 0 where long loops do not run */
    long loop_turns;
    char long_loops_why[160];
    /* occlusion queries that count what passes the depth test: the multipass scheme stops once
     * every ray is retired. query_target: GL_ANY_SAMPLES_PASSED_CONSERVATIVE (ES) or
     * GL_SAMPLES_PASSED (desktop GL). */
    int occlusion_query;
    GLenum query_target;
    char query_why[160];
    /* glBlitFramebuffer copies a rectangle of one framebuffer into another, texel for texel: the
     * kiosk puts its canvas on a screen of the same size that way (a copy, not a drawn quad) */
    int framebuffer_blit;
    char blit_why[160];
    int n_formats;
    struct float_format formats[CAPS_MAX_FORMATS];
    struct shader_target shader;     /* preamble settings for this context */
};

/* Whole-token search in a space-separated extension list. */
int extension_list_has(const char *list, const char *token);
int gl_has_extension(const char *name);

/* Test hook for the GL fault paths (docs/LIMITS.md): 1 when the environment variable BT_FAULT
 * lists NAME among its comma- or space-separated words. The only reader of BT_FAULT. Names:
 *   float_render         the probe finds the 32-bit float formats not renderable
 *   half_float_render    the same for the 16-bit formats
 *   fbo_incomplete       ray-state framebuffers with 32-bit float attachments are incomplete
 *                        (render/path.c), although the probe's plain targets work
 *   half_fbo_incomplete  the same for 16-bit float attachments
 *   mrt_fbo_incomplete   ray-state framebuffers with two colour targets (MRT) are incomplete
 *   framebuffer_blit     the probe finds glBlitFramebuffer missing (the kiosk draws its canvas)
 *   hud_whole            the kiosk blends its whole HUD, not only the rows with something on them
 *   no_highp             the GPU reports no highp float in fragment shaders: they declare mediump,
 *                        which llvmpipe then really computes in 16-bit floats
 *   fp16_alu             the arithmetic probe finds 16-bit floats although highp is reported (lima)
 *   packing              the packing probe finds a float that does not come back bit for bit
 *   loop_limit           the loop probe finds loops ended after 4096 turns (llvmpipe: 65535)
 *   slow_previews        the kiosk measures its previews 100 times slower, and at least 20 us a
 *                        pixel, as on a slow GPU
 *                        (kiosk_tune.h) */
int gl_fault(const char *name);
/* "GL_FRAMEBUFFER_UNSUPPORTED" and the like, for messages. */
const char *gl_framebuffer_status_name(GLenum status);

/* Probe the current context. Returns 0; the probe itself failing (no shader compiles) gives -1
 * with E filled (ERROR_INPUT for a shader file under --shader-dir that cannot be read). */
int gl_caps_probe(struct gl_caps *caps, const struct gl_context *ctx, struct error *e);
/* The best working format of the class (fp32 or fp16), or NULL. */
const struct float_format *caps_format(const struct gl_caps *caps, int fp32);

#endif
