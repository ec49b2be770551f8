/* Where a pixel's rays start when render.samples = N > 1: N points in the pixel square, the same on
 * both engines, so that the GPU image and the CPU reference average the same rays.
 *
 * Every pattern puts one point in each of the N columns and each of the N rows of an N x N grid of
 * the pixel (n-rooks: an edge close to horizontal or vertical is resolved in N levels), at the
 * centres of those slices, and is symmetric about the pixel's centre (no bias: the average is the
 * box filter's). For N = m^2 it is also stratified on the m x m grid: cell (i, j) holds the point
 * of column i m + j and row j m + (m - 1 - i), a rotated grid (for N = 4 the familiar RGSS pattern).
 * Other N take the rank-1 lattice (k, g k + c mod N) whose generator g keeps its points farthest
 * apart. The centre itself is a point exactly when N is odd; the dump, `bentray trace` and
 * `bentray error` always follow the centre's ray, traced besides the N when N is even.
 * Offsets are multiples of 1/PIXEL_SAMPLE_GRID of a pixel, so that a pixel's coordinate plus its
 * offset is exact in a 32-bit float up to 16384 pixels and both engines aim at the same point. */
#ifndef BT_PIXEL_SAMPLES_H
#define BT_PIXEL_SAMPLES_H
#include "scene/scene.h"

#define PIXEL_SAMPLE_GRID 1024

struct pixel_samples {
    int n;
    int centre_included;      /* the centre is sample 0 */
    double dx[SCENE_MAX_SAMPLES], dy[SCENE_MAX_SAMPLES];   /* pixels from the centre, dy up */
};

/* The pattern of n samples (1 <= n <= SCENE_MAX_SAMPLES; anything else gives the centre alone). */
void pixel_samples_make(int n, struct pixel_samples *out);

#endif
