/* Hard cases of numerical stability near a black hole (Schwarzschild, G = c = 1), each on the double-precision CPU reference (ref_trace / cpu_render) and on the GPU
 * (EGL, default path fp32+MRT on llvmpipe): the photon sphere, observers near the horizon and far
 * away, a shadow that fills the view, a mass going to zero (rays aimed exactly at a centre:
 * test_hard_centres.c).
 * Measured numbers are printed; every tolerance is justified next to its assertion. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "hard_cases.h"
#include "physics/escape.h"

/* 1/b^2 of a state: the Binet invariant u'^2 + u^2 - 2 M u^3 with u = 1/r and
 * u' = du/dphi = -(yhat . v) / h, h = |y x v|. Conserved exactly along every orbit of the model. */
static double inverse_b2(vec3d centre, double mass, vec3d x, vec3d v)
{
    vec3d y = v3_sub(x, centre);
    double r = v3_len(y), h = v3_len(v3_cross(y, v));
    double radial = v3_dot(y, v) / r;
    return radial * radial / (h * h) + 1.0 / (r * r) - 2.0 * mass / (r * r * r);
}

/* The same for a ray that reached the sky: its reported direction is the one at infinity
 * (physics/escape.h), so the direction it had at x is found again as the one whose way on to
 * infinity sweeps the angle between x and that direction (escape_sweep, by bisection; outwards). */
static double inverse_b2_of_sky(vec3d centre, double mass, vec3d x, vec3d at_infinity)
{
    vec3d y = v3_sub(x, centre);
    double r = v3_len(y), u = 1.0 / r;
    double sweep = atan2(v3_len(v3_cross(y, at_infinity)), v3_dot(y, at_infinity));
    double lo = 1e-9, hi = 0.5 * 3.14159265358979323846;
    for (int i = 0; i < 80; i++) {
        double mid = 0.5 * (lo + hi);
        if (escape_sweep(mass, u, -u * cos(mid) / sin(mid)) < sweep)
            lo = mid;
        else
            hi = mid;
    }
    double s = sin(0.5 * (lo + hi));
    return u * u / (s * s) - 2.0 * mass * u * u * u;
}

/* Empty Schwarzschild space, M = 1 at the origin, sky colour, no objects, RK4. */
static void empty_hole(struct scene *s, double bound, double step, int steps_per_segment, int segments)
{
    scene_defaults(s);
    snprintf(s->name, sizeof s->name, "hard_schwarzschild");
    s->model.type = MODEL_SCHWARZSCHILD;
    s->model.mass = 1.0;
    s->model.center = v3(0.0, 0.0, 0.0);
    s->render.bound_radius = bound;
    s->render.step_size = step;
    s->render.steps_per_segment = steps_per_segment;
    s->render.steps_per_pass = 64;
    while (steps_per_segment % s->render.steps_per_pass)
        s->render.steps_per_pass--;
    s->render.segments = segments;
    s->render.method = METHOD_RK4;
}

/* ---- 1. the photon sphere ---- */

/* A static observer at r = 30 M sends rays with impact parameter b = b_c (1 + eps), b_c = 3 sqrt(3) M,
 * b = r sin(psi) / sqrt(1 - 2M/r) with psi measured from the inward direction: b < b_c falls in,
 * b > b_c turns back outside r = 3 M and escapes. The camera of a 1x1 image looks exactly along psi. */
static void test_photon_sphere(void **state)
{
    (void)state;
    static struct scene s;
    const double r0 = 30.0, lapse = sqrt(1.0 - 2.0 / r0);
    const double eps[4] = {-1e-3, 1e-3, -1e-6, 1e-6};
    /* GPU steps: 0.05 M (the scene file's step in absolute units; 2000 to 3000 steps per ray) and
     * 0.05 / 0.12 M = 0.417 M (the schwarzschild scene's step relative to its mass M = 0.12). */
    const double steps[2] = {0.05, 0.05 / 0.12};
    double winding[4], rk4_drift[2] = {0.0, 0.0};
    int rk4_right[2] = {0, 0};
    for (int k = 0; k < 4; k++) {
        double b = HC_B_CRIT * (1.0 + eps[k]);
        double psi = asin(b * lapse / r0);
        vec3d dir = v3(sin(psi), 0.0, -cos(psi));
        int32_t want = eps[k] < 0.0 ? DUMP_CAPTURED : DUMP_SKY;
        empty_hole(&s, 40.0, steps[0], 50, 60);
        hc_aim(&s, v3(0.0, 0.0, r0), dir);
        s.render.width = s.render.height = 1;
        hc_validate(&s);

        struct ref_ray ray;
        hc_cpu_ray(&s, dir, &ray);
        winding[k] = ray.winding;
        print_message("b = b_c (1 %+.0e): cpu %-8s winding %.4f rad, closest r %.6f M, %ld steps\n", eps[k],
                      dump_outcome_name(ray.outcome), ray.winding, ray.min_radius, ray.steps);
        /* The reference integrates to rtol 1e-10 per step, 4 orders below the smallest gap (2e-6 in
         * 1/b^2): its outcome must be exact for all four rays. */
        assert_int_equal(ray.outcome, want);
        assert_true(v3_isfinite(ray.position) && v3_isfinite(ray.velocity) && isfinite(ray.winding));
        /* An orbit with b > b_c turns at its largest root of 1/b^2 = u^2 - 2 M u^3, always at r > 3 M. */
        if (want == DUMP_SKY)
            assert_true(ray.min_radius > 3.0);

        for (int m = 0; m < 2; m++)
            for (int st = 0; st < 2; st++) {
                s.render.method = m ? METHOD_EULER : METHOD_RK4;
                s.render.step_size = steps[st];
                s.render.segments = st ? 10 : 60;   /* lambda up to 150 / 208: the rays end well before */
                struct hc_gpu g;
                hc_gpu_render(&s, &g);
                int32_t got = g.dump.records[0].outcome;
                double drift = (got == DUMP_SKY ? inverse_b2_of_sky(s.model.center, 1.0, hc_gpu_x(&g, 0), hc_gpu_v(&g, 0))
                                                : inverse_b2(s.model.center, 1.0, hc_gpu_x(&g, 0), hc_gpu_v(&g, 0))) *
                                   b * b - 1.0;
                long nonfinite = hc_gpu_nonfinite(&g);
                print_message("    gpu %-5s h %.3f M: %-8s%s  1/b^2 drift at the end %+.2e (the gap is %+.0e)\n",
                              method_name(s.render.method), steps[st], dump_outcome_name(got),
                              got == want ? "" : " (wrong)", drift, 2.0 * eps[k]);
                /* Every GPU configuration, however inaccurate, keeps a finite ray state. */
                assert_int_equal(nonfinite, 0);
                if (m == 0 && st == 0 && fabs(eps[k]) == 1e-3) {
                    rk4_drift[k] = drift;       /* asserted after the CPU checks, below */
                    rk4_right[k] = got == want;
                }
                /* The rest is reported only. Euler is first order: its drift at h = 0.05 M is ~6%,
                 * 30x the gap. At h = 0.417 M RK4 drifts by up to ~20% on the captured rays (the
                 * steps are coarse where the ray falls through r ~ 2-3 M). And b = b_c (1 +- 1e-6) is
                 * beyond fp32 on any step: the gap of 2e-6 in 1/b^2 is below the drift that RK4's
                 * truncation (7.5e-6 on the plunge) and the rounding of float positions (~2e-5,
                 * below) produce over the orbit. */
                hc_gpu_free(&g);
            }
    }
    double below = winding[2] - winding[0], above = winding[3] - winding[1];
    print_message("winding from eps = 1e-3 to 1e-6: captured side %+.4f rad, escaping side %+.4f rad, "
                  "ln(1000) = %.4f\n", below, above, log(1000.0));
    /* Linearised about u = 1/(3M), Binet's equation is du'' = du: the deviation grows like e^phi,
     * so a ray that starts eps away from the separatrix spends phi = ln(1/|eps|) + C (+ O(sqrt eps))
     * near the photon sphere, on either side. Going from 1e-3 to 1e-6 adds ln(1000) = 6.908 rad.
     * Tolerance 0.1 rad: covers the O(sqrt(1e-3)) ~ 0.03 correction to the asymptotic law; a
     * winding counted twice, or missing half an orbit, is off by radians. */
    assert_true(fabs(below - log(1000.0)) < 0.1);
    assert_true(fabs(above - log(1000.0)) < 0.1);
    /* GPU, RK4 at h = 0.05 M, b = b_c (1 -+ 1e-3). RK4's truncation at this step: a double-precision
     * RK4 from the same start drifts by 7.5e-6 on the captured ray (all in its plunge through
     * r < 3 M) and 3e-11 on the escaping one. fp32 rounding: half an ulp of the position per step
     * (<= 2e-6 at r < 32 M) in h = |y x v|, a random walk of ~5e-5 M over ~1600 steps, ~2e-5 in
     * 1/b^2 (a correct fp32 camera ray measures 2e-6 and 7e-6). Bound 1e-4: 5x that and 20x below
     * the 2e-3 gap, so the outcome is decided by b and not by rounding; only with that bound met is
     * the outcome asserted. (Currently fails, -1.9e-4: the known camera-ray bug at the end of this
     * file; its 5e-5 rad start error is 3e-4 of b at sin(psi) = 0.17.) */
    for (int k = 0; k < 2; k++) {
        assert_true(fabs(rk4_drift[k]) <= 1e-4);
        assert_true(rk4_right[k]);
    }
}

/* ---- 2. observers near the horizon and far away ---- */

/* Exact fate of a ray leaving a static observer at x (M = 1 at the origin) in the unit local
 * direction dir: r > 3M: inward escapes iff b > b_c, outward always escapes; r < 3M: inward is
 * always captured, outward escapes iff b < b_c. +1 escapes, -1 captured; closeness = |b/b_c - 1|. */
static int exact_fate(vec3d x, vec3d dir, double *closeness)
{
    double r = v3_len(x);
    vec3d out = v3_scale(x, 1.0 / r);
    double b = r * v3_len(v3_cross(dir, out)) / sqrt(1.0 - 2.0 / r);
    int inward = v3_dot(dir, out) < 0.0;
    *closeness = fabs(b / HC_B_CRIT - 1.0);
    if (r > 3.0)
        return inward ? (b > HC_B_CRIT ? 1 : -1) : 1;
    return inward ? -1 : (b < HC_B_CRIT ? 1 : -1);
}

/* Pixels this close to b_c (relative) are not checked. CPU: 1e-6, where case 1 shows the reference
 * still exact. GPU: 1e-2, 200x the 5e-5 in b (1e-4 in 1/b^2) that case 1 bounds for fp32 RK4 at
 * h = 0.05 M, with room for the float camera ray's start error (1e-7 rad, over sin(psi) ~ 5e-3 at
 * 1000 M: 2e-5) and for the far observer's 10^4 steps of 0.1 M at |x| ~ 1000 (ulp 6e-5). */
#define CPU_MARGIN 1e-6
#define GPU_MARGIN 1e-2

struct view {
    const char *name;
    double r, fov;
    vec3d dir;
    double bound, step;
    int steps_per_segment, segments;
};

static void test_observers(void **state)
{
    (void)state;
    /* Bound radius, step and segments let every ray end: lambda_max = 100 M near the hole (an
     * escaping ray needs < 20 M plus ~3 M per radian around the photon sphere, ln(1/1e-6) ~ 14 rad at
     * most here) and 3072 M for the observer at 1000 M (in to ~3 M and out to 1100 M). */
    const struct view views[] = {
        {"2.01 M, at the hole", 2.01, 60.0, {0, 0, -1}, 20.0, 0.05, 50, 40},
        {"2.01 M, outward", 2.01, 40.0, {0, 0, 1}, 20.0, 0.05, 50, 40},
        {"2.5 M, at the hole", 2.5, 60.0, {0, 0, -1}, 20.0, 0.05, 50, 40},
        {"2.5 M, tangential", 2.5, 120.0, {1, 0, 0}, 20.0, 0.05, 50, 40},
        {"1000 M, at the hole", 1000.0, 1.0, {0, 0, -1}, 1100.0, 0.1, 640, 48},
    };
    enum { W = 24, H = 18 };
    for (size_t k = 0; k < sizeof views / sizeof views[0]; k++) {
        const struct view *w = &views[k];
        static struct scene s;
        empty_hole(&s, w->bound, w->step, w->steps_per_segment, w->segments);
        hc_aim(&s, v3(0.0, 0.0, w->r), w->dir);
        s.camera.fov_deg = w->fov;
        struct cpu_image cpu;
        struct hc_gpu g;
        hc_render_both(&s, W, H, &cpu, &g);
        int escape = 0, cpu_wrong = 0, gpu_wrong = 0, cpu_skipped = 0, gpu_skipped = 0, gpu_wrong_in_margin = 0;
        int unfinished = 0;
        double nearest = INFINITY;
        for (int j = 0; j < H; j++)
            for (int i = 0; i < W; i++) {
                int p = j * W + i;
                double close;
                int fate = exact_fate(s.camera.position, camera_ray(&s, i, j), &close);
                int32_t want = fate > 0 ? DUMP_SKY : DUMP_CAPTURED;
                escape += fate > 0;
                nearest = fmin(nearest, close);
                unfinished += (cpu.dump.records[p].outcome == DUMP_UNFINISHED) + (g.dump.records[p].outcome == DUMP_UNFINISHED);
                if (close < CPU_MARGIN)
                    cpu_skipped++;
                else
                    cpu_wrong += cpu.dump.records[p].outcome != want;
                if (close < GPU_MARGIN) {
                    gpu_skipped++;
                    gpu_wrong_in_margin += g.dump.records[p].outcome != want;
                } else {
                    gpu_wrong += g.dump.records[p].outcome != want;
                }
            }
        long nonfinite = hc_gpu_nonfinite(&g);
        print_message("%-20s %3d of %d pixels escape; nearest |b/b_c - 1| %.1e; wrong: cpu %d (%d skipped), "
                      "gpu %d (%d skipped, %d of them wrong); unfinished %d\n", w->name, escape, W * H, nearest,
                      cpu_wrong, cpu_skipped, gpu_wrong, gpu_skipped, gpu_wrong_in_margin, unfinished);
        assert_int_equal(cpu_wrong, 0);             /* exact outside 1e-6 */
        assert_int_equal(gpu_wrong, 0);             /* stated count: none outside the 1e-2 margin */
        assert_int_equal(unfinished, 0);            /* bound, step and segments let every ray end */
        assert_int_equal(nonfinite, 0);
        assert_int_equal(hc_dump_nonfinite(&cpu.dump), 0);
        cpu_image_free(&cpu);
        hc_gpu_free(&g);
    }
}

/* ---- 3. a shadow that fills the view ---- */

/* The schwarzschild scene with M raised to 2.57: the camera, 5.14198 from the mass, sits at
 * 1.0004 horizon radii, inside the photon sphere (3M = 7.71), and every pixel looks inward (the
 * hole is 4 degrees off the view axis, the image corners 31 degrees): every ray is captured. */
static void test_shadow_fills_view(void **state)
{
    (void)state;
    static struct scene s;
    static const char *const sets[] = {"model.mass=2.57", NULL};
    hc_load(&s, "schwarzschild", 32, 24, sets);       /* scene_validate accepts it */
    double r = v3_len(v3_sub(s.camera.position, s.model.center));
    struct cpu_image cpu;
    struct hc_gpu g;
    hc_cpu_render(&s, &cpu);
    hc_gpu_render(&s, &g);
    long cpu_captured = hc_count_outcome(&cpu.dump, DUMP_CAPTURED), gpu_captured = hc_count_outcome(&g.dump, DUMP_CAPTURED);
    long nonfinite = hc_gpu_nonfinite(&g);
    print_message("camera at r = %.5f = %.5f horizon radii: captured cpu %ld, gpu %ld of %d; cpu steps %ld\n", r,
                  r / (2.0 * s.model.mass), cpu_captured, gpu_captured, 32 * 24, cpu.steps);
    assert_true(r > 2.0 * s.model.mass && r < 1.001 * 2.0 * s.model.mass);
    assert_int_equal(cpu_captured, 32 * 24);
    assert_int_equal(gpu_captured, 32 * 24);
    assert_int_equal(nonfinite, 0);
    assert_int_equal(hc_dump_nonfinite(&cpu.dump), 0);
    cpu_image_free(&cpu);
    hc_gpu_free(&g);
}

/* ---- 4. the mass going continuously to zero ---- */

/* Pixels whose straight ray changes its object when every object grows or shrinks by `margin` of
 * its size: within margin * size of a silhouette. */
static int silhouette_pixels(const struct scene *s, double margin, int32_t *shrunk, int32_t *grown, char *on)
{
    int n = 0;
    straight_cast_grown(s, -margin, shrunk);
    straight_cast_grown(s, margin, grown);
    for (int i = 0; i < s->render.width * s->render.height; i++) {
        on[i] = shrunk[i] != grown[i];
        n += on[i];
    }
    return n;
}

static void test_mass_to_zero(void **state)
{
    (void)state;
    enum { W = 32, H = 24, N = W * H };
    static struct scene s0, s1;
    static const char *const zero[] = {"model.mass=0", NULL};
    static const char *const tiny[] = {"model.mass=1e-6", NULL};
    hc_load(&s0, "schwarzschild", W, H, zero);
    hc_load(&s1, "schwarzschild", W, H, tiny);
    const double mass = s1.model.mass;
    struct cpu_image c0, c1;
    struct hc_gpu g0, g1;
    hc_cpu_render(&s0, &c0);
    hc_cpu_render(&s1, &c1);
    hc_gpu_render(&s0, &g0);
    hc_gpu_render(&s1, &g1);
    assert_int_equal(hc_gpu_nonfinite(&g0), 0);
    assert_int_equal(hc_gpu_nonfinite(&g1), 0);

    /* Predicted hit shift of each pixel: the straight ray passes the mass at impact parameter b and
     * is turned by at most 4M/b (the whole-orbit deflection; a ray from a finite distance gets less),
     * so after a path L its point is off by at most 4M/b * L, and on a surface hit at incidence cos_i by
     * that over cos_i. */
    static double predicted[N];
    double pred_max_perp = 0.0;  /* largest 4M/b * L: how far any ray moves across a silhouette */
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            int p = j * W + i;
            vec3d d = camera_ray(&s0, i, j), cam = s0.camera.position;
            double b = v3_len(v3_cross(v3_sub(s0.model.center, cam), d));
            double reach = 2.0 * s0.render.bound_radius;
            predicted[p] = 0.0;
            const struct dump_record *r0 = &c0.dump.records[p];
            if (r0->outcome >= 0) {
                vec3d hit = v3(r0->hit[0], r0->hit[1], r0->hit[2]);
                double L = v3_len(v3_sub(hit, cam));
                double cos_i = fabs(v3_dot(hc_object_normal(&s0.objects[r0->outcome], hit), d));
                predicted[p] = 4.0 * mass / b * L / cos_i;
                reach = L;
            }
            pred_max_perp = fmax(pred_max_perp, 4.0 * mass / b * reach);
        }

    /* Outcomes: the shift moves a ray across a silhouette only if it passes within pred_max_perp of
     * it. Relative to the objects (spheres r >= 0.9, the sail's edges >= 0.79 from its centroid, the
     * floor's half-width 6), that is a growth margin of pred_max_perp / 0.5, doubled. The GPU's fp32
     * positions carry ~1e-4 of rounding after a few hundred steps (5e-4 relative, as in test_render's
     * straight-cast test): its margin adds that. */
    static int32_t shrunk[N], grown[N];
    static char on_cpu[N], on_gpu[N];
    double margin_cpu = 2.0 * pred_max_perp / 0.5, margin_gpu = margin_cpu + 5e-4;
    int sil_cpu = silhouette_pixels(&s0, margin_cpu, shrunk, grown, on_cpu);
    int sil_gpu = silhouette_pixels(&s0, margin_gpu, shrunk, grown, on_gpu);
    int differ_cpu = 0, differ_gpu = 0, off_cpu = 0, off_gpu = 0;
    for (int i = 0; i < N; i++) {
        int dc = c0.dump.records[i].outcome != c1.dump.records[i].outcome;
        int dg = g0.dump.records[i].outcome != g1.dump.records[i].outcome;
        differ_cpu += dc;
        differ_gpu += dg;
        off_cpu += dc && !on_cpu[i];
        off_gpu += dg && !on_gpu[i];
    }
    print_message("M = 1e-6 vs M = 0: outcomes differ on %d (cpu) and %d (gpu) pixels, %d and %d of them off the "
                  "silhouettes (margins %.1e and %.1e: %d and %d silhouette pixels)\n", differ_cpu, differ_gpu, off_cpu,
                  off_gpu, margin_cpu, margin_gpu, sil_cpu, sil_gpu);
    assert_int_equal(off_cpu, 0);
    assert_int_equal(off_gpu, 0);

    /* Hit points: CPU within 2x the prediction (factor 2: the estimate of the lever arm is rough);
     * GPU within 2x the prediction plus 1e-4 of fp32 rounding (the two GPU renders round alike
     * until the tiny force changes a last bit; half an ulp of |x| <= 16 per step, ~1e-6, over the
     * ~500 steps to the far objects grows as a random walk to ~2e-5, 1e-4 leaves 5x). */
    double cpu_ratio = 0.0, cpu_shift = 0.0, gpu_excess = -INFINITY, gpu_shift = 0.0;
    int compared = 0;
    for (int p = 0; p < N; p++) {
        const struct dump_record *a0 = &c0.dump.records[p], *a1 = &c1.dump.records[p];
        const struct dump_record *b0 = &g0.dump.records[p], *b1 = &g1.dump.records[p];
        if (a0->outcome < 0 || a0->outcome != a1->outcome || on_gpu[p])
            continue;
        double dc = hc_dist3f(a0->hit, a1->hit);
        cpu_ratio = fmax(cpu_ratio, dc / predicted[p]);
        cpu_shift = fmax(cpu_shift, dc);
        if (b0->outcome == a0->outcome && b1->outcome == a0->outcome) {
            double dg = hc_dist3f(b0->hit, b1->hit);
            gpu_excess = fmax(gpu_excess, dg - 2.0 * predicted[p]);
            gpu_shift = fmax(gpu_shift, dg);
            compared++;
        }
    }
    print_message("hit shift M = 1e-6 vs 0 over %d hit pixels: cpu max %.2e (at most %.2f of 4M/b L/cos_i), "
                  "gpu max %.2e (exceeds 2x the prediction by at most %.2e)\n", compared, cpu_shift, cpu_ratio,
                  gpu_shift, gpu_excess);
    assert_true(compared > N / 4);
    assert_true(cpu_ratio <= 2.0);
    assert_true(gpu_excess <= 1e-4);

    /* CPU(M = 1e-6) against GPU(M = 1e-6). Outcomes may differ only on the GPU silhouette pixels.
     * Hit points: fp32 positions near |x| = 10 carry ~1e-5..1e-4 of rounding after the ~500 RK4 steps
     * (a correct fp32 path measures 4e-5 here); p99 <= 5e-4 and max <= 2e-3 scene units leave room for
     * grazing incidence on the floor (a factor ~4). Sky directions: each step rounds v to 6e-8;
     * a random walk over 800 steps is ~2e-6 rad, bound 5e-5 (the worst case, linear accumulation).
     * (Currently fails: p99 4.9e-3, max 1.1e-2, sky 2.7e-4 rad, all from the known camera-ray bug
     * below; with a select-based model_initial_velocity the same run gives 3.1e-5, 4.1e-5, 1.5e-6.) */
    struct compare_result cr;
    hc_compare(&g1.dump, &c1.dump, &cr);
    int differ_off = 0;
    for (int i = 0; i < N; i++)
        differ_off += g1.dump.records[i].outcome != c1.dump.records[i].outcome && !on_gpu[i];
    print_message("gpu vs cpu at M = 1e-6: %ld outcomes differ (%d off the silhouettes); hit error mean %.2e p99 %.2e "
                  "max %.2e; sky angle max %.2e rad\n", cr.outcomes.differ, differ_off, cr.hit.mean, cr.hit.p99, cr.hit.max,
                  cr.sky_angle.max);
    assert_int_equal(differ_off, 0);
    assert_int_equal(cr.outcomes.failed_a + cr.outcomes.failed_b, 0);
    assert_int_equal(cr.hit.non_finite + cr.sky_angle.non_finite, 0);
    assert_true(cr.hit.p99 <= 5e-4);
    assert_true(cr.hit.max <= 2e-3);
    assert_true(cr.sky_angle.max <= 5e-5);
    cpu_image_free(&c0);
    cpu_image_free(&c1);
    hc_gpu_free(&g0);
    hc_gpu_free(&g1);
}

/* ---- regression: Schwarzschild camera rays at full precision ----
 * On EGL (GLSL ES 1.00, Mesa llvmpipe) the Schwarzschild camera rays used to be computed at 16 bits:
 * model_initial_velocity() returned early from an `if`, the pattern common.glsl warns about (Mesa
 * evaluates expressions in a branch at 16 bits). Every Schwarzschild pixel started up to 3e-4 rad
 * off (other models: 7e-8), which showed as 1e-2 hit errors against the reference at M = 1e-6 and
 * 2e-4 drift of 1/b^2 at the photon sphere. The shader now computes the bent direction for every
 * ray and selects.
 * Reproduction: a step of 1e-30 leaves every ray where setup put it; the GPU's velocity must be
 * model_initial_velocity(camera_ray) to fp32 accuracy. Tolerance 1e-6 rad: a float camera ray
 * (normalize of a sum of three float vectors) is good to a few 1e-8. */
static void test_schwarzschild_camera_ray_precision(void **state)
{
    (void)state;
    enum { W = 32, H = 24 };
    /* the integrators' setup stage (the scene's exact orbits take their launch angle elsewhere) */
    static const char *const sets[] = {"render.method=rk4", "render.step=1e-30", "render.segments=1", NULL};
    const char *const scenes[] = {"potential", "schwarzschild"};
    double worst[2] = {0.0, 0.0};
    for (int k = 0; k < 2; k++) {
        static struct scene s;
        hc_load(&s, scenes[k], W, H, sets);
        struct hc_gpu g;
        hc_gpu_render(&s, &g);
        for (int j = 0; j < H; j++)
            for (int i = 0; i < W; i++) {
                vec3d want = v3_normalize(model_initial_velocity(&s.model, s.camera.position, camera_ray(&s, i, j)));
                vec3d got = v3_normalize(hc_gpu_v(&g, j * W + i));
                worst[k] = fmax(worst[k], atan2(v3_len(v3_cross(want, got)), v3_dot(want, got)));
            }
        print_message("%-14s largest error of a GPU camera ray: %.2e rad\n", scenes[k], worst[k]);
        hc_gpu_free(&g);
    }
    assert_true(worst[0] <= 1e-6);      /* the control: a model without the early return */
    assert_true(worst[1] <= 1e-6);      /* was 3e-4 rad on EGL before the fix */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_photon_sphere),
        cmocka_unit_test(test_observers),
        cmocka_unit_test(test_shadow_fills_view),
        cmocka_unit_test(test_mass_to_zero),
        cmocka_unit_test(test_schwarzschild_camera_ray_precision),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
