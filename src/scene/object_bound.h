/* The ball that holds an object and the plane of a flat one: what every cull bounds an object by
 * (the single pass's on the GPU, the orbit table's reach, the CPU reference's search for crossings),
 * written once. */
#ifndef BT_OBJECT_BOUND_H
#define BT_OBJECT_BOUND_H
#include "scene/scene.h"

struct object_bound {
    vec3d centre;     /* a sphere's, disk's or rectangle's centre; a triangle's centroid */
    double radius;    /* from the centre to the object's farthest point */
    vec3d normal;     /* a flat object's unit normal; 0 for a sphere and for a degenerate flat one */
    int flat;         /* a disk, rectangle or triangle: it lies in the plane through centre */
};

/* The bound of o as it is written (its rest frame, for an object that moves). */
void object_bound(const struct object *o, struct object_bound *b);

#endif
