/* Internals shared by the stage files of the pipeline. */
#ifndef BT_STAGES_H
#define BT_STAGES_H
#include <stdint.h>
#include "render/programs.h"
#include "render/raystate.h"
#include "render/renderer.h"
#include "physics/orbit_table.h"
#include "render/orbit_store.h"
#include "render/far_reach.h"
#include "results/star_map.h"

/* The programs a renderer times the first draw of (pass_draw_begin): more than any frame uses. */
#define RENDERER_DRAWN_MAX 64

/* Texture units: ray-state inputs first, then scene textures. */
#define UNIT_SKY 6
/* the sky in a single-pass frame that draws its colour (FRAME_WRITES_COLOUR): that pass reads no ray
 * state, so a unit of the inputs is free, while UNIT_SKY may hold an object's texture there */
#define UNIT_FRAME_SKY 3
/* the star map of the GPU's star pass (sky_colour.glsl, GPU_STARS): free in both passes that draw
 * the final colour, the sky stage (two inputs, units 0 and 1) and a single-pass frame's colour (at
 * most one, unit 0) */
#define UNIT_STARS 2
/* the black-body table: above the ray-state inputs of every pass (four; five where the intersection
 * stage shades its hits in a pass of its own, hit_shading_separate), below the object textures,
 * which start at the next unit (intersect_first_object_unit) */
#define UNIT_BLACKBODY(r) (hit_shading_separate(r) ? 5 : 4)
/* the orbit table: the GPU's last texture unit (object textures stay below it) */
#define UNIT_ORBIT(r) ((r)->caps.max_texture_units - 1)

struct renderer {
    const struct scene *scene;    /* of the last run (renderer_run), first the one it was made for */
    uint64_t assets_key;          /* what renderer_create loaded of it: objects, textures, sky */
    struct gl_caps caps;
    struct render_path path;
    struct program_cache own_programs;
    struct program_cache *programs;    /* own_programs, or a cache lent by renderer_share_programs */
    int programs_ready;           /* program_cache_init ran: renderer_destroy tears the renderer down */
    struct raystate rs;
    int have_state;
    GLuint textures[SCENE_MAX_TEXTURES];
    int texture_size[SCENE_MAX_TEXTURES][2];   /* as uploaded (image_read may scale one down) */
    GLuint sky_cubemap;
    GLuint star_map;              /* the GPU's star pass (render.star_pass = gpu): results/star_map.h */
    struct star_map star_layout;  /* its layout and ranges (texels freed once uploaded) */
    vec3d galactic_pole, galactic_x, galactic_y;
    GLuint blackbody_lut;         /* Doppler colour effects only */
    int blackbody_tone;           /* the table's enum blackbody_tone */
    double blackbody_reference;   /* and its reference temperature (TONE_SCENE) */
    char observer_defines[128];   /* OBSERVER_MOVING, DOPPLER_COLOUR, SEARCHLIGHT */
    GLuint mesh_buffers[SCENE_MAX_OBJECTS][2];   /* render.moving_objects = polygons: vertices, indices */
    int mesh_indices[SCENE_MAX_OBJECTS];
    int origin_x, origin_y;       /* image pixel of ray-state texel (0, 0) */
    double subpixel_x, subpixel_y;   /* where in its pixel each ray starts, from the centre (pixels) */
    /* what needs the unclamped colour, which the sky stage then also writes (renderer_set_hdr);
     * NULL: nothing. Named for the image-only path's refusal. */
    const char *hdr_why;
    char model_defines[320];      /* model, method, step control, steps per pass */
    char model_file[64];          /* model_NAME.glsl; model_flat.glsl for straight rays */
    int straight;                 /* rays are straight: one segment, not integrated */
    enum integration_method method;  /* the scene's, or rk4 where orbit_table lacks fp32 textures */
    int exact_orbits;             /* rays follow tabulated exact orbits (not straight, orbit_table) */
    int sky_at_infinity;          /* integrated rays around a mass: the sky along the direction at infinity */
    /* steps that grow away from the objects (render.far_step; STEP_FAR) in the scene as it is now,
     * and the objects' bounds they grow from (render/far_reach.h), far_reach_count of them, packed
     * once: the objects are the renderer's assets */
    int far_steps;
    int far_reach_count;
    float far_ball[FAR_REACH_MAX][4], far_normal[FAR_REACH_MAX][4];
    const char *pipeline_name;    /* of the last run: "multipass", "fused segment", "single pass" */
    char pipeline_why[400];       /* why the last run took it */
    int state_pending;            /* single pass: hit and position not yet written */
    int outcomes_pending;         /* single pass drawn as FRAME_COLOUR: image and velocity neither */
    int codes_written;            /* ... with the outcome codes beside it (FRAME_WRITES_COLOUR_CODES) */
    int run_hooked;               /* the run going on is read segment by segment (renderer_run's hook) */
    enum render_read reads;       /* what the caller reads after a run (renderer_set_reads) */
    long passes;
    double seconds;
    double compile_seconds;       /* of seconds: compiling shaders (pass_draw) */
    int time_first_draws;         /* renderer_time_first_draws: pass_draw_begin waits and times */
    GLuint drawn[RENDERER_DRAWN_MAX];  /* the programs drawn so far; the first RENDERER_DRAWN_MAX */
    int n_drawn;
    struct orbit_store *orbit_store;  /* the tables built, and those built ahead (NULL before the first) */
    struct orbit_table orbit;     /* render.method = orbit_table: the table of the last run (its scalars;
                                     the texels are the store's) */
    GLuint orbit_texture;         /* the same as a float texture; 0 before the first */
    struct orbit_table orbit_spare;  /* the one before it (stage_orbit.c) */
    GLuint orbit_spare_texture;
    GLuint queries[2];            /* occlusion queries of the multipass scheme's early stop; 0: none yet */
    float quad_z;                 /* NDC depth of the pass quads: 0 (heavy passes), -1 (retire) */
    int depth_write_last;         /* pass_run writes depth in the last draw of a stage only */
};

struct pass_input {
    const char *sampler;
    GLuint texture;
};

typedef void (*set_uniforms_fn)(const struct program_uniforms *program, const void *arg);

/* Every ray travelling: the depth buffer that every ray-state framebuffer shares cleared to 1 (through
 * TARGET's framebuffer), and the early-z test on, GL_LESS, without depth writes until a stage that
 * ends rays asks for them (depth_write_last). */
int pass_early_z_begin(struct renderer *r, GLuint target, struct error *e);
/* Draw the quad with each program of the stage into out0 (and out1), inputs bound as samplers. */
int pass_run(struct renderer *r, const struct stage_program *sp, GLuint out0, GLuint out1,
             const struct pass_input *inputs, int n_inputs, set_uniforms_fn set_uniforms, const void *arg,
             struct error *e);

/* Around a draw with `program`: where the renderer times first draws (renderer_time_first_draws),
 * its first draw in this renderer begins once the GPU's work so far is done, so that the draw call's
 * own time is what the driver spends compiling the program for the draw (llvmpipe and the Mesa
 * drivers of the exhibit's GPUs compile much of a program at its first draw, not at its link),
 * added to r->compile_seconds. A later draw is timed not at all, nor any draw of a renderer that
 * does not time them (the kiosk's: no wait for the GPU in the middle of its frames). */
double pass_draw_begin(struct renderer *r, GLuint program);
void pass_draw_end(struct renderer *r, double began);
/* The same as pass_run for up to RAYSTATE_MAX_TARGETS targets (the fused segment pass: four, with MRT). */
int pass_run_targets(struct renderer *r, const struct stage_program *sp, const GLuint out[RAYSTATE_MAX_TARGETS],
                     const struct pass_input *inputs, int n_inputs, set_uniforms_fn set_uniforms, const void *arg,
                     struct error *e);

/* One pass that moves the rays (integrate, orbit): reads the current position, velocity and hit,
 * writes the next position (keeping the segment's start) and velocity. */
int pass_move_rays(struct renderer *r, const struct stage_program *sp, int segment_start, set_uniforms_fn set_uniforms,
                   const void *arg, struct error *e);

void model_set_uniforms(const struct program_uniforms *program, const struct model *m);
void bounds_set_uniforms(const struct program_uniforms *program, const struct scene *s);
void uniform_vec3(const struct program_uniforms *program, const char *name, vec3d v);
void uniform_float(const struct program_uniforms *program, const char *name, double v);

/* The scene's textures and sky; a file that cannot be decoded is ERROR_INPUT (exit 2). */
int textures_load(struct renderer *r, struct error *e);
/* shaders_es/observer.glsl: camera, observer velocity, black-body table (observer.c) */
int observer_defines(const struct scene *s, char *out, size_t len);
void observer_set_uniforms(const struct program_uniforms *program, const struct renderer *r);
int observer_lut_load(struct renderer *r, struct error *e);
void observer_lut_release(struct renderer *r);
void textures_release(struct renderer *r);

int stage_setup(struct renderer *r, struct error *e);
int stage_integrate(struct renderer *r, int segment_start, struct error *e);
/* The integration stage's uniforms (model, bounds, step control): a set_uniforms_fn of a scene. */
/* The integration's uniforms (model, bounds, step control) of renderer r's scene. */
void integrate_set_uniforms(const struct program_uniforms *p, const void *renderer);
/* Uniform vectors the integration's far steps take (2 a bound and the step): 0 without them. */
int far_step_uniform_vecs(const struct renderer *r);
/* render.method = orbit_table (stage_orbit.c): the table for the scene as it is now, built and
 * uploaded when its parameters changed; one pass per segment along the exact orbits. */
int orbit_prepare(struct renderer *r, struct error *e);
void orbit_release(struct renderer *r);
int stage_orbit(struct renderer *r, int segment, int segment_start, struct error *e);
/* The orbit stage's uniforms (table, camera, bounds, the pixel's axis; segment for the orbit stage). */
void orbit_set_uniforms(const struct program_uniforms *p, const struct renderer *r, int segment);
/* Every object against the current segment, render.batch objects per pass. */
int stage_intersect_all(struct renderer *r, int segment, int segment_start, struct error *e);
/* Objects per intersection pass on this GPU: render.batch, bounded by its uniform vectors. */
int intersect_batch_limit(const struct renderer *r);
/* Objects the single pass can test on this GPU (its uniform vectors; render.batch does not apply). */
int frame_object_limit(const struct renderer *r);
/* The objects one intersection pass tests (stage_intersect.c), for every stage that tests objects:
 * its variant defines, its primitives' shader files (appended to files from index n; returns the
 * new count), its uniforms (a set_uniforms_fn), and a batch of every object of the scene for the
 * single pass (-1 where they do not fit one pass on this GPU, frame_object_limit, or the polygon
 * method draws one). */
/* objects one batch may hold: render.batch (at most SCENE_MAX_BATCH) for an intersection pass,
 * every object of the scene for the single pass; either within the GPU's uniform vectors */
#define OBJECT_BATCH_MAX SCENE_MAX_OBJECTS
struct object_batch {
    const struct renderer *r;
    int object[OBJECT_BATCH_MAX];  /* scene indices, in scene order */
    int count;
    int segment;
};
/* Room for a batch's defines: every object's test, its kind's slot list and its motion's, 64
 * moving, textured objects included (test_single_pass_most_objects). */
#define BATCH_DEFINES_LEN 8192
int object_batch_defines(const struct object_batch *b, char *out, size_t len);
int object_batch_files(const struct object_batch *b, const char **files, int n);
void object_batch_set_uniforms(const struct program_uniforms *p, const void *batch);
int object_batch_all(const struct renderer *r, struct object_batch *b);
/* render.pipeline (pipeline.c): the schedule of this frame, chosen once, with why in words (the
 * choice forced, or auto: the single pass where this GPU runs long fragment loops, every object fits
 * one intersection batch and no hook reads the rays back after every segment; else the fused segment
 * pass where four draw buffers work; else the paper's multipass scheme). -1 with e (ERROR_INPUT) where
 * render.pipeline forces a schedule this GPU or scene cannot run. */
enum pipeline_kind { PIPELINE_RUN_SINGLE, PIPELINE_RUN_FUSED, PIPELINE_RUN_MULTIPASS };
struct pipeline_choice_made {
    enum pipeline_kind kind;
    char why[400];
};
int pipeline_choose(const struct renderer *r, int per_segment_hook, struct pipeline_choice_made *out,
                    struct error *e);
const char *pipeline_name(enum pipeline_kind kind);   /* "single pass", "fused segment", "multipass" */
/* The defines of a pass that tests every object (b from frame_batch; none: an empty slot). */
int frame_batch_defines(const struct renderer *r, const struct object_batch *b, char *out, size_t len,
                        struct error *e);
/* The fused pass of segment k. */
int stage_segment(struct renderer *r, int segment, struct error *e);
/* What a single-pass frame writes: the outcome textures (image and velocity, what the sky stage
 * reads), the state (hit and position, for a read-back of the ray state), or the final colour itself
 * (the sky stage's sky_colour.glsl in the same pass, when only the image is read: FRAME_COLOUR
 * in the shaders), or that and each ray's outcome code in a second RGBA8 target (when the image
 * and the outcomes are read, as for a render's summary, on a path with MRT: FRAME_CODES). */
enum frame_output { FRAME_WRITES_OUTCOMES, FRAME_WRITES_STATE, FRAME_WRITES_COLOUR, FRAME_WRITES_COLOUR_CODES };
int stage_frame(struct renderer *r, enum frame_output output, struct error *e);
/* Whether the multipass scheme shades a batch's hit in a pass of its own (render.hit_shading): auto
 * takes it on a GPU where each pass writes one target (no MRT: the packed path, a GPU with one draw
 * buffer) on a 32-bit ray state. There the stage in one pass is one program a target, each finding
 * the hit, and on exact orbits too large for VC4's register allocator (`make shader-stats`); in
 * passes of their own each program is smaller, and only the shading runs once a target. Not on a
 * CPU rasteriser, which has no register file to overflow: there the extra passes and fetches cost
 * more than the finding they save (schwarzschild on the packed path, 320x240: 10.0 s in one pass,
 * 11.8 s separate). With MRT the stage stays one pass: fewer passes over the ray state. */
int hit_shading_separate(const struct renderer *r);
/* Whether a single pass on exact orbits walks in a pass of its own (render.orbit_walk; the frame's
 * pass finishes each ray in a second), where it walks at all. */
int orbit_walk_separate(const struct renderer *r);
/* Every object of the scene as the single pass's batch; -1 with e saying why they do not fit
 * (ERROR_INPUT: only render.pipeline = single asks for it where they do not). */
int frame_batch(const struct renderer *r, struct object_batch *b, struct error *e);
/* Exact orbits in one pass where every object is flat, static and lies in a plane through the mass,
 * inside a bounding sphere about the mass that holds the camera (orbit_crossings.c): each object is
 * met where the orbit crosses its plane (stage_orbit_crossings.glsl), not chord by chord. */
int orbit_crossings_apply(const struct renderer *r);
/* Its uniforms: each object's unit normal. */
void orbit_crossings_set_uniforms(const struct program_uniforms *p, const struct renderer *r);
int stage_terminate(struct renderer *r, int segment, struct error *e);
/* Retire finished rays (all: every ray) into the result textures; mark them for early-z. */
int stage_retire(struct renderer *r, int all, struct error *e);
int stage_sky(struct renderer *r, struct error *e);
/* Whether the GPU's stars take their footprints from the neighbouring rays (a GPU without
 * derivatives): then only the sky stage, which reads the rays' state, draws the final colour
 * (stage_sky.glsl), never a single-pass frame's own pass. */
int stars_from_neighbours(const struct renderer *r);
/* The final colour's uniforms and defines (sky_colour.glsl), for the sky stage and FRAME_WRITES_COLOUR. */
void sky_colour_set_uniforms(const struct program_uniforms *p, const struct renderer *r, int sky_unit);
#define SKY_COLOUR_DEFINES_LEN 160
void sky_colour_defines(const struct renderer *r, char *out, size_t len);
/* The polygon method for moving objects (stage_polygons.c): which objects it draws, their meshes,
 * and the stage that rasterises them into the results. */
int polygons_draw_object(const struct renderer *r, int k);
int polygons_load(struct renderer *r, struct error *e);
void polygons_release(struct renderer *r);
int stage_polygons(struct renderer *r, struct error *e);
/* One object's material vectors as the intersection and polygon shaders read them. */
void intersect_pack_material(const struct renderer *r, const struct object *o, int object_id, float out[5][4]);

#endif
