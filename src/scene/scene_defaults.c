/* Values every scene starts from; a scene file only names what differs. The numbers are the ones
 * documented in docs/SCENES.md: change both together. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "scene/scene.h"
#include "physics/blackbody.h"
#include "physics/relativity.h"
#include "scene/scene_keys.h"

static void render_defaults(struct render_settings *r)
{
    r->polygon_subdivision = 16;
    r->width = 320;
    r->height = 240;
    r->method = METHOD_RK4;
    r->step_size = 0.05;
    r->steps_per_segment = 10;
    r->segments = 0;          /* derived from the path budget */
    r->max_path = 0.0;
    r->unfinished_color = v3(1.0, 0.0, 1.0);
    r->steps_per_pass = 10;
    r->bound_radius = 50.0;
    r->bound_center = v3(0.0, 0.0, 0.0);
    r->precision = PRECISION_AUTO;
    r->mrt = MRT_AUTO;
    r->early_z = 1;
    r->termination_interval = 1;
    r->batch = 8;
    r->step_control = STEP_FIXED;
    r->tolerance = 1e-4;
    r->grow_fraction = 1.0 / 32.0;
    r->step_min = 0.0;
    r->step_max = 0.0;
    r->far_step = 0.0;
    r->chord_tolerance = 1e-3;
    r->max_chords = 1000;
    r->orbit_rows = 512;
    r->orbit_columns = 128;
    r->pipeline = PIPELINE_AUTO;
    r->orbit_walk = ORBIT_WALK_AUTO;
    r->hit_shading = HIT_SHADING_AUTO;
    r->samples = 1;
    r->sky_alpha = 1.0;
    r->gain = 1.0;
    r->bloom_radius = 0.004;
    r->star_pass = STAR_PASS_AUTO;
}

void scene_default_method(struct scene *s)
{
    if (s->render.method_named)
        return;
    s->render.method = model_ops_of(s->model.type)->exact_orbits && s->render.step_control == STEP_FIXED
                           ? METHOD_ORBIT_TABLE : METHOD_RK4;
}

double render_step_min(const struct render_settings *r)
{
    return r->step_min > 0.0 ? r->step_min : r->step_size / 1024.0;
}

double render_step_max(const struct render_settings *r)
{
    return r->step_max > 0.0 ? r->step_max : r->step_size * 64.0;
}

int scene_far_steps(const struct scene *s)
{
    const struct render_settings *r = &s->render;
    double near = r->step_control == STEP_FIXED ? r->step_size : render_step_max(r);
    return !model_is_straight(&s->model) && r->method != METHOD_ORBIT_TABLE && r->far_step > near;
}

double render_requested_path(const struct render_settings *r)
{
    return r->max_path > 0.0 ? r->max_path : SCENE_PATH_BOUND_DIAMETERS * 2.0 * r->bound_radius;
}

double render_path_budget(const struct render_settings *r)
{
    /* fixed steps run whole segments: the path asked for, rounded up to them */
    if (r->step_control == STEP_FIXED)
        return (double)render_segments(r) * r->steps_per_segment * r->step_size;
    return render_requested_path(r);
}

long render_segments_needed(const struct render_settings *r)
{
    if (r->segments > 0)
        return r->segments;
    double per_segment = r->step_size * r->steps_per_segment;
    double n = ceil(render_requested_path(r) / per_segment);
    if (r->step_control != STEP_FIXED)
        n *= SCENE_ADAPTIVE_SEGMENT_MARGIN;
    /* the caller compares with SCENE_MAX_SEGMENTS: keep the count representable */
    return !(n < 1e15) ? (long)1e15 : n < 1.0 ? 1 : (long)n;
}

int render_segments(const struct render_settings *r)
{
    long n = render_segments_needed(r);
    return n > SCENE_MAX_SEGMENTS ? SCENE_MAX_SEGMENTS : (int)n;
}

void render_fix_segments(struct render_settings *r)
{
    r->segments = render_segments(r);
    if (r->step_control == STEP_FIXED)
        r->max_path = 0.0;
}

/* Parameters of every model are kept, not only the flat one's, so that switching model.type with
 * --set gives a working model without naming all its parameters. */
static void model_defaults(struct model *m)
{
    m->type = MODEL_FLAT;
    m->center = v3(0.0, 0.0, 0.0);
    m->scale = 1.0;
    m->strength = 1.0;
    /* Lorenz's classic chaotic parameters */
    m->sigma = 10.0;
    m->rho = 28.0;
    m->beta = 8.0 / 3.0;
    m->ross_a = 0.375;
    m->ross_b = 2.0;
    m->ross_c = 4.0;
    m->profile = PROFILE_YUKAWA;
    m->zeta = -1.0;      /* attractive */
    m->mu = 0.0;         /* unscreened: a Coulomb-like 1/r potential */
    m->radius = 5.0;
    m->amplitude = 0.05;
    m->shell_radius = 2.0;
    m->shell_width = 0.7;
    m->noise_amplitude = 0.5;
    m->noise_frequency = 3.0;
    m->mass = 1.0;
}

int observer_moving(const struct scene *s)
{
    return v3_dot(s->observer.velocity, s->observer.velocity) > 0.0;
}

int doppler_colour(const struct scene *s)
{
    return s->observer.effects != EFFECTS_GEOMETRY;
}

int scene_blackbody_tone(const struct scene *s)
{
    if (s->observer.effects != EFFECTS_SEARCHLIGHT)
        return TONE_LUMINANCE;
    if (s->observer.exposure == EXPOSURE_PAPER)
        return TONE_FIXED_1500K;
    /* the image's filmic curve takes the light as it is (results/tone.h) */
    return s->render.tone_curve == TONE_CURVE_FILMIC ? TONE_SCENE_LINEAR : TONE_SCENE;
}

double scene_reference_temperature(const struct scene *s)
{
    if (s->sky.temperature > 0.0)
        return s->sky.temperature;
    double hottest = 0.0;
    for (int i = 0; i < s->n_lights; i++)
        hottest = fmax(hottest, s->lights[i].temperature);
    for (int i = 0; i < s->n_objects && hottest == 0.0; i++)
        hottest = fmax(hottest, s->objects[i].material.temperature);
    return hottest;
}

/* The point an object's rest frame is placed by when no frame_origin is given. */
static vec3d reference_point(const struct object *o)
{
    if (o->type == PRIM_TRIANGLE)
        return v3_scale(v3_add(o->vertex[0], v3_add(o->vertex[1], o->vertex[2])), 1.0 / 3.0);
    return o->center;
}

int object_motion(const struct object *o, struct object_motion *m)
{
    if (!(v3_dot(o->velocity, o->velocity) > 0.0))
        return 0;
    m->beta = o->velocity;
    m->gamma = lorentz_gamma(o->velocity);
    m->origin = o->frame_origin_given ? o->frame_origin : reference_point(o);
    return 1;
}

void object_rest_geometry(const struct object *o, struct object *rest)
{
    *rest = *o;
    struct object_motion m;
    if (!object_motion(o, &m))
        return;
    rest->center = v3_sub(o->center, m.origin);
    for (int k = 0; k < 3; k++)
        rest->vertex[k] = v3_sub(o->vertex[k], m.origin);
}

int scene_has_black_body(const struct scene *s)
{
    int found = s->sky.temperature > 0.0 || s->sky.stars > 0 || s->sky.catalogue[0] || s->sky.milky_way > 0.0;
    for (int i = 0; i < s->n_lights; i++)
        found |= s->lights[i].temperature > 0.0;
    for (int i = 0; i < s->n_objects; i++)
        found |= s->objects[i].material.temperature > 0.0;
    return found;
}

int scene_has_moving_objects(const struct scene *s)
{
    struct object_motion m;
    for (int i = 0; i < s->n_objects; i++)
        if (object_motion(&s->objects[i], &m))
            return 1;
    return 0;
}

void scene_defaults(struct scene *s)
{
    memset(s, 0, sizeof *s);
    strcpy(s->dir, ".");
    strcpy(s->name, "untitled");
    s->camera.position = v3(0.0, 0.0, 10.0);
    s->camera.look_at = v3(0.0, 0.0, 0.0);
    s->camera.up = v3(0.0, 1.0, 0.0);
    s->camera.fov_deg = 60.0;
    render_defaults(&s->render);
    model_defaults(&s->model);
    s->sky.type = SKY_COLOR;
    s->sky.color = v3(0.02, 0.02, 0.05);
    s->sky.star_seed = 1;
    s->sky.star_brightness = 0.1;
    s->sky.star_size = 0.6;
    s->sky.galactic_pole = v3(0.25, 0.9, 0.35);
    s->sky.galactic_center = v3(0.0, 0.0, -1.0);
    s->ambient_light = v3(1.0, 1.0, 1.0);
    s->observer.gravitational_shift = 1;
    s->quality = (struct quality_bound){-1.0, -1.0, -1.0};
}

struct scene *scene_new(struct error *e)
{
    struct scene *s = calloc(1, sizeof *s);
    if (!s)
        error_set(e, ERROR_RUNTIME, NULL, "out of memory for a scene");
    return s;
}

void scene_free(struct scene *s)
{
    free(s);
}

void scene_object_defaults(struct object *o, const char *name)
{
    memset(o, 0, sizeof *o);
    strncpy(o->name, name, sizeof o->name - 1);
    o->type = PRIM_SPHERE;
    o->center = v3(0.0, 0.0, 0.0);
    o->radius = 1.0;
    o->inner_radius = 0.0;
    o->normal = v3(0.0, 1.0, 0.0);
    /* a 2 x 2 square in the x-z plane */
    o->axis_u = v3(1.0, 0.0, 0.0);
    o->axis_v = v3(0.0, 0.0, 1.0);
    o->vertex[0] = v3(0.0, 0.0, 0.0);
    o->vertex[1] = v3(1.0, 0.0, 0.0);
    o->vertex[2] = v3(0.0, 1.0, 0.0);
    o->uv[1][0] = 1.0;
    o->uv[2][1] = 1.0;
    o->pole = v3(0.0, 1.0, 0.0);
    o->material.color = v3(0.8, 0.8, 0.8);
    o->material.emission = v3(0.0, 0.0, 0.0);
    o->material.ambient = 0.2;
    o->material.diffuse = 0.8;
    o->material.specular = 0.3;
    o->material.shininess = 32.0;
    o->material.texture = -1;
    o->material.checker = 0.0;
    o->material.checker_color = v3(0.1, 0.1, 0.1);
}

void scene_light_defaults(struct light *l, const char *name)
{
    memset(l, 0, sizeof *l);
    strncpy(l->name, name, sizeof l->name - 1);
    /* above and behind the default camera, so a light that only sets its colour still lights
     * what the camera sees */
    l->position = v3(0.0, 10.0, 10.0);
    l->color = v3(1.0, 1.0, 1.0);
}
