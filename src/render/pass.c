/* One pass: a viewport-filling quad drawn into the ray-state targets. */
#include "render/stages.h"
#include "gl/quad.h"
#include "io/clock.h"
#include <stdio.h>

void uniform_vec3(const struct program_uniforms *program, const char *name, vec3d v)
{
    glUniform3f(program_uniform(program, name), (float)v.x, (float)v.y, (float)v.z);
}

void uniform_float(const struct program_uniforms *program, const char *name, double v)
{
    glUniform1f(program_uniform(program, name), (float)v);
}

int pass_move_rays(struct renderer *r, const struct stage_program *sp, int segment_start, set_uniforms_fn set_uniforms,
                   const void *arg, struct error *e)
{
    struct raystate *rs = &r->rs;
    /* write to the one position copy that is neither the segment start nor the current one */
    int out_pos = 0;
    while (out_pos == segment_start || out_pos == rs->cur_position)
        out_pos++;
    int out_vel = 1 - rs->cur_velocity;
    struct pass_input in[] = {
        {"u_ray_position", rs->position[rs->cur_position]},
        {"u_ray_velocity", rs->velocity[rs->cur_velocity]},
        {"u_hit", rs->hit[rs->cur_hit]},
    };
    if (pass_run(r, sp, rs->position[out_pos], rs->velocity[out_vel], in, 3, set_uniforms, arg, e) != 0)
        return -1;
    rs->cur_position = out_pos;
    rs->cur_velocity = out_vel;
    return 0;
}

int pass_early_z_begin(struct renderer *r, GLuint target, struct error *e)
{
    GLuint fbo = raystate_fbo(&r->rs, target, 0, e);
    if (!fbo)
        return -1;
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glDepthMask(GL_TRUE);
    glClearDepthf(1.0f);
    glClear(GL_DEPTH_BUFFER_BIT);
    glDepthMask(GL_FALSE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    return 0;
}

int pass_run(struct renderer *r, const struct stage_program *sp, GLuint out0, GLuint out1,
             const struct pass_input *inputs, int n_inputs, set_uniforms_fn set_uniforms, const void *arg,
             struct error *e)
{
    const GLuint out[RAYSTATE_MAX_TARGETS] = {out0, out1, 0, 0};
    return pass_run_targets(r, sp, out, inputs, n_inputs, set_uniforms, arg, e);
}

double pass_draw_begin(struct renderer *r, GLuint program)
{
    if (!r->time_first_draws)
        return -1.0;
    for (int i = 0; i < r->n_drawn; i++)
        if (r->drawn[i] == program)
            return -1.0;
    if (r->n_drawn == RENDERER_DRAWN_MAX)
        return -1.0;
    r->drawn[r->n_drawn++] = program;
    glFinish();
    return clock_seconds();
}

void pass_draw_end(struct renderer *r, double began)
{
    if (began >= 0.0)
        r->compile_seconds += clock_seconds() - began;
}

int pass_run_targets(struct renderer *r, const struct stage_program *sp, const GLuint out[RAYSTATE_MAX_TARGETS],
                     const struct pass_input *inputs, int n_inputs, set_uniforms_fn set_uniforms, const void *arg,
                     struct error *e)
{
    struct raystate *rs = &r->rs;
    for (int k = 0; k < sp->n_programs; k++) {
        GLuint fbo;
        if (sp->n_programs == 1)
            fbo = raystate_fbo_targets(rs, out, e);
        else
            fbo = raystate_fbo(rs, out[k], 0, e);
        if (!fbo)
            return -1;
        const struct program_uniforms *prog = &sp->program[k];
        /* the target's size: on the packed path, a float target's fragments are the four texels of
         * each ray's block (u_pixel_scale 0.5) and every float texture read is that size too */
        int w, h, state_w, state_h;
        raystate_texture_size(rs, out[k], &w, &h);
        raystate_texture_size(rs, rs->position[0], &state_w, &state_h);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glViewport(0, 0, w, h);
        glUseProgram(prog->id);
        glUniform2f(program_uniform(prog, "u_inv_size"), 1.0f / (float)state_w, 1.0f / (float)state_h);
        if (rs->packed)
            glUniform1f(program_uniform(prog, "u_pixel_scale"), w == rs->width ? 1.0f : 0.5f);
        for (int i = 0; i < n_inputs; i++) {
            if (raystate_storage(rs, inputs[i].texture, e) != 0)
                return -1;
            glActiveTexture(GL_TEXTURE0 + i);
            glBindTexture(GL_TEXTURE_2D, inputs[i].texture);
            glUniform1i(program_uniform(prog, inputs[i].sampler), i);
        }
        if (set_uniforms)
            set_uniforms(prog, arg);
        if (r->depth_write_last)
            glDepthMask(k == sp->n_programs - 1 ? GL_TRUE : GL_FALSE);
        double first = pass_draw_begin(r, prog->id);
        quad_draw(prog->id, r->quad_z);
        pass_draw_end(r, first);
        if (r->depth_write_last)
            glDepthMask(GL_FALSE);
        r->passes++;
    }
    return 0;
}
