#include "cli/options.h"
#include "cli/commands.h"
#include "gl/shader.h"
#include "io/error.h"
#include "io/text_file.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int option_backend_valid(const char *name)
{
    return strcmp(name, "egl") == 0 || strcmp(name, "osmesa") == 0 || strcmp(name, "auto") == 0;
}

int option_parse_int(const char *text, long min, long max, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(text, &end, 10);
    if (errno || end == text || *end != '\0' || v < min || v > max)
        return -1;
    *out = v;
    return 0;
}

int option_parse_size(const char *text, int *w, int *h)
{
    char buf[64];
    long lw, lh;
    if (strlen(text) >= sizeof buf)
        return -1;
    strcpy(buf, text);
    char *x = strchr(buf, 'x');
    if (!x)
        return -1;
    *x = '\0';
    if (option_parse_int(buf, 1, SCENE_MAX_SIZE, &lw) || option_parse_int(x + 1, 1, SCENE_MAX_SIZE, &lh) ||
        lw * lh > SCENE_MAX_PIXELS)
        return -1;
    *w = (int)lw;
    *h = (int)lh;
    return 0;
}

const struct option_spec common_option_specs[] = {
    {"--scene", "FILE", OPT_SCENE},
    {"--backend", "B", OPT_BACKEND},
    {"--shader-dir", "DIR", OPT_SHADER_DIR},
    {"--size", "WxH", OPT_SIZE},
    {"--samples", "N", OPT_SAMPLES},
    {"--precision", "P", OPT_PRECISION},
    {"--no-mrt", NULL, OPT_NO_MRT},
    {"--engine", "E", OPT_ENGINE},
    {"--threads", "N", OPT_THREADS},
    {"--rtol", "R", OPT_RTOL},
    {"--set", "SECTION.KEY=V", OPT_SET},
    {NULL, NULL, 0},
};

static const struct option_spec argument_spec = {"", NULL, OPT_ARGUMENT};

static const struct option_spec *spec_find(const struct option_spec *table, const char *name)
{
    for (; table && table->name; table++)
        if (strcmp(table->name, name) == 0)
            return table;
    return NULL;
}

/* The known option nearest to name within two edits (and nearer than its length), or NULL. */
static const char *spec_guess(const struct option_spec *own, const struct option_spec *common, const char *name)
{
    const char *best = NULL;
    int best_d = 3;
    const struct option_spec *tables[2] = {own, common};
    for (int t = 0; t < 2; t++)
        for (const struct option_spec *sp = tables[t]; sp && sp->name; sp++) {
            int d = edit_distance(name, sp->name, 64);
            if (d < best_d && (size_t)d < strlen(name)) {
                best_d = d;
                best = sp->name;
            }
        }
    return best;
}

static int read_fails(struct option_reader *r, int exit_code)
{
    r->exit_code = exit_code;
    return -1;
}

/* getopt_long's val for r->specs[k]: SPEC_VAL + k, above every character of a short option. */
enum { SPEC_VAL = 0x100 };
/* '-': arguments that are no option come back in order, as 1 with optarg; ':': a value missing
 * at the end of the line is ':', not '?'; h: -h. */
static const char short_options[] = "-:h";

/* The table getopt_long reads: r's own options, the common ones that own does not name again
 * (own wins, as it always did), then --help. */
static int reader_build(struct option_reader *r)
{
    const struct option_spec *tables[2] = {r->own, r->common};
    r->n_specs = 0;
    for (int t = 0; t < 2; t++)
        for (const struct option_spec *sp = tables[t]; sp && sp->name; sp++) {
            if (t == 1 && spec_find(r->own, sp->name))
                continue;
            if (r->n_specs == OPTIONS_MAX_SPECS || strncmp(sp->name, "--", 2) != 0 || sp->name[2] == '\0') {
                fprintf(stderr, "bentray %s: internal: option '%s' does not fit the table of %d long options\n",
                        r->cmd, sp->name, OPTIONS_MAX_SPECS);
                return -1;
            }
            r->specs[r->n_specs] = sp;
            r->long_options[r->n_specs] = (struct option){sp->name + 2, sp->value ? required_argument : no_argument,
                                                          NULL, SPEC_VAL + r->n_specs};
            r->n_specs++;
        }
    r->long_options[r->n_specs] = (struct option){"help", no_argument, NULL, 'h'};
    r->long_options[r->n_specs + 1] = (struct option){NULL, 0, NULL, 0};
    return 0;
}

/* The options that add a value each time they are given; every other option with a value is given
 * at most once. */
static int option_repeats(const char *name)
{
    return strcmp(name, "--set") == 0 || strcmp(name, "--set-range") == 0;
}

static const struct option_spec *spec_of_val(const struct option_reader *r, int val)
{
    return val >= SPEC_VAL && val < SPEC_VAL + r->n_specs ? r->specs[val - SPEC_VAL] : NULL;
}

static int unknown_option(struct option_reader *r, const char *arg)
{
    char name[128];
    snprintf(name, sizeof name, "%.*s", (int)strcspn(arg, "="), arg);
    const char *guess = spec_guess(r->own, r->common, name);
    fprintf(stderr, "bentray %s: unknown option '%s'%s%s%s\n", r->cmd, arg, guess ? " (did you mean " : "",
            guess ? guess : "", guess ? "?)" : "");
    r->usage(stderr);
    return read_fails(r, EXIT_USAGE);
}

/* A long option getopt_long did not take (its '?' with optopt 0): an abbreviation that more than
 * one option begins with, or no option at all. */
static int refused_option(struct option_reader *r, const char *arg)
{
    size_t len = strcspn(arg + 2, "=");
    int matches = 0;
    for (const struct option *lo = r->long_options; lo->name && len > 0; lo++)
        matches += strncmp(lo->name, arg + 2, len) == 0;
    if (matches < 2)
        return unknown_option(r, arg);
    fprintf(stderr, "bentray %s: option '--%.*s' is ambiguous (", r->cmd, (int)len, arg + 2);
    const char *sep = "";
    for (const struct option *lo = r->long_options; lo->name; lo++)
        if (strncmp(lo->name, arg + 2, len) == 0) {
            fprintf(stderr, "%s--%s", sep, lo->name);
            sep = ", ";
        }
    fprintf(stderr, "); give more of its name\n");
    return read_fails(r, EXIT_USAGE);
}

int option_read(struct option_reader *r, const struct option_spec **spec, const char **value)
{
    *value = NULL;
    if (r->next < 1) {
        if (reader_build(r) != 0)
            return read_fails(r, EXIT_RUNTIME);
        r->next = 1;
        optind = 0;                 /* glibc's getopt starts afresh: a process may read several lines */
    } else {
        optind = r->next;           /* the command may have taken an argument itself (trace --pixel I J) */
    }
    opterr = 0;
    /* getopt_long would read "-x" as short options and "--" as the end of the options; bentray
     * has neither, so both are unknown options, as they always were ("-" alone is an argument) */
    const char *arg = r->next < r->argc ? r->argv[r->next] : NULL;
    if (arg && arg[0] == '-' && arg[1] != '\0' && strcmp(arg, "-h") != 0 && (arg[1] != '-' || arg[2] == '\0')) {
        r->next++;
        return unknown_option(r, arg);
    }
    int c = getopt_long(r->argc, r->argv, short_options, r->long_options, NULL);
    r->next = optind;
    const struct option_spec *sp = NULL;
    switch (c) {
    case -1:
        return 0;
    case 'h':
        r->usage(stdout);
        return read_fails(r, EXIT_OK);
    case 1:
        if (!r->arguments) {
            fprintf(stderr, "bentray %s: unexpected argument '%s' (options begin with --)\n", r->cmd, optarg);
            r->usage(stderr);
            return read_fails(r, EXIT_USAGE);
        }
        *spec = &argument_spec;
        *value = optarg;
        return 1;
    case ':':
        sp = spec_of_val(r, optopt);
        fprintf(stderr, "bentray %s: option %s needs a value (%s)\n", r->cmd, sp ? sp->name : r->argv[optind - 1],
                sp ? sp->value : "?");
        return read_fails(r, EXIT_USAGE);
    case '?':
        /* a flag given a value with '=' (optopt its val), or a long option not taken */
        sp = spec_of_val(r, optopt);
        if (sp || optopt == 'h') {
            fprintf(stderr, "bentray %s: option %s takes no value, got '%s'\n", r->cmd, sp ? sp->name : "--help",
                    r->argv[optind - 1]);
            return read_fails(r, EXIT_USAGE);
        }
        arg = r->argv[optind - 1];
        return strncmp(arg, "--", 2) == 0 ? refused_option(r, arg) : unknown_option(r, arg);
    default:
        sp = spec_of_val(r, c);
        if (!sp) {
            fprintf(stderr, "bentray %s: internal: getopt_long returned %d\n", r->cmd, c);
            return read_fails(r, EXIT_RUNTIME);
        }
        /* a value of its own argument that is another option: the value was forgotten */
        if (sp->value && optarg == r->argv[optind - 1] && strncmp(optarg, "--", 2) == 0 && optarg[2] != '\0') {
            fprintf(stderr, "bentray %s: option %s needs a value (%s), not the option '%s'\n", r->cmd, sp->name,
                    sp->value, optarg);
            return read_fails(r, EXIT_USAGE);
        }
        if (sp->value && !option_repeats(sp->name)) {
            int k = c - SPEC_VAL;
            if (r->given[k]) {
                fprintf(stderr, "bentray %s: option %s given twice ('%s', then '%s'): give it once\n", r->cmd,
                        sp->name, r->given[k], optarg);
                return read_fails(r, EXIT_USAGE);
            }
            r->given[k] = optarg;
        }
        *spec = sp;
        *value = sp->value ? optarg : NULL;
        return 1;
    }
}

int options_common(struct common_options *o, const char *cmd, int id, const char *v)
{
    switch (id) {
    case OPT_SCENE:
        o->scene_path = v;
        return 0;
    case OPT_BACKEND:
        if (!option_backend_valid(v)) {
            fprintf(stderr, "bentray %s: --backend: unknown back-end '%s' (expected egl, osmesa or auto)\n", cmd, v);
            return -1;
        }
        o->backend = v;
        return 0;
    case OPT_SHADER_DIR:
        o->shader_dir = v;
        shader_set_directory(v);
        return 0;
    case OPT_SIZE:
        if (option_parse_size(v, &o->width, &o->height) != 0) {
            fprintf(stderr, "bentray %s: --size: expected WxH with 1 <= W, H <= %d and W x H <= %ld pixels, got '%s'\n",
                    cmd, SCENE_MAX_SIZE, SCENE_MAX_PIXELS, v);
            return -1;
        }
        return 0;
    case OPT_SAMPLES: {
        long n;
        if (option_parse_int(v, 1, SCENE_MAX_SAMPLES, &n) != 0) {
            fprintf(stderr, "bentray %s: --samples: expected rays per pixel from 1 to %d, got '%s'\n", cmd,
                    SCENE_MAX_SAMPLES, v);
            return -1;
        }
        o->samples = (int)n;
        return 0;
    }
    case OPT_PRECISION:
        if (strcmp(v, "fp32") && strcmp(v, "fp16") && strcmp(v, "packed") && strcmp(v, "auto")) {
            fprintf(stderr, "bentray %s: --precision: expected fp32, fp16, packed or auto, got '%s'\n", cmd, v);
            return -1;
        }
        o->precision = v;
        return 0;
    case OPT_NO_MRT:
        o->no_mrt = 1;
        return 0;
    case OPT_ENGINE:
        if (strcmp(v, "gpu") && strcmp(v, "cpu")) {
            fprintf(stderr, "bentray %s: --engine: expected gpu or cpu, got '%s'\n", cmd, v);
            return -1;
        }
        o->engine = v;
        return 0;
    case OPT_THREADS: {
        long n;
        if (option_parse_int(v, 0, CPU_MAX_THREADS, &n) != 0) {
            fprintf(stderr, "bentray %s: --threads: expected 0 (one per core) to %d, got '%s'\n", cmd,
                    CPU_MAX_THREADS, v);
            return -1;
        }
        o->threads = (int)n;
        return 0;
    }
    case OPT_RTOL: {
        char *end;
        errno = 0;
        double r = strtod(v, &end);
        if (errno || end == v || *end != '\0' || !(r >= OPTION_RTOL_MIN && r <= OPTION_RTOL_MAX)) {
            fprintf(stderr, "bentray %s: --rtol: expected a relative tolerance from %g to %g, got '%s'\n",
                    cmd, OPTION_RTOL_MIN, OPTION_RTOL_MAX, v);
            return -1;
        }
        o->rtol = r;
        return 0;
    }
    case OPT_SET:
        if (o->n_sets == OPTIONS_MAX_SETS) {
            fprintf(stderr, "bentray %s: --set: at most %d overrides\n", cmd, OPTIONS_MAX_SETS);
            return -1;
        }
        o->sets[o->n_sets++] = v;
        return 0;
    default:
        fprintf(stderr, "bentray %s: internal: option id %d has no meaning here\n", cmd, id);
        return -1;
    }
}

int options_engine_cpu(const struct common_options *o)
{
    return o->engine && strcmp(o->engine, "cpu") == 0;
}

void options_cpu(const struct common_options *o, const struct scene *s, struct cpu_render_options *out)
{
    memset(out, 0, sizeof *out);
    ref_options_default(&out->ref, s);
    if (o->rtol > 0.0) {
        out->ref.atol *= o->rtol / out->ref.rtol;
        out->ref.rtol = o->rtol;
    }
    out->threads = o->threads;
    out->progress = PROGRESS_AUTO;
}

/* Options that belong to one engine are refused with the other, never silently ignored. */
static int check_engine_options(const struct common_options *o, const char *cmd)
{
    const char *wrong = NULL;
    if (o->both_engines) {
        if (o->engine) {
            fprintf(stderr, "bentray %s: --engine: this command runs both engines; GPU and CPU options both "
                            "apply\n", cmd);
            return -1;
        }
    } else if (options_engine_cpu(o)) {
        wrong = o->backend && strcmp(o->backend, "auto") ? "--backend"
                : o->precision                           ? "--precision"
                : o->no_mrt                              ? "--no-mrt"
                : o->shader_dir                          ? "--shader-dir"
                                                         : NULL;
        if (wrong) {
            fprintf(stderr, "bentray %s: %s applies to the GPU engine only, not to --engine cpu\n", cmd, wrong);
            return -1;
        }
    } else {
        wrong = o->threads ? "--threads" : o->rtol > 0.0 ? "--rtol" : NULL;
        if (wrong) {
            fprintf(stderr, "bentray %s: %s applies to the CPU engine only (add --engine cpu)\n", cmd, wrong);
            return -1;
        }
    }
    return 0;
}

int options_load_scene(const struct common_options *o, const char *cmd, struct scene *s)
{
    struct error err;
    if (check_engine_options(o, cmd) != 0)
        return EXIT_USAGE;
    if (!o->scene_path) {
        fprintf(stderr, "bentray %s: --scene FILE is required\n", cmd);
        return EXIT_USAGE;
    }
    if (scene_load(s, o->scene_path, &err) != 0) {
        error_print(&err, NULL, stderr);
        return EXIT_USAGE;
    }
    for (int k = 0; k < o->n_sets; k++)
        if (scene_set(s, o->sets[k], &err) != 0) {
            error_print(&err, NULL, stderr);
            return EXIT_USAGE;
        }
    if (o->width) {
        s->render.width = o->width;
        s->render.height = o->height;
    }
    if (o->samples)
        s->render.samples = o->samples;
    if (o->precision)
        s->render.precision = strcmp(o->precision, "fp32") == 0     ? PRECISION_FP32
                              : strcmp(o->precision, "fp16") == 0   ? PRECISION_FP16
                              : strcmp(o->precision, "packed") == 0 ? PRECISION_PACKED
                                                                    : PRECISION_AUTO;
    if (o->no_mrt)
        s->render.mrt = MRT_OFF;
    if (scene_validate(s, &err) != 0) {
        error_print(&err, NULL, stderr);
        return EXIT_USAGE;
    }
    return 0;
}

enum exit_code exit_code_of(const struct error *e) { return e->status == ERROR_INPUT ? EXIT_USAGE : EXIT_RUNTIME; }

struct scene *options_scene_new(const char *cmd)
{
    struct error e;
    struct scene *s = scene_new(&e);
    if (!s)
        fprintf(stderr, "bentray %s: %s\n", cmd, e.message);
    return s;
}
