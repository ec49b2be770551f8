/* The kiosk in an X11 window, on a private Xvfb server: once the visitor's knob turn is refined
 * and the HUD has settled, the window shows, pixel for pixel, the frame the headless kiosk writes
 * for the same script (the scene with the HUD over it, read from the server as any screenshot
 * would be); the HUD's block is really there in the top-left corner; a window laid over it and
 * taken away leaves the picture whole; and SIGTERM stops the kiosk cleanly, at once, saying so in
 * its log.
 *
 * The windowed kiosk runs in a child process on the real clock, forked before this process opens
 * any GL context; the headless one runs here on its virtual clock. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include "io/png_io.h"
#include "kiosk_config/kiosk_config.h"
#include "kiosk/kiosk_loop.h"
#include "kiosk/kiosk_state.h"
#include "render/frame.h"
#include "xvfb.h"

#define WINDOW_TITLE "bentray kiosk"
#define FRAME_WIDTH 320
#define FRAME_HEIGHT 180
#define PREVIEW_WIDTH 160
#define PREVIEW_HEIGHT 90
#define SCENE_FILE "assets/scenes/schwarzschild.scene"
#define HUD_FONT KIOSK_DEFAULT_FONT
/* The scene's own black hole (its file's M), so that the window shows light bent. */
#define MASS 0.12
/* The visitor: one turn of the speed knob, s after the start, then nothing. */
#define TURN_SECONDS 0.2
#define TURN_COUNTS 10
/* The HUD counts the frames drawn over each whole second, s. */
#define FPS_WINDOW_SECONDS 1.0
/* The headless frame is taken once everything the turn shows for a while has gone: the knob's
 * indicator (KIOSK_INDICATOR_SECONDS after the turn) and the frames/s line (hidden after a whole
 * window without drawing, once refined), with a second to spare; s on the virtual clock. */
#define SPARE_SECONDS 1.0
#define FRAME_SECONDS (TURN_SECONDS + KIOSK_INDICATOR_SECONDS + FPS_WINDOW_SECONDS + SPARE_SECONDS)
#define GRAB_INTERVAL_SECONDS 0.2
/* Longer than the HUD's frames/s window, so that a line coming back would be seen. */
#define STABLE_SECONDS (1.5 * FPS_WINDOW_SECONDS)
#define SETTLE_TIMEOUT_SECONDS 30.0
/* a bound no plausible load reaches: the test proves the stop, and prints the time it took */
#define STOP_SECONDS 30.0
/* Long enough for the server to have drawn the covering window, and its going. */
#define COVER_SECONDS 0.3
/* The corner the HUD's block starts in, px: its margin and padding are half a text height. */
#define HUD_CORNER_WIDTH (FRAME_WIDTH / 4)
#define HUD_CORNER_HEIGHT (FRAME_HEIGHT / 8)
/* The block's lines (title, explanation, speed, mass) end in the top half; the knob's indicator
 * lies in the bottom quarter (its bar a tenth of the height up, its label just above). */
#define HUD_BLOCK_BOTTOM (FRAME_HEIGHT / 2)
#define INDICATOR_TOP (FRAME_HEIGHT * 3 / 4)

static struct xvfb xvfb;
static char work_dir[64];
static char config_path[128], headless_events[128], window_events[128], kiosk_log[128], frames_dir[128];
static struct kiosk_config headless_config, window_config;
static pid_t kiosk_pid = -1;
static double kiosk_started;
static unsigned char *headless_frame;   /* RGBA, top row first */
static unsigned char *window_pixels;    /* RGB, top row first, the last screenshot */
static int keep_work_dir;               /* a failure left pictures there to look at */

/* ---- files -------------------------------------------------------------------------------- */

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f)
        fail_msg("cannot write %s", path);
    fputs(text, f);
    assert_int_equal(fclose(f), 0);
}

static void print_file(const char *path, const char *prefix)
{
    FILE *f = fopen(path, "r");
    char line[1024];
    while (f && fgets(line, sizeof line, f))
        print_message("%s%s", prefix, line);
    if (f)
        fclose(f);
}

static int file_has(const char *path, const char *text)
{
    FILE *f = fopen(path, "r");
    char line[1024];
    int found = 0;
    while (f && !found && fgets(line, sizeof line, f))
        found = strstr(line, text) != NULL;
    if (f)
        fclose(f);
    return found;
}

/* The configuration (the headless one, as a file; the window's is the same with backend x11 and
 * a script without the frame event) and the two scripts, in a fresh directory. */
static void write_kiosk_files(void)
{
    char cwd[PATH_MAX], scene[PATH_MAX + 64], text[2 * PATH_MAX];
    assert_non_null(getcwd(cwd, sizeof cwd));
    assert_true(strlen(cwd) + strlen(SCENE_FILE) + 2 < KIOSK_PATH_LEN);
    snprintf(scene, sizeof scene, "%s/%s", cwd, SCENE_FILE);
    snprintf(work_dir, sizeof work_dir, "/tmp/bt_kiosk_x11_XXXXXX");
    assert_non_null(mkdtemp(work_dir));
    snprintf(config_path, sizeof config_path, "%s/kiosk.conf", work_dir);
    snprintf(headless_events, sizeof headless_events, "%s/headless.events", work_dir);
    snprintf(window_events, sizeof window_events, "%s/window.events", work_dir);
    snprintf(kiosk_log, sizeof kiosk_log, "%s/kiosk.log", work_dir);
    snprintf(frames_dir, sizeof frames_dir, "%s/frames", work_dir);
    assert_int_equal(mkdir(frames_dir, 0700), 0);

    snprintf(text, sizeof text, "%.2f turn speed +%d\n", TURN_SECONDS, TURN_COUNTS);
    write_file(window_events, text);
    snprintf(text, sizeof text, "%.2f turn speed +%d\n%.2f frame\n", TURN_SECONDS, TURN_COUNTS, FRAME_SECONDS);
    write_file(headless_events, text);
    snprintf(text, sizeof text,
             "[kiosk]\n"
             "scenes = %s\n"
             "width = %d\nheight = %d\n"
             "preview_width = %d\npreview_height = %d\n"
             "hud = on\n"
             /* the settled window is compared with the renderer's one-ray image: the anti-aliasing
              * at rest has its own tests (test_kiosk_antialias.c) */
             "refine_samples = 1\n"
             "font = %s\n"
             "[display]\n"
             "backend = headless\n"
             "headless_out = %s\n"
             "headless_frames = 1\n"
             "[speed]\ninput = visitor\n"
             "[mass]\ninput = visitor\nstart = %.2f\n"
             "[input visitor]\ntype = script\npath = %s\n",
             scene, FRAME_WIDTH, FRAME_HEIGHT, PREVIEW_WIDTH, PREVIEW_HEIGHT, HUD_FONT, frames_dir, MASS,
             headless_events);
    write_file(config_path, text);

    struct error e;
    if (kiosk_config_load(&headless_config, config_path, &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    if (kiosk_config_check(&headless_config, &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    window_config = headless_config;
    window_config.display.backend = KIOSK_BACKEND_X11;
    window_config.display.headless_out[0] = '\0';
    window_config.display.headless_frames = 0;
    snprintf(window_config.inputs[0].path, sizeof window_config.inputs[0].path, "%s", window_events);
    if (kiosk_config_check(&window_config, &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
}

/* ---- the two kiosks ----------------------------------------------------------------------- */

/* The windowed kiosk in a child process, on the private server, logging to kiosk_log. */
static void start_window_kiosk(void)
{
    kiosk_started = monotonic_seconds();
    kiosk_pid = fork();
    if (kiosk_pid < 0)
        fail_msg("fork: %s", strerror(errno));
    if (kiosk_pid > 0)
        return;
#ifdef __linux__
    prctl(PR_SET_PDEATHSIG, SIGKILL);        /* a test that crashes leaves no kiosk behind */
#endif
    /* a crash of the kiosk is its own, not a failed test that the copy of the runner goes on from */
    static const int fatal[] = {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT};
    for (size_t i = 0; i < sizeof fatal / sizeof fatal[0]; i++)
        signal(fatal[i], SIG_DFL);
    setenv("DISPLAY", xvfb.display, 1);
    FILE *log = fopen(kiosk_log, "w");
    if (!log)
        _exit(3);
    setvbuf(log, NULL, _IOLBF, 0);           /* readable while it runs, should the test fail */
    struct kiosk_run_options o = {.gl_backend = "egl", .force = 0, .log = log};
    int rc = kiosk_run(&window_config, &o);
    fclose(log);
    _exit(rc);
}

static void run_headless_kiosk(void)
{
    char log_path[160];
    snprintf(log_path, sizeof log_path, "%s/headless.log", work_dir);
    FILE *log = fopen(log_path, "w");
    assert_non_null(log);
    struct kiosk_run_options o = {.gl_backend = "egl", .force = 0, .log = log};
    int rc = kiosk_run(&headless_config, &o);
    fclose(log);
    print_file(log_path, "headless log: ");
    unlink(log_path);
    assert_int_equal(rc, 0);
    char frame_path[192];
    struct error err;
    snprintf(frame_path, sizeof frame_path, "%s/frame_0001.png", frames_dir);
    int w = 0, h = 0;
    if (png_read_rgba8(frame_path, 4096, &w, &h, &headless_frame, &err) != 0)
        fail_msg("%s", err.message);
    unlink(frame_path);
    assert_int_equal(w, FRAME_WIDTH);
    assert_int_equal(h, FRAME_HEIGHT);
}

static int group_setup(void **state)
{
    (void)state;
    if (xvfb_start(&xvfb) != 0)
        return -1;
    if (xvfb.missing)
        return 0;
    write_kiosk_files();
    /* first, while this process has no GL context whose threads a fork would leave behind */
    start_window_kiosk();
    run_headless_kiosk();
    return 0;
}

static int group_teardown(void **state)
{
    (void)state;
    if (kiosk_pid > 0) {
        kill(kiosk_pid, SIGKILL);
        waitpid(kiosk_pid, NULL, 0);
        kiosk_pid = -1;
    }
    xvfb_stop(&xvfb);
    free(headless_frame);
    free(window_pixels);
    if (work_dir[0] && !keep_work_dir) {
        unlink(config_path);
        unlink(headless_events);
        unlink(window_events);
        unlink(kiosk_log);
        rmdir(frames_dir);
        rmdir(work_dir);
    }
    return 0;
}

static void need_xvfb(void)
{
    if (xvfb.missing) {
        print_message("skipped: %s\n", xvfb.missing);
        skip();
    }
}

/* The kiosk's exit, if it has exited: fails with its log. */
static void kiosk_still_running(void)
{
    int status;
    if (kiosk_pid <= 0)                      /* never kill(-1) or waitpid(-1) below */
        fail_msg("the windowed kiosk is no longer running");
    if (waitpid(kiosk_pid, &status, WNOHANG) != kiosk_pid)
        return;
    kiosk_pid = -1;
    print_file(kiosk_log, "kiosk log: ");
    if (WIFSIGNALED(status))
        fail_msg("the windowed kiosk died of signal %d", WTERMSIG(status));
    fail_msg("the windowed kiosk exited with status %d", WEXITSTATUS(status));
}

/* ---- the window, as another client sees it ------------------------------------------------ */

static int x_errors;

/* A window that is not viewable yet (or gone) refuses XGetImage with BadMatch: try again later. */
static int count_x_error(Display *dpy, XErrorEvent *e)
{
    (void)dpy;
    (void)e;
    x_errors++;
    return 0;
}

/* A channel of a pixel as 8 bits, from the visual's mask for it. */
static unsigned char channel(unsigned long pixel, unsigned long mask)
{
    if (!mask)
        return 0;
    int shift = 0, bits = 0;
    while (!((mask >> shift) & 1))
        shift++;
    while ((mask >> (shift + bits)) & 1)
        bits++;
    unsigned long v = (pixel & mask) >> shift;
    return (unsigned char)(bits >= 8 ? v >> (bits - 8) : v * 255 / ((1ul << bits) - 1));
}

/* The window's pixels as RGB, top row first; 0, or -1 while they cannot be read. */
static int grab_window(Display *dpy, Window w, unsigned char *rgb)
{
    XWindowAttributes a;
    x_errors = 0;
    if (!XGetWindowAttributes(dpy, w, &a) || a.map_state != IsViewable)
        return -1;
    if (a.width != FRAME_WIDTH || a.height != FRAME_HEIGHT)
        fail_msg("the kiosk's window is %dx%d, not the configured %dx%d", a.width, a.height, FRAME_WIDTH,
                 FRAME_HEIGHT);
    XImage *img = XGetImage(dpy, w, 0, 0, FRAME_WIDTH, FRAME_HEIGHT, AllPlanes, ZPixmap);
    XSync(dpy, False);
    if (!img || x_errors) {
        if (img)
            XDestroyImage(img);
        return -1;
    }
    const Visual *v = a.visual;
    for (int y = 0; y < FRAME_HEIGHT; y++)
        for (int x = 0; x < FRAME_WIDTH; x++) {
            unsigned long p = XGetPixel(img, x, y);
            unsigned char *out = rgb + ((size_t)y * FRAME_WIDTH + x) * 3;
            out[0] = channel(p, v->red_mask);
            out[1] = channel(p, v->green_mask);
            out[2] = channel(p, v->blue_mask);
        }
    XDestroyImage(img);
    return 0;
}

struct difference {
    int largest;                     /* levels, over R, G and B */
    int pixels;                      /* that differ at all */
};

/* rgb (3 bytes a pixel) against rgba (4), over the rectangle [x0, x1) x [y0, y1). */
static struct difference compare(const unsigned char *rgb, const unsigned char *rgba, int x0, int y0, int x1,
                                 int y1)
{
    struct difference d = {0, 0};
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            size_t i = (size_t)y * FRAME_WIDTH + x;
            int worst = 0;
            for (int ch = 0; ch < 3; ch++) {
                int diff = abs(rgb[i * 3 + ch] - rgba[i * 4 + ch]);
                worst = diff > worst ? diff : worst;
            }
            d.largest = worst > d.largest ? worst : d.largest;
            d.pixels += worst > 0;
        }
    return d;
}

static void pause_seconds(double s)
{
    struct timespec t = {(time_t)s, (long)((s - (double)(time_t)s) * 1e9)};
    nanosleep(&t, NULL);
}

/* The last screenshot and the headless frame as PNG files next to the kiosk's files, which are
 * then kept, for a person to look at what differs. */
static void keep_pictures(void)
{
    unsigned char *rgba = malloc((size_t)FRAME_WIDTH * FRAME_HEIGHT * 4);
    if (!rgba)
        return;
    for (size_t i = 0; i < (size_t)FRAME_WIDTH * FRAME_HEIGHT; i++) {
        memcpy(rgba + i * 4, window_pixels + i * 3, 3);
        rgba[i * 4 + 3] = 255;
    }
    char window_png[160], headless_png[160];
    struct error err;
    snprintf(window_png, sizeof window_png, "%s/window.png", work_dir);
    snprintf(headless_png, sizeof headless_png, "%s/headless.png", work_dir);
    if (png_write_rgba8(window_png, FRAME_WIDTH, FRAME_HEIGHT, rgba, 1, PNG_COMPRESSION_FAST, &err) == 0 &&
        png_write_rgba8(headless_png, FRAME_WIDTH, FRAME_HEIGHT, headless_frame, 1, PNG_COMPRESSION_FAST, &err) == 0) {
        keep_work_dir = 1;
        print_message("kept for comparison: %s and %s (the kiosk's files stay in %s)\n", window_png, headless_png,
                      work_dir);
    } else {
        print_message("%s\n", err.message);
    }
    free(rgba);
}

/* ---- the tests ---------------------------------------------------------------------------- */

/* The window settles to the headless frame exactly: the same renderer, the same compositor, the
 * canvas and the HUD drawn one to one (the window has the frame's size), so nothing filters. A
 * picture passing through on the way (the HUD's lines come and go) is not settled: the window must
 * keep equalling the frame for STABLE_SECONDS, beyond FRAME_SECONDS of the kiosk's clock. */
static void test_window_shows_the_headless_frame(void **state)
{
    (void)state;
    need_xvfb();
    Display *dpy = XOpenDisplay(xvfb.display);
    if (!dpy)
        fail_msg("cannot open the test's X display %s", xvfb.display);
    XErrorHandler previous = XSetErrorHandler(count_x_error);
    window_pixels = malloc((size_t)FRAME_WIDTH * FRAME_HEIGHT * 3);
    assert_non_null(window_pixels);
    Window w = 0;
    struct difference last = {-1, -1};
    int grabs = 0, settled = 0;
    double equal_since = -1.0, elapsed = 0.0;    /* s since the kiosk started */
    double deadline = monotonic_seconds() + SETTLE_TIMEOUT_SECONDS;
    while (!settled && monotonic_seconds() < deadline) {
        kiosk_still_running();
        if (!w)
            w = xvfb_find_window(dpy, DefaultRootWindow(dpy), WINDOW_TITLE);
        elapsed = monotonic_seconds() - kiosk_started;
        if (w && grab_window(dpy, w, window_pixels) == 0) {
            grabs++;
            last = compare(window_pixels, headless_frame, 0, 0, FRAME_WIDTH, FRAME_HEIGHT);
            if (last.pixels)
                equal_since = -1.0;
            else if (equal_since < 0.0)
                equal_since = elapsed;
        } else {
            equal_since = -1.0;
        }
        settled = equal_since >= 0.0 && elapsed - equal_since >= STABLE_SECONDS &&
                  elapsed >= FRAME_SECONDS + STABLE_SECONDS;
        if (!settled)
            pause_seconds(GRAB_INTERVAL_SECONDS);
    }
    XSetErrorHandler(previous);
    XCloseDisplay(dpy);
    if (!settled) {
        print_file(kiosk_log, "kiosk log: ");
        if (grabs)
            keep_pictures();
        if (!w)
            fail_msg("no window called \"%s\" on %s within %.0f s", WINDOW_TITLE, xvfb.display,
                     SETTLE_TIMEOUT_SECONDS);
        fail_msg("after %.0f s (%d screenshots) the window does not stay equal to the headless frame: largest "
                 "difference %d levels, %d of %d pixels differ", SETTLE_TIMEOUT_SECONDS, grabs, last.largest,
                 last.pixels, FRAME_WIDTH * FRAME_HEIGHT);
    }
    print_message("the window equals the headless frame from %.1f s after the kiosk started to %.1f s "
                  "(%d screenshots)\n", equal_since, elapsed, grabs);
}

/* The HUD is in the settled picture: against the renderer's own image of the same state, without
 * a HUD, the top-left corner differs (the translucent band and the text), and nothing else does:
 * not the bottom rows, where the knob's indicator was until KIOSK_INDICATOR_SECONDS after the
 * turn, nor the rest of the scene. */
static void test_window_shows_the_hud(void **state)
{
    (void)state;
    need_xvfb();
    struct kiosk_state st;
    kiosk_state_reset(&st, &headless_config);
    st.speed = knob_turn(&headless_config.speed, st.speed, TURN_COUNTS);
    static struct scene base, drawn;
    struct error e;
    if (scene_load(&base, headless_config.kiosk.scenes[st.scene], &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    base.render.width = FRAME_WIDTH;
    base.render.height = FRAME_HEIGHT;
    if (kiosk_state_apply(&st, &base, &drawn, &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    struct render_result res;
    struct frame_info info;
    struct error gl_err;
    if (render_frame(&drawn, &(struct frame_request){.backend = "egl"}, &res, &info, &gl_err) != 0)
        fail_msg("%s", gl_err.message);
    /* the settled window; where it did not settle, the headless frame, so that what is wrong with
     * the HUD itself is still said */
    unsigned char *picture = malloc((size_t)FRAME_WIDTH * FRAME_HEIGHT * 3);
    assert_non_null(picture);
    int settled = window_pixels && !compare(window_pixels, headless_frame, 0, 0, FRAME_WIDTH, FRAME_HEIGHT).pixels;
    for (size_t i = 0; i < (size_t)FRAME_WIDTH * FRAME_HEIGHT; i++)
        memcpy(picture + i * 3, settled ? window_pixels + i * 3 : headless_frame + i * 4, 3);
    if (!settled)
        print_message("the window did not settle: looking at the headless frame instead\n");

    struct difference corner = compare(picture, res.rgba, 0, 0, HUD_CORNER_WIDTH, HUD_CORNER_HEIGHT);
    int x0 = FRAME_WIDTH, y0 = FRAME_HEIGHT, x1 = 0, y1 = 0;
    for (int y = 0; y < FRAME_HEIGHT; y++)
        for (int x = 0; x < FRAME_WIDTH; x++)
            if (compare(picture, res.rgba, x, y, x + 1, y + 1).pixels) {
                x0 = x < x0 ? x : x0;
                y0 = y < y0 ? y : y0;
                x1 = x + 1 > x1 ? x + 1 : x1;
                y1 = y + 1 > y1 ? y + 1 : y1;
            }
    render_result_free(&res);
    free(picture);
    print_message("against the image without HUD: %d of %d pixels of the top-left %dx%d differ (largest %d "
                  "levels); everything that differs lies in [%d, %d) x [%d, %d)\n",
                  corner.pixels, HUD_CORNER_WIDTH * HUD_CORNER_HEIGHT, HUD_CORNER_WIDTH, HUD_CORNER_HEIGHT,
                  corner.largest, x0, x1, y0, y1);
    /* the band covers the corner but for its margin, half a text height */
    assert_true(corner.pixels > HUD_CORNER_WIDTH * HUD_CORNER_HEIGHT / 2);
    /* one block, from the top-left margin */
    assert_true(x0 < HUD_CORNER_WIDTH && y0 < HUD_CORNER_HEIGHT);
    if (y1 > INDICATOR_TOP)
        fail_msg("the knob's indicator is still on screen (rows down to %d differ from the image without HUD), "
                 "%.1f s after the turn: it should go after %.1f s", y1, FRAME_SECONDS - TURN_SECONDS,
                 KIOSK_INDICATOR_SECONDS);
    /* below the block, the scene is the renderer's image exactly */
    assert_true(y1 <= HUD_BLOCK_BOTTOM);
}

/* A window laid over the kiosk's and taken away again (a notification, a screen saver) leaves
 * the picture as it was, though the kiosk at rest draws nothing. */
static void test_window_comes_back_uncovered(void **state)
{
    (void)state;
    need_xvfb();
    kiosk_still_running();
    Display *dpy = XOpenDisplay(xvfb.display);
    if (!dpy)
        fail_msg("cannot open the test's X display %s", xvfb.display);
    XErrorHandler previous = XSetErrorHandler(count_x_error);
    Window w = xvfb_find_window(dpy, DefaultRootWindow(dpy), WINDOW_TITLE);
    assert_true(w != 0);
    size_t size = (size_t)FRAME_WIDTH * FRAME_HEIGHT * 3;
    unsigned char *before = malloc(size), *after = malloc(size);
    assert_non_null(before);
    assert_non_null(after);
    assert_int_equal(grab_window(dpy, w, before), 0);

    /* the middle of the picture, white, in front (override-redirect: even with a window manager) */
    Window root = DefaultRootWindow(dpy), child;
    int x = 0, y = 0;
    XTranslateCoordinates(dpy, w, root, FRAME_WIDTH / 4, FRAME_HEIGHT / 4, &x, &y, &child);
    unsigned long white = WhitePixel(dpy, DefaultScreen(dpy));
    XSetWindowAttributes cover_attrs = {.override_redirect = True, .background_pixel = white};
    Window cover = XCreateWindow(dpy, root, x, y, FRAME_WIDTH / 2, FRAME_HEIGHT / 2, 0, CopyFromParent, InputOutput,
                                 CopyFromParent, CWOverrideRedirect | CWBackPixel, &cover_attrs);
    XMapRaised(dpy, cover);
    XSync(dpy, False);
    pause_seconds(COVER_SECONDS);
    XImage *on_screen = XGetImage(dpy, root, x, y, 1, 1, AllPlanes, ZPixmap);
    assert_non_null(on_screen);
    unsigned long covered_pixel = XGetPixel(on_screen, 0, 0);
    XDestroyImage(on_screen);
    XDestroyWindow(dpy, cover);
    XSync(dpy, False);
    pause_seconds(COVER_SECONDS);
    assert_int_equal(grab_window(dpy, w, after), 0);
    XSetErrorHandler(previous);
    XCloseDisplay(dpy);

    struct difference d = {0, 0};
    for (size_t i = 0; i < size; i++) {
        int diff = abs(before[i] - after[i]);
        d.largest = diff > d.largest ? diff : d.largest;
        d.pixels += diff > 0;
    }
    free(before);
    free(after);
    print_message("after covering the middle quarter of the window and uncovering it: %d channel values differ "
                  "(largest %d)\n", d.pixels, d.largest);
    if (covered_pixel != white)
        fail_msg("the covering window did not show on the screen");
    if (d.pixels)
        fail_msg("what was covered did not come back (%d channel values differ, largest %d): the kiosk at rest "
                 "draws nothing, so the server must keep the window's pixels", d.pixels, d.largest);
}

/* SIGTERM ends the loop at its next turn: the kiosk exits 0 at once and says why it stopped. */
static void test_sigterm_stops_cleanly(void **state)
{
    (void)state;
    need_xvfb();
    kiosk_still_running();
    double sent = monotonic_seconds();
    assert_int_equal(kill(kiosk_pid, SIGTERM), 0);
    int status = 0, exited = 0;
    while (!exited && monotonic_seconds() < sent + STOP_SECONDS) {
        exited = waitpid(kiosk_pid, &status, WNOHANG) == kiosk_pid;
        if (!exited)
            pause_seconds(0.01);
    }
    double took = monotonic_seconds() - sent;
    print_file(kiosk_log, "kiosk log: ");
    if (!exited)
        fail_msg("the windowed kiosk did not exit within %.1f s of SIGTERM", STOP_SECONDS);
    kiosk_pid = -1;
    print_message("exited %.2f s after SIGTERM\n", took);
    if (WIFSIGNALED(status))
        fail_msg("the windowed kiosk died of signal %d after SIGTERM", WTERMSIG(status));
    assert_int_equal(WEXITSTATUS(status), 0);
    assert_true(file_has(kiosk_log, "bentray kiosk: x11 screen"));
    assert_true(file_has(kiosk_log, "bentray kiosk: stopped after"));
    assert_true(file_has(kiosk_log, "(signal)"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_window_shows_the_headless_frame),
        cmocka_unit_test(test_window_shows_the_hud),
        cmocka_unit_test(test_window_comes_back_uncovered),
        cmocka_unit_test(test_sigterm_stops_cleanly),
    };
    return cmocka_run_group_tests(tests, group_setup, group_teardown);
}
