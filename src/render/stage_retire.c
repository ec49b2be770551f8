/* Early ray termination (paper section 4.1): finished rays are copied into the result textures
 * and marked in the depth buffer, so that the early-z test skips them in the heavy passes.
 * The heavy passes draw at depth 0.5 with GL_LESS and write no depth; this pass draws at depth 0
 * with GL_LESS too (the depth direction never changes within a frame), so a ray is retired once. */
#include "render/stages.h"

struct retire_args {
    const struct renderer *r;
    int all, exit_pair;
};

static void set_retire(const struct program_uniforms *p, const void *arg)
{
    const struct retire_args *a = arg;
    uniform_float(p, "u_retire_all", a->all ? 1.0 : 0.0);
    if (a->r->sky_at_infinity) {
        uniform_float(p, "u_exit_pair", a->exit_pair ? 1.0 : 0.0);
        model_set_uniforms(p, &a->r->scene->model);
    }
}

int stage_retire(struct renderer *r, int all, struct error *e)
{
    /* integrated rays around a mass: the sky's direction at infinity goes into the velocity */
    static const char *const files[] = {"common.glsl", "stage_retire.glsl", NULL};
    static const char *const files_at_infinity[] = {"common.glsl", "model_schwarzschild.glsl", "stage_retire.glsl",
                                                    NULL};
    struct raystate *rs = &r->rs;
    const struct stage_program *sp =
        r->sky_at_infinity ? program_cache_get(r->programs, files_at_infinity, "#define SKY_AT_INFINITY 1\n", 1, e)
                           : program_cache_get(r->programs, files, "", 1, e);
    if (!sp)
        return -1;
    struct retire_args a0 = {r, all, 1}, a1 = {r, all, 0};
    struct pass_input pair0[] = {
        {"u_state0", rs->position[rs->cur_position]},
        {"u_state1", rs->velocity[rs->cur_velocity]},
        {"u_hit", rs->hit[rs->cur_hit]},
        {"u_image", rs->image[rs->cur_hit]},
    };
    struct pass_input pair1[] = {
        {"u_state0", rs->hit[rs->cur_hit]},
        {"u_state1", rs->image[rs->cur_hit]},
        {"u_hit", rs->hit[rs->cur_hit]},
        {"u_image", rs->image[rs->cur_hit]},
    };
    int inputs = r->sky_at_infinity ? 4 : 3;
    r->quad_z = -1.0f;          /* depth 0: in front of the heavy passes' 0.5 */
    int rc = pass_run(r, sp, rs->result_position, rs->result_velocity, pair0, inputs, set_retire, &a0, e);
    /* the depth mark goes with the last draw, after every result texture has its copy */
    r->depth_write_last = r->scene->render.early_z;
    if (rc == 0)
        rc = pass_run(r, sp, rs->result_hit, rs->result_image, pair1, inputs, set_retire, &a1, e);
    r->depth_write_last = 0;
    r->quad_z = 0.0f;
    if (rc != 0)
        return -1;
    return gl_check("ray retirement", e);
}
