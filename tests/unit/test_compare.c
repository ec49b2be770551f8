/* bentray compare: metrics between synthetic dumps whose errors are known exactly, the outcome
 * categories, refusal of dumps that cannot be compared, and a dump file round trip. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "results/compare.h"

static const double PI = 3.14159265358979323846;

/* cmocka 1.1.5 compares floats only in single precision: doubles get their own checks. */
static void check_near(double got, double want, double tol, const char *what)
{
    if (!(fabs(got - want) <= tol)) {
        print_error("%s: got %.17g, want %.17g (tolerance %g)\n", what, got, want, tol);
        fail();
    }
}

static void check_exact(double got, double want, const char *what)
{
    check_near(got, want, 0.0, what);
}

/* A w x h dump of n objects, every pixel sky looking along +z, black, sizes 2. */
static struct dump make_dump(int w, int h, int n_objects, const char *engine)
{
    struct dump d = {.width = w, .height = h, .n_objects = n_objects};
    snprintf(d.engine, sizeof d.engine, "%s", engine);
    snprintf(d.scene, sizeof d.scene, "synthetic");
    for (int i = 0; i < n_objects; i++)
        d.object_size[i] = 2.0f;
    d.records = calloc((size_t)w * h, sizeof *d.records);
    assert_non_null(d.records);
    for (int i = 0; i < w * h; i++) {
        d.records[i].outcome = DUMP_SKY;
        d.records[i].direction[2] = 1.0f;
        d.records[i].rgba[3] = 255;
    }
    return d;
}

static struct dump copy_dump(const struct dump *d, const char *engine)
{
    struct dump c = *d;
    snprintf(c.engine, sizeof c.engine, "%s", engine);
    size_t bytes = (size_t)d->width * d->height * sizeof *d->records;
    c.records = malloc(bytes);
    assert_non_null(c.records);
    memcpy(c.records, d->records, bytes);
    return c;
}

static void set_hit(struct dump_record *r, int object, float x, float y, float z)
{
    r->outcome = object;
    r->hit[0] = x;
    r->hit[1] = y;
    r->hit[2] = z;
}

static void compare_ok(const struct dump *a, const struct dump *b, struct compare_result *r)
{
    struct error e;
    if (compare_dumps(a, b, r, &e) != 0) {
        print_error("compare_dumps refused: %s\n", e.message);
        fail();
    }
}

static void test_identical(void **state)
{
    (void)state;
    struct dump b = make_dump(4, 3, 2, "cpu");
    for (int i = 0; i < 6; i++)
        set_hit(&b.records[i], i % 2, 0.5f * i, -1.0f, 3.0f);
    for (int i = 0; i < 12; i++)
        b.records[i].rgba[0] = (uint8_t)(20 * i);
    struct dump a = copy_dump(&b, "gpu fp32");
    struct compare_result r;
    compare_ok(&a, &b, &r);
    assert_int_equal(r.pixels, 12);
    assert_int_equal(r.outcomes.differ, 0);
    check_exact(r.outcome_fraction, 0.0, "outcome fraction");
    assert_int_equal(r.hit.count, 6);
    check_exact(r.hit.mean, 0.0, "hit mean");
    check_exact(r.hit.max, 0.0, "hit max");
    check_exact(r.hit_relative.p99, 0.0, "relative hit p99");
    assert_int_equal(r.sky_angle.count, 6);
    check_exact(r.sky_angle.max, 0.0, "sky angle max");
    assert_true(isinf(r.psnr_db) && r.psnr_db > 0);
    assert_int_equal(r.image_identical, 1);
    for (int c = 0; c < 3; c++)
        check_exact(r.mean_abs_diff[c], 0.0, "mean abs diff");
    assert_string_equal(r.engine_a, "gpu fp32");
    assert_string_equal(r.engine_b, "cpu");
    assert_string_equal(r.scene, "synthetic");
    dump_free(&a);
    dump_free(&b);
}

/* 100 hits on object 0 (size 2), offsets (3k, 4k, 0) = distance 5k for k = 1..100 in a scrambled
 * order: mean 252.5, nearest-rank p99 the 99th value 495 (interpolation would give 495.05), max 500. */
static void test_hit_offsets(void **state)
{
    (void)state;
    struct dump b = make_dump(10, 10, 1, "cpu");
    struct dump a = make_dump(10, 10, 1, "gpu");
    for (int i = 0; i < 100; i++) {
        float k = (float)((i * 37) % 100 + 1); /* 37 is prime to 100: a permutation of 1..100 */
        set_hit(&b.records[i], 0, 1.0f, 2.0f, 3.0f);
        set_hit(&a.records[i], 0, 1.0f + 3.0f * k, 2.0f + 4.0f * k, 3.0f);
    }
    struct compare_result r;
    compare_ok(&a, &b, &r);
    assert_int_equal(r.hit.count, 100);
    assert_int_equal(r.hit.non_finite, 0);
    check_exact(r.hit.mean, 252.5, "hit mean");
    check_exact(r.hit.p99, 495.0, "hit p99");
    check_exact(r.hit.max, 500.0, "hit max");
    check_exact(r.hit_relative.mean, 126.25, "relative hit mean");
    check_exact(r.hit_relative.p99, 247.5, "relative hit p99");
    check_exact(r.hit_relative.max, 250.0, "relative hit max");
    assert_int_equal(r.sky_angle.count, 0);
    assert_true(isnan(r.sky_angle.mean) && isnan(r.sky_angle.p99) && isnan(r.sky_angle.max));
    dump_free(&a);
    dump_free(&b);
}

/* Nearest rank with few values: p99 of 10 values is the largest (rank ceil(9.9) = 10). */
static void test_p99_few_values(void **state)
{
    (void)state;
    struct dump b = make_dump(10, 1, 1, "cpu");
    struct dump a = make_dump(10, 1, 1, "gpu");
    for (int i = 0; i < 10; i++) {
        set_hit(&b.records[i], 0, 0.0f, 0.0f, 0.0f);
        set_hit(&a.records[i], 0, 0.0f, 0.0f, (float)(9 - i) * 0.5f);
    }
    struct compare_result r;
    compare_ok(&a, &b, &r);
    check_exact(r.hit.p99, 4.5, "p99 of 10 values");
    check_exact(r.hit.mean, 2.25, "mean of 10 values");
    dump_free(&a);
    dump_free(&b);
}

/* Right, half-right, opposite and ~1e-9 rad between final directions; (1, 1, 0) is not unit
 * length on purpose, the angle must not depend on it. */
static void test_sky_angles(void **state)
{
    (void)state;
    static const float dir_a[4][3] = {{0, 1, 0}, {1, 1, 0}, {-1, 0, 0}, {1, 1e-9f, 0}};
    static const float dir_b[4][3] = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}};
    struct dump b = make_dump(2, 2, 0, "cpu");
    struct dump a = make_dump(2, 2, 0, "gpu");
    for (int i = 0; i < 4; i++) {
        memcpy(a.records[i].direction, dir_a[i], sizeof dir_a[i]);
        memcpy(b.records[i].direction, dir_b[i], sizeof dir_b[i]);
    }
    struct compare_result r;
    compare_ok(&a, &b, &r);
    double tiny = (double)1e-9f;
    assert_int_equal(r.sky_angle.count, 4);
    check_near(r.sky_angle.mean, (PI / 2 + PI / 4 + PI + tiny) / 4, 1e-15, "angle mean");
    check_exact(r.sky_angle.p99, PI, "angle p99");
    check_exact(r.sky_angle.max, PI, "angle max");
    dump_free(&a);
    dump_free(&b);
}

/* At 1e-9 rad acos(cos) is 0: the metric must still see the angle. */
static void test_tiny_angle(void **state)
{
    (void)state;
    struct dump b = make_dump(1, 1, 0, "cpu");
    struct dump a = make_dump(1, 1, 0, "gpu");
    float s = (float)sin(1e-9), c = (float)cos(1e-9);
    a.records[0].direction[0] = 0.0f;
    a.records[0].direction[1] = s;
    a.records[0].direction[2] = c;
    double naive = acos((double)c); /* what the acos formula would report */
    check_exact(naive, 0.0, "acos of the float cosine (the test's premise)");
    struct compare_result r;
    compare_ok(&a, &b, &r);
    check_near(r.sky_angle.mean, 1e-9, 1e-9 * 1e-6, "tiny angle");
    check_exact(r.sky_angle.max, r.sky_angle.mean, "one value: max = mean");
    check_exact(r.sky_angle.p99, r.sky_angle.mean, "one value: p99 = mean");
    dump_free(&a);
    dump_free(&b);
}

/* One red byte off by 10 in 100 pixels: MSE over R, G, B = 100 / 300, PSNR = 10 log10(3 * 255^2). */
static void test_psnr(void **state)
{
    (void)state;
    struct dump b = make_dump(10, 10, 0, "cpu");
    for (int i = 0; i < 100; i++)
        memcpy(b.records[i].rgba, (uint8_t[4]){(uint8_t)i, (uint8_t)(2 * i), 200, 255}, 4);
    struct dump a = copy_dump(&b, "gpu");
    a.records[42].rgba[0] += 10;
    a.records[7].rgba[3] = 0; /* alpha is not part of the image metrics */
    struct compare_result r;
    compare_ok(&a, &b, &r);
    check_near(r.psnr_db, 52.90201615587573, 1e-12, "PSNR");
    assert_int_equal(r.image_identical, 0);
    check_exact(r.mean_abs_diff[0], 0.1, "mean |dR|");
    check_exact(r.mean_abs_diff[1], 0.0, "mean |dG|");
    check_exact(r.mean_abs_diff[2], 0.0, "mean |dB|");
    a.records[42].rgba[0] -= 10;
    compare_ok(&a, &b, &r);
    assert_true(isinf(r.psnr_db));
    assert_int_equal(r.image_identical, 1);
    dump_free(&a);
    dump_free(&b);
}

/* Each differing pair falls in exactly one category, the first that fits. */
static void test_outcome_categories(void **state)
{
    (void)state;
    enum { SAME, FAIL_A, FAIL_B, CAPTURED, OTHER, OBJ_SKY, UNFIN };
    static const int32_t pairs[16][3] = {
        {0, 0, SAME},
        {DUMP_SKY, DUMP_SKY, SAME},
        {0, 1, OTHER},
        {2, 0, OTHER},
        {0, DUMP_SKY, OBJ_SKY},
        {DUMP_SKY, 1, OBJ_SKY},
        {DUMP_UNFINISHED, 2, OBJ_SKY},
        {DUMP_CAPTURED, DUMP_SKY, CAPTURED},
        {0, DUMP_CAPTURED, CAPTURED},
        {DUMP_CAPTURED, DUMP_UNFINISHED, CAPTURED},
        {DUMP_FAILED, DUMP_CAPTURED, FAIL_A},
        {DUMP_FAILED, 0, FAIL_A},
        {DUMP_SKY, DUMP_FAILED, FAIL_B},
        {DUMP_UNFINISHED, DUMP_SKY, UNFIN},
        {DUMP_SKY, DUMP_UNFINISHED, UNFIN},
        {DUMP_FAILED, DUMP_FAILED, SAME},
    };
    struct dump a = make_dump(4, 4, 3, "gpu"), b = make_dump(4, 4, 3, "cpu");
    long want[7] = {0};
    for (int i = 0; i < 16; i++) {
        a.records[i].outcome = pairs[i][0];
        b.records[i].outcome = pairs[i][1];
        want[pairs[i][2]]++;
    }
    struct compare_result r;
    compare_ok(&a, &b, &r);
    assert_int_equal(r.outcomes.differ, 16 - want[SAME]);
    assert_int_equal(r.outcomes.failed_a, want[FAIL_A]);
    assert_int_equal(r.outcomes.failed_b, want[FAIL_B]);
    assert_int_equal(r.outcomes.captured_vs_escaped, want[CAPTURED]);
    assert_int_equal(r.outcomes.other_object, want[OTHER]);
    assert_int_equal(r.outcomes.object_vs_sky, want[OBJ_SKY]);
    assert_int_equal(r.outcomes.unfinished, want[UNFIN]);
    assert_int_equal(want[FAIL_A] + want[FAIL_B] + want[CAPTURED] + want[OTHER] + want[OBJ_SKY] + want[UNFIN], 13);
    check_exact(r.outcome_fraction, 13.0 / 16.0, "outcome fraction");
    assert_int_equal(r.hit.count, 1);
    assert_int_equal(r.sky_angle.count, 1);
    dump_free(&a);
    dump_free(&b);
}

/* A non-finite hit point is counted apart and does not poison mean, p99 and max. */
static void test_non_finite_error(void **state)
{
    (void)state;
    struct dump b = make_dump(2, 1, 1, "cpu"), a = make_dump(2, 1, 1, "gpu");
    set_hit(&b.records[0], 0, 0, 0, 0);
    set_hit(&b.records[1], 0, 0, 0, 0);
    set_hit(&a.records[0], 0, 0, 0, 1.5f);
    set_hit(&a.records[1], 0, NAN, 0, 0);
    struct compare_result r;
    compare_ok(&a, &b, &r);
    assert_int_equal(r.hit.count, 1);
    assert_int_equal(r.hit.non_finite, 1);
    check_exact(r.hit.max, 1.5, "finite max");
    dump_free(&a);
    dump_free(&b);
}

static void expect_refusal(const struct dump *a, const struct dump *b, const char *word)
{
    struct compare_result r;
    struct error e;
    assert_int_equal(compare_dumps(a, b, &r, &e), -1);
    assert_int_equal(e.status, ERROR_INPUT);
    assert_string_equal(e.where, "");
    if (!strstr(e.message, word)) {
        print_error("message '%s' does not mention '%s'\n", e.message, word);
        fail();
    }
}

static void test_incompatible(void **state)
{
    (void)state;
    struct dump b = make_dump(4, 3, 2, "cpu");
    struct dump a = make_dump(3, 4, 2, "gpu");
    expect_refusal(&a, &b, "size 3x4");
    dump_free(&a);
    a = copy_dump(&b, "gpu");
    snprintf(a.scene, sizeof a.scene, "lorenz");
    expect_refusal(&a, &b, "scene 'lorenz'");
    snprintf(a.scene, sizeof a.scene, "%s", b.scene);
    a.n_objects = 1;
    expect_refusal(&a, &b, "1 objects");
    a.n_objects = 2;
    a.records[5].outcome = 2; /* only objects 0 and 1 exist */
    expect_refusal(&a, &b, "pixel (1, 1) has outcome 2");
    a.records[5].outcome = -5;
    expect_refusal(&a, &b, "outcome -5");
    a.records[5].outcome = DUMP_SKY;
    b.object_size[1] = 0.0f;
    expect_refusal(&a, &b, "reference dump: object 1 has size 0");
    b.object_size[1] = NAN;
    expect_refusal(&a, &b, "object 1");
    dump_free(&a);
    dump_free(&b);
}

/* The printers: JSON keys stable, infinite PSNR as null beside "identical": true. */
static void test_print(void **state)
{
    (void)state;
    struct dump b = make_dump(2, 2, 1, "cpu \"ref\"");
    struct dump a = copy_dump(&b, "gpu");
    struct compare_result r;
    compare_ok(&a, &b, &r);
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    assert_non_null(f);
    compare_print_json(f, &r);
    fclose(f);
    assert_non_null(strstr(text, "\"psnr_db\": null, \"identical\": true"));
    assert_non_null(strstr(text, "\"engine_b\": \"cpu \\\"ref\\\"\""));
    assert_non_null(strstr(text, "\"hit_error\": {\"count\": 0, \"non_finite\": 0, \"mean\": null"));
    assert_non_null(strstr(text, "\"sky_angle\": {\"count\": 4, \"non_finite\": 0, \"mean\": 0, \"p99\": 0"));
    assert_non_null(strstr(text, "\"outcomes\": {\"differ\": 0, \"fraction\": 0,"));
    free(text);
    f = open_memstream(&text, &len);
    assert_non_null(f);
    compare_print_table(f, &r);
    fclose(f);
    assert_non_null(strstr(text, "image: identical"));
    free(text);
    dump_free(&a);
    dump_free(&b);
}

/* The v2 fields (colour, scene name, object sizes) survive dump_write and dump_read. */
static void test_file_round_trip(void **state)
{
    (void)state;
    char dir[] = "/tmp/bentray_compare_XXXXXX", path[64];
    struct error err;
    assert_non_null(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/t.dump", dir);
    struct dump d = make_dump(3, 2, 3, "cpu dopri5 rtol 1e-10");
    snprintf(d.scene, sizeof d.scene, "schwarzschild");
    d.object_size[0] = 0.25f, d.object_size[1] = 7.5f, d.object_size[2] = 1e-3f;
    for (int i = 0; i < 6; i++) {
        set_hit(&d.records[i], i % 3 - 1, 0.1f * i, -2.0f, 1e-7f * i);
        memcpy(d.records[i].rgba, (uint8_t[4]){(uint8_t)(40 * i), 255, (uint8_t)i, (uint8_t)(250 - i)}, 4);
        d.records[i].steps = 1000u * i;
        d.records[i].depth = 0.5f + i;
    }
    assert_int_equal(dump_write(path, &d, 0, &err), 0);
    struct dump e;
    assert_int_equal(dump_read(path, &e, &err), 0);
    assert_int_equal(e.width, 3);
    assert_int_equal(e.height, 2);
    assert_string_equal(e.engine, d.engine);
    assert_string_equal(e.scene, "schwarzschild");
    assert_int_equal(e.n_objects, 3);
    assert_memory_equal(e.object_size, d.object_size, 3 * sizeof(float));
    assert_memory_equal(e.records, d.records, 6 * sizeof *d.records);
    struct compare_result r;
    compare_ok(&e, &d, &r);
    assert_int_equal(r.image_identical, 1);
    dump_free(&e);
    dump_free(&d);
    unlink(path);
    assert_int_equal(rmdir(dir), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_identical),
        cmocka_unit_test(test_hit_offsets),
        cmocka_unit_test(test_p99_few_values),
        cmocka_unit_test(test_sky_angles),
        cmocka_unit_test(test_tiny_angle),
        cmocka_unit_test(test_psnr),
        cmocka_unit_test(test_outcome_categories),
        cmocka_unit_test(test_non_finite_error),
        cmocka_unit_test(test_incompatible),
        cmocka_unit_test(test_print),
        cmocka_unit_test(test_file_round_trip),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
