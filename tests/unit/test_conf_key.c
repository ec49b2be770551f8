/* The one apply function of configuration keys (conf/conf_key.h) on a small table of its own: a
 * lamp with a typed [lamp NAME] section, so that every kind, the types a key applies to, the
 * guesses, the setters and the messages are checked without a scene or the kiosk. Then the two real
 * tables, which must word the same mistakes the same way. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "conf/conf_key.h"
#include "conf/conf_path.h"
#include "kiosk_config/kiosk_config.h"
#include "kiosk_config/kiosk_config_keys.h"
#include "scene/scene_keys.h"

enum { SEC_ROOM, SEC_LAMP };
enum { LAMP_BULB, LAMP_LED, LAMP_ARC };

struct lamp {
    char name[16];
    int type;
    double watts;
    int colour_count;
    int64_t serial;
    int usb_id;
    double aim[3];
    char word[16];
    char ref[16];
    int set_calls;
};

struct room {
    char title[32];
    char note[32];
    double tint[3];
    double uv[2];
    int mode;
    char dir[64];
    char picture[64];
    char shelf[64];
    struct lamp lamps[2];
};

static const struct conf_choice modes[] = {{"dim", 3}, {"bright", 7}, {NULL, 0}};
static const struct conf_choice lamp_types[] = {{"bulb", LAMP_BULB}, {"led", LAMP_LED}, {"arc", LAMP_ARC}, {NULL, 0}};

/* stores twice the count, so that a test can tell the setter ran instead of the field copy */
static int set_colours(void *owner, void *target, const union conf_parsed *v, struct error *e)
{
    (void)owner;
    struct lamp *l = target;
    if (v->integer == 13) {
        error_set(e, ERROR_INPUT, NULL, "13 colours bring bad luck");
        return -1;
    }
    l->colour_count = 2 * v->integer;
    l->set_calls++;
    return 0;
}

#define AT_ROOM(f) offsetof(struct room, f)
#define AT_LAMP(f) offsetof(struct lamp, f)
#define BULB (1u << LAMP_BULB)
#define LED (1u << LAMP_LED)

static const struct conf_key keys[] = {
    {SEC_ROOM, "title", CONF_TEXT, .lo = 1, .hi = 31, .offset = AT_ROOM(title)},
    {SEC_ROOM, "note", CONF_TEXT, .lo = 0, .hi = 31, .offset = AT_ROOM(note)},
    {SEC_ROOM, "tint", CONF_COLOR, .lo = 0.0, .hi = 1.0, .offset = AT_ROOM(tint)},
    {SEC_ROOM, "uv", CONF_TEXCOORD, .offset = AT_ROOM(uv)},
    {SEC_ROOM, "mode", CONF_CHOICE, .choices = modes, .offset = AT_ROOM(mode)},
    {SEC_ROOM, "picture", CONF_FILE, .offset = AT_ROOM(picture)},
    {SEC_ROOM, "shelf", CONF_DIR, .offset = AT_ROOM(shelf)},
    {SEC_LAMP, "type", CONF_CHOICE, .choices = lamp_types, .flags = CONF_REQUIRED, .offset = AT_LAMP(type)},
    {SEC_LAMP, "watts", CONF_NUMBER, .lo = 0.0, .hi = 100.0, .flags = CONF_ABOVE_LO, .applies = BULB,
     .offset = AT_LAMP(watts), .hint = "a bulb draws at most 100 W"},
    {SEC_LAMP, "watts", CONF_NUMBER, .lo = 0.0, .hi = 20.0, .flags = CONF_ABOVE_LO | CONF_REQUIRED, .applies = LED,
     .offset = AT_LAMP(watts)},
    {SEC_LAMP, "colours", CONF_INTEGER, .lo = 1, .hi = 64, .applies = LED, .set = set_colours},
    {SEC_LAMP, "serial", CONF_INT64, .lo = -1e12, .hi = 1e12, .offset = AT_LAMP(serial)},
    {SEC_LAMP, "usb_id", CONF_HEX16, .offset = AT_LAMP(usb_id)},
    {SEC_LAMP, "aim", CONF_VECTOR, .lo = -INFINITY, .hi = INFINITY, .flags = CONF_NONZERO, .offset = AT_LAMP(aim)},
    {SEC_LAMP, "word", CONF_WORD, .offset = AT_LAMP(word)},
    {SEC_LAMP, "ref", CONF_NAME, .offset = AT_LAMP(ref)},
};

static void label(const void *owner, int section, int instance, char *buf, size_t len)
{
    const struct room *r = owner;
    if (section == SEC_LAMP)
        snprintf(buf, len, "[lamp %s]", r->lamps[instance].name);
    else
        snprintf(buf, len, "[room]");
}

static void *target(void *owner, int section, int instance)
{
    struct room *r = owner;
    return section == SEC_LAMP ? (void *)&r->lamps[instance] : owner;
}

static const char *type_word(int section) { return section == SEC_LAMP ? "lamp type" : NULL; }
static int type_of(const void *owner, int section, int instance)
{
    (void)section;
    return ((const struct room *)owner)->lamps[instance].type;
}
static const char *type_name(int section, int t)
{
    (void)section;
    return conf_choice_name(lamp_types, t);
}
static int resolve_path(const void *owner, const char *rel, char *out, size_t len)
{
    const struct room *r = owner;
    int n = rel[0] == '/' ? snprintf(out, len, "%s", rel) : snprintf(out, len, "%s/%s", r->dir, rel);
    return n < 0 || (size_t)n >= len ? -1 : 0;
}

static const struct conf_key_table table = {
    .keys = keys,
    .count = sizeof keys / sizeof keys[0],
    .name_len = 16,
    .path_len = 64,
    .max_abs = 1e6,
    .max_abs_reason = "no lamp is that large",
    .relative_note = "relative paths start at the room",
    .label = label,
    .target = target,
    .type_word = type_word,
    .type_of = type_of,
    .type_name = type_name,
    .resolve_path = resolve_path,
};

static struct room room;

static int setup(void **state)
{
    (void)state;
    memset(&room, 0, sizeof room);
    snprintf(room.dir, sizeof room.dir, "tests");
    snprintf(room.lamps[0].name, sizeof room.lamps[0].name, "desk");
    snprintf(room.lamps[1].name, sizeof room.lamps[1].name, "hall");
    room.lamps[1].type = LAMP_LED;
    return 0;
}

/* Applies and returns the message ("" when it was taken). */
static const char *apply(int section, int instance, const char *key, const char *value)
{
    static struct error e;
    static char *const msg = e.message;
    error_clear(&e);
    if (conf_key_apply(&table, &room, section, instance, key, value, &e) == 0)
        assert_string_equal(msg, "");
    else
        assert_true(msg[0] != '\0' && e.status == ERROR_INPUT && e.where[0] == '\0');
    print_message("%s = \"%s\": %s\n", key, value, msg[0] ? msg : "taken");
    return msg;
}

static void expect(const char *msg, const char *part)
{
    if (!strstr(msg, part))
        fail_msg("\"%s\" does not contain \"%s\"", msg, part);
}

static void test_kinds_store(void **state)
{
    (void)state;
    assert_string_equal(apply(SEC_ROOM, 0, "title", "Kitchen"), "");
    assert_string_equal(room.title, "Kitchen");
    assert_string_equal(apply(SEC_ROOM, 0, "note", ""), "");  /* text that may be empty */
    assert_string_equal(apply(SEC_ROOM, 0, "tint", "0.5 0 1"), "");
    assert_true(room.tint[0] == 0.5 && room.tint[2] == 1.0);
    assert_string_equal(apply(SEC_ROOM, 0, "uv", "-2 3.5"), "");
    assert_true(room.uv[0] == -2.0 && room.uv[1] == 3.5);
    assert_string_equal(apply(SEC_ROOM, 0, "mode", "bright"), "");
    assert_int_equal(room.mode, 7);  /* the choice's value, not its index */
    assert_string_equal(apply(SEC_LAMP, 0, "watts", "60"), "");
    assert_true(room.lamps[0].watts == 60.0);
    assert_string_equal(apply(SEC_LAMP, 0, "serial", "-123456789012"), "");
    assert_true(room.lamps[0].serial == -123456789012LL);
    assert_string_equal(apply(SEC_LAMP, 0, "usb_id", "0x077D"), "");
    assert_int_equal(room.lamps[0].usb_id, 0x077d);
    assert_string_equal(apply(SEC_LAMP, 0, "aim", "0 0 -1"), "");
    assert_true(room.lamps[0].aim[2] == -1.0);
    assert_string_equal(apply(SEC_LAMP, 0, "word", "gpio/chip0"), "");
    assert_string_equal(room.lamps[0].word, "gpio/chip0");
    assert_string_equal(apply(SEC_LAMP, 0, "ref", "desk-2"), "");
    assert_string_equal(apply(SEC_ROOM, 0, "shelf", "unit"), "");
    assert_string_equal(room.shelf, "tests/unit");  /* joined with the file's directory */
    assert_string_equal(apply(SEC_ROOM, 0, "picture", "unit/test_conf_key.c"), "");
    assert_string_equal(room.picture, "tests/unit/test_conf_key.c");
    /* the setter stores instead of the field copy */
    assert_string_equal(apply(SEC_LAMP, 1, "colours", "5"), "");
    assert_int_equal(room.lamps[1].colour_count, 10);
    assert_int_equal(room.lamps[1].set_calls, 1);
}

static void test_refusals(void **state)
{
    (void)state;
    expect(apply(SEC_LAMP, 0, "watts", "0"), "key 'watts' in [lamp desk]: expected a number > 0 and <= 100, "
                                             "got \"0\": a bulb draws at most 100 W");
    /* the same name has its own range for another type */
    expect(apply(SEC_LAMP, 1, "watts", "60"), "expected a number > 0 and <= 20, got \"60\"");
    expect(apply(SEC_LAMP, 0, "watts", "2e6"), "got \"2e6\" (no lamp is that large)");
    expect(apply(SEC_LAMP, 0, "watts", "0x10"), "got \"0x10\"");
    expect(apply(SEC_LAMP, 0, "watts", "60 # W"), "(a comment after a value starts with ' ;', not '#')");
    expect(apply(SEC_LAMP, 0, "watts", ""), "key 'watts' in [lamp desk] has an empty value");
    expect(apply(SEC_ROOM, 0, "title", ""), "key 'title' in [room] has an empty value");
    expect(apply(SEC_ROOM, 0, "tint", "0.5 0 2"), "expected 3 numbers \"r g b\", each from 0 to 1");
    expect(apply(SEC_ROOM, 0, "mode", "dark"), "expected one of dim, bright, got \"dark\"");
    expect(apply(SEC_LAMP, 0, "usb_id", "1917"), "written with 0x");
    expect(apply(SEC_LAMP, 0, "usb_id", "0x10000"), "from 0x0000 to 0xffff");
    expect(apply(SEC_LAMP, 0, "serial", "2000000000000"), "expected an integer from -1000000000000 to 1000000000000");
    expect(apply(SEC_LAMP, 0, "aim", "0 0 0"), "3 numbers \"x y z\", not all zero");
    expect(apply(SEC_LAMP, 0, "word", "two words"), "1 to 15 characters without blanks");
    expect(apply(SEC_LAMP, 0, "ref", "desk.2"), "a section name: 1 to 15 letters, digits, '_' or '-'");
    expect(apply(SEC_ROOM, 0, "shelf", "test_conf_key.c"), "no directory \"tests/test_conf_key.c\"");
    expect(apply(SEC_ROOM, 0, "shelf", "test_conf_key.c"), "(relative paths start at the room)");
    expect(apply(SEC_ROOM, 0, "picture", "unit"), "\"tests/unit\" is not a regular file");
    expect(apply(SEC_ROOM, 0, "picture", "a-path-longer-than-sixty-four-bytes-with-its-directory-and-more"),
           "a path of 1 to 63 characters");
    expect(apply(SEC_LAMP, 1, "colours", "13"), "key 'colours' in [lamp hall]: 13 colours bring bad luck");
    assert_int_equal(room.lamps[1].set_calls, 0);
    /* a refused value leaves the field as it was */
    assert_true(room.lamps[0].watts == 0.0 && room.lamps[0].usb_id == 0);
}

static void test_keys_and_types(void **state)
{
    (void)state;
    expect(apply(SEC_LAMP, 0, "colours", "3"),
           "key 'colours' in [lamp desk] does not apply to lamp type 'bulb' (only to led)");
    expect(apply(SEC_LAMP, 0, "wats", "3"), "unknown key 'wats' in [lamp desk] (did you mean 'watts'?)");
    expect(apply(SEC_ROOM, 0, "titel", "x"), "unknown key 'titel' in [room] (did you mean 'title'?)");
    expect(apply(SEC_ROOM, 0, "watts", "3"), "unknown key 'watts' in [room]");
    assert_null(strstr(apply(SEC_ROOM, 0, "zzzzzzzz", "3"), "did you mean"));
    assert_null(conf_key_for(&table, &room, SEC_LAMP, 0, "colours"));
    const struct conf_key *k = conf_key_for(&table, &room, SEC_LAMP, 1, "watts");
    assert_non_null(k);
    assert_true(k->hi == 20.0);
    assert_int_equal(conf_key_find(&table, SEC_LAMP, "watts"), 8);
    assert_int_equal(conf_key_find(&table, SEC_ROOM, "watts"), -1);
}

static void test_required_and_numbers(void **state)
{
    (void)state;
    struct error e;
    const char *msg = e.message;
    int key_line[16] = {0};
    assert_int_equal(conf_key_check_required(&table, &room, SEC_LAMP, 0, key_line, &e), -1);
    assert_string_equal(msg, "[lamp desk] has no type: add 'type = bulb', 'led' or 'arc'");
    key_line[conf_key_find(&table, SEC_LAMP, "type")] = 3;
    /* a bulb needs no watts, a LED does */
    assert_int_equal(conf_key_check_required(&table, &room, SEC_LAMP, 0, key_line, &e), 0);
    assert_int_equal(conf_key_check_required(&table, &room, SEC_LAMP, 1, key_line, &e), -1);
    assert_string_equal(msg, "[lamp hall] of type 'led' needs 'watts'");
    key_line[conf_key_find(&table, SEC_LAMP, "watts")] = 4;
    assert_int_equal(conf_key_check_required(&table, &room, SEC_LAMP, 1, key_line, &e), 0);
    assert_int_equal(conf_key_check_required(&table, &room, SEC_ROOM, 0, key_line, &e), 0);
    assert_int_equal(conf_key_apply_number(&table, &room, SEC_LAMP, 0, "watts", 40.0, &e), 0);
    assert_true(room.lamps[0].watts == 40.0);
    assert_int_equal(conf_key_apply_number(&table, &room, SEC_LAMP, 0, "watts", NAN, &e), -1);
    expect(msg, "(not a finite number)");
    assert_int_equal(conf_key_apply_number(&table, &room, SEC_LAMP, 0, "watts", 1e-320, &e), -1);
    expect(msg, "(too large or too small for a double)");
    assert_int_equal(conf_key_apply_number(&table, &room, SEC_LAMP, 0, "watts", 101.0, &e), -1);
    expect(msg, "expected a number > 0 and <= 100, got 101");
    assert_int_equal(conf_key_apply_number(&table, &room, SEC_LAMP, 0, "serial", 1.0, &e), -1);
    expect(msg, "key 'serial' in [lamp desk] is not a number");
    assert_true(room.lamps[0].watts == 40.0);
}

/* Relative paths start at the directory of the file that names them, for both file kinds. */
static void test_paths(void **state)
{
    (void)state;
    char dir[64], out[16];
    conf_path_dir("exhibit/scenes/a.scene", dir, sizeof dir);
    assert_string_equal(dir, "exhibit/scenes");
    conf_path_dir("a.scene", dir, sizeof dir);
    assert_string_equal(dir, ".");
    conf_path_dir("/a.scene", dir, sizeof dir);
    assert_string_equal(dir, "/");
    assert_int_equal(conf_path_join("/", "sky.png", out, sizeof out), 0);
    assert_string_equal(out, "/sky.png");
    assert_int_equal(conf_path_join(".", "sky.png", out, sizeof out), 0);
    assert_string_equal(out, "sky.png");
    assert_int_equal(conf_path_join("d", "/abs.png", out, sizeof out), 0);
    assert_string_equal(out, "/abs.png");
    assert_int_equal(conf_path_join("d", "sky.png", out, sizeof out), 0);
    assert_string_equal(out, "d/sky.png");
    /* 15 bytes and the NUL fit, 16 do not */
    assert_int_equal(conf_path_join("dd", "abcdefghijkl", out, sizeof out), 0);
    assert_int_equal(conf_path_join("dd", "abcdefghijklm", out, sizeof out), -1);
}

/* A scene and the kiosk's configuration word the same mistakes alike: they share the function. */
static void test_scene_and_kiosk_word_alike(void **state)
{
    (void)state;
    static struct scene s;
    static struct kiosk_config c;
    struct error scene_e, kiosk_e;
    const char *scene_msg = scene_e.message, *kiosk_msg = kiosk_e.message;
    scene_defaults(&s);
    kiosk_config_defaults(&c);
    assert_int_equal(scene_key_apply(&s, SECTION_RENDER, 0, "bound_radius", "", &scene_e), -1);
    assert_int_equal(kiosk_key_apply(&c, KSEC_SPEED, 0, "start", "", &kiosk_e), -1);
    expect(scene_msg, "key 'bound_radius' in [render] has an empty value");
    expect(kiosk_msg, "key 'start' in [speed] has an empty value");
    assert_string_equal(strstr(scene_msg, " has"), strstr(kiosk_msg, " has"));
    assert_int_equal(scene_key_apply(&s, SECTION_RENDER, 0, "bound_radius", "2 # two", &scene_e), -1);
    assert_int_equal(kiosk_key_apply(&c, KSEC_SPEED, 0, "start", "0.2 # two", &kiosk_e), -1);
    expect(scene_msg, "(a comment after a value starts with ' ;', not '#')");
    expect(kiosk_msg, "(a comment after a value starts with ' ;', not '#')");
    assert_int_equal(scene_key_apply(&s, SECTION_RENDER, 0, "bound_radus", "2", &scene_e), -1);
    assert_int_equal(kiosk_key_apply(&c, KSEC_SPEED, 0, "strat", "0.2", &kiosk_e), -1);
    assert_string_equal(scene_msg, "unknown key 'bound_radus' in [render] (did you mean 'bound_radius'?)");
    assert_string_equal(kiosk_msg, "unknown key 'strat' in [speed] (did you mean 'start'?)");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_kinds_store, setup),
        cmocka_unit_test_setup(test_refusals, setup),
        cmocka_unit_test_setup(test_keys_and_types, setup),
        cmocka_unit_test_setup(test_required_and_numbers, setup),
        cmocka_unit_test(test_paths),
        cmocka_unit_test(test_scene_and_kiosk_word_alike),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
