/* Checks that involve more than one key, run once the file and every --set have been applied
 * (a single key's range is checked when it is read). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "scene/scene.h"
#include "scene/scene_keys.h"
#include "physics/relativity.h"

/* Below this the up vector is taken as parallel to the view direction (sine of their angle). */
#define CAMERA_UP_MIN_SINE 1e-6

__attribute__((format(printf, 3, 4)))
static int invalid(const struct scene *s, struct error *err, const char *fmt, ...)
{
    va_list ap;
    err->status = ERROR_INPUT;
    snprintf(err->where, sizeof err->where, "%s", s->path[0] ? s->path : "scene");
    va_start(ap, fmt);
    vsnprintf(err->message, sizeof err->message, fmt, ap);
    va_end(ap);
    return -1;
}

/* v scaled by its largest component, so that lengths and products of tiny or huge vectors neither
 * underflow nor overflow (an up vector of 1e-200 is a direction, not a zero) */
static vec3d by_largest(vec3d v)
{
    double m = fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
    return m > 0.0 ? v3_scale(v, 1.0 / m) : v;
}

static int validate_camera(const struct scene *s, struct error *err)
{
    const struct camera *c = &s->camera;
    vec3d view = by_largest(v3_sub(c->look_at, c->position)), up = by_largest(c->up);
    double view_len = v3_len(view), up_len = v3_len(up);
    double from_bound = v3_len(v3_sub(c->position, s->render.bound_center));

    if (view_len == 0.0)
        return invalid(s, err, "camera position and look_at are the same point (%g %g %g): "
                       "the view direction is undefined", c->position.x, c->position.y, c->position.z);
    if (up_len == 0.0)
        return invalid(s, err, "camera up is (0 0 0): it gives no direction; choose an up vector across the "
                       "view direction");
    if (v3_len(v3_cross(view, up)) <= CAMERA_UP_MIN_SINE * view_len * up_len)
        return invalid(s, err, "camera up (%g %g %g) is parallel to the view direction: "
                       "choose an up vector across it", c->up.x, c->up.y, c->up.z);
    /* rays are followed only inside the bounding sphere: a camera outside it sees only sky */
    if (!(from_bound < s->render.bound_radius))
        return invalid(s, err, "the camera is %g from render.bound_center, outside the bounding "
                       "sphere of radius %g: enlarge render.bound_radius or move the camera",
                       from_bound, s->render.bound_radius);
    double horizon = model_capture_radius(&s->model);
    if (horizon > 0.0) {
        double r = v3_len(v3_sub(c->position, s->model.center));
        if (!(r > horizon))
            return invalid(s, err, "the camera is %g from the mass, inside the horizon radius "
                           "2M = %g: no light leaves it; move the camera out", r, horizon);
    }
    return 0;
}

static int validate_render(const struct scene *s, struct error *err)
{
    const struct render_settings *r = &s->render;
    /* the keys check each side as it is set; this catches scenes changed in code */
    if (r->width < 1 || r->height < 1 || r->width > SCENE_MAX_SIZE || r->height > SCENE_MAX_SIZE)
        return invalid(s, err, "the image is %dx%d; each side must be from 1 to %d pixels", r->width, r->height,
                       SCENE_MAX_SIZE);
    if ((long)r->width * r->height > SCENE_MAX_PIXELS)
        return invalid(s, err, "the image is %dx%d = %ld pixels; at most %ld pixels (width x height) are allowed",
                       r->width, r->height, (long)r->width * r->height, SCENE_MAX_PIXELS);
    /* a pass runs steps_per_pass steps, and a segment must end on a pass boundary for its
     * intersection test to see the whole segment */
    if (r->steps_per_segment % r->steps_per_pass != 0)
        return invalid(s, err, "render.steps_per_segment (%d) must be a multiple of "
                       "render.steps_per_pass (%d)", r->steps_per_segment, r->steps_per_pass);
    if (r->step_control == STEP_EMBEDDED && r->method != METHOD_DOPRI5)
        return invalid(s, err, "render.step_control = embedded needs render.method = dopri5 (the embedded "
                       "pair gives the error estimate); use step_control = doubling with %s",
                       method_name(r->method));
    const struct model_ops *ops = model_ops_of(s->model.type);
    if (r->method == METHOD_ORBIT_TABLE && !ops->exact_orbits && ops->integrates)
        return invalid(s, err, "render.method = orbit_table follows the exact orbits of Schwarzschild space; model %s "
                       "has none: use euler, rk4 or dopri5", model_name(s->model.type));
    if (r->method == METHOD_ORBIT_TABLE && r->step_control != STEP_FIXED)
        return invalid(s, err, "render.method = orbit_table takes no steps, so render.step_control must be fixed; "
                       "its chords are set by render.chord_tolerance");
    if (r->step_control == STEP_FIXED && r->segments > 0 && r->max_path > 0.0)
        return invalid(s, err, "render.segments = %d and render.max_path = %g both set the budget of fixed steps: "
                       "set one (render.segments = 0 derives the segments from max_path, render.max_path = 0 leaves the "
                       "budget to segments)", r->segments, r->max_path);
    long needed = render_segments_needed(r);
    /* flat space and exact orbits take no steps */
    if (r->method != METHOD_ORBIT_TABLE && ops->integrates && needed > SCENE_MAX_SEGMENTS)
        return invalid(s, err, "a path budget of %g (render.max_path%s) takes %ld segments of %d steps of %g, more "
                       "than the %d a frame may run: raise render.step or render.steps_per_segment, or lower "
                       "render.max_path", render_requested_path(r),
                       r->max_path > 0.0 ? "" : " 0: the default",
                       needed, r->steps_per_segment, r->step_size, SCENE_MAX_SEGMENTS);
    if (r->far_step > 0.0 && !(r->far_step < r->bound_radius))
        return invalid(s, err, "render.far_step (%g) must be shorter than the bounding sphere's radius "
                       "(render.bound_radius %g): a step across the scene is no step of its light", r->far_step,
                       r->bound_radius);
    double lo = render_step_min(r), hi = render_step_max(r);
    if (r->step_control != STEP_FIXED && !(lo <= r->step_size && r->step_size <= hi))
        return invalid(s, err, "render.step (%g) must lie within render.step_min (%g) and render.step_max (%g)",
                       r->step_size, lo, hi);
    return 0;
}

/* accretion = on: matter on circular orbits about the mass (physics/accretion.h) */
static int validate_accretion(const struct scene *s, const struct object *o, struct error *err)
{
    const struct model_ops *ops = model_ops_of(s->model.type);
    int schwarzschild = ops->gravity_mass != NULL;
    double mass = model_gravity_mass(&s->model);
    if (!schwarzschild && ops->integrates)
        return invalid(s, err, "[object %s]: accretion = on puts matter on orbits about a black hole; model %s has "
                       "none (model.type = schwarzschild, or flat, where the matter rests)", o->name,
                       model_name(s->model.type));
    if (!(o->material.temperature > 0.0))
        return invalid(s, err, "[object %s]: accretion = on needs the disk's hottest temperature: set temperature "
                       "(K)", o->name);
    if (v3_dot(o->velocity, o->velocity) > 0.0)
        return invalid(s, err, "[object %s]: an accretion disk's matter orbits the mass; it takes no velocity",
                       o->name);
    double off = v3_len(v3_sub(o->center, s->model.center));
    if (schwarzschild && !(off <= SCENE_ACCRETION_CENTRE_TOL * o->radius))
        return invalid(s, err, "[object %s]: an accretion disk orbits the mass: its center must be model.center "
                       "(it is %g away)", o->name, off);
    if (!(o->inner_radius > 3.0 * mass) || !(o->inner_radius > 0.0))
        return invalid(s, err, "[object %s]: accretion = on with inner_radius %g: matter orbits the mass only "
                       "beyond the photon sphere, 3M = %g, and stably beyond 6M = %g; raise inner_radius (above 0)",
                       o->name, o->inner_radius, 3.0 * mass, 6.0 * mass);
    return 0;
}

static int validate_objects(const struct scene *s, struct error *err)
{
    for (int i = 0; i < s->n_objects; i++) {
        const struct object *o = &s->objects[i];
        if (o->type == PRIM_RECT) {
            double cosine = v3_dot(o->axis_u, o->axis_v) / (v3_len(o->axis_u) * v3_len(o->axis_v));
            if (!(fabs(cosine) <= SCENE_RECT_ORTHO_TOL))
                return invalid(s, err, "[object %s]: axis_u and axis_v of a rect must be "
                               "orthogonal (the cosine of their angle is %g)", o->name, cosine);
        }
        double edge = 0.0;
        if (o->type == PRIM_RECT)
            edge = fmax(v3_len(o->axis_u), v3_len(o->axis_v));
        else if (o->type == PRIM_TRIANGLE)
            for (int k = 0; k < 3; k++)
                edge = fmax(edge, v3_len(v3_sub(o->vertex[(k + 1) % 3], o->vertex[k])));
        if (!(edge <= SCENE_MAX_FLAT_EDGE))
            return invalid(s, err, "[object %s]: a %s's %s is %g long; at most %g, as the GPU's 32-bit intersection of "
                           "flat primitives holds (docs/LIMITS.md): split it, or scale the scene down", o->name,
                           o->type == PRIM_RECT ? "rect" : "triangle", o->type == PRIM_RECT ? "axis" : "edge", edge,
                           SCENE_MAX_FLAT_EDGE);
        if (o->type == PRIM_DISK && !(o->inner_radius < o->radius)) {
            return invalid(s, err, "[object %s]: inner_radius (%g) must be smaller than radius (%g)",
                           o->name, o->inner_radius, o->radius);
        }
        double speed = v3_len(o->velocity);
        if (!(speed <= BETA_MAX))
            return invalid(s, err, "[object %s]: velocity has speed %g c; it must stay below %g c", o->name, speed,
                           BETA_MAX);
        if (o->material.clock_period > 0.0 && !model_is_straight(&s->model))
            return invalid(s, err, "[object %s] carries a clock, but light is bent here (model %s): clocks show "
                           "the light-travel time of straight rays, in flat space only", o->name,
                           model_name(s->model.type));
        if (speed > 0.0 && !model_is_straight(&s->model))
            return invalid(s, err, "[object %s] moves, but light is bent here (model %s): moving objects are "
                           "traced in flat space only", o->name, model_name(s->model.type));
        if (o->material.accretion && validate_accretion(s, o, err) != 0)
            return -1;
        if (o->material.texture >= s->n_textures)
            return invalid(s, err, "[object %s]: texture index %d, but the scene has %d textures",
                           o->name, o->material.texture, s->n_textures);
    }
    return 0;
}

static int validate_observer(const struct scene *s, struct error *err)
{
    double speed = v3_len(s->observer.velocity);
    if (!(speed <= BETA_MAX))
        return invalid(s, err, "observer.velocity has speed %g c; it must stay below %g c (gamma %.0f)", speed,
                       BETA_MAX, 1.0 / sqrt(1.0 - BETA_MAX * BETA_MAX));
    if (s->observer.effects != EFFECTS_GEOMETRY && !scene_has_black_body(s))
        return invalid(s, err, "observer.effects = %s colours black bodies, but nothing in the scene is one: "
                       "give [sky], a [light] or an emitting [object] a temperature (K)",
                       s->observer.effects == EFFECTS_DOPPLER ? "doppler" : "searchlight");
    return 0;
}

static double shadow_diameter_deg(double mass, double r)
{
    if (!(mass > 0.0))
        return 0.0;
    if (!(r > 2.0 * mass))
        return 360.0;
    /* the shadow's radius is measured from the direction to the centre: pi - the critical launch
     * angle, which is measured from the outward one */
    const double pi = 3.14159265358979323846;
    return 2.0 * (pi - orbit_critical_angle(mass, r)) * 180.0 / pi;
}

static double camera_radius(const struct scene *s)
{
    return v3_len(v3_sub(s->camera.position, s->model.center));
}

double scene_shadow_diameter_deg_at(const struct scene *s, double mass)
{
    /* the shadow of the orbits physics/orbit_table.h holds */
    if (!model_ops_of(s->model.type)->exact_orbits)
        return 0.0;
    return shadow_diameter_deg(mass, camera_radius(s));
}

double scene_shadow_diameter_deg(const struct scene *s)
{
    return scene_shadow_diameter_deg_at(s, s->model.mass);
}

double scene_mass_for_shadow(const struct scene *s, double diameter_deg)
{
    /* the shadow grows with the mass, from nothing to the whole sky at r = 2M: bisection */
    double r = camera_radius(s), lo = 0.0, hi = 0.5 * r;
    for (int i = 0; i < 200 && hi - lo > 1e-12 * r; i++) {
        double mid = 0.5 * (lo + hi);
        if (shadow_diameter_deg(mid, r) <= diameter_deg)
            lo = mid;
        else
            hi = mid;
    }
    /* rounded down to three significant digits: a value to write into a scene as it prints */
    if (!(lo > 0.0))
        return 0.0;
    double unit = pow(10.0, floor(log10(lo)) - 2.0);
    return floor(lo / unit) * unit;
}

/* [kiosk]: at both ends of a knob's range (the shadow grows with the mass and shrinks as the view
 * widens, so the ends bound it), a black hole's shadow fills at most SCENE_KIOSK_SHADOW_MAX_FRACTION
 * of the view's height. */
static int validate_knob_shadow(const struct scene *s, const char *knob, const struct knob_mapping *m,
                                const struct scene *trial, int at_max, double value, struct error *err)
{
    double across = scene_shadow_diameter_deg(trial);
    double limit = SCENE_KIOSK_SHADOW_MAX_FRACTION * trial->camera.fov_deg;
    if (!(across > limit))
        return 0;
    char hint[160] = "";
    if (strcmp(m->key, "model.mass") == 0)
        snprintf(hint, sizeof hint, "; with this camera and view, %s_max = %.3g keeps it within", knob,
                 scene_mass_for_shadow(trial, limit));
    if (across >= 360.0)
        return invalid(s, err, "[kiosk] %s_%s = %g puts the camera at or inside the black hole's horizon, where "
                       "everything is black%s", knob, at_max ? "max" : "min", value, hint);
    return invalid(s, err, "[kiosk] %s_%s = %g: the black hole's shadow would span %.0f degrees of the view's %g, "
                   "more than %.0f%% of its height: visitors would look at black%s", knob, at_max ? "max" : "min",
                   value, across, trial->camera.fov_deg, 100.0 * SCENE_KIOSK_SHADOW_MAX_FRACTION, hint);
}

/* [kiosk]: the knob's key set to either end of its range in TRIAL, a copy of s, is taken, and
 * keeps a black hole's shadow within the view. */
static int validate_knob_ends(const struct scene *s, const char *knob, const struct knob_mapping *m,
                              struct scene *trial, struct error *err)
{
    const double ends[2] = {m->min, m->max};
    for (int i = 0; i < 2; i++) {
        struct error e;
        *trial = *s;
        if (scene_set_number(trial, m->key, ends[i], &e) != 0)
            return invalid(s, err, "[kiosk] %s_%s = %g: %s", knob, i ? "max" : "min", ends[i], e.message);
        if (validate_knob_shadow(s, knob, m, trial, i, ends[i], err) != 0)
            return -1;
    }
    return 0;
}

/* [kiosk]: a knob mapped to a key names a number this scene has, over a range that the key takes
 * at both ends. */
static int validate_knob(const struct scene *s, const char *knob, const struct knob_mapping *m,
                         struct error *err)
{
    if (m->key[0] == '\0') {
        if (m->steps || m->min != 0.0 || m->max != 0.0)
            return invalid(s, err, "[kiosk] %s_min, %s_max and %s_steps need %s_key: the key the knob sets",
                           knob, knob, knob, knob);
        return 0;
    }
    double value;
    if (strncmp(m->key, "kiosk.", 6) == 0 || scene_get_number(s, m->key, &value) != 0)
        return invalid(s, err, "[kiosk] %s_key = %s: not a number of this scene (a key such as model.rho, as "
                       "--set names it)", knob, m->key);
    if (!(m->min < m->max))
        return invalid(s, err, "[kiosk] %s_min (%g) must be below %s_max (%g)", knob, m->min, knob, m->max);
    if (value < m->min || value > m->max)
        return invalid(s, err, "[kiosk] %s_key = %s: the scene's own value %g lies outside %s_min .. %s_max "
                       "(%g .. %g), where the knob could never bring it back", knob, m->key, value, knob, knob,
                       m->min, m->max);
    if (m->steps < 1)
        return invalid(s, err, "[kiosk] %s_steps: the detents from %s_min to %s_max, 1 to %d", knob, knob, knob,
                       SCENE_KIOSK_MAX_STEPS);
    struct scene *trial = scene_new(err);
    if (!trial)
        return -1;
    int rc = validate_knob_ends(s, knob, m, trial, err);
    scene_free(trial);
    return rc;
}

int scene_kiosk_validate(const struct scene *s, struct error *err)
{
    memset(err, 0, sizeof *err);
    return validate_knob(s, "speed", &s->kiosk.speed, err) || validate_knob(s, "mass", &s->kiosk.mass, err) ? -1 : 0;
}

int scene_validate(const struct scene *s, struct error *err)
{
    memset(err, 0, sizeof *err);
    if (validate_camera(s, err) || validate_observer(s, err) || validate_render(s, err) ||
        validate_objects(s, err))
        return -1;
    if (s->sky.type == SKY_CUBEMAP && s->sky.cubemap[0] == '\0')
        return invalid(s, err, "[sky] type is cubemap but no cubemap is given: add cubemap = PREFIX "
                       "(faces PREFIX_px.png ... PREFIX_nz.png)");
    if (s->sky.catalogue[0] && s->sky.stars > 0)
        return invalid(s, err, "[sky] stars = %d and catalogue = %s: the sky takes its stars from one of them, "
                       "the generated ones or the catalogue's", s->sky.stars, s->sky.catalogue);
    if (s->sky.catalogue_colours[0] && !s->sky.catalogue[0])
        return invalid(s, err, "[sky] catalogue_colours colours the stars of [sky] catalogue, which is not given");
    vec3d pole = v3_normalize(s->sky.galactic_pole), centre = v3_normalize(s->sky.galactic_center);
    if (v3_len(v3_cross(pole, centre)) < 1e-6)
        return invalid(s, err, "[sky] galactic_center lies along galactic_pole: it must point away from the pole, "
                       "toward the Milky Way's bulge in the galactic plane");
    return 0;
}
