/* The render path: which float format holds the ray state and whether one pass writes
 * several targets (MRT) or each target gets its own pass. */
#ifndef BT_PATH_H
#define BT_PATH_H
#include "gl/caps.h"
#include "scene/scene.h"

struct render_path {
    const struct float_format *format;
    int fp32;                 /* 0: fp16, reduced accuracy */
    int mrt;                  /* 1: x and v (and hit, image) written by one pass */
    const char *name;         /* "fp32+mrt", "fp32", "fp16+mrt", "fp16" */
    char description[160];
};

/* Pick the best path the context supports, or the one forced; -1 with err naming what is missing. */
int render_path_choose(const struct gl_caps *caps, enum precision_choice precision, enum mrt_choice mrt,
                       struct render_path *path, char *err, size_t errlen);

#endif
