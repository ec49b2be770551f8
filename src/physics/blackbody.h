/* Colour of black-body radiation (Müller, Grottel and Weiskopf 2010, section 3.3): Planck's law,
 * the CIE 1931 colour-matching functions, XYZ -> BT.709 -> sRGB, the two tone mappings of their
 * Figure 6, and the lookup table over temperature that the shaders sample. */
#ifndef BT_BLACKBODY_H
#define BT_BLACKBODY_H

/* The table spans from a dull red glow to well into the blue-white saturation of hot stars;
 * temperatures are spaced logarithmically because colour changes with ratios of T, not with
 * differences. */
#define BLACKBODY_LUT_SIZE 256
#define BLACKBODY_T_MIN_K 500.0
#define BLACKBODY_T_MAX_K 60000.0

enum blackbody_tone {
    /* XYZ / Y(T): hue only, every temperature equally bright (no searchlight effect). */
    TONE_LUMINANCE,
    /* XYZ / Y(1500 K), then a log curve on the sRGB values: brightness grows with T (the
     * searchlight effect is kept). The paper's exposure: a 6000 K body is already white. */
    TONE_FIXED_1500K,
    /* XYZ / Y(T_ref) times BLACKBODY_SCENE_GAIN, then the log curve on the luminance, the hue kept
     * (the primaries scaled together, desaturated only as far as the gamut needs): a body at the scene's own
     * reference temperature T_ref (its sky's, or its lights') shows mid-grey at rest, so that both
     * the searchlight's brightening ahead and its dimming behind stay visible before the clip. */
    TONE_SCENE,
    /* XYZ / Y(T_ref) times BLACKBODY_LINEAR_GREY, linear light with no curve: the image's filmic
     * curve (render.tone_curve, results/tone.h) brings it to the screen, so that a body brighter
     * than white stays brighter, and its hue. The table holds each colour's chromaticity
     * (sRGB-encoded over its largest primary) and, in alpha, log2 of that largest primary over
     * BLACKBODY_LOG2_SPAN stops about 0 (blackbody_lut_decode). */
    TONE_SCENE_LINEAR,
};

/* TONE_SCENE_LINEAR: the linear luminance of a body at the reference temperature (photography's
 * mid-grey), and the stops of log2 luminance the table's alpha spans, half each side of 1. */
#define BLACKBODY_LINEAR_GREY 0.18
#define BLACKBODY_LOG2_SPAN 24.0

/* TONE_SCENE: the display value (after the log curve) of a body at the reference temperature. */
#define BLACKBODY_SCENE_GREY 0.45

/* Spectral radiance of a black body, W sr^-1 m^-3 (per metre of wavelength), Eq. 10. */
double planck_radiance(double wavelength_m, double temperature_k);

/* CIE 1931 2-degree colour-matching functions, wavelength in nm (analytic fit, see the .c file). */
double cie_x_bar(double wavelength_nm);
double cie_y_bar(double wavelength_nm);
double cie_z_bar(double wavelength_nm);

/* Tristimulus values of a black body, Eq. 11, absolute: integral of radiance times x̄, ȳ, z̄ over
 * 360..830 nm, in W sr^-1 m^-2. Y grows with temperature; nothing is normalised here. */
void blackbody_xyz(double temperature_k, double xyz[3]);

/* Linear BT.709 RGB from XYZ, Eq. 12 (may leave [0,1]: nothing is clamped). */
void xyz_to_linear_bt709(const double xyz[3], double rgb[3]);

/* The sRGB transfer function, Eq. 13; the input is clamped to [0,1] first. */
double srgb_encode(double linear);

/* Display colour (sRGB-encoded, each in [0,1]) of a black body under a tone mapping. */
void blackbody_srgb(double temperature_k, enum blackbody_tone tone, double srgb[3]);
/* The same with TONE_SCENE's reference temperature (ignored by the other tones). */
void blackbody_srgb_exposed(double temperature_k, enum blackbody_tone tone, double reference_k, double srgb[3]);

/* Apparent temperature T D of a black body seen with Doppler factor D (frequency ratio, above 1
 * when approaching): a Planck spectrum shifted by D and scaled by the searchlight factor D^5 of
 * Eq. 9 is again a Planck spectrum. */
double doppler_temperature(double temperature_k, double doppler_factor);

/* Temperature of texel i (0..BLACKBODY_LUT_SIZE-1). */
double blackbody_lut_temperature(int i);

/* Texture coordinate s of a temperature: texel centres, clamped to the first and last one so that
 * temperatures outside the table take its end colours. */
double blackbody_lut_coordinate(double temperature_k);

/* A texel of the TONE_SCENE_LINEAR table (bytes over 255, or their linear interpolation) as linear
 * RGB, which may pass 1. */
void blackbody_lut_decode(const double rgba[4], double linear[3]);

/* The table: 8-bit sRGB of blackbody_srgb at each texel temperature, rounded, alpha 255 (for
 * TONE_SCENE_LINEAR the chromaticity and log2 of the brightness, as said above). */
void blackbody_lut_fill(enum blackbody_tone tone, unsigned char rgba[4 * BLACKBODY_LUT_SIZE]);
void blackbody_lut_fill_exposed(enum blackbody_tone tone, double reference_k, unsigned char rgba[4 * BLACKBODY_LUT_SIZE]);

#endif
