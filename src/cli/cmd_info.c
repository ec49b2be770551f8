/* bentray info: what the GL back-ends can do, proved by rendering (see src/gl/caps.c). */
#include "cli/commands.h"
#include "cli/options.h"
#include "gl/caps.h"
#include "gl/packing.h"
#include "gl/shader.h"
#include "render/path.h"
#include "render/renderer.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void usage(FILE *out)
{
    fprintf(out, "usage: bentray info [--backend egl|osmesa|auto|all] [--shader-dir DIR]\n"
                 "       bentray info --shader STAGE --scene FILE [--set SECTION.KEY=V ...] [--backend B]\n"
                 "Probe the headless GL back-ends and print their versions, renderer, the float\n"
                 "render-target formats that really work, MRT, fragment highp, and the render path\n"
                 "and pipeline bentray would choose. --backend all (the default) probes every back-end built in.\n"
                 "With --shader, print the fragment shader of pipeline stage STAGE (shaders_es/stage_STAGE.glsl)\n"
                 "as the GL compiles it for that scene, as `bentray render` draws it: the preamble, the\n"
                 "scene's defines, then each file after a comment with its name and a #line with its\n"
                 "number. A stage the scene's pipeline does not run prints nothing (exit 1).\n"
                 "  --shader STAGE       one of: frame, orbit_frame, orbit_walk, orbit_crossings (single\n"
                 "                       pass), segment (fused), setup, integrate, orbit, intersect, terminate, retire, sky\n"
                 "                       (multipass), fill\n");
}

/* Every render path of the ladder (render/path.c), each "yes" or the reason this GPU cannot take
 * it, in the order the automatic choice tries them. */
static void print_paths(const struct gl_caps *c)
{
    static const struct { int fp32, mrt; const char *name; } ladder[4] = {
        {1, 1, "fp32+mrt"}, {1, 0, "fp32"}, {0, 1, "fp16+mrt"}, {0, 0, "fp16"}};
    int any = 0;
    printf("render paths (the first that works and that the scene allows is taken):\n");
    for (int i = 0; i < 4; i++) {
        const struct float_format *f = caps_format(c, ladder[i].fp32);
        char why[240];
        if (!f)
            snprintf(why, sizeof why, "no: no %s float format renders", ladder[i].fp32 ? "32-bit" : "16-bit");
        else if (ladder[i].mrt && !c->mrt_works)
            snprintf(why, sizeof why, "no: MRT does not work (%.200s)", c->mrt_why);
        else if (render_path_state_status(f, ladder[i].mrt) != GL_FRAMEBUFFER_COMPLETE)
            snprintf(why, sizeof why, "no: its ray-state framebuffer (%s) is incomplete", f->name);
        else
            snprintf(why, sizeof why, "yes (%s%s)", f->name, ladder[i].fp32 ? "" : "; reduced accuracy");
        any += why[0] == 'y';
        printf("  %-14s %s\n", ladder[i].name, why);
    }
    int image_only = !any && c->long_loops && c->fragment_highp;
    if (any)
        printf("  %-14s not taken: a float format renders\n", "image only");
    else if (!c->long_loops)
        printf("  %-14s no: %s\n", "image only", c->long_loops_why);
    else if (!c->fragment_highp)
        printf("  %-14s no: the fragment shaders have no highp\n", "image only");
    else
        printf("  %-14s yes (the image%s; the rest of the ray state cannot be read)\n", "image only",
               c->mrt_works ? " and the rays' outcomes in 8-bit targets" : " alone: no MRT for the outcomes");
    /* the packing is probed here whatever the path (cmd_info runs probe_packing) */
    int fp32 = caps_format(c, 1) != NULL;
    if (!c->packing)
        printf("  %-14s no: %s\n", "packed 8-bit", c->packing_why);
    else if (fp32 || image_only || c->long_loops)
        printf("  %-14s not taken: %s (packing floats into RGBA8 texels: exact, %s)\n", "packed 8-bit",
               fp32 ? "a 32-bit float format renders" : image_only ? "the image-only path is"
                    : "the single pass keeps its rays in 32 bits, a 16-bit state stores only their results",
               c->packing_why);
    else
        printf("  %-14s yes%s (each 32-bit float of the ray state in an RGBA8 texel: %s)\n", "packed 8-bit",
               any ? ", before fp16, whose state stored pass after pass would change rays' outcomes" : "",
               c->packing_why);
}

static void print_caps(const struct gl_caps *c)
{
    printf("back-end:        %s (%s)\n", c->backend, c->platform_version);
    printf("GL version:      %s\n", c->version);
    printf("GLSL version:    %s\n", c->glsl_version);
    printf("renderer:        %s (%s)\n", c->renderer, c->vendor);
    printf("fragment highp:  %s (%d mantissa bits)\n", c->fragment_highp ? "yes" : "no", c->fragment_highp_bits);
    printf("arithmetic:      %s%s\n", c->fragment_fp32 ? "32-bit floats (probed)" : "no 32-bit floats: ",
           c->fragment_fp32 ? "" : c->fragment_fp32_why);
    if (!c->long_loops)
        printf("loop turns:      no long loops (GLSL ES 1.00)\n");
    else if (c->loop_turns >= CAPS_LOOP_TURNS_PROBED)
        printf("loop turns:      at least %ld (probed)\n", c->loop_turns);
    else
        printf("loop turns:      %ld: a fragment-shader loop ends there (probed)\n", c->loop_turns);
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
    int have_path = render_path_choose(c, PRECISION_AUTO, MRT_AUTO, &path, &e) == 0;
    if (have_path)
        printf("render path:     %s\n", path.description);
    else
        printf("render path:     none: %.511s\n", e.message);   /* cut at 511 characters, as before */
    print_paths(c);
    int fused = render_path_can_fuse(c, c->mrt_works);
    char else_path[128];
    snprintf(else_path, sizeof else_path, "%s", fused ? "one fused pass a segment (4 draw buffers) where the scene's objects "
                                                        "fit one pass, else multipass" : "multipass");
    if (have_path && path.packed)
        printf("pipeline:        multipass (the packed path writes one float a fragment)\n");
    else if (have_path && path.image_only)
        printf("pipeline:        single pass only, where the scene's objects fit one pass (the image-only path: the "
               "fused pass and the multipass scheme keep the ray state in float textures)\n");
    else if (c->long_loops)
        printf("pipeline:        single pass where the scene's objects fit one pass, else %s (%s)\n", else_path,
               c->long_loops_why);
    else
        printf("pipeline:        %s; the single pass only when forced (%s)\n", else_path, c->long_loops_why);
    if (have_path && path.table_format)
        printf("exact orbits:    yes: render.method = orbit_table's table sampled as %s%s\n", path.table_format->name,
               path.fp32 ? "" : ", in the single pass (rk4 where a frame takes another pipeline)");
    else
        printf("exact orbits:    no: render.method = orbit_table integrates its rays with rk4 here (the table needs "
               "32-bit float textures beside a 32-bit ray state)\n");
    /* render.orbit_walk = auto (stage_frame.c: orbit_walk_separate) */
    if (c->cpu_rasterizer)
        printf("orbit walk:      in the frame's pass (a CPU rasteriser: render.orbit_walk = auto takes inline)\n");
    else
        printf("orbit walk:      a pass of its own, then a pass that finishes each ray (a GPU: render.orbit_walk = "
               "auto takes separate)\n");
    /* render.hit_shading = auto (stage_intersect.c: hit_shading_separate), for the multipass scheme */
    if (c->cpu_rasterizer)
        printf("hit shading:     in the intersection pass (a CPU rasteriser: render.hit_shading = auto takes inline)\n");
    else if (have_path && !path.image_only && !path.mrt && path.fp32)
        printf("hit shading:     a pass of its own after the passes that find the hit (one target a pass on a 32-bit "
               "ray state: render.hit_shading = auto takes separate)\n");
    else
        printf("hit shading:     in the intersection pass (render.hit_shading = auto takes inline: %s)\n",
               !have_path || path.image_only ? "no ray state in float textures here"
               : path.mrt ? "MRT writes both of its targets in one pass" : "a 16-bit ray state");
}

/* The sources of the stage's programs, as compiled, in order. */
struct captured {
    char *source[8];
    int n, more;
};

static void keep_source(const char *source, void *arg)
{
    struct captured *c = arg;
    for (int i = 0; i < c->n; i++)
        if (strcmp(c->source[i], source) == 0)
            return;
    if (c->n == 8) {
        c->more++;
        return;
    }
    c->source[c->n] = strdup(source);
    c->n += c->source[c->n] != NULL;
}

/* bentray info --shader STAGE --scene FILE: one frame of the scene at 8x8 (no program depends on
 * the size), its renderer handing over what it compiles from stage_STAGE.glsl. */
static int print_shader(const struct common_options *o, const char *backend, const char *stage)
{
    char file[64], stages[256];
    snprintf(file, sizeof file, "stage_%s.glsl", stage);
    shader_stage_names(stages, sizeof stages);
    struct error e;
    char *text = strlen(stage) < 40 ? shader_load_text(file, &e) : NULL;
    if (!text) {
        fprintf(stderr, "bentray info: --shader: no stage '%s' (stages: %s)\n", stage, stages);
        return EXIT_USAGE;
    }
    free(text);
    struct scene *s = options_scene_new("info");
    if (!s)
        return EXIT_RUNTIME;
    int rc = options_load_scene(o, "info", s);
    struct gl_context *ctx = NULL;
    struct renderer *r = NULL;
    struct captured c = {0};
    if (rc == EXIT_OK && !(ctx = gl_context_create(strcmp(backend, "all") == 0 ? "auto" : backend, &e))) {
        fprintf(stderr, "bentray info: %s\n", e.message);
        rc = EXIT_RUNTIME;
    }
    if (rc == EXIT_OK && !(r = renderer_create(ctx, s, &e))) {
        fprintf(stderr, "bentray info: %s%s%s\n", e.where, e.where[0] ? ": " : "", e.message);
        rc = exit_code_of(&e);
    }
    if (rc == EXIT_OK) {
        renderer_capture_shaders(r, file, keep_source, &c);
        renderer_set_reads(r, RENDER_READ_IMAGE);
        if (renderer_run(r, s, 0, 0, 8, 8, NULL, NULL, &e) != 0) {
            fprintf(stderr, "bentray info: %s\n", e.message);
            rc = exit_code_of(&e);
        }
    }
    if (rc == EXIT_OK && c.n == 0) {
        fprintf(stderr, "bentray info: --shader %s: the scene's frame runs no program of %s (%s: %s)\n", stage,
                file, renderer_pipeline(r), renderer_pipeline_why(r));
        rc = EXIT_RUNTIME;
    }
    if (rc == EXIT_OK) {
        fputs(c.source[0], stdout);
        fprintf(stderr, "bentray info: %s, the first of %d variant%s compiled for this scene's frame (%s: %s)\n",
                file, c.n + c.more, c.n + c.more == 1 ? "" : "s", renderer_pipeline(r), renderer_pipeline_why(r));
    }
    for (int i = 0; i < c.n; i++)
        free(c.source[i]);
    renderer_destroy(r);
    if (ctx)
        gl_context_destroy(ctx);
    scene_free(s);
    return rc;
}

int cmd_info(int argc, char **argv)
{
    const char *backend = "all", *stage = NULL;
    struct common_options o = {.backend = "auto"};
    enum { BACKEND, SHADER_DIR, SHADER };
    static const struct option_spec specs[] = {{"--backend", "B", BACKEND}, {"--shader-dir", "DIR", SHADER_DIR},
                                               {"--shader", "STAGE", SHADER}, {NULL, NULL, 0}};
    struct option_reader rd = {.cmd = "info", .own = specs, .common = common_option_specs, .usage = usage,
                               .argc = argc, .argv = argv};
    const struct option_spec *sp;
    const char *v;
    int got, scene_options = 0;
    while ((got = option_read(&rd, &sp, &v)) > 0) {
        switch (sp->id) {
        case BACKEND:
            backend = v;
            break;
        case SHADER_DIR:
            shader_set_directory(v);
            break;
        case SHADER:
            stage = v;
            break;
        default:
            if (options_common(&o, "info", sp->id, v) != 0)
                return EXIT_USAGE;
            scene_options = 1;
        }
    }
    if (got < 0)
        return rd.exit_code;
    if (stage && !o.scene_path) {
        fprintf(stderr, "bentray info: --shader STAGE needs --scene FILE: the shader depends on the scene\n");
        return EXIT_USAGE;
    }
    if (!stage && scene_options) {
        fprintf(stderr, "bentray info: --scene and the scene's options go with --shader STAGE\n");
        return EXIT_USAGE;
    }
    if (stage && strcmp(backend, "all") != 0 && !option_backend_valid(backend)) {
        fprintf(stderr, "bentray info: --backend: unknown back-end '%s' (expected egl, osmesa or auto)\n", backend);
        return EXIT_USAGE;
    }
    if (stage)
        return print_shader(&o, backend, stage);
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
            probe_packing(&caps);
            print_caps(&caps);
            printf("\n");
            shown++;
        }
        gl_context_destroy(ctx);
    }
    return shown > 0 && failures == 0 ? EXIT_OK : EXIT_RUNTIME;
}
