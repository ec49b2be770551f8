#include "scene/texture_wrap.h"

void texture_wraps(enum primitive_type type, int wraps[2])
{
    wraps[0] = type == PRIM_SPHERE;
    wraps[1] = type == PRIM_DISK;
}
