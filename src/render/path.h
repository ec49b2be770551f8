/* The render path: which float format holds the ray state and whether one pass writes
 * several targets (MRT) or each target gets its own pass. */
#ifndef BT_PATH_H
#define BT_PATH_H
#include "gl/caps.h"
#include "scene/scene.h"

struct render_path {
    const struct float_format *format;  /* of the ray state's textures; NULL on the image-only path */
    int fp32;                 /* 0: fp16, reduced accuracy */
    int mrt;                  /* 1: x and v (and hit, image) written by one pass */
    /* 1: no float format renders here, but the GPU runs long loops: the single pass draws each
     * frame's image (and its rays' outcome codes, with mrt) into 8-bit targets, and no other part
     * of the ray state can be read (renderer_run refuses what needs it) */
    int image_only;
    /* 1: no float format renders and the GPU runs no long loops (GLES 2: VC4), but its fragment
     * shaders pack floats into RGBA8 texels exactly (gl/packing.h): the ray state's float textures
     * hold each texel as a 2x2 block of RGBA8 texels, one float each, and the multipass scheme runs
     * on them one target a pass (raystate.h) */
    int packed;
    const struct float_format *table_format;  /* the 32-bit float format the orbit table is sampled
                                                 from: the ray state's where it is 32-bit, else
                                                 RGBA32F on GLES 3 and desktop GL (the single pass
                                                 only, renderer.c), NULL on GLES 2's fp16 paths */
    const char *name;         /* "fp32+mrt", "fp32", "fp16+mrt", "fp16", "image only", "packed 8-bit" */
    char description[256];
};

/* The fused segment pass writes position, velocity, hit and image at once: whether this GPU can,
 * given MRT (the path's, or the probe's for `bentray info`) and its draw buffers. */
#define SEGMENT_FUSED_TARGETS 4
int render_path_can_fuse(const struct gl_caps *caps, int mrt);

/* Pick the best path the context supports, or the one forced; -1 with e naming what is missing
 * (ERROR_INPUT where the path was forced, ERROR_RUNTIME where none works). Where no float format
 * renders, the image-only path, on a GPU that runs long loops and computes in 32 bits, with the
 * precision not forced. Where only 16-bit floats render, the GPU runs no long loops (the ray state
 * is stored between passes) and packs floats exactly, the packed path: a 16-bit ray state stored
 * pass after pass changes rays' outcomes (bent ones and straight ones alike), the packed one is the
 * 32-bit scheme's.
 * The chosen path's ray-state framebuffer (its colour targets and the depth buffer, as
 * raystate_init makes them) is built once: where it is incomplete, the next path the scene allows
 * is taken (precision auto: fp32 -> fp16; mrt auto: MRT -> separate passes) and the description
 * says why. Where no allowed path's framebuffer is complete, the preferred path is returned and
 * raystate_init reports the failure. Needs the probed context current. */
int render_path_choose(const struct gl_caps *caps, enum precision_choice precision, enum mrt_choice mrt,
                       struct render_path *path, struct error *e);

/* Completeness of the bound framebuffer whose `targets` colour targets (1, or 2 with MRT) have
 * format f (NULL: not a float format): glCheckFramebufferStatus, or GL_FRAMEBUFFER_UNSUPPORTED
 * where the test hook says so (gl/caps.h): BT_FAULT=fbo_incomplete (half_fbo_incomplete for 16-bit
 * formats), mrt_fbo_incomplete for two targets of any format. */
GLenum render_path_framebuffer_status(const struct float_format *f, int targets);
/* The ray state's framebuffer in small (4x4): one colour target of format f, two with mrt, and a
 * 16-bit depth renderbuffer, as raystate_fbo makes them; its status as above. Leaves no GL error
 * and no binding behind. */
GLenum render_path_state_status(const struct float_format *f, int mrt);

#endif
