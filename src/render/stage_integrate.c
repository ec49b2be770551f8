/* Stage 2, ray integration (paper section 3.2): the n_integration steps of one segment, K per
 * pass. The segment's start position stays untouched for the intersection stage. */
#include "render/stages.h"
#include <stdio.h>

void integrate_set_uniforms(const struct program_uniforms *p, const void *renderer)
{
    const struct renderer *rn = renderer;
    const struct scene *s = rn->scene;
    const struct render_settings *r = &s->render;
    model_set_uniforms(p, &s->model);
    bounds_set_uniforms(p, s);
    if (r->step_control != STEP_FIXED) {
        uniform_float(p, "u_tolerance", r->tolerance);
        uniform_float(p, "u_grow_below", r->grow_fraction * r->tolerance);
        uniform_float(p, "u_step_min", render_step_min(r));
        uniform_float(p, "u_step_max", render_step_max(r));
    }
    if (r->step_control != STEP_FIXED || rn->far_steps)
        uniform_float(p, "u_path_max", render_path_budget(r));
    if (rn->far_steps)
        uniform_float(p, "u_far_step", r->far_step);
    if (rn->far_steps && rn->far_reach_count > 0) {
        glUniform4fv(program_uniform(p, "u_reach_ball"), rn->far_reach_count, &rn->far_ball[0][0]);
        glUniform4fv(program_uniform(p, "u_reach_normal"), rn->far_reach_count, &rn->far_normal[0][0]);
    }
}

int far_step_uniform_vecs(const struct renderer *r)
{
    return r->far_steps ? 2 * r->far_reach_count + 1 : 0;
}

int stage_integrate(struct renderer *r, int segment_start, struct error *e)
{
    const struct scene *s = r->scene;
    const char *const files[] = {"common.glsl", "bounds.glsl", r->model_file, "stage_integrate.glsl", NULL};
    const struct stage_program *sp = program_cache_get(r->programs, files, r->model_defines, 1, e);
    if (!sp)
        return -1;
    int passes = r->straight ? 1 : s->render.steps_per_segment / s->render.steps_per_pass;
    for (int k = 0; k < passes; k++)
        if (pass_move_rays(r, sp, segment_start, integrate_set_uniforms, r, e) != 0)
            return -1;
    return gl_check("ray integration", e);
}
