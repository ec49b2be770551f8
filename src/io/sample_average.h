/* The average of a pixel's samples in linear light (render.samples): images hold sRGB-encoded values
 * (as the textures and sky they come from do), so each sample is decoded to linear light, summed, and
 * the mean encoded again; averaging the encoded values instead would darken every edge between a
 * bright and a dark surface. Colours are weighted by their alpha (render.sky_alpha), so that a
 * transparent sky does not bleed into an object's edge; where every sample is transparent the plain
 * mean is kept. Both engines average through pixel_average, so the same samples give the same bits. */
#ifndef BT_SAMPLE_AVERAGE_H
#define BT_SAMPLE_AVERAGE_H
#include <stddef.h>

/* The sRGB transfer function and its inverse: on [0, 1], and beyond 1 along the same curve (colours
 * brighter than white in a float image). linear_to_srgb clamps to [0, 1]. */
double srgb_to_linear(double encoded);
double linear_to_srgb(double linear);
double linear_to_srgb_unclamped(double linear);

/* One pixel's running sums. */
struct pixel_average {
    double premultiplied[3];   /* linear colour times alpha */
    double alpha;
    double plain[3];           /* linear colour */
};

/* Add a sample: its sRGB-encoded colour (0..1, or above for a float image) and alpha. */
void pixel_average_add(struct pixel_average *p, const double encoded[3], double alpha);
/* The mean of n samples, sRGB-encoded (unclamped) and its alpha. */
void pixel_average_mean(const struct pixel_average *p, int n, double encoded[3], double *alpha);

/* A whole image of them. */
struct sample_average {
    size_t pixels;
    int count;                 /* images added */
    struct pixel_average *sum;
};

/* 0, or -1 when out of memory. */
int sample_average_init(struct sample_average *a, size_t pixels);
/* Add one image of a.pixels RGBA8 pixels; with color (RGBA floats, the same unclamped; may be NULL)
 * its values are summed instead. */
void sample_average_add(struct sample_average *a, const unsigned char *rgba, const float *color);
/* The mean so far into rgba (RGBA8) and, where not NULL, color (RGBA floats); nothing when no image
 * was added. */
void sample_average_write(const struct sample_average *a, unsigned char *rgba, float *color);
void sample_average_free(struct sample_average *a);

/* Root mean square difference of two RGBA8 images in linear light (0 to 1), over the colour
 * channels: the error measure of anti-aliasing (bench, tests). */
double image_rms_linear(const unsigned char *a, const unsigned char *b, size_t pixels);

/* The 8-bit code of an sRGB-encoded value, clamped, rounded to nearest (as GL stores a float in RGBA8). */
unsigned char unorm8(double encoded);

#endif
