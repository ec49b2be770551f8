/* The kiosk configuration: the example kiosk/kiosk.conf loads with the values it states and names
 * every key, left-out keys keep their defaults, and each kind of bad file fails at its line with a
 * message naming the key. Bad files are written under build/test_kiosk_config/ by the test itself.
 * Runs from the repository root. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "kiosk_config/kiosk_config.h"
#include "kiosk_config/kiosk_config_keys.h"

#define EXAMPLE "kiosk/kiosk.conf"
#define DIR "build/test_kiosk_config"
/* scene files as seen from DIR */
#define SCENE "../../assets/scenes/lorenz.scene"
#define SCENE2 "../../assets/scenes/starflight.scene"
#define DEFAULT_FONT "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"

/* ---- files ------------------------------------------------------------------------------------ */

static void make_dir(const char *path)
{
    if (mkdir(path, 0755) != 0 && errno != EEXIST)
        fail_msg("cannot create %s: %s", path, strerror(errno));
}

static void make_dirs(void)
{
    make_dir("build");
    make_dir(DIR);
}

static void write_file(const char *path, const char *text, size_t len)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        fail_msg("cannot write %s: %s", path, strerror(errno));
    assert_int_equal(fwrite(text, 1, len, f), len);
    assert_int_equal(fclose(f), 0);
}

/* DIR/NAME.conf holding TEXT; its path in PATH. */
static void write_conf(char path[256], const char *name, const char *text)
{
    make_dirs();
    snprintf(path, 256, DIR "/%s.conf", name);
    write_file(path, text, strlen(text));
}

static void assert_contains(const char *text, const char *part)
{
    if (!strstr(text, part))
        fail_msg("\"%s\" does not contain \"%s\"", text, part);
}

/* cmocka 1.1 compares only floats; the knobs are doubles */
#define assert_near(a, b) check_near((a), (b), #a, __LINE__)
static void check_near(double a, double b, const char *what, int line)
{
    if (!(fabs(a - b) <= 1e-12))
        fail_msg("line %d: %s is %.17g, expected %.17g", line, what, a, b);
}

/* Loads and checks TEXT; any error fails the test with where and message. */
static void load_good(struct kiosk_config *c, const char *name, const char *text)
{
    struct error err;
    char path[256];
    write_conf(path, name, text);
    if (kiosk_config_load(c, path, &err) != 0)
        fail_msg("load: %s: %s", err.where, err.message);
    if (kiosk_config_check(c, &err) != 0)
        fail_msg("check: %s: %s", err.where, err.message);
}

/* ---- the example -------------------------------------------------------------------------------- */

static void test_example_loads(void **state)
{
    static struct kiosk_config c;
    struct error err;
    const struct kiosk_input *in;
    (void)state;

    if (kiosk_config_load(&c, EXAMPLE, &err) != 0)
        fail_msg("%s: %s", err.where, err.message);
    if (kiosk_config_check(&c, &err) != 0)
        fail_msg("%s: %s", err.where, err.message);

    assert_int_equal(c.kiosk.n_scenes, 7);
    assert_string_equal(c.kiosk.scenes[0], "kiosk/../assets/scenes/schwarzschild.scene");
    assert_string_equal(c.kiosk.scenes[1], "kiosk/../assets/scenes/demo.scene");
    assert_string_equal(c.kiosk.scenes[2], "kiosk/../assets/scenes/starflight.scene");
    assert_string_equal(c.kiosk.scenes[3], "kiosk/../assets/scenes/blackhole_flight.scene");
    assert_string_equal(c.kiosk.scenes[4], "kiosk/../assets/scenes/cube_approach.scene");
    assert_string_equal(c.kiosk.scenes[5], "kiosk/../assets/scenes/lorenz.scene");
    assert_string_equal(c.kiosk.scenes[6], "kiosk/../assets/scenes/star_sky.scene");
    assert_int_equal(c.kiosk.start_scene, 0);
    assert_int_equal(c.kiosk.idle_seconds, 120);
    assert_int_equal(c.kiosk.preview_width, 320);
    assert_int_equal(c.kiosk.preview_height, 180);
    assert_int_equal(c.kiosk.width, 1280);
    assert_int_equal(c.kiosk.height, 720);
    assert_int_equal(c.kiosk.refine_frames, 4);
    assert_int_equal(c.kiosk.hud, 1);
    assert_string_equal(c.kiosk.font, DEFAULT_FONT);
    assert_string_equal(c.kiosk.log, "stderr");
    assert_string_equal(c.kiosk.assets_root, "kiosk/../assets");

    assert_int_equal(c.display.backend, KIOSK_BACKEND_AUTO);
    assert_string_equal(c.display.drm_device, "");
    assert_string_equal(c.display.connector, "");
    assert_int_equal(c.display.mode_width, 0);
    assert_int_equal(c.display.vsync, 1);
    assert_string_equal(c.display.headless_out, "");
    assert_int_equal(c.display.headless_frames, 0);

    assert_string_equal(c.speed.input, "speed_knob");
    assert_near(c.speed.min, 0.0);
    assert_near(c.speed.max, 0.99);
    assert_near(c.speed.step, 0.05);
    assert_int_equal(c.speed.curve, KIOSK_CURVE_RAPIDITY);
    assert_near(c.speed.start, 0.0);
    assert_string_equal(c.mass.input, "mass_knob");
    assert_near(c.mass.min, 0.0);
    assert_near(c.mass.max, 4.0);
    assert_near(c.mass.step, 0.05);
    assert_int_equal(c.mass.curve, KIOSK_CURVE_LINEAR);
    assert_near(c.mass.start, 1.0);

    assert_int_equal(c.n_buttons, 2);
    assert_string_equal(c.buttons[0].name, "next");
    assert_int_equal(c.buttons[0].action, KIOSK_ACTION_NEXT_SCENE);
    assert_string_equal(c.buttons[0].input, "next_button");
    assert_int_equal(c.buttons[0].bit, -1);
    assert_string_equal(c.buttons[1].name, "effects");
    assert_int_equal(c.buttons[1].action, KIOSK_ACTION_CYCLE_EFFECTS);
    assert_string_equal(c.buttons[1].input, "effects_button");

    assert_int_equal(c.n_inputs, 5);
    in = kiosk_config_input(&c, "speed_knob");
    assert_non_null(in);
    assert_int_equal(in->type, KIOSK_INPUT_POWERMATE);
    assert_int_equal(in->vid, 0x077d);
    assert_int_equal(in->pid, 0x0410);
    in = kiosk_config_input(&c, "mass_knob");
    assert_non_null(in);
    assert_int_equal(in->type, KIOSK_INPUT_GPIO_ENCODER);
    assert_string_equal(in->chip, "gpiochip0");
    assert_string_equal(in->line_a_name, "KNOB_MASS_A");
    assert_string_equal(in->line_b_name, "KNOB_MASS_B");
    assert_int_equal(in->line_a, -1);
    assert_int_equal(in->line_b, -1);
    assert_int_equal(in->counts_per_detent, 4);
    in = kiosk_config_input(&c, "next_button");
    assert_non_null(in);
    assert_int_equal(in->type, KIOSK_INPUT_GPIO_BUTTON);
    assert_string_equal(in->chip, "gpiochip0");
    assert_string_equal(in->line_name, "BUTTON_NEXT");
    assert_int_equal(in->line, -1);
    assert_int_equal(in->active_low, 1);
    assert_int_equal(in->debounce_ms, 20);
    in = kiosk_config_input(&c, "effects_button");
    assert_non_null(in);
    assert_string_equal(in->line_name, "BUTTON_EFFECTS");
    in = kiosk_config_input(&c, "keys");
    assert_non_null(in);
    assert_int_equal(in->type, KIOSK_INPUT_KEYBOARD);
    assert_null(kiosk_config_input(&c, "box"));

    assert_int_equal(c.attract.enabled, 0);
    assert_string_equal(c.attract.script, "kiosk/../assets/tours/attract.events");   /* shipped, off until enabled */
}

/* Every key of the table is in the example, set or commented out: the file is the documentation. */
static void test_example_names_every_key(void **state)
{
    static char text[1 << 16];
    FILE *f = fopen(EXAMPLE, "rb");
    size_t n;
    (void)state;
    assert_non_null(f);
    n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = '\0';
    for (int i = 0; i < kiosk_key_count; i++) {
        char set[96], commented[96];
        snprintf(set, sizeof set, "\n%s = ", kiosk_keys[i].name);
        snprintf(commented, sizeof commented, "\n; %s = ", kiosk_keys[i].name);
        if (!strstr(text, set) && !strstr(text, commented))
            fail_msg("key '%s' of [%s] is not in %s", kiosk_keys[i].name,
                     kiosk_section_name(kiosk_keys[i].section), EXAMPLE);
    }
}

/* ---- defaults ----------------------------------------------------------------------------------- */

#define KIOSK_OK "[kiosk]\nscenes = " SCENE "\n"                        /* lines 1-2 */
#define KNOBS_OK "[input kb]\ntype = keyboard\n[speed]\ninput = kb\n[mass]\ninput = kb\n"  /* 6 lines */

static void test_defaults(void **state)
{
    static struct kiosk_config c;
    struct error err;
    (void)state;

    kiosk_config_defaults(&c);
    assert_int_equal(c.kiosk.n_scenes, 0);
    assert_int_equal(kiosk_config_check(&c, &err), -1);   /* a kiosk needs scenes */
    assert_string_equal(err.where, "kiosk configuration");
    assert_contains(err.message, "no scenes");

    load_good(&c, "defaults", KIOSK_OK KNOBS_OK);
    assert_int_equal(c.kiosk.n_scenes, 1);
    assert_string_equal(c.kiosk.scenes[0], DIR "/" SCENE);
    assert_int_equal(c.kiosk.start_scene, 0);
    assert_int_equal(c.kiosk.idle_seconds, 120);
    assert_int_equal(c.kiosk.preview_width, 320);
    assert_int_equal(c.kiosk.preview_height, 180);
    assert_int_equal(c.kiosk.width, 1280);
    assert_int_equal(c.kiosk.height, 720);
    assert_int_equal(c.kiosk.refine_frames, 4);
    assert_int_equal(c.kiosk.hud, 1);
    assert_string_equal(c.kiosk.font, DEFAULT_FONT);
    assert_string_equal(c.kiosk.log, "stderr");
    assert_string_equal(c.kiosk.assets_root, "");
    assert_int_equal(c.display.backend, KIOSK_BACKEND_AUTO);
    assert_string_equal(c.display.drm_device, "");
    assert_string_equal(c.display.connector, "");
    assert_int_equal(c.display.mode_width, 0);
    assert_int_equal(c.display.mode_height, 0);
    assert_int_equal(c.display.vsync, 1);
    assert_int_equal(c.display.headless_frames, 0);
    assert_near(c.speed.min, 0.0);
    assert_near(c.speed.max, 0.99);
    assert_near(c.speed.step, 0.05);
    assert_int_equal(c.speed.curve, KIOSK_CURVE_RAPIDITY);
    assert_near(c.speed.start, 0.0);
    assert_near(c.mass.min, 0.0);
    assert_near(c.mass.max, 10.0);
    assert_near(c.mass.step, 0.1);
    assert_int_equal(c.mass.curve, KIOSK_CURVE_LINEAR);
    assert_int_equal(c.n_buttons, 0);
    assert_int_equal(c.n_inputs, 1);
    assert_int_equal(c.attract.enabled, 0);
}

/* start follows min unless given; named sections and typed inputs start from their own defaults */
static void test_section_defaults(void **state)
{
    static struct kiosk_config c;
    const struct kiosk_input *in;
    (void)state;
    load_good(&c, "section_defaults", KIOSK_OK
              "[input pm]\ntype = powermate\n"
              "[input box]\ntype = hid\nvid = 0x1234\npid = 0xABCD\nbuttons = 2\nbutton_offset = 1\n"
              "[input enc]\ntype = gpio_encoder\nchip = gpiochip1\nline_a = 5\nline_b = 6\n"
              "[input btn]\ntype = gpio_button\nchip = gpiochip1\nline = 7\n"
              "[speed]\ninput = pm\nmin = 0.2\n"
              "[mass]\ninput = enc\nmin = 0.5\nmax = 8\ncurve = log\nstep = 0.25\n"
              "[button a]\naction = reset\ninput = box\nbit = 1\n"
              "[button b]\naction = previous_scene\ninput = btn\n"
              "[button c]\naction = pipeline_view\ninput = pm\n");
    assert_near(c.speed.start, 0.2);
    assert_near(c.mass.start, 0.5);
    assert_int_equal(c.mass.curve, KIOSK_CURVE_LOG);
    in = kiosk_config_input(&c, "pm");
    assert_int_equal(in->vid, KIOSK_POWERMATE_VID);
    assert_int_equal(in->pid, KIOSK_POWERMATE_PID);
    in = kiosk_config_input(&c, "box");
    assert_int_equal(in->vid, 0x1234);
    assert_int_equal(in->pid, 0xabcd);
    assert_int_equal(in->report_id, 0);
    assert_int_equal(in->report_length, 8);
    assert_int_equal(in->axis_offset, 0);
    assert_int_equal(in->axis_size, 1);
    assert_int_equal(in->axis_signed, 1);
    assert_int_equal(in->axis_mode, KIOSK_AXIS_RELATIVE);
    in = kiosk_config_input(&c, "enc");
    assert_int_equal(in->line_a, 5);
    assert_int_equal(in->line_b, 6);
    assert_int_equal(in->counts_per_detent, 4);
    in = kiosk_config_input(&c, "btn");
    assert_int_equal(in->line, 7);
    assert_int_equal(in->active_low, 1);
    assert_int_equal(in->debounce_ms, 20);
    assert_int_equal(c.buttons[0].bit, 1);
    assert_int_equal(c.buttons[1].bit, -1);
    assert_int_equal(c.buttons[2].action, KIOSK_ACTION_PIPELINE_VIEW);
}

/* A list longer than a line goes on over indented lines; ';' leaves one out; start_scene may come
 * first and name a scene. */
static void test_scene_list(void **state)
{
    static struct kiosk_config c;
    (void)state;
    load_good(&c, "scene_list",
              "[kiosk]\n"
              "start_scene = starflight\n"
              "scenes = " SCENE ",\n"
              "   ; ../../assets/scenes/rossler.scene\n"
              "   ../../assets/scenes/demo.scene   " SCENE2 " ; the last\n"
              "width = 640\nheight = 360\n" KNOBS_OK);
    assert_int_equal(c.kiosk.n_scenes, 3);
    assert_string_equal(c.kiosk.scenes[1], DIR "/../../assets/scenes/demo.scene");
    assert_string_equal(c.kiosk.scenes[2], DIR "/" SCENE2);
    assert_int_equal(c.kiosk.start_scene, 2);
    assert_int_equal(c.kiosk.width, 640);
    load_good(&c, "scene_index", "[kiosk]\nscenes = " SCENE " " SCENE2 "\nstart_scene = 1\n" KNOBS_OK);
    assert_int_equal(c.kiosk.start_scene, 1);
}

/* ---- bad files ---------------------------------------------------------------------------------- */

enum phase { AT_LOAD, AT_CHECK };

struct bad_case {
    const char *name;
    enum phase phase;
    const char *text;
    int line;                 /* 0: the message names the file alone */
    const char *parts[3];     /* what the message must say */
};

static const struct bad_case bad_cases[] = {
    {"unknown_key", AT_LOAD, KIOSK_OK "idle_secnds = 60\n", 3,
     {"unknown key 'idle_secnds' in [kiosk] (did you mean 'idle_seconds'?)"}},
    {"unknown_key_far", AT_LOAD, KIOSK_OK "brightness = 60\n", 3, {"unknown key 'brightness' in [kiosk]"}},
    {"unknown_input_key", AT_LOAD, KIOSK_OK "[input box]\ntype = hid\naxis_sise = 2\n", 5,
     {"unknown key 'axis_sise' in [input box] (did you mean 'axis_size'?)"}},
    {"unknown_section", AT_LOAD, KIOSK_OK "[dispaly]\nvsync = on\n", 3,
     {"unknown section [dispaly]", "did you mean [display]?"}},
    {"unknown_section_far", AT_LOAD, "[knobs]\n", 1, {"unknown section [knobs]", "sections: kiosk"}},
    {"duplicate_key", AT_LOAD, KIOSK_OK "width = 640\nheight = 360\nwidth = 800\n", 5,
     {"key 'width' in [kiosk] is already set at line 3"}},
    {"duplicate_section", AT_LOAD, "[speed]\nmin = 0\n" KIOSK_OK "[speed]\nmax = 0.5\n", 5,
     {"section [speed] appears twice (lines 1 and 5)"}},
    {"duplicate_input", AT_LOAD, "[input a]\ntype = keyboard\n[input a]\ntype = keyboard\n", 3,
     {"section [input a] appears twice (lines 1 and 3)"}},
    {"out_of_range", AT_LOAD, KIOSK_OK "idle_seconds = 5\n", 3,
     {"key 'idle_seconds' in [kiosk]: expected an integer from 10 to 86400, got \"5\""}},
    {"nan", AT_LOAD, KIOSK_OK "[mass]\nmax = nan\n", 4,
     {"key 'max' in [mass]", "got \"nan\"", "not a finite number"}},
    {"inf", AT_LOAD, KIOSK_OK "[mass]\nstep = -inf\n", 4, {"key 'step' in [mass]", "not a finite number"}},
    /* a denormal, refused as the scene refuses it */
    {"denormal", AT_LOAD, KIOSK_OK "[mass]\nstep = 1e-320\n", 4, {"key 'step' in [mass]", "too large or too small for a double"}},
    {"plus_sign", AT_LOAD, KIOSK_OK "idle_seconds = +120\n", 3,
     {"key 'idle_seconds' in [kiosk]: expected an integer from 10 to 86400, got \"+120\""}},
    {"trailing_garbage", AT_LOAD, KIOSK_OK "width = 1280px\n", 3,
     {"key 'width' in [kiosk]: expected an integer from 16 to 8192, got \"1280px\""}},
    {"trailing_number", AT_LOAD, KIOSK_OK "[speed]\nstep = 0.05 0.1\n", 4,
     {"key 'step' in [speed]", "got \"0.05 0.1\""}},
    {"hash_comment", AT_LOAD, KIOSK_OK "idle_seconds = 120 # two minutes\n", 3,
     {"key 'idle_seconds' in [kiosk]", "not '#'"}},
    {"empty_value", AT_LOAD, KIOSK_OK "hud =\n", 3, {"key 'hud' in [kiosk] has an empty value"}},
    {"bad_choice", AT_LOAD, KIOSK_OK "hud = yes\n", 3, {"key 'hud' in [kiosk]: expected one of off, on"}},
    {"speed_of_light", AT_LOAD, KIOSK_OK "[speed]\nmax = 1.0\n", 4,
     {"key 'max' in [speed]: expected a number > 0 and <= 0.99, got \"1.0\"", "fractions of c"}},
    {"speed_curve_log", AT_LOAD, KIOSK_OK "[speed]\ncurve = log\n", 4,
     {"key 'curve' in [speed]: expected one of linear, rapidity"}},
    {"missing_scene", AT_LOAD, "[kiosk]\nscenes = " SCENE ", missing.scene\n", 2,
     {"key 'scenes' in [kiosk]: scene 2", "\"" DIR "/missing.scene\"", "No such file"}},
    {"missing_scene_continued", AT_LOAD, "[kiosk]\nscenes = " SCENE ",\n    gone.scene\n", 3,
     {"key 'scenes' in [kiosk]: scene 2", DIR "/gone.scene"}},
    {"scene_is_directory", AT_LOAD, "[kiosk]\nscenes = ../../assets/scenes\n", 2,
     {"key 'scenes' in [kiosk]: scene 1", "is not a regular file"}},
    {"empty_scene_entry", AT_LOAD, "[kiosk]\nscenes = " SCENE ",," SCENE2 "\n", 2,
     {"key 'scenes' in [kiosk]", "empty entry"}},
    {"start_scene_unknown", AT_LOAD, KIOSK_OK "start_scene = nebula\n", 3,
     {"key 'start_scene' in [kiosk]", "no scene in 'scenes' is called 'nebula'"}},
    {"start_scene_past_end", AT_LOAD, KIOSK_OK "start_scene = 1\n", 3,
     {"key 'start_scene' in [kiosk]: index 1 is past the end of 'scenes'"}},
    {"font_missing", AT_LOAD, KIOSK_OK "font = nofont.ttf\n", 3,
     {"key 'font' in [kiosk]", DIR "/nofont.ttf"}},
    {"assets_root_missing", AT_LOAD, KIOSK_OK "assets_root = nowhere\n", 3,
     {"key 'assets_root' in [kiosk]", "no directory"}},
    {"log_dir_missing", AT_LOAD, KIOSK_OK "log = nowhere/kiosk.log\n", 3,
     {"key 'log' in [kiosk]", "nowhere"}},
    {"mode_bad", AT_LOAD, "[display]\nmode = 1920*1080\n", 2,
     {"key 'mode' in [display]: expected WIDTHxHEIGHT"}},
    {"drm_device_relative", AT_LOAD, "[display]\ndrm_device = card0\n", 2,
     {"key 'drm_device' in [display]: expected an absolute device path"}},
    {"vid_not_hex", AT_LOAD, "[input pm]\ntype = powermate\nvid = 077d\n", 3,
     {"key 'vid' in [input pm]: expected a hexadecimal number", "got \"077d\""}},
    {"key_not_for_type", AT_LOAD, "[input knob]\ntype = powermate\naxis_size = 2\n", 3,
     {"key 'axis_size' in [input knob] does not apply to input type 'powermate' (only to hid)"}},
    {"keyboard_takes_no_keys", AT_LOAD, "[input kb]\ntype = keyboard\nchip = gpiochip0\n", 3,
     {"key 'chip' in [input kb] does not apply to input type 'keyboard' (only to gpio_encoder, gpio_button)"}},
    {"key_before_type", AT_LOAD, "[input knob]\nvid = 0x077d\ntype = powermate\n", 2,
     {"key 'vid' in [input knob] comes before 'type'"}},
    {"input_without_type", AT_LOAD, "[input knob]\n[speed]\n", 1, {"[input knob] has no type"}},
    {"hid_without_vid", AT_LOAD, "[input box]\ntype = hid\npid = 0x0001\n\n[speed]\n", 1,
     {"[input box] of type 'hid' needs 'vid'"}},
    {"button_without_action", AT_LOAD, "[button b]\ninput = kb\n", 1, {"[button b] needs 'action'"}},
    {"bit_out_of_range", AT_LOAD, "[button b]\naction = reset\ninput = kb\nbit = 8\n", 4,
     {"key 'bit' in [button b]: expected an integer from 0 to 7"}},
    {"bad_section_name", AT_LOAD, "[input my knob]\n", 1, {"bad input name \"my knob\""}},
    {"named_without_name", AT_LOAD, "[button]\n", 1, {"[button] needs a name"}},
    {"key_before_section", AT_LOAD, "width = 100\n", 1, {"key 'width' comes before any section"}},
    {"syntax_error", AT_LOAD, KIOSK_OK "hud on\n", 3, {"syntax error"}},

    {"scene_escapes_root", AT_CHECK,
     "[kiosk]\nassets_root = root\nscenes = root/inside.scene root/../outside.scene\n" KNOBS_OK, 3,
     {"key 'scenes' in [kiosk]: scene 2", "outside assets_root"}},
    {"scene_link_escapes_root", AT_CHECK,
     "[kiosk]\nscenes = root/inside.scene, root/link.scene\nassets_root = root\n" KNOBS_OK, 2,
     {"key 'scenes' in [kiosk]: scene 2", "outside.scene\", outside assets_root"}},
    {"undefined_input", AT_CHECK, KIOSK_OK "[input kb]\ntype = keyboard\n[speed]\ninput = knobb\n"
     "[mass]\ninput = kb\n", 6, {"key 'input' in [speed]: there is no [input knobb] section (inputs: kb)"}},
    {"knob_without_input", AT_CHECK, KIOSK_OK "[input kb]\ntype = keyboard\n[speed]\ninput = kb\n", 0,
     {"[mass] has no input"}},
    {"button_on_encoder", AT_CHECK, KIOSK_OK KNOBS_OK
     "[input enc]\ntype = gpio_encoder\nchip = c\nline_a = 1\nline_b = 2\n"
     "[button b]\naction = reset\ninput = enc\n", 16, {"key 'input' in [button b]", "gpio_encoder"}},
    {"button_on_keyboard", AT_CHECK, KIOSK_OK KNOBS_OK "[button b]\naction = reset\ninput = kb\n", 11,
     {"key 'input' in [button b]: [input kb] is a keyboard", "would never fire"}},
    {"encoder_mixed_lines", AT_CHECK, KIOSK_OK KNOBS_OK
     "[input enc]\ntype = gpio_encoder\nchip = gpiochip0\nline_a = 17\nline_b_name = KNOB_B\n", 13,
     {"key 'line_b_name' in [input enc]", "by offset (line_a, line_b) and by name"}},
    {"encoder_one_line", AT_CHECK, KIOSK_OK KNOBS_OK
     "[input enc]\ntype = gpio_encoder\nchip = gpiochip0\nline_a = 17\n", 9,
     {"[input enc] needs both lines"}},
    {"gpio_line_twice", AT_CHECK, KIOSK_OK KNOBS_OK
     "[input b1]\ntype = gpio_button\nchip = gpiochip0\nline = 4\n"
     "[input b2]\ntype = gpio_button\nchip = gpiochip0\nline = 4\n", 13,
     {"[input b2] uses a GPIO line that [input b1] already uses"}},
    {"preview_larger", AT_CHECK, KIOSK_OK "width = 320\nheight = 180\npreview_width = 640\n"
     "preview_height = 360\n" KNOBS_OK, 5,
     {"key 'preview_width' in [kiosk]: the preview 640x360 is larger than the refined frame 320x180"}},
    {"bit_on_gpio_button", AT_CHECK, KIOSK_OK KNOBS_OK
     "[input btn]\ntype = gpio_button\nchip = gpiochip0\nline = 3\n"
     "[button b]\naction = reset\ninput = btn\nbit = 0\n", 16,
     {"key 'bit' in [button b] does not apply to input type 'gpio_button'"}},
    {"hid_bit_beyond_buttons", AT_CHECK, KIOSK_OK KNOBS_OK
     "[input box]\ntype = hid\nvid = 0x1\npid = 0x2\nbutton_offset = 1\nbuttons = 2\n"
     "[button b]\naction = reset\ninput = box\nbit = 2\n", 18,
     {"key 'bit' in [button b]: bit 2, but [input box] declares buttons = 2"}},
    {"hid_axis_past_report", AT_CHECK, KIOSK_OK KNOBS_OK
     "[input box]\ntype = hid\nvid = 0x1\npid = 0x2\nreport_length = 2\naxis_offset = 1\naxis_size = 2\n",
     14, {"key 'axis_offset' in [input box]: the axis at bytes 1 to 2 is outside the report's data"}},
    {"hid_relative_with_min", AT_CHECK, KIOSK_OK KNOBS_OK
     "[input box]\ntype = hid\nvid = 0x1\npid = 0x2\naxis_min = 0\n", 13,
     {"key 'axis_min' in [input box] applies to axis_mode absolute only"}},
    {"hid_absolute_reversed", AT_CHECK, KIOSK_OK KNOBS_OK
     "[input box]\ntype = hid\nvid = 0x1\npid = 0x2\naxis_mode = absolute\naxis_min = 100\naxis_max = 10\n",
     15, {"key 'axis_max' in [input box]: axis_mode absolute needs axis_min < axis_max", "100 and 10"}},
    {"button_line_twice", AT_CHECK, KIOSK_OK KNOBS_OK
     "[input btn]\ntype = gpio_button\nchip = gpiochip0\nline = 1\nline_name = B\n", 13,
     {"key 'line_name' in [input btn]: the line is given both by offset"}},
    {"knob_on_button", AT_CHECK, KIOSK_OK "[input btn]\ntype = gpio_button\nchip = c\nline = 1\n"
     "[input kb]\ntype = keyboard\n[speed]\ninput = btn\n[mass]\ninput = kb\n", 10,
     {"key 'input' in [speed]: [input btn] is a gpio_button"}},
    {"same_press_twice", AT_CHECK, KIOSK_OK KNOBS_OK
     "[input btn]\ntype = gpio_button\nchip = gpiochip0\nline = 3\n"
     "[button a]\naction = reset\ninput = btn\n[button b]\naction = next_scene\ninput = btn\n", 18,
     {"key 'input' in [button b]: the same press of [input btn] as [button a]"}},
    {"start_outside", AT_CHECK, KIOSK_OK KNOBS_OK "min = 1\nmax = 2\nstart = 3\n", 11,
     {"key 'start' in [mass]: 3 is outside min..max"}},
    {"max_below_min", AT_CHECK, KIOSK_OK KNOBS_OK "min = 2\nmax = 1\n", 10,
     {"key 'max' in [mass]: 1 is not above min (2)"}},
    {"log_from_zero", AT_CHECK, KIOSK_OK KNOBS_OK "curve = log\n", 9,
     {"key 'curve' in [mass]: log needs min > 0"}},
    {"step_over_range", AT_CHECK, KIOSK_OK KNOBS_OK "max = 1\nstep = 2\n", 10,
     {"key 'step' in [mass]: 2 is not above 0 and at most the whole range, 1"}},
    {"kms_key_for_x11", AT_CHECK, KIOSK_OK KNOBS_OK "[display]\nbackend = x11\nmode = 800x600\n", 11,
     {"key 'mode' in [display] applies to backend kms"}},
    {"headless_without_out", AT_CHECK, KIOSK_OK KNOBS_OK "[display]\nbackend = headless\n", 10,
     {"key 'backend' in [display]", "set 'headless_out'"}},
    {"attract_without_script", AT_CHECK, KIOSK_OK KNOBS_OK "[attract]\nenabled = on\n", 10,
     {"key 'enabled' in [attract]", "no 'script'"}},
};

/* Files the cases refer to: a root with one scene, a scene beside it, and a link out of it. */
static void make_fixture_files(void)
{
    static const char scene[] = "[scene]\nname = fixture\n";
    make_dirs();
    make_dir(DIR "/root");
    write_file(DIR "/root/inside.scene", scene, strlen(scene));
    write_file(DIR "/outside.scene", scene, strlen(scene));
    unlink(DIR "/root/link.scene");
    if (symlink("../outside.scene", DIR "/root/link.scene") != 0)
        fail_msg("symlink: %s", strerror(errno));
}

static void test_bad_files(void **state)
{
    static struct kiosk_config c;
    (void)state;
    make_fixture_files();
    for (size_t i = 0; i < sizeof bad_cases / sizeof bad_cases[0]; i++) {
        const struct bad_case *b = &bad_cases[i];
        struct error err;
        char path[256], where[300];
        int rc;

        write_conf(path, b->name, b->text);
        rc = kiosk_config_load(&c, path, &err);
        if (b->phase == AT_CHECK) {
            if (rc != 0)
                fail_msg("%s: loading failed, only the check should: %s: %s", b->name, err.where,
                         err.message);
            rc = kiosk_config_check(&c, &err);
        }
        if (rc == 0)
            fail_msg("%s: accepted", b->name);
        if (b->line > 0)
            snprintf(where, sizeof where, "%s:%d", path, b->line);
        else
            snprintf(where, sizeof where, "%s", path);
        if (strcmp(err.where, where) != 0)
            fail_msg("%s: error at %s, expected %s (%s)", b->name, err.where, where, err.message);
        for (int j = 0; j < 3 && b->parts[j]; j++)
            if (!strstr(err.message, b->parts[j]))
                fail_msg("%s: \"%s\" does not say \"%s\"", b->name, err.message, b->parts[j]);
        unlink(path);
    }
}

/* ---- size limits -------------------------------------------------------------------------------- */

static void test_oversized_file(void **state)
{
    static struct kiosk_config c;
    struct error err;
    size_t len = KIOSK_MAX_FILE_BYTES + 1;
    char *text = malloc(len);
    char path[256];
    (void)state;

    assert_non_null(text);
    /* a valid file up to its size: only the size is wrong */
    memset(text, '\n', len);
    memcpy(text, KIOSK_OK, strlen(KIOSK_OK));
    make_dirs();
    snprintf(path, sizeof path, DIR "/oversized.conf");
    write_file(path, text, len);
    free(text);
    assert_int_equal(kiosk_config_load(&c, path, &err), -1);
    assert_string_equal(err.where, path);
    assert_contains(err.message, "larger than 1048576 bytes");
    unlink(path);

    /* exactly the limit is fine */
    text = malloc(len - 1);
    assert_non_null(text);
    memset(text, '\n', len - 1);
    memcpy(text, KIOSK_OK KNOBS_OK, strlen(KIOSK_OK KNOBS_OK));
    write_file(path, text, len - 1);
    free(text);
    if (kiosk_config_load(&c, path, &err) != 0)
        fail_msg("%s: %s", err.where, err.message);
    unlink(path);
}

static void test_missing_file(void **state)
{
    static struct kiosk_config c;
    struct error err;
    (void)state;
    assert_int_equal(kiosk_config_load(&c, DIR "/no_such.conf", &err), -1);
    assert_string_equal(err.where, DIR "/no_such.conf");
    assert_contains(err.message, "cannot open the kiosk configuration: No such file");
}

/* inih's line buffer would cut a longer line; it is refused and said instead. */
static void test_long_line(void **state)
{
    static struct kiosk_config c;
    struct error err;
    char text[512], path[256];
    (void)state;
    snprintf(text, sizeof text, "[display]\nconnector = %0250d\n", 0);
    write_conf(path, "long_line", text);
    assert_int_equal(kiosk_config_load(&c, path, &err), -1);
    assert_contains(err.where, ":2");
    assert_contains(err.message, "characters long, at most 197");
    unlink(path);
}

/* 32 scenes over continued lines are the most; the 33rd is refused at its own line. */
static void test_too_many_scenes(void **state)
{
    static struct kiosk_config c;
    static char text[8192];
    struct error err;
    char path[256];
    size_t used;
    (void)state;
    used = (size_t)snprintf(text, sizeof text, KNOBS_OK "[kiosk]\nscenes = " SCENE "\n");
    for (int i = 1; i < KIOSK_MAX_SCENES; i++)
        used += (size_t)snprintf(text + used, sizeof text - used, "  " SCENE "\n");
    load_good(&c, "max_scenes", text);
    assert_int_equal(c.kiosk.n_scenes, KIOSK_MAX_SCENES);

    snprintf(text + used, sizeof text - used, "  " SCENE "\n");
    write_conf(path, "too_many_scenes", text);
    assert_int_equal(kiosk_config_load(&c, path, &err), -1);
    snprintf(text, sizeof text, "%s:%d", path, 6 + 1 + KIOSK_MAX_SCENES + 1);
    assert_string_equal(err.where, text);
    assert_contains(err.message, "key 'scenes' in [kiosk]: more than 32 scenes");
    unlink(path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_example_loads),
        cmocka_unit_test(test_example_names_every_key),
        cmocka_unit_test(test_defaults),
        cmocka_unit_test(test_section_defaults),
        cmocka_unit_test(test_scene_list),
        cmocka_unit_test(test_bad_files),
        cmocka_unit_test(test_oversized_file),
        cmocka_unit_test(test_missing_file),
        cmocka_unit_test(test_long_line),
        cmocka_unit_test(test_too_many_scenes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
