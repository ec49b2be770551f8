/* The star sky ([sky] stars, milky_way): the generated catalogue (deterministic, its distributions,
 * its lookup by direction), black-body colours, and every star of a test sky at the pixel its
 * direction predicts with its flux, in flat space at rest and seen from a ship at 0.6 c, on both
 * engines; and a lensed star's brightness against the point lens's magnification. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdlib.h>
#include "hard_cases.h"
#include "io/sample_average.h"
#include "physics/bright_stars.h"
#include "physics/relativity.h"
#include "physics/star_catalogue.h"
#include "render/frame.h"
#include "results/star_light.h"
#include "results/star_map.h"
#include "scene/camera.h"

/* The same seed gives the same stars, another seed other stars; every star lies in its cell. */
static void test_catalogue_deterministic(void **state)
{
    (void)state;
    struct star_catalogue a, b, c;
    vec3d pole = v3(0.2, 1.0, 0.3);
    assert_int_equal(star_catalogue_make(&a, 5000, 7, pole, v3(0, 0, -1)), 0);
    assert_int_equal(star_catalogue_make(&b, 5000, 7, pole, v3(0, 0, -1)), 0);
    assert_int_equal(star_catalogue_make(&c, 5000, 8, pole, v3(0, 0, -1)), 0);
    assert_int_equal(a.n, 5000);
    assert_memory_equal(a.stars, b.stars, 5000 * sizeof *a.stars);
    int same = 0;
    for (int i = 0; i < 5000; i++)
        same += memcmp(&a.stars[i], &c.stars[i], sizeof a.stars[i]) == 0;
    assert_int_equal(same, 0);
    for (int cell = 0; cell < a.rows * a.columns; cell++)
        for (int k = a.cell_start[cell]; k < a.cell_start[cell + 1]; k++) {
            double lat, lon;
            star_catalogue_galactic(&a, a.stars[k].direction, &lat, &lon);
            int row = (int)floor((lat + 0.5 * PI_D) / a.row_step), col = (int)floor((lon + PI_D) / a.column_step);
            row = row >= a.rows ? a.rows - 1 : row;
            col = col >= a.columns ? a.columns - 1 : col;
            assert_int_equal(row * a.columns + col, cell);
            assert_true(fabs(v3_len(a.stars[k].direction) - 1.0) < 1e-12);
        }
    assert_int_equal(a.cell_start[a.rows * a.columns], 5000);
    star_catalogue_free(&a);
    star_catalogue_free(&b);
    star_catalogue_free(&c);
}

/* |observed - expected| within 5 standard deviations of a binomial count. */
static void assert_share(long count, long n, double p, const char *what)
{
    double sd = sqrt(n * p * (1.0 - p));
    if (fabs(count - n * p) > 5.0 * sd)
        fail_msg("%s: %ld of %ld, expected %.0f +- %.0f", what, count, n, n * p, 5.0 * sd);
}

/* 200000 stars: magnitudes follow N(<m) ~ 10^(0.5 m) (a tenth of the stars are 2 magnitudes
 * brighter than the faintest), the spectral classes come in their shares, and the disk half gathers
 * toward the galactic plane. */
static void test_catalogue_distributions(void **state)
{
    (void)state;
    struct star_catalogue c;
    const int n = 200000;
    assert_int_equal(star_catalogue_make(&c, n, 1, v3(0.0, 0.0, 1.0), v3(1.0, 0.0, 0.0)), 0);
    double faintest = star_faintest_magnitude(n), brightest = INFINITY, dimmest = -INFINITY;
    assert_true(fabs(faintest - (6.0 + 2.0 * log10(40.0))) < 1e-12);
    long two_brighter = 0, near_plane = 0, hot = 0, a_class = 0, m_class = 0;
    for (int i = 0; i < n; i++) {
        const struct star *s = &c.stars[i];
        brightest = fmin(brightest, s->magnitude);
        dimmest = fmax(dimmest, s->magnitude);
        two_brighter += s->magnitude < faintest - 2.0;
        near_plane += fabs(s->direction.z) < sin(0.2);
        assert_true(s->temperature >= 2400.0 && s->temperature <= 45000.0);
        hot += s->temperature >= 30000.0;
        a_class += s->temperature >= 7500.0 && s->temperature < 10000.0;
        m_class += s->temperature < 3700.0;
    }
    assert_true(dimmest <= faintest && brightest < faintest - 8.0);
    assert_share(two_brighter, n, 0.1, "stars 2 magnitudes above the faintest");
    assert_share(hot, n, 0.005, "O stars");
    assert_share(a_class, n, 0.2, "A stars");
    assert_share(m_class, n, 0.095, "M stars");
    /* uniform half: sin(0.2) of the sphere; disk half: 1 - e^-1 within a latitude scale */
    assert_share(near_plane, n, 0.5 * sin(0.2) + 0.5 * (1.0 - exp(-1.0)), "stars within 0.2 rad of the plane");
    star_catalogue_free(&c);
}

struct visited {
    char *seen;
    const struct star *base;
};

static void mark(const struct star *s, void *arg)
{
    struct visited *v = arg;
    v->seen[s - v->base] = 1;
}

/* The lookup visits every star within the radius, at the poles and across longitude's seam too. */
static void test_catalogue_near(void **state)
{
    (void)state;
    struct star_catalogue c;
    assert_int_equal(star_catalogue_make(&c, 20000, 3, v3(0.3, -0.2, 1.0), v3(0.0, 1.0, 0.0)), 0);
    struct visited v = {malloc(c.n), c.stars};
    uint64_t x = 12345;
    const double radii[] = {1e-4, 3e-3, 0.05, 0.3, 1.6};
    for (int trial = 0; trial < 400; trial++) {
        double u[3];
        for (int k = 0; k < 3; k++) {
            x = x * 6364136223846793005ull + 1442695040888963407ull;
            u[k] = (double)(x >> 11) * 0x1.0p-53;
        }
        vec3d d = v3_normalize(v3(u[0] - 0.5, u[1] - 0.5, u[2] - 0.5));
        if (trial < 20)   /* right at the poles and on the seam at longitude pi */
            d = trial < 10 ? v3_scale(c.pole, trial % 2 ? 1.0 : -1.0) : v3_normalize(v3_scale(c.x_axis, -1.0));
        double radius = radii[trial % 5];
        memset(v.seen, 0, c.n);
        star_catalogue_near(&c, d, radius, mark, &v);
        for (int i = 0; i < c.n; i++)
            if (acos(fmin(v3_dot(c.stars[i].direction, d), 1.0)) <= radius && !v.seen[i])
                fail_msg("trial %d: star %d within %g rad was not visited", trial, i, radius);
    }
    free(v.seen);
    star_catalogue_free(&c);
}

static double luminance(const double rgb[3]) { return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]; }

/* Unit luminance; a 6500 K star nearly white, a 3000 K one red, a 20000 K one blue. */
static void test_chromaticity(void **state)
{
    (void)state;
    double c[3];
    star_chromaticity(6500.0, c);
    /* BT.709's luminance row of the XYZ -> RGB matrix, to its printed digits */
    assert_true(fabs(luminance(c) - 1.0) < 1e-3);
    assert_true(fabs(c[0] - 1.0) < 0.1 && fabs(c[1] - 1.0) < 0.1 && fabs(c[2] - 1.0) < 0.1);
    star_chromaticity(3000.0, c);
    assert_true(fabs(luminance(c) - 1.0) < 1e-3);
    assert_true(c[0] > c[1] && c[1] > c[2]);
    star_chromaticity(20000.0, c);
    assert_true(c[2] > c[1] && c[1] > c[0]);
}

/* A flat scene of point stars only: camera at the origin looking down -z, black sky. */
static void star_scene(struct scene *s, int width, int height, vec3d velocity)
{
    scene_defaults(s);
    const char *const sets[] = {
        "model.type=flat", "camera.position=0 0 0", "camera.look_at=0 0 -1", "camera.fov=60",
        "sky.color=0 0 0", "sky.stars=400", "sky.star_seed=11", "sky.star_size=0.8",
        "sky.star_brightness=0.01", "render.bound_radius=10", NULL};
    struct error err;
    for (int i = 0; sets[i]; i++)
        if (scene_set(s, sets[i], &err) != 0)
            fail_msg("%s: %s", err.where, err.message);
    s->observer.velocity = velocity;
    s->observer.effects = v3_len(velocity) > 0.0 ? EFFECTS_SEARCHLIGHT : EFFECTS_GEOMETRY;
    s->render.width = width;
    s->render.height = height;
    hc_validate(s);
}

/* Where star direction d (scene frame) falls on the image: pixel coordinates, x right and y down
 * from the top-left pixel's centre, through the pinhole camera of s (aberrated to the observer's
 * frame when it moves). 0 when behind the camera. */
static int project(const struct scene *s, vec3d d, double *x, double *y)
{
    if (v3_len(s->observer.velocity) > 0.0)
        d = aberrate_to_observer(s->observer.velocity, d);
    struct camera_frame f;
    camera_frame_make(s, &f);
    double z = v3_dot(d, f.forward);
    if (z <= 0.0)
        return 0;
    int w = s->render.width, h = s->render.height;
    double ndc_x = v3_dot(d, f.right) / z / (f.tan_half * w / h), ndc_y = v3_dot(d, f.up) / z / f.tan_half;
    *x = (ndc_x + 1.0) * 0.5 * w - 0.5;
    *y = h - 1 - ((ndc_y + 1.0) * 0.5 * h - 0.5);
    return 1;
}

/* Every star of the test sky that lies in view, at least 4 pixels from the edges and from every
 * other star: the brightest pixel of the 9x9 window about its predicted position is the one the
 * position falls in, and the window's light sums to the star's flux (times D^2 under the
 * searchlight) within 1%. color: the image's unclamped sRGB-encoded floats. */
static int check_stars(const struct scene *s, const float *color, const char *engine)
{
    struct star_catalogue c;
    assert_int_equal(star_catalogue_make(&c, s->sky.stars, (uint64_t)s->sky.star_seed, s->sky.galactic_pole, s->sky.galactic_center), 0);
    int w = s->render.width, h = s->render.height, checked = 0;
    for (int i = 0; i < c.n; i++) {
        double x, y;
        if (!project(s, c.stars[i].direction, &x, &y) || x < 4 || y < 4 || x > w - 5 || y > h - 5)
            continue;
        int alone = 1;
        for (int k = 0; k < c.n && alone; k++) {
            double xk, yk;
            alone = k == i || !project(s, c.stars[k].direction, &xk, &yk) || hypot(xk - x, yk - y) > 8.0;
        }
        double doppler = 1.0;
        if (s->observer.effects != EFFECTS_GEOMETRY)
            doppler = camera_doppler(s, aberrate_to_observer(s->observer.velocity, c.stars[i].direction));
        double chroma[3];
        star_chromaticity(c.stars[i].temperature * doppler, chroma);
        /* colours cut at the gamut's edge; positions within 0.05 px of a pixel's border, where
         * either pixel may be the brighter */
        double off_x = fabs(x - floor(x) - 0.5), off_y = fabs(y - floor(y) - 0.5);
        if (!alone || fabs(luminance(chroma) - 1.0) > 1e-3 || off_x < 0.05 || off_y < 0.05)
            continue;
        int px = (int)lrint(x), py = (int)lrint(y), best_x = -1, best_y = -1;
        double best = -1.0, sum = 0.0;
        for (int v = py - 4; v <= py + 4; v++)
            for (int u = px - 4; u <= px + 4; u++) {
                const float *p = color + 4 * ((size_t)v * w + u);
                double lin[3] = {srgb_to_linear(p[0]), srgb_to_linear(p[1]), srgb_to_linear(p[2])};
                double l = luminance(lin);
                sum += l;
                if (l > best) {
                    best = l;
                    best_x = u;
                    best_y = v;
                }
            }
        double flux = s->sky.star_brightness * pow(10.0, -0.4 * (c.stars[i].magnitude - 6.0));
        if (s->observer.effects == EFFECTS_SEARCHLIGHT)
            flux *= doppler * doppler;
        if (best_x != px || best_y != py || fabs(sum / flux - 1.0) > 0.01)
            fail_msg("%s: star %d predicted at (%.2f, %.2f): brightest pixel (%d, %d), light %.5g of flux %.5g",
                     engine, i, x, y, best_x, best_y, sum, flux);
        checked++;
    }
    star_catalogue_free(&c);
    return checked;
}

/* s's float image with its stars drawn by the GPU's own pass (render.star_pass = gpu), reads as asked */
static void render_star_pass(struct scene *s, enum render_read reads, struct render_result *out)
{
    struct error err;
    s->render.star_pass = STAR_PASS_GPU;
    if (render_frame(s, &(struct frame_request){.backend = "egl", .hdr = 1, .reads = reads}, out, NULL, &err) != 0)
        fail_msg("render: %s", err.message);
    s->render.star_pass = STAR_PASS_CPU;
}

/* s's float images: the GPU's rays with the CPU's star pass, the CPU engine's, and the GPU's rays
 * with its own star pass */
static void render_three(struct scene *s, struct render_result *g, struct cpu_image *cpu, struct render_result *gp)
{
    struct error err;
    if (render_frame(s, &(struct frame_request){.backend = "egl", .hdr = 1}, g, NULL, &err) != 0)
        fail_msg("render: %s", err.message);
    struct cpu_render_options o = {.threads = 0, .hdr = 1};
    ref_options_default(&o.ref, s);
    if (cpu_render(s, &o, cpu, &err) != 0)
        fail_msg("cpu render: %s", err.message);
    render_star_pass(s, RENDER_READ_IMAGE, gp);
}

static void stars_on_both_engines(vec3d velocity)
{
    static struct scene s;
    star_scene(&s, 240, 180, velocity);
    struct render_result g;
    struct error err;
    if (render_frame(&s, &(struct frame_request){.backend = "egl", .hdr = 1}, &g, NULL, &err) != 0)
        fail_msg("render: %s", err.message);
    int on_gpu = check_stars(&s, g.color, "gpu");
    struct cpu_image cpu;
    struct cpu_render_options o = {.threads = 0, .hdr = 1};
    ref_options_default(&o.ref, &s);
    if (cpu_render(&s, &o, &cpu, &err) != 0)
        fail_msg("cpu render: %s", err.message);
    int on_cpu = check_stars(&s, cpu.color, "cpu");
    /* the GPU's own star pass, in the frame's pass (results/star_map.h) */
    struct render_result gp;
    render_star_pass(&s, RENDER_READ_IMAGE, &gp);
    int on_gpu_pass = check_stars(&s, gp.color, "gpu star pass");
    /* the same pass where the whole ray state is read: the sky stage's pass draws them instead of
     * the frame's own (stage_sky.c) */
    struct render_result gs;
    render_star_pass(&s, RENDER_READ_STATE, &gs);
    int on_sky_stage = check_stars(&s, gs.color, "gpu star pass, sky stage");
    /* on a GPU without derivatives (VC4), the sky stage's pass takes the footprints from the
     * neighbouring rays, as the CPU's pass does (stage_sky.glsl) */
    struct render_result gn;
    setenv("BT_FAULT", "no_derivatives", 1);
    render_star_pass(&s, RENDER_READ_IMAGE, &gn);
    unsetenv("BT_FAULT");
    int on_neighbours = check_stars(&s, gn.color, "gpu star pass, footprints from neighbours");
    /* and where only the 8-bit image is read, the frame's own pass draws them (FRAME_COLOUR, as the
     * kiosk): the same colours, within a level of 255 */
    struct render_result g8;
    s.render.star_pass = STAR_PASS_GPU;
    if (render_frame(&s, &(struct frame_request){.backend = "egl"}, &g8, NULL, &err) != 0)
        fail_msg("render: %s", err.message);
    int worst = 0;
    for (size_t i = 0; i < (size_t)s.render.width * s.render.height * 4; i++) {
        if (i % 4 == 3)
            continue;
        double c = gp.color[i] < 0.0 ? 0.0 : gp.color[i] > 1.0 ? 1.0 : gp.color[i];
        int d = abs((int)g8.rgba[i] - (int)lrint(c * 255.0));
        worst = d > worst ? d : worst;
    }
    print_message("the frame's own pass against the sky stage's: %d levels at most\n", worst);
    assert_true(worst <= 1);
    render_result_free(&g8);
    s.render.star_pass = STAR_PASS_CPU;
    print_message("beta %.2f: %d stars at their pixels with their flux on the GPU, %d on the CPU, %d by the GPU's "
                  "star pass (%d in the sky stage, %d from neighbours)\n", v3_len(velocity), on_gpu, on_cpu,
                  on_gpu_pass, on_sky_stage, on_neighbours);
    assert_true(on_gpu >= 5 && on_gpu == on_cpu && on_gpu_pass == on_cpu && on_sky_stage == on_cpu &&
                on_neighbours == on_cpu);
    render_result_free(&gn);
    render_result_free(&gs);
    render_result_free(&gp);
    render_result_free(&g);
    cpu_image_free(&cpu);
}

/* The star map's masks (results/star_map.h): at every level, each cell's bit 8 - k set exactly where
 * cell k of the 3x3 about it holds a star, that cell found as the GPU's pass finds it (its fold
 * across the square's border, written here as sky_colour.glsl writes it), so that the pass, which
 * reads only the cells a mask names, reads every cell with a star. */
static int map_cell_holds_star(const struct star_map *m, int level, int i, int j)
{
    const unsigned char *p = m->texels + 4 * ((size_t)(m->level_y[level] + j) * m->width + m->level_x[level] +
                                              2 * STAR_MAP_SLOTS * i + 1);
    return p[3] >= 127;
}

static void test_star_map_masks(void **state)
{
    (void)state;
    static struct star_catalogue c;
    assert_int_equal(star_catalogue_make(&c, 30000, 1, v3(0.45, 0.89, 0.1), v3(0.25, -0.1, -1.0)), 0);
    static struct star_map m;
    assert_int_equal(star_map_build(&m, &c, 256), 0);
    long cells = 0, holding = 0, bits = 0;
    for (int level = 0; level < m.levels; level++) {
        int n = m.cells >> level;
        for (int cj = 0; cj < n; cj++)
            for (int ci = 0; ci < n; ci++) {
                const unsigned char *p = m.texels + 4 * ((size_t)(m.mask_y + cj) * m.width + m.mask_x[level] + ci);
                int mask = p[0] | p[1] << 8;
                for (int k = 0; k < 9; k++) {
                    double x = ci - 1 + k % 3, y = cj - 1 + k / 3, nn = n;
                    double fx = x < 0.0 ? 0.0 : x > nn - 1.0 ? nn - 1.0 : x;
                    double fy = x < 0.0 || x > nn - 1.0 ? nn - 1.0 - y : y;
                    x = fx;
                    y = fy;
                    fx = y < 0.0 || y > nn - 1.0 ? nn - 1.0 - x : x;
                    fy = y < 0.0 ? 0.0 : y > nn - 1.0 ? nn - 1.0 : y;
                    int holds = map_cell_holds_star(&m, level, (int)fx, (int)fy);
                    assert_int_equal((mask >> (8 - k)) & 1, holds);
                    bits += holds;
                }
                assert_int_equal(mask >> 9, 0);
                holding += map_cell_holds_star(&m, level, ci, cj);
                cells++;
            }
    }
    print_message("%d levels, %ld cells, %ld hold a star, %ld mask bits set\n", m.levels, cells, holding, bits);
    assert_true(holding > 0 && holding < cells);   /* both kinds of cell were checked */
    star_map_free(&m);
    star_catalogue_free(&c);
}

static void test_flat_stars_at_rest(void **state)
{
    (void)state;
    stars_on_both_engines(v3(0.0, 0.0, 0.0));
}

/* At 0.6 c along the view: each star where aberration puts it, with its flux times D^2. */
static void test_flat_stars_aberrated(void **state)
{
    (void)state;
    stars_on_both_engines(v3(0.0, 0.0, -0.6));
}

/* The light within 4 pixels of where direction d falls, linear luminance. */
static double light_about(const struct scene *s, const float *color, vec3d d)
{
    double x, y, sum = 0.0;
    assert_true(project(s, d, &x, &y));
    int px = (int)lrint(x), py = (int)lrint(y), w = s->render.width;
    assert_true(px >= 4 && py >= 4 && px < w - 4 && py < s->render.height - 4);
    for (int v = py - 4; v <= py + 4; v++)
        for (int u = px - 4; u <= px + 4; u++) {
            const float *p = color + 4 * ((size_t)v * w + u);
            double lin[3] = {srgb_to_linear(p[0]), srgb_to_linear(p[1]), srgb_to_linear(p[2])};
            sum += luminance(lin);
        }
    return sum;
}

/* A mass M = 1 at distance D = 40000 in front of one star, the star half an Einstein angle
 * theta_E = sqrt(4 M / D) off the axis (u = 1/2): the two images lie where the point lens puts them,
 * theta = (beta +- sqrt(beta^2 + 4 theta_E^2)) / 2, with the star's flux times the magnifications
 * (u^2 + 2) / (2 u sqrt(u^2 + 4)) +- 1/2 = 1.59 and 0.59, within 2% (the weak field's own error at
 * impact parameters of 300 M is below 1%), on both engines. */
static void test_lensed_star(void **state)
{
    (void)state;
    static struct scene s;
    scene_defaults(&s);
    const double mass = 1.0, distance = 40000.0, theta_e = sqrt(4.0 * mass / distance), beta = 0.5 * theta_e;
    struct star_catalogue c;
    assert_int_equal(star_catalogue_make(&c, 1, 5, s.sky.galactic_pole, s.sky.galactic_center), 0);
    vec3d star = c.stars[0].direction, side = v3_perpendicular(star);
    double per_brightness = pow(10.0, -0.4 * (c.stars[0].magnitude - 6.0)), flux = 0.25;
    star_catalogue_free(&c);
    /* the lens's direction from the camera, beta from the star; side: from the lens toward the star */
    vec3d axis = v3_add(v3_scale(star, cos(beta)), v3_scale(side, -sin(beta)));
    vec3d toward = v3_normalize(v3_sub(star, v3_scale(axis, v3_dot(star, axis))));
    char sets[6][160];
    snprintf(sets[0], sizeof sets[0], "model.center=%.17g %.17g %.17g", distance * axis.x, distance * axis.y,
             distance * axis.z);
    snprintf(sets[1], sizeof sets[1], "camera.look_at=%.17g %.17g %.17g", distance * axis.x, distance * axis.y,
             distance * axis.z);
    snprintf(sets[2], sizeof sets[2], "camera.up=%.17g %.17g %.17g", toward.x, toward.y, toward.z);
    snprintf(sets[3], sizeof sets[3], "camera.fov=%.17g", 4.0 * theta_e * 180.0 / PI_D);
    snprintf(sets[4], sizeof sets[4], "sky.star_brightness=%.17g", flux / per_brightness);
    snprintf(sets[5], sizeof sets[5], "sky.star_seed=5");
    const char *const fixed[] = {"model.type=schwarzschild", "model.mass=1", "camera.position=0 0 0",
                                 "render.method=orbit_table", "render.bound_radius=1e7", "sky.color=0 0 0",
                                 "sky.stars=1", "sky.star_size=0.8", NULL};
    struct error err;
    for (int i = 0; fixed[i]; i++)
        if (scene_set(&s, fixed[i], &err) != 0)
            fail_msg("%s: %s", err.where, err.message);
    for (int i = 0; i < 6; i++)
        if (scene_set(&s, sets[i], &err) != 0)
            fail_msg("%s: %s", err.where, err.message);
    s.render.width = s.render.height = 200;
    hc_validate(&s);
    double root = sqrt(beta * beta + 4.0 * theta_e * theta_e), u = beta / theta_e;
    double theta_plus = 0.5 * (beta + root), theta_minus = 0.5 * (root - beta);
    double mu_plus = (u * u + 2.0) / (2.0 * u * sqrt(u * u + 4.0)) + 0.5, mu_minus = mu_plus - 1.0;
    vec3d image_plus = v3_add(v3_scale(axis, cos(theta_plus)), v3_scale(toward, sin(theta_plus)));
    vec3d image_minus = v3_add(v3_scale(axis, cos(theta_minus)), v3_scale(toward, -sin(theta_minus)));

    /* the GPU's own star pass among them: its magnification from the derivatives of the exit
     * directions */
    struct render_result g, gp, gn;
    struct cpu_image cpu;
    render_three(&s, &g, &cpu, &gp);
    /* and on a GPU without derivatives: the footprints from the neighbouring rays (stage_sky.glsl) */
    setenv("BT_FAULT", "no_derivatives", 1);
    render_star_pass(&s, RENDER_READ_IMAGE, &gn);
    unsetenv("BT_FAULT");
    const float *images[4] = {g.color, cpu.color, gp.color, gn.color};
    const char *names[4] = {"gpu", "cpu", "gpu star pass", "gpu star pass, footprints from neighbours"};
    for (int e = 0; e < 4; e++) {
        double plus = light_about(&s, images[e], image_plus) / flux, minus = light_about(&s, images[e], image_minus) / flux;
        print_message("%s: magnifications %.4f and %.4f (point lens: %.4f and %.4f)\n", names[e], plus, minus,
                      mu_plus, mu_minus);
        assert_true(fabs(plus / mu_plus - 1.0) < 0.02);
        assert_true(fabs(minus / mu_minus - 1.0) < 0.02);
    }
    render_result_free(&gn);
    render_result_free(&gp);
    render_result_free(&g);
    cpu_image_free(&cpu);
}

/* J2000 right ascension (hours) and declination (degrees) as a unit vector of the equatorial frame */
static vec3d equatorial(double ra_hours, double dec_deg)
{
    double a = ra_hours * 15.0 * PI_D / 180.0, d = dec_deg * PI_D / 180.0;
    return v3(cos(d) * cos(a), cos(d) * sin(a), sin(d));
}

/* The real sky ([sky] catalogue: the Yale Bright Star Catalogue with Marble's colours,
 * physics/bright_stars.h) toward Orion, on both engines: Betelgeuse and Rigel at the pixels their
 * directions predict, each the brightest pixel about it, with its flux within 1%, Betelgeuse red and
 * Rigel blue. The galactic frame (assets/scenes/orion.scene's) puts Orion's belt (Alnilam) straight
 * ahead and the celestial north up; the test predicts the stars' directions from their RA and Dec
 * by that rotation alone, not through the galactic frame the renderer takes. */
static void test_real_sky_orion(void **state)
{
    (void)state;
    static struct scene s;
    star_scene(&s, 320, 240, v3(0.0, 0.0, 0.0));
    const char *const sets[] = {"sky.stars=0", "sky.catalogue=" BRIGHT_STARS_XPLANET_PATH,
                                "sky.catalogue_colours=" BRIGHT_STARS_MARBLE_PATH, "sky.star_brightness=1e-4",
                                "camera.fov=44", "sky.galactic_pole=-0.842479 0.449866 0.296395",
                                "sky.galactic_center=0.035900 -0.502070 0.864082", NULL};
    struct error err;
    for (int i = 0; sets[i]; i++)
        if (scene_set(&s, sets[i], &err) != 0)
            fail_msg("%s: %s", err.where, err.message);
    hc_validate(&s);
    /* the frame: forward along Alnilam, up toward the celestial pole, right = forward x up */
    vec3d forward = equatorial(5.6036, -1.2019), north = v3(0.0, 0.0, 1.0);
    vec3d up = v3_normalize(v3_sub(north, v3_scale(forward, v3_dot(north, forward)))), right = v3_cross(forward, up);
    static const struct {
        const char *name;
        double ra, dec, magnitude, bv;
        int red;
    } known[] = {{"Betelgeuse", 5.9195, 7.4069, 0.50, 1.85, 1}, {"Rigel", 5.2423, -8.2017, 0.12, 0.00, 0}};
    struct render_result g, gp;
    struct cpu_image cpu;
    render_three(&s, &g, &cpu, &gp);
    const float *images[3] = {g.color, cpu.color, gp.color};
    const char *names[3] = {"gpu", "cpu", "gpu star pass"};
    for (size_t k = 0; k < sizeof known / sizeof known[0]; k++) {
        vec3d eq = equatorial(known[k].ra, known[k].dec);
        vec3d d = v3(v3_dot(eq, right), v3_dot(eq, up), -v3_dot(eq, forward));
        double x, y;
        assert_true(project(&s, d, &x, &y));
        int px = (int)lrint(x), py = (int)lrint(y), w = s.render.width;
        double chroma[3];
        star_chromaticity(star_temperature_of_bv(known[k].bv), chroma);
        double flux = s.sky.star_brightness * pow(10.0, -0.4 * (known[k].magnitude - 6.0)) * luminance(chroma);
        for (int e = 0; e < 3; e++) {
            double best = -1.0, sum = 0.0, rgb[3] = {0.0, 0.0, 0.0};
            int best_x = -1, best_y = -1;
            for (int v = py - 4; v <= py + 4; v++)
                for (int u = px - 4; u <= px + 4; u++) {
                    const float *p = images[e] + 4 * ((size_t)v * w + u);
                    double lin[3] = {srgb_to_linear(p[0]), srgb_to_linear(p[1]), srgb_to_linear(p[2])};
                    sum += luminance(lin);
                    for (int c = 0; c < 3; c++)
                        rgb[c] += lin[c];
                    if (luminance(lin) > best) {
                        best = luminance(lin);
                        best_x = u;
                        best_y = v;
                    }
                }
            print_message("%s %s: predicted (%.2f, %.2f), brightest (%d, %d), light %.4g of %.4g, rgb %.3g %.3g %.3g\n",
                          names[e], known[k].name, x, y, best_x, best_y, sum, flux, rgb[0], rgb[1], rgb[2]);
            assert_int_equal(best_x, px);
            assert_int_equal(best_y, py);
            assert_true(fabs(sum / flux - 1.0) < 0.01);
            assert_true(known[k].red ? rgb[0] > 2.0 * rgb[2] : rgb[2] > 1.2 * rgb[0]);
        }
    }
    render_result_free(&gp);
    render_result_free(&g);
    cpu_image_free(&cpu);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_catalogue_deterministic),
        cmocka_unit_test(test_catalogue_distributions),
        cmocka_unit_test(test_catalogue_near),
        cmocka_unit_test(test_chromaticity),
        cmocka_unit_test(test_star_map_masks),
        cmocka_unit_test(test_flat_stars_at_rest),
        cmocka_unit_test(test_flat_stars_aberrated),
        cmocka_unit_test(test_lensed_star),
        cmocka_unit_test(test_real_sky_orion),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
