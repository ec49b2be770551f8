/* The kiosk's state: knob curves (speed in rapidity, so gamma 7 is a few turns away), button
 * actions, how the state makes the drawn scene, the scripted-input file, and one renderer that
 * follows the scene as the knobs change it (the same image as a fresh renderer, bit for bit). */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include "kiosk_config/kiosk_config.h"
#include "hard_cases.h"
#include "kiosk/kiosk_events.h"
#include "kiosk/kiosk_state.h"
#include "input/script.h"

static struct kiosk_config config;

static void load_example(void)
{
    struct error e;
    if (kiosk_config_load(&config, "kiosk/kiosk.conf", &e) != 0 || kiosk_config_check(&config, &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
}

/* Rapidities add: equal turns give equal boosts, gamma 7 (0.99 c) is reached within a few turns of
 * a 24-detent knob, and turning back returns to rest. */
static void test_speed_knob_in_rapidity(void **state)
{
    (void)state;
    struct kiosk_knob k = {.min = 0.0, .max = 0.99, .step = 0.05, .curve = KIOSK_CURVE_RAPIDITY};
    double v = 0.0;
    int detents = 0;
    while (v < 0.99 && detents < 1000) {
        double next = knob_turn(&k, v, 1);
        assert_true(next > v);
        assert_true(fabs(atanh(fmin(next, 0.98999999)) - atanh(v) - 0.05) <= 1e-9 || next == 0.99);
        v = next;
        detents++;
    }
    print_message("0.99 c (gamma %.1f) after %d detents of 0.05 in rapidity\n", 1.0 / sqrt(1.0 - v * v), detents);
    assert_true(detents <= 3 * 24);
    assert_true(v == 0.99);                                   /* clamped at max */
    assert_true(knob_turn(&k, v, 5) == 0.99);
    assert_true(fabs(knob_turn(&k, knob_turn(&k, 0.0, 17), -17)) <= 1e-12);
    assert_true(knob_turn(&k, 0.3, -1000) == 0.0);            /* clamped at min */
}

static void test_mass_knob(void **state)
{
    (void)state;
    struct kiosk_knob lin = {.min = 0.0, .max = 2.0, .step = 0.1, .curve = KIOSK_CURVE_LINEAR};
    assert_true(fabs(knob_turn(&lin, 0.5, 3) - 0.8) <= 1e-12);
    assert_true(knob_turn(&lin, 0.5, 100) == 2.0);
    assert_true(knob_turn(&lin, 0.5, -100) == 0.0);
    struct kiosk_knob lg = {.min = 0.01, .max = 5.0, .step = log(2.0), .curve = KIOSK_CURVE_LOG};
    assert_true(fabs(knob_turn(&lg, 0.25, 2) - 1.0) <= 1e-12);   /* each count doubles */
    assert_true(fabs(knob_turn(&lg, 0.0, 1) - 0.02) <= 1e-12);   /* from 0: starts at min */
    assert_true(knob_turn(&lg, 1.0, 0) == 1.0);
    /* detents back to where the range starts give its end exactly, not what the sums' roundings
     * leave (0.12 - 12 x 0.01 is 1.04e-17 in double): a mass of 0 is flat space, shown as M = 0 */
    struct kiosk_knob fine = {.min = 0.0, .max = 0.25, .step = 0.01, .curve = KIOSK_CURVE_LINEAR};
    struct knob_mapping map = {.key = "model.mass", .min = 0.0, .max = 0.25, .steps = 25};
    double a = 0.12, b = 0.12;
    for (int i = 0; i < 12; i++) {
        a = knob_turn(&fine, a, -1);
        b = knob_turn_mapped(&map, NULL, b, -1);
    }
    assert_true(a == 0.0);
    assert_true(b == 0.0);
    for (int i = 0; i < 25; i++)
        b = knob_turn_mapped(&map, NULL, b, 1);
    assert_true(b == 0.25);
    /* and across 0 of a range on both sides */
    struct kiosk_knob both = {.min = -1.0, .max = 1.0, .step = 0.1, .curve = KIOSK_CURVE_LINEAR};
    double c = 0.3;
    for (int i = 0; i < 3; i++)
        c = knob_turn(&both, c, -1);
    assert_true(c == 0.0);
    assert_true(fabs(knob_turn(&both, c, -1) + 0.1) <= 1e-12);
}

static void test_actions(void **state)
{
    (void)state;
    load_example();
    static struct scene with_black_body, without;
    hc_load(&with_black_body, "starflight", 16, 12, NULL);
    hc_load(&without, "schwarzschild", 16, 12, NULL);
    struct kiosk_state st;
    kiosk_state_reset(&st, &config);
    int n = config.kiosk.n_scenes;
    assert_int_equal(st.scene, config.kiosk.start_scene);
    kiosk_state_action(&st, &config, &without, KIOSK_ACTION_PREVIOUS_SCENE);
    assert_int_equal(st.scene, (config.kiosk.start_scene + n - 1) % n);
    kiosk_state_action(&st, &config, &without, KIOSK_ACTION_NEXT_SCENE);
    assert_int_equal(st.scene, config.kiosk.start_scene);
    kiosk_state_action(&st, &config, &without, KIOSK_ACTION_CYCLE_EFFECTS);
    assert_int_equal(st.effects, EFFECTS_GEOMETRY);                /* nothing to colour */
    /* flat space: geometry, Doppler colour, searchlight and round again (no gravity to add) */
    kiosk_state_action(&st, &config, &with_black_body, KIOSK_ACTION_CYCLE_EFFECTS);
    assert_int_equal(st.effects, EFFECTS_DOPPLER);
    kiosk_state_action(&st, &config, &with_black_body, KIOSK_ACTION_CYCLE_EFFECTS);
    assert_int_equal(st.effects, EFFECTS_SEARCHLIGHT);
    kiosk_state_action(&st, &config, &with_black_body, KIOSK_ACTION_CYCLE_EFFECTS);
    assert_int_equal(st.effects, EFFECTS_GEOMETRY);
    /* a scene change and reset show the scene's own effects, as its file sets them
     * (starflight: searchlight), and the button goes on from there */
    kiosk_state_action(&st, &config, &with_black_body, KIOSK_ACTION_NEXT_SCENE);
    assert_int_equal(with_black_body.observer.effects, EFFECTS_SEARCHLIGHT);
    assert_int_equal(kiosk_state_effects(&st, &with_black_body), EFFECTS_SEARCHLIGHT);
    kiosk_state_action(&st, &config, &with_black_body, KIOSK_ACTION_CYCLE_EFFECTS);
    assert_int_equal(kiosk_state_effects(&st, &with_black_body), EFFECTS_GEOMETRY);
    kiosk_state_action(&st, &config, &with_black_body, KIOSK_ACTION_RESET);
    assert_int_equal(kiosk_state_effects(&st, &with_black_body), EFFECTS_SEARCHLIGHT);
    kiosk_state_action(&st, &config, &with_black_body, KIOSK_ACTION_PIPELINE_VIEW);
    assert_true(st.pipeline_view);
    st.speed = 0.7;
    kiosk_state_action(&st, &config, &with_black_body, KIOSK_ACTION_RESET);
    assert_true(st.speed == config.speed.start && !st.pipeline_view);
    /* staff mode: toggled, not part of what is drawn (the picture stays the same state), ended by
     * reset, which a visitor may press */
    struct kiosk_state before = st;
    kiosk_state_action(&st, &config, &with_black_body, KIOSK_ACTION_STAFF_MODE);
    assert_true(st.staff);
    assert_true(kiosk_state_same(&before, &st));
    kiosk_state_action(&st, &config, &with_black_body, KIOSK_ACTION_STAFF_MODE);
    assert_false(st.staff);
    kiosk_state_action(&st, &config, &with_black_body, KIOSK_ACTION_STAFF_MODE);
    kiosk_state_action(&st, &config, &with_black_body, KIOSK_ACTION_RESET);
    assert_false(st.staff);
}

/* Around a mass the effects button adds gravity's shift as a layer of its own, after motion's
 * colour and brightness; from a scene's own Doppler colour with gravity (blackhole_flight) it goes on
 * to the searchlight with it. The scene drawn takes each layer (kiosk_state_apply). */
static void test_effects_layers_with_gravity(void **state)
{
    (void)state;
    static struct scene flight, drawn;
    hc_load(&flight, "blackhole_flight", 16, 12, NULL);
    assert_int_equal(flight.observer.effects, EFFECTS_DOPPLER);
    assert_true(flight.observer.gravitational_shift);
    struct kiosk_state st;
    kiosk_state_reset(&st, &config);
    static const struct {
        enum relativity_effects effects;
        int gravity;
    } ladder[] = {
        {EFFECTS_DOPPLER, 1},     /* the scene's own */
        {EFFECTS_SEARCHLIGHT, 1}, {EFFECTS_GEOMETRY, 1},    {EFFECTS_DOPPLER, 0},
        {EFFECTS_SEARCHLIGHT, 0}, {EFFECTS_SEARCHLIGHT, 1}, {EFFECTS_GEOMETRY, 1}, {EFFECTS_DOPPLER, 0},
    };
    struct error err = {0};
    for (size_t i = 0; i < sizeof ladder / sizeof ladder[0]; i++) {
        if (i > 0)
            kiosk_state_action(&st, &config, &flight, KIOSK_ACTION_CYCLE_EFFECTS);
        assert_int_equal(kiosk_state_effects(&st, &flight), ladder[i].effects);
        if (ladder[i].effects != EFFECTS_GEOMETRY)
            assert_int_equal(kiosk_state_gravitational_shift(&st, &flight), ladder[i].gravity);
        assert_int_equal(kiosk_state_apply(&st, &flight, &drawn, &err), 0);
        assert_int_equal(drawn.observer.effects, ladder[i].effects);
        assert_int_equal(drawn.observer.gravitational_shift, kiosk_state_gravitational_shift(&st, &flight));
    }
    /* a layer chosen is part of what is drawn */
    struct kiosk_state other = st;
    other.gravitational_shift = !st.gravitational_shift;
    assert_false(kiosk_state_same(&st, &other));
}

/* The shipped attract tour (kiosk.conf's [attract] script) is a valid script, plays over the shipped
 * scene list as it says: every scene shown once, back at the start scene when it ends (so that each
 * pass begins where the visitor would), staff mode never entered, every event a visitor's. */
static void test_shipped_tour(void **state)
{
    (void)state;
    load_example();
    static struct script sc;
    struct error e;
    assert_true(config.attract.script[0] != '\0');
    if (script_load(&sc, config.attract.script, &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    struct kiosk_state st;
    kiosk_state_reset(&st, &config);
    int shown[KIOSK_MAX_SCENES] = {0}, frames = 0;
    static struct scene scene;
    hc_load(&scene, "schwarzschild", 16, 12, NULL);
    shown[st.scene] = 1;
    for (int i = 0; i < sc.n; i++) {
        const struct script_event *ev = &sc.events[i];
        frames += ev->kind == SCRIPT_FRAME;
        if (ev->kind != SCRIPT_PRESS)
            continue;
        assert_int_not_equal(ev->action, KIOSK_ACTION_STAFF_MODE);
        kiosk_state_action(&st, &config, &scene, ev->action);
        shown[st.scene] = 1;
    }
    assert_int_equal(frames, 0);             /* a headless screen's event has no place on an exhibit */
    assert_int_equal(st.scene, config.kiosk.start_scene);
    for (int i = 0; i < config.kiosk.n_scenes; i++)
        if (!shown[i])
            fail_msg("the tour never shows %s", config.kiosk.scenes[i]);
    assert_true(sc.events[sc.n - 1].t < 120.0);   /* a pass a visitor can stand */
}

/* Speed along the view, the black hole's mass (0: flat space, not integrated), the camera kept. */
static void test_apply(void **state)
{
    (void)state;
    static struct scene base, out;
    hc_load(&base, "schwarzschild", 16, 12, NULL);
    base.kiosk.mass.key[0] = '\0';                 /* a black hole without [kiosk]: the knob sets its mass */
    struct kiosk_state st = {.speed = 0.6, .mass = 0.5, .effects = EFFECTS_GEOMETRY};
    struct error e;
    assert_int_equal(kiosk_state_apply(&st, &base, &out, &e), 0);
    vec3d view = v3_normalize(v3_sub(base.camera.look_at, base.camera.position));
    assert_true(fabs(v3_len(out.observer.velocity) - 0.6) <= 1e-12);
    assert_true(v3_dot(v3_normalize(out.observer.velocity), view) >= 1.0 - 1e-12);
    assert_true(out.model.mass == 0.5);
    assert_true(v3_len(v3_sub(out.camera.position, base.camera.position)) == 0.0);
    st.mass = 0.0;
    assert_int_equal(kiosk_state_apply(&st, &base, &out, &e), 0);
    assert_true(model_is_straight(&out.model));
    st.mass = 10.0;                                 /* horizon radius 20: the camera is inside */
    assert_int_not_equal(kiosk_state_apply(&st, &base, &out, &e), 0);
    assert_non_null(strstr(e.message, "horizon"));
}

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static void test_script(void **state)
{
    (void)state;
    static struct script sc;
    struct error e;
    char err[600];
    write_file("build/test_script_good.txt", "# a tour\n0 turn speed +3\n0.5 turn mass -2\n\n1 press next_scene\n"
                                              "1 frame\n  2.25 press cycle_effects\n");
    assert_int_equal(script_load(&sc, "build/test_script_good.txt", &e), 0);
    assert_int_equal(sc.n, 5);
    assert_true(sc.events[0].kind == SCRIPT_TURN && sc.events[0].knob == SCRIPT_KNOB_SPEED && sc.events[0].counts == 3);
    assert_true(sc.events[1].knob == SCRIPT_KNOB_MASS && sc.events[1].counts == -2);
    assert_true(sc.events[2].kind == SCRIPT_PRESS && sc.events[2].action == KIOSK_ACTION_NEXT_SCENE);
    assert_true(sc.events[3].kind == SCRIPT_FRAME && sc.events[3].t == 1.0);
    assert_true(sc.events[4].action == KIOSK_ACTION_CYCLE_EFFECTS && sc.events[4].line == 7);
    static const struct { const char *text, *want; } bad[] = {
        {"1 turn speed +3\n0.5 frame\n", ":2: time 0.5 goes back"},
        {"1 jump\n", ":1: unknown event \"jump\""},
        {"nan frame\n", ":1: expected a time"},
        {"-1 frame\n", ":1: expected a time"},
        {"1 turn speed +5000\n", ":1: turn speed: expected counts from -1000 to +1000"},
        /* LONG_MIN, whose labs() would be undefined */
        {"0.5 turn speed -9223372036854775808\n", ":1: turn speed: expected counts from -1000 to +1000"},
        /* a far-future event would keep a headless kiosk waiting */
        {"0.5 frame\n1e15 frame\n", ":2: expected a time in seconds from 0 to 86400"},
        {"1 turn volume 3\n", ":1: turn: expected the knob speed or mass"},
        {"1 press launch\n", ":1: press: expected next_scene"},
        {"1 frame now\n", ":1: unexpected \"now\""},
        {"1\n", ":1: expected an event"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        write_file("build/test_script_bad.txt", bad[i].text);
        assert_int_equal(script_load(&sc, "build/test_script_bad.txt", &e), -1);
        assert_int_equal(e.status, ERROR_INPUT);
        error_format(&e, err, sizeof err);
        if (!strstr(err, bad[i].want))
            fail_msg("script \"%s\": got \"%s\", want \"%s\"", bad[i].text, err, bad[i].want);
    }
    assert_int_equal(script_load(&sc, "build/no_such_script.txt", &e), -1);
    assert_int_equal(e.status, ERROR_INPUT);
    assert_string_equal(e.where, "build/no_such_script.txt");
    error_format(&e, err, sizeof err);
    assert_non_null(strstr(err, "no_such_script.txt: cannot open the script"));
    /* a byte-order mark and CR LF line ends, as a Windows editor saves it: read as written */
    write_file("build/test_script_crlf.txt", "\xEF\xBB\xBF" "0 frame\r\n1 turn mass +2\r\n");
    assert_int_equal(script_load(&sc, "build/test_script_crlf.txt", &e), 0);
    assert_int_equal(sc.n, 2);
    assert_true(sc.events[1].kind == SCRIPT_TURN && sc.events[1].counts == 2);
    /* CR line ends alone would make one line of the whole file: refused, not cut at its first CR */
    write_file("build/test_script_cr.txt", "0 frame\r1 turn mass +2\r");
    assert_int_equal(script_load(&sc, "build/test_script_cr.txt", &e), -1);
    error_format(&e, err, sizeof err);
    assert_non_null(strstr(err, "test_script_cr.txt:1: a carriage return inside the line"));
    /* a NUL byte does not end the line silently: refused with its line */
    static const char with_nul[] = "0 frame\n1 turn mass +2\0 frame\n";
    FILE *f = fopen("build/test_script_nul.txt", "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(with_nul, 1, sizeof with_nul - 1, f), sizeof with_nul - 1);
    assert_int_equal(fclose(f), 0);
    assert_int_equal(script_load(&sc, "build/test_script_nul.txt", &e), -1);
    error_format(&e, err, sizeof err);
    assert_non_null(strstr(err, "test_script_nul.txt:2: the line holds a NUL byte"));
}

/* One renderer whose scene the knobs change between frames draws what a fresh renderer draws, while
 * other renderers come and go on the same context (the fresh ones here). */
static void test_renderer_follows_the_scene(void **state)
{
    (void)state;
    enum { W = 40, H = 30 };
    static struct scene base, live, fresh;
    hc_load(&base, "blackhole_flight", W, H, NULL);
    static const struct kiosk_state states[] = {
        {.speed = 0.0, .mass = 0.12, .effects = EFFECTS_GEOMETRY},
        {.speed = 0.0, .mass = 0.12, .effects = EFFECTS_GEOMETRY},
        {.speed = 0.0, .mass = 0.0, .effects = EFFECTS_GEOMETRY},
        {.speed = 0.5, .mass = 0.12, .effects = EFFECTS_GEOMETRY},
        {.speed = 0.5, .mass = 0.12, .effects = EFFECTS_DOPPLER},
        {.speed = 0.5, .mass = 0.0, .effects = EFFECTS_DOPPLER},
        {.speed = 0.8, .mass = 0.3, .effects = EFFECTS_SEARCHLIGHT},
        {.speed = 0.0, .mass = 0.12, .effects = EFFECTS_GEOMETRY},
    };
    struct error e;
    struct error gl_err;
    struct renderer *r = renderer_create(hc_context(), &live, &gl_err);
    for (size_t k = 0; k < sizeof states / sizeof states[0]; k++) {
        if (kiosk_state_apply(&states[k], &base, &live, &e) != 0)
            fail_msg("%s", e.message);
        if (k == 0) {
            renderer_destroy(r);
            r = renderer_create(hc_context(), &live, &gl_err);
            assert_non_null(r);
        }
        struct render_result a;
        if (renderer_run(r, &live, 0, 0, W, H, NULL, NULL, &e) != 0 || renderer_read(r, &a, RENDER_READ_IMAGE, &e))
            fail_msg("%s", e.message);
        fresh = live;
        struct hc_gpu g;
        hc_gpu_render(&fresh, &g);
        if (memcmp(a.rgba, g.res.rgba, 4 * W * H) != 0)
            fail_msg("state %zu: the renderer that followed the knobs draws another image", k);
        render_result_free(&a);
        hc_gpu_free(&g);
    }
    /* another scene's objects, textures or sky are not what this renderer loaded: refused, not drawn */
    static struct scene other;
    hc_load(&other, "neutron_star", W, H, NULL);
    assert_int_equal(renderer_run(r, &other, 0, 0, W, H, NULL, NULL, &e), -1);
    assert_non_null(strstr(e.message, "make a renderer for the new scene"));
    fresh = live;
    fresh.n_objects--;
    assert_int_equal(renderer_run(r, &fresh, 0, 0, W, H, NULL, NULL, &e), -1);
    /* the scene it follows still runs */
    assert_int_equal(renderer_run(r, &live, 0, 0, W, H, NULL, NULL, &e), 0);
    renderer_destroy(r);
}

/* A scene whose model has no mass maps the knobs to its own keys (lorenz.scene: the mass knob sets
 * rho from 0 to 50 in 25 detents, the speed knob the flow's strength): a turn moves the key from the
 * scene's own value, the observer stays at rest, the next scene starts from its own values. */
static void test_knobs_mapped_to_scene_keys(void **state)
{
    (void)state;
    load_example();
    static struct scene lorenz, out;
    struct error e;
    if (scene_load(&lorenz, "assets/scenes/lorenz.scene", &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    assert_string_equal(lorenz.kiosk.mass.key, "model.rho");
    struct kiosk_state st;
    kiosk_state_reset(&st, &config);
    assert_true(isnan(st.mass_param) && isnan(st.speed_param));
    struct input_event ev = {.kind = INPUT_KNOB, .knob = INPUT_KNOB_MASS, .counts = 3, .bit = -1};
    struct event_outcome o;
    double mass_before = st.mass;
    kiosk_event_apply(&config, &st, &lorenz, &ev, &o);
    assert_true(o.changed);
    assert_true(fabs(st.mass_param - (28.0 + 3 * 2.0)) <= 1e-12);   /* 50 / 25 per detent */
    assert_true(st.mass == mass_before);
    ev.knob = INPUT_KNOB_SPEED;
    ev.counts = 100;                                                /* clamped at speed_max */
    kiosk_event_apply(&config, &st, &lorenz, &ev, &o);
    assert_true(st.speed_param == 0.01);
    st.speed = 0.5;                                                 /* not used: speed is mapped */
    assert_int_equal(kiosk_state_apply(&st, &lorenz, &out, &e), 0);
    assert_true(out.model.rho == 34.0);
    assert_true(out.model.strength == 0.01);
    assert_true(v3_len(out.observer.velocity) == 0.0);
    ev.counts = -1000;                                              /* clamped at speed_min */
    kiosk_event_apply(&config, &st, &lorenz, &ev, &o);
    assert_true(st.speed_param == 0.0);
    kiosk_state_action(&st, &config, &lorenz, KIOSK_ACTION_NEXT_SCENE);
    assert_true(isnan(st.mass_param) && isnan(st.speed_param));
    assert_int_equal(kiosk_state_apply(&st, &lorenz, &out, &e), 0);
    assert_true(out.model.rho == 28.0);                             /* the scene's own again */
    /* a Schwarzschild scene without [kiosk] (the shipped ones map model.mass): the mass knob is the
     * black hole's mass */
    static struct scene bh;
    if (scene_load(&bh, "assets/scenes/schwarzschild.scene", &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    bh.kiosk.mass.key[0] = '\0';
    ev.knob = INPUT_KNOB_MASS;
    ev.counts = 2;
    kiosk_event_apply(&config, &st, &bh, &ev, &o);
    assert_true(isnan(st.mass_param));
    assert_true(fabs(st.mass - knob_turn(&config.mass, mass_before, 2)) <= 1e-12);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_speed_knob_in_rapidity),
        cmocka_unit_test(test_mass_knob),
        cmocka_unit_test(test_actions),
        cmocka_unit_test(test_apply),
        cmocka_unit_test(test_script),
        cmocka_unit_test(test_effects_layers_with_gravity),
        cmocka_unit_test(test_shipped_tour),
        cmocka_unit_test(test_knobs_mapped_to_scene_keys),
        cmocka_unit_test(test_renderer_follows_the_scene),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
