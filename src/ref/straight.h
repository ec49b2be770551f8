/* Straight-line ray casting in double precision: the image the nonlinear tracer must give
 * when every field is off (flat space, zero mass, zero potential). */
#ifndef BT_STRAIGHT_H
#define BT_STRAIGHT_H
#include "scene/camera.h"
#include <stdint.h>

/* Where the point at fraction t of the straight segment a -> b (a: the camera) lies on object k's
 * rest-frame shape (the point itself for an object at rest): the event on the photon's path,
 * Poincaré transformed (docs/RELATIVITY.md), in the coordinates the object's keys are written in,
 * so that its scene geometry serves for intersection and shading alike. */
vec3d straight_rest_point(const struct scene *s, int k, vec3d a, vec3d b, double t);
/* Index of the object the segment a -> b (a: the camera) hits first, with its fraction t along the
 * segment, or -1. Moving objects are intersected in their rest frames. */
int straight_first_hit(const struct scene *s, vec3d a, vec3d b, double *t);
/* Object index hit first by each pixel's straight ray, or -1 (sky): width * height, top row first. */
void straight_cast(const struct scene *s, int32_t *ids);
/* The same with every object grown by the relative amount `growth` (negative: shrunk) about its
 * centre: pixels whose id changes between -e and +e lie within e of a silhouette, where float
 * rounding may decide the outcome. */
void straight_cast_grown(const struct scene *s, double growth, int32_t *ids);

#endif
