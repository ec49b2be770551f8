#include "cli/options.h"
#include "cli/commands.h"
#include "gl/shader.h"
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

static const char *value_of(const char *cmd, int argc, char **argv, int *i)
{
    if (*i + 1 >= argc) {
        fprintf(stderr, "bentray %s: option %s needs a value\n", cmd, argv[*i]);
        return NULL;
    }
    return argv[++*i];
}

int options_exit_code(enum option_status status)
{
    return status == OPTION_HELP ? EXIT_OK : EXIT_USAGE;
}

int option_unknown(const char *cmd, const char *arg, usage_fn usage)
{
    fprintf(stderr, "bentray %s: unknown option or missing value: '%s'\n", cmd, arg);
    usage(stderr);
    return EXIT_USAGE;
}

enum option_status options_common(struct common_options *o, const char *cmd, int argc, char **argv, int *i,
                                  usage_fn usage)
{
    const char *opt = argv[*i], *v;
    if (strcmp(opt, "--help") == 0 || strcmp(opt, "-h") == 0) {
        usage(stdout);
        return OPTION_HELP;
    } else if (strcmp(opt, "--scene") == 0) {
        if (!(v = value_of(cmd, argc, argv, i)))
            return OPTION_ERROR;
        o->scene_path = v;
    } else if (strcmp(opt, "--backend") == 0) {
        if (!(v = value_of(cmd, argc, argv, i)))
            return OPTION_ERROR;
        if (!option_backend_valid(v)) {
            fprintf(stderr, "bentray %s: --backend: unknown back-end '%s' (expected egl, osmesa or auto)\n", cmd, v);
            return OPTION_ERROR;
        }
        o->backend = v;
    } else if (strcmp(opt, "--shader-dir") == 0) {
        if (!(v = value_of(cmd, argc, argv, i)))
            return OPTION_ERROR;
        o->shader_dir = v;
        shader_set_directory(v);
    } else if (strcmp(opt, "--size") == 0) {
        if (!(v = value_of(cmd, argc, argv, i)))
            return OPTION_ERROR;
        if (option_parse_size(v, &o->width, &o->height) != 0) {
            fprintf(stderr, "bentray %s: --size: expected WxH with 1 <= W, H <= %d and W x H <= %ld pixels, got '%s'\n",
                    cmd, SCENE_MAX_SIZE, SCENE_MAX_PIXELS, v);
            return OPTION_ERROR;
        }
    } else if (strcmp(opt, "--samples") == 0) {
        long n;
        if (!(v = value_of(cmd, argc, argv, i)))
            return OPTION_ERROR;
        if (option_parse_int(v, 1, SCENE_MAX_SAMPLES, &n) != 0) {
            fprintf(stderr, "bentray %s: --samples: expected rays per pixel from 1 to %d, got '%s'\n", cmd,
                    SCENE_MAX_SAMPLES, v);
            return OPTION_ERROR;
        }
        o->samples = (int)n;
    } else if (strcmp(opt, "--precision") == 0) {
        if (!(v = value_of(cmd, argc, argv, i)))
            return OPTION_ERROR;
        if (strcmp(v, "fp32") && strcmp(v, "fp16") && strcmp(v, "auto")) {
            fprintf(stderr, "bentray %s: --precision: expected fp32, fp16 or auto, got '%s'\n", cmd, v);
            return OPTION_ERROR;
        }
        o->precision = v;
    } else if (strcmp(opt, "--no-mrt") == 0) {
        o->no_mrt = 1;
    } else if (strcmp(opt, "--engine") == 0) {
        if (!(v = value_of(cmd, argc, argv, i)))
            return OPTION_ERROR;
        if (strcmp(v, "gpu") && strcmp(v, "cpu")) {
            fprintf(stderr, "bentray %s: --engine: expected gpu or cpu, got '%s'\n", cmd, v);
            return OPTION_ERROR;
        }
        o->engine = v;
    } else if (strcmp(opt, "--threads") == 0) {
        long n;
        if (!(v = value_of(cmd, argc, argv, i)))
            return OPTION_ERROR;
        if (option_parse_int(v, 0, CPU_MAX_THREADS, &n) != 0) {
            fprintf(stderr, "bentray %s: --threads: expected 0 (one per core) to %d, got '%s'\n", cmd,
                    CPU_MAX_THREADS, v);
            return OPTION_ERROR;
        }
        o->threads = (int)n;
    } else if (strcmp(opt, "--rtol") == 0) {
        if (!(v = value_of(cmd, argc, argv, i)))
            return OPTION_ERROR;
        char *end;
        errno = 0;
        double r = strtod(v, &end);
        if (errno || end == v || *end != '\0' || !(r >= OPTION_RTOL_MIN && r <= OPTION_RTOL_MAX)) {
            fprintf(stderr, "bentray %s: --rtol: expected a relative tolerance from %g to %g, got '%s'\n",
                    cmd, OPTION_RTOL_MIN, OPTION_RTOL_MAX, v);
            return OPTION_ERROR;
        }
        o->rtol = r;
    } else if (strcmp(opt, "--set") == 0) {
        if (!(v = value_of(cmd, argc, argv, i)))
            return OPTION_ERROR;
        if (o->n_sets == OPTIONS_MAX_SETS) {
            fprintf(stderr, "bentray %s: --set: at most %d overrides\n", cmd, OPTIONS_MAX_SETS);
            return OPTION_ERROR;
        }
        o->sets[o->n_sets++] = v;
    } else {
        return OPTION_NOT_COMMON;
    }
    return OPTION_CONSUMED;
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
            return OPTION_ERROR;
        }
    } else if (options_engine_cpu(o)) {
        wrong = o->backend && strcmp(o->backend, "auto") ? "--backend"
                : o->precision                           ? "--precision"
                : o->no_mrt                              ? "--no-mrt"
                : o->shader_dir                          ? "--shader-dir"
                                                         : NULL;
        if (wrong) {
            fprintf(stderr, "bentray %s: %s applies to the GPU engine only, not to --engine cpu\n", cmd, wrong);
            return OPTION_ERROR;
        }
    } else {
        wrong = o->threads ? "--threads" : o->rtol > 0.0 ? "--rtol" : NULL;
        if (wrong) {
            fprintf(stderr, "bentray %s: %s applies to the CPU engine only (add --engine cpu)\n", cmd, wrong);
            return OPTION_ERROR;
        }
    }
    return 0;
}

int options_load_scene(const struct common_options *o, const char *cmd, struct scene *s)
{
    struct conf_error err;
    if (check_engine_options(o, cmd) != 0)
        return EXIT_USAGE;
    if (!o->scene_path) {
        fprintf(stderr, "bentray %s: --scene FILE is required\n", cmd);
        return EXIT_USAGE;
    }
    if (scene_load(s, o->scene_path, &err) != 0) {
        fprintf(stderr, "%s: error: %s\n", err.where, err.message);
        return EXIT_USAGE;
    }
    for (int k = 0; k < o->n_sets; k++)
        if (scene_set(s, o->sets[k], &err) != 0) {
            fprintf(stderr, "%s: error: %s\n", err.where, err.message);
            return EXIT_USAGE;
        }
    if (o->width) {
        s->render.width = o->width;
        s->render.height = o->height;
    }
    if (o->samples)
        s->render.samples = o->samples;
    if (o->precision)
        s->render.precision = strcmp(o->precision, "fp32") == 0   ? PRECISION_FP32
                              : strcmp(o->precision, "fp16") == 0 ? PRECISION_FP16
                                                                  : PRECISION_AUTO;
    if (o->no_mrt)
        s->render.mrt = MRT_OFF;
    if (scene_validate(s, &err) != 0) {
        fprintf(stderr, "%s: error: %s\n", err.where, err.message);
        return EXIT_USAGE;
    }
    return 0;
}
