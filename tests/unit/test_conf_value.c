/* The values every configuration reads alike (conf/conf_value.h): numbers, integers, ranges and
 * choices, and their words in messages; then the same values given to a scene key and to a kiosk
 * key, which must agree on each: both readers take their numbers from here. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "kiosk_config/kiosk_config.h"
#include "conf/conf_value.h"
#include "kiosk_config/kiosk_config_keys.h"
#include "scene/scene_keys.h"

static void test_numbers(void **state)
{
    (void)state;
    double x[3];
    const char *why = NULL;
    assert_int_equal(conf_parse_numbers("0.5", x, 1, &why), 0);
    assert_true(x[0] == 0.5);
    assert_int_equal(conf_parse_numbers("  -1.5e2 ", x, 1, &why), 0);
    assert_true(x[0] == -150.0);
    assert_int_equal(conf_parse_numbers("1 2\t3", x, 3, &why), 0);
    assert_true(x[0] == 1.0 && x[1] == 2.0 && x[2] == 3.0);
    assert_null(why);
    /* the form: wrong count, separators, trailing garbage, hexadecimal floats and integers */
    static const char *const malformed[] = {"", " ", "1 2", "1,2", "0.5,", "120 s", "0x1p-1", "-0X10", "+0x1",
                                            "abc", "1e", "--1"};
    for (size_t i = 0; i < sizeof malformed / sizeof malformed[0]; i++) {
        why = NULL;
        assert_int_equal(conf_parse_numbers(malformed[i], x, 1, &why), -1);
        assert_null(why);
    }
    assert_int_equal(conf_parse_numbers("1 2", x, 3, &why), -1);
    /* beyond the form: not finite, out of a double's range (a denormal too) */
    static const char *const out_of_range[] = {"inf", "-infinity", "nan", "1e400", "-1e400", "1e-320", "4e-324"};
    for (size_t i = 0; i < sizeof out_of_range / sizeof out_of_range[0]; i++) {
        why = NULL;
        assert_int_equal(conf_parse_numbers(out_of_range[i], x, 1, &why), -1);
        assert_non_null(why);
    }
    /* the smallest normal double is a number */
    assert_int_equal(conf_parse_numbers("2.2250738585072014e-308", x, 1, &why), 0);
}

static void test_integers(void **state)
{
    (void)state;
    long long v;
    assert_int_equal(conf_parse_integer("42", &v), 0);
    assert_true(v == 42);
    assert_int_equal(conf_parse_integer("-7 ", &v), 0);
    assert_true(v == -7);
    static const char *const bad[] = {"", "+5", " 5", "0x10", "5.0", "1e3", "5 6", "-", "99999999999999999999"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        assert_int_equal(conf_parse_integer(bad[i], &v), -1);
}

static void test_ranges(void **state)
{
    (void)state;
    assert_true(conf_in_range(0.0, 0.0, 1.0, 0));
    assert_false(conf_in_range(0.0, 0.0, 1.0, CONF_ABOVE_LO));
    assert_true(conf_in_range(1.0, 0.0, 1.0, CONF_ABOVE_LO));
    assert_false(conf_in_range(1.0, 0.0, 1.0, CONF_BELOW_HI));
    assert_false(conf_in_range(NAN, -INFINITY, INFINITY, 0));
    char buf[96];
    conf_describe_range(0.0, 1.0, 0, buf, sizeof buf);
    assert_string_equal(buf, " from 0 to 1");
    conf_describe_range(0.0, 10.0, CONF_ABOVE_LO | CONF_BELOW_HI, buf, sizeof buf);
    assert_string_equal(buf, " > 0 and < 10");
    conf_describe_range(0.0, INFINITY, CONF_ABOVE_LO, buf, sizeof buf);
    assert_string_equal(buf, " > 0");
    conf_describe_range(-INFINITY, 5.0, 0, buf, sizeof buf);
    assert_string_equal(buf, " <= 5");
    conf_describe_range(-INFINITY, INFINITY, 0, buf, sizeof buf);
    assert_string_equal(buf, "");
}

static void test_choices_and_quotes(void **state)
{
    (void)state;
    static const char *const names[] = {"euler", "rk4", "dopri5", NULL};
    assert_int_equal(conf_choice_find(names, "rk4"), 1);
    assert_int_equal(conf_choice_find(names, "RK4"), -1);
    assert_int_equal(conf_choice_find(names, ""), -1);
    char buf[128];
    conf_describe_choices(names, buf, sizeof buf);
    assert_string_equal(buf, "one of euler, rk4, dopri5");
    conf_quote("abc", buf, sizeof buf);
    assert_string_equal(buf, "\"abc\"");
    char longer[200];
    memset(longer, 'y', sizeof longer - 1);
    longer[sizeof longer - 1] = '\0';
    conf_quote(longer, buf, sizeof buf);
    assert_int_equal(strlen(buf), CONF_QUOTE_MAX + 5);
    assert_string_equal(buf + CONF_QUOTE_MAX + 1, "...\"");
}

/* One value for [render] bound_radius of a scene (> 0) and for [speed] start of the kiosk
 * configuration (0 to its top): accepted by both or by neither, with the same words. */
static void test_scene_and_kiosk_agree(void **state)
{
    (void)state;
    static const struct {
        const char *value;
        int ok;
    } cases[] = {
        {"0.5", 1}, {"5e-1", 1}, {".5", 1}, {"+0.5", 1}, {"0.5 ", 1},
        {"0x1p-1", 0}, {"0X.8", 0}, {"1e-320", 0}, {"inf", 0}, {"nan", 0}, {"0.5,", 0}, {"0.5 0.5", 0},
        {"half", 0}, {"1e400", 0},
    };
    static struct scene s;
    static struct kiosk_config c;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        struct error scene_e, kiosk_e;
        const char *scene_msg = scene_e.message, *kiosk_msg = kiosk_e.message;
        scene_defaults(&s);
        kiosk_config_defaults(&c);
        int scene_rc = scene_key_apply(&s, SECTION_RENDER, 0, "bound_radius", cases[i].value, &scene_e);
        int kiosk_rc = kiosk_key_apply(&c, KSEC_SPEED, 0, "start", cases[i].value, &kiosk_e);
        print_message("\"%s\": scene %s, kiosk %s\n", cases[i].value, scene_rc == 0 ? "ok" : scene_msg,
                      kiosk_rc == 0 ? "ok" : kiosk_msg);
        assert_int_equal(scene_rc, cases[i].ok ? 0 : -1);
        assert_int_equal(kiosk_rc, cases[i].ok ? 0 : -1);
        if (cases[i].ok) {
            assert_true(s.render.bound_radius == 0.5);
            assert_true(c.speed.start == 0.5);
        } else {
            /* the same value quoted the same way, and the same reason beyond the form, if any */
            char quoted[CONF_QUOTE_MAX + 8];
            conf_quote(cases[i].value, quoted, sizeof quoted);
            assert_non_null(strstr(scene_msg, quoted));
            assert_non_null(strstr(kiosk_msg, quoted));
            const char *scene_why = strstr(scene_msg, quoted) + strlen(quoted);
            const char *kiosk_why = strstr(kiosk_msg, quoted) + strlen(quoted);
            int scene_has = strncmp(scene_why, " (", 2) == 0, kiosk_has = strncmp(kiosk_why, " (", 2) == 0;
            assert_int_equal(scene_has, kiosk_has);
            if (scene_has)
                assert_memory_equal(scene_why, kiosk_why, strcspn(scene_why, ")"));
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_numbers),
        cmocka_unit_test(test_integers),
        cmocka_unit_test(test_ranges),
        cmocka_unit_test(test_choices_and_quotes),
        cmocka_unit_test(test_scene_and_kiosk_agree),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
