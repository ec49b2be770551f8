/* The searchlight shows (observer.exposure = scene): starflight's 6000 K sky, looked at straight
 * ahead of the motion at 0.6 c, is brighter than at rest and looked at straight behind, darker, on
 * both engines; with the paper's fixed 1500 K exposure the sky is white at rest and barely changes. */
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

/* starflight at speed beta (0: at rest) along its view (+1: ahead, -1: behind), on the GPU or CPU. */
static double measure(const char *exposure, double beta, int engine_cpu)
{
    static struct scene s;
    char velocity[64], exp[64];
    snprintf(velocity, sizeof velocity, "observer.velocity=0 0 %g", -beta);
    snprintf(exp, sizeof exp, "observer.exposure=%s", exposure);
    const char *const sets[] = {velocity, exp, NULL};
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_searchlight_shows),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
