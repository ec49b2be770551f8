/* render.method = orbit_table, single pass, where every object is flat and lies in a plane through
 * the mass (an accretion disk about the hole): shaders_es/stage_orbit_crossings.glsl meets each
 * object where the exact orbit crosses its plane, a constant number of table lookups a pixel,
 * instead of following the orbit chord by chord (stage_orbit_frame.glsl). Decided here, from the
 * scene in double; the shader trusts what this checks. */
#include "physics/relativity.h"
#include "render/stages.h"
#include "scene/object_bound.h"
#include <math.h>

/* How far (relative to the object's size and distance) a plane may pass from the mass and still
 * count as through it: roundings of a scene's own numbers (an accretion disk's centre may sit as
 * far from the mass, SCENE_ACCRETION_CENTRE_TOL), far below the shader's chord across each
 * crossing (CROSSING_CHORD of the radius there), which meets the object's own plane. */
#define CROSSING_PLANE_TOLERANCE 1e-9
/* The bounding sphere's centre on the mass: to roundings, relative to its radius. */
#define CROSSING_CENTRE_TOLERANCE 1e-12

int orbit_crossings_apply(const struct renderer *r)
{
    const struct scene *s = r->scene;
    if (!r->exact_orbits || s->n_objects < 1)
        return 0;
    vec3d mass = s->model.center;
    double bound = s->render.bound_radius;
    /* Every point of an orbit up to its hit must lie inside the bounding sphere, as the chord walk
     * requires of its chords' ends. With the sphere about the mass, the orbit's radius on its way
     * in stays below the camera's, and on its way out below the hit's: so the camera and every
     * object inside the sphere are enough. */
    if (v3_len(v3_sub(s->render.bound_center, mass)) > CROSSING_CENTRE_TOLERANCE * bound)
        return 0;
    if (!(v3_len(v3_sub(s->camera.position, mass)) < bound))
        return 0;
    struct object_motion motion;
    for (int i = 0; i < s->n_objects; i++) {
        const struct object *o = &s->objects[i];
        struct object_bound b;
        object_bound(o, &b);
        if (!b.flat || v3_len(b.normal) == 0.0 || object_motion(o, &motion))
            return 0;
        vec3d from_mass = v3_sub(b.centre, mass);
        double distance = v3_len(from_mass);
        if (fabs(v3_dot(b.normal, from_mass)) > CROSSING_PLANE_TOLERANCE * (distance + b.radius))
            return 0;
        if (!(distance + b.radius < bound))
            return 0;
    }
    return 1;
}

void orbit_crossings_set_uniforms(const struct program_uniforms *p, const struct renderer *r)
{
    const struct scene *s = r->scene;
    float normals[OBJECT_BATCH_MAX][3];
    int n = s->n_objects < OBJECT_BATCH_MAX ? s->n_objects : OBJECT_BATCH_MAX;
    for (int i = 0; i < n; i++) {
        struct object_bound b;
        object_bound(&s->objects[i], &b);
        normals[i][0] = (float)b.normal.x;
        normals[i][1] = (float)b.normal.y;
        normals[i][2] = (float)b.normal.z;
    }
    glUniform3fv(program_uniform(p, "u_crossing_normal"), n, &normals[0][0]);
}
