/* Special relativity of the moving observer (Müller, Grottel and Weiskopf 2010) and the frequency
 * shift between static observers in Schwarzschild space-time: the formulas against independent
 * closed forms and the paper's numbers, the GPU's aberrated camera rays against the exact formula
 * per pixel, the black-body colours of both engines against each other, and the static image
 * untouched when the observer rests with every effect off. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include "hard_cases.h"
#include "physics/blackbody.h"
#include "physics/relativity.h"

/* closed forms in double: a few roundings apart */
#define FORMULA_TOL 1e-12

static double angle_between(vec3d a, vec3d b)
{
    return atan2(v3_len(v3_cross(a, b)), v3_dot(a, b));
}

/* The aberration formula in its textbook form: the angle to the direction of motion changes as
 * cos(theta) = (cos(theta') - beta) / (1 - beta cos(theta')), the azimuth about beta does not.
 * Evaluated as tan(theta / 2) = sqrt((1 + beta) / (1 - beta)) tan(theta' / 2), which keeps its
 * precision ahead, where the cosine form cancels. */
static vec3d aberration_by_angle(vec3d beta, vec3d d_observer)
{
    double b = v3_len(beta);
    vec3d axis = v3_scale(beta, 1.0 / b);
    double c_obs = v3_dot(d_observer, axis);
    vec3d across = v3_axpy(-c_obs, axis, d_observer);
    double across_len = v3_len(across);
    double theta_obs = atan2(across_len, c_obs);
    double theta = 2.0 * atan(sqrt((1.0 + b) / (1.0 - b)) * tan(0.5 * theta_obs));
    if (!(across_len > 0.0))
        return v3_scale(axis, cos(theta));
    return v3_add(v3_scale(axis, cos(theta)), v3_scale(across, sin(theta) / across_len));
}

static void test_aberration_formula(void **state)
{
    (void)state;
    static const double speeds[] = {0.1, 0.5, 0.9, 0.99, BETA_MAX};
    static const vec3d axes[] = {{0, 0, -1}, {1, 0, 0}, {0.3, -0.8, 0.52}};
    for (int a = 0; a < 3; a++)
        for (int k = 0; k < 5; k++) {
            vec3d beta = v3_scale(v3_normalize(axes[a]), speeds[k]);
            for (int t = 0; t <= 12; t++) {
                double th = PI_D * t / 12.0;
                vec3d perp = v3_perpendicular(v3_normalize(beta));
                vec3d d = v3_add(v3_scale(v3_normalize(beta), cos(th)), v3_scale(perp, sin(th)));
                vec3d got = aberrate_to_scene(beta, d);
                assert_true(fabs(v3_len(got) - 1.0) <= 1e-12);          /* already a unit vector */
                double err = angle_between(got, aberration_by_angle(beta, d));
                if (!(err <= 1e-9))
                    fail_msg("beta %g axis %d theta' %g: %.3g rad from the angle formula", speeds[k], a, th, err);
                /* and back */
                assert_true(angle_between(aberrate_to_observer(beta, got), d) <= 1e-9);
            }
        }
    /* at rest nothing changes, exactly */
    vec3d d = v3_normalize(v3(0.2, -0.4, -1.0));
    vec3d same = aberrate_to_scene(v3(0, 0, 0), d);
    assert_true(same.x == d.x && same.y == d.y && same.z == d.z);
}

/* Section 3.3: a 6000 K black body approaching at 0.2 c appears at 7348 K, receding at 4899 K. */
static void test_paper_temperatures(void **state)
{
    (void)state;
    vec3d beta = v3(0.0, 0.0, 0.2);
    double approach = doppler_observer(beta, v3(0, 0, 1));    /* looking where it flies */
    double recede = doppler_observer(beta, v3(0, 0, -1));
    assert_true(fabs(approach - sqrt(1.2 / 0.8)) <= FORMULA_TOL);
    assert_true(fabs(recede - sqrt(0.8 / 1.2)) <= FORMULA_TOL);
    assert_int_equal(lround(doppler_temperature(6000.0, approach)), 7348);
    assert_int_equal(lround(doppler_temperature(6000.0, recede)), 4899);
    /* transverse in the observer's frame: 1 / gamma, the time dilation of the source */
    double across = doppler_observer(beta, v3(1, 0, 0));
    assert_true(fabs(across - sqrt(1.0 - 0.04)) <= FORMULA_TOL);
}

/* An emitter at r seen by a static observer far away: sqrt(1 - 2M/r); the inverse on the way in. */
static void test_gravitational_shift(void **state)
{
    (void)state;
    const double mass = 0.7;
    static const double radii[] = {1.5, 2.1, 3.0, 10.0, 1e6};
    for (int k = 0; k < 5; k++) {
        double r = radii[k];
        assert_true(fabs(gravitational_shift(mass, r, INFINITY) - sqrt(1.0 - 2.0 * mass / r)) <= FORMULA_TOL);
        assert_true(fabs(gravitational_shift(mass, INFINITY, r) * sqrt(1.0 - 2.0 * mass / r) - 1.0) <= FORMULA_TOL);
        /* static to static: the product of the two legs through infinity */
        double via = gravitational_shift(mass, r, INFINITY) * gravitational_shift(mass, INFINITY, 4.0);
        assert_true(fabs(gravitational_shift(mass, r, 4.0) - via) <= FORMULA_TOL);
    }
    assert_true(gravitational_shift(0.0, 0.0, INFINITY) == 1.0);   /* no mass: no shift anywhere */
}

/* The flat test scene without objects: every ray is sky and keeps its first direction. */
static void load_sky_only(struct scene *s, int w, int h, const char *const *sets)
{
    hc_load(s, "test", w, h, sets);
    s->n_objects = 0;
    hc_validate(s);
}

/* Every pixel's ray on the GPU against the angle formula in double. The tolerance: the GPU forms the
 * view direction and the boost in fp32 (1.5e-7 rad measured up to 0.9 c); the boost magnifies the
 * angle of rays ahead by sqrt((1+b)/(1-b)) (14 at 0.99 c) and cancels in d + boost * beta, so 0.99 c
 * gets 1e-5 rad (7e-6 measured): a few thousandths of a pixel at any size the kiosk shows. */
static void test_gpu_aberration_per_pixel(void **state)
{
    (void)state;
    enum { W = 40, H = 30 };
    static const char *const v1[] = {"observer.velocity=0 0 -0.5", NULL};
    static const char *const v2[] = {"observer.velocity=0.9 0 0", NULL};
    static const char *const v3s[] = {"observer.velocity=0.4 0.5 -0.7", NULL};
    static const char *const v4[] = {"observer.velocity=0 0 -0.99", NULL};
    const char *const *cases[] = {v1, v2, v3s, v4};
    for (int c = 0; c < 4; c++) {
        static struct scene s;
        load_sky_only(&s, W, H, cases[c]);
        struct hc_gpu g;
        hc_gpu_render(&s, &g);
        double worst = 0.0, moved = 0.0;
        for (int j = 0; j < H; j++)
            for (int i = 0; i < W; i++) {
                vec3d view = camera_view_direction(&s, i, j);
                vec3d want = aberration_by_angle(s.observer.velocity, view);
                vec3d got = v3_normalize(hc_gpu_v(&g, j * W + i));
                worst = fmax(worst, angle_between(want, got));
                moved = fmax(moved, angle_between(view, got));
            }
        print_message("%s: largest error %.2e rad; rays turned by up to %.3f rad\n", cases[c][0], worst, moved);
        assert_true(worst <= (v3_len(s.observer.velocity) > 0.95 ? 1e-5 : 2e-6));
        assert_true(moved >= 0.1);      /* the effect is there */
        hc_gpu_free(&g);
    }
}

/* The observer at rest with every effect off is the static renderer, bit for bit. */
static void test_rest_is_static(void **state)
{
    (void)state;
    static const char *const rest[] = {"observer.velocity=0 0 0", "observer.effects=geometry", NULL};
    static const char *const scenes[] = {"test", "schwarzschild", "neutron_star"};
    for (int k = 0; k < 3; k++) {
        static struct scene a, b;
        hc_load(&a, scenes[k], 32, 24, NULL);
        hc_load(&b, scenes[k], 32, 24, rest);
        struct hc_gpu ga, gb;
        hc_gpu_render(&a, &ga);
        hc_gpu_render(&b, &gb);
        size_t n = 4 * 32 * 24;
        assert_memory_equal(ga.res.velocity, gb.res.velocity, n * sizeof(float));
        assert_memory_equal(ga.res.hit, gb.res.hit, n * sizeof(float));
        assert_memory_equal(ga.res.rgba, gb.res.rgba, n);
        hc_gpu_free(&ga);
        hc_gpu_free(&gb);
    }
}

/* Doppler colours: the GPU samples the same 8-bit table as the CPU, so both engines agree to a
 * level or two (fp32 against double in the table coordinate and the Doppler factor); and the
 * colour follows the physics: ahead the sky is hotter (bluer) than aside, and with the searchlight
 * (a 1500 K sky, dark red at rest) brighter. */
static void test_doppler_colour_engines_agree(void **state)
{
    (void)state;
    static const char *const effects[2][4] = {
        {"observer.velocity=0 0 -0.6", "observer.effects=doppler", "sky.temperature=4000", NULL},
        {"observer.velocity=0 0 -0.6", "observer.effects=searchlight", "sky.temperature=1500", NULL},
    };
    for (int e = 0; e < 2; e++) {
        static struct scene s;
        load_sky_only(&s, 48, 36, effects[e]);
        s.camera.fov_deg = 150.0;      /* from well ahead to well aside */
        s.sky.type = SKY_COLOR;
        s.sky.color = v3(1.0, 1.0, 1.0);
        struct cpu_image cpu;
        struct hc_gpu g;
        hc_render_both(&s, 48, 36, &cpu, &g);
        int worst = 0;
        for (size_t k = 0; k < 4u * 48 * 36; k++)
            worst = abs((int)cpu.rgba[k] - (int)g.res.rgba[k]) > worst ? abs((int)cpu.rgba[k] - (int)g.res.rgba[k])
                                                                   : worst;
        print_message("effects %s: largest difference %d levels\n", effects[e][1], worst);
        assert_true(worst <= 2);
        /* the centre looks ahead (D = 2): bluer than the corner, 75 degrees aside (D about 0.8) */
        const unsigned char *centre = g.res.rgba + 4 * (18 * 48 + 24), *corner = g.res.rgba;
        print_message("centre %d %d %d, corner %d %d %d\n", centre[0], centre[1], centre[2], corner[0], corner[1],
                      corner[2]);
        if (e == 0)
            assert_true(centre[2] - centre[0] > corner[2] - corner[0]);
        else
            assert_true(centre[0] + centre[1] + centre[2] > 2 * (corner[0] + corner[1] + corner[2]));
        cpu_image_free(&cpu);
        hc_gpu_free(&g);
    }
}

/* Black-body light on objects (Eq. 18) and the gravitational shift of light from a static light
 * and from the sky, near a black hole, seen by a moving observer: the GPU image against the CPU
 * reference. The static colours of this scene differ between the engines where outcomes differ
 * (rays near silhouettes); the Doppler colours may add at most one level on average. */
static void test_doppler_shading_near_black_hole(void **state)
{
    (void)state;
    static const char *const moving[] = {"observer.velocity=0.3 0 -0.4", "observer.effects=doppler",
                                         "light.key.temperature=5000", "sky.temperature=6000", NULL};
    double mean[2];
    for (int k = 0; k < 2; k++) {
        static struct scene s;
        hc_load(&s, "schwarzschild", 48, 36, k ? moving : NULL);
        struct cpu_image cpu;
        struct hc_gpu g;
        hc_render_both(&s, 48, 36, &cpu, &g);
        struct compare_result r;
        hc_compare(&g.dump, &cpu.dump, &r);
        mean[k] = (r.mean_abs_diff[0] + r.mean_abs_diff[1] + r.mean_abs_diff[2]) / 3.0;
        print_message("%s: mean difference %.3f levels, PSNR %.1f dB, outcomes differ %.3f%%\n",
                      k ? "moving observer, doppler" : "static", mean[k], r.psnr_db, 100.0 * r.outcome_fraction);
        cpu_image_free(&cpu);
        hc_gpu_free(&g);
    }
    assert_true(mean[1] <= mean[0] + 1.0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_aberration_formula),
        cmocka_unit_test(test_paper_temperatures),
        cmocka_unit_test(test_gravitational_shift),
        cmocka_unit_test(test_gpu_aberration_per_pixel),
        cmocka_unit_test(test_rest_is_static),
        cmocka_unit_test(test_doppler_colour_engines_agree),
        cmocka_unit_test(test_doppler_shading_near_black_hole),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
