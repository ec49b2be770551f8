/* The light of an 8-bit image ([render] gain and tone_curve): what both engines do last to each
 * sample's colour before it becomes an 8-bit code, the GPU in sky_colour.glsl (tone_map), the CPU
 * here. The colour comes sRGB-encoded (the shading's and the sky's display values, unclamped, the
 * stars' light added in linear light) and goes back so:
 *
 * - gain: the linear light multiplied (an exposure: not observer.exposure, the searchlight's
 *   reference, which the black-body table applies before);
 * - clip (the default): each channel then clipped at white, as before any curve (a bright
 *   colour turns white channel by channel, its hue lost);
 * - filmic: Narkowicz's fit of the ACES filmic curve (2015),
 *   f(L) = min(L (2.51 L + 0.03) / (L (2.43 L + 0.59) + 0.14), 1), on the luminance L alone: the
 *   colour scaled by f(L) / L keeps its hue and saturation, and where a channel would still pass
 *   white it is mixed toward the grey of the same luminance, as little as brings it to white.
 *   Bright light rolls off smoothly to white at L = 7.24; dark light is near linear (slope 0.21).
 *
 * Images of floats (16-bit PNG, PFM) keep the linear light as traced: no gain, no curve. */
#ifndef BT_TONE_H
#define BT_TONE_H
#include "scene/scene.h"

/* Whether the settings change anything (gain 1 with clip does not: the shaders then carry no
 * tone map at all). */
int tone_active(const struct render_settings *r);
/* The filmic curve of linear luminance L. */
double tone_filmic(double luminance);
/* rgb (sRGB-encoded, any value) through the gain and the curve, sRGB-encoded in [0, 1]. */
void tone_map(const struct render_settings *r, double rgb[3]);
/* The same on linear light (any value; below 0 taken as 0), linear in [0, 1]. */
void tone_map_linear(const struct render_settings *r, double lin[3]);

#endif
