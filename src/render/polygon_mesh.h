/* Tessellated surfaces of the primitives, for the polygon method of drawing moving objects (Müller,
 * Grottel and Weiskopf 2010, section 3.2): vertices in the object's rest frame with the normal and
 * texture coordinates the ray tracer computes at the same point, so that the two methods differ
 * only where the polygon method is an approximation. Pure C: the tests use it without GL. */
#ifndef BT_POLYGON_MESH_H
#define BT_POLYGON_MESH_H
#include <stdint.h>
#include "scene/scene.h"

struct mesh_vertex {
    float rest[3];     /* rest-frame position relative to the frame origin */
    float normal[3];
    float uv[2];
};

struct polygon_mesh {
    struct mesh_vertex *vertices;
    uint16_t *indices;  /* triangles */
    int n_vertices, n_indices;
};

/* The mesh of one object (its rest geometry, object_rest_geometry()), n segments along each edge
 * (1..SCENE_MAX_SUBDIVISION; a sphere has n rings and 2n sectors). 0, or -1 when out of memory. */
int polygon_mesh_build(const struct object *rest, int n, struct polygon_mesh *m);
void polygon_mesh_free(struct polygon_mesh *m);

#endif
