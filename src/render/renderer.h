/* The GPU pipeline of the paper's Figure 1, as named stages:
 *   setup -> [ integrate (n_integration / K passes) -> intersect (one pass per batch of objects)
 *              -> terminate -> retire (every termination_interval segments) ] x n_segs
 *   -> retire all -> sky
 * Retired rays are skipped by the early-z test in every later heavy pass (paper section 4.1).
 * No read-back until the final image, except where a caller asks for one per segment (trace). */
#ifndef BT_RENDERER_H
#define BT_RENDERER_H
#include "gl/caps.h"
#include "io/error.h"
#include "gl/context.h"
#include "gl/gl_api.h"
#include "render/path.h"
#include "scene/scene.h"

struct renderer;

/* Called after each segment (for bentray trace); NULL for none. */
typedef int (*segment_hook)(struct renderer *r, int segment, void *arg);

struct render_result {
    int width, height;
    unsigned char *rgba;                    /* final image, RGBA8, top row first */
    float *color;                           /* the same unclamped, RGBA floats (renderer_set_hdr); else NULL */
    float *position, *velocity, *hit, *image; /* ray state, RGBA floats, top row first; NULL if not read */
    signed char *outcome;                   /* read with RENDER_READ_OUTCOMES from a frame that drew its
                                               colour itself: each ray's outcome code (the image
                                               texture's alpha: dump.h's outcomes), top row first, in
                                               place of image (then NULL); NULL otherwise */
    long outcome_nonfinite;                 /* with outcome: the values of the image texture that were
                                               not finite (or beyond the path's float) */
    double seconds;                         /* wall time of the GPU passes (glFinish included) */
    double sky_seconds;                     /* wall time of the stars of the sky, drawn on the CPU
                                               (render/frame.h); 0 without them */
    double bloom_seconds;                   /* wall time of the bloom, on the CPU (render/frame.h);
                                               0 without it */
    long passes;                            /* quads drawn */
    double compile_seconds;                 /* of seconds: compiling the shaders of programs built or
                                               drawn for the first time (renderer_run) */
};

/* Probes the context, picks the render path the scene asks for, loads textures and sky.
 * NULL with e: ERROR_INPUT when the failure is the user's request (a forced path this GPU lacks,
 * a size beyond its limits, a texture that cannot be decoded), ERROR_RUNTIME otherwise. */
struct renderer *renderer_create(const struct gl_context *ctx, const struct scene *scene, struct error *e);
const struct render_path *renderer_path(const struct renderer *r);
/* Whether the ray state can be read back here (renderer_read with more than the outcomes, the
 * stars of the sky, a float image): not on the image-only path (render/path.h), whose runs refuse
 * to be asked for it. */
int renderer_state_readable(const struct renderer *r);
/* Whether the ray state's textures hold floats a shader can sample (the kiosk's pipeline view):
 * not on the image-only path, nor on the packed path, whose textures hold bytes. */
int renderer_state_sampled(const struct renderer *r);
/* Whether the frame's own pass draws the stars of [sky] (render.star_pass = gpu, or auto on a path
 * whose rays' state cannot be read back); else the CPU's pass adds them after the frame. */
int renderer_gpu_stars(const struct renderer *r);
const struct gl_caps *renderer_caps(const struct renderer *r);

/* Trace the rays of scene through a width x height block of image pixels whose lower-left pixel
 * (GL order, rows bottom-up) is (origin_x, origin_y); a full frame is (0, 0, scene width, scene
 * height). scene is the one the renderer was made with, or one that differs from it in values
 * only (the kiosk's knobs, a preview's size, steps and chords, the camera, the observer): the
 * same objects, textures and sky, which renderer_create loaded (else -1 with e; a new scene
 * takes a new renderer). It must stay valid until the next run; reads of this run follow it.
 * A hook that fails stops the run, and e says at which segment. 0, or -1 with e. */
int renderer_run(struct renderer *r, const struct scene *scene, int origin_x, int origin_y, int width, int height,
                 segment_hook hook, void *hook_arg, struct error *e);
/* Where in its pixel every ray of the following runs starts: (dx, dy) pixels from the centre, GL
 * order (dy up), each in [-0.5, 0.5) (scene/pixel_samples.h); (0, 0) until set. */
void renderer_set_subpixel(struct renderer *r, double dx, double dy);
/* What renderer_read reads besides the image: nothing, the whole ray state, or only the image
 * texture with each ray's outcome code (what a summary needs; a single-pass frame then skips the
 * pass that writes hit and position), or the outcome codes and exit directions (what the stars of the
 * sky are drawn from, results/star_light.h). */
enum render_read { RENDER_READ_IMAGE = 0, RENDER_READ_STATE = 1, RENDER_READ_OUTCOMES = 2, RENDER_READ_SKY = 3 };
/* What the caller reads after each following run (enum render_read; RENDER_READ_OUTCOMES until
 * set). It changes no result, only the passes: with RENDER_READ_IMAGE a single-pass frame draws
 * its final image in its own pass (the sky stage's colour in it, one full-screen pass and two float
 * targets less), and a later read of more traces the frame again for its outcomes. */
void renderer_set_reads(struct renderer *r, enum render_read reads);
/* Whether a read of kind reads brings back part k of the ray state: 0 position, 1 velocity,
 * 2 hit, 3 image (render_result's order). */
int render_read_includes(enum render_read reads, int k);
/* The read that brings back what both reads and RENDER_READ_SKY ask for. */
enum render_read render_read_with_sky(enum render_read reads);
/* With why (what needs it: "writing a float image (a 16-bit PNG or PFM)", "render.bloom", ...), each
 * run also keeps the final colour unclamped, as floats, and renderer_read returns it in
 * render_result.color; on a GPU whose path is image only, the run is refused naming why. NULL: off,
 * until set. */
void renderer_set_hdr(struct renderer *r, const char *why);
/* With on, the first draw of each program in this renderer waits for the GPU's work before it and
 * is timed, its time added to render_result.compile_seconds beside the programs' links (what
 * `bentray render`'s time line says); off until set, as the kiosk keeps it, whose frames should not
 * wait for the GPU at a scene's first draws. */
void renderer_time_first_draws(struct renderer *r, int on);
int renderer_hdr(const struct renderer *r);
const char *renderer_hdr_why(const struct renderer *r);   /* as renderer_set_hdr was given it */
/* Read the final image, and what `reads` (enum render_read) asks for. 0, or -1 with e. */
int renderer_read(struct renderer *r, struct render_result *out, enum render_read reads, struct error *e);
/* Position of the ray of texel (x, y) (GL order) right now: for per-segment hooks. 0, or -1 with e. */
int renderer_read_position(struct renderer *r, int x, int y, float xyzw[4], struct error *e);
void render_result_free(struct render_result *res);
/* The outcome code of pixel i (top row first) of a result read with the outcomes (or more): an
 * object's id, or dump.h's DUMP_SKY, DUMP_CAPTURED, DUMP_UNFINISHED, DUMP_FAILED; from image or
 * outcome, whichever the read brought back. */
int render_result_outcome(const struct render_result *res, size_t i);
/* The textures of the last run, on the GPU, for a display to draw from (the kiosk's compositor and
 * pipeline view): the final image (RGBA8) and each ray's final state (layout: common.glsl).
 * Valid until the next run or renderer_destroy; all 0 before the first run, and each 0 that no
 * run has written yet (a texture takes memory only once written, render/raystate.h). A
 * single-pass frame writes the hit and position textures only when renderer_complete_state (or
 * renderer_read with the state) asks for them. */
struct renderer_textures {
    int width, height;
    GLuint image, position, velocity, hit, outcome;
    /* render.method = orbit_table: the orbit table the last run followed (physics/orbit_table.h:
     * texel (j, row).x is u = 1/r at fraction j / (columns - 1) of the row's orbit; escaping rows
     * first, each side from the critical launch angle outwards); 0 for integrated rays */
    GLuint orbit_table;
    int orbit_width, orbit_height, orbit_columns, orbit_rows_per_side;
    double orbit_u_capture;         /* u where captured orbits end, just inside the horizon */
};
void renderer_textures(const struct renderer *r, struct renderer_textures *out);
/* Bytes of GPU memory the ray state holds now: only the textures its passes have used
 * (render/raystate.h), so a single-pass frame holds a fraction of the multipass scheme's. */
size_t renderer_state_bytes(const struct renderer *r);
/* The single-pass frame's deferred hit and position, and its outcome textures where it drew its
 * image itself (a no-op after a multipass frame). */
int renderer_complete_state(struct renderer *r, struct error *e);
/* "multipass", "fused segment" or "single pass": how the last run was scheduled. */
const char *renderer_pipeline(const struct renderer *r);
/* Why the last run took that pipeline, in words ("render.pipeline = multipass", "OpenGL ES 3.2
 * runs long fragment-shader loops", ...). */
const char *renderer_pipeline_why(const struct renderer *r);
void renderer_destroy(struct renderer *r);
/* From now on every fragment shader this renderer compiles from shader file `file` ("stage_frame.glsl")
 * goes to sink whole, as the GL compiles it (bentray info --shader). Programs already built are not
 * compiled again: call it before the first run. */
void renderer_capture_shaders(struct renderer *r, const char *file, void (*sink)(const char *source, void *arg),
                              void *arg);
/* The programs this renderer compiles into and takes from: its own, or those it shares. */
const struct program_cache *renderer_programs(const struct renderer *r);
/* From now on r takes its programs from pc and adds those it builds there, where pc compiles for the
 * same shader target and MRT choice (program_cache_fits): 1, else 0 and r keeps its own. pc must
 * outlive r; call it before the first run. The kiosk shares one cache among all its scenes. */
int renderer_share_programs(struct renderer *r, struct program_cache *pc);
/* Whether the rays of s follow exact orbits from an orbit table: render.method = orbit_table around
 * a mass that bends them (on a GPU with 32-bit float textures; without, the renderer integrates). */
int scene_on_exact_orbits(const struct scene *s);
/* render.method = orbit_table: the orbit table this scene needs now (its mass, the camera's radius,
 * the bounding sphere, the chord tolerance and the objects' distances from the mass). */
struct orbit_table_params;
void orbit_table_params_for(const struct scene *s, struct orbit_table_params *p);
/* Orbit tables the next runs are expected to ask for, most wanted first (the kiosk: the tables of
 * the knobs' next detents), built by a worker thread while the GPU draws; what was still waiting
 * from an earlier call is dropped. 0, or -1 with e (no memory). */
int renderer_orbit_prefetch(struct renderer *r, const struct orbit_table_params *p, int n, struct error *e);
/* For a renderer not made yet: a store (orbit_store.h) whose worker has begun the orbit table that s
 * needs now, where s is on exact orbits; NULL where it is not, or without memory. Give it to the
 * renderer made for s (renderer_orbit_store_give), or orbit_store_destroy it. */
struct orbit_store;
struct orbit_store *renderer_orbit_ahead(const struct scene *s);
/* From now on r's runs take their tables from store (kept, waited for, or built then), and r
 * destroys it. Where r has a store already, store is destroyed; NULL changes nothing. */
void renderer_orbit_store_give(struct renderer *r, struct orbit_store *store);
/* Tables still waiting for the worker or being built. */
int renderer_orbit_pending(const struct renderer *r);
/* Tables this renderer's runs built themselves (none kept, none being built ahead). */
int renderer_orbit_tables_built(const struct renderer *r);
/* Seconds this renderer's runs have spent building orbit tables or waiting for the worker's. */
double renderer_orbit_build_seconds(const struct renderer *r);

#endif
