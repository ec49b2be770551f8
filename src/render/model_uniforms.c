/* Continuous parameters of the model reach the shaders as uniforms (no recompilation when a
 * knob turns); the model's type is a compile-time choice (see renderer.c). */
#include "render/stages.h"

void model_set_uniforms(const struct program_uniforms *p, const struct model *m)
{
    uniform_vec3(p, "u_model_center", m->center);
    uniform_float(p, "u_model_inv_scale", 1.0 / m->scale);   /* scale > 0 (scene_keys.c) */
    uniform_float(p, "u_model_strength", m->strength);
    glUniform3f(program_uniform(p, "u_lorenz"), (float)m->sigma, (float)m->rho, (float)m->beta);
    glUniform3f(program_uniform(p, "u_rossler"), (float)m->ross_a, (float)m->ross_b, (float)m->ross_c);
    glUniform2f(program_uniform(p, "u_yukawa"), (float)m->zeta, (float)m->mu);
    uniform_float(p, "u_poly_inv_radius", m->radius > 0.0 ? 1.0 / m->radius : 0.0);
    glUniform4f(program_uniform(p, "u_refraction"), (float)m->amplitude, (float)m->shell_radius,
                (float)m->shell_width, (float)m->noise_amplitude);
    uniform_float(p, "u_noise_frequency", m->noise_frequency);
    uniform_float(p, "u_mass", m->mass);
}

void bounds_set_uniforms(const struct program_uniforms *p, const struct scene *s)
{
    double capture = model_capture_radius(&s->model);
    uniform_vec3(p, "u_bound_center", s->render.bound_center);
    uniform_float(p, "u_bound_radius2", s->render.bound_radius * s->render.bound_radius);
    uniform_vec3(p, "u_capture_center", s->model.center);
    uniform_float(p, "u_capture_radius2", capture * capture);
}
