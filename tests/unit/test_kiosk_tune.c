/* The kiosk's previews tuned to its preview rate (src/kiosk/kiosk_tune.h): kept where they are fast
 * enough, shrunk (aspect kept, at least KIOSK_TUNE_MIN_SIDE) where a preview takes longer than the
 * rate allows, emulated by BT_FAULT=slow_previews; the bands follow the preview's size; and a
 * preview drawn at the tuned size is the renderer's image of the preview scene at that size. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "hard_cases.h"
#include "kiosk/kiosk_tune.h"
#include "kiosk_config/kiosk_config.h"

static struct kiosk_config config;
static struct scene scenes[2];

static void load(int rate)
{
    struct error e;
    if (kiosk_config_load(&config, "tests/kiosk/headless.conf", &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    snprintf(config.display.headless_out, sizeof config.display.headless_out, "/tmp");
    config.kiosk.preview_rate = rate;
    if (kiosk_config_check(&config, &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    assert_int_equal(config.kiosk.n_scenes, 2);
    for (int i = 0; i < 2; i++)
        if (scene_load(&scenes[i], config.kiosk.scenes[i], &e) != 0)
            fail_msg("%s: %s", e.where, e.message);
}

/* Tunes a fresh view; its log in log_text. */
static void tune(struct kiosk_view *v, char *log_text, size_t len)
{
    struct error e;
    if (kiosk_view_init(v, &config, hc_context(), &e) != 0)
        fail_msg("%s", e.message);
    FILE *log = tmpfile();
    if (kiosk_tune_previews(v, &config, scenes, NULL, NULL, log, &e) != 0)
        fail_msg("%s", e.message);
    rewind(log);
    size_t n = fread(log_text, 1, len - 1, log);
    log_text[n] = '\0';
    fclose(log);
    print_message("%s", log_text);
}

static void test_fast_previews_kept(void **state)
{
    (void)state;
    load(1);                         /* one a second: any preview of 80 x 45 is fast enough */
    static struct kiosk_view v;
    char text[2048];
    tune(&v, text, sizeof text);
    for (int i = 0; i < 2; i++) {
        assert_int_equal(v.preview_sizes[i][0], config.kiosk.preview_width);
        assert_int_equal(v.preview_sizes[i][1], config.kiosk.preview_height);
    }
    assert_non_null(strstr(text, "within the 1 a second asked for"));
    kiosk_view_release(&v);
}

static void test_slow_previews_shrink(void **state)
{
    (void)state;
    load(30);
    setenv("BT_FAULT", "slow_previews", 1);
    static struct kiosk_view v;
    char text[2048];
    tune(&v, text, sizeof text);
    unsetenv("BT_FAULT");
    int band_rows_full = 0;
    for (int i = 0; i < 2; i++) {
        int w = v.preview_sizes[i][0], h = v.preview_sizes[i][1];
        print_message("scene %d previews at %dx%d\n", i, w, h);
        assert_true(w < config.kiosk.preview_width && h < config.kiosk.preview_height);
        assert_true(w >= KIOSK_TUNE_MIN_SIDE && h >= KIOSK_TUNE_MIN_SIDE);
        /* the aspect kept to a pixel, where no side reached the smallest */
        if (h > KIOSK_TUNE_MIN_SIDE)
            assert_true(abs(w * config.kiosk.preview_height - h * config.kiosk.preview_width) <=
                        config.kiosk.preview_width);
    }
    assert_non_null(strstr(text, "more than the 30 a second asked for allow: previews at"));
    /* a scene loaded again previews at its tuned size, its bands as many rays as one preview */
    struct error e;
    if (kiosk_view_load(&v, 0, &scenes[0], &e) != 0)
        fail_msg("%s", e.message);
    assert_int_equal(v.preview_width, v.preview_sizes[0][0]);
    struct kiosk_view wide;
    if (kiosk_view_init(&wide, &config, hc_context(), &e) != 0)
        fail_msg("%s", e.message);
    band_rows_full = wide.band_rows;
    kiosk_view_release(&wide);
    assert_true(v.band_rows <= band_rows_full);
    /* as many rays as one preview (PREVIEW_STEP_FACTOR of them), or the fewest rows that keep the
     * bands at KIOSK_MAX_BANDS */
    int fewest = config.kiosk.height / KIOSK_MAX_BANDS > 1 ? config.kiosk.height / KIOSK_MAX_BANDS : 1;
    assert_true((long)v.band_rows * config.kiosk.width <= 2L * v.preview_width * v.preview_height ||
                v.band_rows == fewest);
    kiosk_view_release(&v);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fast_previews_kept),
        cmocka_unit_test(test_slow_previews_shrink),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
