/* A scene's [quality]: parsed from the file, and held against comparisons that meet and miss it. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>
#include "results/quality.h"

static struct compare_result result(double differing_fraction, double exit_p99, double hit_p99)
{
    struct compare_result r;
    memset(&r, 0, sizeof r);
    r.outcome_fraction = differing_fraction;
    r.sky_angle.p99 = exit_p99;
    r.hit_relative.p99 = hit_p99;
    return r;
}

static void test_unstated_is_not_checked(void **state)
{
    (void)state;
    struct scene s;
    scene_defaults(&s);
    char report[256];
    struct compare_result r = result(0.5, 1.0, 1.0);
    assert_false(quality_stated(&s.quality));
    assert_int_equal(quality_check(&s.quality, &r, report, sizeof report), -1);
}

static void test_each_bound_counts(void **state)
{
    (void)state;
    struct quality_bound q = {0.1, 1e-3, 0.01};
    char report[512];
    struct compare_result all_met = result(0.0005, 9e-4, 0.009);
    assert_int_equal(quality_check(&q, &all_met, report, sizeof report), 0);
    assert_non_null(strstr(report, "exit p99 0.0009 rad <= 0.001 rad: met"));
    struct compare_result differing = result(0.002, 9e-4, 0.009);   /* 0.2% > 0.1% */
    assert_int_equal(quality_check(&q, &differing, report, sizeof report), 1);
    assert_non_null(strstr(report, "differing outcomes 0.2% > 0.1%: MISSED"));
    struct compare_result two = result(0.0005, 2e-3, 0.02);
    assert_int_equal(quality_check(&q, &two, report, sizeof report), 2);
    /* a bound at exactly the measured value is met */
    struct compare_result edge = result(0.001, 1e-3, 0.01);
    assert_int_equal(quality_check(&q, &edge, report, sizeof report), 0);
}

static void test_unstated_bound_and_empty_statistic(void **state)
{
    (void)state;
    struct quality_bound q = {-1.0, 1e-3, -1.0};
    char report[512];
    struct compare_result no_sky = result(0.9, NAN, 5.0);    /* only exit p99 is stated; no sky pixel */
    assert_int_equal(quality_check(&q, &no_sky, report, sizeof report), 0);
    assert_non_null(strstr(report, "no pixels to measure"));
    assert_null(strstr(report, "differing"));
    struct compare_result nan_hit = result(0.0, 1e-4, NAN);
    struct quality_bound h = {-1.0, -1.0, 0.01};
    assert_int_equal(quality_check(&h, &nan_hit, report, sizeof report), 0);
}

static void test_scene_file_states_quality(void **state)
{
    (void)state;
    const char *path = "build/test_quality.scene";
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs("[quality]\ndiffering_percent = 0.25\nexit_p99 = 2e-3\n", f);
    fclose(f);
    static struct scene s;
    struct error e;
    assert_int_equal(scene_load(&s, path, &e), 0);
    assert_true(quality_stated(&s.quality));
    assert_true(s.quality.differing_percent == 0.25);
    assert_true(s.quality.exit_p99 == 2e-3);
    assert_true(s.quality.hit_p99 < 0.0);
    assert_int_equal(scene_set(&s, "quality.hit_p99=101", &e), 0);
    assert_true(s.quality.hit_p99 == 101.0);
    assert_int_not_equal(scene_set(&s, "quality.exit_p99=4", &e), 0);    /* above pi */
    assert_int_not_equal(scene_set(&s, "quality.differing_percent=nan", &e), 0);
    remove(path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_unstated_is_not_checked),
        cmocka_unit_test(test_each_bound_counts),
        cmocka_unit_test(test_unstated_bound_and_empty_statistic),
        cmocka_unit_test(test_scene_file_states_quality),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
