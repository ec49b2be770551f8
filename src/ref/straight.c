#include "ref/straight.h"
#include "physics/intersect.h"
#include "physics/relativity.h"
#include <math.h>
#include <stdlib.h>

vec3d straight_rest_point(const struct scene *s, int k, vec3d a, vec3d b, double t)
{
    struct object_motion m;
    vec3d p = v3_add(a, v3_scale(v3_sub(b, a), t));
    if (!object_motion(&s->objects[k], &m))
        return p;
    /* the photon passed p at scene time t_obs - |p - a|: light from the camera's past; the rest
     * frame's coordinates are placed back at the frame origin, where the object's keys put its
     * shape, so that its written geometry serves in both frames */
    return v3_add(rest_position(&m, s->observer.time - v3_len(v3_sub(p, a)), p), m.origin);
}

int straight_first_hit(const struct scene *s, vec3d a, vec3d b, double *t_hit)
{
    int best = -1;
    double best_t = INFINITY, t, p, q;
    for (int k = 0; k < s->n_objects; k++) {
        /* a moving object: the segment's end events in its rest frame; the fraction of a hit is
         * the same in both frames, since the Poincaré transformation is affine along the photon */
        const struct object *o = &s->objects[k];
        int moving = v3_dot(o->velocity, o->velocity) > 0.0;
        vec3d ra = moving ? straight_rest_point(s, k, a, b, 0.0) : a;
        vec3d rb = moving ? straight_rest_point(s, k, a, b, 1.0) : b;
        int found = 0;
        switch (o->type) {
        case PRIM_SPHERE: found = intersect_sphere(ra, rb, o->center, o->radius, &t); break;
        case PRIM_TRIANGLE: found = intersect_triangle(ra, rb, o->vertex[0], o->vertex[1], o->vertex[2], &t, &p, &q); break;
        case PRIM_DISK: found = intersect_disk(ra, rb, o->center, o->normal, o->inner_radius, o->radius, &t); break;
        case PRIM_RECT: found = intersect_rect(ra, rb, o->center, o->axis_u, o->axis_v, &t, &p, &q); break;
        default: break;
        }
        if (found && t < best_t) {
            best_t = t;
            best = k;
        }
    }
    if (t_hit)
        *t_hit = best_t;
    return best;
}

void straight_cast(const struct scene *s, int32_t *ids)
{
    /* one segment from the camera to beyond the far side of the bounding sphere */
    double reach = 2.0 * s->render.bound_radius + v3_len(v3_sub(s->camera.position, s->render.bound_center));
    for (int j = 0; j < s->render.height; j++)
        for (int i = 0; i < s->render.width; i++) {
            vec3d far = v3_axpy(reach, camera_ray(s, i, j), s->camera.position);
            ids[j * s->render.width + i] = straight_first_hit(s, s->camera.position, far, NULL);
        }
}

static vec3d grow_about(vec3d p, vec3d centre, double f)
{
    return v3_add(centre, v3_scale(v3_sub(p, centre), f));
}

void straight_cast_grown(const struct scene *s, double growth, int32_t *ids)
{
    struct scene *g = malloc(sizeof *g);
    if (!g)
        abort();
    *g = *s;
    double f = 1.0 + growth;
    for (int k = 0; k < g->n_objects; k++) {
        struct object *o = &g->objects[k];
        o->radius *= f;
        o->inner_radius /= f;
        o->axis_u = v3_scale(o->axis_u, f);
        o->axis_v = v3_scale(o->axis_v, f);
        vec3d centroid = v3_scale(v3_add(o->vertex[0], v3_add(o->vertex[1], o->vertex[2])), 1.0 / 3.0);
        for (int v = 0; v < 3; v++)
            o->vertex[v] = grow_about(o->vertex[v], centroid, f);
    }
    straight_cast(g, ids);
    free(g);
}
