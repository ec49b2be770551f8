/* The ray state on the GPU (paper sections 3.1-3.3): float RGBA textures, one texel per pixel.
 * Layout of each texture: shaders_es/common.glsl. Positions are triple-buffered so that the
 * start of a segment survives the integration passes that build it; the rest ping-pong.
 *
 * Early ray termination (paper section 4.1) skips finished rays through the early-z test, so
 * their texels in the ping-pong copies stop being written and go stale. The termination test
 * therefore copies a ray's final state, once, into the result textures (never read while they
 * are written), and marks the ray in the depth buffer that every ray-state framebuffer shares.
 *
 * A texture takes memory only once a pass writes or reads it (raystate_storage): the single pass
 * writes two of the seventeen float textures (the results it ends in), or none where it draws the
 * final colour itself (the kiosk, a render's summary: the RGBA8 image and outcome codes), and on
 * exact orbits with its walk in a pass of its own the two RGBA8 walk textures, so its frames
 * neither clear nor hold the others, on a board whose GPU shares 1 GB with everything else. */
#ifndef BT_RAYSTATE_H
#define BT_RAYSTATE_H
#include "gl/gl_api.h"
#include "render/path.h"

#define DEPTH_NO_HIT 60000.0f      /* depth key of a ray still travelling (fits fp16) */

#define RAYSTATE_MAX_FBOS 32
#define RAYSTATE_MAX_TARGETS 4     /* colour targets of one pass: the fused segment pass writes four */
#define RAYSTATE_TEXTURES 21       /* the float textures below, final_color, outcome_codes, orbit_walk */

struct raystate {
    int width, height;
    GLuint position[3], velocity[2], hit[2], image[2];
    GLuint result_position, result_velocity, result_hit, result_image; /* final state of each ray */
    GLuint depth;                  /* renderbuffer: 0 where a ray has been terminated, 1 elsewhere */
    GLuint final_color;            /* RGBA8 image for presentation and PNG */
    GLuint outcome_codes;          /* RGBA8: each ray's outcome code (image texture's alpha) + 4 in
                                      r, how many of its image values are not finite in g, for a
                                      summary of a frame that drew its colour itself (sky_colour.glsl) */
    GLuint orbit_walk[2];          /* RGBA8: where each ray's walk along its exact orbit stopped
                                      (shaders_es/stage_orbit_walk.glsl), ping-pong */
    GLuint hit_found[2];           /* a batch's hit found, before the pass that shades it
                                      (render.hit_shading = separate, stage_intersect.c): depth key,
                                      fraction, object, halves (shaders_es/stage_intersect.glsl) */
    GLuint hit_chord[2];           /* ... on exact orbits the short chord that carries it: start, end */
    GLuint hdr_color;              /* the colour unclamped (raystate_hdr_color); 0 until asked for */
    int cur_position, cur_velocity, cur_hit;  /* indices of the current copies */
    struct { GLuint target[RAYSTATE_MAX_TARGETS], fbo; } fbos[RAYSTATE_MAX_FBOS];
    int n_fbos;
    const struct float_format *format;  /* of every texture but the RGBA8 ones; for messages */
    /* the packed path (render/path.h): every float texture, and the depth buffer, twice as wide and
     * high, each texel a 2x2 block of RGBA8 texels, one float each (shaders_es/common.glsl) */
    int packed;
    const char *path_name;         /* the render path these textures serve */
    int mrt;
    GLuint stored[RAYSTATE_TEXTURES];  /* the textures given memory so far (raystate_storage) */
    int n_stored;
};

/* Names every texture and checks the path's framebuffer of result targets (with the depth buffer)
 * in small (render_path_state_status), so that a format this GPU cannot render into fails here,
 * named with the path and the size; no texture takes memory yet. On failure nothing stays
 * allocated. */
int raystate_init(struct raystate *rs, const struct render_path *path, int width, int height, struct error *e);
void raystate_release(struct raystate *rs);
/* Gives TEXTURE, one of the ray state's, its memory if it has none yet (its texels then read as
 * zero on llvmpipe, undefined elsewhere, as the texture's first contents always were); the active
 * unit's binding is left as it was. Every pass's targets (raystate_fbo) and inputs pass through
 * it. 0, or -1 with e where the GPU has no memory for it. */
int raystate_storage(struct raystate *rs, GLuint texture, struct error *e);
/* Whether TEXTURE has its memory (a pass wrote or read it). */
int raystate_stored(const struct raystate *rs, GLuint texture);
/* Bytes of GPU memory the ray state's textures hold now (the depth buffer included). */
size_t raystate_bytes(const struct raystate *rs);
/* The size of TEXTURE, one of the ray state's, in texels: the image's, twice it for a float texture
 * on the packed path. */
void raystate_texture_size(const struct raystate *rs, GLuint texture, int *width, int *height);
/* Framebuffer with target0 (and target1 when nonzero) and the shared depth buffer attached;
 * made once and cached. */
GLuint raystate_fbo(struct raystate *rs, GLuint target0, GLuint target1, struct error *e);
/* The same for up to RAYSTATE_MAX_TARGETS colour targets (the first n nonzero). */
GLuint raystate_fbo_targets(struct raystate *rs, const GLuint target[RAYSTATE_MAX_TARGETS], struct error *e);
/* Read one texture back as floats, top row first (image order): w*h*4 floats. */
int raystate_read(struct raystate *rs, GLuint texture, float *rgba_top_down, struct error *e);
/* Read one of the RGBA8 textures back (final_color, outcome_codes): w*h*4 bytes, GL order (bottom
 * row first); `what` names it in a GL error. 0, or -1 with e. */
int raystate_read_bytes(struct raystate *rs, GLuint texture, unsigned char *rgba_bottom_up, const char *what,
                        struct error *e);
/* The float texture (the path's format) the sky stage writes the unclamped colour into
 * (renderer_set_hdr), made on first use. */
GLuint raystate_hdr_color(struct raystate *rs);

#endif
