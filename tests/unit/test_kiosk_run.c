/* The kiosk's loop, headless, driven by a script (tests/kiosk/visitor.events): the frames it
 * writes are compared with the renderer's own images of the scenes the state describes, pixel for
 * pixel, so a knob, a button, the preview, the refinement bands and the compositor are all
 * checked by what ends up on screen. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include "kiosk_config/kiosk_config.h"
#include "io/png_io.h"
#include "kiosk/compositor.h"
#include "kiosk/kiosk_loop.h"
#include "kiosk/kiosk_state.h"
#include "kiosk/kiosk_view.h"
#include "render/frame.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define FRAMES 8
#define RESET_FRAME 6
#define PIPELINE_FRAME 7
static struct kiosk_config config;
static char out_dir[64];
static unsigned char *frames[FRAMES];
static int width, height;
static int compile_ahead = KIOSK_AHEAD_AUTO;   /* [kiosk] compile_ahead of the next run */
static char run_log[8192];                     /* the last run's log */

/* Runs the kiosk of config_path until it has written n frames; reads them into out. */
static void run_config(const char *config_path, int n, unsigned char **out)
{
    struct error e;
    if (kiosk_config_load(&config, config_path, &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    snprintf(out_dir, sizeof out_dir, "/tmp/bt_kiosk_XXXXXX");
    assert_non_null(mkdtemp(out_dir));
    snprintf(config.display.headless_out, sizeof config.display.headless_out, "%s", out_dir);
    config.display.headless_frames = n;
    config.kiosk.compile_ahead = compile_ahead;
    /* the frames are compared with the renderer's one-ray images: the anti-aliasing that follows a
     * refinement at rest has its own tests (test_kiosk_antialias.c, tests/render/kiosk.sh) */
    config.kiosk.refine_samples = 1;
    if (kiosk_config_check(&config, &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    FILE *log = tmpfile();
    struct kiosk_run_options o = {.gl_backend = "egl", .force = 0, .log = log};
    int rc = kiosk_run(&config, &o);
    rewind(log);
    char line[512];
    run_log[0] = 0;
    while (fgets(line, sizeof line, log)) {
        print_message("log: %s", line);
        strncat(run_log, line, sizeof run_log - strlen(run_log) - 1);
    }
    fclose(log);
    assert_int_equal(rc, 0);
    for (int i = 0; i < n; i++) {
        char path[128];
        snprintf(path, sizeof path, "%s/frame_%04d.png", out_dir, i + 1);
        struct error err;
        assert_int_equal(png_read_rgba8(path, 4096, &width, &height, &out[i], &err), 0);
        assert_int_equal(width, config.kiosk.width);
        assert_int_equal(height, config.kiosk.height);
        unlink(path);
    }
    rmdir(out_dir);
}

static int run_kiosk(void **state)
{
    (void)state;
    run_config("tests/kiosk/headless.conf", FRAMES, frames);
    return 0;
}

static int free_frames(void **state)
{
    (void)state;
    for (int i = 0; i < FRAMES; i++)
        free(frames[i]);
    return 0;
}

/* The renderer's image of the state's scene file with the state applied, at the kiosk's size, or
 * of its preview. */
static unsigned char *expected_image(const struct kiosk_state *st, int preview)
{
    static struct scene base, s;
    struct error e;
    if (scene_load(&base, config.kiosk.scenes[st->scene], &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    base.render.width = config.kiosk.width;
    base.render.height = config.kiosk.height;
    base.render.star_pass = STAR_PASS_GPU;   /* as the kiosk draws its stars */
    if (kiosk_state_apply(st, &base, &s, &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    if (preview) {
        static struct scene full;
        full = s;
        kiosk_preview_scene(&full, config.kiosk.preview_width, config.kiosk.preview_height, &s);
    }
    struct render_result res;
    struct frame_info info;
    struct error gl_err;
    if (render_frame(&s, &(struct frame_request){.backend = "egl"}, &res, &info, &gl_err) != 0)
        fail_msg("%s", gl_err.message);
    unsigned char *rgba = res.rgba;
    res.rgba = NULL;
    render_result_free(&res);
    return rgba;
}

static int max_difference(const unsigned char *a, const unsigned char *b)
{
    int worst = 0;
    for (int i = 0; i < width * height * 4; i++)
        worst = abs(a[i] - b[i]) > worst ? abs(a[i] - b[i]) : worst;
    return worst;
}

static void check_image(const unsigned char *image, int frame, const struct kiosk_state *st, const char *what)
{
    unsigned char *want = expected_image(st, 0);
    int worst = max_difference(image, want);
    print_message("frame %d (%s): largest difference from the renderer's image %d\n", frame + 1, what, worst);
    /* the refined frame is the renderer's image band by band, copied texel for texel */
    assert_int_equal(worst, 0);
    free(want);
}

static void check_frame(int frame, const struct kiosk_state *st, const char *what)
{
    check_image(frames[frame], frame, st, what);
}

/* The mass knob turned by `counts` detents, as the kiosk does: the key the scene's [kiosk] maps it
 * to (the shipped black holes map model.mass), or the black hole's mass itself. */
static void turn_mass(struct kiosk_state *st, long counts)
{
    static struct scene s;
    struct error e;
    if (scene_load(&s, config.kiosk.scenes[st->scene], &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    if (s.kiosk.mass.key[0])
        st->mass_param = knob_turn_mapped(&s.kiosk.mass, &s, st->mass_param, counts);
    else
        st->mass = knob_turn(&config.mass, st->mass, counts);
}

static void test_refined_frames_are_the_scenes_images(void **state)
{
    (void)state;
    struct kiosk_state st;
    kiosk_state_reset(&st, &config);
    check_frame(0, &st, "start");
    st.speed = knob_turn(&config.speed, st.speed, 20);
    check_frame(2, &st, "speed knob +20");
    turn_mass(&st, 4);
    check_frame(3, &st, "mass knob +4");
    st.scene = 1;
    st.mass_param = NAN;              /* a mapped key starts at the next scene's own value */
    check_frame(4, &st, "next scene");
    /* the effects button goes on from the scene's own (starflight: searchlight) to the next */
    static struct scene shown;
    struct error e;
    if (scene_load(&shown, config.kiosk.scenes[st.scene], &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    assert_int_equal(kiosk_state_effects(&st, &shown), shown.observer.effects);
    kiosk_state_action(&st, &config, &shown, KIOSK_ACTION_CYCLE_EFFECTS);
    assert_int_equal(kiosk_state_effects(&st, &shown), (shown.observer.effects + 1) % 3);
    check_frame(5, &st, "the effects button");
}

/* Every control changes what is on screen, and reset brings back the first frame exactly. */
static void test_controls_change_the_picture(void **state)
{
    (void)state;
    for (int i = 1; i < FRAMES; i++)
        assert_true(max_difference(frames[i], frames[i - 1]) > 0);
    assert_int_equal(max_difference(frames[RESET_FRAME], frames[0]), 0);
}

/* Bilinear upscaling with texel centres at half-integers and clamped edges, as GL filters. */
static double sample(const unsigned char *img, int w, int h, double x, double y, int ch)
{
    x = fmin(fmax(x, 0.0), w - 1.0);
    y = fmin(fmax(y, 0.0), h - 1.0);
    int x0 = (int)x, y0 = (int)y, x1 = x0 + 1 < w ? x0 + 1 : x0, y1 = y0 + 1 < h ? y0 + 1 : y0;
    double fx = x - x0, fy = y - y0;
#define AT(X, Y) img[((size_t)(Y) * w + (X)) * 4 + ch]
    return (1 - fy) * ((1 - fx) * AT(x0, y0) + fx * AT(x1, y0)) + fy * ((1 - fx) * AT(x0, y1) + fx * AT(x1, y1));
#undef AT
}

/* A turn shows the preview at once, in the same frame: the renderer's image of the preview scene
 * (a quarter of the rays, steps twice as long), upscaled over the canvas. */
static void test_preview_comes_first(void **state)
{
    (void)state;
    struct kiosk_state st;
    kiosk_state_reset(&st, &config);
    st.speed = knob_turn(&config.speed, st.speed, 20);
    unsigned char *small = expected_image(&st, 1);
    int pw = config.kiosk.preview_width, ph = config.kiosk.preview_height, worst = 0;
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++)
            for (int ch = 0; ch < 3; ch++) {
                double want = sample(small, pw, ph, (x + 0.5) * pw / width - 0.5, (y + 0.5) * ph / height - 0.5, ch);
                int d = (int)fabs(frames[1][((size_t)y * width + x) * 4 + ch] - want);
                worst = d > worst ? d : worst;
            }
    free(small);
    print_message("preview frame against the preview image upscaled: largest difference %d levels; "
                  "against the refined frame %d\n", worst, max_difference(frames[1], frames[2]));
    /* bound: GL weighs the four texels with fixed-point fractions (8 bits on llvmpipe), so its
     * blend may round differently from the exact one by a level or two */
    assert_true(worst <= 2);
    assert_true(max_difference(frames[1], frames[2]) > 0);
}

/* After idle_seconds without input the tour plays (its own knob turns and scene change), each pass
 * from the start state, so the second pass shows what the first did; the first touch of a knob
 * ends it at once, from the start state (tests/kiosk/attract.conf). */
static void test_attract_mode(void **state)
{
    (void)state;
    static struct kiosk_config visitor_config;
    visitor_config = config;
    unsigned char *shown[4];
    run_config("tests/kiosk/attract.conf", 4, shown);
    struct kiosk_state st;
    kiosk_state_reset(&st, &config);
    check_image(shown[0], 0, &st, "before the tour");
    st.speed = knob_turn(&config.speed, st.speed, 10);
    st.scene = 1;
    check_image(shown[1], 1, &st, "the tour, one second in");
    check_image(shown[2], 2, &st, "the tour's second pass, one second in");
    kiosk_state_reset(&st, &config);
    turn_mass(&st, 2);
    check_image(shown[3], 3, &st, "a visitor took over");
    for (int i = 0; i < 4; i++)
        free(shown[i]);
    config = visitor_config;
}

/* Pixel (x, y) of panel k of the pipeline frame (x, y from the panel's top-left corner). */
static const unsigned char *panel_pixel(int k, int x, int y)
{
    int px, py, pw, ph;
    pipeline_panel_rect(width, height, k, &px, &py, &pw, &ph);
    return &frames[PIPELINE_FRAME][((size_t)(py + y) * width + px + x) * 4];
}

/* The pipeline view shows the renderer's own ray state in a 3 x 2 grid; its last panel colours each
 * ray by its outcome, in exactly one of five colours (shaders_es/kiosk_pipeline.glsl). The start
 * view of the black hole has rays that hit objects, rays that reach the sky and captured rays.
 * Every panel keeps the frame's aspect ratio, centred in its cell with black above and below. The
 * segment-of-the-hit panel colours the rays that hit an object only. With exact orbits its
 * step-size panel shows the orbit table instead. */
static void test_pipeline_view(void **state)
{
    (void)state;
    static const unsigned char outcome[5][3] = {
        {51, 204, 77}, {77, 128, 255}, {0, 0, 0}, {230, 26, 26}, {230, 26, 230}};
    int seen[5] = {0}, other = 0;
    int px, py, pw, ph;
    pipeline_panel_rect(width, height, 5, &px, &py, &pw, &ph);
    print_message("panels of %dx%d on a %dx%d canvas, the outcome panel's at (%d, %d)\n", pw, ph, width, height,
                  px, py);
    /* the frame's aspect, to a pixel */
    assert_true(abs(pw * height - ph * width) <= width + height);
    assert_true(pw <= width / 3 && ph <= height / 2);
    /* black where a cell is wider or higher than its panel: the row above the outcome panel */
    if (py > height / 2)
        for (int x = 0; x < pw; x++) {
            const unsigned char *p = &frames[PIPELINE_FRAME][((size_t)(py - 1) * width + px + x) * 4];
            assert_true(p[0] == 0 && p[1] == 0 && p[2] == 0);
        }
    /* the outcome panel, less a pixel at each edge (where the canvas's filter may mix in the band)
     * and its upper quarter (the HUD may write the panel's label there on a small canvas) */
    int hit_grey = 0, hit_coloured = 0, missed_coloured = 0;
    for (int y = ph / 4; y < ph - 1; y++)
        for (int x = 1; x < pw - 1; x++) {
            const unsigned char *p = panel_pixel(5, x, y);
            int k = 0;
            while (k < 5 && (abs(p[0] - outcome[k][0]) > 1 || abs(p[1] - outcome[k][1]) > 1 ||
                             abs(p[2] - outcome[k][2]) > 1))
                k++;
            if (k < 5)
                seen[k]++;
            else
                other++;
            /* the same ray in the segment-of-the-hit panel: grey (64) where it hit nothing */
            const unsigned char *d = panel_pixel(3, x, y);
            int grey = abs(d[0] - 64) <= 1 && abs(d[1] - 64) <= 1 && abs(d[2] - 64) <= 1;
            hit_grey += k == 0 && grey;
            hit_coloured += k == 0 && !grey;
            missed_coloured += (k == 1 || k == 2) && !grey;
        }
    print_message("outcome panel: %d object, %d sky, %d captured, %d unfinished, %d failed, %d other pixels\n",
                  seen[0], seen[1], seen[2], seen[3], seen[4], other);
    print_message("segment-of-the-hit panel: %d hits coloured, %d hits grey, %d sky or captured coloured\n",
                  hit_coloured, hit_grey, missed_coloured);
    assert_int_equal(other, 0);
    assert_true(seen[0] > 0 && seen[1] > 0 && seen[2] > 0);
    assert_true(hit_coloured > 0);
    assert_int_equal(hit_grey, 0);
    assert_int_equal(missed_coloured, 0);

    /* below the outcome panel its legend: each of the five colours; below the segment-of-the-hit
     * panel its colour scale, blue (the first segment) at its left end, red (the last) at its right */
    int lx, ly, lw, lh, legend[5] = {0};
    assert_int_equal(pipeline_legend_rect(width, height, 5, &lx, &ly, &lw, &lh), 0);
    for (int x = lx; x < lx + lw; x++) {
        const unsigned char *p = &frames[PIPELINE_FRAME][((size_t)(ly + lh / 2) * width + x) * 4];
        for (int k = 0; k < 5; k++)
            legend[k] += abs(p[0] - outcome[k][0]) <= 1 && abs(p[1] - outcome[k][1]) <= 1 &&
                         abs(p[2] - outcome[k][2]) <= 1;
    }
    print_message("outcome legend: %d %d %d %d %d pixels of each colour\n", legend[0], legend[1], legend[2],
                  legend[3], legend[4]);
    for (int k = 0; k < 5; k++)
        assert_true(legend[k] > 0);
    assert_int_equal(pipeline_legend_rect(width, height, 3, &lx, &ly, &lw, &lh), 0);
    const unsigned char *first = &frames[PIPELINE_FRAME][((size_t)(ly + lh / 2) * width + lx) * 4];
    const unsigned char *last = &frames[PIPELINE_FRAME][((size_t)(ly + lh / 2) * width + lx + lw - 1) * 4];
    print_message("segment scale: (%d, %d, %d) at its left end, (%d, %d, %d) at its right\n", first[0], first[1],
                  first[2], last[0], last[1], last[2]);
    assert_true(first[2] > 200 && first[0] < 40);
    assert_true(last[0] > 200 && last[2] < 40);

    /* The black hole's rays follow exact orbits, so the step-size panel (bottom middle) shows the
     * orbit table: each row one orbit, coloured by 1/r against the horizon's, escaping orbits in
     * its upper half, captured ones in its lower. Only captured orbits come near the horizon
     * (red: 1/r at 0.9 of the horizon's or more, ramp() in kiosk_pipeline.glsl); no escaping
     * orbit comes nearer than the photon sphere (2/3, where the red channel is at most 140 of 255). */
    int near_horizon[2] = {0, 0}, panel_pixels = 0;
    pipeline_panel_rect(width, height, 4, &px, &py, &pw, &ph);
    for (int y = 1; y < ph - 1; y++) {
        int lower = y >= ph / 2;
        if (y == ph / 2 - 1 || y == ph / 2)
            continue;                  /* the middle line, where the canvas's filter mixes both halves */
        for (int x = 1; x < pw - 1; x++) {
            const unsigned char *p = panel_pixel(4, x, y);
            near_horizon[lower] += p[0] >= 230 && p[1] <= 100 && p[2] <= 40;
            panel_pixels++;
        }
    }
    print_message("orbit table panel: %d of %d pixels near the horizon in the escaping half, %d in the captured "
                  "half\n", near_horizon[0], panel_pixels, near_horizon[1]);
    assert_int_equal(near_horizon[0], 0);
    assert_true(near_horizon[1] > 0);
}

/* With steps of fixed size every ray's step is the scene's, and the step-size panel shows the steps
 * each ray took instead (blue none to red the whole budget), or with lorenz's far steps the path
 * each ray took (its state's w): lorenz's rays that hit an object near the camera take little of it,
 * those that reach the sky much, so the panel is not one colour. */
static void test_pipeline_steps_taken(void **state)
{
    (void)state;
    struct kiosk_config saved = config;
    unsigned char *frame[1];
    run_config("tests/kiosk/pipeline_lorenz.conf", 1, frame);
    int px, py, pw, ph, bluer = 0, greener = 0;
    pipeline_panel_rect(width, height, 4, &px, &py, &pw, &ph);
    for (int y = py + ph / 4; y < py + ph - 1; y++)
        for (int x = px + 1; x < px + pw - 1; x++) {
            const unsigned char *p = &frame[0][((size_t)y * width + x) * 4];
            bluer += p[2] > 200 && p[1] < 150;
            greener += p[1] > 200 && p[2] < 200;
        }
    print_message("steps-taken panel: %d pixels of few steps (blue), %d of more (green and on)\n", bluer, greener);
    assert_true(bluer > 0 && greener > 0);
    free(frame[0]);
    config = saved;
}

/* The canvas is copied to a screen of its size where the GL can (glBlitFramebuffer), and the HUD
 * blended over the rows it covers. The frames of a run with the HUD on are the same bytes as
 * those of the plain way, the canvas drawn as a quad and the whole HUD blended over it (the fault
 * hooks framebuffer_blit and hud_whole), and the HUD is really on them. */
static void test_screen_copied_or_drawn(void **state)
{
    (void)state;
    unsigned char *copied[FRAMES], *drawn[FRAMES];
    run_config("tests/kiosk/headless_hud.conf", FRAMES, copied);
    setenv("BT_FAULT", "framebuffer_blit hud_whole", 1);
    run_config("tests/kiosk/headless_hud.conf", FRAMES, drawn);
    unsetenv("BT_FAULT");
    /* the pipeline view labels its panels (hud.c) from the bands above them, and covers none of
     * them below their upper halves, where a label may reach on a canvas this small (the HUD's
     * lines would cover the image panel there): the HUD is drawn again when the view changes,
     * though its lines' text does not */
    int label = 0, covered = 0;
    for (int k = 0; k < PIPELINE_COLUMNS * PIPELINE_ROWS; k++) {
        int px, py, pw, ph;
        pipeline_panel_rect(width, height, k, &px, &py, &pw, &ph);
        for (int y = (k / PIPELINE_COLUMNS) * (height / PIPELINE_ROWS); y < py + ph; y++)
            for (int x = px; x < px + pw; x++) {
                int differs = memcmp(&copied[PIPELINE_FRAME][((size_t)y * width + x) * 4],
                                     &frames[PIPELINE_FRAME][((size_t)y * width + x) * 4], 4) != 0;
                label += y < py && differs;
                covered += y >= py + ph / 2 && differs;
            }
    }
    print_message("pipeline view: %d pixels of the panels' labels, %d of the panels covered\n", label, covered);
    assert_true(label > 0);
    assert_int_equal(covered, 0);
    int hud_pixels = 0;
    for (int f = 0; f < FRAMES; f++) {
        for (int i = 0; i < width * height * 4; i++)
            hud_pixels += copied[f][i] != frames[f][i];
        print_message("frame %d with the HUD: largest difference copied / drawn %d\n", f + 1,
                      max_difference(copied[f], drawn[f]));
        assert_memory_equal(copied[f], drawn[f], (size_t)width * height * 4);
        free(copied[f]);
        free(drawn[f]);
    }
    print_message("%d bytes of the frames differ from those without the HUD\n", hud_pixels);
    assert_true(hud_pixels > 0);
}

/* compile_ahead = on: every program of both scenes is compiled before the first frame, the
 * visitor's script (two scenes, both knobs, the effects, reset, the pipeline view) then compiles
 * none, and the frames are those of the run that compiled as it went: programs shared between the
 * scenes carry nothing of one scene into the other. */
/* A scene with point stars and the Milky Way (star_sky.scene): the kiosk's frame is the renderer's
 * image with its stars drawn in the frame's own pass (render.star_pass = gpu, whose stars
 * test_stars.c checks against the CPU's pass), and those stars are there: hundreds of pixels
 * brighter than the same frame without them. */
static void test_stars_in_the_kiosk(void **state)
{
    (void)state;
    unsigned char *shown[2];
    run_config("tests/kiosk/stars.conf", 2, shown);
    struct kiosk_state st;
    kiosk_state_reset(&st, &config);
    check_image(shown[0], 0, &st, "stars");
    static struct scene base, s;
    struct error e;
    if (scene_load(&base, config.kiosk.scenes[0], &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    base.render.width = config.kiosk.width;
    base.render.height = config.kiosk.height;
    base.sky.stars = 0;
    base.sky.milky_way = 0.0;
    if (kiosk_state_apply(&st, &base, &s, &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    struct render_result dark;
    if (render_frame(&s, &(struct frame_request){.backend = "egl"}, &dark, NULL, &e) != 0)
        fail_msg("%s", e.message);
    int brighter = 0;
    for (int i = 0; i < width * height; i++)
        brighter += shown[0][4 * i] + shown[0][4 * i + 1] + shown[0][4 * i + 2] >
                    dark.rgba[4 * i] + dark.rgba[4 * i + 1] + dark.rgba[4 * i + 2] + 90;
    print_message("%d pixels lit by the stars\n", brighter);
    assert_true(brighter >= 200);
    render_result_free(&dark);
    free(shown[0]);
    free(shown[1]);
}

static void test_programs_compiled_ahead(void **state)
{
    (void)state;
    unsigned char *ahead[FRAMES];
    compile_ahead = KIOSK_AHEAD_ON;
    run_config("tests/kiosk/headless.conf", FRAMES, ahead);
    compile_ahead = KIOSK_AHEAD_AUTO;
    long before = -1, after = -1;
    const char *at = strstr(run_log, "shader programs compiled ahead");
    assert_non_null(at);
    while (at > run_log && at[-1] != ' ')
        at--;
    while (at > run_log && at[-1] == ' ')
        at--;
    while (at > run_log && at[-1] != ' ')
        at--;
    before = strtol(at, NULL, 10);
    const char *end = strstr(run_log, "frames drawn, ");
    assert_non_null(end);
    after = strtol(end + strlen("frames drawn, "), NULL, 10);
    print_message("%ld programs compiled ahead, %ld after\n", before, after);
    assert_true(before >= 4);
    assert_int_equal(after, 0);
    for (int f = 0; f < FRAMES; f++) {
        assert_memory_equal(ahead[f], frames[f], (size_t)width * height * 4);
        free(ahead[f]);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_refined_frames_are_the_scenes_images),
        cmocka_unit_test(test_controls_change_the_picture),
        cmocka_unit_test(test_preview_comes_first),
        cmocka_unit_test(test_pipeline_view),
        cmocka_unit_test(test_pipeline_steps_taken),
        cmocka_unit_test(test_attract_mode),
        cmocka_unit_test(test_screen_copied_or_drawn),
        cmocka_unit_test(test_stars_in_the_kiosk),
        cmocka_unit_test(test_programs_compiled_ahead),
    };
    return cmocka_run_group_tests(tests, run_kiosk, free_frames);
}
