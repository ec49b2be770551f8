/* The average of a pixel's samples in linear light (render.samples): images hold sRGB-encoded 8-bit
 * values (as the textures and sky they come from do), so each sample is decoded to linear light,
 * summed, and the mean encoded again. Averaging the encoded values instead would darken every
 * edge between a bright and a dark surface. */
#ifndef BT_SAMPLE_AVERAGE_H
#define BT_SAMPLE_AVERAGE_H
#include <stddef.h>

struct sample_average {
    size_t pixels;
    int count;            /* images added */
    double *sum;          /* 3 channels per pixel, linear light */
};

/* 0, or -1 when out of memory. */
int sample_average_init(struct sample_average *a, size_t pixels);
/* Add one image of a.pixels RGBA8 pixels (alpha is ignored). */
void sample_average_add(struct sample_average *a, const unsigned char *rgba);
/* The mean so far into rgba (alpha 255); nothing when no image was added. */
void sample_average_write(const struct sample_average *a, unsigned char *rgba);
void sample_average_free(struct sample_average *a);

/* The sRGB transfer function and its inverse, on [0, 1]. */
double srgb_to_linear(double encoded);
double linear_to_srgb(double linear);

#endif
