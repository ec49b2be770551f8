#include "io/sample_average.h"
#include <math.h>
#include <stdlib.h>

double srgb_to_linear(double c)
{
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

double linear_to_srgb_unclamped(double l)
{
    return l <= 0.0031308 ? 12.92 * l : 1.055 * pow(l, 1.0 / 2.4) - 0.055;
}

double linear_to_srgb(double l)
{
    return linear_to_srgb_unclamped(l < 0.0 ? 0.0 : l > 1.0 ? 1.0 : l);
}

unsigned char unorm8(double c)
{
    c = c < 0.0 ? 0.0 : c > 1.0 ? 1.0 : c;
    return (unsigned char)lrint(c * 255.0);
}

void pixel_average_add(struct pixel_average *p, const double encoded[3], double alpha)
{
    for (int c = 0; c < 3; c++) {
        double l = srgb_to_linear(encoded[c]);
        p->premultiplied[c] += l * alpha;
        p->plain[c] += l;
    }
    p->alpha += alpha;
}

void pixel_average_mean(const struct pixel_average *p, int n, double encoded[3], double *alpha)
{
    for (int c = 0; c < 3; c++)
        encoded[c] = linear_to_srgb_unclamped(p->alpha > 0.0 ? p->premultiplied[c] / p->alpha : p->plain[c] / n);
    *alpha = p->alpha / n;
}

int sample_average_init(struct sample_average *a, size_t pixels)
{
    a->pixels = pixels;
    a->count = 0;
    a->sum = calloc(pixels ? pixels : 1, sizeof *a->sum);
    return a->sum ? 0 : -1;
}

void sample_average_add(struct sample_average *a, const unsigned char *rgba, const float *color)
{
    if (!color) {
        /* 8-bit codes: each code's linear value once, the same numbers pixel_average_add computes */
        double linear[256];
        for (int v = 0; v < 256; v++)
            linear[v] = srgb_to_linear(v / 255.0);
        for (size_t i = 0; i < a->pixels; i++) {
            struct pixel_average *p = &a->sum[i];
            double alpha = rgba[4 * i + 3] / 255.0;
            for (int c = 0; c < 3; c++) {
                double l = linear[rgba[4 * i + c]];
                p->premultiplied[c] += l * alpha;
                p->plain[c] += l;
            }
            p->alpha += alpha;
        }
        a->count++;
        return;
    }
    for (size_t i = 0; i < a->pixels; i++) {
        double encoded[3], alpha;
        for (int c = 0; c < 3; c++)
            encoded[c] = (double)color[4 * i + c];
        alpha = (double)color[4 * i + 3];
        pixel_average_add(&a->sum[i], encoded, alpha);
    }
    a->count++;
}

void sample_average_write(const struct sample_average *a, unsigned char *rgba, float *color)
{
    if (a->count == 0)
        return;
    for (size_t i = 0; i < a->pixels; i++) {
        double encoded[3], alpha;
        pixel_average_mean(&a->sum[i], a->count, encoded, &alpha);
        for (int c = 0; c < 3; c++) {
            rgba[4 * i + c] = unorm8(encoded[c]);
            if (color)
                color[4 * i + c] = (float)encoded[c];
        }
        rgba[4 * i + 3] = unorm8(alpha);
        if (color)
            color[4 * i + 3] = (float)alpha;
    }
}

void sample_average_free(struct sample_average *a)
{
    free(a->sum);
    a->sum = NULL;
}

double image_rms_linear(const unsigned char *a, const unsigned char *b, size_t pixels)
{
    double linear[256], sum = 0.0;
    for (int v = 0; v < 256; v++)
        linear[v] = srgb_to_linear(v / 255.0);
    for (size_t i = 0; i < pixels; i++)
        for (int c = 0; c < 3; c++) {
            double d = linear[a[4 * i + c]] - linear[b[4 * i + c]];
            sum += d * d;
        }
    return pixels ? sqrt(sum / (3.0 * (double)pixels)) : 0.0;
}
