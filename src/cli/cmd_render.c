/* bentray render: one scene, headless, to a PNG and optionally a per-pixel dump. */
#include "cli/commands.h"
#include "cli/options.h"
#include "io/png_io.h"
#include "render/frame.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static void usage(FILE *out)
{
    fprintf(out,
            "usage: bentray render --scene FILE [options]\n"
            "Render a scene headless to a PNG.\n"
            "  --scene FILE         scene file (assets/scenes/*.scene; format in docs/SCENES.md)\n"
            "  --out FILE.png       output image (default: NAME.png, NAME from the scene)\n"
            "  --dump FILE          also write per-pixel results (format in docs/DUMP.md)\n"
            "  --force              replace existing output files\n"
            "  --size WxH           image size (overrides render.width/height)\n"
            "GPU engine:\n"
            "  --backend B          egl, osmesa or auto (default auto: EGL, then OSMesa)\n"
            "  --precision P        fp32, fp16 or auto: the float format of the ray state\n"
            "  --no-mrt             write x and v in separate passes even where MRT works\n"
            "  --set SECTION.KEY=V  override any scene key, e.g. --set model.mass=1.5\n"
            "  --shader-dir DIR     load shaders from DIR instead of the built-in copies\n"
            "  --quiet              print only the output path\n"
            "  --engine E           gpu (default) or cpu: the double-precision reference (docs/ERRORS.md)\n"
            "  --rtol R             cpu engine: relative tolerance per step (default 1e-10)\n"
            "  --threads N          cpu engine: worker threads (default 0: one per core)\n"
            "exit codes: 0 ok, 1 runtime failure, 2 bad usage or input\n");
}

/* One rendered frame from either engine: the image, its per-pixel records and a summary line. */
struct rendered {
    int width, height;
    unsigned char *rgba;
    struct dump dump;
    long nonfinite;
    char how[512];
    struct render_result gpu;
    struct cpu_image cpu;
};

static void summarise(const struct rendered *r, const struct scene *s)
{
    long objects = 0, sky = 0, captured = 0, unfinished = 0, failed = 0;
    size_t n = (size_t)r->width * r->height;
    for (size_t i = 0; i < n; i++) {
        int32_t o = r->dump.records[i].outcome;
        objects += o >= 0;
        sky += o == DUMP_SKY;
        captured += o == DUMP_CAPTURED;
        unfinished += o == DUMP_UNFINISHED;
        failed += o == DUMP_FAILED;
    }
    fprintf(stderr, "%s: %dx%d, %s model, %s\n", s->name, r->width, r->height, model_name(s->model.type), r->how);
    fprintf(stderr, "rays: %ld hit an object, %ld sky, %ld captured, %ld unfinished, %ld failed\n", objects, sky,
            captured, unfinished, failed);
    if (unfinished)
        fprintf(stderr, "note: %ld rays were still travelling after %d segments; they show the sky in their "
                        "last direction (raise render.segments or render.step)\n", unfinished, s->render.segments);
    if (r->nonfinite)
        fprintf(stderr, "warning: %ld non-finite values in the ray state\n", r->nonfinite);
}

static long count_nonfinite(const struct render_result *res)
{
    long nonfinite = 0;
    size_t n = (size_t)res->width * res->height;
    const float *arrays[4] = {res->position, res->velocity, res->hit, res->image};
    for (int a = 0; a < 4; a++)
        for (size_t k = 0; k < 4 * n; k++)
            nonfinite += !isfinite(arrays[a][k]);
    return nonfinite;
}

/* Returns an exit code; r is filled on EXIT_OK. */
static int render_gpu(const struct scene *s, const char *backend, struct rendered *r)
{
    struct frame_info info;
    char err[2048];
    int bad_input;
    if (render_frame(s, backend, &r->gpu, 1, &info, err, sizeof err, &bad_input) != 0) {
        fprintf(stderr, "bentray render: %s\n", err);
        return bad_input ? EXIT_USAGE : EXIT_RUNTIME;
    }
    char engine[32];
    snprintf(engine, sizeof engine, "gpu %s", info.path_name);
    if (result_to_dump(&r->gpu, s, engine, &r->dump) != 0) {
        fprintf(stderr, "bentray render: out of memory\n");
        return EXIT_RUNTIME;
    }
    r->width = r->gpu.width;
    r->height = r->gpu.height;
    r->rgba = r->gpu.rgba;
    r->nonfinite = count_nonfinite(&r->gpu);
    snprintf(r->how, sizeof r->how, "%s on %s (%s), %.3f s, %ld passes", info.path_description, info.backend,
             info.renderer, r->gpu.seconds, r->gpu.passes);
    return EXIT_OK;
}

static int render_cpu(const struct common_options *o, const struct scene *s, struct rendered *r)
{
    struct cpu_render_options opt;
    char err[1024];
    options_cpu(o, s, &opt);
    if (cpu_render(s, &opt, &r->cpu, err, sizeof err) != 0) {
        fprintf(stderr, "bentray render: %s\n", err);
        return EXIT_RUNTIME;
    }
    r->width = r->cpu.width;
    r->height = r->cpu.height;
    r->rgba = r->cpu.rgba;
    r->dump = r->cpu.dump;
    r->cpu.dump.records = NULL;    /* now owned by r->dump */
    snprintf(r->how, sizeof r->how, "CPU reference (Dormand-Prince 5(4), rtol %.0e), %.3f s, %ld steps, %ld rejected",
             opt.ref.rtol, r->cpu.seconds, r->cpu.steps, r->cpu.rejected);
    return EXIT_OK;
}

int cmd_render(int argc, char **argv)
{
    struct common_options o = {.backend = "auto"};
    const char *out_path = NULL, *dump_path = NULL;
    int force = 0, quiet = 0;
    for (int i = 1; i < argc; i++) {
        enum option_status c = options_common(&o, "render", argc, argv, &i, usage);
        if (c == OPTION_CONSUMED)
            continue;
        if (c != OPTION_NOT_COMMON)
            return options_exit_code(c);
        if (strcmp(argv[i], "--out") == 0 && i + 1 < argc) {
            out_path = argv[++i];
        } else if (strcmp(argv[i], "--dump") == 0 && i + 1 < argc) {
            dump_path = argv[++i];
        } else if (strcmp(argv[i], "--force") == 0) {
            force = 1;
        } else if (strcmp(argv[i], "--quiet") == 0) {
            quiet = 1;
        } else {
            fprintf(stderr, "bentray render: unknown option or missing value: '%s'\n", argv[i]);
            usage(stderr);
            return EXIT_USAGE;
        }
    }
    static struct scene s;
    int rc = options_load_scene(&o, "render", &s);
    if (rc)
        return rc;
    char default_out[SCENE_NAME_LEN + 8];
    if (!out_path) {
        snprintf(default_out, sizeof default_out, "%s.png", s.name);
        out_path = default_out;
    }
    /* refuse before the work, not after: a long render must not end in "file exists" */
    const char *outputs[2] = {out_path, dump_path};
    for (int k = 0; k < 2; k++)
        if (outputs[k] && !force && access(outputs[k], F_OK) == 0) {
            fprintf(stderr, "bentray render: %s: refusing to replace existing file %s (use --force to overwrite "
                            "it)\n", k ? "--dump" : "--out", outputs[k]);
            return EXIT_USAGE;
        }
    struct rendered r = {0};
    char err[2048];
    rc = options_engine_cpu(&o) ? render_cpu(&o, &s, &r) : render_gpu(&s, o.backend, &r);
    if (rc == EXIT_OK && png_write_rgba8(out_path, r.width, r.height, r.rgba, force, err, sizeof err) != 0) {
        fprintf(stderr, "bentray render: --out: %s\n", err);
        rc = EXIT_RUNTIME;
    } else if (rc == EXIT_OK && dump_path && dump_write(dump_path, &r.dump, force, err, sizeof err) != 0) {
        fprintf(stderr, "bentray render: --dump: %s\n", err);
        rc = EXIT_RUNTIME;
    }
    if (rc == EXIT_OK) {
        if (!quiet)
            summarise(&r, &s);
        printf("%s\n", out_path);
    }
    dump_free(&r.dump);
    render_result_free(&r.gpu);
    cpu_image_free(&r.cpu);
    return rc;
}
