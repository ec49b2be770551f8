/* A frame in bands of rows (render/frame_bands.h: how a long render shows its progress) is the
 * whole frame's bit for bit, on every pipeline; the outcomes read alone (what `bentray render`
 * reads without --dump) are those of the whole state. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include "hard_cases.h"
#include "render/frame_bands.h"

static struct renderer *make_renderer(const struct scene *s)
{
    struct error gl_err;
    struct renderer *r = renderer_create(hc_context(), s, &gl_err);
    if (!r)
        fail_msg("renderer: %s", gl_err.message);
    return r;
}

static void whole_frame(const struct scene *s, int what, struct render_result *out)
{
    struct error e;
    struct renderer *r = make_renderer(s);
    renderer_set_reads(r, what);
    if (renderer_run(r, s, 0, 0, s->render.width, s->render.height, NULL, NULL, &e) != 0 ||
        renderer_read(r, out, what, &e) != 0)
        fail_msg("render: %s", e.message);
    renderer_destroy(r);
}

static void banded_frame_reading(const struct scene *s, int rows, enum render_read reads, struct render_result *out)
{
    struct error e;
    struct renderer *r = make_renderer(s);
    if (frame_run_bands(r, s, rows, out, reads, &e) != 0)
        fail_msg("bands: %s", e.message);
    renderer_destroy(r);
}

static void banded_frame(const struct scene *s, int rows, struct render_result *out)
{
    banded_frame_reading(s, rows, RENDER_READ_STATE, out);
}

/* Pixels whose colour differs by more than 2 of 255 in some channel. */
static long pixels_off(const unsigned char *a, const unsigned char *b, size_t pixels)
{
    long off = 0;
    for (size_t i = 0; i < pixels; i++) {
        int worst = 0;
        for (int c = 0; c < 3; c++) {
            int d = abs((int)a[4 * i + c] - (int)b[4 * i + c]);
            worst = d > worst ? d : worst;
        }
        off += worst > 2;
    }
    return off;
}

/* Bands of about 7 rows on a 40 x 30 image: each scene through the pipeline it takes
 * (exact orbits and integrated rays in the single pass, the multipass and the fused segment
 * schemes, a moving observer), image and ray state equal to the byte. */
static void test_bands_are_the_frame(void **state)
{
    (void)state;
    static const struct {
        const char *scene;
        const char *set;
    } cases[] = {
        {"schwarzschild", NULL},
        {"lorenz", NULL},
        {"lorenz", "render.pipeline=multipass"},
        {"potential", "render.pipeline=fused"},
        {"starflight", NULL},
        {"demo", "render.pipeline=multipass"},
        /* the GPU's stars take their footprints from derivatives over 2x2 pixels: no band may
         * split such a group (bands of 7 rows are moved to even edges) */
        {"star_sky", "render.star_pass=gpu"},
        {"demo", "render.star_pass=gpu"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        static struct scene s;
        const char *const sets[] = {cases[k].set, NULL};
        hc_load(&s, cases[k].scene, 40, 30, sets);
        struct render_result whole, bands;
        whole_frame(&s, RENDER_READ_STATE, &whole);
        banded_frame(&s, 7, &bands);
        size_t n = (size_t)40 * 30 * 4;
        printf("  %s%s%s: bands of 7 rows against the whole frame\n", cases[k].scene, cases[k].set ? ", " : "",
               cases[k].set ? cases[k].set : "");
        assert_memory_equal(whole.rgba, bands.rgba, n);
        assert_memory_equal(whole.position, bands.position, n * sizeof(float));
        assert_memory_equal(whole.velocity, bands.velocity, n * sizeof(float));
        assert_memory_equal(whole.hit, bands.hit, n * sizeof(float));
        assert_memory_equal(whole.image, bands.image, n * sizeof(float));
        render_result_free(&whole);
        render_result_free(&bands);
    }
}

/* Moving bodies drawn as polygons are rasterised band by band: each band's viewport takes its part
 * of the projection. Rasterisation rules may put an edge pixel on either side of a band's border;
 * at most a pixel in a hundred differs, where a band drawn with the whole image's projection
 * squeezed into it would differ nearly everywhere the bodies are. */
static void test_polygon_bands(void **state)
{
    (void)state;
    static struct scene s;
    const char *const sets[] = {"render.moving_objects=polygons", "render.samples=1", NULL};
    hc_load(&s, "three_ships", 64, 48, sets);
    struct render_result whole, bands;
    whole_frame(&s, RENDER_READ_IMAGE, &whole);
    banded_frame(&s, 5, &bands);
    long off = pixels_off(whole.rgba, bands.rgba, 64 * 48);
    printf("  three_ships as polygons: %ld of %d pixels differ in bands of 5 rows\n", off, 64 * 48);
    assert_true(off <= 64 * 48 / 100);
    render_result_free(&whole);
    render_result_free(&bands);
}

/* The outcome codes read alone are the whole state's, and the image is the same; read from a frame
 * that drew its colour itself (the single pass), they come as bytes, without the float image, and
 * in bands of 7 rows (the last shorter) they are the whole frame's too. */
static void test_outcomes_alone(void **state)
{
    (void)state;
    const char *const scenes[] = {"schwarzschild", "lorenz", "refraction"};
    int bytes = 0;
    for (size_t k = 0; k < sizeof scenes / sizeof scenes[0]; k++) {
        static struct scene s;
        hc_load(&s, scenes[k], 40, 30, NULL);
        struct render_result all, outcomes;
        whole_frame(&s, RENDER_READ_STATE, &all);
        whole_frame(&s, RENDER_READ_OUTCOMES, &outcomes);
        size_t n = (size_t)40 * 30 * 4;
        assert_null(outcomes.position);
        assert_null(outcomes.hit);
        assert_true((outcomes.image != NULL) != (outcomes.outcome != NULL));
        bytes += outcomes.outcome != NULL;
        assert_memory_equal(all.rgba, outcomes.rgba, n);
        for (size_t i = 0; i < n / 4; i++)
            assert_int_equal(render_result_outcome(&outcomes, i), render_result_outcome(&all, i));
        if (outcomes.image)
            assert_memory_equal(all.image, outcomes.image, n * sizeof(float));
        struct render_result banded;
        banded_frame_reading(&s, 7, RENDER_READ_OUTCOMES, &banded);
        assert_true((banded.outcome != NULL) == (outcomes.outcome != NULL));
        assert_memory_equal(banded.rgba, outcomes.rgba, n);
        for (size_t i = 0; i < n / 4; i++)
            assert_int_equal(render_result_outcome(&banded, i), render_result_outcome(&all, i));
        assert_int_equal(banded.outcome_nonfinite, outcomes.outcome_nonfinite);
        render_result_free(&banded);
        render_result_free(&all);
        render_result_free(&outcomes);
    }
    print_message("outcomes read as bytes in %d of %zu scenes\n", bytes, sizeof scenes / sizeof scenes[0]);
    assert_true(bytes > 0);
}

/* Without --progress a render is drawn in bands (and can show progress) when it is large, or when
 * its rays may take very many steps in all: a small frame with a long budget shows it too. */
static void test_long_budgets_in_bands(void **state)
{
    (void)state;
    static struct scene s;
    struct error e;
    if (scene_load(&s, "assets/scenes/potential.scene", &e) != 0)
        fail_msg("%s", e.message);
    assert_false(frame_bands_wanted(&s, 320L * 240));             /* the scene as shipped: one run */
    assert_true(frame_bands_wanted(&s, FRAME_BAND_MIN_PIXELS));   /* a large frame */
    if (scene_set(&s, "render.segments=100000", &e) != 0 || scene_set(&s, "render.max_path=0", &e) != 0)
        fail_msg("%s", e.message);
    assert_true(frame_bands_wanted(&s, 64L * 48));                 /* small, but 3e9 steps at most */
    assert_false(frame_bands_wanted(&s, 16L * 12));                /* 1.9e8 */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bands_are_the_frame),
        cmocka_unit_test(test_polygon_bands),
        cmocka_unit_test(test_outcomes_alone),
        cmocka_unit_test(test_long_budgets_in_bands),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
