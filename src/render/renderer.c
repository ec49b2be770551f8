/* The pass schedule of one frame (paper Figure 1). */
#include "io/clock.h"
#include "gl/quad.h"
#include "gl/packing.h"
#include "gl/readback.h"
#include "render/stages.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>

static uint64_t fnv1a(uint64_t h, const void *bytes, size_t n)
{
    const unsigned char *c = bytes;
    for (size_t i = 0; i < n; i++)
        h = (h ^ c[i]) * 1099511628211u;
    return h;
}

/* What renderer_create loads of a scene, as one number: its objects' count, its textures and its
 * sky (FNV-1a over them); a run's scene must have the same. */
static uint64_t assets_key(const struct scene *s)
{
    int counts[3] = {s->n_objects, s->n_textures, (int)s->sky.type};
    uint64_t h = fnv1a(14695981039346656037u, counts, sizeof counts);
    h = fnv1a(h, s->sky.cubemap, strlen(s->sky.cubemap) + 1);
    for (int i = 0; i < s->n_textures; i++)
        h = fnv1a(h, s->textures[i], strlen(s->textures[i]) + 1);
    return h;
}

/* A mass too small for an orbit table in double precision bends no camera ray by a float rounding
 * but those within a few microradians of it (orbit_table.h): flat space, on exact orbits. */
static int mass_unresolved(const struct scene *s)
{
    return model_ops_of(s->model.type)->exact_orbits &&
           !orbit_table_resolves(s->model.mass, v3_len(v3_sub(s->camera.position, s->model.center)));
}

int scene_on_exact_orbits(const struct scene *s)
{
    return s->render.method == METHOD_ORBIT_TABLE && model_ops_of(s->model.type)->exact_orbits &&
           !model_is_straight(&s->model) && !mass_unresolved(s);
}

/* The variant of the scene as it is now: a knob may have switched the field off (flat space, not
 * integrated) or on, set the observer moving, or changed the effects between two frames. The
 * programs of every variant stay cached; only the black-body table is rebuilt when the tone
 * mapping changes. */
static int renderer_follow_scene(struct renderer *r, struct error *e)
{
    const struct scene *scene = r->scene;
    /* exact orbits need their table sampled as 32-bit floats; without it the rays are integrated (the
     * path says so). On a 16-bit ray state only the single pass keeps an orbit's values in 32 bits
     * (its loop stores nothing between chords): a run read segment by segment (trace), or one whose
     * scene asks for another pipeline, integrates with rk4 there */
    int table = r->path.table_format && (r->path.fp32 || (!r->run_hooked && scene->render.pipeline != PIPELINE_MULTIPASS &&
                                                         scene->render.pipeline != PIPELINE_FUSED));
    r->method = scene->render.method == METHOD_ORBIT_TABLE && !table ? METHOD_RK4 : scene->render.method;
    /* a model with its fields off is flat space: nothing is integrated (model_is_straight); so is
     * a mass too small for an orbit table, on exact orbits */
    r->straight = model_is_straight(&scene->model) || (r->method == METHOD_ORBIT_TABLE && mass_unresolved(scene));
    r->exact_orbits = !r->straight && r->method == METHOD_ORBIT_TABLE;
    /* integrated rays around a mass look the sky up along their direction at infinity (exact
     * orbits take it from the orbit table) */
    const struct model_ops *ops = model_ops_of(scene->model.type);
    r->sky_at_infinity = !r->straight && !r->exact_orbits && ops->direction_at_infinity;
    snprintf(r->model_file, sizeof r->model_file, "model_%s.glsl",
             r->straight ? "flat" : model_name(scene->model.type));
    /* steps that grow away from the objects (their bounds packed in renderer_open) */
    r->far_steps = !r->straight && !r->exact_orbits && scene_far_steps(scene);
    char far_define[64] = "";
    if (r->far_steps) {
        snprintf(far_define, sizeof far_define, "#define STEP_FAR %d\n%s", r->far_reach_count,
                 r->caps.cpu_rasterizer ? "#define FAR_REACH_COPIES 1\n" : "");
    }
    static const char *const method_defines[] = {"EULER", "RK4", "DOPRI5", "ORBIT_TABLE"};
    static const char *const control_defines[] = {"FIXED", "DOUBLING", "EMBEDDED"};
    int written = snprintf(r->model_defines, sizeof r->model_defines,
             "#define MODEL_%s 1\n%s%s%s#define METHOD_%s 1\n#define STEP_%s 1\n%s#define STEPS_PER_PASS %d\n%s",
             r->straight ? "FLAT" : "CURVED",
             /* a 16-bit ray state: each value rounded to a 16-bit float before it is written (common.glsl) */
             r->path.format && !r->path.fp32 ? "#define STATE_HALF 1\n" : "",
             !r->straight && model_capture_radius(&scene->model) > 0.0 ? "#define MODEL_HORIZON 1\n" : "",
             r->sky_at_infinity ? "#define SKY_AT_INFINITY 1\n" : "",
             method_defines[r->method],
             control_defines[scene->render.step_control], far_define, scene->render.steps_per_pass,
             !r->straight && ops->shader_defines ? ops->shader_defines(&scene->model) : "");
    if (written < 0 || (size_t)written >= sizeof r->model_defines)
        return error_set(e, ERROR_RUNTIME, NULL, "internal: the model's defines do not fit");
    if (observer_defines(scene, r->observer_defines, sizeof r->observer_defines) != 0)
        return error_set(e, ERROR_RUNTIME, NULL, "internal: the observer's defines do not fit");
    return observer_lut_load(r, e);
}

/* The checks of renderer_create: 0, or -1 with e, ERROR_INPUT when the failure is the user's request
 * (a forced path missing, a size beyond this GPU). */
static int renderer_open(struct renderer *r, const struct gl_context *ctx, const struct scene *scene,
                         struct error *e)
{
    r->scene = scene;
    r->assets_key = assets_key(scene);
    /* until a caller says it reads only the image, every run keeps its outcomes readable */
    r->reads = RENDER_READ_OUTCOMES;
    if (gl_caps_probe(&r->caps, ctx, e) != 0) {
        quad_release();              /* the probe takes its share of the pass quad even when it fails */
        return -1;
    }
    /* the objects' bounds that steps grow away from, as many as the GPU's uniforms spare (far_reach.h) */
    int most = r->caps.max_fragment_uniform_vectors >= FAR_REACH_ROOMY_VECS ? FAR_REACH_MAX : 1;
    r->far_reach_count = far_reach_pack(scene, most, r->far_ball, r->far_normal);
    if (!r->caps.fragment_fp32) {
        /* a picture computed in 16-bit floats is a wrong one: potential's rays never finish, a black
         * hole's shadow comes out at the wrong size (docs/LIMITS.md) */
        error_set(e, ERROR_RUNTIME, NULL, "this GPU (%s) does not compute its fragment shaders in 32-bit floats: %s; "
                  "bentray's rays need them, so it draws nothing rather than a wrong picture", r->caps.renderer,
                  r->caps.fragment_fp32_why);
        quad_release();
        return -1;
    }
    /* its status says whose failure it is: a forced path that this GPU lacks is the user's request,
     * no path at all the machine's */
    /* the packing is probed at start only where no float format renders; here where it is asked for */
    if (scene->render.precision == PRECISION_PACKED && !r->caps.packing)
        probe_packing(&r->caps);
    if (render_path_choose(&r->caps, scene->render.precision, scene->render.mrt, &r->path, e) != 0) {
        quad_release();
        return -1;
    }
    /* the packed path's float textures are twice the image's size each way (raystate.h) */
    int largest = r->path.packed ? r->caps.max_texture_size / 2 : r->caps.max_texture_size;
    if (scene->render.width > largest || scene->render.height > largest) {
        error_set(e, ERROR_INPUT, NULL, "image size %dx%d exceeds this GPU's texture limit %d%s", scene->render.width,
                  scene->render.height, r->caps.max_texture_size,
                  r->path.packed ? " at twice its size each way (the packed path's ray state)" : "");
        quad_release();
        return -1;
    }
    if (scene->render.method == METHOD_ORBIT_TABLE && !r->path.table_format) {
        if (scene->render.precision == PRECISION_FP16) {
            error_set(e, ERROR_INPUT, NULL, "render.method = orbit_table needs 32-bit float textures, and "
                      "render.precision = fp16 asks for 16-bit ones: use render.method = rk4 or precision auto");
            quad_release();
            return -1;
        }
        /* a GPU without them draws the scene integrated, and says so */
        size_t used = strlen(r->path.description);
        snprintf(r->path.description + used, sizeof r->path.description - used,
                 "; render.method = orbit_table needs 32-bit float textures: rays integrated with rk4 instead");
    } else if (scene->render.method == METHOD_ORBIT_TABLE && !r->path.fp32) {
        size_t used = strlen(r->path.description);
        snprintf(r->path.description + used, sizeof r->path.description - used,
                 "; exact orbits in the single pass, their table sampled as %s (rk4 where a frame takes another "
                 "pipeline)", r->path.table_format->name);
    }
    /* packed, the table is twice as wide and high (stage_orbit.c) */
    int twice = r->path.packed ? 2 : 1;
    int table_width = twice * (scene->render.orbit_columns + 1 + ORBIT_WARP_SAMPLES);
    int table_height = twice * 2 * scene->render.orbit_rows;
    if (scene->render.method == METHOD_ORBIT_TABLE && r->path.table_format &&
        (table_width > r->caps.max_texture_size || table_height > r->caps.max_texture_size)) {
        error_set(e, ERROR_INPUT, NULL, "the orbit table (%dx%d texels for render.orbit_columns = %d, "
                  "render.orbit_rows = %d%s) exceeds this GPU's texture limit %d", table_width, table_height,
                  scene->render.orbit_columns, scene->render.orbit_rows, r->path.packed ? ", packed" : "",
                  r->caps.max_texture_size);
        quad_release();
        return -1;
    }
    struct shader_target target = r->caps.shader;
    target.state_packed = r->path.packed;
    program_cache_init(&r->own_programs, &target, r->path.mrt);
    r->programs = &r->own_programs;
    r->programs_ready = 1;
    if (renderer_follow_scene(r, e) != 0)
        return -1;
    struct pipeline_choice_made forced;
    /* a pipeline the scene asks for and this GPU cannot run is refused before any work (ERROR_INPUT) */
    if (pipeline_choose(r, 0, &forced, e) != 0)
        return -1;
    if (textures_load(r, e) != 0 || polygons_load(r, e) != 0)
        return -1;
    return 0;
}

struct renderer *renderer_create(const struct gl_context *ctx, const struct scene *scene, struct error *e)
{
    error_clear(e);
    struct renderer *r = calloc(1, sizeof *r);
    if (!r) {
        error_set(e, ERROR_RUNTIME, NULL, "out of memory");
        return NULL;
    }
    if (renderer_open(r, ctx, scene, e) != 0) {
        if (r->programs_ready)
            renderer_destroy(r);
        else
            free(r);
        return NULL;
    }
    return r;
}

const struct render_path *renderer_path(const struct renderer *r) { return &r->path; }
const struct gl_caps *renderer_caps(const struct renderer *r) { return &r->caps; }
const char *renderer_pipeline(const struct renderer *r) { return r->pipeline_name ? r->pipeline_name : "multipass"; }
const char *renderer_pipeline_why(const struct renderer *r) { return r->pipeline_why; }

void renderer_set_hdr(struct renderer *r, const char *why) { r->hdr_why = why; }
void renderer_time_first_draws(struct renderer *r, int on) { r->time_first_draws = on; }

void renderer_capture_shaders(struct renderer *r, const char *file, void (*sink)(const char *source, void *arg),
                              void *arg)
{
    r->programs = &r->own_programs;
    r->programs->target.capture_file = file;
    r->programs->target.capture = sink;
    r->programs->target.capture_arg = arg;
}

const struct program_cache *renderer_programs(const struct renderer *r) { return r->programs; }

int renderer_share_programs(struct renderer *r, struct program_cache *pc)
{
    if (!program_cache_fits(pc, &r->own_programs.target, r->own_programs.mrt))
        return 0;
    r->programs = pc;
    return 1;
}
int renderer_hdr(const struct renderer *r) { return r->hdr_why != NULL; }
const char *renderer_hdr_why(const struct renderer *r) { return r->hdr_why; }

void renderer_set_subpixel(struct renderer *r, double dx, double dy)
{
    r->subpixel_x = dx;
    r->subpixel_y = dy;
}

/* The whole ray in one pass (stage_frame.c); the sky stage after it, unless the pass drew the colour
 * itself, which it does where only the image is read, and where the image and the outcomes are read
 * (a render's summary) on a 32-bit path whose pass writes two targets: the outcome codes then go to
 * an 8-bit target beside the image, and no float texture is written, cleared or read back. Not on
 * a 16-bit path, whose sky stage reads the shaded colour rounded to a half float: the colour drawn
 * in the pass, not rounded, would differ from it by a level or so where it is not the image alone
 * that is asked for. */
static int run_single_pass(struct renderer *r, struct error *e)
{
    /* the stars' footprints from neighbouring rays are the sky stage's alone */
    int codes = r->reads == RENDER_READ_OUTCOMES && r->path.mrt && r->path.fp32 && !r->hdr_why &&
                !stars_from_neighbours(r);
    if (codes) {
        /* two 8-bit targets where the path writes two float ones: complete on every GPU known, and
         * where one is not, the float outcomes as before */
        struct error unused;
        codes = raystate_fbo(&r->rs, r->rs.final_color, r->rs.outcome_codes, &unused) != 0;
    }
    int colour = (r->reads == RENDER_READ_IMAGE && !r->hdr_why && !stars_from_neighbours(r)) || codes;
    if ((r->exact_orbits && orbit_prepare(r, e) != 0) ||
        stage_frame(r, codes ? FRAME_WRITES_COLOUR_CODES : colour ? FRAME_WRITES_COLOUR : FRAME_WRITES_OUTCOMES,
                    e) != 0 ||
        (!colour && stage_sky(r, e) != 0))
        return -1;
    r->state_pending = 1;
    r->outcomes_pending = colour;
    r->codes_written = codes;
    return 0;
}

/* The paper's Figure 1, segment by segment: setup; per segment, move the rays (integrate K steps, or
 * follow their orbits), intersect them with the objects and end those that are done (or all three in
 * one fused pass); every termination_interval segments, retire the ended rays behind the early-z test;
 * then the polygons of moving objects and the sky. */
static int run_segments(struct renderer *r, int fused, segment_hook hook, void *hook_arg, struct error *e)
{
    const struct scene *s = r->scene;
    r->state_pending = 0;
    r->outcomes_pending = 0;
    r->codes_written = 0;
    if (stage_setup(r, e) != 0)
        return -1;
    int early_z = s->render.early_z;
    if (early_z) {
        /* every ray-state framebuffer shares the depth buffer: 1 = travelling */
        if (pass_early_z_begin(r, r->rs.result_hit, e) != 0)
            return -1;
    }
    int orbit = r->exact_orbits;
    if (orbit && orbit_prepare(r, e) != 0)
        return -1;
    int segments = r->straight ? 1 : orbit ? r->orbit.max_segments : render_segments(&s->render);
    /* Early stop: the first moving pass after each retirement runs inside an occlusion query,
     * which counts the rays the early-z test lets through: those still travelling. When it
     * counted none, every ray was retired before that segment, and no later segment can change a
     * ray: the loop ends there, one segment later, with the results of the full count. Not with
     * a hook, which reads the ray state after every segment. */
    int stop_early = early_z && !hook && r->caps.occlusion_query;
    if (stop_early && !r->queries[0])
        glGenQueries(2, r->queries);
    int pending = -1;
    for (int seg = 0; seg < segments; seg++) {
        int start = r->rs.cur_position;
        if (pending >= 0) {
            GLuint travelling = 1;
            glGetQueryObjectuiv(r->queries[pending & 1], GL_QUERY_RESULT, &travelling);
            pending = -1;
            if (travelling == 0)
                break;
        }
        int probe = stop_early && seg > 0 && seg % s->render.termination_interval == 0;
        if (probe)
            glBeginQuery(r->caps.query_target, r->queries[seg & 1]);
        int moved = fused   ? stage_segment(r, seg, e)
                    : orbit ? stage_orbit(r, seg, start, e)
                            : stage_integrate(r, start, e);
        if (probe)
            glEndQuery(r->caps.query_target);
        if (moved != 0)
            return -1;
        pending = probe ? seg : pending;
        /* the fused pass has intersected and ended the segment's rays too */
        if (!fused && (stage_intersect_all(r, seg, start, e) != 0 || stage_terminate(r, seg, e) != 0))
            return -1;
        if (early_z && (seg + 1) % s->render.termination_interval == 0 && seg + 1 < segments &&
            stage_retire(r, 0, e) != 0)
            return -1;
        if (hook && hook(r, seg, hook_arg) != 0)
            return error_set(e, ERROR_RUNTIME, NULL, "the reader of every segment stopped the run at segment %d",
                             seg);
    }
    if (stage_retire(r, 1, e) != 0 || stage_polygons(r, e) != 0)
        return -1;
    glDisable(GL_DEPTH_TEST);
    return stage_sky(r, e);
}

/* On the image-only path, what the caller asked for that needs the ray state in float textures,
 * refused before any pass: -1 with e, else 0. */
static int image_only_refuses(const struct renderer *r, int per_segment_hook, struct error *e)
{
    if (!r->path.image_only)
        return 0;
    const char *needs = per_segment_hook                ? "reading the rays after every segment (trace)"
                        : r->hdr_why                    ? r->hdr_why
                        : r->reads == RENDER_READ_STATE ? "reading the rays' state back (--dump, the pipeline view)"
                        : r->reads == RENDER_READ_SKY   ? "drawing the stars of the sky from the rays' exit directions"
                                                        : NULL;
    if (needs)
        return error_set(e, ERROR_RUNTIME, NULL, "render path image only: %s needs float render targets, and no "
                         "float format renders on this GPU (bentray info lists them)%s", needs,
                         r->reads == RENDER_READ_SKY && !per_segment_hook && !r->hdr_why
                             ? "; render.star_pass = gpu (or auto) draws them in the frame's own pass" : "");
    if (r->reads == RENDER_READ_OUTCOMES && !r->path.mrt)
        return error_set(e, r->caps.mrt_works ? ERROR_INPUT : ERROR_RUNTIME, NULL, "render path image only: each "
                         "ray's outcome (the summary) is drawn beside the image in a second target, and %s%s",
                         r->caps.mrt_works ? "render.mrt = off (--no-mrt) asks for one target a pass"
                                           : "multiple render targets do not work here: ",
                         r->caps.mrt_works ? "" : r->caps.mrt_why);
    return 0;
}

/* On the packed path, what needs a float render target or the ray state at its own size: -1 with
 * e, refused before any pass, else 0. */
static int packed_refuses(const struct renderer *r, struct error *e)
{
    if (!r->path.packed)
        return 0;
    /* the float colour is packed as the ray state is, four fragments a ray: no derivatives across rays */
    if (r->hdr_why && r->star_map)
        return error_set(e, ERROR_RUNTIME, NULL, "render path packed 8-bit: %s with render.star_pass = gpu: the "
                         "packed float colour's pass cannot take the stars' derivatives; star_pass = cpu (or auto) "
                         "draws them", r->hdr_why);
    for (int k = 0; k < r->scene->n_objects; k++)
        if (polygons_draw_object(r, k))
            return error_set(e, ERROR_RUNTIME, NULL, "render path packed 8-bit: render.moving_objects = polygons "
                             "draws into float targets, and no float format renders on this GPU (moving_objects = "
                             "rays traces [object %s] on any)", r->scene->objects[k].name);
    return 0;
}

int renderer_state_readable(const struct renderer *r) { return !r->path.image_only; }
int renderer_state_sampled(const struct renderer *r) { return !r->path.image_only && !r->path.packed; }
int renderer_gpu_stars(const struct renderer *r) { return r->star_map != 0; }

int renderer_run(struct renderer *r, const struct scene *scene, int origin_x, int origin_y, int width, int height,
                 segment_hook hook, void *hook_arg, struct error *e)
{
    if (assets_key(scene) != r->assets_key)
        return error_set(e, ERROR_RUNTIME, NULL, "internal: a run of scene '%s' on the renderer made for '%s', whose "
                         "objects, textures or sky it loaded: make a renderer for the new scene", scene->name,
                         r->scene->name);
    r->scene = scene;
    r->run_hooked = hook != NULL;
    if (!r->have_state || r->rs.width != width || r->rs.height != height) {
        if (r->have_state)
            raystate_release(&r->rs);
        r->have_state = 0;
        if (raystate_init(&r->rs, &r->path, width, height, e) != 0)
            return -1;
        r->have_state = 1;
    }
    if (renderer_follow_scene(r, e) != 0)
        return -1;
    double t0 = clock_seconds(), built = r->programs->build_seconds;
    r->passes = 0;
    r->compile_seconds = 0.0;
    r->quad_z = 0.0f;
    r->depth_write_last = 0;
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    r->origin_x = origin_x;
    r->origin_y = origin_y;
    struct pipeline_choice_made run;
    if (image_only_refuses(r, hook != NULL, e) != 0 || packed_refuses(r, e) != 0 ||
        pipeline_choose(r, hook != NULL, &run, e) != 0)
        return -1;
    r->pipeline_name = pipeline_name(run.kind);
    snprintf(r->pipeline_why, sizeof r->pipeline_why, "%s", run.why);
    if ((run.kind == PIPELINE_RUN_SINGLE ? run_single_pass(r, e)
                                         : run_segments(r, run.kind == PIPELINE_RUN_FUSED, hook, hook_arg, e)) != 0)
        return -1;
    glFinish();
    r->seconds = clock_seconds() - t0;
    r->compile_seconds += r->programs->build_seconds - built;
    return 0;
}

int renderer_read_position(struct renderer *r, int x, int y, float xyzw[4], struct error *e)
{
    float buf[4 * 1];
    GLuint fbo = raystate_fbo(&r->rs, r->rs.position[r->rs.cur_position], 0, e);
    if (!fbo)
        return -1;
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    if (read_float_pixels(x, y, 1, 1, buf) != 0)
        return error_set(e, ERROR_RUNTIME, NULL, "cannot read the ray position back");
    memcpy(xyzw, buf, sizeof buf);
    return 0;
}

int render_read_includes(enum render_read reads, int k)
{
    switch (reads) {
    case RENDER_READ_STATE: return 1;
    case RENDER_READ_OUTCOMES: return k == 3;
    case RENDER_READ_SKY: return k == 1 || k == 3;
    default: return 0;
    }
}

enum render_read render_read_with_sky(enum render_read reads) { return reads == RENDER_READ_STATE ? RENDER_READ_STATE : RENDER_READ_SKY; }

/* The single-pass frame's deferred outcome textures (image and velocity), traced again when the
 * frame drew its colour itself; then, with state, its hit and position. */
static int complete(struct renderer *r, int state, struct error *e)
{
    glDisable(GL_DEPTH_TEST);
    if (r->outcomes_pending) {
        r->outcomes_pending = 0;
        if (stage_frame(r, FRAME_WRITES_OUTCOMES, e) != 0)
            return -1;
    }
    if (!state || !r->state_pending)
        return 0;
    r->state_pending = 0;
    return stage_frame(r, FRAME_WRITES_STATE, e);
}

/* The outcome codes of a frame drawn with FRAME_WRITES_COLOUR_CODES, from the 8-bit target where
 * sky_colour.glsl left them (r: code + 4, g: the image's values not finite), into out->outcome and
 * out->outcome_nonfinite. */
static int read_outcome_codes(struct raystate *rs, struct render_result *out, struct error *e)
{
    size_t n = (size_t)rs->width * rs->height;
    unsigned char *codes = malloc(n * 4);
    out->outcome = malloc(n ? n : 1);
    if (!codes || !out->outcome) {
        free(codes);
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory reading the outcomes back");
    }
    if (raystate_read_bytes(rs, rs->outcome_codes, codes, "reading the outcomes back", e) != 0) {
        free(codes);
        return -1;
    }
    /* GL rows run bottom-up; images and dumps run top-down */
    size_t w = (size_t)rs->width;
    out->outcome_nonfinite = 0;
    for (int y = 0; y < rs->height; y++) {
        const unsigned char *row = codes + 4 * w * (size_t)(rs->height - 1 - y);
        signed char *to = out->outcome + w * (size_t)y;
        for (size_t x = 0; x < w; x++) {
            to[x] = (signed char)(row[4 * x] - 4);
            out->outcome_nonfinite += row[4 * x + 1];
        }
    }
    free(codes);
    return 0;
}

int renderer_read(struct renderer *r, struct render_result *out, enum render_read reads, struct error *e)
{
    struct raystate *rs = &r->rs;
    size_t n = (size_t)rs->width * rs->height;
    memset(out, 0, sizeof *out);
    out->width = rs->width;
    out->height = rs->height;
    out->passes = r->passes;
    out->seconds = r->seconds;
    out->compile_seconds = r->compile_seconds;
    out->rgba = malloc(n * 4);
    if (!out->rgba)
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory reading the image back");
    if (raystate_read_bytes(rs, rs->final_color, out->rgba, "reading the image back", e) != 0)
        return -1;
    if (rows_flip(out->rgba, (size_t)rs->width * 4, rs->height) != 0)
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory reading the image back");
    if (r->hdr_why) {
        out->color = malloc(n * 4 * sizeof(float));
        if (!out->color)
            return error_set(e, ERROR_RUNTIME, NULL, "out of memory reading the image back");
        if (raystate_read(rs, raystate_hdr_color(rs), out->color, e) != 0)
            return -1;
    }
    if (reads == RENDER_READ_IMAGE)
        return 0;
    if (reads == RENDER_READ_OUTCOMES && r->codes_written)
        return read_outcome_codes(rs, out, e);
    /* the image and velocity textures are written by every pipeline (a single pass that drew its
     * colour itself writes them now), position and hit on demand */
    if (complete(r, render_read_includes(reads, 0), e) != 0)
        return -1;
    float **dst[4] = {&out->position, &out->velocity, &out->hit, &out->image};
    GLuint src[4] = {rs->result_position, rs->result_velocity, rs->result_hit, rs->result_image};
    for (int k = 0; k < 4; k++) {
        if (!render_read_includes(reads, k))
            continue;
        *dst[k] = malloc(n * 4 * sizeof(float));
        if (!*dst[k])
            return error_set(e, ERROR_RUNTIME, NULL, "out of memory reading the ray state back");
        if (raystate_read(rs, src[k], *dst[k], e) != 0)
            return -1;
    }
    return 0;
}

int renderer_complete_state(struct renderer *r, struct error *e)
{
    return complete(r, 1, e);
}

void renderer_set_reads(struct renderer *r, enum render_read reads)
{
    r->reads = reads;
}

/* A texture of the ray state that the last run wrote (it has its memory), else 0. */
static GLuint written(const struct raystate *rs, GLuint texture)
{
    return raystate_stored(rs, texture) ? texture : 0;
}

void renderer_textures(const struct renderer *r, struct renderer_textures *out)
{
    memset(out, 0, sizeof *out);
    if (!r->have_state)
        return;
    out->width = r->rs.width;
    out->height = r->rs.height;
    out->image = written(&r->rs, r->rs.final_color);
    out->position = written(&r->rs, r->rs.result_position);
    out->velocity = written(&r->rs, r->rs.result_velocity);
    out->hit = written(&r->rs, r->rs.result_hit);
    out->outcome = written(&r->rs, r->rs.result_image);
    if (r->exact_orbits && r->orbit_texture) {
        out->orbit_table = r->orbit_texture;
        out->orbit_width = r->orbit.width;
        out->orbit_height = r->orbit.height;
        out->orbit_columns = r->orbit.p.columns;
        out->orbit_rows_per_side = r->orbit.p.rows_per_side;
        out->orbit_u_capture = r->orbit.u_capture;
    }
}

size_t renderer_state_bytes(const struct renderer *r)
{
    return r->have_state ? raystate_bytes(&r->rs) : 0;
}

int render_result_outcome(const struct render_result *res, size_t i)
{
    return res->outcome ? res->outcome[i] : (int)lrintf(res->image[4 * i + 3]);
}

void render_result_free(struct render_result *res)
{
    free(res->outcome);
    free(res->rgba);
    free(res->color);
    free(res->position);
    free(res->velocity);
    free(res->hit);
    free(res->image);
    memset(res, 0, sizeof *res);
}

void renderer_destroy(struct renderer *r)
{
    if (!r)
        return;
    if (r->have_state)
        raystate_release(&r->rs);
    textures_release(r);
    observer_lut_release(r);
    orbit_release(r);
    polygons_release(r);
    if (r->queries[0])
        glDeleteQueries(2, r->queries);
    program_cache_release(&r->own_programs);
    quad_release();
    free(r);
}
