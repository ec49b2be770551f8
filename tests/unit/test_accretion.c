/* A thin accretion disk (`accretion = on`, physics/accretion.h): the frequency ratio g of light
 * from its orbiting matter against the closed form for a static observer, from the ray's launch
 * direction; the thin disk's temperature profile; a face-on disk without left-right asymmetry and
 * an edge-on one brighter on its approaching side; the GPU's picture against the CPU reference's;
 * and the scenes validation refuses. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "hard_cases.h"
#include "physics/accretion.h"
#include "scene/camera.h"

/* M = 1 at the origin; an accretion disk about it in the plane y = 0 from 6 M to 20 M, 8000 K at
 * its hottest, seen from `camera` with the Doppler colours of its light (effects = searchlight:
 * hue and brightness). */
static void disk_scene(struct scene *s, vec3d camera, vec3d up, int width, int height)
{
    scene_defaults(s);
    snprintf(s->name, sizeof s->name, "accretion");
    s->model.type = MODEL_SCHWARZSCHILD;
    s->model.mass = 1.0;
    s->model.center = v3(0.0, 0.0, 0.0);
    s->render.bound_radius = 60.0;
    s->render.method = METHOD_ORBIT_TABLE;
    s->render.step_control = STEP_FIXED;
    /* the reference's budget (lambda = step x steps x segments) lets every ray end */
    s->render.step_size = 0.1;
    s->render.steps_per_segment = 1000;
    s->render.segments = 100;
    s->render.width = width;
    s->render.height = height;
    s->camera.position = camera;
    s->camera.look_at = v3(0.0, 0.0, 0.0);
    s->camera.up = up;
    s->camera.fov_deg = 45.0;
    s->observer.effects = EFFECTS_SEARCHLIGHT;
    s->ambient_light = v3(0.0, 0.0, 0.0);
    struct object *disk = hc_add_object(s, PRIM_DISK, "disk");
    disk->center = v3(0.0, 0.0, 0.0);
    disk->normal = v3(0.0, 1.0, 0.0);
    disk->inner_radius = 6.0;
    disk->radius = 20.0;
    disk->material.color = v3(0.0, 0.0, 0.0);
    disk->material.emission = v3(1.0, 1.0, 1.0);
    disk->material.ambient = 0.0;
    disk->material.diffuse = 0.0;
    disk->material.specular = 0.0;
    disk->material.temperature = 8000.0;
    disk->material.accretion = 1;
    hc_validate(s);
}

/* ---- 1. g against the closed form ---- */

/* Whether pixel (i, j)'s ray, traced by the CPU reference, hits the disk (object 0); its launch
 * direction and the ray. */
static int disk_hit(const struct scene *s, int i, int j, vec3d *dir, struct ref_ray *ray)
{
    *dir = camera_ray(s, i, j);
    hc_cpu_ray(s, *dir, ray);
    return ray->outcome == 0;
}

/* g = sqrt(1 - 3M/r) / (sqrt(1 - 2M/r_o) (1 - Omega L_z/E)) for the static observer at the camera,
 * L_z / E from the launch direction in its frame: b = r_o sin psi / sqrt(1 - 2M/r_o), along the
 * normal of the launch plane (the photon arrives along -dir). */
static double closed_form_g(const struct scene *s, vec3d dir, vec3d hit, vec3d axis)
{
    double mass = s->model.mass;
    vec3d y = v3_sub(s->camera.position, s->model.center);
    double r_o = v3_len(y);
    vec3d outward = v3_scale(y, 1.0 / r_o);
    double sin_psi = v3_len(v3_cross(outward, dir));
    double b = r_o * sin_psi / sqrt(1.0 - 2.0 * mass / r_o);
    vec3d spin = v3_normalize(v3_cross(outward, v3_scale(dir, -1.0)));
    double lambda_z = b * v3_dot(spin, axis);
    double r = v3_len(v3_sub(hit, s->model.center));
    double omega = sqrt(mass / (r * r * r));
    return sqrt(1.0 - 3.0 * mass / r) / (sqrt(1.0 - 2.0 * mass / r_o) * (1.0 - omega * lambda_z));
}

static void test_shift_closed_form(void **state)
{
    (void)state;
    static const vec3d cameras[] = {{0.0, 3.0, 30.0}, {0.0, 12.0, 12.0}, {25.0, 1.0, -4.0}, {0.0, 0.4, 9.0}};
    long hits = 0;
    double worst = 0.0, lowest = INFINITY, highest = 0.0;
    for (size_t c = 0; c < sizeof cameras / sizeof cameras[0]; c++) {
        static struct scene s;
        disk_scene(&s, cameras[c], v3(0.0, 1.0, 0.0), 64, 64);
        for (int j = 0; j < 64; j += 2)
            for (int i = 0; i < 64; i += 2) {
                vec3d dir;
                struct ref_ray ray;
                if (!disk_hit(&s, i, j, &dir, &ray))
                    continue;
                double lapse_o = sqrt(1.0 - 2.0 * s.model.mass / v3_len(s.camera.position));
                vec3d from_mass = v3_sub(ray.hit, s.model.center);
                double lambda_z = photon_lambda_z(s.model.mass, from_mass, ray.velocity, v3(0.0, 1.0, 0.0));
                double g = keplerian_emitter_shift(s.model.mass, v3_len(from_mass), lambda_z) / lapse_o;
                double want = closed_form_g(&s, dir, ray.hit, v3(0.0, 1.0, 0.0));
                worst = fmax(worst, fabs(g / want - 1.0));
                lowest = fmin(lowest, g);
                highest = fmax(highest, g);
                hits++;
            }
    }
    print_message("%ld hits on the disk from 4 cameras: g from %.3f to %.3f, largest relative difference from the "
                  "closed form %.2e\n", hits, lowest, highest, worst);
    assert_true(hits > 500);
    /* b and the plane are conserved along the orbit: what the hit's direction gives is what the
     * launch gave, to the reference integration's tolerance (rtol 1e-10) */
    assert_true(worst <= 1e-6);
    /* the views reach both sides of the disk: matter coming and going */
    assert_true(lowest < 0.8 && highest > 1.1);
}

/* With observer.gravitational_shift off (the kiosk's layer before gravity's) the ratio the image
 * uses is the Doppler factor of special relativity for the matter's motion as the static observer
 * at the hit measures it: speed beta = sqrt(M / (r - 2M)) along the orbit, the photon leaving at
 * cos(angle) = lambda_z sqrt(1 - 2M/r) / r to that motion in that observer's frame, D = 1 / (gamma (1 -
 * beta cos)); no lapse at the hit or at the camera. */
static void test_shift_without_gravity(void **state)
{
    (void)state;
    static const vec3d cameras[] = {{0.0, 3.0, 30.0}, {0.0, 0.4, 9.0}};
    long hits = 0;
    double worst = 0.0, largest_gravity = 0.0;
    for (size_t c = 0; c < sizeof cameras / sizeof cameras[0]; c++) {
        static struct scene s;
        disk_scene(&s, cameras[c], v3(0.0, 1.0, 0.0), 64, 64);
        s.observer.gravitational_shift = 0;
        double mass = s.model.mass;
        vec3d y = v3_sub(s.camera.position, s.model.center);
        double r_o = v3_len(y);
        vec3d outward = v3_scale(y, 1.0 / r_o);
        for (int j = 0; j < 64; j += 2)
            for (int i = 0; i < 64; i += 2) {
                vec3d dir;
                struct ref_ray ray;
                if (!disk_hit(&s, i, j, &dir, &ray))
                    continue;
                vec3d from_mass = v3_sub(ray.hit, s.model.center);
                double r = v3_len(from_mass);
                double lambda_z = photon_lambda_z(mass, from_mass, ray.velocity, v3(0.0, 1.0, 0.0));
                double shown = camera_doppler(&s, dir) *
                               emitted_ratio_shown(&s, ray.hit, keplerian_emitter_shift(mass, r, lambda_z));
                /* the launch's lambda_z, as closed_form_g takes it */
                double b = r_o * v3_len(v3_cross(outward, dir)) / sqrt(1.0 - 2.0 * mass / r_o);
                double launch_lambda = b * v3_dot(v3_normalize(v3_cross(outward, v3_scale(dir, -1.0))), v3(0.0, 1.0, 0.0));
                double beta = sqrt(mass / (r - 2.0 * mass));
                double cos_angle = launch_lambda * sqrt(1.0 - 2.0 * mass / r) / r;
                double want = sqrt(1.0 - beta * beta) / (1.0 - beta * cos_angle);
                worst = fmax(worst, fabs(shown / want - 1.0));
                largest_gravity = fmax(largest_gravity, fabs(closed_form_g(&s, dir, ray.hit, v3(0.0, 1.0, 0.0)) / want - 1.0));
                hits++;
            }
    }
    print_message("%ld hits: g without gravity's shift against special relativity's Doppler factor %.2e; gravity's "
                  "shift, the difference it makes, up to %.1f%%\n", hits, worst, 100.0 * largest_gravity);
    assert_true(hits > 200);
    assert_true(worst <= 1e-6);      /* the reference's integration tolerance, as above */
    assert_true(largest_gravity > 0.05);   /* the layer takes out a shift a visitor can see */
}

static void test_shift_limits(void **state)
{
    (void)state;
    /* no mass: matter at rest, no shift */
    assert_true(keplerian_emitter_shift(0.0, 7.0, 2.5) == 1.0);
    /* light leaving along the axis carries no angular momentum about it: the transverse shift
     * sqrt(1 - 3M/r) alone */
    double lambda_z = photon_lambda_z(1.0, v3(10.0, 0.0, 0.0), v3(0.0, -1.0, 0.0), v3(0.0, 1.0, 0.0));
    assert_true(lambda_z == 0.0);
    assert_true(fabs(keplerian_emitter_shift(1.0, 10.0, lambda_z) - sqrt(0.7)) <= 1e-15);
    /* light sent forwards from the orbit's tangent in flat space: L / E is the distance, b = r */
    assert_true(fabs(photon_lambda_z(0.0, v3(10.0, 0.0, 0.0), v3(0.0, 0.0, 1.0), v3(0.0, 1.0, 0.0)) - 10.0) <= 1e-12);
    /* no circular orbit inside the photon sphere */
    assert_true(keplerian_emitter_shift(1.0, 2.9, 0.0) == 0.0);
    /* the thin disk's profile: 0 at its inner edge, its peak at 49/36 of it, r^-3/4 far out */
    assert_true(thin_disk_temperature(8000.0, 6.0, 6.0) == 0.0);
    assert_true(fabs(thin_disk_temperature(8000.0, 6.0, 49.0 / 36.0 * 6.0) - 8000.0) <= 1e-9);
    assert_true(thin_disk_temperature(8000.0, 6.0, 8.0) < 8000.0 && thin_disk_temperature(8000.0, 6.0, 9.0) < 8000.0);
    double far = thin_disk_temperature(8000.0, 6.0, 1e6) / thin_disk_temperature(8000.0, 6.0, 1e7);
    assert_true(fabs(far - pow(10.0, 0.75)) <= 1e-3 * far);
}

/* ---- 2. pictures ---- */

/* Sum of R, G, B over the pixels of columns [x0, x1) of the image. */
static double columns_light(const struct render_result *r, int x0, int x1)
{
    double sum = 0.0;
    for (int y = 0; y < r->height; y++)
        for (int x = x0; x < x1; x++)
            for (int c = 0; c < 3; c++)
                sum += r->rgba[4 * ((size_t)y * r->width + x) + c];
    return sum;
}

static void test_face_on(void **state)
{
    (void)state;
    static struct scene s;
    /* on the axis, looking down: every orbit plane holds the axis, so no light carries angular
     * momentum about it, and the picture is the same mirrored */
    disk_scene(&s, v3(0.0, 30.0, 0.0), v3(0.0, 0.0, -1.0), 96, 96);
    struct hc_gpu g;
    hc_gpu_render(&s, &g);
    int most = 0;
    for (int y = 0; y < 96; y++)
        for (int x = 0; x < 96; x++)
            for (int c = 0; c < 3; c++) {
                int a = g.res.rgba[4 * (y * 96 + x) + c], b = g.res.rgba[4 * (y * 96 + 95 - x) + c];
                most = abs(a - b) > most ? abs(a - b) : most;
            }
    print_message("face on: left and right differ by at most %d/255\n", most);
    /* float roundings of mirrored rays only */
    assert_true(most <= 2);
    hc_gpu_free(&g);
}

static void test_edge_on(void **state)
{
    (void)state;
    static struct scene s;
    /* nearly in the disk's plane: the matter on the left (x < 0) comes towards the camera (it turns
     * counterclockwise about +y), that on the right goes away */
    disk_scene(&s, v3(0.0, 1.5, 30.0), v3(0.0, 1.0, 0.0), 128, 64);
    struct hc_gpu g;
    hc_gpu_render(&s, &g);
    double left = columns_light(&g.res, 0, 64), right = columns_light(&g.res, 64, 128);
    /* the closed form's ratio at the disk's outer edge, where the view meets it side-on */
    vec3d approaching = v3(-20.0, 0.0, 0.0), receding = v3(20.0, 0.0, 0.0);
    double g_ratio = closed_form_g(&s, v3_normalize(v3_sub(approaching, s.camera.position)), approaching,
                                   v3(0.0, 1.0, 0.0)) /
                     closed_form_g(&s, v3_normalize(v3_sub(receding, s.camera.position)), receding, v3(0.0, 1.0, 0.0));
    print_message("edge on: light of the approaching half %.3g against the receding half's %.3g (%.2f times); "
                  "g at the outer edges %.3f times\n", left, right, left / right, g_ratio);
    assert_true(g_ratio > 1.0);
    /* the black body at g T is brighter for a larger g: the approaching half outshines the other */
    assert_true(left > 1.2 * right);
    hc_gpu_free(&g);
}

static void test_gpu_against_reference(void **state)
{
    (void)state;
    static const vec3d cameras[] = {{0.0, 3.0, 30.0}, {0.0, 0.4, 9.0}};
    /* with gravity's shift and without it (the kiosk's layers, observer.gravitational_shift) */
    static struct hc_gpu close_with_gravity;
    for (size_t c = 0; c < 4; c++) {
        static struct scene s;
        disk_scene(&s, cameras[c % 2], v3(0.0, 1.0, 0.0), 160, 90);
        s.observer.gravitational_shift = c < 2;
        struct cpu_image cpu;
        struct hc_gpu g;
        hc_render_both(&s, 160, 90, &cpu, &g);
        struct compare_result cr;
        hc_compare(&g.dump, &cpu.dump, &cr);
        print_message("camera %g %g %g, gravitational shift %s: %ld outcomes differ, PSNR %.1f dB, mean |difference| "
                      "%.3f %.3f %.3f /255\n", cameras[c % 2].x, cameras[c % 2].y, cameras[c % 2].z,
                      c < 2 ? "on" : "off", cr.outcomes.differ, cr.psnr_db,
                      cr.mean_abs_diff[0], cr.mean_abs_diff[1], cr.mean_abs_diff[2]);
        assert_int_equal(cr.outcomes.differ, 0);
        /* the same g and temperature in float as in double: the colours agree to the 8-bit levels
         * of the black-body table's neighbouring texels */
        assert_true(cr.psnr_db >= 45.0);
        for (int k = 0; k < 3; k++)
            assert_true(cr.mean_abs_diff[k] <= 0.5);
        cpu_image_free(&cpu);
        if (c == 1) {
            close_with_gravity = g;      /* kept for the layer's own difference below */
            continue;
        }
        if (c == 3) {
            /* near the hole, gravity's shift is a colour a visitor sees: the layer changes the disk */
            hc_compare(&g.dump, &close_with_gravity.dump, &cr);
            print_message("camera 0 0.4 9, with gravity's shift against without: PSNR %.1f dB, mean |difference| "
                          "%.2f %.2f %.2f /255\n", cr.psnr_db, cr.mean_abs_diff[0], cr.mean_abs_diff[1],
                          cr.mean_abs_diff[2]);
            assert_int_equal(cr.outcomes.differ, 0);
            assert_true(cr.mean_abs_diff[0] + cr.mean_abs_diff[1] + cr.mean_abs_diff[2] >= 3.0);
            hc_gpu_free(&close_with_gravity);
        }
        hc_gpu_free(&g);
    }
}

static void test_flat_space_moved(void **state)
{
    (void)state;
    /* flat space (or the mass knob at 0): the matter rests, and its temperature falls off from the
     * disk's own centre, wherever that is: the disk and the camera moved together draw the same */
    static struct scene here, there;
    disk_scene(&here, v3(0.0, 3.0, 30.0), v3(0.0, 1.0, 0.0), 96, 54);
    here.model.type = MODEL_FLAT;
    here.render.method = METHOD_RK4;
    hc_validate(&here);
    there = here;
    vec3d shift = v3(20.0, -5.0, 3.0);
    there.camera.position = v3_add(here.camera.position, shift);
    there.camera.look_at = v3_add(here.camera.look_at, shift);
    there.render.bound_center = v3_add(here.render.bound_center, shift);
    there.objects[0].center = v3_add(here.objects[0].center, shift);
    hc_validate(&there);
    struct hc_gpu a, b;
    hc_gpu_render(&here, &a);
    hc_gpu_render(&there, &b);
    int most = 0;
    long lit = 0;
    for (int k = 0; k < 96 * 54 * 4; k++) {
        int d = abs(a.res.rgba[k] - b.res.rgba[k]);
        most = d > most ? d : most;
        lit += k % 4 != 3 && a.res.rgba[k] > 64;
    }
    print_message("flat space, the disk moved by (20, -5, 3): pixels differ by at most %d/255, %ld channels lit\n",
                  most, lit);
    assert_true(lit > 1000);
    /* float roundings of the moved coordinates only */
    assert_true(most <= 2);
    hc_gpu_free(&a);
    hc_gpu_free(&b);
}

/* ---- 3. what validation refuses ---- */

static void expect_refused(struct scene *s, const char *words)
{
    struct error e;
    assert_int_not_equal(scene_validate(s, &e), 0);
    print_message("refused: %s\n", e.message);
    assert_non_null(strstr(e.message, words));
}

static void test_refused(void **state)
{
    (void)state;
    static struct scene s;
    disk_scene(&s, v3(0.0, 3.0, 30.0), v3(0.0, 1.0, 0.0), 64, 64);
    s.objects[0].inner_radius = 2.9;
    expect_refused(&s, "beyond the photon sphere, 3M = 3");
    disk_scene(&s, v3(0.0, 3.0, 30.0), v3(0.0, 1.0, 0.0), 64, 64);
    s.objects[0].material.temperature = 0.0;
    s.observer.effects = EFFECTS_GEOMETRY;
    expect_refused(&s, "hottest temperature");
    disk_scene(&s, v3(0.0, 3.0, 30.0), v3(0.0, 1.0, 0.0), 64, 64);
    s.objects[0].center = v3(0.0, 0.0, 1.0);
    expect_refused(&s, "its center must be model.center");
    disk_scene(&s, v3(0.0, 3.0, 30.0), v3(0.0, 1.0, 0.0), 64, 64);
    s.model.type = MODEL_POTENTIAL;
    s.render.method = METHOD_RK4;
    expect_refused(&s, "accretion = on puts matter on orbits about a black hole");
    /* flat space: the matter rests, an inner edge above 0 is all it needs */
    disk_scene(&s, v3(0.0, 3.0, 30.0), v3(0.0, 1.0, 0.0), 64, 64);
    s.model.type = MODEL_FLAT;
    struct error e;
    assert_int_equal(scene_validate(&s, &e), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_shift_limits),
        cmocka_unit_test(test_shift_closed_form),
        cmocka_unit_test(test_shift_without_gravity),
        cmocka_unit_test(test_face_on),
        cmocka_unit_test(test_edge_on),
        cmocka_unit_test(test_gpu_against_reference),
        cmocka_unit_test(test_flat_space_moved),
        cmocka_unit_test(test_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
