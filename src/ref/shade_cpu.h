/* Colour of a traced ray on the CPU, computed as shaders_es/shade.glsl and sky_colour.glsl compute
 * it: the same material model, bilinear texture filtering with clamped edges, cube-map face
 * selection of the GL specification, and the same rounding to 8 bits. */
#ifndef BT_SHADE_CPU_H
#define BT_SHADE_CPU_H
#include "io/error.h"
#include "ref/reference.h"
#include <stddef.h>

struct cpu_texture {
    int width, height;
    unsigned char *rgba;          /* top row first, as read from the PNG (= t = 0 row in GL) */
};

struct cpu_materials {
    const struct scene *scene;
    struct cpu_texture textures[SCENE_MAX_TEXTURES];
    struct cpu_texture sky[6];    /* +x, -x, +y, -y, +z, -z */
    int has_sky_cubemap;
    struct cpu_texture blackbody; /* the GPU's black-body table (Doppler colour effects only) */
    int blackbody_linear;         /* the table is TONE_SCENE_LINEAR's (blackbody_lut_decode) */
};

/* Load the scene's textures and sky faces. 0, or -1 with e: the PNG reader's error, naming the file
 * in its message (a file refused or not a PNG is the user's), or out of memory (the machine's). */
int cpu_materials_load(struct cpu_materials *mat, const struct scene *s, struct error *e);
void cpu_materials_free(struct cpu_materials *mat);
/* The same colour unclamped above 1 (sRGB-encoded, as the GPU's float target holds it) and its alpha. */
void cpu_shade_color(const struct cpu_materials *mat, const struct ref_ray *ray, vec3d view, double rgba[4]);

#endif
