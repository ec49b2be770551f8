/* The real sky ([sky] catalogue, physics/bright_stars.h): the Yale Bright Star Catalogue as Debian's
 * xplanet ships it, read whole; known stars at their galactic coordinates; colours from Marble's
 * B-V classes by HR number; every malformed line or colour record refused with its place. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "physics/bright_stars.h"

static const vec3d galactic_pole = {0.0, 0.0, 1.0}, galactic_centre = {1.0, 0.0, 0.0};

/* the star nearest direction d, and the angle to it in degrees */
static const struct star *nearest(const struct star *stars, int n, vec3d d, double *degrees)
{
    const struct star *best = NULL;
    double best_dot = -2.0;
    for (int i = 0; i < n; i++) {
        double c = v3_dot(stars[i].direction, d);
        if (c > best_dot) {
            best_dot = c;
            best = &stars[i];
        }
    }
    *degrees = acos(fmin(best_dot, 1.0)) * 180.0 / PI_D;
    return best;
}

static vec3d galactic(double l_deg, double b_deg)
{
    double l = l_deg * PI_D / 180.0, b = b_deg * PI_D / 180.0;
    return v3(cos(b) * cos(l), cos(b) * sin(l), sin(b));
}

/* The whole catalogue: 9096 stars (9102 lines less its comments), Sirius the brightest; with the
 * scene's galactic frame the identity, Sirius, Betelgeuse, Rigel and Vega at their galactic
 * coordinates (the IAU's l and b, J2000) within 0.05 degrees, each the nearest star there with its
 * catalogue magnitude. */
static void test_real_catalogue(void **state)
{
    (void)state;
    struct star *stars;
    int n;
    struct error err;
    if (bright_stars_read(BRIGHT_STARS_XPLANET_PATH, BRIGHT_STARS_MARBLE_PATH, galactic_pole, galactic_centre, &stars, &n,
                          &err) != 0)
        fail_msg("%s: %s", err.where, err.message);
    assert_int_equal(n, 9096);
    double brightest = 99.0;
    for (int i = 0; i < n; i++) {
        brightest = fmin(brightest, stars[i].magnitude);
        assert_true(fabs(v3_len(stars[i].direction) - 1.0) < 1e-12);
    }
    assert_true(brightest == -1.46);
    static const struct {
        const char *name;
        double l, b, magnitude;
    } known[] = {
        {"Sirius", 227.2303, -8.8903, -1.46},
        {"Betelgeuse", 199.7872, -8.9586, 0.50},
        {"Rigel", 209.2412, -25.2454, 0.12},
        {"Vega", 67.4482, 19.2372, 0.03},
    };
    for (size_t k = 0; k < sizeof known / sizeof known[0]; k++) {
        double degrees;
        const struct star *s = nearest(stars, n, galactic(known[k].l, known[k].b), &degrees);
        print_message("%-10s %.4f degrees from its galactic coordinates, magnitude %.2f, %.0f K\n", known[k].name,
                      degrees, s->magnitude, s->temperature);
        assert_true(degrees < 0.05);
        assert_true(s->magnitude == known[k].magnitude);
    }
    free(stars);
}

/* Colours by HR number from Marble's classes: Betelgeuse (class 5, B-V 1.85) red, Rigel (class 1,
 * B-V 0.00) blue-white, at the temperatures of their classes' B-V; a star Marble does not list,
 * and every star read without the colours, white. */
static void test_colours(void **state)
{
    (void)state;
    char path[] = "/tmp/bt_bsc_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    const char *text = "# Dec RA Mag Name HR\n"
                       "  7.4069  5.9195  0.50 \" 58Alp Ori\" 2061  39801 113271\n"
                       " -8.2017  5.2423  0.12 \" 19Bet Ori\" 1713\n"
                       "\n"
                       " 10.0     1.0     6.40 \"unlisted\" 9000\n"
                       " 20.0     2.0     3.00\n";
    assert_int_equal(write(fd, text, strlen(text)), (ssize_t)strlen(text));
    close(fd);
    struct star *stars;
    int n;
    struct error err;
    if (bright_stars_read(path, BRIGHT_STARS_MARBLE_PATH, galactic_pole, galactic_centre, &stars, &n, &err) != 0)
        fail_msg("%s: %s", err.where, err.message);
    assert_int_equal(n, 4);
    print_message("Betelgeuse %.0f K, Rigel %.0f K\n", stars[0].temperature, stars[1].temperature);
    assert_true(stars[0].temperature == star_temperature_of_bv(1.85) && stars[0].temperature < 3500.0);
    assert_true(stars[1].temperature == star_temperature_of_bv(0.0) && stars[1].temperature > 9500.0);
    assert_true(stars[2].temperature == BRIGHT_STAR_WHITE_K);
    assert_true(stars[3].temperature == BRIGHT_STAR_WHITE_K);
    free(stars);
    if (bright_stars_read(path, NULL, galactic_pole, galactic_centre, &stars, &n, &err) != 0)
        fail_msg("%s: %s", err.where, err.message);
    for (int i = 0; i < n; i++)
        assert_true(stars[i].temperature == BRIGHT_STAR_WHITE_K);
    free(stars);
    /* the B-V of a black body: hotter for bluer, the Sun's 0.65 about 5800 K */
    assert_true(fabs(star_temperature_of_bv(0.65) - 5800.0) < 150.0);
    unlink(path);
}

static void write_file(const char *path, const void *bytes, size_t n)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(bytes, 1, n, f), n);
    assert_int_equal(fclose(f), 0);
}

/* Every malformed line refused at its FILE:LINE, with what is wrong; nothing returned. */
static void test_refusals(void **state)
{
    (void)state;
    static const struct {
        const char *line, *message;
    } bad[] = {
        {"abc 1 2", "expected a star's declination"},
        {"10 5", "expected a star's declination"},
        {"95 5 1", "declination 95 is outside"},
        {"10 25 1", "right ascension 25 is outside"},
        {"10 5 40", "visual magnitude 40 is outside"},
        {"10 5 nan", "expected a star's declination"},
        {"10 0x5 1", "expected a star's declination"},
        {"10 5 1e999", "expected a star's declination"},
        {"10 5 1x", "after the magnitude"},
        {"10 5 1 \"open", "no closing quote"},
        {"10 5 1 \"name\" 0", "(HR) \"0\" is not one of"},
        {"10 5 1 \"name\" 12x", "(HR) \"12x\" is not one of"},
        {"10 5 1\r junk", "carriage return"},
    };
    char path[] = "/tmp/bt_bsc_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        char text[256], where[300];
        snprintf(text, sizeof text, "# a comment\n 1.0 2.0 3.0 \"good\" 17\n%s\n 4.0 5.0 6.0\n", bad[k].line);
        write_file(path, text, strlen(text));
        struct star *stars = (struct star *)&text;
        int n = -1;
        struct error err;
        assert_int_equal(bright_stars_read(path, NULL, galactic_pole, galactic_centre, &stars, &n, &err), -1);
        snprintf(where, sizeof where, "%s:3", path);
        if (err.status != ERROR_INPUT || strcmp(err.where, where) != 0 || !strstr(err.message, bad[k].message))
            fail_msg("line \"%s\": %s: %s", bad[k].line, err.where, err.message);
        assert_null(stars);
        assert_int_equal(n, 0);
    }
    /* Marble's colour file: its header, whole records, classes 0..6 */
    unsigned char record[8 + 32] = {'s', 't', 'a', 'r', 0, 0, 0, 4, 0, 0, 0x08, 0x0d};
    record[8 + 31] = 9;   /* colour class 9 */
    static const struct {
        size_t size;
        int magic_ok;
        const char *message;
    } colours[] = {
        {40, 0, "does not begin with \"star\""},
        {39, 1, "not whole records of 32 bytes"},
        {40, 1, "record 1 (byte 8): colour class 9 is not one of 0..6"},
    };
    for (size_t k = 0; k < sizeof colours / sizeof colours[0]; k++) {
        record[0] = colours[k].magic_ok ? 's' : 'S';
        write_file(path, record, colours[k].size);
        int n;
        struct error err;
        assert_int_equal(bright_stars_read(NULL, path, galactic_pole, galactic_centre, NULL, &n, &err), -1);
        if (err.status != ERROR_INPUT || strcmp(err.where, path) != 0 || !strstr(err.message, colours[k].message))
            fail_msg("colours %zu: %s: %s", k, err.where, err.message);
    }
    record[8 + 31] = 6;
    write_file(path, record, sizeof record);
    int n;
    struct error err;
    assert_int_equal(bright_stars_read(NULL, path, galactic_pole, galactic_centre, NULL, &n, &err), 0);
    unlink(path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_real_catalogue),
        cmocka_unit_test(test_colours),
        cmocka_unit_test(test_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
