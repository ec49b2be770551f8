/* The searchlight shows (observer.exposure = scene): a sky of one black body (starflight's flight
 * under its former 3000 K star cube map, which spreads its light evenly over the view), looked at
 * straight ahead of the motion at 0.6 c, is brighter than at rest and looked at straight behind,
 * darker, on both engines; with the paper's fixed 1500 K exposure the sky is white at rest and
 * barely changes. (starflight's own point stars put their light in a few pixels each, whose mean
 * over the view is not the sky's brightness.) */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include "hard_cases.h"
#include "render/frame.h"

/* Mean of the 8-bit colour values over the middle ninth of the image. */
static double centre_mean(const unsigned char *rgba, int w, int h)
{
    double sum = 0.0;
    long n = 0;
    for (int y = h / 3; y < 2 * h / 3; y++)
        for (int x = w / 3; x < 2 * w / 3; x++, n++)
            sum += (rgba[4 * (y * w + x)] + rgba[4 * (y * w + x) + 1] + rgba[4 * (y * w + x) + 2]) / 3.0;
    return sum / n;
}

/* The one black-body sky of the first test. */
static const char *const black_body_sky[] = {"sky.type=cubemap", "sky.cubemap=../sky/stars", "sky.temperature=3000",
                                             "sky.stars=0", "sky.milky_way=0", NULL};

/* starflight at speed beta (0: at rest) along its view (+1: ahead, -1: behind), on the GPU or CPU,
 * its sky as the scene has it or as sky (NULL-terminated --set words). */
static double measure_sky(const char *exposure, double beta, int engine_cpu, const char *const *sky)
{
    static struct scene s;
    char velocity[64], exp[64];
    snprintf(velocity, sizeof velocity, "observer.velocity=0 0 %g", -beta);
    snprintf(exp, sizeof exp, "observer.exposure=%s", exposure);
    const char *sets[12] = {velocity, exp};
    for (int i = 0; sky && sky[i] && i < 9; i++)
        sets[2 + i] = sky[i];
    hc_load(&s, "starflight", 80, 60, sets);
    double mean;
    if (engine_cpu) {
        struct cpu_image cpu;
        hc_cpu_render(&s, &cpu);
        mean = centre_mean(cpu.rgba, 80, 60);
        cpu_image_free(&cpu);
    } else {
        struct render_result res;
        struct error gl_err;
        if (render_frame(&s, &(struct frame_request){.backend = "egl"}, &res, NULL, &gl_err) != 0)
            fail_msg("render: %s", gl_err.message);
        mean = centre_mean(res.rgba, 80, 60);
        render_result_free(&res);
    }
    return mean;
}

static double measure(const char *exposure, double beta, int engine_cpu)
{
    return measure_sky(exposure, beta, engine_cpu, black_body_sky);
}

static void test_searchlight_shows(void **state)
{
    (void)state;
    for (int cpu = 0; cpu < 2; cpu++) {
        double rest = measure("scene", 0.0, cpu), ahead = measure("scene", 0.6, cpu), behind = measure("scene", -0.6, cpu);
        printf("  %s, exposure scene: centre mean %.1f at rest, %.1f ahead at 0.6 c, %.1f behind\n", cpu ? "cpu" : "gpu",
               rest, ahead, behind);
        assert_true(ahead > 1.5 * rest);
        assert_true(behind < 0.5 * rest);
        assert_true(rest > 5.0);
    }
    double rest = measure("paper", 0.0, 0), ahead = measure("paper", 0.6, 0);
    printf("  gpu, exposure paper: centre mean %.1f at rest, %.1f ahead at 0.6 c\n", rest, ahead);
    assert_true(ahead < 1.2 * rest);
}

/* starflight's own point stars in a coarse image (80x60, a pixel 1.25 degrees wide), where the
 * aberration ahead gathers each pixel's sky into a footprint wider than the stars are looked for
 * (STAR_FOOTPRINT_MAX_RAD): the centre grows brighter ahead, on the CPU's star pass and the GPU's,
 * not dark (those pixels once showed no star at all: a black disk ahead). */
static void test_point_stars_ahead(void **state)
{
    (void)state;
    static const char *const cpu_pass[] = {"sky.milky_way=0", NULL};
    static const char *const gpu_pass[] = {"sky.milky_way=0", "render.star_pass=gpu", NULL};
    const char *const *passes[2] = {cpu_pass, gpu_pass};
    for (int k = 0; k < 2; k++) {
        double rest = measure_sky("scene", 0.0, 0, passes[k]), ahead = measure_sky("scene", 0.6, 0, passes[k]);
        printf("  point stars, %s pass: centre mean %.1f at rest, %.1f ahead at 0.6 c\n", k ? "gpu" : "cpu", rest,
               ahead);
        assert_true(rest > 5.0);
        assert_true(ahead > 1.5 * rest);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_searchlight_shows),
        cmocka_unit_test(test_point_stars_ahead),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
