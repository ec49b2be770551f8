/* compare_result as JSON (stable keys, docs/ERRORS.md) and as a short table for people. */
#include "results/compare.h"
#include <math.h>

/* JSON string: names come from files, so quotes, backslashes and control bytes are escaped. */
static void json_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\')
            fprintf(f, "\\%c", c);
        else if (c < 0x20)
            fprintf(f, "\\u%04x", c);
        else
            fputc(c, f);
    }
    fputc('"', f);
}

/* JSON has no NaN or infinity: those are null, and the surrounding keys say why. */
static void json_number(FILE *f, double v)
{
    if (isfinite(v))
        fprintf(f, "%.9g", v);
    else
        fputs("null", f);
}

static void json_stats(FILE *f, const char *key, const struct compare_stats *s, const char *after)
{
    fprintf(f, "  \"%s\": {\"count\": %ld, \"non_finite\": %ld, \"mean\": ", key, s->count, s->non_finite);
    json_number(f, s->mean);
    fputs(", \"p99\": ", f);
    json_number(f, s->p99);
    fputs(", \"max\": ", f);
    json_number(f, s->max);
    fprintf(f, "}%s\n", after);
}

static void json_outcomes(FILE *f, const struct compare_result *r)
{
    const struct compare_outcomes *o = &r->outcomes;
    fprintf(f, "  \"outcomes\": {\"differ\": %ld, \"fraction\": ", o->differ);
    json_number(f, r->outcome_fraction);
    fprintf(f, ", \"failed_a\": %ld, \"failed_b\": %ld, \"captured_vs_escaped\": %ld, \"other_object\": %ld, "
               "\"object_vs_sky\": %ld, \"unfinished\": %ld},\n",
            o->failed_a, o->failed_b, o->captured_vs_escaped, o->other_object, o->object_vs_sky, o->unfinished);
}

static void json_image(FILE *f, const struct compare_result *r)
{
    fputs("  \"image\": {\"psnr_db\": ", f);
    json_number(f, r->psnr_db);
    fprintf(f, ", \"identical\": %s, \"mean_abs_diff\": [", r->image_identical ? "true" : "false");
    for (int c = 0; c < 3; c++) {
        json_number(f, r->mean_abs_diff[c]);
        fputs(c < 2 ? ", " : "]}\n", f);
    }
}

void compare_print_json(FILE *f, const struct compare_result *r)
{
    fputs("{\n  \"scene\": ", f);
    json_string(f, r->scene);
    fputs(",\n  \"engine_a\": ", f);
    json_string(f, r->engine_a);
    fputs(",\n  \"engine_b\": ", f);
    json_string(f, r->engine_b);
    fprintf(f, ",\n  \"width\": %d,\n  \"height\": %d,\n  \"pixels\": %ld,\n", r->width, r->height, r->pixels);
    json_outcomes(f, r);
    json_stats(f, "hit_error", &r->hit, ",");
    json_stats(f, "hit_error_relative", &r->hit_relative, ",");
    json_stats(f, "sky_angle", &r->sky_angle, ",");
    json_image(f, r);
    fputs("}\n", f);
}

/* One row: "-" where nothing was measured. */
static void table_row(FILE *f, const char *name, const struct compare_stats *s, const char *unit)
{
    fprintf(f, "%-18s %9ld", name, s->count);
    if (s->count == 0)
        fprintf(f, " %10s %10s %10s", "-", "-", "-");
    else
        fprintf(f, " %10.3g %10.3g %10.3g", s->mean, s->p99, s->max);
    fprintf(f, "  %s", unit);
    if (s->non_finite)
        fprintf(f, " (%ld not finite)", s->non_finite);
    fputc('\n', f);
}

void compare_print_table(FILE *f, const struct compare_result *r)
{
    const struct compare_outcomes *o = &r->outcomes;
    fprintf(f, "scene %s, %dx%d = %ld pixels\n", r->scene, r->width, r->height, r->pixels);
    fprintf(f, "  a (under test): %s\n  b (reference):  %s\n", r->engine_a, r->engine_b);
    fprintf(f, "outcome differs: %ld of %ld pixels (%.4g%%)\n", o->differ, r->pixels,
            100.0 * r->outcome_fraction);
    fprintf(f, "  failed in a %ld, failed in b %ld, captured/escaped %ld, other object %ld, object/sky %ld, "
               "unfinished %ld\n",
            o->failed_a, o->failed_b, o->captured_vs_escaped, o->other_object, o->object_vs_sky, o->unfinished);
    fprintf(f, "%-18s %9s %10s %10s %10s\n", "error", "pixels", "mean", "p99", "max");
    table_row(f, "hit point", &r->hit, "scene units");
    table_row(f, "hit point / size", &r->hit_relative, "of the object's size");
    table_row(f, "sky direction", &r->sky_angle, "rad");
    if (r->image_identical)
        fputs("image: identical (PSNR infinite)\n", f);
    else
        fprintf(f, "image: PSNR %.2f dB; mean |difference| R %.3g G %.3g B %.3g (1/255)\n", r->psnr_db,
                r->mean_abs_diff[0], r->mean_abs_diff[1], r->mean_abs_diff[2]);
}
