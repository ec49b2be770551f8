/* Bloom ([render] bloom, bloom_radius): the glare that a camera's lens or an eye adds around very
 * bright light. Light is not thresholded: a fraction `bloom` of every pixel's linear light is
 * spread by a point-spread function and the rest stays where it fell, so the light of the image is
 * kept (away from its edges) and only what is far brighter than its surroundings shows a halo. The
 * point-spread is the sum of BLOOM_LEVELS Gaussians of equal weight whose widths double, the
 * narrowest sigma = bloom_radius times the image's height: between the narrowest and the widest it
 * falls about as 1 / r^2, as the glare of an eye (Spencer, Shirley, Zimmerman, Greenberg,
 * "Physically-based glare effects for digital images", SIGGRAPH 1995) and of a lens with a little
 * scatter. Each Gaussian is drawn on the image of a pyramid (each 2 times coarser than the one
 * before) where it is still at least a pixel wide, and interpolated back bilinearly: the image is
 * shared into the coarse one by the transpose of that interpolation, so a point of light keeps
 * its centre and its light, and the blur there is narrowed by the two steps' own widening, so the
 * sum has each Gaussian's variance. A point's halo then departs from a circle by a few percent
 * where it meets the coarse grids at another phase (tests/unit/test_bloom.c). Near an image's edge
 * the taps inside it are weighted to sum to 1, so an evenly lit image stays even up to its edges.
 *
 * Both engines apply it the same way, on the CPU, to the frame's colour after its samples are
 * averaged and the stars of the sky added, before the gain and tone curve (results/tone.h) and the
 * 8-bit code; so the GPU's frame is read as floats where bloom is on. Images of floats (16-bit PNG,
 * PFM) keep the light as traced, as for the gain and the curve. The kiosk draws no bloom (its log
 * says so). */
#ifndef BT_BLOOM_H
#define BT_BLOOM_H
#include "scene/scene.h"

#define BLOOM_LEVELS 5

/* Whether the settings ask for bloom (render.bloom above 0). */
int bloom_active(const struct render_settings *r);
/* The sigmas of the point-spread's Gaussians for an image `height` rows high, pixels. */
void bloom_sigmas(const struct render_settings *r, int height, double sigma[BLOOM_LEVELS]);
/* The bloomed linear light of an image: in, w*h pixels of 3 linear floats; out the same (may not
 * be in). 0, or -1 when out of memory. */
int bloom_linear(const struct render_settings *r, int w, int h, const float *in, float *out);
/* A frame's 8-bit image: color, w*h RGBA floats as the engines hold them (sRGB-encoded, unclamped;
 * render_result.color) through the bloom (none where render.bloom is 0), the gain and the tone
 * curve into rgba (alpha from color, clamped). color is not changed. 0, or -1 when out of memory. */
int bloom_image(const struct render_settings *r, int w, int h, const float *color, unsigned char *rgba);

#endif
