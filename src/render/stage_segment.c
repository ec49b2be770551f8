/* render.pipeline = fused: the integration, intersection and termination stages of one segment in
 * one pass (shaders_es/stage_segment.glsl), writing position, velocity, hit and image at once into
 * four draw buffers. The retirement stage, early-z and the early stop stay as the multipass scheme
 * runs them: the same rays, bit for bit, in two passes a segment (this one and the retirement's)
 * instead of five or more. For GPUs with four draw buffers that need not run long fragment loops
 * (OpenGL ES 2 with EXT_draw_buffers), and wherever the rays are read after every segment. */
#include "render/stages.h"
#include <stdio.h>

/* Why this frame cannot run fused (NULL: it can). */
static const char *fused_missing(const struct renderer *r, char *buf, size_t n)
{
    struct object_batch b;
    if (r->exact_orbits)
        return "render.method = orbit_table runs its own orbit stage";
    if (!r->path.mrt)
        return r->caps.mrt_works ? "the render path writes one target a pass (mrt = off)" : "MRT does not work here";
    if (!render_path_can_fuse(&r->caps, r->path.mrt)) {
        snprintf(buf, n, "GL_MAX_DRAW_BUFFERS is %d, the fused pass writes %d", r->caps.max_draw_buffers,
                 SEGMENT_FUSED_TARGETS);
        return buf;
    }
    if (object_batch_all(r, &b) != 0) {
        frame_objects_why(r, buf, n);
        return buf;
    }
    return NULL;
}

int segment_fused_choose(const struct renderer *r, char *why, size_t whylen, struct error *e)
{
    enum pipeline_choice choice = r->scene->render.pipeline;
    char buf[160];
    if (choice == PIPELINE_MULTIPASS) {
        snprintf(why, whylen, "render.pipeline = multipass");
        return 0;
    }
    const char *missing = fused_missing(r, buf, sizeof buf);
    if (choice == PIPELINE_FUSED && missing)
        return error_set(e, ERROR_INPUT, NULL, "render.pipeline = fused: %s; use render.pipeline = multipass or auto",
                         missing);
    if (missing) {
        snprintf(why, whylen, "%s", missing);
        return 0;
    }
    snprintf(why, whylen, choice == PIPELINE_FUSED ? "render.pipeline = fused"
                                                   : "%d draw buffers: one pass a segment", r->caps.max_draw_buffers);
    return 1;
}

struct segment_args {
    const struct renderer *r;
    struct object_batch batch;    /* every object; its segment is this pass's (u_segment_index) */
};

static void set_segment(const struct program_uniforms *p, const void *arg)
{
    const struct segment_args *a = arg;
    object_batch_set_uniforms(p, &a->batch);
    integrate_set_uniforms(p, a->r->scene);
    observer_set_uniforms(p, a->r);
}

int stage_segment(struct renderer *r, int segment, struct error *e)
{
    struct raystate *rs = &r->rs;
    const struct scene *s = r->scene;
    struct segment_args a = {.r = r};
    char batch[4096];
    if (frame_batch(r, &a.batch, e) != 0 || frame_batch_defines(r, &a.batch, batch, sizeof batch, e) != 0)
        return -1;
    a.batch.segment = segment;
    const char *files[PRIM_COUNT + 10] = {"common.glsl", r->model_file};
    int n = object_batch_files(&a.batch, files, 2);
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
    const struct stage_program *sp = program_cache_get(&r->programs, files, defines, 1, e);
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
