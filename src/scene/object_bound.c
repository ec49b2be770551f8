/* The bounding ball and plane of an object (object_bound.h). */
#include "scene/object_bound.h"
#include <math.h>

/* n made unit, or 0 where it has no length (a degenerate flat object) */
static vec3d unit_or_zero(vec3d n)
{
    double len = v3_len(n);
    return len > 0.0 ? v3_scale(n, 1.0 / len) : v3(0.0, 0.0, 0.0);
}

void object_bound(const struct object *o, struct object_bound *b)
{
    b->centre = o->center;
    b->radius = o->radius;
    b->normal = v3(0.0, 0.0, 0.0);
    b->flat = 1;
    switch (o->type) {
    case PRIM_SPHERE:
        b->flat = 0;
        break;
    case PRIM_DISK:
        b->normal = unit_or_zero(o->normal);
        break;
    case PRIM_RECT:
        /* the corners centre +- u +- v: the two half-diagonals, equal where u and v are orthogonal */
        b->radius = fmax(v3_len(v3_add(o->axis_u, o->axis_v)), v3_len(v3_sub(o->axis_u, o->axis_v)));
        b->normal = unit_or_zero(v3_cross(o->axis_u, o->axis_v));
        break;
    case PRIM_TRIANGLE:
    default:
        b->centre = v3_scale(v3_add(o->vertex[0], v3_add(o->vertex[1], o->vertex[2])), 1.0 / 3.0);
        b->radius = 0.0;
        for (int k = 0; k < 3; k++)
            b->radius = fmax(b->radius, v3_len(v3_sub(o->vertex[k], b->centre)));
        b->normal = unit_or_zero(v3_cross(v3_sub(o->vertex[1], o->vertex[0]), v3_sub(o->vertex[2], o->vertex[0])));
        break;
    }
}
