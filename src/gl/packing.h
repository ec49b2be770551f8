/* 32-bit floats in RGBA8 texels on the GPU (shaders_es/common.glsl, pack_float): the way to a ray state on a GPU
 * without float textures. Exact only where the fragment shaders compute in 32-bit floats, so the
 * probe runs it: floats unpacked, scaled and packed again must come back bit for bit. */
#ifndef BT_PACKING_H
#define BT_PACKING_H
#include "gl/caps.h"
#include <stdint.h>

/* side x side floats, as their IEEE 754 bits (in[y * side + x] the texel at x, y; high byte in r),
 * unpacked on the GPU, times factor, packed again and read back into out the same way. side a
 * power of two up to the GPU's largest texture. 0, or -1 where the program does not compile or
 * the target is incomplete (out left alone), with e. */
int gl_pack_round_trip(const struct shader_target *t, const uint32_t *in, int side, float factor,
                       uint32_t *out, struct error *e);

/* The bits x * factor has in 32-bit IEEE arithmetic as the packing gives them back: x unpacked (a
 * subnormal as zero, NaN as infinity of its sign), times factor. A product below the smallest
 * normal float comes back as zero of either sign (0 returned), or where the GPU rounds it up to
 * the smallest normal, that (*also: the magnitude allowed beside zero, 0 for none). */
uint32_t packed_product(uint32_t x, float factor, uint32_t *also);
/* Whether got, read back, is one packed_product allows (want, also). */
int packed_as_allowed(uint32_t got, uint32_t want, uint32_t also);

/* The packed layout of a float texture (shaders_es/common.glsl, unpack_block): texel (x, y) of a
 * width x height texture of four floats a texel is the 2x2 block of RGBA8 texels at (2x, 2y) of one
 * twice as wide and high, its x, y, z, w at (0, 0), (1, 0), (0, 1), (1, 1) of the block, each float's
 * IEEE 754 bytes high first. Both arrays row by row from row 0; bytes holds 16 * width * height. */
void packed_from_floats(const float *texels, int width, int height, unsigned char *bytes);
void packed_to_floats(const unsigned char *bytes, int width, int height, float *texels);

/* The probe: PACKING_PROBE_SIDE^2 floats of every exponent, once as they are and once times -2;
 * sets c->packing and c->packing_why (gl_caps_probe leaves them "not probed": no render path takes
 * the packing yet, and a probe costs every start a compile; bentray info runs it). */
#define PACKING_PROBE_SIDE 16
void probe_packing(struct gl_caps *c);

#endif
