/* Colour of black-body radiation (Müller, Grottel and Weiskopf 2010, section 3.3), in double
 * precision on the CPU; the shaders only sample the table made here. */
#include "physics/blackbody.h"

#include <math.h>

/* CODATA 2018 exact SI values. */
#define PLANCK_H_J_S 6.62607015e-34
#define SPEED_OF_LIGHT_M_S 299792458.0
#define BOLTZMANN_K_J_PER_K 1.380649e-23

/* The range over which the CIE 1931 tables are defined; outside it the observer sees nothing. */
#define VISIBLE_MIN_NM 360.0
#define VISIBLE_MAX_NM 830.0
/* Simpson's rule with 1 nm steps: the colour-matching lobes are tens of nm wide and the Planck
 * factor varies slowly across 1 nm, so the quadrature error is far below the fit's own. */
#define XYZ_STEP_NM 1.0
#define NM_TO_M 1e-9

/* The fixed exposure of TONE_FIXED_1500K: a 1500 K body has luminance 1 before the curve. */
#define FIXED_EXPOSURE_T_K 1500.0
/* The paper's global curve C_sRGB -> 0.6 log10(C_sRGB + 1); it reaches 1 at 10^(1/0.6) - 1. */
#define LOG_CURVE_GAIN 0.6

/* sRGB transfer function, Eq. 13. */
#define SRGB_LINEAR_LIMIT 0.0031308
#define SRGB_LINEAR_SLOPE 12.92
#define SRGB_OFFSET 0.055
#define SRGB_GAMMA 2.4

double planck_radiance(double wavelength_m, double temperature_k)
{
    const double h = PLANCK_H_J_S, c = SPEED_OF_LIGHT_M_S, k = BOLTZMANN_K_J_PER_K;
    double l5 = pow(wavelength_m, 5.0);
    /* expm1: at the Rayleigh-Jeans end (hc/kTλ << 1) exp(x) - 1 would lose most of its digits. */
    return 2.0 * h * c * c / (l5 * expm1(h * c / (k * temperature_k * wavelength_m)));
}

/* Wyman, Sloan and Shirley, "Simple Analytic Approximations to the CIE XYZ Color Matching
 * Functions", JCGT 2(2), 2013: their multi-lobe piecewise-Gaussian fit, coefficients as published.
 * Each lobe is wider on one side of its peak than the other, as the CIE curves are. */
static double lobe(double nm, double peak_nm, double width_below_nm, double width_above_nm)
{
    double t = (nm - peak_nm) / (nm < peak_nm ? width_below_nm : width_above_nm);
    return exp(-0.5 * t * t);
}

double cie_x_bar(double nm)
{
    return 1.056 * lobe(nm, 599.8, 37.9, 31.0) + 0.362 * lobe(nm, 442.0, 16.0, 26.7)
         - 0.065 * lobe(nm, 501.1, 20.4, 26.2);
}

double cie_y_bar(double nm)
{
    return 0.821 * lobe(nm, 568.8, 46.9, 40.5) + 0.286 * lobe(nm, 530.9, 16.3, 31.1);
}

double cie_z_bar(double nm)
{
    return 1.217 * lobe(nm, 437.0, 11.8, 36.0) + 0.681 * lobe(nm, 459.0, 26.0, 13.8);
}

void blackbody_xyz(double temperature_k, double xyz[3])
{
    /* Simpson needs an even count: 470. */
    int intervals = (int)lround((VISIBLE_MAX_NM - VISIBLE_MIN_NM) / XYZ_STEP_NM);
    double sum[3] = {0.0, 0.0, 0.0};
    for (int i = 0; i <= intervals; i++) {
        double nm = VISIBLE_MIN_NM + i * XYZ_STEP_NM;
        double weight = (i == 0 || i == intervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        double radiance = weight * planck_radiance(nm * NM_TO_M, temperature_k);
        sum[0] += radiance * cie_x_bar(nm);
        sum[1] += radiance * cie_y_bar(nm);
        sum[2] += radiance * cie_z_bar(nm);
    }
    for (int j = 0; j < 3; j++)
        xyz[j] = sum[j] * XYZ_STEP_NM * NM_TO_M / 3.0;
}

void xyz_to_linear_bt709(const double xyz[3], double rgb[3])
{
    static const double m[3][3] = {{3.2405, -1.5372, -0.4985},
                                   {-0.9693, 1.8760, 0.0416},
                                   {0.0556, -0.2040, 1.0573}};
    for (int i = 0; i < 3; i++)
        rgb[i] = m[i][0] * xyz[0] + m[i][1] * xyz[1] + m[i][2] * xyz[2];
}

/* Eq. 13 without the clamp: the power branch continues smoothly above 1. */
static double srgb_transfer(double linear)
{
    if (linear <= SRGB_LINEAR_LIMIT)
        return SRGB_LINEAR_SLOPE * linear;
    return (1.0 + SRGB_OFFSET) * pow(linear, 1.0 / SRGB_GAMMA) - SRGB_OFFSET;
}

/* The inverse of srgb_transfer over [0, 1]. */
static double srgb_decode(double encoded)
{
    if (encoded <= SRGB_LINEAR_SLOPE * SRGB_LINEAR_LIMIT)
        return encoded / SRGB_LINEAR_SLOPE;
    return pow((encoded + SRGB_OFFSET) / (1.0 + SRGB_OFFSET), SRGB_GAMMA);
}

/* BT.709's luminance of linear RGB (the Y row of its inverse matrix). */
static double bt709_luminance(const double rgb[3])
{
    return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

/* Scaled down by the largest primary where one is above 1: the hue is kept, where clipping each
 * primary would turn every bright colour white or yellow. */
static void fit_gamut_keeping_hue(double rgb[3])
{
    double largest = fmax(rgb[0], fmax(rgb[1], rgb[2]));
    for (int j = 0; j < 3; j++)
        rgb[j] = largest > 1.0 ? rgb[j] / largest : rgb[j];
}

double srgb_encode(double linear)
{
    return srgb_transfer(fmin(fmax(linear, 0.0), 1.0));
}

void blackbody_srgb(double temperature_k, enum blackbody_tone tone, double srgb[3])
{
    blackbody_srgb_exposed(temperature_k, tone, FIXED_EXPOSURE_T_K, srgb);
}

/* The linear value whose sRGB encoding the log curve maps to `display`: TONE_SCENE's gain. */
static double scene_gain(void)
{
    double encoded = pow(10.0, BLACKBODY_SCENE_GREY / LOG_CURVE_GAIN) - 1.0;
    return pow((encoded + SRGB_OFFSET) / (1.0 + SRGB_OFFSET), SRGB_GAMMA);
}

void blackbody_srgb_exposed(double temperature_k, enum blackbody_tone tone, double reference_k, double srgb[3])
{
    double xyz[3], rgb[3], luminance = 0.0;
    blackbody_xyz(temperature_k, xyz);
    /* Cold enough (a few tens of K) that no visible photon is left in double: black, not 0/0. */
    if (!(xyz[1] > 0.0)) {
        srgb[0] = srgb[1] = srgb[2] = 0.0;
        return;
    }
    if (tone == TONE_LUMINANCE) {
        luminance = xyz[1];
    } else {
        double fixed[3];
        blackbody_xyz(tone == TONE_SCENE && reference_k > 0.0 ? reference_k : FIXED_EXPOSURE_T_K, fixed);
        luminance = fixed[1] / (tone == TONE_SCENE ? scene_gain() : 1.0);
    }
    for (int j = 0; j < 3; j++)
        xyz[j] /= luminance;
    xyz_to_linear_bt709(xyz, rgb);
    /* Black bodies below about 1900 K lie outside the BT.709 gamut (too saturated a red): the
     * negative primary cannot be shown and becomes 0. */
    for (int j = 0; j < 3; j++)
        rgb[j] = fmax(rgb[j], 0.0);
    if (tone == TONE_LUMINANCE) {
        /* the paper's complaint about the plain mapping: clipping each primary would turn every
         * low temperature the same yellow */
        fit_gamut_keeping_hue(rgb);
        for (int j = 0; j < 3; j++)
            srgb[j] = srgb_encode(rgb[j]);
    } else if (tone == TONE_SCENE) {
        /* The log curve on the luminance, the chromaticity kept: a grey comes out as the paper's
         * curve on each channel makes it, a coloured body as bright as that grey and of its own
         * hue, fitted into the gamut by its largest primary. The curve on each channel would pull
         * every colour towards grey (12000 K to (166, 171, 182) at a 6000 K reference), hiding
         * the Doppler blue ahead and red behind that the searchlight is there to show. */
        double y = bt709_luminance(rgb);
        double grey = fmin(LOG_CURVE_GAIN * log10(srgb_transfer(y) + 1.0), 1.0);
        double y_out = srgb_decode(grey);
        double scale = y > 0.0 ? y_out / y : 0.0;
        for (int j = 0; j < 3; j++)
            rgb[j] *= scale;
        /* a primary above 1: towards the grey of the same luminance, just enough to fit, so that
         * a hotter body never looks dimmer than a cooler one (scaling by the largest primary
         * would darken the bluest) */
        double largest = fmax(rgb[0], fmax(rgb[1], rgb[2]));
        double keep = largest > 1.0 ? (1.0 - y_out) / (largest - y_out) : 1.0;
        for (int j = 0; j < 3; j++)
            srgb[j] = srgb_encode(y_out + keep * (rgb[j] - y_out));
    } else {
        /* As the paper writes it: the curve acts on C_sRGB, the transfer function taken past 1
         * unclipped. Only after the curve is the value clipped, at C_sRGB = 10^(1/0.6) - 1
         * (linear about 8000 times the luminance of 1500 K): the searchlight's brightening
         * survives, and the paper's 1500 K dark red and white above 3600 K come out. */
        for (int j = 0; j < 3; j++)
            srgb[j] = fmin(LOG_CURVE_GAIN * log10(srgb_transfer(rgb[j]) + 1.0), 1.0);
    }
}

double doppler_temperature(double temperature_k, double doppler_factor)
{
    return temperature_k * doppler_factor;
}

double blackbody_lut_temperature(int i)
{
    double u = (double)i / (BLACKBODY_LUT_SIZE - 1);
    return BLACKBODY_T_MIN_K * pow(BLACKBODY_T_MAX_K / BLACKBODY_T_MIN_K, u);
}

double blackbody_lut_coordinate(double temperature_k)
{
    /* Also catches T <= 0 and NaN (log gives -inf / NaN; fmax(NaN, 0) is 0): the coldest colour. */
    double u = log(temperature_k / BLACKBODY_T_MIN_K) / log(BLACKBODY_T_MAX_K / BLACKBODY_T_MIN_K);
    u = fmin(fmax(u, 0.0), 1.0);
    return (0.5 + (BLACKBODY_LUT_SIZE - 1) * u) / BLACKBODY_LUT_SIZE;
}

void blackbody_lut_fill(enum blackbody_tone tone, unsigned char rgba[4 * BLACKBODY_LUT_SIZE])
{
    blackbody_lut_fill_exposed(tone, FIXED_EXPOSURE_T_K, rgba);
}

/* TONE_SCENE_LINEAR's linear BT.709 colour of a black body: XYZ / Y(T_ref) times the grey */
static void blackbody_linear(double temperature_k, double reference_k, double rgb[3])
{
    double xyz[3], ref[3];
    blackbody_xyz(temperature_k, xyz);
    blackbody_xyz(reference_k > 0.0 ? reference_k : FIXED_EXPOSURE_T_K, ref);
    for (int j = 0; j < 3; j++)
        xyz[j] = ref[1] > 0.0 && xyz[1] > 0.0 ? xyz[j] / ref[1] * BLACKBODY_LINEAR_GREY : 0.0;
    xyz_to_linear_bt709(xyz, rgb);
    for (int j = 0; j < 3; j++)
        rgb[j] = fmax(rgb[j], 0.0);   /* outside the gamut below about 1900 K, as above */
}

void blackbody_lut_decode(const double rgba[4], double linear[3])
{
    double scale = exp2((rgba[3] - 0.5) * BLACKBODY_LOG2_SPAN);
    for (int j = 0; j < 3; j++)
        linear[j] = srgb_decode(rgba[j]) * scale;
}

void blackbody_lut_fill_exposed(enum blackbody_tone tone, double reference_k, unsigned char rgba[4 * BLACKBODY_LUT_SIZE])
{
    for (int i = 0; i < BLACKBODY_LUT_SIZE && tone == TONE_SCENE_LINEAR; i++) {
        double rgb[3];
        blackbody_linear(blackbody_lut_temperature(i), reference_k, rgb);
        double top = fmax(rgb[0], fmax(rgb[1], rgb[2]));
        for (int j = 0; j < 3; j++)
            rgba[4 * i + j] = (unsigned char)lround(255.0 * srgb_encode(top > 0.0 ? rgb[j] / top : 0.0));
        double stops = top > 0.0 ? log2(top) / BLACKBODY_LOG2_SPAN + 0.5 : 0.0;
        rgba[4 * i + 3] = (unsigned char)lround(255.0 * (stops < 0.0 ? 0.0 : stops > 1.0 ? 1.0 : stops));
    }
    for (int i = 0; i < BLACKBODY_LUT_SIZE && tone != TONE_SCENE_LINEAR; i++) {
        double srgb[3];
        blackbody_srgb_exposed(blackbody_lut_temperature(i), tone, reference_k, srgb);
        for (int j = 0; j < 3; j++)
            rgba[4 * i + j] = (unsigned char)lround(255.0 * srgb[j]);
        rgba[4 * i + 3] = 255;
    }
}
