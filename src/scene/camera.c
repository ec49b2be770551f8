#include "scene/camera.h"
#include "physics/relativity.h"
#include <math.h>

vec3d camera_view_direction(const struct scene *s, int i, int j)
{
    return camera_view_direction_at(s, i, j, 0.0, 0.0);
}

void camera_frame_make(const struct scene *s, struct camera_frame *f)
{
    const struct camera *c = &s->camera;
    f->scene = s;
    f->forward = v3_normalize(v3_sub(c->look_at, c->position));
    f->right = v3_normalize(v3_cross(f->forward, c->up));
    f->up = v3_cross(f->right, f->forward);
    f->tan_half = tan(c->fov_deg * PI_D / 360.0);
    f->moving = observer_moving(s);
}

vec3d camera_frame_view(const struct camera_frame *f, int i, int j, double dx, double dy)
{
    int w = f->scene->render.width, h = f->scene->render.height;
    double ndc_x = ((i + 0.5 + dx) / w) * 2.0 - 1.0;
    double ndc_y = ((h - 1 - j + 0.5 + dy) / h) * 2.0 - 1.0;   /* image rows run top-down, GL rows bottom-up */
    vec3d d = v3_add(f->forward, v3_add(v3_scale(f->right, ndc_x * f->tan_half * w / h), v3_scale(f->up, ndc_y * f->tan_half)));
    return v3_normalize(d);
}

vec3d camera_frame_ray(const struct camera_frame *f, int i, int j, double dx, double dy)
{
    vec3d d = camera_frame_view(f, i, j, dx, dy);
    return f->moving ? v3_normalize(aberrate_to_scene(f->scene->observer.velocity, d)) : d;
}

vec3d camera_view_direction_at(const struct scene *s, int i, int j, double dx, double dy)
{
    struct camera_frame f;
    camera_frame_make(s, &f);
    return camera_frame_view(&f, i, j, dx, dy);
}

vec3d camera_ray(const struct scene *s, int i, int j)
{
    return camera_ray_at(s, i, j, 0.0, 0.0);
}

vec3d camera_ray_at(const struct scene *s, int i, int j, double dx, double dy)
{
    struct camera_frame f;
    camera_frame_make(s, &f);
    return camera_frame_ray(&f, i, j, dx, dy);
}

double static_lapse(const struct scene *s, vec3d p)
{
    double mass = model_gravity_mass(&s->model);
    if (mass == 0.0)
        return 1.0;
    double r = fmax(v3_len(v3_sub(p, s->model.center)), 1e-9);
    return sqrt(fmax(1.0 - 2.0 * mass / r, 0.0));
}

double static_lapse_shown(const struct scene *s, vec3d p)
{
    return s->observer.gravitational_shift ? static_lapse(s, p) : 1.0;
}

double emitted_ratio_shown(const struct scene *s, vec3d p, double ratio)
{
    double lapse = static_lapse(s, p);
    return s->observer.gravitational_shift || lapse <= 0.0 ? ratio : ratio / lapse;
}

double camera_doppler(const struct scene *s, vec3d view)
{
    return doppler_observer(s->observer.velocity, view) / static_lapse_shown(s, s->camera.position);
}
