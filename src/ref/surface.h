/* The objects of a scene as surfaces that a curved ray crosses: a signed function g(x) that
 * changes sign on the surface (sphere: |x - c|^2 - r^2; flat primitives: distance from their
 * plane), the test whether a point of the plane lies on the primitive, and the shading
 * geometry (normal, texture coordinates) exactly as shaders_es/stage_intersect.glsl computes it. */
#ifndef BT_SURFACE_H
#define BT_SURFACE_H
#include "scene/scene.h"

struct surface {
    const struct object *object;
    int is_sphere;
    vec3d center;           /* sphere centre, or a point of the plane */
    double radius;
    vec3d normal;           /* unit normal of the plane (flat primitives) */
    double bound_radius;    /* a sphere about center that holds the whole primitive */
    int degenerate;         /* zero-area triangle or rectangle, zero normal: never hit */
};

void surface_init(struct surface *sf, const struct object *o);
/* Signed value whose zero set holds the surface; positive outside a sphere / on the normal's side. */
double surface_value(const struct surface *sf, vec3d x);
/* For a point p on the surface (g(p) = 0): does it belong to the primitive? */
int surface_contains(const struct surface *sf, vec3d p);
/* Normal and texture coordinates at a hit point p, as the intersect stage computes them. */
void surface_shading(const struct surface *sf, vec3d p, vec3d *normal, double uv[2]);

#endif
