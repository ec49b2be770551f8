/* render.pipeline = single: the whole frame in one fragment-shader loop per ray instead of four or
 * more passes per segment. Integrated rays run shaders_es/stage_frame.glsl, rays on exact orbits
 * (render.method = orbit_table) shaders_es/stage_orbit_frame.glsl. Both call the very shader
 * functions of the setup, integration (or orbit), intersection and termination stages, and write
 * the result textures of the multipass scheme, two colour targets a pass as every stage here:
 * image and velocity, which the sky stage needs, and on demand (a dump, trace or the kiosk's
 * pipeline view) hit and position in a second pass of the same loop. Where only the image is read
 * (renderer_set_reads), the pass ends with the sky stage's colour instead (sky_colour.glsl) and
 * writes the final image itself: one full-screen pass and two float targets less; where the outcomes
 * are read too (a render's summary), with MRT, each ray's outcome code goes to an 8-bit target beside
 * it (FRAME_WRITES_COLOUR_CODES, sky_colour.glsl's FRAME_CODES). On exact orbits
 * the walk along the chords may run in a pass of its own before the one that finishes each ray
 * (render.orbit_walk, orbit_walk_passes below, shaders_es/stage_orbit_walk.glsl). */
#include "render/stages.h"
#include <stdio.h>
#include <string.h>

int frame_batch(const struct renderer *r, struct object_batch *b, struct error *e)
{
    if (object_batch_all(r, b) == 0)
        return 0;
    return error_set(e, ERROR_INPUT, NULL, "render.pipeline = single: the scene's %d objects do not fit one pass on "
                     "this GPU (at most %d, their textures within its texture units, none drawn as polygons); use "
                     "render.pipeline = multipass or auto", r->scene->n_objects, frame_object_limit(r));
}

struct frame_args {
    const struct renderer *r;
    struct object_batch batch;
    enum frame_output output;
    int crossings;                /* orbit_crossings_apply */
    int walked;                   /* the walk in passes of its own (orbit_walk_passes) */
    int attempt;                  /* ... and which of its pairs of passes this is */
};

/* Walks a ray takes at most: after a hit its orbit misses, it goes on from the chord's end (the
 * last hit found is kept), as the multipass scheme's intersection stage keeps no such hit. */
enum { ORBIT_HIT_TRIES = 3 };

static void set_frame(const struct program_uniforms *p, const void *arg)
{
    const struct frame_args *a = arg;
    const struct renderer *r = a->r;
    object_batch_set_uniforms(p, &a->batch);
    if (a->output == FRAME_WRITES_COLOUR || a->output == FRAME_WRITES_COLOUR_CODES)
        sky_colour_set_uniforms(p, r, UNIT_FRAME_SKY);
    if (r->exact_orbits) {
        orbit_set_uniforms(p, r, 0);
        if (a->crossings)
            orbit_crossings_set_uniforms(p, r);
        if (a->walked) {
            uniform_float(p, "u_orbit_resume", a->attempt > 0);
            uniform_float(p, "u_orbit_last_try", a->attempt == ORBIT_HIT_TRIES - 1);
        }
        return;
    }
    integrate_set_uniforms(p, r);
    observer_set_uniforms(p, r);
    uniform_float(p, "u_step_size", r->scene->render.step_size);
    uniform_float(p, "u_segments", r->straight ? 1 : render_segments(&r->scene->render));
}

int frame_batch_defines(const struct renderer *r, const struct object_batch *b, char *out, size_t len,
                        struct error *e)
{
    if (b->count > 0) {
        if (object_batch_defines(b, out, len) == 0)
            return 0;
        return error_set(e, ERROR_RUNTIME, NULL, "internal: the defines of a pass with every object do not fit");
    }
    /* nothing to meet: an empty batch of one slot keeps the shading code well-formed */
    snprintf(out, len, "#define BATCH_SIZE 1\n#define LIGHT_COUNT %d\n#define BATCH_TESTS\n%s%s\n", r->scene->n_lights,
             r->exact_orbits ? "#define ORBIT_HITS 1\n#define BATCH_WEDGES\n#define BATCH_GROUP_CULLS\n" : "",
             r->observer_defines);
    return 0;
}

/* Whether the walk of rays on exact orbits runs in a pass of its own (render.orbit_walk): auto takes it
 * on a GPU, whose register file the one pass overflows (`make shader-stats`: the kiosk's black-hole
 * frame spills 263 values on V3D 4.2 in one pass, 94 and 37 in the two, and compiles in 27 s of an
 * x86 core instead of 2 + 3), and not on a CPU rasteriser, where nothing spills into memory that was
 * not there already and the finish pass only adds the work it does again. */
int orbit_walk_separate(const struct renderer *r)
{
    switch (r->scene->render.orbit_walk) {
    case ORBIT_WALK_SEPARATE: return 1;
    case ORBIT_WALK_INLINE: return 0;
    default: return !r->caps.cpu_rasterizer;
    }
}

/* The frame's program: the walk's pass (FRAME_WALK), or the frame itself (writing OUTPUT). */
static const struct stage_program *frame_program(struct renderer *r, const struct frame_args *a, int walk,
                                                 struct error *e)
{
    const struct scene *s = r->scene;
    enum frame_output output = a->output;
    int colour = output == FRAME_WRITES_COLOUR || output == FRAME_WRITES_COLOUR_CODES;
    char batch[BATCH_DEFINES_LEN];
    if (frame_batch_defines(r, &a->batch, batch, sizeof batch, e) != 0)
        return NULL;
    const char *files[PRIM_COUNT + 12] = {"common.glsl", "bounds.glsl", r->model_file};
    int n = object_batch_files(&a->batch, files, 3);
    files[n++] = "observer.glsl";
    if (colour && !walk)
        files[n++] = "sky_colour.glsl";
    if (r->exact_orbits)
        files[n++] = "orbit_table.glsl";
    files[n++] = "shade.glsl";
    files[n++] = "stage_intersect.glsl";
    if (!r->exact_orbits) {
        files[n++] = "stage_integrate.glsl";
        files[n++] = "segment_end.glsl";
        files[n++] = "stage_frame.glsl";
    } else if (a->crossings) {
        files[n++] = "stage_orbit_crossings.glsl";
    } else {
        files[n++] = "stage_orbit_walk.glsl";
        if (!walk)
            files[n++] = "stage_orbit_frame.glsl";
    }
    files[n] = NULL;
    char written[SKY_COLOUR_DEFINES_LEN + 160], sky_defines[SKY_COLOUR_DEFINES_LEN] = "";
    if (colour && !walk)
        sky_colour_defines(r, sky_defines, sizeof sky_defines);
    /* where the outputs read of a ray that leaves only that it leaves (its sky is along its direction
     * at infinity), the walk stops in the first group of chords that meets nothing and ends outside
     * the bounding sphere, without finding the chord that crosses it (stage_orbit_walk.glsl) */
    int unplaced = r->exact_orbits && output != FRAME_WRITES_STATE;
    snprintf(written, sizeof written, "%s%s%s%s%s",
             unplaced ? "#define ORBIT_SKY_UNPLACED 1\n" : "",
             walk ? "#define ORBIT_WALK_PASS 1\n" : a->walked ? "#define ORBIT_WALKED 1\n" : "",
             walk ? "" : output == FRAME_WRITES_STATE ? "#define FRAME_STATE 1\n" : colour ? "#define FRAME_COLOUR 1\n" : "",
             sky_defines,
             output == FRAME_WRITES_COLOUR_CODES && !walk ? "#define FRAME_CODES 1\n" : "");
    char defines[sizeof batch + sizeof r->model_defines + sizeof written + 160];
    if (r->exact_orbits)
        snprintf(defines, sizeof defines, "%s%s#define SINGLE_PASS 1\n#define MAX_SEGMENTS %d\n#define ORBIT_HIT_TRIES %d\n%s%s",
                 r->model_defines, batch, s->render.max_chords, ORBIT_HIT_TRIES, written,
                 a->batch.count == 0 ? "#define ORBIT_NOTHING_TO_MEET 1\n" : "");
    else
        snprintf(defines, sizeof defines, "%s%s#define SINGLE_PASS 1\n#define CHORD_CULL 1\n%s#define PASSES_PER_SEGMENT %d\n%s",
                 r->model_defines, batch, r->caps.cpu_rasterizer ? "" : "#define CHORD_CULL_UNIFORMS 1\n",
                 r->straight ? 1 : s->render.steps_per_segment / s->render.steps_per_pass, written);
    return program_cache_get(r->programs, files, defines, !walk && output != FRAME_WRITES_COLOUR, e);
}

/* The walk and the finish of rays on exact orbits in pairs of passes (stage_orbit_walk.glsl): the
 * walk writes where each ray stopped into a spare position texture (the single pass uses none of
 * them), the finish reads it and writes the frame's outputs, and marks the rays it finished in the
 * depth buffer, as the multipass scheme's retirement does (stage_retire.c); a ray whose hit the
 * orbit misses goes on in the next pair, whose passes the early-z test skips for every other ray.
 * A pair runs only where a ray goes on: the walk after the first runs in an occlusion query
 * (ES 3: any sample), and where it drew nothing, no ray goes on. */
static int orbit_walk_passes(struct renderer *r, struct frame_args *a, GLuint out0, GLuint out1, struct error *e)
{
    struct raystate *rs = &r->rs;
    const struct stage_program *walk = frame_program(r, a, 1, e);
    const struct stage_program *finish = walk ? frame_program(r, a, 0, e) : NULL;
    if (!finish)
        return -1;
    GLuint state[2] = {rs->orbit_walk[0], rs->orbit_walk[1]};
    if (pass_early_z_begin(r, state[0], e) != 0)
        return -1;
    int query = r->caps.occlusion_query;
    if (query && !r->queries[0])
        glGenQueries(2, r->queries);
    int rc = 0;
    for (int attempt = 0; attempt < ORBIT_HIT_TRIES && rc == 0; attempt++) {
        a->attempt = attempt;
        GLuint before = state[(attempt + 1) % 2], now = state[attempt % 2];
        struct pass_input walk_in = {"u_orbit_walk", before};
        int counted = query && attempt > 0;
        if (counted)
            glBeginQuery(r->caps.query_target, r->queries[0]);
        rc = pass_run(r, walk, now, 0, &walk_in, 1, set_frame, a, e);
        if (counted) {
            glEndQuery(r->caps.query_target);
            GLuint going_on = 1;
            glGetQueryObjectuiv(r->queries[0], GL_QUERY_RESULT, &going_on);
            if (going_on == 0)
                break;
        }
        struct pass_input finish_in = {"u_orbit_walk", now};
        r->depth_write_last = 1;
        rc = rc != 0 ? rc : pass_run(r, finish, out0, out1, &finish_in, 1, set_frame, a, e);
        r->depth_write_last = 0;
    }
    glDisable(GL_DEPTH_TEST);
    return rc;
}

int stage_frame(struct renderer *r, enum frame_output output, struct error *e)
{
    struct raystate *rs = &r->rs;
    struct frame_args a = {.r = r, .output = output, .crossings = orbit_crossings_apply(r)};
    if (frame_batch(r, &a.batch, e) != 0)
        return -1;
    a.walked = r->exact_orbits && !a.crossings && a.batch.count > 0 && orbit_walk_separate(r);
    GLuint out0 = rs->result_image, out1 = rs->result_velocity;
    switch (output) {
    case FRAME_WRITES_STATE: out0 = rs->result_hit, out1 = rs->result_position; break;
    case FRAME_WRITES_COLOUR: out0 = rs->final_color, out1 = 0; break;
    case FRAME_WRITES_COLOUR_CODES: out0 = rs->final_color, out1 = rs->outcome_codes; break;
    case FRAME_WRITES_OUTCOMES: break;
    }
    if (a.walked) {
        if (orbit_walk_passes(r, &a, out0, out1, e) != 0)
            return -1;
    } else {
        const struct stage_program *sp = frame_program(r, &a, 0, e);
        if (!sp || pass_run(r, sp, out0, out1, NULL, 0, set_frame, &a, e) != 0)
            return -1;
    }
    return gl_check("the single-pass frame", e);
}
