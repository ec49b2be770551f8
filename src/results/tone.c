#include "results/tone.h"
#include "io/sample_average.h"
#include <math.h>

int tone_active(const struct render_settings *r)
{
    return r->gain != 1.0 || r->tone_curve != TONE_CURVE_CLIP;
}

double tone_filmic(double l)
{
    /* the fit passes 1 at L = 7.24 (it tends to 2.51 / 2.43): white from there on */
    return fmin(l * (2.51 * l + 0.03) / (l * (2.43 * l + 0.59) + 0.14), 1.0);
}

void tone_map_linear(const struct render_settings *r, double lin[3])
{
    for (int c = 0; c < 3; c++)
        lin[c] = fmax(lin[c], 0.0) * r->gain;
    if (r->tone_curve == TONE_CURVE_FILMIC) {
        double l = 0.2126 * lin[0] + 0.7152 * lin[1] + 0.0722 * lin[2];
        double mapped = l > 0.0 ? tone_filmic(l) : 0.0;
        double top = 0.0;
        for (int c = 0; c < 3; c++) {
            lin[c] = l > 0.0 ? lin[c] * mapped / l : 0.0;
            top = fmax(top, lin[c]);
        }
        /* toward the grey of the same luminance, as far as brings the largest channel to white */
        double toward = top > 1.0 ? (top - 1.0) / (top - mapped) : 0.0;
        for (int c = 0; c < 3; c++)
            lin[c] += toward * (mapped - lin[c]);
    }
    for (int c = 0; c < 3; c++)
        lin[c] = fmin(fmax(lin[c], 0.0), 1.0);
}

void tone_map(const struct render_settings *r, double rgb[3])
{
    double lin[3];
    for (int c = 0; c < 3; c++)
        lin[c] = srgb_to_linear(rgb[c]);
    tone_map_linear(r, lin);
    for (int c = 0; c < 3; c++)
        rgb[c] = linear_to_srgb(lin[c]);
}
