/* Shared option parsing for the sub-commands: one place that turns argv into settings and
 * reports which option is wrong. */
#ifndef BT_OPTIONS_H
#define BT_OPTIONS_H
#include "ref/engine_cpu.h"
#include "scene/scene.h"
#include <getopt.h>
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

typedef void (*usage_fn)(FILE *out);

/* One option of a command, declared once in the command's table (as glmark2 declares a scene's
 * options): its name, the word for its value in messages (NULL: a flag without value), and the
 * command's own id for it. A table ends with an entry whose name is NULL. */
struct option_spec {
    const char *name;
    const char *value;
    int id;
};

/* Ids option_read gives besides a command's own (which must be >= 0): an argument that is no
 * option (a file of bentray compare), and the common options of the commands that
 * render a scene (common_option_specs, applied by options_common). */
enum {
    OPT_ARGUMENT = -100,
    OPT_SCENE,
    OPT_BACKEND,
    OPT_SHADER_DIR,
    OPT_SIZE,
    OPT_SAMPLES,
    OPT_PRECISION,
    OPT_NO_MRT,
    OPT_ENGINE,
    OPT_THREADS,
    OPT_RTOL,
    OPT_SET,
};
extern const struct option_spec common_option_specs[];

/* The most options one command reads: its own and the common ones together. */
#define OPTIONS_MAX_SPECS 48

/* A command's options being read, one by one, from its argument list: set cmd, own (its table),
 * common (common_option_specs, or NULL), usage, argc and argv, and arguments to 1 if the command
 * takes arguments that are not options (bentray compare's files); leave the rest zero. */
struct option_reader {
    const char *cmd;
    const struct option_spec *own, *common;
    usage_fn usage;
    int argc;
    char **argv;
    int arguments;
    int next;        /* the argument read next; 0: the first after the command's name. A command
                      * whose option takes a second value (trace --pixel I J) reads argv[next]
                      * after option_read and moves next on. */
    int exit_code;   /* when option_read returned -1: EXIT_OK after --help, else EXIT_USAGE */
    /* option_read's own: the table getopt_long reads, built on the first call from own and common */
    int n_specs;
    const struct option_spec *specs[OPTIONS_MAX_SPECS];
    struct option long_options[OPTIONS_MAX_SPECS + 2];    /* the specs, --help, the end */
    const char *given[OPTIONS_MAX_SPECS];                 /* each valued option's value, once given */
};

/* The next option, looked up in own and then in common: 1 with its spec and *value (the argument
 * after it, or after '=' in --name=value; NULL for a flag), 0 at the end of the list, -1 when the
 * command is to exit with r->exit_code. Read with glibc's getopt_long, so a long option may be
 * abbreviated to any unique beginning of its name (--sam 4 for --samples 4). Every command reads
 * its options through here, so each fails the same way, after a message on stderr naming the
 * command and the option: an unknown option (with the nearest known one within two edits, and
 * the usage), an abbreviation that more than one option begins with (naming them), a value
 * missing (the end of the line, or another option where the value should be), a value given to
 * a flag (--force=1), an argument where the command takes none. A value may begin with '-'
 * (--rtol -1, --pixel -1 5), but not with "--" unless joined with '='. --help and -h print the
 * usage on stdout (-1, EXIT_OK). With r->arguments, an argument that is not an option comes back
 * as OPT_ARGUMENT with itself as the value ("-" alone is an argument: standard output). "--" and
 * an argument with one '-' but "-h" and "-" are unknown options. An option with a value given twice is
 * refused, naming both values (--set and --set-range add one each time; a flag may be repeated). getopt_long's state is the
 * process's: one reader is read at a time, and each starts it afresh on its first call. */
int option_read(struct option_reader *r, const struct option_spec **spec, const char **value);

/* Applies common option id with its value to o: 0, or -1 after a message that names the option
 * and what it expects. */
int options_common(struct common_options *o, const char *cmd, int id, const char *value);

/* Load the scene and apply --size, --precision, --no-mrt and --set. Prints the error
 * (file:line or option) and returns EXIT_USAGE on bad input, 0 on success. */
int options_load_scene(const struct common_options *o, const char *cmd, struct scene *s);

/* Is the CPU reference engine asked for? */
int options_engine_cpu(const struct common_options *o);
/* Options of the CPU engine for scene s (tolerances default from the scene). */
void options_cpu(const struct common_options *o, const struct scene *s, struct cpu_render_options *out);

/* A scene of the command's own, on the heap (scene_new), or NULL after "bentray CMD: out of
 * memory ..." on stderr: the command then ends with EXIT_RUNTIME. */
struct scene *options_scene_new(const char *cmd);

#endif
