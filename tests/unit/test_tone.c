/* The light of an 8-bit image ([render] gain and tone_curve, results/tone.h): the filmic curve's
 * shape, the hue kept, the gain as a factor of linear light, and the GPU's shader against the
 * reference's C on a scene brighter than white. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include "hard_cases.h"
#include "io/sample_average.h"
#include "physics/blackbody.h"
#include "results/tone.h"

/* hue angle of a linear colour, degrees (HSV's) */
static double hue(const double c[3])
{
    double top = fmax(c[0], fmax(c[1], c[2])), low = fmin(c[0], fmin(c[1], c[2])), d = top - low;
    if (d <= 0.0)
        return 0.0;
    double h = top == c[0] ? fmod((c[1] - c[2]) / d, 6.0) : top == c[1] ? (c[2] - c[0]) / d + 2.0 : (c[0] - c[1]) / d + 4.0;
    return fmod(60.0 * h + 360.0, 360.0);
}

/* The curve: 0 at 0, rising below 1 up to L = 7.24, white beyond, near linear (slope 0.03/0.14) in
 * the dark. */
static void test_filmic_curve(void **state)
{
    (void)state;
    assert_true(tone_filmic(0.0) == 0.0);
    double last = 0.0;
    for (double l = 1e-4; l < 1e6; l *= 1.1) {
        double f = tone_filmic(l);
        assert_true(l < 7.2 ? f > last && f < 1.0 : l > 7.3 ? f == 1.0 : f >= last);
        last = f;
    }
    assert_true(fabs(tone_filmic(1e-5) / 1e-5 - 0.03 / 0.14) < 1e-3);
}

/* Colours brighter than white keep their hue through the filmic curve and land in [0, 1]; with the
 * clip curve the same colours turn whiter (their hue moves); gain 2 with clip doubles the linear
 * light of a dim colour; the defaults change nothing. */
static void test_hue_and_gain(void **state)
{
    (void)state;
    struct scene s;
    scene_defaults(&s);
    assert_false(tone_active(&s.render));
    static const double colours[][3] = {{3.0, 1.0, 0.2}, {0.3, 0.5, 4.0}, {1.5, 2.5, 0.1}, {8.0, 0.2, 0.2}};
    int clip_moved = 0;
    for (size_t k = 0; k < sizeof colours / sizeof colours[0]; k++) {
        double rgb[3], lin_in[3];
        for (int c = 0; c < 3; c++) {
            lin_in[c] = colours[k][c];
            rgb[c] = linear_to_srgb_unclamped(colours[k][c]);
        }
        double clip[3] = {rgb[0], rgb[1], rgb[2]};
        s.render.tone_curve = TONE_CURVE_FILMIC;
        tone_map(&s.render, rgb);
        double lin_out[3];
        for (int c = 0; c < 3; c++) {
            assert_true(rgb[c] >= 0.0 && rgb[c] <= 1.0);
            lin_out[c] = srgb_to_linear(rgb[c]);
        }
        print_message("linear %.1f %.1f %.1f: hue %.2f, filmic %.3f %.3f %.3f hue %.2f\n", lin_in[0], lin_in[1],
                      lin_in[2], hue(lin_in), lin_out[0], lin_out[1], lin_out[2], hue(lin_out));
        assert_true(fabs(hue(lin_out) - hue(lin_in)) < 0.5);
        s.render.tone_curve = TONE_CURVE_CLIP;
        tone_map(&s.render, clip);
        double lin_clip[3] = {srgb_to_linear(clip[0]), srgb_to_linear(clip[1]), srgb_to_linear(clip[2])};
        clip_moved += fabs(hue(lin_clip) - hue(lin_in)) > 2.0;
    }
    assert_true(clip_moved >= 3);
    s.render.tone_curve = TONE_CURVE_CLIP;
    s.render.gain = 2.0;
    assert_true(tone_active(&s.render));
    double dim[3] = {linear_to_srgb(0.1), linear_to_srgb(0.2), linear_to_srgb(0.3)};
    tone_map(&s.render, dim);
    assert_true(fabs(srgb_to_linear(dim[0]) - 0.2) < 1e-9 && fabs(srgb_to_linear(dim[2]) - 0.6) < 1e-9);
}

/* The black-body table for the filmic curve (TONE_SCENE_LINEAR, with observer.effects = searchlight):
 * each texel decodes to the black body's linear colour, its luminance Y(T) / Y(T_ref) times the
 * grey within 4.5% (an 8-bit log2 over 24 stops: an eighth of a stop a step), wherever that is
 * above 2^-11; the reference temperature at the grey. */
static void test_linear_table(void **state)
{
    (void)state;
    const double reference = 6500.0;
    unsigned char rgba[4 * BLACKBODY_LUT_SIZE];
    blackbody_lut_fill_exposed(TONE_SCENE_LINEAR, reference, rgba);
    double ref_xyz[3];
    blackbody_xyz(reference, ref_xyz);
    int checked = 0;
    double worst = 0.0;
    for (int i = 0; i < BLACKBODY_LUT_SIZE; i++) {
        double t = blackbody_lut_temperature(i), xyz[3];
        blackbody_xyz(t, xyz);
        double want = xyz[1] / ref_xyz[1] * BLACKBODY_LINEAR_GREY;
        double texel[4] = {rgba[4 * i] / 255.0, rgba[4 * i + 1] / 255.0, rgba[4 * i + 2] / 255.0, rgba[4 * i + 3] / 255.0};
        double lin[3];
        blackbody_lut_decode(texel, lin);
        double got = 0.2126 * lin[0] + 0.7152 * lin[1] + 0.0722 * lin[2];
        /* below about 1900 K the colour leaves the gamut and loses luminance with its negative primary */
        if (want < exp2(-11.0) || t < 2000.0)
            continue;
        worst = fmax(worst, fabs(got / want - 1.0));
        checked++;
    }
    print_message("%d texels from 2000 K: luminance within %.1f%% of Y(T) / Y(T_ref) x the grey\n", checked, 100.0 * worst);
    assert_true(checked > 150 && worst < 0.045);
}

/* demo.scene's disk at the searchlight (colours brighter than white where the disk is hot) with
 * gain 1.7 and the filmic curve: the GPU's image against the reference's, the same outcomes and
 * the colours within the 8-bit levels of the black-body table's neighbouring texels; and different
 * from the image without the curve. */
static void test_gpu_against_reference(void **state)
{
    (void)state;
    static struct scene s;
    /* the disk alone: hc_render_both's GPU frame draws no stars of the CPU's pass */
    const char *const sets[] = {"observer.effects=searchlight", "render.tone_curve=filmic", "render.gain=1.7",
                                "render.samples=1", "sky.stars=0", "sky.milky_way=0", NULL};
    hc_load(&s, "demo", 160, 90, sets);
    struct cpu_image cpu;
    struct hc_gpu g;
    hc_render_both(&s, 160, 90, &cpu, &g);
    struct compare_result cr;
    hc_compare(&g.dump, &cpu.dump, &cr);
    print_message("filmic, gain 1.7: %ld outcomes differ, PSNR %.1f dB, mean |difference| %.3f %.3f %.3f /255\n",
                  cr.outcomes.differ, cr.psnr_db, cr.mean_abs_diff[0], cr.mean_abs_diff[1], cr.mean_abs_diff[2]);
    assert_int_equal(cr.outcomes.differ, 0);
    /* the same curve in float as in double: the colours agree as the untoned images do (60 dB here) */
    assert_true(cr.psnr_db >= 50.0);
    struct hc_gpu plain;
    s.render.tone_curve = TONE_CURVE_CLIP;
    s.render.gain = 1.0;
    hc_gpu_render(&s, &plain);
    long differ = 0;
    for (size_t i = 0; i < (size_t)s.render.width * s.render.height * 4; i++)
        differ += abs((int)plain.res.rgba[i] - (int)g.res.rgba[i]) > 2;
    print_message("%ld of the image's values differ from the image without the curve\n", differ);
    assert_true(differ > 1000);
    hc_gpu_free(&plain);
    cpu_image_free(&cpu);
    hc_gpu_free(&g);
}

/* star_sky.scene's point stars drawn by the CPU's pass after the GPU's rays, with gain 2 and the
 * filmic curve: the frame is read as floats and the curve applied after the stars, on the CPU
 * (render/frame.h), as the reference applies it: the same outcomes, the colours within the two star
 * passes' agreement, and brighter stars than without the gain. */
static void test_curve_after_cpu_stars(void **state)
{
    (void)state;
    static struct scene s;
    const char *const sets[] = {"render.tone_curve=filmic", "render.gain=2", "render.star_pass=cpu", NULL};
    hc_load(&s, "star_sky", 160, 90, sets);
    struct cpu_image cpu;
    hc_cpu_render(&s, &cpu);
    struct render_result res, plain;
    hc_frame(&s, RENDER_READ_STATE, &res);
    assert_null(res.color);
    struct dump gpu;
    assert_int_equal(result_to_dump(&res, &s, "gpu", &gpu), 0);
    struct compare_result cr;
    hc_compare(&gpu, &cpu.dump, &cr);
    print_message("CPU stars, filmic, gain 2: %ld outcomes differ, PSNR %.1f dB\n", cr.outcomes.differ, cr.psnr_db);
    assert_int_equal(cr.outcomes.differ, 0);
    assert_true(cr.psnr_db >= 40.0);
    s.render.tone_curve = TONE_CURVE_CLIP;
    s.render.gain = 1.0;
    hc_frame(&s, RENDER_READ_IMAGE, &plain);
    double lit = 0.0, unlit = 0.0;
    for (size_t i = 0; i < (size_t)s.render.width * s.render.height * 4; i++) {
        lit += (i % 4 != 3) * res.rgba[i];
        unlit += (i % 4 != 3) * plain.rgba[i];
    }
    print_message("the image's codes summed: %.0f with the gain and curve, %.0f without\n", lit, unlit);
    assert_true(lit > 1.2 * unlit);
    dump_free(&gpu);
    render_result_free(&res);
    render_result_free(&plain);
    cpu_image_free(&cpu);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_filmic_curve),
        cmocka_unit_test(test_hue_and_gain),
        cmocka_unit_test(test_linear_table),
        cmocka_unit_test(test_gpu_against_reference),
        cmocka_unit_test(test_curve_after_cpu_stars),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
