/* Bounded work per turn of the kiosk's loop (kiosk/kiosk_view.h): a frame whose rays may take more
 * than KIOSK_TURN_RAY_STEPS steps in all is drawn in tiles, one a turn, and a tiled preview, once
 * whole, holds the renderer's own image of the preview. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include "hard_cases.h"
#include "kiosk_config/kiosk_config.h"
#include "kiosk/kiosk_view.h"
#include "render/frame.h"

/* One tile of the whole width where the frame is cheap; rows, then columns, then one pixel as the
 * rays grow dearer; never more ray-steps than the bound (but for a single pixel). */
static void test_plan(void **state)
{
    (void)state;
    struct kiosk_tiles t;
    kiosk_tiles_plan(&t, 320, 180, 180, 0);
    assert_int_equal(t.count, 1);
    kiosk_tiles_plan(&t, 320, 180, 180, 270);           /* a lorenz preview: 15.6 M ray-steps */
    assert_int_equal(t.count, 1);
    kiosk_tiles_plan(&t, 1280, 720, 22, 540);           /* its refinement: bands of 22 rows */
    assert_int_equal(t.tile_width, 1280);
    assert_int_equal(t.tile_height, 22);
    assert_int_equal(t.count, 33);
    const long costs[] = {1000, 100000, 10000000, 1000000000L};
    for (int i = 0; i < 4; i++) {
        kiosk_tiles_plan(&t, 320, 180, 180, costs[i]);
        long rays = (long)t.tile_width * t.tile_height;
        assert_true(rays * costs[i] <= KIOSK_TURN_RAY_STEPS || rays == 1);
        assert_true(t.columns * t.tile_width >= 320);
        assert_int_equal(t.count, t.columns * ((180 + t.tile_height - 1) / t.tile_height));
        printf("  %ld steps a ray: tiles of %d x %d, %d of them\n", costs[i], t.tile_width, t.tile_height, t.count);
    }
}

/* lorenz with a budget of 9e4 steps a ray (a thousand times its own): its preview (32 x 18) is
 * drawn in tiles, one a call, not shown until whole; then it holds what the renderer draws of the
 * preview scene in one run. */
static void test_tiled_preview(void **state)
{
    (void)state;
    static struct kiosk_config c;
    struct error e;
    if (kiosk_config_load(&c, "kiosk/kiosk.conf", &e) != 0 || kiosk_config_check(&c, &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    c.kiosk.preview_width = 32;
    c.kiosk.preview_height = 18;
    c.kiosk.width = 64;
    c.kiosk.height = 36;
    int scene = -1;
    for (int i = 0; i < c.kiosk.n_scenes; i++)
        if (strstr(c.kiosk.scenes[i], "lorenz"))
            scene = i;
    assert_true(scene >= 0);
    static struct scene base;
    struct error se;
    assert_int_equal(scene_load(&base, c.kiosk.scenes[scene], &se), 0);
    base.render.max_path = 9e4 * base.render.step_size;
    assert_int_equal(scene_validate(&base, &se), 0);
    static struct kiosk_view v;
    if (kiosk_view_init(&v, &c, hc_context(), &e) != 0 || kiosk_view_load(&v, scene, &base, &e) != 0)
        fail_msg("%s", e.message);
    struct kiosk_state st;
    kiosk_state_reset(&st, &c);
    st.scene = scene;
    assert_int_equal(kiosk_view_preview(&v, &st, &e), 0);
    int tiles = v.preview.count, calls = 1;
    printf("  preview in %d tiles of %d x %d\n", tiles, v.preview.tile_width, v.preview.tile_height);
    assert_true(tiles > 1);
    assert_true(kiosk_view_preview_pending(&v));
    assert_false(kiosk_view_refined(&v));
    while (kiosk_view_preview_pending(&v)) {
        assert_int_equal(kiosk_view_refine(&v, &e), 0);
        calls++;
    }
    assert_int_equal(calls, tiles);
    /* the whole preview, read from its offscreen texture, against one run of the preview scene */
    unsigned char *tiled = malloc(32 * 18 * 4);
    glBindFramebuffer(GL_FRAMEBUFFER, v.comp.preview_fbo);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, 32, 18, GL_RGBA, GL_UNSIGNED_BYTE, tiled);
    static struct scene preview;
    preview = v.live;
    struct render_result res;
    struct error gl_err;
    if (render_frame(&preview, &(struct frame_request){.backend = "egl"}, &res, NULL, &gl_err) != 0)
        fail_msg("%s", gl_err.message);
    /* render_result rows run top-down, GL's bottom-up */
    for (int y = 0; y < 18; y++)
        assert_memory_equal(tiled + (size_t)y * 32 * 4, res.rgba + (size_t)(17 - y) * 32 * 4, 32 * 4);
    render_result_free(&res);
    free(tiled);
    kiosk_view_release(&v);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_plan),
        cmocka_unit_test(test_tiled_preview),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
