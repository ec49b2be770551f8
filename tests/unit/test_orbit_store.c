/* Orbit tables built ahead (render/orbit_store.h) and the kiosk's mass knob that uses them: a table
 * from the store is the table built directly, bit for bit; the store keeps to its budget, reports a
 * failed build at the caller, and lets go while its worker builds; a renderer given a table begun
 * before it was made draws what one building its own draws; a mass detent of the kiosk takes
 * its table from the store and draws what a fresh render of the same state draws, over the knob's
 * whole range. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include <time.h>
#include "hard_cases.h"
#include "kiosk/kiosk_events.h"
#include "kiosk/kiosk_view.h"
#include "kiosk_config/kiosk_config.h"
#include "kiosk_config/kiosk_config_keys.h"
#include "render/orbit_store.h"

/* The worker has nothing left to build; a minute without that is a hang, not a slow machine. */
static void wait_idle(int (*pending)(void *), void *arg)
{
    for (int i = 0; i < 60000 && pending(arg) > 0; i++)
        nanosleep(&(struct timespec){0, 1000000}, NULL);
    assert_int_equal(pending(arg), 0);
}

static int store_pending(void *s) { return orbit_store_pending(s); }

static void params_at(struct scene *s, double mass, struct orbit_table_params *p)
{
    s->model.mass = mass;
    orbit_table_params_for(s, p);
}

static void test_prefetched_tables_are_built_tables(void **state)
{
    (void)state;
    static struct scene s;
    hc_load(&s, "schwarzschild", 32, 24, NULL);
    s.render.orbit_rows = 64;
    s.render.orbit_columns = 24;
    struct orbit_table_params p[6];
    const double masses[] = {0.12, 0.13, 0.5, 1.0, 2.0, 2.5};
    for (int k = 0; k < 6; k++)
        params_at(&s, masses[k], &p[k]);
    struct error e;
    struct orbit_store *store = orbit_store_create(ORBIT_STORE_BUDGET, &e);
    assert_non_null(store);
    orbit_store_prefetch(store, p, 6);
    wait_idle(store_pending, store);
    for (int k = 0; k < 6; k++) {
        const struct orbit_table *got = orbit_store_get(store, &p[k], &e);
        assert_non_null(got);
        struct orbit_table direct;
        assert_int_equal(orbit_table_build(&direct, &p[k], &e), 0);
        assert_int_equal(got->width, direct.width);
        assert_int_equal(got->height, direct.height);
        assert_int_equal(got->max_segments, direct.max_segments);
        assert_memory_equal(got->texels, direct.texels, (size_t)direct.width * direct.height * 4 * sizeof(float));
        assert_true(got->psi_c == direct.psi_c && got->critical_from_axis == direct.critical_from_axis);
        orbit_table_free(&direct);
    }
    assert_int_equal(orbit_store_caller_builds(store), 0);   /* every one came from the worker */
    /* one not asked for ahead is built by the caller */
    struct orbit_table_params other;
    params_at(&s, 0.7, &other);
    assert_non_null(orbit_store_get(store, &other, &e));
    assert_int_equal(orbit_store_caller_builds(store), 1);
    orbit_store_destroy(store);
}

/* A renderer given a store that began its scene's table before the renderer was made (as `bentray
 * render` does, while it makes its GL context) builds no table itself and draws, bit for bit, what a
 * renderer that built its own draws: ray state, outcomes and image. A scene that is not on exact
 * orbits gets no store. */
static void test_table_begun_before_the_renderer(void **state)
{
    (void)state;
    static struct scene s;
    hc_load(&s, "schwarzschild", 40, 30, NULL);
    struct orbit_store *ahead = renderer_orbit_ahead(&s);
    assert_non_null(ahead);
    wait_idle(store_pending, ahead);
    struct error e;
    struct renderer *r = renderer_create(hc_context(), &s, &e);
    if (!r)
        fail_msg("renderer: %s", e.message);
    renderer_orbit_store_give(r, ahead);
    renderer_set_reads(r, RENDER_READ_STATE);
    struct render_result got;
    if (renderer_run(r, &s, 0, 0, 40, 30, NULL, NULL, &e) != 0 || renderer_read(r, &got, RENDER_READ_STATE, &e) != 0)
        fail_msg("render: %s", e.message);
    assert_int_equal(renderer_orbit_tables_built(r), 0);
    renderer_destroy(r);
    struct hc_gpu own;
    hc_gpu_render(&s, &own);
    size_t n = 40 * 30 * 4;
    assert_memory_equal(got.rgba, own.res.rgba, n);
    assert_memory_equal(got.position, own.res.position, n * sizeof(float));
    assert_memory_equal(got.velocity, own.res.velocity, n * sizeof(float));
    assert_memory_equal(got.hit, own.res.hit, n * sizeof(float));
    assert_memory_equal(got.image, own.res.image, n * sizeof(float));
    render_result_free(&got);
    hc_gpu_free(&own);
    static struct scene flat;
    hc_load(&flat, "starflight", 8, 6, NULL);
    assert_null(renderer_orbit_ahead(&flat));
}

/* A budget of three tables keeps three: the prefetch stops at it, and a table asked for beyond it
 * pushes out the one least recently used. */
static void test_budget(void **state)
{
    (void)state;
    static struct scene s;
    hc_load(&s, "schwarzschild", 32, 24, NULL);
    s.render.orbit_rows = 16;
    s.render.orbit_columns = 8;
    struct orbit_table_params p[6];
    for (int k = 0; k < 6; k++)
        params_at(&s, 0.1 + 0.1 * k, &p[k]);
    size_t one = orbit_store_table_bytes(&p[0]);
    struct error e;
    struct orbit_store *store = orbit_store_create(3 * one, &e);
    orbit_store_prefetch(store, p, 6);
    wait_idle(store_pending, store);
    assert_int_equal(orbit_store_bytes(store), 3 * one);
    for (int k = 0; k < 3; k++)
        assert_non_null(orbit_store_get(store, &p[k], &e));
    assert_int_equal(orbit_store_caller_builds(store), 0);
    assert_non_null(orbit_store_get(store, &p[5], &e));      /* built here; p[0] goes */
    assert_int_equal(orbit_store_caller_builds(store), 1);
    assert_int_equal(orbit_store_bytes(store), 3 * one);
    assert_non_null(orbit_store_get(store, &p[1], &e));
    assert_int_equal(orbit_store_caller_builds(store), 1);
    assert_non_null(orbit_store_get(store, &p[0], &e));
    assert_int_equal(orbit_store_caller_builds(store), 2);
    orbit_store_destroy(store);
}

/* Parameters no table can have (the camera inside the horizon): the worker's failure is the
 * caller's error, with orbit_table_build's words. */
static void test_failed_build_reported(void **state)
{
    (void)state;
    static struct scene s;
    hc_load(&s, "schwarzschild", 32, 24, NULL);
    struct orbit_table_params bad;
    params_at(&s, 0.12, &bad);
    bad.mass = bad.r_observer;                                 /* r_o < 2M */
    struct error e, direct_e;
    struct orbit_store *store = orbit_store_create(ORBIT_STORE_BUDGET, &e);
    orbit_store_prefetch(store, &bad, 1);
    wait_idle(store_pending, store);
    error_clear(&e);
    assert_null(orbit_store_get(store, &bad, &e));
    struct orbit_table t;
    assert_int_equal(orbit_table_build(&t, &bad, &direct_e), -1);
    assert_string_equal(e.message, direct_e.message);
    print_message("%s\n", e.message);
    orbit_store_destroy(store);
}

/* The store goes while its worker builds a large table: the worker finishes and frees it (a leak or
 * a use after free shows under the sanitizers and Valgrind). */
static void test_destroy_while_building(void **state)
{
    (void)state;
    static struct scene s;
    hc_load(&s, "schwarzschild", 32, 24, NULL);
    struct orbit_table_params p[2];
    params_at(&s, 0.3, &p[0]);
    params_at(&s, 0.4, &p[1]);
    struct error e;
    struct orbit_store *store = orbit_store_create(ORBIT_STORE_BUDGET, &e);
    orbit_store_prefetch(store, p, 2);
    orbit_store_destroy(store);
    /* time for the worker to end before the process does */
    nanosleep(&(struct timespec){0, 300000000}, NULL);
}

static int view_pending(void *v) { return renderer_orbit_pending(((struct kiosk_view *)v)->renderer); }

/* The shipped kiosk's schwarzschild scene, its mass knob turned over its whole range one detent at a
 * time, a visitor's pause after each: every detent finds its table built ahead, no ray is left
 * unfinished or failed, and every fourth detent's preview is what a fresh render of that preview
 * scene draws. */
static void test_mass_knob_takes_tables_built_ahead(void **state)
{
    (void)state;
    static struct kiosk_config c;
    struct error e;
    if (kiosk_config_load(&c, "kiosk/kiosk.conf", &e) != 0 || kiosk_config_check(&c, &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    c.kiosk.preview_width = 24;
    c.kiosk.preview_height = 16;
    c.kiosk.width = 48;
    c.kiosk.height = 32;
    int scene = kiosk_scene_find(&c, "schwarzschild");
    assert_true(scene >= 0);
    static struct kiosk_view v;
    if (kiosk_view_init(&v, &c, hc_context(), &e) != 0 || kiosk_view_load(&v, scene, NULL, &e) != 0)
        fail_msg("%s", e.message);
    struct kiosk_state st;
    kiosk_state_reset(&st, &c);
    st.scene = scene;
    assert_int_equal(kiosk_view_preview(&v, &st, &e), 0);
    int detents = 0, compared = 0;
    for (long direction = -1; direction <= 1; direction += 2) {
        for (;;) {
            wait_idle(view_pending, &v);
            int built = renderer_orbit_tables_built(v.renderer);
            struct input_event ev = {.kind = INPUT_KNOB, .knob = INPUT_KNOB_MASS, .counts = direction, .bit = -1};
            struct event_outcome o = {0};
            kiosk_event_apply(&c, &st, &v.base, &ev, &o);
            if (!o.changed)
                break;
            detents++;
            if (kiosk_view_preview(&v, &st, &e) != 0)
                fail_msg("detent %d: %s", detents, e.message);
            assert_true(isfinite(v.live.model.mass));
            if (v.live.model.mass > 0.0)
                assert_int_equal(renderer_orbit_tables_built(v.renderer), built);
            if (detents % 4 != 0)
                continue;
            struct render_result shown;
            if (renderer_read(v.renderer, &shown, RENDER_READ_IMAGE, &e) != 0)
                fail_msg("%s", e.message);
            static struct scene fresh;
            fresh = v.live;
            struct hc_gpu g;
            hc_gpu_render(&fresh, &g);
            assert_int_equal(shown.width, 24);
            assert_memory_equal(shown.rgba, g.res.rgba, 24 * 16 * 4);
            assert_int_equal(hc_count_outcome(&g.dump, DUMP_UNFINISHED), 0);
            assert_int_equal(hc_count_outcome(&g.dump, DUMP_FAILED), 0);
            assert_int_equal(hc_gpu_nonfinite(&g), 0);
            render_result_free(&shown);
            hc_gpu_free(&g);
            compared++;
        }
    }
    print_message("%d mass detents over the knob's range, %d compared with fresh renders\n", detents, compared);
    assert_true(detents >= 20);
    kiosk_view_release(&v);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_prefetched_tables_are_built_tables),
        cmocka_unit_test(test_budget),
        cmocka_unit_test(test_failed_build_reported),
        cmocka_unit_test(test_destroy_while_building),
        cmocka_unit_test(test_mass_knob_takes_tables_built_ahead),
        cmocka_unit_test(test_table_begun_before_the_renderer),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
