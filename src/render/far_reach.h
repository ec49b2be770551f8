/* Where fixed steps may grow (render.far_step): the objects' bounds a ray's distance is measured
 * from. Each is a ball and, for a flat object, its plane: the point's distance from the object is at
 * least its distance from the ball and at least its distance from the plane. A scene with more
 * objects than a pass can hold bounds merges the two whose union's ball is the smallest until they
 * fit (a merged bound has no plane). The shader's far_step (shaders_es/stage_integrate.glsl) grows
 * the step with the smallest of those distances. */
#ifndef BT_FAR_REACH_H
#define BT_FAR_REACH_H
#include "scene/scene.h"

/* At most this many bounds (two uniform vectors each) */
#define FAR_REACH_MAX 4
/* A GPU with fewer fragment uniform vectors than this (GLES 2 promises 16) gets one bound, the
 * ball of every object */
#define FAR_REACH_ROOMY_VECS 128

/* The bounds of s's objects, at most `most` (1 to FAR_REACH_MAX): ball[k] the centre and radius,
 * normal[k] a flat bound's unit normal (0 for the others; w 0). Returns how many; 0 for a scene
 * without objects. */
int far_reach_pack(const struct scene *s, int most, float ball[][4], float normal[][4]);

#endif
