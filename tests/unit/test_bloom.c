/* Bloom ([render] bloom and bloom_radius, results/bloom.h): the point-spread's light kept, its
 * symmetry and its fall with distance, an evenly lit image left even up to its edges, and both
 * engines' images with it, through the frame's own path (render_frame) and the reference's. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include "hard_cases.h"
#include "io/sample_average.h"
#include "results/bloom.h"
#include "results/tone.h"

#define SIDE 513
#define MID (SIDE / 2)

static double at(const float *img, int x, int y)
{
    return img[3 * ((size_t)y * SIDE + x)];
}

/* One very bright pixel in a black image: the light of the whole image kept (the widest Gaussian's
 * reach stays inside it), (1 - bloom) of it left at the pixel, the halo's centre at the pixel, the
 * halo falling at every step out, about as 1 / r^2 between the narrowest and the widest sigma (a
 * slope of -2 on a log-log plot, within 0.5), and the same along x and y and on either side within
 * 10% out to the widest sigma: the wide Gaussians are drawn on coarser images of a pyramid, whose grid a point of light
 * meets at one of its phases (the halo's centre and light do not depend on it; its shape a little). */
/* The checks above for a point at (px, py); returns how far the halo departs from symmetry within
 * the widest sigma (32 pixels). Beyond it the widest Gaussian alone is left, drawn on an image 16
 * times coarser and interpolated back: within 25% out to 64 pixels, where a pixel holds under 2e-6
 * of the point's light, and only printed further out. */
static double point_spread_at(const struct scene *s, int px, int py)
{
    static float in[3 * SIDE * SIDE], out[3 * SIDE * SIDE];
    memset(in, 0, sizeof in);
    const double light = 1000.0;
    for (int c = 0; c < 3; c++)
        in[3 * (py * SIDE + px) + c] = (float)light;
    assert_int_equal(bloom_linear(&s->render, SIDE, SIDE, in, out), 0);
    double total = 0.0, cx = 0.0, cy = 0.0;
    for (int y = 0; y < SIDE; y++)
        for (int x = 0; x < SIDE; x++) {
            total += at(out, x, y);
            cx += x * at(out, x, y);
            cy += y * at(out, x, y);
        }
    cx = cx / total - px;
    cy = cy / total - py;
    print_message("at %d %d: light kept %.7f of the pixel's; at the pixel %.4f; the halo's centre off by %.2g %.2g "
                  "pixels\n", px, py, total / light, at(out, px, py) / light, cx, cy);
    assert_true(fabs(total / light - 1.0) < 1e-5);
    assert_true(fabs(cx) < 1e-3 && fabs(cy) < 1e-3);
    assert_true(at(out, px, py) > (1.0 - s->render.bloom) * light);
    double last = at(out, px, py), worst = 0.0, worst_tail = 0.0;
    int reach = 0;
    for (int d = 1; d < 160; d++) {
        double right = at(out, px + d, py), values[3] = {at(out, px - d, py), at(out, px, py + d), at(out, px, py - d)};
        if (right <= 1e-7 * light)
            continue;
        for (int k = 0; k < 3; k++) {
            if (d <= 32)
                worst = fmax(worst, fabs(values[k] / right - 1.0));
            if (d <= 64)
                worst_tail = fmax(worst_tail, fabs(values[k] / right - 1.0));
        }
        assert_true(right < last);
        reach = d;
        last = right;
    }
    double slope = log(at(out, px + 32, py) / at(out, px + 4, py)) / log(32.0 / 4.0);
    print_message("  the halo the same each way within %.2f%% to 32 pixels, %.2f%% to 64, out to %d pixels; it falls as "
                  "r^%.2f from 4 to 32 pixels\n", 100.0 * worst, 100.0 * worst_tail, reach, slope);
    assert_true(worst_tail < 0.25);
    assert_true(reach >= 90);   /* 3 sigma of the widest, where its kernel ends */
    assert_true(slope > -2.5 && slope < -1.5);
    return worst;
}

static void test_point_spread(void **state)
{
    (void)state;
    struct scene s;
    scene_defaults(&s);
    s.render.bloom = 0.25;
    s.render.bloom_radius = 2.0 / SIDE;   /* sigmas 2, 4, 8, 16 and 32 pixels */
    assert_true(bloom_active(&s.render));
    double sigma[BLOOM_LEVELS];
    bloom_sigmas(&s.render, SIDE, sigma);
    assert_true(fabs(sigma[0] - 2.0) < 1e-12 && fabs(sigma[BLOOM_LEVELS - 1] - 32.0) < 1e-12);
    /* the pyramid's grids met at several phases */
    static const int points[][2] = {{MID, MID}, {MID + 1, MID + 5}, {MID + 7, MID - 3}, {MID - 8, MID + 11}};
    double worst = 0.0;
    for (size_t k = 0; k < sizeof points / sizeof points[0]; k++)
        worst = fmax(worst, point_spread_at(&s, points[k][0], points[k][1]));
    assert_true(worst < 0.10);
}

/* An evenly lit image stays even, edges and corners too, with the whole light spread and the
 * widest sigma far past the image; bloom 0 changes nothing. */
static void test_even_light(void **state)
{
    (void)state;
    struct scene s;
    scene_defaults(&s);
    assert_false(bloom_active(&s.render));
    s.render.bloom = 1.0;
    s.render.bloom_radius = 0.25;
    static float in[3 * SIDE * SIDE], out[3 * SIDE * SIDE];
    for (size_t i = 0; i < 3 * SIDE * SIDE; i++)
        in[i] = 0.5f;
    assert_int_equal(bloom_linear(&s.render, SIDE, SIDE, in, out), 0);
    for (size_t i = 0; i < 3 * SIDE * SIDE; i++)
        assert_true(fabsf(out[i] - 0.5f) < 1e-5f);
    /* a one-pixel image and a one-row image */
    assert_int_equal(bloom_linear(&s.render, 1, 1, in, out), 0);
    assert_true(fabsf(out[0] - 0.5f) < 1e-6f);
    assert_int_equal(bloom_linear(&s.render, SIDE, 1, in, out), 0);
    assert_true(fabsf(out[3 * (SIDE - 1)] - 0.5f) < 1e-5f);
    s.render.bloom = 0.0;
    for (size_t i = 0; i < 3 * SIDE; i++)
        in[i] = (float)(i % 7) * 0.3f;
    assert_int_equal(bloom_linear(&s.render, SIDE, 1, in, out), 0);
    for (size_t i = 0; i < 3 * SIDE; i++)
        assert_true(out[i] == in[i]);
}

/* Without spread (bloom 0) the image's codes are those of the plain path, sRGB-encoded values from
 * below 0 to far beyond white and NaN: each channel clipped, or through the filmic curve and a
 * gain as tone_map does them (results/tone.h); the same code, or the next where a value lies within
 * the decoding table's interpolation (2e-7) of a code's edge. */
static void test_codes(void **state)
{
    (void)state;
    struct scene s;
    scene_defaults(&s);
    enum { N = 4000 };
    static float color[4 * N];
    static unsigned char rgba[4 * N];
    for (int i = 0; i < N; i++)
        for (int c = 0; c < 4; c++)
            color[4 * i + c] = (float)(-0.5 + 3.5 * (i * 4 + c) / (4.0 * N));
    color[4 * 17] = NAN;
    for (int curve = 0; curve < 2; curve++) {
        s.render.tone_curve = curve ? TONE_CURVE_FILMIC : TONE_CURVE_CLIP;
        s.render.gain = curve ? 1.7 : 1.0;
        assert_int_equal(bloom_image(&s.render, N, 1, color, rgba), 0);
        int exact = 0;
        for (int i = 0; i < N; i++) {
            double rgb[3];
            for (int c = 0; c < 3; c++)
                rgb[c] = isnan(color[4 * i + c]) ? 0.0 : color[4 * i + c];
            if (curve)
                tone_map(&s.render, rgb);
            for (int c = 0; c < 3; c++) {
                int want = unorm8(rgb[c]), got = rgba[4 * i + c];
                assert_true(abs(want - got) <= 1);
                exact += want == got;
            }
            assert_int_equal(rgba[4 * i + 3], unorm8(color[4 * i + 3]));
        }
        print_message("%s: %d of %d codes exact\n", curve ? "filmic, gain 1.7" : "clip", exact, 3 * N);
        assert_true(exact >= 3 * N - 10);
    }
}

static double luminance8(const unsigned char *p)
{
    return 0.2126 * srgb_to_linear(p[0] / 255.0) + 0.7152 * srgb_to_linear(p[1] / 255.0) +
           0.0722 * srgb_to_linear(p[2] / 255.0);
}

/* demo.scene's disk far brighter than white (gain 8, the filmic curve) with bloom 0.3: the frame's
 * own path on the GPU (render_frame, the colour read as floats) against the reference, the same
 * outcomes and colours within the untoned images' agreement; the dump's colours the image's; the
 * sky beside the disk brighter than without bloom (its halo) and the light of the whole image
 * about kept. */
static void test_both_engines(void **state)
{
    (void)state;
    static struct scene s;
    const char *const sets[] = {"render.gain=8", "render.samples=1", "render.bloom=0.3", NULL};
    hc_load(&s, "demo", 160, 90, sets);
    struct cpu_image cpu;
    hc_cpu_render(&s, &cpu);
    assert_null(cpu.color);   /* kept only for a float image */
    struct render_result res;
    hc_frame(&s, RENDER_READ_STATE, &res);
    assert_null(res.color);
    assert_true(res.bloom_seconds > 0.0);
    struct dump gpu;
    assert_int_equal(result_to_dump(&res, &s, "gpu", &gpu), 0);
    struct compare_result cr;
    hc_compare(&gpu, &cpu.dump, &cr);
    print_message("bloom 0.3, gain 8: %ld outcomes differ, PSNR %.1f dB\n", cr.outcomes.differ, cr.psnr_db);
    assert_int_equal(cr.outcomes.differ, 0);
    assert_true(cr.psnr_db >= 45.0);
    size_t n = (size_t)s.render.width * s.render.height;
    for (size_t i = 0; i < n; i++)
        assert_memory_equal(cpu.dump.records[i].rgba, cpu.rgba + 4 * i, 4);
    /* without bloom: the sky next to the disk is darker, the disk itself brighter */
    struct cpu_image plain;
    s.render.bloom = 0.0;
    hc_cpu_render(&s, &plain);
    long sky_brighter = 0, sky = 0;
    double with = 0.0, without = 0.0;
    for (size_t i = 0; i < n; i++) {
        with += luminance8(cpu.rgba + 4 * i);
        without += luminance8(plain.rgba + 4 * i);
        if (plain.dump.records[i].outcome != DUMP_SKY)
            continue;
        sky++;
        sky_brighter += luminance8(cpu.rgba + 4 * i) > luminance8(plain.rgba + 4 * i) + 0.01;
    }
    print_message("%ld of %ld sky pixels brighter by more than 0.01 with bloom; the image's light %.3f of its "
                  "light without\n", sky_brighter, sky, with / without);
    assert_true(sky_brighter * 4 > sky);
    cpu_image_free(&plain);
    cpu_image_free(&cpu);
    dump_free(&gpu);
    render_result_free(&res);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_point_spread),
        cmocka_unit_test(test_even_light),
        cmocka_unit_test(test_codes),
        cmocka_unit_test(test_both_engines),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
