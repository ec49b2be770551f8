/* Black-body colour of src/physics/blackbody.c against the numbers of Müller, Grottel and Weiskopf
 * (2010) section 3.3, the radiation laws that follow from Planck's, tabulated CIE 1931 values, the
 * Planckian locus, and the properties the shaders rely on in the lookup table. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "physics/blackbody.h"

/* pi is not in strict C11. */
static const double pi = 3.14159265358979323846;

/* Wien's displacement constant (CODATA 2018), m K, and Stefan-Boltzmann's, W m^-2 K^-4. */
#define WIEN_B_M_K 2.897771955e-3
#define STEFAN_BOLTZMANN_W_M2_K4 5.670374419e-8
/* Both constants follow exactly from h, c, k_B, and the quadratures below are good to about 1e-8:
 * 1e-6 still catches a constant rounded to four digits (6.626e-34 is 1e-5 off). */
#define RADIATION_LAW_TOL 1e-6

/* The multi-lobe fit of Wyman et al. follows the CIE 1931 tables to a few hundredths; its worst
 * sample here is z̄(450), 0.034 high. */
#define CIE_FIT_TOL 0.05
/* Chromaticity of a Planck spectrum through the fit: the fit's errors largely cancel in x, y. */
#define CHROMATICITY_TOL 0.005

/* Largest step between adjacent texels, in 8-bit levels, over the whole table. Measured: 9 for
 * TONE_LUMINANCE (near 880 K, where green leaves 0 while red is pinned at 1) and 26 for
 * TONE_FIXED_1500K (near 1930 K, where luminance grows about 30% per texel of the 1.9% temperature
 * spacing and the curve has not yet flattened). The bounds leave a few levels of margin; a larger
 * step means a visible band when the GPU interpolates. */
#define MAX_STEP_LUMINANCE 12
#define MAX_STEP_FIXED_1500K 30

static void assert_near(double got, double want, double tol, const char *what)
{
    if (!(fabs(got - want) <= tol)) {
        print_error("%s: got %.17g, want %.17g (tolerance %g)\n", what, got, want, tol);
        fail();
    }
}

static void assert_rel_near(double got, double want, double rel, const char *what)
{
    if (!(fabs(got - want) <= rel * fabs(want))) {
        print_error("%s: got %.17g, want %.17g (relative tolerance %g)\n", what, got, want, rel);
        fail();
    }
}

static void chromaticity(double temperature_k, double *x, double *y)
{
    double xyz[3];
    blackbody_xyz(temperature_k, xyz);
    double sum = xyz[0] + xyz[1] + xyz[2];
    *x = xyz[0] / sum;
    *y = xyz[1] / sum;
}

/* ---- Doppler shift of temperature ---- */

static void test_paper_doppler_temperatures(void **state)
{
    (void)state;
    double beta = 0.2;
    double d = sqrt((1.0 + beta) / (1.0 - beta));
    assert_near(d, sqrt(1.5), 1e-15, "D at 0.2c");
    assert_near(round(doppler_temperature(6000.0, d)), 7348.0, 0.0, "6000 K approaching");
    assert_near(round(doppler_temperature(6000.0, 1.0 / d)), 4899.0, 0.0, "6000 K receding");
}

/* Eq. 9: the shifted spectrum D^5 L(λ D, T) is exactly Planck's at T D. */
static void test_shifted_spectrum_is_planck(void **state)
{
    (void)state;
    const double d[] = {0.3, 1.0 / sqrt(1.5), sqrt(1.5), 4.0};
    const double nm[] = {380.0, 555.0, 780.0, 2000.0};
    for (size_t i = 0; i < sizeof d / sizeof d[0]; i++)
        for (size_t j = 0; j < sizeof nm / sizeof nm[0]; j++) {
            double lambda = nm[j] * 1e-9;
            double shifted = pow(d[i], 5.0) * planck_radiance(lambda * d[i], 6000.0);
            assert_rel_near(planck_radiance(lambda, doppler_temperature(6000.0, d[i])), shifted,
                            1e-12, "D^5 L(lambda D, T) = L(lambda, T D)");
        }
}

/* ---- Planck's law ---- */

/* Golden-section search for the peak of λ -> L(λ, T) in [lo, hi]. */
static double planck_peak(double temperature_k, double lo, double hi)
{
    const double g = (sqrt(5.0) - 1.0) / 2.0;
    for (int i = 0; i < 200 && hi - lo > 1e-15; i++) {
        double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
        if (planck_radiance(a, temperature_k) < planck_radiance(b, temperature_k))
            lo = a;
        else
            hi = b;
    }
    return 0.5 * (lo + hi);
}

static void test_wien_displacement(void **state)
{
    (void)state;
    const double t[] = {3000.0, 6000.0, 10000.0};
    for (size_t i = 0; i < sizeof t / sizeof t[0]; i++) {
        double want = WIEN_B_M_K / t[i];
        assert_rel_near(planck_peak(t[i], 0.5 * want, 2.0 * want), want, RADIATION_LAW_TOL,
                        "Wien peak");
    }
}

/* pi times the radiance integrated over all wavelengths is the emitted flux sigma T^4. Simpson in
 * ln(lambda), 10 nm to 1 mm: the tails beyond hold less than 1e-8 of the total here. */
static void test_stefan_boltzmann(void **state)
{
    (void)state;
    const double t[] = {3000.0, 6000.0, 10000.0};
    const int intervals = 4000;
    double u0 = log(10e-9), u1 = log(1e-3), h = (u1 - u0) / intervals;
    for (size_t k = 0; k < sizeof t / sizeof t[0]; k++) {
        double sum = 0.0;
        for (int i = 0; i <= intervals; i++) {
            double lambda = exp(u0 + i * h);
            double w = (i == 0 || i == intervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
            sum += w * planck_radiance(lambda, t[k]) * lambda;
        }
        double flux = pi * sum * h / 3.0;
        assert_rel_near(flux, STEFAN_BOLTZMANN_W_M2_K4 * pow(t[k], 4.0), RADIATION_LAW_TOL,
                        "Stefan-Boltzmann");
    }
}

/* Far in the radio, L = 2ckT/λ^4 (1 - x/2 + ...) with x = hc/(kTλ) ~ 2e-9: exp(x) - 1 would have
 * lost about half its digits there, expm1 keeps them. */
static void test_rayleigh_jeans_limit(void **state)
{
    (void)state;
    const double h = 6.62607015e-34, c = 299792458.0, k = 1.380649e-23;
    double lambda = 1000.0, t = 6000.0, x = h * c / (k * t * lambda);
    double rayleigh_jeans = 2.0 * c * k * t / pow(lambda, 4.0);
    assert_rel_near(planck_radiance(lambda, t) / rayleigh_jeans, 1.0 - x / 2.0, 1e-13,
                    "Rayleigh-Jeans limit");
}

/* ---- CIE 1931 colour-matching functions ---- */

static void test_cie_fit(void **state)
{
    (void)state;
    double peak_nm = 0.0, peak = 0.0;
    for (double nm = 360.0; nm <= 830.0; nm += 0.1) {
        double xb = cie_x_bar(nm), yb = cie_y_bar(nm), zb = cie_z_bar(nm);
        if (!(xb >= 0.0 && yb >= 0.0 && zb >= 0.0)) {
            print_error("negative colour-matching function at %g nm: %g %g %g\n", nm, xb, yb, zb);
            fail();
        }
        if (yb > peak) {
            peak = yb;
            peak_nm = nm;
        }
    }
    assert_near(peak_nm, 555.0, 5.0, "y_bar peak wavelength");
    assert_near(peak, 1.0, 0.02, "y_bar peak value");
    /* CIE 1931 2-degree tables. */
    assert_near(cie_y_bar(555.0), 1.0, CIE_FIT_TOL, "y_bar(555)");
    assert_near(cie_x_bar(600.0), 1.0622, CIE_FIT_TOL, "x_bar(600)");
    assert_near(cie_z_bar(450.0), 1.7471, CIE_FIT_TOL, "z_bar(450)");
    assert_near(cie_x_bar(450.0), 0.3362, CIE_FIT_TOL, "x_bar(450)");
    assert_near(cie_y_bar(500.0), 0.3230, CIE_FIT_TOL, "y_bar(500)");
    assert_near(cie_x_bar(700.0), 0.011359, CIE_FIT_TOL, "x_bar(700)");
}

/* Planckian locus (CIE 15): 6500 K, and illuminant A, which is defined as a 2856 K black body. */
static void test_planckian_locus(void **state)
{
    (void)state;
    double x, y;
    chromaticity(6500.0, &x, &y);
    assert_near(x, 0.3135, CHROMATICITY_TOL, "x of 6500 K");
    assert_near(y, 0.3237, CHROMATICITY_TOL, "y of 6500 K");
    chromaticity(2856.0, &x, &y);
    assert_near(x, 0.4476, CHROMATICITY_TOL, "x of illuminant A");
    assert_near(y, 0.4074, CHROMATICITY_TOL, "y of illuminant A");
}

static void test_luminance_grows_with_temperature(void **state)
{
    (void)state;
    double previous = 0.0;
    for (int i = 0; i < BLACKBODY_LUT_SIZE; i++) {
        double xyz[3];
        blackbody_xyz(blackbody_lut_temperature(i), xyz);
        assert_true(xyz[1] > previous);
        previous = xyz[1];
    }
}

/* ---- XYZ -> BT.709 -> sRGB ---- */

static void test_d65_is_white(void **state)
{
    (void)state;
    const double d65[3] = {0.9505, 1.0, 1.089};
    double rgb[3];
    xyz_to_linear_bt709(d65, rgb);
    for (int j = 0; j < 3; j++)
        assert_near(rgb[j], 1.0, 0.01, "D65 in BT.709");
}

static void test_srgb_encode(void **state)
{
    (void)state;
    assert_near(srgb_encode(0.0), 0.0, 0.0, "sRGB(0)");
    assert_near(srgb_encode(0.0031308), 12.92 * 0.0031308, 1e-15, "sRGB at the knee");
    assert_near(srgb_encode(0.5), 0.7354, 1e-4, "sRGB(0.5)");
    assert_near(srgb_encode(1.0), 1.0, 1e-12, "sRGB(1)");
    assert_near(srgb_encode(-0.5), 0.0, 0.0, "sRGB clamps below");
    assert_near(srgb_encode(7.0), 1.0, 1e-12, "sRGB clamps above");
    /* The two branches meet at the knee (Eq. 13 is continuous to about 1e-7). */
    assert_near(srgb_encode(0.0031308 * (1.0 + 1e-9)), srgb_encode(0.0031308), 1e-6, "knee");
}

/* ---- tone mappings ---- */

static void test_tone_luminance(void **state)
{
    (void)state;
    double c[3];
    blackbody_srgb(6500.0, TONE_LUMINANCE, c);
    double hi = fmax(c[0], fmax(c[1], c[2])), lo = fmin(c[0], fmin(c[1], c[2]));
    assert_true(hi - lo < 0.08);
    /* Per-temperature normalisation: hot and cold are equally bright at their largest primary. */
    blackbody_srgb(1500.0, TONE_LUMINANCE, c);
    assert_near(c[0], 1.0, 1e-12, "1500 K red saturated");
    assert_true(c[0] > c[1] && c[1] > c[2]);
    blackbody_srgb(30000.0, TONE_LUMINANCE, c);
    assert_near(c[2], 1.0, 1e-12, "30000 K blue saturated");
    assert_true(c[2] > c[1] && c[1] > c[0]);
}

static void test_tone_fixed_1500k(void **state)
{
    (void)state;
    double c[3];
    blackbody_srgb(1500.0, TONE_FIXED_1500K, c);
    assert_true(c[0] > c[1] && c[1] > c[2]);
    assert_true(c[0] < 0.8);
    const double white_k[] = {3600.0, 10000.0, 30000.0};
    for (size_t i = 0; i < sizeof white_k / sizeof white_k[0]; i++) {
        blackbody_srgb(white_k[i], TONE_FIXED_1500K, c);
        for (int j = 0; j < 3; j++)
            assert_true(c[j] > 0.9);
    }
    /* The searchlight effect survives: brightness never falls as temperature rises. */
    double previous = 0.0;
    for (int i = 0; i < BLACKBODY_LUT_SIZE; i++) {
        blackbody_srgb(blackbody_lut_temperature(i), TONE_FIXED_1500K, c);
        double luma = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
        if (!(luma >= previous)) {
            print_error("brightness falls at %g K: %g after %g\n", blackbody_lut_temperature(i),
                        luma, previous);
            fail();
        }
        previous = luma;
    }
}

static void test_colours_in_range(void **state)
{
    (void)state;
    for (int tone = TONE_LUMINANCE; tone <= TONE_FIXED_1500K; tone++)
        for (double t = 10.0; t < 1e6; t *= 1.1) {
            double c[3];
            blackbody_srgb(t, (enum blackbody_tone)tone, c);
            for (int j = 0; j < 3; j++)
                assert_true(c[j] >= 0.0 && c[j] <= 1.0);
        }
}

/* ---- the lookup table ---- */

static void test_lut_coordinates(void **state)
{
    (void)state;
    const int n = BLACKBODY_LUT_SIZE;
    assert_rel_near(blackbody_lut_temperature(0), BLACKBODY_T_MIN_K, 1e-15, "first texel");
    assert_rel_near(blackbody_lut_temperature(n - 1), BLACKBODY_T_MAX_K, 1e-14, "last texel");
    for (int i = 0; i < n; i++) {
        assert_near(blackbody_lut_coordinate(blackbody_lut_temperature(i)), (i + 0.5) / n, 1e-12,
                    "texel centre");
        if (i > 0)
            assert_true(blackbody_lut_temperature(i) > blackbody_lut_temperature(i - 1));
    }
    /* Outside the table: the end colours, also for nonsense input. */
    assert_near(blackbody_lut_coordinate(100.0), 0.5 / n, 1e-15, "cold clamp");
    assert_near(blackbody_lut_coordinate(0.0), 0.5 / n, 1e-15, "0 K clamp");
    assert_near(blackbody_lut_coordinate(-300.0), 0.5 / n, 1e-15, "negative T clamp");
    assert_near(blackbody_lut_coordinate(NAN), 0.5 / n, 1e-15, "NaN clamp");
    assert_near(blackbody_lut_coordinate(1e6), (n - 0.5) / n, 1e-15, "hot clamp");
    assert_near(blackbody_lut_coordinate(INFINITY), (n - 0.5) / n, 1e-15, "infinite T clamp");
}

static void check_lut(enum blackbody_tone tone, int max_step, const char *name)
{
    unsigned char rgba[4 * BLACKBODY_LUT_SIZE];
    blackbody_lut_fill(tone, rgba);
    int worst = 0;
    for (int i = 0; i < BLACKBODY_LUT_SIZE; i++) {
        double c[3];
        blackbody_srgb(blackbody_lut_temperature(i), tone, c);
        for (int j = 0; j < 3; j++) {
            assert_int_equal(rgba[4 * i + j], (int)lround(255.0 * c[j]));
            if (i > 0) {
                int step = abs((int)rgba[4 * i + j] - (int)rgba[4 * (i - 1) + j]);
                worst = step > worst ? step : worst;
            }
        }
        assert_int_equal(rgba[4 * i + 3], 255);
    }
    if (worst > max_step) {
        print_error("%s: adjacent texels differ by %d levels (bound %d)\n", name, worst, max_step);
        fail();
    }
}

static void test_lut_luminance(void **state)
{
    (void)state;
    check_lut(TONE_LUMINANCE, MAX_STEP_LUMINANCE, "TONE_LUMINANCE");
}

static void test_lut_fixed_1500k(void **state)
{
    (void)state;
    check_lut(TONE_FIXED_1500K, MAX_STEP_FIXED_1500K, "TONE_FIXED_1500K");
}

/* TONE_SCENE: the reference temperature lies below the clip in every channel, twice it is brighter
 * and half of it darker (the searchlight's two sides), at any reference. */
static void test_scene_exposure(void **state)
{
    (void)state;
    const double references[] = {3000.0, 6000.0, 12000.0};
    for (int i = 0; i < 3; i++) {
        double t = references[i], at[3], hot[3], cold[3];
        blackbody_srgb_exposed(t, TONE_SCENE, t, at);
        blackbody_srgb_exposed(2.0 * t, TONE_SCENE, t, hot);
        blackbody_srgb_exposed(0.5 * t, TONE_SCENE, t, cold);
        double sum_at = at[0] + at[1] + at[2], sum_hot = hot[0] + hot[1] + hot[2], sum_cold = cold[0] + cold[1] + cold[2];
        for (int c = 0; c < 3; c++)
            assert_true(at[c] < 0.9);
        assert_true(sum_hot > 1.2 * sum_at);
        assert_true(sum_cold < 0.6 * sum_at);
    }
}

static double decode_srgb(double v)
{
    return v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
}

/* TONE_SCENE maps the luminance through the paper's curve and keeps the body's hue (docs/RELATIVITY.md):
 * from 3000 K to 30000 K at a 6000 K reference, the linear output is the body's own BT.709 colour
 * scaled (its primaries in the same ratios) wherever no primary reaches 1, and moved towards the grey
 * of its luminance only as far as the gamut needs; the luminance never falls as T rises; the
 * searchlight's Doppler colours stay visible: blue ahead at twice the reference, red behind at half. */
static void test_scene_tone_keeps_hue(void **state)
{
    (void)state;
    double last_luminance = 0.0;
    for (double t = 3000.0; t <= 30000.0 * 1.0001; t *= 1.122) {
        double xyz[3], in[3], out[3], srgb[3];
        blackbody_xyz(t, xyz);
        xyz_to_linear_bt709(xyz, in);
        blackbody_srgb_exposed(t, TONE_SCENE, 6000.0, srgb);
        int at_top = 0;
        for (int c = 0; c < 3; c++) {
            out[c] = decode_srgb(srgb[c]);
            at_top |= srgb[c] >= 1.0 - 1e-12;
        }
        double luminance = 0.2126 * out[0] + 0.7152 * out[1] + 0.0722 * out[2];
        if (!at_top)
            for (int c = 0; c < 3; c += 2)
                assert_float_equal(out[c] / out[1], in[c] / in[1], 1e-9 * in[c] / in[1]);
        /* the primaries keep their order, and none is lost to the clip */
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++)
                if (in[a] > in[b] * (1.0 + 1e-6))
                    assert_true(out[a] > out[b]);
        assert_true(luminance >= last_luminance);
        last_luminance = luminance;
    }
    double ahead[3], behind[3];
    blackbody_srgb_exposed(12000.0, TONE_SCENE, 6000.0, ahead);
    blackbody_srgb_exposed(3000.0, TONE_SCENE, 6000.0, behind);
    printf("  exposure scene, reference 6000 K: 12000 K as (%.0f, %.0f, %.0f), 3000 K as (%.0f, %.0f, %.0f)\n",
           255 * ahead[0], 255 * ahead[1], 255 * ahead[2], 255 * behind[0], 255 * behind[1], 255 * behind[2]);
    /* the curve on each channel gave 12000 K as (166, 171, 182): blue minus red 0.06 */
    assert_true(ahead[2] - ahead[0] >= 0.15);
    assert_true(behind[0] - behind[2] >= 0.10);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_scene_exposure),
        cmocka_unit_test(test_scene_tone_keeps_hue),
        cmocka_unit_test(test_paper_doppler_temperatures),
        cmocka_unit_test(test_shifted_spectrum_is_planck),
        cmocka_unit_test(test_wien_displacement),
        cmocka_unit_test(test_stefan_boltzmann),
        cmocka_unit_test(test_rayleigh_jeans_limit),
        cmocka_unit_test(test_cie_fit),
        cmocka_unit_test(test_planckian_locus),
        cmocka_unit_test(test_luminance_grows_with_temperature),
        cmocka_unit_test(test_d65_is_white),
        cmocka_unit_test(test_srgb_encode),
        cmocka_unit_test(test_tone_luminance),
        cmocka_unit_test(test_tone_fixed_1500k),
        cmocka_unit_test(test_colours_in_range),
        cmocka_unit_test(test_lut_coordinates),
        cmocka_unit_test(test_lut_luminance),
        cmocka_unit_test(test_lut_fixed_1500k),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
