/* Stage 4, test for ray termination (paper section 4.1): rays that left the scene, were
 * captured or failed get their outcome at the end of the segment. */
#include "render/stages.h"

struct terminate_args {
    const struct scene *scene;
    int segment;
};

static void set_terminate(const struct program_uniforms *p, const void *arg)
{
    const struct terminate_args *a = arg;
    bounds_set_uniforms(p, a->scene);
    uniform_float(p, "u_segment_index", a->segment);
}

int stage_terminate(struct renderer *r, int segment, struct error *e)
{
    static const char *const files[] = {"common.glsl", "bounds.glsl", "stage_terminate.glsl", NULL};
    struct raystate *rs = &r->rs;
    const struct stage_program *sp = program_cache_get(r->programs, files, "", 1, e);
    if (!sp)
        return -1;
    struct terminate_args a = {r->scene, segment};
    int out = 1 - rs->cur_hit;
    struct pass_input in[] = {
        {"u_segment_end", rs->position[rs->cur_position]},
        {"u_hit", rs->hit[rs->cur_hit]},
        {"u_image", rs->image[rs->cur_hit]},
    };
    if (pass_run(r, sp, rs->hit[out], rs->image[out], in, 3, set_terminate, &a, e) != 0)
        return -1;
    rs->cur_hit = out;
    return gl_check("ray termination test", e);
}
