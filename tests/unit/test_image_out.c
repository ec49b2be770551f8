/* Images beyond 8-bit sRGB (io/image_out.h): 16-bit PNG and linear PFM from the float colour the
 * renderer keeps on request, a transparent sky (render.sky_alpha), on both engines. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <png.h>
#include <unistd.h>
#include "hard_cases.h"
#include "io/image_out.h"
#include "io/sample_average.h"
#include "render/frame.h"

/* The 16-bit samples of a PNG (RGBA), rows top-down, as stored. */
static uint16_t *read_png16(const char *path, int *w, int *h)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png)))
        fail_msg("libpng could not read %s", path);
    png_init_io(png, f);
    png_read_png(png, info, PNG_TRANSFORM_IDENTITY, NULL);
    assert_int_equal(png_get_bit_depth(png, info), 16);
    assert_int_equal(png_get_color_type(png, info), PNG_COLOR_TYPE_RGB_ALPHA);
    *w = (int)png_get_image_width(png, info);
    *h = (int)png_get_image_height(png, info);
    png_bytepp rows = png_get_rows(png, info);
    uint16_t *out = malloc((size_t)*w * *h * 4 * sizeof *out);
    for (int y = 0; y < *h; y++)
        for (int i = 0; i < *w * 4; i++)
            out[(size_t)y * *w * 4 + i] = (uint16_t)(rows[y][2 * i] << 8 | rows[y][2 * i + 1]);
    png_destroy_read_struct(&png, &info, NULL);
    fclose(f);
    return out;
}

/* 16-bit PNG: each float rounded to the nearest of 65536 levels and clamped; PFM: linear light,
 * rows bottom-up, little-endian, brighter than white kept. */
static void test_writers(void **state)
{
    (void)state;
    const float color[2 * 2 * 4] = {0.0f, 0.5f, 1.0f, 1.0f, 0.25f, 2.0f, -1.0f, 0.5f,
                                    0.75f, 0.1f, 0.9f, 0.0f, 1.0f, 1.0f, 1.0f, 1.0f};
    unsigned char rgba8[16] = {0};
    char dir[] = "/tmp/bentray-image-XXXXXX", png[64], pfm[64];
    struct error e;
    assert_non_null(mkdtemp(dir));
    snprintf(png, sizeof png, "%s/a.png", dir);
    snprintf(pfm, sizeof pfm, "%s/a.pfm", dir);
    assert_int_equal(image_write(png, IMAGE_PNG16, 2, 2, rgba8, color, 0, PNG_COMPRESSION_FAST, &e), 0);
    int w, h;
    uint16_t *v = read_png16(png, &w, &h);
    assert_int_equal(w, 2);
    assert_int_equal(h, 2);
    for (int i = 0; i < 16; i++) {
        double c = color[i] < 0.0f ? 0.0 : color[i] > 1.0f ? 1.0 : color[i];
        assert_int_equal(v[i], lrint(c * 65535.0));
    }
    free(v);
    assert_int_equal(image_write(pfm, IMAGE_PFM, 2, 2, rgba8, color, 0, PNG_COMPRESSION_FAST, &e), 0);
    FILE *f = fopen(pfm, "rb");
    char header[16];
    assert_int_equal(fread(header, 1, 12, f), 12);
    assert_memory_equal(header, "PF\n2 2\n-1.0\n", 12);
    float px[12];
    assert_int_equal(fread(px, sizeof(float), 12, f), 12);
    fclose(f);
    /* the first row in the file is the image's bottom row: pixels 2 and 3 */
    assert_true(fabs(px[0] - srgb_to_linear(0.75)) < 1e-6);
    assert_true(fabs(px[3] - 1.0) < 1e-6);
    /* the top row: 0, 0.5, 1 and 0.25, 2 (brighter than white, kept), -1 (cut to 0) */
    assert_true(px[6] == 0.0f && fabs(px[7] - srgb_to_linear(0.5)) < 1e-6 && fabs(px[8] - 1.0) < 1e-6);
    assert_true(px[10] > 4.0f && px[11] == 0.0f);
    /* an existing file without overwrite: the user's error, the file kept */
    assert_int_equal(image_write(pfm, IMAGE_PFM, 2, 2, rgba8, color, 0, PNG_COMPRESSION_FAST, &e), -1);
    assert_non_null(strstr(e.message, "refusing to replace existing file"));
    assert_non_null(strstr(e.message, pfm));
    assert_int_equal(e.status, ERROR_INPUT);
    unlink(png);
    unlink(pfm);
    rmdir(dir);
    /* into a directory that is not there: the user's error too */
    assert_int_equal(image_write(pfm, IMAGE_PFM, 2, 2, rgba8, color, 0, PNG_COMPRESSION_FAST, &e), -1);
    assert_non_null(strstr(e.message, "No such file"));
    assert_int_equal(e.status, ERROR_INPUT);
    assert_int_equal(image_write(png, IMAGE_PFM, 2, 2, rgba8, NULL, 0, PNG_COMPRESSION_FAST, &e), -1);
    assert_non_null(strstr(e.message, "no float colour"));
    enum image_format fmt;
    assert_int_equal(image_format_of("x.jpg", 8, &fmt, &e), -1);
    assert_non_null(strstr(e.message, "bentray writes PNG"));
    assert_int_equal(e.status, ERROR_INPUT);
    assert_int_equal(image_format_of("x.PFM", 8, &fmt, &e), 0);
    assert_int_equal(fmt, IMAGE_PFM);
    assert_int_equal(image_format_of("x.pfm", 16, &fmt, &e), -1);
    assert_int_equal(e.status, ERROR_INPUT);
    assert_int_equal(image_format_of("-", 16, &fmt, &e), 0);
    assert_int_equal(fmt, IMAGE_PNG16);
}

static void gpu_frame(const struct scene *s, struct render_result *res)
{
    struct error gl_err;
    struct frame_request req = {.backend = "egl", .hdr = 1};
    if (render_frame(s, &req, res, NULL, &gl_err) != 0)
        fail_msg("render: %s", gl_err.message);
}

/* The float colour is the 8-bit image before it was clamped and rounded: the same where it lies in
 * [0, 1], and above 1 where the searchlight (three_ships seen at 0.9 c ahead, its sky taken as RGB)
 * brightens the sky by D^4. */
static void test_float_colour_is_the_image(void **state)
{
    (void)state;
    static struct scene s;
    const char *const sets[] = {"observer.velocity=0 0 -0.9", "observer.effects=searchlight", "sky.temperature=0",
                                "render.samples=1", NULL};
    hc_load(&s, "three_ships", 48, 36, sets);
    struct render_result res;
    gpu_frame(&s, &res);
    assert_non_null(res.color);
    int brighter = 0;
    for (int i = 0; i < 48 * 36 * 4; i++) {
        assert_int_equal(res.rgba[i], unorm8(res.color[i]));
        brighter += (i % 4 != 3) && res.color[i] > 1.0f;
    }
    printf("  %d colour values brighter than white\n", brighter);
    assert_true(brighter > 0);
    render_result_free(&res);
}

/* render.sky_alpha = 0: transparent where rays reached the sky, opaque on objects and in the
 * shadow, on both engines; with 4 samples an edge pixel is partly covered. */
static void test_transparent_sky(void **state)
{
    (void)state;
    static struct scene s;
    const char *const sets[] = {"render.sky_alpha=0", NULL};
    hc_load(&s, "schwarzschild", 48, 36, sets);
    struct render_result res;
    struct cpu_image cpu;
    gpu_frame(&s, &res);
    hc_cpu_render(&s, &cpu);
    long sky = 0, partial = 0;
    for (int i = 0; i < 48 * 36; i++) {
        int32_t o = cpu.dump.records[i].outcome;
        unsigned char want = o == DUMP_SKY ? 0 : 255;
        assert_int_equal(cpu.rgba[4 * i + 3], want);
        sky += o == DUMP_SKY;
    }
    long agree = 0;
    for (int i = 0; i < 48 * 36; i++)
        agree += res.rgba[4 * i + 3] == cpu.rgba[4 * i + 3];
    assert_true(sky > 0);
    assert_true(agree >= 48 * 36 - 2);   /* a silhouette pixel may fall on either side */
    render_result_free(&res);
    cpu_image_free(&cpu);
    s.render.samples = 4;
    gpu_frame(&s, &res);
    for (int i = 0; i < 48 * 36; i++)
        partial += res.rgba[4 * i + 3] > 0 && res.rgba[4 * i + 3] < 255;
    printf("  %ld sky pixels, %ld partly covered with 4 samples\n", sky, partial);
    assert_true(partial > 0);
    render_result_free(&res);
}

/* The CPU reference's float colour is the GPU's to float precision where their rays agree. */
static void test_engines_agree_in_float(void **state)
{
    (void)state;
    static struct scene s;
    hc_load(&s, "test", 40, 30, NULL);
    struct render_result res;
    gpu_frame(&s, &res);
    struct cpu_render_options o = {.threads = 0, .progress = PROGRESS_NONE, .hdr = 1};
    struct error e;
    ref_options_default(&o.ref, &s);
    struct cpu_image cpu;
    assert_int_equal(cpu_render(&s, &o, &cpu, &e), 0);
    assert_non_null(cpu.color);
    double worst = 0.0;
    long far = 0;
    for (int i = 0; i < 40 * 30 * 4; i++) {
        double d = fabs((double)cpu.color[i] - res.color[i]);
        worst = d > worst ? d : worst;
        far += d > 0.02;
    }
    printf("  largest difference %.3g, %ld values off by more than 0.02 (silhouettes)\n", worst, far);
    assert_true(far <= 40 * 30 * 4 / 100);
    render_result_free(&res);
    cpu_image_free(&cpu);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_writers),
        cmocka_unit_test(test_float_colour_is_the_image),
        cmocka_unit_test(test_transparent_sky),
        cmocka_unit_test(test_engines_agree_in_float),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
