/* bentray info: what the GL back-ends can do, proved by rendering (see src/gl/caps.c). */
#include "cli/commands.h"
#include "cli/options.h"
#include "gl/caps.h"
#include "render/path.h"
#include <stdio.h>
#include <string.h>

static void usage(FILE *out)
{
    fprintf(out, "usage: bentray info [--backend egl|osmesa|auto|all] [--shader-dir DIR]\n"
                 "Probe the headless GL back-ends and print their versions, renderer, the float\n"
                 "render-target formats that really work, MRT, fragment highp, and the render path\n"
                 "and pipeline bentray would choose. --backend all (the default) probes every back-end built in.\n");
}

static void print_caps(const struct gl_caps *c)
{
    printf("back-end:        %s (%s)\n", c->backend, c->platform_version);
    printf("GL version:      %s\n", c->version);
    printf("GLSL version:    %s\n", c->glsl_version);
    printf("renderer:        %s (%s)\n", c->renderer, c->vendor);
    printf("fragment highp:  %s (%d mantissa bits)\n", c->fragment_highp ? "yes" : "no", c->fragment_highp_bits);
    printf("max texture:     %d\n", c->max_texture_size);
    printf("float render targets (written, sampled and read back):\n");
    for (int i = 0; i < c->n_formats; i++)
        printf("  %-46s %s%s%s\n", c->formats[i].name, c->formats[i].works ? "works" : "no: ",
               c->formats[i].works ? "" : c->formats[i].why, "");
    printf("draw buffers:    GL_MAX_DRAW_BUFFERS %d; MRT %s%s\n", c->max_draw_buffers,
           c->mrt_works ? "works" : "no: ", c->mrt_works ? "" : c->mrt_why);
    if (c->occlusion_query)
        printf("occlusion query: works: the multipass scheme stops once every ray is retired\n");
    else
        printf("occlusion query: no: the multipass scheme runs every segment (%s)\n", c->query_why);
    if (c->framebuffer_blit)
        printf("framebuffer blit: works: the kiosk copies its canvas to a screen of its size\n");
    else
        printf("framebuffer blit: no: the kiosk draws its canvas on the screen (%s)\n", c->blit_why);
    struct render_path path;
    struct error e;
    if (render_path_choose(c, PRECISION_AUTO, MRT_AUTO, &path, &e) == 0)
        printf("render path:     %s\n", path.description);
    else
        printf("render path:     none: %.511s\n", e.message);   /* cut at 511 characters, as before */
    int fused = render_path_can_fuse(c, c->mrt_works);
    char else_path[128];
    snprintf(else_path, sizeof else_path, "%s", fused ? "one fused pass a segment (4 draw buffers) where the scene's objects "
                                                        "fit one pass, else multipass" : "multipass");
    if (c->long_loops)
        printf("pipeline:        single pass where the scene's objects fit one pass, else %s (%s)\n", else_path,
               c->long_loops_why);
    else
        printf("pipeline:        %s; the single pass only when forced (%s)\n", else_path, c->long_loops_why);
}

int cmd_info(int argc, char **argv)
{
    const char *backend = "all";
    enum { BACKEND, SHADER_DIR };
    static const struct option_spec specs[] = {
        {"--backend", "B", BACKEND}, {"--shader-dir", "DIR", SHADER_DIR}, {NULL, NULL, 0}};
    struct option_reader rd = {.cmd = "info", .own = specs, .usage = usage, .argc = argc, .argv = argv};
    const struct option_spec *sp;
    const char *v;
    int got;
    while ((got = option_read(&rd, &sp, &v)) > 0) {
        switch (sp->id) {
        case BACKEND:
            backend = v;
            break;
        case SHADER_DIR:
            shader_set_directory(v);
            break;
        }
    }
    if (got < 0)
        return rd.exit_code;
    static const char *const all[] = {"egl", "osmesa", NULL};
    const char *one[] = {backend, NULL};
    const char *const *list = strcmp(backend, "all") == 0 ? all : one;
    if (strcmp(backend, "all") != 0 && !option_backend_valid(backend)) {
        fprintf(stderr, "bentray info: --backend: unknown back-end '%s' (expected egl, osmesa, auto or all)\n", backend);
        return EXIT_USAGE;
    }
    int failures = 0, shown = 0;
    for (int i = 0; list[i]; i++) {
        struct error e;
        if (list == all && !gl_backend_built(list[i])) {
            printf("back-end:        %s (not built in)\n\n", list[i]);
            continue;
        }
        struct gl_context *ctx = gl_context_create(list[i], &e);
        if (!ctx) {
            printf("back-end:        %s: unavailable: %s\n\n", list[i], e.message);
            failures++;
            continue;
        }
        struct gl_caps caps;
        if (gl_caps_probe(&caps, ctx, &e) != 0) {
            printf("back-end:        %s: probe failed: %s\n\n", list[i], e.message);
            failures++;
        } else {
            print_caps(&caps);
            printf("\n");
            shown++;
        }
        gl_context_destroy(ctx);
    }
    return shown > 0 && failures == 0 ? EXIT_OK : EXIT_RUNTIME;
}
