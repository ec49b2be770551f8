/* render.pipeline = single for render.method = orbit_table: the whole frame in one fragment-shader
 * loop per ray (shaders_es/stage_orbit_frame.glsl) instead of four passes per segment. It runs the
 * same shader functions as the orbit, intersection and termination stages, and writes the result
 * textures of the multipass scheme, two colour targets a pass as every stage here: image and
 * velocity, which the sky stage needs, and on demand (a dump, trace or the kiosk's pipeline view)
 * hit and position in a second pass of the same loop. */
#include "render/stages.h"
#include <stdio.h>
#include <string.h>

int orbit_frame_applies(const struct renderer *r)
{
    const struct scene *s = r->scene;
    struct object_batch b;
    return r->exact_orbits && s->render.pipeline != PIPELINE_MULTIPASS &&
           object_batch_all(r, &b) == 0;
}

struct frame_args {
    const struct renderer *r;
    struct object_batch batch;
};

static void set_frame(GLuint p, const void *arg)
{
    const struct frame_args *a = arg;
    object_batch_set_uniforms(p, &a->batch);
    orbit_set_uniforms(p, a->r, 0);
}

int stage_orbit_frame(struct renderer *r, int state, char *err, size_t errlen)
{
    struct raystate *rs = &r->rs;
    struct frame_args a = {.r = r};
    if (object_batch_all(r, &a.batch) != 0) {
        snprintf(err, errlen, "render.pipeline = single: the scene's %d objects do not fit one pass on this GPU "
                 "(at most %d); use render.pipeline = multipass", r->scene->n_objects, intersect_batch_limit(r));
        return -1;
    }
    char batch[1024];
    if (a.batch.count > 0) {
        if (object_batch_defines(&a.batch, batch, sizeof batch) != 0) {
            snprintf(err, errlen, "internal: the defines of the single pass do not fit");
            return -1;
        }
    } else {
        /* nothing to meet: an empty batch of one slot keeps the shading code well-formed */
        snprintf(batch, sizeof batch, "#define BATCH_SIZE 1\n#define LIGHT_COUNT %d\n#define BATCH_TESTS\n#define ORBIT_HITS 1\n%s\n",
                 r->scene->n_lights, r->observer_defines);
    }
    const char *files[PRIM_COUNT + 10] = {"common.glsl", "model_schwarzschild.glsl"};
    int n = object_batch_files(&a.batch, files, 2);
    files[n++] = "observer.glsl";
    files[n++] = "orbit_table.glsl";
    files[n++] = "shade.glsl";
    files[n++] = "stage_intersect.glsl";
    files[n++] = "stage_orbit_frame.glsl";
    files[n] = NULL;
    {
        char defines[sizeof batch + sizeof r->model_defines + 128];
        snprintf(defines, sizeof defines, "%s%s#define SINGLE_PASS 1\n#define MAX_SEGMENTS %d\n%s", r->model_defines,
                 batch, r->scene->render.max_chords, state ? "#define ORBIT_FRAME_STATE 1\n" : "");
        const struct stage_program *sp = program_cache_get(&r->programs, files, defines, 1, err, errlen);
        if (!sp)
            return -1;
        GLuint out0 = state ? rs->result_hit : rs->result_image;
        GLuint out1 = state ? rs->result_position : rs->result_velocity;
        if (pass_run(r, sp, out0, out1, NULL, 0, set_frame, &a, err, errlen) != 0)
            return -1;
    }
    return gl_check("the single-pass frame", err, errlen);
}
