/* The kiosk's anti-aliasing ([kiosk] refine_samples, kiosk/kiosk_view.h): once the one-ray frame is
 * refined, the frame is traced again for each point of pixel_samples(N), band by band (or tile by
 * tile), and blended into the canvas so that it holds the mean of the samples drawn so far. The
 * canvas at the end is that mean of the renderer's own images; a change of state stops it at once;
 * refine_samples = 1 draws the one-ray frame alone; an odd count takes the one-ray frame as its
 * centre sample. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "hard_cases.h"
#include "kiosk_config/kiosk_config.h"
#include "kiosk/kiosk_view.h"

#define W 64
#define H 36

static struct kiosk_config config;

static int scene_named(const char *name)
{
    for (int i = 0; i < config.kiosk.n_scenes; i++)
        if (strstr(config.kiosk.scenes[i], name))
            return i;
    fail_msg("no scene %s in kiosk/kiosk.conf", name);
    return -1;
}

static void load_config(int samples)
{
    struct error e;
    if (kiosk_config_load(&config, "kiosk/kiosk.conf", &e) != 0 || kiosk_config_check(&config, &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    config.kiosk.preview_width = W / 2;
    config.kiosk.preview_height = H / 2;
    config.kiosk.width = W;
    config.kiosk.height = H;
    config.kiosk.refine_samples = samples;
}

/* The canvas, GL's rows (bottom-up). */
static void read_canvas(const struct kiosk_view *v, unsigned char *rgba)
{
    glBindFramebuffer(GL_FRAMEBUFFER, v->comp.canvas_fbo);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
}

/* The renderer's image of s with its rays started (dx, dy) off the pixels' centres, GL's rows. */
static void image_at(const struct scene *s, double dx, double dy, unsigned char *rgba)
{
    struct error e;
    struct renderer *r = renderer_create(hc_context(), s, &e);
    if (!r)
        fail_msg("%s", e.message);
    renderer_set_reads(r, RENDER_READ_IMAGE);
    renderer_set_subpixel(r, dx, dy);
    struct render_result res;
    if (renderer_run(r, s, 0, 0, W, H, NULL, NULL, &e) != 0 || renderer_read(r, &res, RENDER_READ_IMAGE, &e) != 0)
        fail_msg("%s", e.message);
    for (int y = 0; y < H; y++)
        memcpy(rgba + (size_t)y * W * 4, res.rgba + (size_t)(H - 1 - y) * W * 4, W * 4);
    render_result_free(&res);
    renderer_destroy(r);
}

/* A view of scene `name` at its start state, previewed. */
static void start(struct kiosk_view *v, const char *name, const struct scene *base, struct kiosk_state *st)
{
    struct error e;
    int scene = scene_named(name);
    if (kiosk_view_init(v, &config, hc_context(), &e) != 0 || kiosk_view_load(v, scene, base, &e) != 0)
        fail_msg("%s", e.message);
    kiosk_state_reset(st, &config);
    st->scene = scene;
    assert_int_equal(kiosk_view_preview(v, st, &e), 0);
}

/* Calls of kiosk_view_refine until refined, then until done. */
static void refine_all(struct kiosk_view *v, int *to_refined, int *to_done)
{
    struct error e;
    *to_refined = *to_done = 0;
    while (!kiosk_view_refined(v)) {
        assert_false(kiosk_view_done(v));
        assert_int_equal(kiosk_view_refine(v, &e), 0);
        (*to_refined)++;
    }
    while (!kiosk_view_done(v)) {
        assert_int_equal(kiosk_view_refine(v, &e), 0);
        (*to_done)++;
    }
}

/* The canvas against the mean of the renderer's images at the pattern's points: each of the N - 1
 * blends after the first rounds the canvas to 8 bits, half a level each at most, and GL may round
 * its 8-bit blend a level differently (llvmpipe blends in 8-bit fixed point): 2 levels. Returns
 * the largest difference between the canvas and the one-ray frame. */
static int check_mean(const struct kiosk_view *v, const unsigned char *canvas, const unsigned char *one_ray)
{
    int n = v->samples.n;
    unsigned char *img = malloc(W * H * 4);
    double *sum = calloc(W * H * 4, sizeof *sum);
    for (int k = 0; k < n; k++) {
        image_at(&v->full, v->samples.dx[k], v->samples.dy[k], img);
        for (int i = 0; i < W * H * 4; i++)
            sum[i] += img[i];
    }
    int worst = 0, moved = 0;
    for (int i = 0; i < W * H * 4; i++) {
        int d = (int)fabs(canvas[i] - sum[i] / n);
        worst = d > worst ? d : worst;
        d = abs(canvas[i] - one_ray[i]);
        moved = d > moved ? d : moved;
    }
    print_message("%d samples: the canvas %d levels at most from their mean, %d from the one-ray frame\n", n,
                  worst, moved);
    assert_true(worst <= 2);
    free(img);
    free(sum);
    return moved;
}

/* schwarzschild, 4 rays a pixel (the points do not hold the centre): the refinement, then four
 * frames more, each in as many bands as the refinement; the canvas ends as their mean, which
 * smooths the objects' edges (the one-ray frame differs from it). */
static void test_four_samples_are_their_mean(void **state)
{
    (void)state;
    load_config(4);
    static struct kiosk_view v;
    struct kiosk_state st;
    start(&v, "schwarzschild", NULL, &st);
    assert_int_equal(v.samples.n, 4);
    assert_false(v.samples.centre_included);
    int bands, more;
    struct error e;
    while (!kiosk_view_refined(&v))
        assert_int_equal(kiosk_view_refine(&v, &e), 0);
    assert_int_equal(kiosk_view_samples_drawn(&v), 0);
    static unsigned char one_ray[W * H * 4], canvas[W * H * 4];
    read_canvas(&v, one_ray);
    unsigned char want[W * H * 4];
    image_at(&v.full, 0.0, 0.0, want);
    assert_memory_equal(one_ray, want, sizeof want);
    assert_int_equal(kiosk_view_preview(&v, &st, &e), 0);
    refine_all(&v, &bands, &more);
    print_message("refined in %d bands, anti-aliased in %d more\n", bands, more);
    assert_int_equal(more, 4 * bands);
    assert_int_equal(kiosk_view_samples_drawn(&v), 4);
    read_canvas(&v, canvas);
    assert_true(check_mean(&v, canvas, one_ray) > 16);
    /* done: nothing more to draw */
    assert_int_equal(kiosk_view_refine(&v, &e), 0);
    unsigned char again[W * H * 4];
    read_canvas(&v, again);
    assert_memory_equal(again, canvas, sizeof again);
    kiosk_view_release(&v);
}

/* A change of state during the anti-aliasing stops it: the preview is on screen, the refinement and
 * the samples start over. */
static void test_a_knob_stops_it(void **state)
{
    (void)state;
    load_config(4);
    static struct kiosk_view v;
    struct kiosk_state st;
    start(&v, "schwarzschild", NULL, &st);
    struct error e;
    while (!kiosk_view_refined(&v))
        assert_int_equal(kiosk_view_refine(&v, &e), 0);
    assert_int_equal(kiosk_view_refine(&v, &e), 0);
    assert_true(v.sample_rows > 0);
    st.speed = knob_turn(&config.speed, st.speed, 5);
    assert_int_equal(kiosk_view_preview(&v, &st, &e), 0);
    assert_false(kiosk_view_refined(&v));
    assert_false(kiosk_view_done(&v));
    assert_int_equal(v.sample, 0);
    assert_int_equal(v.sample_rows, 0);
    assert_int_equal(kiosk_view_samples_drawn(&v), 0);
    kiosk_view_release(&v);
}

/* One ray a pixel: done once refined, the renderer's image alone. Three: the one-ray frame is the
 * centre sample, and two more follow. */
static void test_one_and_three(void **state)
{
    (void)state;
    int bands, more;
    load_config(1);
    static struct kiosk_view v;
    struct kiosk_state st;
    start(&v, "schwarzschild", NULL, &st);
    refine_all(&v, &bands, &more);
    assert_int_equal(more, 0);
    assert_true(kiosk_view_done(&v));
    kiosk_view_release(&v);
    load_config(3);
    start(&v, "schwarzschild", NULL, &st);
    assert_true(v.samples.centre_included);
    refine_all(&v, &bands, &more);
    assert_int_equal(more, 2 * bands);
    assert_int_equal(kiosk_view_samples_drawn(&v), 3);
    static unsigned char canvas[W * H * 4], one_ray[W * H * 4];
    read_canvas(&v, canvas);
    image_at(&v.full, 0.0, 0.0, one_ray);
    check_mean(&v, canvas, one_ray);
    kiosk_view_release(&v);
}

/* lorenz with a budget that tiles its refinement (more than KIOSK_TURN_RAY_STEPS steps a band):
 * each sample is drawn tile by tile as the refinement is, and the canvas ends as the mean. */
static void test_tiled_frames(void **state)
{
    (void)state;
    load_config(4);
    int scene = scene_named("lorenz");
    static struct scene base;
    struct error e;
    assert_int_equal(scene_load(&base, config.kiosk.scenes[scene], &e), 0);
    base.render.steps_per_segment = 64;
    base.render.max_path = 3e5 * base.render.step_size;
    assert_int_equal(scene_validate(&base, &e), 0);
    static struct kiosk_view v;
    struct kiosk_state st;
    start(&v, "lorenz", &base, &st);
    int bands, more;
    refine_all(&v, &bands, &more);
    print_message("lorenz: %d tiles of %d x %d a frame\n", v.refine.count, v.refine.tile_width, v.refine.tile_height);
    assert_true(v.refine.tile_width < W);
    /* the preview's tiles first, its first drawn by kiosk_view_preview itself */
    assert_int_equal(bands, v.preview.count - 1 + v.refine.count);
    assert_int_equal(more, 4 * v.refine.count);
    static unsigned char canvas[W * H * 4], one_ray[W * H * 4];
    read_canvas(&v, canvas);
    image_at(&v.full, 0.0, 0.0, one_ray);
    check_mean(&v, canvas, one_ray);
    kiosk_view_release(&v);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_four_samples_are_their_mean),
        cmocka_unit_test(test_a_knob_stops_it),
        cmocka_unit_test(test_one_and_three),
        cmocka_unit_test(test_tiled_frames),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
