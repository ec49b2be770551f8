/* Hard cases of ray-object geometry, each on the double-precision CPU reference and on the GPU
 * (EGL, default path fp32+MRT): rays tangent to a sphere, rays lying in the plane of a triangle or
 * rectangle, zero-area triangles, and hits exactly at the joints between two segments.
 * Measured numbers are printed; every tolerance is justified next to its assertion. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "hard_cases.h"

enum field { FLAT, STRAIGHT_INTEGRATED, CURVED, N_FIELDS };
static const char *const field_names[N_FIELDS] = {"flat", "integrated, zeta -1e-20", "curved"};
/* A potential of zeta 0 is flat space and is not integrated (model_is_straight); this one is,
 * step by step, while bending rays by ~1e-20 / r^2: far below float rounding. */
#define NEGLIGIBLE_ZETA (-1e-20)

/* An empty scene at the test scenes' settings (step 0.05, 10 steps per segment, 80 segments,
 * bound 30). FLAT: straight rays, not integrated. STRAIGHT_INTEGRATED: a potential with a
 * negligible zeta, straight rays integrated step by step. CURVED: a Yukawa potential of strength zeta about
 * `centre`. */
static void base_scene(struct scene *s, enum field f, double zeta, vec3d centre)
{
    scene_defaults(s);
    snprintf(s->name, sizeof s->name, "hard_geometry");
    s->render.bound_radius = 30.0;
    s->render.step_size = 0.05;
    s->render.steps_per_segment = 10;
    s->render.steps_per_pass = 10;
    s->render.segments = 80;
    s->model.type = f == FLAT ? MODEL_FLAT : MODEL_POTENTIAL;
    s->model.profile = PROFILE_YUKAWA;
    s->model.zeta = f == CURVED ? zeta : f == STRAIGHT_INTEGRATED ? NEGLIGIBLE_ZETA : 0.0;
    s->model.mu = 0.0;
    s->model.center = centre;
}

/* ---- 6a. rays tangent to a sphere ---- */

/* Unit sphere at the origin; a ray along -z from (1 + offset, 0, 10): offset < 0 passes through
 * the sphere, offset 0 touches it at (1, 0, 0), offset > 0 misses. (1, 0, 10) and the direction
 * are exact in float and double, so offset 0 is exact tangency on both engines. */
static void test_tangent_sphere(void **state)
{
    (void)state;
    const double offsets[5] = {-1e-3, -1e-6, 0.0, 1e-6, 1e-3};
    /* CURVED: zeta = -1e-7 at (0, 5, 0). The pull toward it is at most 1e-7 / 25 = 4e-9 per unit
     * length^2; over the 10 units to the sphere it moves the ray by at most 0.5 * 4e-9 * 100 = 2e-7
     * (toward the centre, in y, and 4e-8 in x), 5x below the smallest nonzero offset 1e-6: there
     * the straight cast must still decide; at offset 0 the bend decides (reported). */
    const double zeta = -1e-7;
    const vec3d centre = v3(0.0, 5.0, 0.0);
    for (int f = 0; f < N_FIELDS; f++)
        for (int k = 0; k < 5; k++) {
            static struct scene s;
            base_scene(&s, (enum field)f, zeta, centre);
            struct object *o = hc_add_object(&s, PRIM_SPHERE, "ball");
            o->center = v3(0.0, 0.0, 0.0);
            o->radius = 1.0;
            hc_aim(&s, v3(1.0 + offsets[k], 0.0, 10.0), v3(0.0, 0.0, -1.0));
            s.render.width = s.render.height = 1;
            hc_validate(&s);
            vec3d dir = v3(0.0, 0.0, -1.0);
            double th;
            int straight = straight_first_hit(&s, s.camera.position, v3_axpy(40.0, dir, s.camera.position), &th);
            struct ref_ray ray;
            hc_cpu_ray(&s, dir, &ray);
            struct hc_gpu g;
            hc_gpu_render(&s, &g);
            int32_t gpu = g.dump.records[0].outcome;
            long nonfinite = hc_gpu_nonfinite(&g);
            print_message("%-19s offset %+.0e: straight cast %-6s cpu %-6s gpu %s\n", field_names[f], offsets[k],
                          straight >= 0 ? "sphere" : "sky", ray.outcome >= 0 ? "sphere" : dump_outcome_name(ray.outcome),
                          gpu >= 0 ? "sphere" : dump_outcome_name(gpu));
            assert_int_equal(nonfinite, 0);
            assert_true(v3_isfinite(ray.position) && v3_isfinite(ray.velocity));
            /* The exact answer, where it exists: hit for offset < 0, miss for offset > 0. */
            if (offsets[k] != 0.0)
                assert_int_equal(straight, offsets[k] < 0.0 ? 0 : -1);
            /* CPU = double straight cast: always when the rays are straight (the flat engine is the
             * straight cast; the integrated one must find the same tangency on its dense output), and
             * for the curved field wherever the offset is 5x the bend. */
            if (f != CURVED || offsets[k] != 0.0)
                assert_int_equal(ray.outcome, straight >= 0 ? 0 : DUMP_SKY);
            /* GPU: sphere or sky, never anything else; at offset 1e-3 it must be right: fp32 rounding
             * of the ray (<= 1e-5 after 200 steps at |x| <= 10) is 100x smaller. */
            assert_true(gpu == 0 || gpu == DUMP_SKY);
            if (fabs(offsets[k]) == 1e-3)
                assert_int_equal(gpu, offsets[k] < 0.0 ? 0 : DUMP_SKY);
            hc_gpu_free(&g);
        }
}

/* ---- 6b. rays lying in the plane of a triangle or a rectangle ---- */

/* A W x 1 image from (0, 0, 10) looking along -z: the only row has ndc_y = 0 exactly, so every ray
 * lies exactly in the plane y = 0 (also in float: right = (tan * aspect, 0, 0) exactly), as do the
 * triangle and the rectangle. CURVED: zeta = -0.5 at (3, 0, 0), in the plane, so the force has no y
 * component and the rays bend within the plane. A ray in the plane of a primitive never hits it
 * (parallel: the crossing would be a ratio of rounding errors). Control: the same primitives tilted
 * by 0.01 rad about the x axis must be hit, so the test can see a hit where there is one. */
static void in_plane_scene(struct scene *s, enum field f, double tilt)
{
    base_scene(s, f, -0.5, v3(3.0, 0.0, 0.0));
    hc_aim(s, v3(0.0, 0.0, 10.0), v3(0.0, 0.0, -1.0));
    s->render.width = 16;
    /* horizontally +-19 degrees: the vertical field of a 16 x 1 image is 1/16 of the horizontal */
    s->camera.fov_deg = 2.0 * atan(0.35 / 16.0) * 180.0 / PI_D;
    s->render.height = 1;
    double c = cos(tilt), sn = sin(tilt);
    struct object *t = hc_add_object(s, PRIM_TRIANGLE, "sail");
    t->vertex[0] = v3(-4.0, -2.0 * sn, -2.0 * c);
    t->vertex[1] = v3(4.0, -2.0 * sn, -2.0 * c);
    t->vertex[2] = v3(0.0, 3.0 * sn, 3.0 * c);
    struct object *r = hc_add_object(s, PRIM_RECT, "floor");
    r->center = v3(0.0, 5.0 * sn, 5.0 * c);
    r->axis_u = v3(5.0, 0.0, 0.0);
    r->axis_v = v3(0.0, sn, c);
    hc_validate(s);
}

static void test_rays_in_plane(void **state)
{
    (void)state;
    for (int f = 0; f < N_FIELDS; f++) {
        static struct scene s;
        for (int tilted = 0; tilted < 2; tilted++) {
            in_plane_scene(&s, (enum field)f, tilted ? 0.01 : 0.0);
            struct cpu_image cpu;
            struct hc_gpu g;
            hc_cpu_render(&s, &cpu);
            hc_gpu_render(&s, &g);
            long cpu_hits = 0, gpu_hits = 0;
            for (int i = 0; i < s.render.width; i++) {
                cpu_hits += cpu.dump.records[i].outcome >= 0;
                gpu_hits += g.dump.records[i].outcome >= 0;
            }
            long nonfinite = hc_gpu_nonfinite(&g);
            print_message("%-19s %s: hits cpu %ld gpu %ld of %d rays; gpu non-finite %ld\n", field_names[f],
                          tilted ? "tilted by 0.01 rad (control)" : "rays in the plane          ", cpu_hits, gpu_hits,
                          s.render.width, nonfinite);
            assert_int_equal(nonfinite, 0);
            assert_int_equal(hc_dump_nonfinite(&cpu.dump), 0);
            if (tilted) {
                /* the rays cross the tilted primitives at z in [-2, 5]: most of them hit */
                assert_true(cpu_hits >= s.render.width / 2);
                assert_true(gpu_hits >= s.render.width / 2);
            } else {
                assert_int_equal(cpu_hits, 0);
                assert_int_equal(gpu_hits, 0);
            }
            cpu_image_free(&cpu);
            hc_gpu_free(&g);
        }
    }
}

/* ---- 6c. zero-area triangles ---- */

/* Three ways to have no area: collinear with an exactly zero cross product, a repeated vertex, and
 * collinear points that are not exact in binary (0.1, 0.2, 0.3) k: their cross product in double is
 * a rounding residue, not zero. Rays go through a point of each: a 1x1 image aimed at it and a
 * 9x9 image around it. Such a triangle is never hit. */
static void test_degenerate_triangles(void **state)
{
    (void)state;
    const vec3d tris[3][3] = {
        {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}},
        {{0.0, -1.0, 0.0}, {0.0, -1.0, 0.0}, {0.0, 1.0, 0.0}},
        {{0.1, 0.2, 0.3}, {0.2, 0.4, 0.6}, {0.3, 0.6, 0.9}},
    };
    const char *const names[3] = {"collinear, exact", "repeated vertex", "collinear, rounded"};
    for (int t = 0; t < 3; t++) {
        vec3d e1 = v3_sub(tris[t][1], tris[t][0]), e2 = v3_sub(tris[t][2], tris[t][0]);
        double residue = v3_len(v3_cross(e1, e2));
        /* the ray of the 1x1 image goes through a point in the middle of the segment */
        const vec3d targets[3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.2, 0.4, 0.6}};
        vec3d target = targets[t];
        for (int f = 0; f < N_FIELDS; f++)
            for (int big = 0; big < 2; big++) {
                static struct scene s;
                base_scene(&s, (enum field)f, -0.5, v3(3.0, 0.0, 0.0));
                struct object *o = hc_add_object(&s, PRIM_TRIANGLE, "flat");
                for (int v = 0; v < 3; v++)
                    o->vertex[v] = tris[t][v];
                vec3d cam = v3_add(target, v3(0.3, 0.2, 9.0));
                hc_aim(&s, cam, v3_normalize(v3_sub(target, cam)));
                s.camera.fov_deg = 10.0;
                s.render.width = s.render.height = big ? 9 : 1;
                hc_validate(&s);
                struct cpu_image cpu;
                struct hc_gpu g;
                hc_cpu_render(&s, &cpu);
                hc_gpu_render(&s, &g);
                long cpu_hits = 0, gpu_hits = 0, n = (long)s.render.width * s.render.height;
                for (long i = 0; i < n; i++) {
                    cpu_hits += cpu.dump.records[i].outcome >= 0;
                    gpu_hits += g.dump.records[i].outcome >= 0;
                }
                long nonfinite = hc_gpu_nonfinite(&g);
                print_message("%-19s |e1 x e2| = %.1e, %-19s %ldx%ld: hits cpu %ld gpu %ld\n", names[t], residue,
                              field_names[f], (long)s.render.width, (long)s.render.height, cpu_hits, gpu_hits);
                assert_int_equal(nonfinite, 0);
                assert_int_equal(hc_dump_nonfinite(&cpu.dump), 0);
                assert_int_equal(cpu_hits, 0);
                assert_int_equal(gpu_hits, 0);
                cpu_image_free(&cpu);
                hc_gpu_free(&g);
            }
    }
}

/* ---- 7. hits exactly at segment joints ---- */

/* Straight rays integrated in steps (potential, negligible zeta): a camera looking along -z with a tiny
 * field of view (0.5 degrees, so every ray is within 0.4 degrees of the axis) and a large rectangle
 * across the view at distance k * steps_per_segment * step = k * 0.5: the central ray reaches it
 * exactly at the end of segment k - 1 / the start of segment k, its neighbours a hair later
 * (depth k / cos(theta), cos(theta) >= 1 - 3e-5). Two cameras: at the origin (every position a
 * multiple of the float step) and at z = 9 (positions not exact in float). */
static void test_segment_joints(void **state)
{
    (void)state;
    const int ks[4] = {1, 2, 7, 18};
    const double cam_z[2] = {0.0, 9.0};
    enum { W = 16, H = 12, N = W * H };
    for (int c = 0; c < 2; c++)
        for (int q = 0; q < 4; q++) {
            static struct scene s;
            /* the (force-free) centre away from the camera: see the known bug at the end of this file */
            base_scene(&s, STRAIGHT_INTEGRATED, 0.0, v3(50.0, 0.0, 0.0));
            s.render.bound_radius = 40.0;
            double seg = s.render.steps_per_segment * s.render.step_size;
            double plane_z = cam_z[c] - ks[q] * seg;
            struct object *o = hc_add_object(&s, PRIM_RECT, "wall");
            o->center = v3(0.0, 0.0, plane_z);
            o->axis_u = v3(1.0, 0.0, 0.0);
            o->axis_v = v3(0.0, 1.0, 0.0);
            hc_aim(&s, v3(0.0, 0.0, cam_z[c]), v3(0.0, 0.0, -1.0));
            s.camera.fov_deg = 0.5;
            struct cpu_image cpu;
            struct hc_gpu g;
            hc_render_both(&s, W, H, &cpu, &g);
            long cracks_cpu = 0, cracks_gpu = 0;
            double off_plane_cpu = 0, off_plane_gpu = 0, depth_cpu = 0, depth_gpu = 0, apart = 0;
            for (int j = 0; j < H; j++)
                for (int i = 0; i < W; i++) {
                    int p = j * W + i;
                    const struct dump_record *a = &cpu.dump.records[p], *b = &g.dump.records[p];
                    vec3d d = camera_ray(&s, i, j);
                    double want_depth = ks[q] / -d.z;          /* k / cos(theta) */
                    cracks_cpu += a->outcome != 0;
                    cracks_gpu += b->outcome != 0;
                    if (a->outcome == 0) {
                        off_plane_cpu = fmax(off_plane_cpu, fabs(a->hit[2] - plane_z));
                        depth_cpu = fmax(depth_cpu, fabs(a->depth - want_depth));
                    }
                    if (b->outcome == 0) {
                        off_plane_gpu = fmax(off_plane_gpu, fabs(b->hit[2] - plane_z));
                        depth_gpu = fmax(depth_gpu, fabs(b->depth - want_depth));
                    }
                    if (a->outcome == 0 && b->outcome == 0)
                        apart = fmax(apart, hc_dist3f(a->hit, b->hit));
                }
            long nonfinite = hc_gpu_nonfinite(&g);
            print_message("camera z %g, wall at k = %2d (z = %+5.1f): cracks cpu %ld gpu %ld; |hit z - wall| cpu %.1e gpu %.1e; "
                          "|depth - k/cos| cpu %.1e gpu %.1e; cpu-gpu hit %.1e\n", cam_z[c], ks[q], plane_z, cracks_cpu,
                          cracks_gpu, off_plane_cpu, off_plane_gpu, depth_cpu, depth_gpu, apart);
            assert_int_equal(nonfinite, 0);
            /* No cracks: the wall covers the whole view, so every ray must hit it on both engines. */
            assert_int_equal(cracks_cpu, 0);
            assert_int_equal(cracks_gpu, 0);
            /* On the wall: the CPU locates the crossing to double resolution and stores it as float:
             * within one ulp of the wall's z (plus 1e-12 where z = 0). The GPU's hit is
             * a + t (b - a) in float with a and b one step apart across the wall: two roundings at
             * the larger of |z| and the step, at most 2 ulp. */
            double z_scale = fmax(fabs(plane_z), s.render.step_size);
            assert_true(off_plane_cpu <= hc_ulp(plane_z) + 1e-12);
            assert_true(off_plane_gpu <= 2.0 * hc_ulp(z_scale));
            /* Depth k / cos(theta) in segments. CPU: lambda from the dense output (rtol 1e-10), stored
             * as float: 1e-6 relative. GPU: every step x += h v rounds z by up to half an ulp of the
             * largest |z| passed, which in segments is ulp / 2 / (10 h); over the 10 k steps before the
             * wall that adds up to k ulp / (2 h) (the rounding repeats alike step after step, so the
             * worst case is nearly reached: 9.3e-6 of a 9.5e-6 bound for k = 1 from z = 9). Bound: 2x. */
            double z_max = fmax(fabs(cam_z[c]), fabs(plane_z));
            assert_true(depth_cpu <= 1e-6 * ks[q]);
            assert_true(depth_gpu <= 2.0 * ks[q] * hc_ulp(z_max) / (2.0 * s.render.step_size) + 1e-6);
            /* The hit points of both engines: x and y stay below 0.08, where float rounding is 7e-9 per
             * step (2.5e-6 over 360 steps, linearly), and the float camera ray is off by ~1e-7 rad
             * (1e-6 over 9 units): 1e-5. */
            assert_true(apart <= 1e-5);
            cpu_image_free(&cpu);
            hc_gpu_free(&g);
        }
}

/* ---- regression: a ray at the model's centre in a model without a horizon ----
 * The GPU used to count a ray whose position is exactly the model's centre as captured even when
 * the model has no horizon (capture radius 0): travelling() required |x - centre|^2 > 0 and the
 * termination test used <= 0, both true at distance 0, so a camera at the centre rendered every
 * pixel black, flat space included. Both stages now capture only where the capture radius is > 0,
 * as the CPU reference does.
 * Reproduction: the test scene (flat) and the potential scene with zeta = -1e-20 (integrated, with
 * a force below float rounding; zeta = 0 would be flat space, cast without integration), the
 * camera at the model centre: no ray may be captured, and GPU and CPU outcomes agree. */
static void test_camera_at_model_centre(void **state)
{
    (void)state;
    static const char *const flat_sets[] = {"camera.position=0 0 0", "camera.look_at=0 0 -1", NULL};
    static const char *const potential_sets[] = {"model.zeta=-1e-20", "camera.position=0 0.2 2.5", "camera.look_at=0 0 -1",
                                                 NULL};
    const char *const scenes[2] = {"test", "potential"};
    const char *const *const sets[2] = {flat_sets, potential_sets};
    long captured[2], differ[2];
    for (int k = 0; k < 2; k++) {
        static struct scene s;
        hc_load(&s, scenes[k], 8, 6, sets[k]);
        assert_true(v3_len(v3_sub(s.camera.position, s.model.center)) == 0.0);
        struct cpu_image cpu;
        struct hc_gpu g;
        hc_cpu_render(&s, &cpu);
        hc_gpu_render(&s, &g);
        captured[k] = hc_count_outcome(&g.dump, DUMP_CAPTURED);
        differ[k] = 0;
        for (int i = 0; i < 48; i++)
            differ[k] += cpu.dump.records[i].outcome != g.dump.records[i].outcome;
        print_message("camera at the %s model's centre: gpu captured %ld of 48 (cpu %ld); outcomes differ on %ld\n",
                      model_name(s.model.type), captured[k], hc_count_outcome(&cpu.dump, DUMP_CAPTURED), differ[k]);
        cpu_image_free(&cpu);
        hc_gpu_free(&g);
    }
    for (int k = 0; k < 2; k++) {
        assert_int_equal(captured[k], 0);   /* was 48 of 48 before the fix */
        assert_int_equal(differ[k], 0);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tangent_sphere),
        cmocka_unit_test(test_rays_in_plane),
        cmocka_unit_test(test_degenerate_triangles),
        cmocka_unit_test(test_segment_joints),
        cmocka_unit_test(test_camera_at_model_centre),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
