/* Anti-aliasing (render.samples): where a pixel's rays start, their average in linear light, and
 * that the average converges as stratified sampling should, on both engines and on the polygon
 * method of moving objects. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include "hard_cases.h"
#include "io/sample_average.h"
#include "render/frame.h"
#include "scene/pixel_samples.h"

/* Every pattern: offsets inside the pixel on the 1/1024 grid, one sample in each of the N columns and
 * N rows (n-rooks), symmetric about the centre (mean offset 0), the centre first exactly when N is
 * odd; for N = m^2 one sample in each cell of the m x m grid. */
static void test_sample_pattern(void **state)
{
    (void)state;
    struct pixel_samples p;
    for (int n = 1; n <= SCENE_MAX_SAMPLES; n++) {
        pixel_samples_make(n, &p);
        assert_int_equal(p.n, n);
        assert_int_equal(p.centre_included, n % 2);
        if (p.centre_included)
            assert_true(p.dx[0] == 0.0 && p.dy[0] == 0.0);
        int column[SCENE_MAX_SAMPLES] = {0}, row[SCENE_MAX_SAMPLES] = {0};
        double mean_x = 0.0, mean_y = 0.0;
        int m = (int)lrint(sqrt((double)n)), cells[16][16] = {{0}};
        for (int k = 0; k < n; k++) {
            double dx = p.dx[k], dy = p.dy[k];
            assert_true(dx >= -0.5 && dx < 0.5 && dy >= -0.5 && dy < 0.5);
            assert_true(dx * PIXEL_SAMPLE_GRID == floor(dx * PIXEL_SAMPLE_GRID));
            assert_true(dy * PIXEL_SAMPLE_GRID == floor(dy * PIXEL_SAMPLE_GRID));
            column[(int)floor((dx + 0.5) * n)]++;
            row[(int)floor((dy + 0.5) * n)]++;
            mean_x += dx / n;
            mean_y += dy / n;
            if (m * m == n)
                cells[(int)floor((dx + 0.5) * m)][(int)floor((dy + 0.5) * m)]++;
        }
        for (int i = 0; i < n; i++) {
            assert_int_equal(column[i], 1);
            assert_int_equal(row[i], 1);
        }
        assert_true(fabs(mean_x) < 1e-3 && fabs(mean_y) < 1e-3);
        for (int i = 0; m * m == n && i < n; i++)
            assert_int_equal(cells[i / m][i % m], 1);
    }
    /* four samples: the rotated grid */
    pixel_samples_make(4, &p);
    const double rgss[4][2] = {{-0.375, -0.125}, {-0.125, 0.375}, {0.125, -0.375}, {0.375, 0.125}};
    for (int k = 0; k < 4; k++)
        assert_true(p.dx[k] == rgss[k][0] && p.dy[k] == rgss[k][1]);
}

/* One image comes back unchanged; black and white average to the sRGB code of half the light (188),
 * not to 128. */
static void test_linear_average(void **state)
{
    (void)state;
    unsigned char image[4 * 256], out[4 * 256];
    for (int v = 0; v < 256; v++)
        for (int c = 0; c < 4; c++)
            image[4 * v + c] = (unsigned char)v;
    struct sample_average a;
    assert_int_equal(sample_average_init(&a, 256), 0);
    sample_average_add(&a, image, NULL);
    sample_average_write(&a, out, NULL);
    for (int v = 0; v < 256; v++)
        for (int c = 0; c < 3; c++)
            assert_int_equal(out[4 * v + c], v);
    sample_average_free(&a);
    unsigned char black[4] = {0, 0, 0, 255}, white[4] = {255, 255, 255, 255}, mean[4];
    assert_int_equal(sample_average_init(&a, 1), 0);
    sample_average_add(&a, black, NULL);
    sample_average_add(&a, white, NULL);
    sample_average_write(&a, mean, NULL);
    assert_int_equal(mean[0], 188);
    assert_int_equal(mean[3], 255);
    sample_average_free(&a);
}

/* The image of s on the GPU, as bentray render makes it (render_frame: every sample). */
static unsigned char *gpu_image(const struct scene *s)
{
    struct render_result res;
    struct error gl_err;
    if (render_frame(s, &(struct frame_request){.backend = "egl"}, &res, NULL, &gl_err) != 0)
        fail_msg("render: %s", gl_err.message);
    unsigned char *rgba = res.rgba;
    res.rgba = NULL;
    render_result_free(&res);
    return rgba;
}


/* The test scene's edges and checkerboards at 80 x 60: against 64 samples a pixel, the error falls
 * with N. Stratified sampling of an edge gives about N^-3/4 (jittered) to N^-1 (a rotated grid):
 * from 1 to 4 samples and from 4 to 16, at least a factor 1.6 each (4^-3/4 = 1/2.8, with room for
 * the pixels whose texture varies smoothly, where any N is already close). Measured on llvmpipe:
 * see the printed figures. */
static void test_gpu_converges(void **state)
{
    (void)state;
    static struct scene s;
    hc_load(&s, "test", 80, 60, NULL);
    size_t pixels = 80 * 60;
    s.render.samples = 64;
    unsigned char *reference = gpu_image(&s);
    const int counts[] = {1, 4, 16};
    double error[3];
    for (int c = 0; c < 3; c++) {
        s.render.samples = counts[c];
        unsigned char *image = gpu_image(&s);
        error[c] = image_rms_linear(image, reference, pixels);
        printf("samples %2d: rms error against 64 samples %.5f (linear light)\n", counts[c], error[c]);
        free(image);
    }
    assert_true(error[0] > 0.01);   /* the scene has edges: one ray a pixel is visibly off */
    assert_true(error[1] * 1.6 < error[0]);
    assert_true(error[2] * 1.6 < error[1]);
    free(reference);
}

/* The reference engine averages the same rays the same way: with 4 samples its image is the GPU's
 * to within what one ray a pixel already differs by (float against double, at silhouettes). */
static void test_engines_agree(void **state)
{
    (void)state;
    static struct scene s;
    hc_load(&s, "test", 64, 48, NULL);
    size_t pixels = 64 * 48;
    double rms[2];
    for (int c = 0; c < 2; c++) {
        s.render.samples = c == 0 ? 1 : 4;
        struct cpu_image cpu;
        hc_cpu_render(&s, &cpu);
        unsigned char *gpu = gpu_image(&s);
        rms[c] = image_rms_linear(cpu.rgba, gpu, pixels);
        free(gpu);
        cpu_image_free(&cpu);
    }
    printf("cpu against gpu: rms %.5f with 1 sample, %.5f with 4\n", rms[0], rms[1]);
    assert_true(rms[1] < 0.01);
    assert_true(rms[1] <= 1.5 * rms[0] + 1e-3);
}

/* The dump follows the pixel's centre: its rays are bit for bit those of one sample a pixel, while
 * the image is not. */
static void test_dump_follows_centre(void **state)
{
    (void)state;
    static struct scene s;
    hc_load(&s, "schwarzschild", 48, 36, NULL);
    struct render_result one, four;
    struct error gl_err;
    assert_int_equal(render_frame(&s, &(struct frame_request){.backend = "egl", .reads = RENDER_READ_STATE}, &one, NULL, &gl_err), 0);
    s.render.samples = 4;
    assert_int_equal(render_frame(&s, &(struct frame_request){.backend = "egl", .reads = RENDER_READ_STATE}, &four, NULL, &gl_err), 0);
    size_t n = (size_t)48 * 36 * 4;
    assert_memory_equal(one.position, four.position, n * sizeof(float));
    assert_memory_equal(one.velocity, four.velocity, n * sizeof(float));
    assert_memory_equal(one.hit, four.hit, n * sizeof(float));
    assert_true(memcmp(one.rgba, four.rgba, n) != 0);
    render_result_free(&one);
    render_result_free(&four);
}

/* One frame of s with every ray started (dx, dy) pixels off its centre. */
static unsigned char *shifted_image(const struct scene *s, double dx, double dy)
{
    struct error gl_err, e;
    struct renderer *r = renderer_create(hc_context(), s, &gl_err);
    if (!r)
        fail_msg("renderer: %s", gl_err.message);
    renderer_set_subpixel(r, dx, dy);
    struct render_result res;
    if (renderer_run(r, s, 0, 0, s->render.width, s->render.height, NULL, NULL, &e) != 0 ||
        renderer_read(r, &res, RENDER_READ_IMAGE, &e) != 0)
        fail_msg("render: %s", e.message);
    renderer_destroy(r);
    unsigned char *rgba = res.rgba;
    res.rgba = NULL;
    render_result_free(&res);
    return rgba;
}

/* Moving bodies drawn as polygons move with the sample as the traced rays do: the polygon image of
 * a sample a third of a pixel right and up matches the rays' image of that sample better than the
 * rays' image of the opposite one (an offset applied the wrong way round would swap the two). */
static void test_polygons_follow_samples(void **state)
{
    (void)state;
    static struct scene rays, polygons;
    hc_load(&rays, "three_ships", 96, 72, NULL);
    const char *const sets[] = {"render.moving_objects=polygons", NULL};
    hc_load(&polygons, "three_ships", 96, 72, sets);
    size_t pixels = 96 * 72;
    unsigned char *p = shifted_image(&polygons, 0.33, 0.33);
    unsigned char *same = shifted_image(&rays, 0.33, 0.33);
    unsigned char *opposite = shifted_image(&rays, -0.33, -0.33);
    double near = image_rms_linear(p, same, pixels), far = image_rms_linear(p, opposite, pixels);
    printf("polygons against rays: rms %.5f at the same offset, %.5f at the opposite one\n", near, far);
    assert_true(near < far);
    free(p);
    free(same);
    free(opposite);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sample_pattern),
        cmocka_unit_test(test_linear_average),
        cmocka_unit_test(test_gpu_converges),
        cmocka_unit_test(test_engines_agree),
        cmocka_unit_test(test_dump_follows_centre),
        cmocka_unit_test(test_polygons_follow_samples),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
