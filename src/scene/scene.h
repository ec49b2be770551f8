/* The scene: camera, model of light propagation, objects, lights, sky and render settings.
 * Filled by scene_load() from a scene file (assets/scenes/NAME.scene) and --set overrides. */
#ifndef BT_SCENE_H
#define BT_SCENE_H
#include <stddef.h>
#include "physics/vec3.h"
#include "physics/model.h"
#include "conf/conf_reader.h"

/* Fixed arrays of struct scene: refused at the section or key that would overflow them. */
#define SCENE_MAX_OBJECTS 64        /* [object] sections */
#define SCENE_MAX_LIGHTS 4          /* [light] sections */
#define SCENE_MAX_TEXTURES 8        /* different texture files */
#define SCENE_NAME_LEN 64           /* bytes of a name, with its terminator */
#define SCENE_PATH_LEN 512          /* bytes of a path, with its terminator */
/* Upper limits that keep a typo from asking for hours of work or gigabytes (docs/LIMITS.md). */
#define SCENE_MAX_SIZE 8192         /* pixels along either side of the image */
/* Pixels of the image, width x height (3840 x 2160 fits). Each costs 214 bytes of GPU memory at fp32
 * (13 RGBA32F ray-state textures, the RGBA8 image, 16-bit depth) and 120 bytes of host memory while
 * its ray state is read back and turned into a dump record: 1.8 GB and 1.0 GB at the limit. */
#define SCENE_MAX_PIXELS (1L << 23)
#define SCENE_MAX_SEGMENTS 100000   /* segments of a ray (passes of integrate, intersect, terminate) */
#define SCENE_MAX_STEPS_PER_SEGMENT 10000 /* integration steps */
#define SCENE_MAX_STEPS_PER_PASS 64 /* integration steps unrolled in one shader */
#define SCENE_MAX_BATCH 16          /* objects intersected in one pass */
#define SCENE_MAX_SUBDIVISION 128
#define SCENE_MAX_SAMPLES 256       /* render.samples: rays per pixel, each a whole frame on the GPU */
#define SCENE_MAX_CHORDS 10000     /* render.max_chords: loop iterations of the single pass */
#define SCENE_MAX_ORBIT_ROWS 4096   /* orbit table rows per side: 2 x 4096 rows of a float texture */
#define SCENE_MAX_ORBIT_COLUMNS 4095 /* samples along each tabulated orbit (one more texel: its end) */   /* a sphere's mesh then has 129 x 257 vertices: 16-bit indices */
/* Pixels along either side of a texture or a sky cube face, as its PNG header declares it: one
 * decoded image of 8192 x 8192 is 256 MiB of RGBA8. */
#define SCENE_MAX_TEXTURE_SIZE 8192
/* Largest magnitude of any number in a scene, scene units: the GPU holds them in 32-bit floats
 * (largest 3.4e38) and squares lengths, and 1e18 squared still fits. */
#define SCENE_MAX_ABS_VALUE 1e18
/* Longest edge of a flat primitive (a rect's axis, a triangle's edge), scene units: the GPU's
 * intersection of one takes the normal as the cross product of two edges and squares it, a fourth
 * power of their length, which 32-bit floats hold up to about 1.36e9; a rect of axes 1e10 was
 * missed on the GPU and hit on the CPU. */
#define SCENE_MAX_FLAT_EDGE 1e9

enum primitive_type { PRIM_SPHERE, PRIM_TRIANGLE, PRIM_DISK, PRIM_RECT, PRIM_COUNT };
enum precision_choice { PRECISION_AUTO, PRECISION_FP32, PRECISION_FP16, PRECISION_PACKED };
enum mrt_choice { MRT_AUTO, MRT_ON, MRT_OFF };
/* Step-size control (paper section 4.2): fixed h; step doubling (one step of h against two of h/2);
 * the error estimate of the embedded Dormand-Prince 5(4) pair (method dopri5 only). */
enum step_control { STEP_FIXED, STEP_DOUBLING, STEP_EMBEDDED };
enum sky_type { SKY_COLOR, SKY_CUBEMAP };
/* How moving objects are drawn: traced per pixel in their rest frames (exact), or as the paper's
 * comparison, their tessellated surface's vertices transformed and the triangles rasterised. */
enum moving_objects_method { MOVING_RAYS, MOVING_POLYGONS };
/* How a frame is scheduled on the GPU: auto picks the fewest passes this scene and GPU allow;
 * multipass is the paper's scheme (one pass per stage and segment); single follows every ray
 * to its end in one fragment-shader loop; fused runs each segment's integration, intersection
 * and termination as one pass (four draw buffers). */
enum pipeline_choice { PIPELINE_AUTO, PIPELINE_MULTIPASS, PIPELINE_SINGLE, PIPELINE_FUSED };
/* Where the single pass on exact orbits walks its chords: auto (a pass of its own on a GPU, in the
 * frame's pass on a CPU rasteriser), separate (a walk pass, then a pass that finishes the ray),
 * inline (one pass). The same rays either way (docs/PIPELINE.md). */
enum orbit_walk_choice { ORBIT_WALK_AUTO, ORBIT_WALK_SEPARATE, ORBIT_WALK_INLINE };
/* render.hit_shading: where the multipass scheme shades a batch's hit (stage_intersect.c) */
enum hit_shading_choice { HIT_SHADING_AUTO, HIT_SHADING_SEPARATE, HIT_SHADING_INLINE };

struct camera {
    vec3d position;
    vec3d look_at;
    vec3d up;
    double fov_deg;          /* vertical field of view, degrees */
};

/* Material of the paper's section 3.4: ambient, emissive, texture-modulated, fake Blinn-Phong. */
struct material {
    vec3d color;             /* base (diffuse) colour, linear RGB 0..1 */
    vec3d emission;          /* emitted colour, added unlit */
    double ambient;          /* ambient factor */
    double diffuse;          /* diffuse factor */
    double specular;         /* specular factor */
    double shininess;        /* Blinn-Phong exponent */
    int texture;             /* index into scene.textures, -1 for none */
    double checker;          /* >0: procedural checkerboard with this many squares per unit texcoord */
    vec3d checker_color;     /* second colour of the checkerboard */
    double clock_period;     /* > 0: a clock face in texture space, one turn per period of proper time */
    double temperature;      /* K; > 0: the emission is a black body, its luminance from `emission` */
    int accretion;           /* a disk of matter on Keplerian orbits about the mass, hottest at
                                `temperature` (physics/accretion.h) */
};

/* Geometry of one object. Which fields are used depends on the primitive. */
struct object {
    char name[SCENE_NAME_LEN];
    enum primitive_type type;
    vec3d center;            /* sphere, disk, rect */
    double radius;           /* sphere; disk outer radius */
    double inner_radius;     /* disk (annulus); 0 for a full disk */
    vec3d normal;            /* disk */
    vec3d axis_u, axis_v;    /* rect: half-edge vectors from the centre */
    vec3d vertex[3];         /* triangle */
    double uv[3][2];         /* triangle texture coordinates */
    vec3d pole;              /* sphere: north axis for texture coordinates */
    struct material material;
    /* Motion (flat space only): velocity in units of c. The geometry above is the object's shape
     * in its rest frame, placed so that at scene time t = 0 the point frame_origin is where it is
     * written; objects with the same velocity and frame_origin move as one rigid body. */
    vec3d velocity;
    vec3d frame_origin;
    int frame_origin_given;  /* 0: the object's reference point (centre, or a triangle's centroid) */
};

struct light {
    vec3d position;
    vec3d color;
    double temperature;            /* K; > 0: a black body (colour from its apparent temperature) */
    char name[SCENE_NAME_LEN];     /* from [light NAME]: lets --set light.NAME.key find it */
};

struct sky {
    enum sky_type type;
    vec3d color;             /* SKY_COLOR */
    char cubemap[SCENE_PATH_LEN]; /* SKY_CUBEMAP: path prefix, faces are PREFIX_{px,nx,py,ny,pz,nz}.png */
    double temperature;      /* K; > 0: every texel a black body, its luminance from the texel */
    /* Point stars and the Milky Way over the sky above (results/star_light.h) */
    int stars;               /* stars of a generated catalogue (physics/star_catalogue.h); 0: none */
    char catalogue[SCENE_PATH_LEN];  /* "": none; the real sky's stars (physics/bright_stars.h) */
    char catalogue_colours[SCENE_PATH_LEN];  /* "": none; their colours, by HR number */
    int star_seed;           /* the catalogue's seed: the same stars for the same seed */
    double star_brightness;  /* light of a 6th-magnitude star at rest, linear, summed over its pixels */
    double star_size;        /* standard deviation of a star's Gaussian image, pixels */
    double milky_way;        /* linear radiance of the galactic band at its brightest; 0: none */
    vec3d galactic_pole;     /* the band's axis; the stars gather toward the plane it is normal to */
    vec3d galactic_center;   /* toward the band's bright bulge (its part in the plane counts) */
};

/* Relativistic effects shown (Müller, Grottel and Weiskopf 2010): aberration only; black-body
 * colour from the Doppler-shifted temperature, each temperature at its own luminance (Figure 6
 * left); the same at one fixed luminance scale with the logarithmic curve, which keeps the
 * searchlight's brightening (Figure 6 right). */
enum relativity_effects { EFFECTS_GEOMETRY, EFFECTS_DOPPLER, EFFECTS_SEARCHLIGHT };

/* The camera's motion: velocity in units of c relative to the scene's rest frame (flat space) or to
 * the static observer at the camera (Schwarzschild). */
/* The searchlight's exposure: the scene's own reference temperature at mid-grey (its brightening
 * ahead and dimming behind both visible), or the paper's fixed 1500 K (a 6000 K sky is white). */
enum searchlight_exposure { EXPOSURE_SCENE, EXPOSURE_PAPER };

struct observer {
    vec3d velocity;
    enum relativity_effects effects;
    enum searchlight_exposure exposure;
    /* 1: colours shifted by gravity as well as motion (a static emitter deeper in the field is seen
     * redder, the camera's own depth makes all it sees bluer); 0: motion's shift alone, for teaching
     * the two apart (the kiosk's effects button) */
    int gravitational_shift;
    double time;             /* scene time of the observation, length units (c = 1) */
};

enum star_pass_choice { STAR_PASS_CPU, STAR_PASS_GPU, STAR_PASS_AUTO };
enum tone_curve_choice { TONE_CURVE_CLIP, TONE_CURVE_FILMIC };

struct render_settings {
    int width, height;
    enum integration_method method;  /* unnamed: scene_default_method */
    int method_named;        /* render.method was written in the file or by --set */
    double step_size;        /* integration step h, scene length units (affine parameter) */
    int steps_per_segment;   /* paper's n_integration */
    int segments;            /* paper's n_segs; 0: derived from the path budget (render_segments) */
    int steps_per_pass;      /* K: integration steps unrolled in one shader */
    double bound_radius;     /* radius of the bounding sphere around bound_center */
    vec3d bound_center;
    enum precision_choice precision;
    enum mrt_choice mrt;
    /* acceleration (paper section 4): early ray termination through the early-z test, every
     * termination_interval segments; objects intersected batch at a time */
    int early_z;
    int termination_interval;
    int batch;
    /* adaptive integration: the step shrinks where the local error estimate exceeds tolerance,
     * and (step doubling) grows where it is below grow_fraction * tolerance; step_min and
     * step_max bound it (0: step / 1024 and step * 64) */
    enum step_control step_control;
    double tolerance;
    double grow_fraction;
    double step_min, step_max;
    /* the longest step a ray takes where no object is near (0, or no more than the step near them:
     * steps do not grow). The longest step from a point grows with its distance from the nearest
     * object's bound from `step` (fixed steps) or step_max (adaptive ones) to at most this
     * (shaders_es/stage_integrate.glsl, far_bound); a ray's state then carries the path it
     * travelled, as with adaptive steps, and its budget is that path */
    double far_step;
    enum moving_objects_method moving_objects;
    int polygon_subdivision;
    /* method orbit_table: largest distance of a segment's chord from the exact orbit (scene
     * units), which sets each ray's number of segments (at most `segments`); the table's rows per
     * side of the critical launch angle and samples along each orbit */
    double chord_tolerance;
    int max_chords;           /* method orbit_table: most chords a ray's orbit is split into */
    int orbit_rows, orbit_columns;
    enum orbit_walk_choice orbit_walk;
    enum hit_shading_choice hit_shading;
    enum pipeline_choice pipeline;  /* MOVING_POLYGONS: segments along each edge of a primitive's mesh */
    /* the budget of a ray, in its affine parameter (the path length of light with |v| = 1): 0 takes
     * SCENE_PATH_BOUND_DIAMETERS diameters of the bounding sphere (render_path_budget) */
    double max_path;
    vec3d unfinished_color;  /* what a ray still travelling at the end of its budget shows */
    /* rays per pixel, averaged in linear light (scene/pixel_samples.h: where they start); the
     * dump and trace follow the first, the pixel's centre */
    int samples;
    double sky_alpha;         /* the image's alpha where rays reached the sky (1: opaque) */
    /* where the stars and the Milky Way of [sky] are drawn: after the rays on the CPU's cores
     * (results/star_light.h, the reference), or in the frame's own pass on the GPU (results/star_map.h;
     * the kiosk always); auto (the default): the CPU's, or the GPU's where the rays' state cannot be
     * read back (the image-only path: renderer_gpu_stars) */
    enum star_pass_choice star_pass;
    /* the light of an 8-bit image (results/tone.h): linear light times gain, then each channel
     * clipped at white, or the filmic curve on the luminance */
    double gain;
    enum tone_curve_choice tone_curve;
    /* the glare about bright light (results/bloom.h): the fraction of each pixel's light spread,
     * 0 for none, and the narrowest Gaussian's sigma as a fraction of the image's height */
    double bloom;
    double bloom_radius;
};

/* The six faces of a cube map sky, in GL's order (+x, -x, +y, -y, +z, -z), and the file of face f
 * for the prefix of [sky] cubemap: PREFIX_px.png and so on (scene_keys.c). */
#define SCENE_CUBEMAP_FACES 6
extern const char *const scene_cubemap_faces[SCENE_CUBEMAP_FACES];
void scene_cubemap_face_path(const char *prefix, int face, char *out, size_t len);

/* The bounds adaptive steps stay within (the defaults resolved). */
double render_step_min(const struct render_settings *r);
double render_step_max(const struct render_settings *r);

/* The default budget of a ray: a path this many times the bounding sphere's diameter. A straight
 * ray crosses the sphere within one diameter; the rest is for bent ones (orbits, flows). */
#define SCENE_PATH_BOUND_DIAMETERS 3
/* Adaptive steps shrink where light bends most: segments derived from the budget at the initial
 * step are this many times the budget's share, so that a ray's budget, not its segments, ends it. */
#define SCENE_ADAPTIVE_SEGMENT_MARGIN 2
/* The budget of a ray, in the affine parameter. Fixed steps: the segments a frame runs x
 * steps_per_segment x step, as the paper counts it (the segments given, or max_path rounded up to
 * whole segments). Adaptive steps: max_path, or SCENE_PATH_BOUND_DIAMETERS bounding-sphere
 * diameters where it is 0. */
double render_path_budget(const struct render_settings *r);
/* The path asked for: max_path, or SCENE_PATH_BOUND_DIAMETERS bounding-sphere diameters. */
double render_requested_path(const struct render_settings *r);
/* Segments a frame runs: `segments` where given; else enough for the budget at `step`
 * (SCENE_ADAPTIVE_SEGMENT_MARGIN times that with adaptive steps). May exceed SCENE_MAX_SEGMENTS;
 * validation refuses such a scene. */
long render_segments_needed(const struct render_settings *r);
int render_segments(const struct render_settings *r);
/* Writes the segments a frame runs into `segments`, for code that changes steps or segments and
 * keeps the path: fixed steps then take their budget from the segments (max_path cleared). */
void render_fix_segments(struct render_settings *r);

/* What the scene's own settings reach against the CPU reference at the scene's own size
 * ([quality], each an upper bound; negative where the file states none): the percentage of
 * pixels whose outcome differs, the 99th percentiles of the exit-direction error of sky pixels
 * (radians) and of the hit error relative to the object's size (docs/ERRORS.md). Checked by
 * `bentray error --check`. */
struct quality_bound {
    double differing_percent;
    double exit_p99;
    double hit_p99;
};

/* [kiosk]: what a kiosk knob sets in this scene where its own meaning does not apply (a model
 * without a mass, a flow the observer's speed means nothing in): a numeric key of the scene, as
 * --set names it ("model.rho"), moved evenly from min to max over steps detents. key "": the knob
 * keeps its own meaning (kiosk/kiosk.conf [speed], [mass]). */
/* What a visitor reads on the kiosk's screen: lines of text without a file's or a key's name. */
#define SCENE_KIOSK_WORDS_LEN 64
/* a caption: two rows of the kiosk's visitor block at any screen from 1024x768 (kiosk/hud.c) */
#define SCENE_KIOSK_CAPTION_LEN 97

struct knob_mapping {
    char key[SCENE_NAME_LEN];
    char label[SCENE_KIOSK_WORDS_LEN];   /* what the knob changes, in a visitor's words ("" : none) */
    double min, max;
    int steps;
};

#define SCENE_KIOSK_MAX_STEPS 1000   /* detents of a mapped knob from its min to its max */
/* The kiosk's knobs keep a black hole's shadow within this share of the view's height: beyond it a
 * visitor sees mostly black (scene_kiosk_validate, and the kiosk for scenes without [kiosk]). */
#define SCENE_KIOSK_SHADOW_MAX_FRACTION 0.6

struct scene_kiosk {
    char title[SCENE_KIOSK_WORDS_LEN];       /* the scene's title on the kiosk ("": its name) */
    char caption[SCENE_KIOSK_CAPTION_LEN];   /* one line for visitors under the title ("": none) */
    struct knob_mapping speed, mass;
};

struct scene {
    char path[SCENE_PATH_LEN];     /* file it came from */
    char dir[SCENE_PATH_LEN];      /* its directory: relative asset paths resolve against it */
    char name[SCENE_NAME_LEN];
    char description[256];
    struct camera camera;
    struct observer observer;
    struct model model;
    struct render_settings render;
    struct sky sky;
    vec3d ambient_light;           /* colour of the ambient light */
    int n_objects;
    struct object objects[SCENE_MAX_OBJECTS];
    int n_lights;
    struct light lights[SCENE_MAX_LIGHTS];
    int n_textures;
    char textures[SCENE_MAX_TEXTURES][SCENE_PATH_LEN]; /* resolved paths of PNG textures */
    int texture_line[SCENE_MAX_TEXTURES];  /* line of the first key that named each (0: --set or code) */
    int cubemap_line;                      /* line of [sky] cubemap (0: --set or code) */
    struct quality_bound quality;
    struct scene_kiosk kiosk;
};

/* 1 when the observer moves (the setup stage aberrates); 1 when colours follow the Doppler factor. */
int observer_moving(const struct scene *s);
int doppler_colour(const struct scene *s);
/* The black-body tone mapping of the scene's effects (enum blackbody_tone, physics/blackbody.h) and
 * the reference temperature its exposure takes: the sky's temperature, else the hottest light's,
 * else the hottest emitting object's (0: none). */
int scene_blackbody_tone(const struct scene *s);
double scene_reference_temperature(const struct scene *s);
/* 1 when the object has a velocity; then m holds its motion (physics/relativity.h). */
struct object_motion;
int object_motion(const struct object *o, struct object_motion *m);
/* The object's geometry in its rest frame, coordinates relative to its frame origin. */
void object_rest_geometry(const struct object *o, struct object *rest);
/* 1 when the sky, a light or an object is a black body: the Doppler effects have something to colour. */
int scene_has_black_body(const struct scene *s);
/* 1 when any object moves. */
int scene_has_moving_objects(const struct scene *s);
/* 1 when s's steps grow away from the objects: integrated rays (not straight, not exact orbits)
 * whose far_step is beyond `step` (fixed steps) or step_max (adaptive ones). Fixed steps' state then
 * carries the path, as adaptive steps' does, and their budget is a path. */
int scene_far_steps(const struct scene *s);

/* Errors from loading or overriding a scene are the one error type (io/error.h): where ("file:line"
 * or "--set model.mass=x"), the message, and status ERROR_INPUT, as for every configuration file. */

/* Defaults for every field (flat space, one sphere-free empty scene). */
void scene_defaults(struct scene *s);
/* A zeroed scene on the heap, owned by the caller; NULL with e filled (ERROR_RUNTIME) when there
 * is no memory for one. */
struct scene *scene_new(struct error *e);
/* Frees a scene of scene_new; NULL is nothing to free. */
void scene_free(struct scene *s);
/* Parse FILE into s (defaults first). 0 ok, -1 with err filled. */
int scene_load(struct scene *s, const char *path, struct error *err);
/* A scene that names no render.method takes the cheapest exact one that applies: orbit_table
 * (exact orbits, no steps) around a Schwarzschild mass with fixed steps, rk4 elsewhere.
 * scene_load and scene_set apply it; a scene built field by field calls it itself. */
void scene_default_method(struct scene *s);
/* Apply one "section.key=value" override (sections of objects: object.NAME.key). */
int scene_set(struct scene *s, const char *assignment, struct error *err);
/* The value of a numeric key of an unnamed section ("model.rho"); 0, or -1 where there is none. */
int scene_get_number(const struct scene *s, const char *key, double *out);
/* Sets such a key to value, checked as a number written in a file would be (finite, the key's
 * range), without going through text: the kiosk's knobs. 0, or -1 with err (where: "key=value"). */
int scene_set_number(struct scene *s, const char *key, double value, struct error *err);
/* [kiosk] as the file writes it: each mapped knob's key is a number of this scene, over a range the
 * key accepts that holds the scene's own value. scene_load runs it, before any --set: rendering
 * ignores the section, so an override that changes the model does not make it wrong. */
int scene_kiosk_validate(const struct scene *s, struct error *err);
/* Angular diameter, degrees, of the black hole's shadow as the static observer at the camera sees
 * it (the rays that fall through the horizon: b < 3 sqrt(3) M); 0 where nothing casts one (no mass,
 * not Schwarzschild), 360 with the camera at or inside the horizon. */
double scene_shadow_diameter_deg(const struct scene *s);
/* The same with the model's mass taken as MASS (a kiosk knob's). */
double scene_shadow_diameter_deg_at(const struct scene *s, double mass);
/* The largest mass whose shadow, seen from the camera of s, spans at most `diameter_deg`, rounded
 * down to three significant digits (as messages print it). */
double scene_mass_for_shadow(const struct scene *s, double diameter_deg);
/* 1 when path names one of the files the scene is read from (its file, a texture, a cube face: by
 * name or as the same file through links), with which one in words; 0 otherwise ("-" included). */
int scene_input_named(const struct scene *s, const char *path, char *which, size_t len);
/* Cross-field checks after all overrides (e.g. camera not inside the horizon). */
int scene_validate(const struct scene *s, struct error *err);

#endif
