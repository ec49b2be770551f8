#include "io/sample_average.h"
#include <math.h>
#include <stdlib.h>

double srgb_to_linear(double c)
{
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

double linear_to_srgb(double l)
{
    l = l < 0.0 ? 0.0 : l > 1.0 ? 1.0 : l;
    return l <= 0.0031308 ? 12.92 * l : 1.055 * pow(l, 1.0 / 2.4) - 0.055;
}

int sample_average_init(struct sample_average *a, size_t pixels)
{
    a->pixels = pixels;
    a->count = 0;
    a->sum = calloc(pixels ? 3 * pixels : 1, sizeof *a->sum);
    return a->sum ? 0 : -1;
}

void sample_average_add(struct sample_average *a, const unsigned char *rgba)
{
    double decoded[256];
    for (int v = 0; v < 256; v++)
        decoded[v] = srgb_to_linear(v / 255.0);
    for (size_t i = 0; i < a->pixels; i++)
        for (int c = 0; c < 3; c++)
            a->sum[3 * i + c] += decoded[rgba[4 * i + c]];
    a->count++;
}

void sample_average_write(const struct sample_average *a, unsigned char *rgba)
{
    if (a->count == 0)
        return;
    for (size_t i = 0; i < a->pixels; i++) {
        for (int c = 0; c < 3; c++)
            rgba[4 * i + c] = (unsigned char)lrint(255.0 * linear_to_srgb(a->sum[3 * i + c] / a->count));
        rgba[4 * i + 3] = 255;
    }
}

void sample_average_free(struct sample_average *a)
{
    free(a->sum);
    a->sum = NULL;
}
