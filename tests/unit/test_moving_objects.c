/* Objects moving near light speed in flat space (Müller, Grottel and Weiskopf 2010, section 3):
 * a sphere keeps a circular outline at any speed (Penrose 1959, Terrell 1959), exactly in the C
 * intersection and within half a pixel on the GPU; a scene seen later is the same scene with its
 * moving objects further on; the reflection Doppler factor of Eq. 17 is the radar formula head on. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include "hard_cases.h"
#include "physics/relativity.h"

static double angle_between(vec3d a, vec3d b)
{
    return atan2(v3_len(v3_cross(a, b)), v3_dot(a, b));
}

/* A sphere of radius 1 moving across the view of a camera at the origin, placed so that the light
 * seen at time 0 left it (at scene time about -10) ten units straight ahead. */
static void moving_sphere(struct scene *s, int w, int h, vec3d beta, double time)
{
    hc_load(s, "test", w, h, NULL);
    s->n_objects = 0;
    s->n_lights = 0;
    s->camera.position = v3(0, 0, 0);
    s->camera.look_at = v3(0, 0, -1);
    s->camera.up = v3(0, 1, 0);
    s->camera.fov_deg = 40.0;
    s->render.bound_center = v3(0, 0, 0);
    s->render.bound_radius = 200.0;
    s->observer.time = time;
    struct object *o = hc_add_object(s, PRIM_SPHERE, "ball");
    o->center = v3(10.0 * beta.x, 0.0, -10.0);
    o->radius = 1.0;
    o->velocity = beta;
    hc_validate(s);
}

static int hits(const struct scene *s, vec3d d)
{
    return straight_first_hit(s, s->camera.position, v3_scale(d, 300.0), NULL) >= 0;
}

/* The outline along great circles from axis c at n azimuths: angular radius at each (bisection on
 * the exact C intersection in the sphere's rest frame). */
static void outline(const struct scene *s, vec3d c, int n, double *radius)
{
    vec3d e1 = v3_perpendicular(c), e2 = v3_cross(c, e1);
    for (int k = 0; k < n; k++) {
        double phi = 2.0 * PI_D * k / n;
        vec3d across = v3_add(v3_scale(e1, cos(phi)), v3_scale(e2, sin(phi)));
        double lo = 0.0, hi = 0.5;                 /* inside at lo, outside at hi (radians) */
        for (int it = 0; it < 60; it++) {
            double mid = 0.5 * (lo + hi);
            vec3d d = v3_add(v3_scale(c, cos(mid)), v3_scale(across, sin(mid)));
            if (hits(s, d))
                lo = mid;
            else
                hi = mid;
        }
        radius[k] = 0.5 * (lo + hi);
    }
}

/* The cone axis of the outline: the mean of its boundary directions, which converges to the axis
 * when repeated from a guess inside (the samples become uniform around the circle). */
static vec3d outline_axis(const struct scene *s, vec3d guess, int n, double *radius)
{
    vec3d c = guess;
    for (int round = 0; round < 30; round++) {
        outline(s, c, n, radius);
        vec3d e1 = v3_perpendicular(c), e2 = v3_cross(c, e1), sum = v3(0, 0, 0);
        for (int k = 0; k < n; k++) {
            double phi = 2.0 * PI_D * k / n;
            vec3d across = v3_add(v3_scale(e1, cos(phi)), v3_scale(e2, sin(phi)));
            sum = v3_add(sum, v3_add(v3_scale(c, cos(radius[k])), v3_scale(across, sin(radius[k]))));
        }
        c = v3_normalize(sum);
    }
    outline(s, c, n, radius);
    return c;
}

/* A first guess of the outline's axis: the mean direction of the hits of a fine scan. */
static vec3d first_hit_direction(const struct scene *s)
{
    vec3d sum = v3(0, 0, 0);
    for (int j = 0; j < 200; j++)
        for (int i = 0; i < 200; i++) {
            vec3d d = v3_normalize(v3(-0.6 + 1.2 * i / 199.0, -0.6 + 1.2 * j / 199.0, -1.0));
            if (hits(s, d))
                sum = v3_add(sum, d);
        }
    if (!(v3_len(sum) > 0.0))
        fail_msg("the ball is not in view");
    return v3_normalize(sum);
}

/* Exact: the boundary rays of a moving sphere lie on a cone. At rest its half-angle is
 * asin(1/10); moving, it is seen where it was when the light left, far from where it is at the
 * time of the picture, and its outline stays a circle. Tolerance 1e-9 rad: the bisection stops at
 * 0.5 * 2^-60, the rest is double rounding. */
static void test_outline_is_a_circle(void **state)
{
    (void)state;
    static const double speeds[] = {0.0, 0.5, 0.9, 0.99};
    enum { N = 48 };
    for (int k = 0; k < 4; k++) {
        static struct scene s;
        moving_sphere(&s, 32, 24, v3(speeds[k], 0.0, 0.0), 0.0);
        double radius[N];
        vec3d axis = outline_axis(&s, first_hit_direction(&s), N, radius);
        double lo = radius[0], hi = radius[0];
        for (int i = 1; i < N; i++) {
            lo = fmin(lo, radius[i]);
            hi = fmax(hi, radius[i]);
        }
        print_message("beta %.2f: outline centre %.4f rad off the view axis, radius %.6f rad, spread %.1e rad\n",
                      speeds[k], angle_between(axis, v3(0, 0, -1)), 0.5 * (lo + hi), hi - lo);
        assert_true(hi - lo <= 1e-9);
        if (k == 0)
            assert_true(fabs(0.5 * (lo + hi) - asin(0.1)) <= 1e-9);
        else   /* seen where it was, not where it is */
            assert_true(angle_between(axis, v3_normalize(s.objects[0].center)) >= 0.4);
    }
}

/* The GPU image of the moving ball: every pixel whose centre lies more than half a pixel inside the
 * exact outline is a hit, every one more than half a pixel outside is sky. */
static void test_gpu_outline_within_half_a_pixel(void **state)
{
    (void)state;
    enum { W = 96, H = 72, N = 32 };
    static const double speeds[] = {0.5, 0.9, 0.99};
    for (int k = 0; k < 3; k++) {
        static struct scene s;
        moving_sphere(&s, W, H, v3(speeds[k], 0.0, 0.0), 0.0);
        double radius[N];
        vec3d axis = outline_axis(&s, first_hit_direction(&s), N, radius);
        double rho = radius[0];
        struct hc_gpu g;
        hc_gpu_render(&s, &g);
        double pixel = (s.camera.fov_deg * PI_D / 180.0) / H;     /* at the centre; smaller off axis */
        int wrong = 0, inside = 0;
        for (int j = 0; j < H; j++)
            for (int i = 0; i < W; i++) {
                double a = angle_between(camera_ray(&s, i, j), axis);
                int hit = g.dump.records[j * W + i].outcome >= 0;
                inside += hit;
                if ((a < rho - 0.5 * pixel && !hit) || (a > rho + 0.5 * pixel && hit))
                    wrong++;
            }
        print_message("beta %.2f: %d pixels inside, %d off the exact outline by more than half a pixel\n", speeds[k],
                      inside, wrong);
        assert_int_equal(wrong, 0);
        assert_true(inside > 20);
        hc_gpu_free(&g);
    }
}

/* Seen dt later, a body moving with beta looks exactly as if it had started beta dt further on:
 * the picture depends on the observation time only through the bodies' motion (the Poincaré
 * transformation's time translation). The three bodies of three_ships 1.5 later, against each
 * moved by its own beta * 1.5: the same pixels on the GPU, hit points to fp32 rounding. */
static void test_later_is_further(void **state)
{
    (void)state;
    static const char *const later[] = {"observer.time=1.5", NULL};
    static struct scene a, b;
    hc_load(&a, "three_ships", 64, 48, later);
    hc_load(&b, "three_ships", 64, 48, NULL);
    for (int k = 0; k < b.n_objects; k++)
        b.objects[k].center = v3_axpy(1.5 - b.observer.time, b.objects[k].velocity, b.objects[k].center);
    struct hc_gpu ga, gb;
    hc_gpu_render(&a, &ga);
    hc_gpu_render(&b, &gb);
    struct compare_result r;
    hc_compare(&ga.dump, &gb.dump, &r);
    print_message("later vs moved: %ld of %ld outcomes differ, hit p99 %.2e of size, %ld hits\n", r.outcomes.differ,
                  r.pixels, r.hit_relative.p99, (long)r.hit.count);
    assert_true(r.outcomes.differ <= 2);            /* rays that graze an edge */
    assert_true(r.hit.count > 100);
    assert_true(r.hit_relative.p99 <= 1e-4);
    hc_gpu_free(&ga);
    hc_gpu_free(&gb);
}

/* Eq. 17 head on is the radar formula: light sent to a mirror approaching at beta comes back with
 * frequency ratio (1 + beta) / (1 - beta); a mirror at rest changes nothing. And the emission
 * Doppler factor of a source approaching head on is sqrt((1 + beta) / (1 - beta)). */
static void test_reflection_doppler(void **state)
{
    (void)state;
    vec3d beta = v3(0, 0, 0.6);           /* the mirror moves towards +z, where the light comes from */
    double radar = reflection_doppler(beta, v3(0, 0, -1), v3(0, 0, 1));
    assert_true(fabs(radar - 1.6 / 0.4) <= 1e-12);
    assert_true(reflection_doppler(v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0)) == 1.0);
    assert_true(fabs(emission_doppler(beta, v3(0, 0, 1)) - 2.0) <= 1e-12);
    /* the rest position: the origin's event (0, a) is the rest frame's origin; a later event on the
     * body's worldline keeps its rest position */
    struct object_motion m = {beta, lorentz_gamma(beta), v3(1, 2, 3)};
    vec3d p0 = rest_position(&m, 0.0, v3(1, 2, 3));
    vec3d p1 = rest_position(&m, 2.0, v3(1, 2, 3 + 0.6 * 2.0));
    assert_true(v3_len(p0) <= 1e-15);
    assert_true(v3_len(p1) <= 1e-12);
    /* lengths along beta are gamma times longer at rest than in the scene frame at one time */
    vec3d q = rest_position(&m, 0.0, v3(1, 2, 4));
    assert_true(fabs(q.z - lorentz_gamma(beta)) <= 1e-12);
}

/* The reading of a clock face seen along the view axis at observation time t_obs: the proper time
 * of the event where the centre ray hit it (the traced hit, not a formula). */
static double clock_seen(struct scene *s, double t_obs)
{
    s->observer.time = t_obs;
    struct ref_ray ray;
    hc_cpu_ray(s, v3(0, 0, -1), &ray);
    assert_int_equal(ray.outcome, 0);
    struct object_motion m;
    assert_true(object_motion(&s->objects[0], &m));
    double emitted = t_obs - v3_len(v3_sub(ray.hit, s->camera.position));
    return proper_time(&m, emitted, ray.hit);
}

/* The temporal Doppler effect: a clock coming straight at the observer is seen to run fast by
 * D = sqrt((1 + beta) / (1 - beta)), one going away slow by 1/D; each is slow by 1/gamma in the
 * scene frame, and the light-travel time makes the difference. Exact for uniform motion along the
 * line of sight: 1e-9 relative. */
static void test_clock_rate_is_doppler(void **state)
{
    (void)state;
    static const double betas[] = {0.5, -0.5, 0.9};
    for (int k = 0; k < 3; k++) {
        static struct scene s;
        moving_sphere(&s, 32, 24, v3(0, 0, 0), 0.0);
        struct object *o = &s.objects[0];
        o->type = PRIM_RECT;
        o->center = v3(0, 0, -30);
        o->axis_u = v3(1, 0, 0);
        o->axis_v = v3(0, 1, 0);
        o->velocity = v3(0, 0, betas[k]);       /* + is towards the camera */
        o->material.clock_period = 10.0;
        hc_validate(&s);
        double rate = (clock_seen(&s, 27.0) - clock_seen(&s, 25.0)) / 2.0;
        double b = betas[k], want = sqrt((1.0 + b) / (1.0 - b));
        print_message("beta %+.1f towards the eye: the clock is seen to run at %.9f, Doppler factor %.9f\n", b, rate,
                      want);
        assert_true(fabs(rate / want - 1.0) <= 1e-9);
    }
}

/* The clocks scene on both engines: the same hands (colours within a level on average), and the
 * hands turn between two observation times. */
static void test_clock_faces_agree_and_turn(void **state)
{
    (void)state;
    static const char *const later[] = {"observer.time=14", NULL};
    static struct scene s, t;
    hc_load(&s, "clocks", 96, 72, NULL);
    struct cpu_image cpu;
    struct hc_gpu g, gl;
    hc_render_both(&s, 96, 72, &cpu, &g);
    struct compare_result r;
    hc_compare(&g.dump, &cpu.dump, &r);
    double mean = (r.mean_abs_diff[0] + r.mean_abs_diff[1] + r.mean_abs_diff[2]) / 3.0;
    hc_load(&t, "clocks", 96, 72, later);
    hc_gpu_render(&t, &gl);
    int turned = 0;
    for (int i = 0; i < 96 * 72; i++)
        turned += memcmp(g.res.rgba + 4 * i, gl.res.rgba + 4 * i, 3) != 0;
    print_message("clocks: GPU vs CPU mean difference %.3f levels; %d pixels changed 2 time units later\n", mean,
                  turned);
    assert_true(mean <= 1.0);
    assert_true(turned >= 20);
    cpu_image_free(&cpu);
    hc_gpu_free(&g);
    hc_gpu_free(&gl);
}

/* Black-body emitters moving towards and away from the eye: the approaching one is hotter (bluer),
 * the receding one cooler (redder), on both engines alike. */
static void test_emitters_shift(void **state)
{
    (void)state;
    enum { W = 64, H = 48 };
    static struct scene s;
    moving_sphere(&s, W, H, v3(0, 0, 0), 0.0);
    s.observer.effects = EFFECTS_DOPPLER;
    struct object *o = &s.objects[0];
    o->center = v3(-1.5, 0, -10);
    o->velocity = v3(0, 0, 0.5);             /* towards the eye */
    o->material.emission = v3(1, 1, 1);
    o->material.temperature = 4000.0;
    o->material.ambient = o->material.diffuse = o->material.specular = 0.0;
    struct object *away = hc_add_object(&s, PRIM_SPHERE, "away");
    *away = *o;
    snprintf(away->name, sizeof away->name, "away");
    away->center = v3(1.5, 0, -10);
    away->velocity = v3(0, 0, -0.5);
    struct cpu_image cpu;
    struct hc_gpu g;
    hc_render_both(&s, W, H, &cpu, &g);
    struct compare_result r;
    hc_compare(&g.dump, &cpu.dump, &r);
    double mean = (r.mean_abs_diff[0] + r.mean_abs_diff[1] + r.mean_abs_diff[2]) / 3.0;
    int blue[2] = {0, 0}, n[2] = {0, 0};
    for (int i = 0; i < W * H; i++) {
        int id = g.dump.records[i].outcome;
        if (id >= 0) {
            blue[id] += g.res.rgba[4 * i + 2] - g.res.rgba[4 * i];
            n[id]++;
        }
    }
    print_message("emitters: GPU vs CPU mean difference %.3f levels; blue minus red: approaching %.0f, receding %.0f "
                  "(%d and %d pixels)\n", mean, (double)blue[0] / n[0], (double)blue[1] / n[1], n[0], n[1]);
    assert_true(mean <= 1.0);
    assert_true(n[0] > 10 && n[1] > 10);
    assert_true((double)blue[0] / n[0] > (double)blue[1] / n[1] + 50.0);
    cpu_image_free(&cpu);
    hc_gpu_free(&g);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_outline_is_a_circle),
        cmocka_unit_test(test_gpu_outline_within_half_a_pixel),
        cmocka_unit_test(test_later_is_further),
        cmocka_unit_test(test_reflection_doppler),
        cmocka_unit_test(test_clock_rate_is_doppler),
        cmocka_unit_test(test_clock_faces_agree_and_turn),
        cmocka_unit_test(test_emitters_shift),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
