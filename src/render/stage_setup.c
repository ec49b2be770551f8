/* Stage 1, ray setup (paper section 3.1): hit and image start as "no hit", positions at the
 * camera, velocities from the pinhole camera through the model's initial-velocity map. */
#include "render/stages.h"
#include "results/dump.h"
#include <stdio.h>
#include <math.h>

static const char *const fill_files[] = {"common.glsl", "stage_fill.glsl", NULL};

static void set_fill(const struct program_uniforms *p, const void *arg)
{
    (void)arg;
    glUniform4f(program_uniform(p, "u_fill0"), 0.0f, 0.0f, 0.0f, DEPTH_NO_HIT);
    glUniform4f(program_uniform(p, "u_fill1"), 0.0f, 0.0f, 0.0f, (float)DUMP_UNFINISHED);
}

static void set_camera(const struct program_uniforms *p, const void *arg)
{
    const struct renderer *r = arg;
    observer_set_uniforms(p, r);
    uniform_float(p, "u_step_size", r->scene->render.step_size);
    model_set_uniforms(p, &r->scene->model);
}

int stage_setup(struct renderer *r, struct error *e)
{
    struct raystate *rs = &r->rs;
    const struct stage_program *fill = program_cache_get(r->programs, fill_files, "", 1, e);
    if (!fill || pass_run(r, fill, rs->hit[0], rs->image[0], NULL, 0, set_fill, NULL, e) != 0)
        return -1;
    rs->cur_hit = 0;

    const char *const files[] = {"common.glsl", r->model_file, "observer.glsl", "stage_setup.glsl", NULL};
    char defines[sizeof r->model_defines + sizeof r->observer_defines];
    snprintf(defines, sizeof defines, "%s%s", r->model_defines, r->observer_defines);
    const struct stage_program *sp = program_cache_get(r->programs, files, defines, 1, e);
    if (!sp)
        return -1;
    if (pass_run(r, sp, rs->position[0], rs->velocity[0], NULL, 0, set_camera, r, e) != 0)
        return -1;
    rs->cur_position = 0;
    rs->cur_velocity = 0;
    return gl_check("ray setup", e);
}
