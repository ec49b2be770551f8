/* bentray render: one scene, headless, to a PNG and optionally a per-pixel dump. */
#include "cli/commands.h"
#include "cli/options.h"
#include "io/clock.h"
#include "io/std_streams.h"
#include "io/image_out.h"
#include "io/output_file.h"
#include "cli/measure.h"
#include <stdlib.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static void usage(FILE *out)
{
    fprintf(out,
            "usage: bentray render --scene FILE [options]\n"
            "Render a scene headless to a PNG.\n"
            "  --scene FILE         scene file (assets/scenes/*.scene; format in docs/SCENES.md)\n"
            "  --out FILE           output image: FILE.png (8-bit sRGB RGBA), FILE.pfm (linear floats) or -\n"
            "                       (a PNG on standard output); default NAME.png in the working directory,\n"
            "                       NAME the scene's name with characters other than letters, digits, - _ . as _\n"
            "  --depth 8|16         bits a channel of a PNG (default 8)\n"
            "  --compression C      fast (default) or small: a PNG written fast, or a smaller file\n"
            "                       (libpng's default deflate; sizes and times in docs/BENCH.md)\n"
            "  --dump FILE          also write per-pixel results (format in docs/DUMP.md)\n"
            "  --force              replace existing output files\n"
            "  --size WxH           image size (overrides render.width/height)\n"
            "  --samples N          rays per pixel, averaged in linear light (overrides render.samples;\n"
            "                       1 to 256; the dump follows each pixel's centre)\n"
            "GPU engine:\n"
            "  --backend B          egl, osmesa or auto (default auto: EGL, then OSMesa)\n"
            "  --precision P        fp32, fp16, packed or auto: the float format of the ray state\n"
            "  --no-mrt             write x and v in separate passes even where MRT works\n"
            "  --set SECTION.KEY=V  override any scene key, e.g. --set model.mass=1.5\n"
            "  --shader-dir DIR     load shaders from DIR instead of the built-in copies\n"
            "  --quiet              print only the output path (no summary, no progress; warnings stay)\n"
            "  --progress           report progress from the start (default: once a render has run 1 s)\n"
            "  --engine E           gpu (default) or cpu: the double-precision reference (docs/ERRORS.md)\n"
            "  --rtol R             cpu engine: relative tolerance per step (default 1e-10)\n"
            "  --threads N          cpu engine: worker threads (default 0: one per core)\n"
            "exit codes: 0 ok, 1 runtime failure, 2 bad usage or input\n");
}

/* Which key raises a ray's budget: segments where they set it, else the path. */
static const char *budget_key(const struct render_settings *r)
{
    if (r->step_control == STEP_FIXED && r->segments > 0)
        return "render.segments";
    return r->step_control == STEP_FIXED || r->segments == 0 ? "render.max_path" : "render.max_path or render.segments";
}

/* The shaders' compile is said on the time line from this long: with Mesa's shader cache it takes
 * 0.04 s of schwarzschild's frame here, without it 0.65 s (llvmpipe, docs/BENCH.md). */
#define COMPILE_SAID_SECONDS 0.1

static void summarise(const struct measured *m, const struct scene *s)
{
    const struct dump *d = &m->dump;
    const struct outcome_counts *c = &m->counts;
    long objects = c->objects, sky = c->sky, captured = c->captured, unfinished = c->unfinished, failed = c->failed;
    fprintf(stderr, "%s: %dx%d, %s model, %s\n", s->name, d->width, d->height, model_name(s->model.type), m->how);
    fprintf(stderr, "rays: %ld hit an object, %ld sky, %ld captured, %ld unfinished, %ld failed\n", objects, sky,
            captured, unfinished, failed);
    /* what the user waits for: the GPU's or the CPU's work above, and around it the context, the
     * shaders' compilation, the orbit table, the read-back and the files written */
    char compile[128] = "";
    if (m->compile_seconds >= COMPILE_SAID_SECONDS)
        snprintf(compile, sizeof compile, " (%.3f s of it compiling shaders, which a driver with a shader cache "
                 "keeps for later runs)", m->compile_seconds);
    fprintf(stderr, "time: %.3f s rendering%s, %.3f s since bentray started\n", m->seconds, compile,
            clock_since_start());
    if (unfinished)
        fprintf(stderr, "note: %ld rays were still travelling at the end of their budget (a path of %g in %d "
                        "segments); they show render.unfinished_color (raise %s)\n", unfinished,
                render_path_budget(&s->render), render_segments(&s->render), budget_key(&s->render));
    if (m->nonfinite)
        fprintf(stderr, "warning: %ld non-finite values in the ray state\n", m->nonfinite);
}

/* From this speed (units of c) on, the Doppler shift behind a moving observer dims what it sees there
 * by more than a factor of 3 in D (D = sqrt((1 - b) / (1 + b)) straight behind). */
#define DIMMING_SPEED 0.5

/* The image is mostly black because the camera looks away from its own motion, where the Doppler
 * effects shift the light to the red and dim it: say so, with the angle and the keys to change. */
static void warn_dark_behind(const struct scene *s, size_t dark, size_t n)
{
    double beta = v3_len(s->observer.velocity);
    if (n == 0 || dark * 10 < 9 * n || beta < DIMMING_SPEED || s->observer.effects == EFFECTS_GEOMETRY)
        return;
    vec3d look = v3_normalize(v3_sub(s->camera.look_at, s->camera.position));
    double cosine = v3_dot(look, s->observer.velocity) / beta;
    if (cosine >= 0.0)
        return;
    fprintf(stderr, "warning: %.0f%% of the image is black: the camera looks %.0f degrees away from its motion at "
                    "%.2f c, where observer.effects = %s shifts the light to the red and dims it (look along "
                    "observer.velocity, lower its speed, or take effects = geometry)\n",
            100.0 * (double)dark / (double)n, acos(cosine) * 180.0 / PI_D, beta,
            s->observer.effects == EFFECTS_SEARCHLIGHT ? "searchlight" : "doppler");
}

/* Warnings that --quiet does not hide: an image that says little about the scene. A tenth or more of
 * the rays still travelling at the end, half or more failed (the model's numbers overflow), half or
 * more captured (the shadow fills the view), nine tenths black behind a fast observer, or a
 * segment so long that its chord cuts straight across the bounding sphere. */
static void warn_meaningless(const struct measured *m, const struct scene *s)
{
    const struct dump *d = &m->dump;
    const struct outcome_counts *c = &m->counts;
    size_t n = (size_t)d->width * d->height, failed = (size_t)c->failed, unfinished = (size_t)c->unfinished,
           captured = (size_t)c->captured, dark = (size_t)c->dark;
    if (n > 0 && captured * 2 >= n)
        fprintf(stderr, "warning: %zu of %zu rays (%.0f%%) fell into the horizon: the black hole's shadow fills most "
                        "of the view (move camera.position away, widen camera.fov or lower model.mass)\n",
                captured, n, 100.0 * (double)captured / (double)n);
    warn_dark_behind(s, dark, n);
    /* a tenth of the image showing the sky where the rays are not leaving is no longer a detail */
    if (n > 0 && unfinished * 10 >= n)
        fprintf(stderr, "warning: %zu of %zu rays (%.0f%%) were still travelling after the last segment: they show "
                        "render.unfinished_color, not the scene (raise %s)\n",
                unfinished, n, 100.0 * (double)unfinished / (double)n, budget_key(&s->render));
    if (n > 0 && failed * 2 >= n)
        fprintf(stderr, "warning: %zu of %zu rays failed (their state stopped being finite, or one step crossed the "
                        "whole scene): the model's settings (model %s's keys in [model], or render.step) give no "
                        "meaningful image\n", failed, n,
                model_name(s->model.type));
    const struct render_settings *r = &s->render;
    double segment = r->step_size * r->steps_per_segment;
    if (!model_is_straight(&s->model) && r->method != METHOD_ORBIT_TABLE && segment > 2.0 * r->bound_radius)
        fprintf(stderr, "warning: one segment (render.step %g x %d steps) is longer than the bounding sphere's "
                        "diameter %g: its chord cuts across the scene, so hits and bends mean little\n",
                r->step_size, r->steps_per_segment, 2.0 * r->bound_radius);
}

/* Either engine, with progress on stderr for a long render unless quiet; returns an exit code, m
 * filled on EXIT_OK. */
static int render_with(const struct common_options *o, const struct scene *s, int need_state,
                       enum progress_mode progress, int hdr, struct measured *m)
{
    struct error e;
    if (options_engine_cpu(o)) {
        struct cpu_render_options opt;
        options_cpu(o, s, &opt);
        opt.progress = progress;
        opt.hdr = hdr;
        if (measure_cpu(s, &opt, m, &e) == 0)
            return EXIT_OK;
    } else if (measure_gpu(s, o->backend, need_state, progress, hdr, m, &e) == 0) {
        return EXIT_OK;
    }
    fprintf(stderr, "bentray render: %s\n", e.message);
    return exit_code_of(&e);
}

/* The image's name when --out is not given: the scene's name with every character outside
 * letters, digits, '-', '_' and '.' replaced by '_' and no leading dot, in the working directory
 * ("../escaped" gives "_._escaped.png"). */
static void default_output_name(const char *scene_name, char *out, size_t len)
{
    char name[SCENE_NAME_LEN];
    size_t n = 0;
    for (const char *c = scene_name; *c && n + 1 < sizeof name; c++) {
        int plain = (*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') || (*c >= '0' && *c <= '9') ||
                    *c == '-' || *c == '_' || (*c == '.' && n > 0);
        name[n++] = plain ? *c : '_';
    }
    name[n] = '\0';
    snprintf(out, len, "%s.png", n > 0 ? name : "bentray");
}


/* What the command line asks of a render besides the scene. */
struct render_job {
    const char *out_path, *dump_path;
    int force, quiet, progress, to_stdout;
    enum image_format format;
    enum png_compression compression;
};

/* Loads S from O, renders it and writes what J asks for; the command's exit code. */
static int render_scene(const struct common_options *o, const struct render_job *j, struct scene *s)
{
    const char *out_path = j->out_path, *dump_path = j->dump_path;
    int force = j->force, quiet = j->quiet, progress = j->progress, to_stdout = j->to_stdout;
    enum image_format format = j->format;
    struct error why;
    int rc = options_load_scene(o, "render", s);
    if (rc)
        return rc;
    char default_out[SCENE_NAME_LEN + 8];
    if (!out_path) {
        default_output_name(s->name, default_out, sizeof default_out);
        out_path = default_out;
    }
    /* refuse before the work, not after: a long render must not end in "file exists" */
    const char *outputs[2] = {to_stdout ? NULL : out_path, dump_path};
    for (int k = 0; k < 2; k++) {
        if (outputs[k] && output_check(outputs[k], force, &why) != 0) {
            fprintf(stderr, "bentray render: %s: %s\n", k ? "--dump" : "--out", why.message);
            return exit_code_of(&why);
        }
    }
    /* no input is ever an output: the scene being rendered, its textures and its sky stay as they are */
    for (int k = 0; k < 2; k++) {
        char which[SCENE_PATH_LEN + 64];
        if (outputs[k] && scene_input_named(s, outputs[k], which, sizeof which)) {
            fprintf(stderr, "bentray render: %s %s is %s, which this render reads: name another file\n",
                    k ? "--dump" : "--out", outputs[k], which);
            return EXIT_USAGE;
        }
    }
    if (dump_path && !to_stdout && output_same(out_path, dump_path)) {
        fprintf(stderr, "bentray render: --out and --dump name the same file %s: give them different names\n",
                dump_path);
        return EXIT_USAGE;
    }
    struct measured r = {0};
    struct error err;
    rc = render_with(o, s, dump_path != NULL, quiet ? PROGRESS_NONE : progress ? PROGRESS_ALWAYS : PROGRESS_AUTO,
                     image_format_float(format), &r);
    if (rc == EXIT_OK &&
        image_write(out_path, format, r.dump.width, r.dump.height, r.rgba, r.color, force, j->compression, &err) != 0) {
        fprintf(stderr, "bentray render: --out: %s\n", err.message);
        rc = exit_code_of(&err);
    } else if (rc == EXIT_OK && dump_path && dump_write(dump_path, &r.dump, force, &err) != 0) {
        fprintf(stderr, "bentray render: --dump: %s\n", err.message);
        rc = exit_code_of(&err);
    }
    if (rc == EXIT_OK) {
        if (!quiet)
            summarise(&r, s);
        warn_meaningless(&r, s);
        if (!to_stdout)
            printf("%s\n", out_path);
    }
    measured_free(&r);
    return rc;
}

int cmd_render(int argc, char **argv)
{
    struct common_options o = {.backend = "auto"};
    const char *out_path = NULL, *dump_path = NULL;
    int force = 0, quiet = 0, progress = 0, depth = 8;
    enum png_compression compression = PNG_COMPRESSION_FAST;
    enum { OUT, DUMP, FORCE, QUIET, DEPTH, PROGRESS, COMPRESSION };
    static const struct option_spec specs[] = {
        {"--out", "FILE", OUT},     {"--dump", "FILE", DUMP},   {"--force", NULL, FORCE},
        {"--quiet", NULL, QUIET},   {"--depth", "8|16", DEPTH}, {"--progress", NULL, PROGRESS},
        {"--compression", "fast|small", COMPRESSION},
        {NULL, NULL, 0},
    };
    struct option_reader rd = {.cmd = "render", .own = specs, .common = common_option_specs,
                               .usage = usage, .argc = argc, .argv = argv};
    const struct option_spec *sp;
    const char *v;
    int got;
    while ((got = option_read(&rd, &sp, &v)) > 0) {
        switch (sp->id) {
        case OUT:
            out_path = v;
            break;
        case DUMP:
            dump_path = v;
            break;
        case FORCE:
            force = 1;
            break;
        case QUIET:
            quiet = 1;
            break;
        case DEPTH:
            if (strcmp(v, "8") && strcmp(v, "16")) {
                fprintf(stderr, "bentray render: --depth: expected 8 or 16 bits a channel, got '%s'\n", v);
                return EXIT_USAGE;
            }
            depth = atoi(v);
            break;
        case PROGRESS:
            progress = 1;
            break;
        case COMPRESSION:
            if (strcmp(v, "fast") && strcmp(v, "small")) {
                fprintf(stderr, "bentray render: --compression: expected fast or small, got '%s'\n", v);
                return EXIT_USAGE;
            }
            compression = strcmp(v, "small") == 0 ? PNG_COMPRESSION_SMALL : PNG_COMPRESSION_FAST;
            break;
        default:
            if (options_common(&o, "render", sp->id, v) != 0)
                return EXIT_USAGE;
        }
    }
    if (got < 0)
        return rd.exit_code;
    if (quiet && progress) {
        fprintf(stderr, "bentray render: --progress and --quiet contradict each other: give one\n");
        return EXIT_USAGE;
    }
    /* a name that promises another format than the one written would be a lie on the disk */
    enum image_format format = IMAGE_PNG8;
    struct error why;
    if (image_format_of(out_path ? out_path : "x.png", depth, &format, &why) != 0) {
        fprintf(stderr, "bentray render: --out %s: %s\n", out_path, why.message);
        return EXIT_USAGE;
    }
    int to_stdout = out_path && strcmp(out_path, "-") == 0;
    if (dump_path && strcmp(dump_path, "-") == 0) {
        fprintf(stderr, "bentray render: --dump -: a dump is written to a file (only --out - goes to standard "
                        "output); name one, e.g. --dump scene.dump\n");
        return EXIT_USAGE;
    }
    if (to_stdout && std_stdout_closed()) {
        fprintf(stderr, "bentray render: --out -: standard output is closed; nothing rendered\n");
        return EXIT_RUNTIME;
    }
    if (to_stdout && isatty(STDOUT_FILENO)) {
        fprintf(stderr, "bentray render: --out -: standard output is a terminal; send the PNG to a file or a pipe "
                        "(bentray render ... --out - > image.png)\n");
        return EXIT_USAGE;
    }
    if (compression == PNG_COMPRESSION_SMALL && format == IMAGE_PFM) {
        fprintf(stderr, "bentray render: --compression small: --out %s is a PFM, which is not compressed; "
                        "name a .png or leave --compression out\n", out_path);
        return EXIT_USAGE;
    }
    struct render_job job = {out_path, dump_path, force, quiet, progress, to_stdout, format, compression};
    struct scene *s = options_scene_new("render");
    if (!s)
        return EXIT_RUNTIME;
    int rc = render_scene(&o, &job, s);
    scene_free(s);
    return rc;
}
