/* Exact ray-segment intersections in double precision for the CPU reference and the tests.
 * The segment runs from a to b; a hit is reported as t in [0, 1] with point a + t (b - a).
 * Each function returns 1 and the smallest such t, or 0 without touching its outputs.
 * shaders_es/prim_*.glsl are the float versions with the same semantics. */
#ifndef BT_INTERSECT_H
#define BT_INTERSECT_H
#include "physics/vec3.h"

/* Sphere of centre c: the first crossing of the surface, which for a segment starting inside is
 * where it leaves. Grazing segments (discriminant exactly 0) hit; a == b never hits. */
int intersect_sphere(vec3d a, vec3d b, vec3d c, double radius, double *t);

/* Triangle p0 p1 p2 (Moller-Trumbore). bary_u, bary_v weigh p1 and p2. Segments parallel to the
 * plane and triangles of zero area never hit. */
int intersect_triangle(vec3d a, vec3d b, vec3d p0, vec3d p1, vec3d p2,
                       double *t, double *bary_u, double *bary_v);

/* Annulus around c in the plane with the given normal (any length): inner_radius <= |p - c| <= outer_radius. */
int intersect_disk(vec3d a, vec3d b, vec3d c, vec3d normal, double inner_radius, double outer_radius,
                   double *t);

/* Rectangle c + s_u axis_u + s_v axis_v with s_u, s_v in [-1, 1]; axis_u, axis_v are orthogonal
 * half-edges. Reports s_u, s_v of the hit. */
int intersect_rect(vec3d a, vec3d b, vec3d c, vec3d axis_u, vec3d axis_v,
                   double *t, double *s_u, double *s_v);

#endif
