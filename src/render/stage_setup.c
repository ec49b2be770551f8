/* Stage 1, ray setup (paper section 3.1): hit and image start as "no hit", positions at the
 * camera, velocities from the pinhole camera through the model's initial-velocity map. */
#include "render/stages.h"
#include <stdio.h>
#include <math.h>

static const char *const fill_files[] = {"common.glsl", "stage_fill.glsl", NULL};

struct setup_args {
    const struct scene *scene;
    vec3d forward, right, up;
    double origin_x, origin_y;
};

static void set_fill(GLuint p, const void *arg)
{
    (void)arg;
    glUniform4f(glGetUniformLocation(p, "u_fill0"), 0.0f, 0.0f, 0.0f, DEPTH_NO_HIT);
    glUniform4f(glGetUniformLocation(p, "u_fill1"), 0.0f, 0.0f, 0.0f, (float)OUTCOME_UNFINISHED);
}

static void set_camera(GLuint p, const void *arg)
{
    const struct setup_args *a = arg;
    const struct scene *s = a->scene;
    uniform_vec3(p, "u_camera_position", s->camera.position);
    uniform_vec3(p, "u_camera_forward", a->forward);
    uniform_vec3(p, "u_camera_right", a->right);
    uniform_vec3(p, "u_camera_up", a->up);
    glUniform2f(glGetUniformLocation(p, "u_pixel_origin"), (float)a->origin_x, (float)a->origin_y);
    glUniform2f(glGetUniformLocation(p, "u_image_size"), (float)s->render.width, (float)s->render.height);
    uniform_float(p, "u_step_size", s->render.step_size);
    model_set_uniforms(p, &s->model);
}

int stage_setup(struct renderer *r, int origin_x, int origin_y, char *err, size_t errlen)
{
    const struct scene *s = r->scene;
    struct raystate *rs = &r->rs;
    const struct stage_program *fill = program_cache_get(&r->programs, fill_files, "", 1, err, errlen);
    if (!fill || pass_run(r, fill, rs->hit[0], rs->image[0], NULL, 0, set_fill, NULL, err, errlen) != 0)
        return -1;
    rs->cur_hit = 0;

    const char *const files[] = {"common.glsl", r->model_file, "stage_setup.glsl", NULL};
    const struct stage_program *sp = program_cache_get(&r->programs, files, r->model_defines, 1, err, errlen);
    if (!sp)
        return -1;
    struct setup_args a;
    a.scene = s;
    a.forward = v3_normalize(v3_sub(s->camera.look_at, s->camera.position));
    vec3d right = v3_normalize(v3_cross(a.forward, s->camera.up));
    vec3d up = v3_cross(right, a.forward);
    double tan_half = tan(s->camera.fov_deg * PI_D / 360.0);
    double aspect = (double)s->render.width / (double)s->render.height;
    a.right = v3_scale(right, tan_half * aspect);
    a.up = v3_scale(up, tan_half);
    a.origin_x = origin_x;
    a.origin_y = origin_y;
    if (pass_run(r, sp, rs->position[0], rs->velocity[0], NULL, 0, set_camera, &a, err, errlen) != 0)
        return -1;
    rs->cur_position = 0;
    rs->cur_velocity = 0;
    return gl_check("ray setup", err, errlen);
}
