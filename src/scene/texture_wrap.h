/* Which texture coordinate of a primitive goes round: the sphere's longitude (s) and the disk's
 * angle (t) meet themselves where the angle passes pi, so the texels at the two ends of that
 * coordinate are neighbours there, and a texture is filtered across the seam as GL_REPEAT would
 * (ES 2.0 allows GL_REPEAT only for power-of-two sizes). Rectangles and triangles map onto their
 * texture without wrapping. */
#ifndef BT_TEXTURE_WRAP_H
#define BT_TEXTURE_WRAP_H
#include "scene/scene.h"

/* wraps[0]: s goes round, wraps[1]: t goes round (1 or 0). */
void texture_wraps(enum primitive_type type, int wraps[2]);

#endif
