/* The star map the GPU draws the point stars of the sky from, in the frame's own pass
 * (shaders_es/sky_colour.glsl, GPU_STARS; `[render] star_pass = gpu`, and always in the kiosk): the
 * same stars, flux, magnification and colours as the CPU's pass (results/star_light.h), which stays
 * the reference the GPU's is tested against.
 *
 * - The sky's directions are laid out on the octahedral map (the unit square; every direction one
 *   point, its border folded onto itself: u = 0 meets u = 0 with v mirrored, and so on), split into
 *   cells of STAR_MAP_CELLS a side. A cell holds at most STAR_MAP_SLOTS stars: where more fall into
 *   one, the brightest (the others are counted in `dropped`).
 * - Coarser levels: cells of 2x2, 4x4 ... of the first, each again the brightest stars of its
 *   block, down to 4 cells a side. A pixel looks up the level whose cells are as wide as the
 *   light of the brightest star reaches from it (its footprint, from the derivatives of its exit
 *   direction), and there the 3x3 cells about its direction, whatever the number of stars: each
 *   cell has a mask of which of the 3x3 about it hold a star, and the pass reads the mask and
 *   then only those cells.
 * - One RGBA8 texture, two texels a star side by side, STAR_MAP_SLOTS stars a cell, brightest
 *   first: the star's place in its cell (16 bits in u,
 *   16 in v), then its magnitude (16 bits over [brightest, faintest]), its temperature (8 bits
 *   over ln T, STAR_CHROMA_TEXELS steps from BLACKBODY_T_MIN_K to BLACKBODY_T_MAX_K) and whether
 *   the cell holds a star. Level 0 fills rows 0 .. N-1; the coarser levels lie side by side in the
 *   rows below; the last row holds the colours of black bodies per unit luminance over ln T
 *   (star_chromaticity), each as RGB over its largest component (the shader divides by the
 *   luminance again). Below it, one texel a cell, the masks: bit 8 - k (R the low 8 bits, G the
 *   ninth) set where cell k of the 3x3 about the cell (k = 3 dy + dx from its lower-left
 *   neighbour, folded across the square's border as the pass folds it) holds a star; level 0 at
 *   x = 0, each coarser level beside the last. */
#ifndef BT_STAR_MAP_H
#define BT_STAR_MAP_H
#include "physics/star_catalogue.h"

/* cells a side at level 0: about 0.4 degrees a cell; a pixel of a 4K frame 60 degrees wide reaches
 * less than that */
#define STAR_MAP_CELLS 512
/* stars a cell can hold: with two, a kiosk frame of the 9096 stars of the real sky (a level of
 * 256 cells a side at 720p) keeps all but a few in a thousand */
#define STAR_MAP_SLOTS 2
#define STAR_MAP_MIN_CELLS 4
#define STAR_MAP_LEVELS_MAX 16
#define STAR_CHROMA_TEXELS 256

struct star_map {
    int cells;                   /* cells a side at level 0 */
    int levels;
    int level_x[STAR_MAP_LEVELS_MAX], level_y[STAR_MAP_LEVELS_MAX];   /* each level's first texel */
    int chroma_y;                /* the colours' row */
    int mask_x[STAR_MAP_LEVELS_MAX], mask_y;   /* each level's first mask texel */
    int width, height;           /* texels */
    unsigned char *texels;       /* RGBA8, rows from the first */
    double faintest, brightest;  /* magnitudes: the 16-bit encoding's ends */
    int stars, dropped;          /* stars placed at level 0, and those a brighter one displaced */
};

/* The octahedral map of unit vector d: (u, v) in [0, 1]^2; and back (any (u, v) of the square). */
void octahedral_encode(vec3d d, double *u, double *v);
vec3d octahedral_decode(double u, double v);

/* The map of catalogue c with `cells` cells a side at level 0 (a power of two, at least
 * STAR_CHROMA_TEXELS / (2 STAR_MAP_SLOTS), so that the colours' row fits). 0, or -1 when out of
 * memory. */
int star_map_build(struct star_map *m, const struct star_catalogue *c, int cells);
void star_map_free(struct star_map *m);

#endif
