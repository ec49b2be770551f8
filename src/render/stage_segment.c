/* render.pipeline = fused: the integration, intersection and termination stages of one segment in
 * one pass (shaders_es/stage_segment.glsl), writing position, velocity, hit and image at once into
 * four draw buffers. The retirement stage, early-z and the early stop stay as the multipass scheme
 * runs them: the same rays, bit for bit, in two passes a segment (this one and the retirement's)
 * instead of five or more. For GPUs with four draw buffers that need not run long fragment loops
 * (OpenGL ES 2 with EXT_draw_buffers), and wherever the rays are read after every segment. */
#include "render/stages.h"
#include <stdio.h>

struct segment_args {
    const struct renderer *r;
    struct object_batch batch;    /* every object; its segment is this pass's (u_segment_index) */
};

static void set_segment(const struct program_uniforms *p, const void *arg)
{
    const struct segment_args *a = arg;
    object_batch_set_uniforms(p, &a->batch);
    integrate_set_uniforms(p, a->r);
    observer_set_uniforms(p, a->r);
}

int stage_segment(struct renderer *r, int segment, struct error *e)
{
    struct raystate *rs = &r->rs;
    const struct scene *s = r->scene;
    struct segment_args a = {.r = r};
    char batch[BATCH_DEFINES_LEN];
    if (frame_batch(r, &a.batch, e) != 0 || frame_batch_defines(r, &a.batch, batch, sizeof batch, e) != 0)
        return -1;
    a.batch.segment = segment;
    const char *files[PRIM_COUNT + 11] = {"common.glsl", "bounds.glsl", r->model_file};
    int n = object_batch_files(&a.batch, files, 3);
    files[n++] = "observer.glsl";
    files[n++] = "shade.glsl";
    files[n++] = "stage_intersect.glsl";
    files[n++] = "stage_integrate.glsl";
    files[n++] = "segment_end.glsl";
    files[n++] = "stage_segment.glsl";
    files[n] = NULL;
    char defines[sizeof batch + sizeof r->model_defines + 96];
    snprintf(defines, sizeof defines, "%s%s#define SINGLE_PASS 1\n#define PASSES_PER_SEGMENT %d\n", r->model_defines,
             batch, r->straight ? 1 : s->render.steps_per_segment / s->render.steps_per_pass);
    const struct stage_program *sp = program_cache_get(r->programs, files, defines, 1, e);
    if (!sp)
        return -1;
    /* the other copies of each: the segment's start stays where it is */
    int out_pos = rs->cur_position == 0 ? 1 : 0;
    int out_vel = 1 - rs->cur_velocity, out_hit = 1 - rs->cur_hit;
    struct pass_input in[] = {
        {"u_ray_position", rs->position[rs->cur_position]},
        {"u_ray_velocity", rs->velocity[rs->cur_velocity]},
        {"u_hit", rs->hit[rs->cur_hit]},
        {"u_image", rs->image[rs->cur_hit]},
    };
    const GLuint out[SEGMENT_FUSED_TARGETS] = {rs->position[out_pos], rs->velocity[out_vel], rs->hit[out_hit],
                                       rs->image[out_hit]};
    if (pass_run_targets(r, sp, out, in, 4, set_segment, &a, e) != 0)
        return -1;
    rs->cur_position = out_pos;
    rs->cur_velocity = out_vel;
    rs->cur_hit = out_hit;
    return gl_check("the fused segment pass", e);
}
