/* Shared option parsing for the sub-commands: one place that turns argv into settings and
 * reports which option is wrong. */
#ifndef BT_OPTIONS_H
#define BT_OPTIONS_H
#include "ref/engine_cpu.h"
#include "scene/scene.h"
#include <stdio.h>

/* --set overrides on one command line; each is a pointer into argv, kept in a fixed array. */
#define OPTIONS_MAX_SETS 64
/* --rtol, the CPU reference's relative tolerance per step: below 1e-14 it is under double rounding
 * and the step controller can only stall; above 1e-2 the reference is no longer a reference. */
#define OPTION_RTOL_MIN 1e-14
#define OPTION_RTOL_MAX 1e-2

struct common_options {
    const char *scene_path;
    const char *backend;          /* egl|osmesa|auto */
    const char *shader_dir;
    int width, height;            /* 0: from the scene */
    int samples;                  /* rays per pixel; 0: from the scene (render.samples) */
    const char *precision;        /* NULL: from the scene */
    int no_mrt;
    const char *engine;           /* gpu|cpu; NULL: gpu */
    int threads;                  /* cpu engine: 0 = one per core */
    double rtol;                  /* cpu engine: 0 = REF_DEFAULT_RTOL */
    int both_engines;             /* the command runs both engines (bentray error) */
    int n_sets;
    const char *sets[OPTIONS_MAX_SETS];
};

int option_backend_valid(const char *name);
/* Parse "WxH": each side from 1 to SCENE_MAX_SIZE, W x H at most SCENE_MAX_PIXELS; 0 ok. */
int option_parse_size(const char *text, int *w, int *h);
/* Parse a non-negative integer option fully; 0 ok. */
int option_parse_int(const char *text, long min, long max, long *out);

enum option_status { OPTION_ERROR = -1, OPTION_NOT_COMMON = 0, OPTION_CONSUMED = 1, OPTION_HELP = 2 };
typedef void (*usage_fn)(FILE *out);

/* Try to consume argv[*i] (and its value) as a common option or --help (usage printed on
 * stdout). OPTION_ERROR: bad value, the message names the option. */
enum option_status options_common(struct common_options *o, const char *cmd, int argc, char **argv, int *i,
                                  usage_fn usage);
/* Exit code for OPTION_HELP (0) and OPTION_ERROR (2). */
int options_exit_code(enum option_status status);
/* Report an option the command does not know; returns EXIT_USAGE. */
int option_unknown(const char *cmd, const char *arg, usage_fn usage);

/* Load the scene and apply --size, --precision, --no-mrt and --set. Prints the error
 * (file:line or option) and returns EXIT_USAGE on bad input, 0 on success. */
int options_load_scene(const struct common_options *o, const char *cmd, struct scene *s);

/* Is the CPU reference engine asked for? */
int options_engine_cpu(const struct common_options *o);
/* Options of the CPU engine for scene s (tolerances default from the scene). */
void options_cpu(const struct common_options *o, const struct scene *s, struct cpu_render_options *out);

#endif
