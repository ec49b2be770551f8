/* Error metrics between two per-pixel dumps of the same scene: a configuration under test (a)
 * against a reference (b). Definitions and JSON keys in docs/ERRORS.md. */
#ifndef BT_COMPARE_H
#define BT_COMPARE_H
#include "results/dump.h"
#include <stdio.h>

/* One error over the pixels it applies to. Mean, 99th percentile (nearest rank: the value at
 * rank ceil(0.99 n) of the n sorted errors) and maximum of the finite errors; with count 0 they
 * are NAN (nothing measured). Non-finite errors (a hit point or direction that is not finite)
 * would swamp every statistic, so they are counted apart. */
struct compare_stats {
    long count;        /* pixels with a finite error */
    long non_finite;   /* pixels where the error is not finite, left out of mean, p99, max */
    double mean, p99, max;
};

/* Pixels whose outcome differs, split into categories that do not overlap: each differing pixel
 * falls in the first category that fits, in this order, so the categories add up to differ. */
struct compare_outcomes {
    long differ;               /* outcome of a != outcome of b */
    long failed_a;             /* a failed (non-finite state) */
    long failed_b;             /* the reference failed */
    long captured_vs_escaped;  /* one captured by the horizon, the other not */
    long other_object;         /* both hit an object, different ones */
    long object_vs_sky;        /* one hit an object, the other reached the sky or is unfinished */
    long unfinished;           /* one unfinished, the other reached the sky */
};

struct compare_result {
    char scene[32];
    char engine_a[32];                 /* under test */
    char engine_b[32];                 /* reference */
    int width, height;
    long pixels;                       /* width * height */
    struct compare_outcomes outcomes;
    double outcome_fraction;           /* outcomes.differ / pixels */
    struct compare_stats hit;          /* |hit_a - hit_b|, scene units, both on the same object */
    struct compare_stats hit_relative; /* the same divided by the object's size (from b) */
    struct compare_stats sky_angle;    /* radians between the final directions, both sky */
    double psnr_db;                    /* over R, G, B (alpha ignored), peak 255; INFINITY if identical */
    int image_identical;               /* every R, G, B byte equal */
    double mean_abs_diff[3];           /* mean |a - b| of R, G, B in 1/255 units (8-bit levels) */
};

/* Check one dump on its own: outcomes in range (-4 .. n_objects - 1), object sizes finite and
 * positive. 0 when usable, else -1 with the reason in e (ERROR_INPUT, no place: the caller knows
 * the dump's file). */
int compare_dump_check(const struct dump *d, struct error *e);

/* Compare a (under test) with b (reference). Returns 0 and fills r, or -1 with the reason in e
 * (no place) when the dumps cannot be compared: one fails compare_dump_check, or they differ in
 * size, scene name or object count (ERROR_INPUT), or there is no memory (ERROR_RUNTIME). */
int compare_dumps(const struct dump *a, const struct dump *b, struct compare_result *r, struct error *e);

/* JSON object with stable keys (docs/ERRORS.md); NAN statistics and an infinite PSNR are null. */
void compare_print_json(FILE *f, const struct compare_result *r);
/* A short table for people. */
void compare_print_table(FILE *f, const struct compare_result *r);

#endif
