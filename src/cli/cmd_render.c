/* bentray render: one scene, headless, to a PNG and optionally a per-pixel dump. */
#include "cli/commands.h"
#include "cli/options.h"
#include "io/png_io.h"
#include "render/frame.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
            "  --backend B          egl, osmesa or auto (default auto: EGL, then OSMesa)\n"
            "  --precision P        fp32, fp16 or auto: the float format of the ray state\n"
            "  --no-mrt             write x and v in separate passes even where MRT works\n"
            "  --set SECTION.KEY=V  override any scene key, e.g. --set model.mass=1.5\n"
            "  --shader-dir DIR     load shaders from DIR instead of the built-in copies\n"
            "  --quiet              print only the output path\n"
            "exit codes: 0 ok, 1 runtime failure, 2 bad usage or input\n");
}

static void summarise(const struct dump *d, const struct render_result *res, const struct frame_info *info,
                      const struct scene *s)
{
    long objects = 0, sky = 0, captured = 0, unfinished = 0, failed = 0, nonfinite = 0;
    size_t n = (size_t)d->width * d->height;
    for (size_t i = 0; i < n; i++) {
        int32_t o = d->records[i].outcome;
        objects += o >= 0;
        sky += o == DUMP_SKY;
        captured += o == DUMP_CAPTURED;
        unfinished += o == DUMP_UNFINISHED;
        failed += o == DUMP_FAILED;
        const float *arrays[4] = {res->position, res->velocity, res->hit, res->image};
        for (int a = 0; a < 4; a++)
            for (int k = 0; k < 4; k++)
                nonfinite += !isfinite(arrays[a][4 * i + k]);
    }
    fprintf(stderr, "%s: %dx%d, %s model, %s on %s (%s), %.3f s, %ld passes\n", s->name, d->width, d->height,
            model_name(s->model.type), info->path_description, info->backend, info->renderer, res->seconds,
            res->passes);
    fprintf(stderr, "rays: %ld hit an object, %ld sky, %ld captured, %ld unfinished, %ld failed\n", objects, sky,
            captured, unfinished, failed);
    if (unfinished)
        fprintf(stderr, "note: %ld rays were still travelling after %d segments; they show the sky in their "
                        "last direction (raise render.segments or render.step)\n", unfinished, s->render.segments);
    if (nonfinite)
        fprintf(stderr, "warning: %ld non-finite values in the ray state\n", nonfinite);
}

int cmd_render(int argc, char **argv)
{
    struct common_options o = {.backend = "auto"};
    const char *out_path = NULL, *dump_path = NULL;
    int force = 0, quiet = 0;
    for (int i = 1; i < argc; i++) {
        int c = options_common(&o, "render", argc, argv, &i);
        if (c < 0)
            return EXIT_USAGE;
        if (c > 0)
            continue;
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            usage(stdout);
            return EXIT_OK;
        } else if (strcmp(argv[i], "--out") == 0 && i + 1 < argc) {
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
    struct render_result res;
    struct frame_info info;
    char err[2048];
    int bad_input;
    if (render_frame(&s, o.backend, &res, 1, &info, err, sizeof err, &bad_input) != 0) {
        fprintf(stderr, "bentray render: %s\n", err);
        return bad_input ? EXIT_USAGE : EXIT_RUNTIME;
    }
    struct dump d;
    char engine[32];
    snprintf(engine, sizeof engine, "gpu %s", info.path_name);
    if (result_to_dump(&res, engine, &d) != 0) {
        render_result_free(&res);
        fprintf(stderr, "bentray render: out of memory\n");
        return EXIT_RUNTIME;
    }
    rc = EXIT_OK;
    if (png_write_rgba8(out_path, res.width, res.height, res.rgba, force, err, sizeof err) != 0) {
        fprintf(stderr, "bentray render: --out: %s\n", err);
        rc = EXIT_RUNTIME;
    } else if (dump_path && dump_write(dump_path, &d, force, err, sizeof err) != 0) {
        fprintf(stderr, "bentray render: --dump: %s\n", err);
        rc = EXIT_RUNTIME;
    }
    if (rc == EXIT_OK) {
        if (!quiet)
            summarise(&d, &res, &info, &s);
        printf("%s\n", out_path);
    }
    dump_free(&d);
    render_result_free(&res);
    return rc;
}
