/* render.pipeline = single: the whole frame in one fragment-shader loop per ray instead of four or
 * more passes per segment. Integrated rays run shaders_es/stage_frame.glsl, rays on exact orbits
 * (render.method = orbit_table) shaders_es/stage_orbit_frame.glsl. Both call the very shader
 * functions of the setup, integration (or orbit), intersection and termination stages, and write
 * the result textures of the multipass scheme, two colour targets a pass as every stage here:
 * image and velocity, which the sky stage needs, and on demand (a dump, trace or the kiosk's
 * pipeline view) hit and position in a second pass of the same loop. Where only the image is read
 * (renderer_set_reads), the pass ends with the sky stage's colour instead (sky_colour.glsl) and
 * writes the final image itself: one full-screen pass and two float targets less. */
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
};

static void set_frame(const struct program_uniforms *p, const void *arg)
{
    const struct frame_args *a = arg;
    const struct renderer *r = a->r;
    object_batch_set_uniforms(p, &a->batch);
    if (a->output == FRAME_WRITES_COLOUR)
        sky_colour_set_uniforms(p, r, UNIT_FRAME_SKY);
    if (r->exact_orbits) {
        orbit_set_uniforms(p, r, 0);
        if (a->crossings)
            orbit_crossings_set_uniforms(p, r);
        return;
    }
    integrate_set_uniforms(p, r->scene);
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
             r->exact_orbits ? "#define ORBIT_HITS 1\n" : "", r->observer_defines);
    return 0;
}

int stage_frame(struct renderer *r, enum frame_output output, struct error *e)
{
    struct raystate *rs = &r->rs;
    const struct scene *s = r->scene;
    struct frame_args a = {.r = r, .output = output, .crossings = orbit_crossings_apply(r)};
    if (frame_batch(r, &a.batch, e) != 0)
        return -1;
    char batch[4096];
    if (frame_batch_defines(r, &a.batch, batch, sizeof batch, e) != 0)
        return -1;
    const char *files[PRIM_COUNT + 12] = {"common.glsl", "bounds.glsl", r->model_file};
    int n = object_batch_files(&a.batch, files, 3);
    files[n++] = "observer.glsl";
    if (output == FRAME_WRITES_COLOUR)
        files[n++] = "sky_colour.glsl";
    if (r->exact_orbits)
        files[n++] = "orbit_table.glsl";
    files[n++] = "shade.glsl";
    files[n++] = "stage_intersect.glsl";
    files[n++] = !r->exact_orbits ? "stage_integrate.glsl" : a.crossings ? "stage_orbit_crossings.glsl"
                                                                         : "stage_orbit_frame.glsl";
    if (!r->exact_orbits) {
        files[n++] = "segment_end.glsl";
        files[n++] = "stage_frame.glsl";
    }
    files[n] = NULL;
    char written[64];
    snprintf(written, sizeof written, "%s%s",
             output == FRAME_WRITES_STATE ? "#define FRAME_STATE 1\n" : output == FRAME_WRITES_COLOUR ? "#define FRAME_COLOUR 1\n" : "",
             output == FRAME_WRITES_COLOUR ? sky_colour_defines(r) : "");
    char defines[sizeof batch + sizeof r->model_defines + sizeof written + 128];
    if (r->exact_orbits)
        snprintf(defines, sizeof defines, "%s%s#define SINGLE_PASS 1\n#define MAX_SEGMENTS %d\n%s%s", r->model_defines,
                 batch, s->render.max_chords, written, a.batch.count == 0 ? "#define ORBIT_NOTHING_TO_MEET 1\n" : "");
    else
        snprintf(defines, sizeof defines, "%s%s#define SINGLE_PASS 1\n#define CHORD_CULL 1\n#define PASSES_PER_SEGMENT %d\n%s",
                 r->model_defines, batch, r->straight ? 1 : s->render.steps_per_segment / s->render.steps_per_pass,
                 written);
    const struct stage_program *sp =
        program_cache_get(r->programs, files, defines, output != FRAME_WRITES_COLOUR, e);
    if (!sp)
        return -1;
    GLuint out0 = output == FRAME_WRITES_STATE ? rs->result_hit : output == FRAME_WRITES_COLOUR ? rs->final_color
                                                                                               : rs->result_image;
    GLuint out1 = output == FRAME_WRITES_STATE ? rs->result_position : output == FRAME_WRITES_COLOUR ? 0
                                                                                                    : rs->result_velocity;
    if (pass_run(r, sp, out0, out1, NULL, 0, set_frame, &a, e) != 0)
        return -1;
    return gl_check("the single-pass frame", e);
}
