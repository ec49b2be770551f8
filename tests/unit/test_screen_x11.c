/* The kiosk's X11 screen on a private Xvfb server that the test starts and stops itself: the
 * window has the configured size, a frame cleared to a known colour reads back as that colour,
 * presenting works, an idle window gives no events, keys and the window manager's close message
 * give the kiosk's events, a resize is followed. Also the errors of back-ends that cannot open:
 * X11 without DISPLAY, KMS on a device that does not exist, and auto passing over KMS to X11. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <X11/Xatom.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/keysym.h>
#include "kiosk_config/kiosk_config.h"
#include "gl/gl_api.h"
#include "display/screen.h"
#include "xvfb.h"

#define MISSING_DRM_DEVICE "/nonexistent/dri/card7"
#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif
#define WIDTH 320
#define HEIGHT 240

static struct xvfb xvfb;

/* Mesa unloads its driver when the last EGL display that uses it is terminated, and LeakSanitizer
 * then counts what the driver's globals still held as leaks. One display kept initialised until
 * exit keeps the driver loaded, so that a leak reported here is one of the screen's. */
static void keep_gl_driver_loaded(void)
{
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    if (!get_platform_display)
        return;
    EGLDisplay dpy = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (dpy != EGL_NO_DISPLAY)
        eglInitialize(dpy, NULL, NULL);
}

static int group_setup(void **state)
{
    (void)state;
    keep_gl_driver_loaded();
    return xvfb_start(&xvfb);
}

static int group_teardown(void **state)
{
    (void)state;
    xvfb_stop(&xvfb);
    return 0;
}

static void need_xvfb(void)
{
    if (xvfb.missing) {
        print_message("skipped: %s\n", xvfb.missing);
        skip();
    }
    setenv("DISPLAY", xvfb.display, 1);
}

static void config_of_size(struct kiosk_config *c, int width, int height)
{
    kiosk_config_defaults(c);
    c->kiosk.width = width;
    c->kiosk.height = height;
}

static void open_x11(struct screen **s, const struct kiosk_config *c)
{
    struct error e;
    *s = screen_open_x11(&c->display, c->kiosk.width, c->kiosk.height, &e);
    if (!*s)
        fail_msg("screen_open_x11 on %s: %s", xvfb.display, e.message);
}

/* ---- the window's frame ----------------------------------------------------------------------- */

/* Clear framebuffer 0 to (r, g, b), read the centre back before the swap, present. */
static void clear_read_present(struct screen *s, int r, int g, int b)
{
    glBindFramebuffer(GL_FRAMEBUFFER, s->framebuffer);
    glViewport(0, 0, s->width, s->height);
    glClearColor((float)r / 255.0f, (float)g / 255.0f, (float)b / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    unsigned char px[4] = {0};
    glReadPixels(s->width / 2, s->height / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    assert_int_equal(glGetError(), GL_NO_ERROR);
    if (abs(px[0] - r) > 1 || abs(px[1] - g) > 1 || abs(px[2] - b) > 1)
        fail_msg("read back %d,%d,%d after clearing to %d,%d,%d", px[0], px[1], px[2], r, g, b);
    struct error e;
    if (s->present(s, &e) != 0)
        fail_msg("present: %s", e.message);
}

static void test_x11_frame_reads_back(void **state)
{
    (void)state;
    need_xvfb();
    struct kiosk_config c;
    config_of_size(&c, WIDTH, HEIGHT);
    struct screen *s;
    open_x11(&s, &c);
    assert_string_equal(s->name, "x11");
    assert_int_equal(s->width, WIDTH);
    assert_int_equal(s->height, HEIGHT);
    assert_int_equal(s->framebuffer, 0);
    assert_true(s->gl->is_es);
    assert_int_equal(s->gl->dialect, DIALECT_GLSL_ES_100);
    assert_true(s->fd(s) >= 0);
    print_message("%s, %s on %s\n", s->gl->platform_version, (const char *)glGetString(GL_RENDERER), xvfb.display);
    GLint viewport[4];
    glGetIntegerv(GL_VIEWPORT, viewport);     /* the window surface has the window's size */
    assert_int_equal(viewport[2], WIDTH);
    assert_int_equal(viewport[3], HEIGHT);
    clear_read_present(s, 64, 128, 191);
    clear_read_present(s, 200, 30, 90);       /* a second frame: the swap left a usable buffer */
    struct input_event ev[8];
    assert_int_equal(s->events(s, 1.0, ev, 8), 0);
    screen_close(s);
}

/* ---- events through a second connection, as a window manager and a keyboard would send them ---- */

static void send_key(Display *dpy, Window w, KeySym sym)
{
    XEvent e;
    memset(&e, 0, sizeof e);
    e.xkey.type = KeyPress;
    e.xkey.display = dpy;
    e.xkey.window = w;
    e.xkey.root = DefaultRootWindow(dpy);
    e.xkey.same_screen = True;
    e.xkey.keycode = XKeysymToKeycode(dpy, sym);
    assert_true(e.xkey.keycode != 0);
    XSendEvent(dpy, w, False, KeyPressMask, &e);
}

static void send_close(Display *dpy, Window w)
{
    XEvent e;
    memset(&e, 0, sizeof e);
    e.xclient.type = ClientMessage;
    e.xclient.window = w;
    e.xclient.message_type = XInternAtom(dpy, "WM_PROTOCOLS", False);
    e.xclient.format = 32;
    e.xclient.data.l[0] = (long)XInternAtom(dpy, "WM_DELETE_WINDOW", False);
    e.xclient.data.l[1] = CurrentTime;
    XSendEvent(dpy, w, False, NoEventMask, &e);
}

/* events() of s until want arrived or 5 s passed; returns how many arrived. */
static int collect(struct screen *s, struct input_event *out, int want)
{
    int n = 0;
    double deadline = monotonic_seconds() + 5.0;
    while (n < want && monotonic_seconds() < deadline) {
        n += s->events(s, 42.0, out + n, want - n);
        struct timespec pause = {0, 5 * 1000 * 1000};
        nanosleep(&pause, NULL);
    }
    return n;
}

static void test_x11_events(void **state)
{
    (void)state;
    need_xvfb();
    struct kiosk_config c;
    config_of_size(&c, WIDTH, HEIGHT);
    struct screen *s;
    open_x11(&s, &c);
    Display *other = XOpenDisplay(xvfb.display);
    assert_non_null(other);
    Window w = xvfb_find_window(other, DefaultRootWindow(other), "bentray kiosk");
    assert_true(w != 0);

    /* an exhibit's window: fullscreen asked of the window manager, a class for its rules, no pointer
     * (Xvfb has no window manager: the size stays the frame's, as checked above) */
    XClassHint class_hint;
    assert_true(XGetClassHint(other, w, &class_hint) != 0);
    assert_string_equal(class_hint.res_name, "bentray-kiosk");
    assert_string_equal(class_hint.res_class, "Bentray");
    XFree(class_hint.res_name);
    XFree(class_hint.res_class);
    Atom type;
    int format;
    unsigned long n_items, after;
    unsigned char *data = NULL;
    assert_int_equal(XGetWindowProperty(other, w, XInternAtom(other, "_NET_WM_STATE", False), 0, 8, False, XA_ATOM,
                                        &type, &format, &n_items, &after, &data), Success);
    assert_int_equal(n_items, 1);
    assert_true(((Atom *)data)[0] == XInternAtom(other, "_NET_WM_STATE_FULLSCREEN", False));
    XFree(data);
    XWindowAttributes attrs;
    assert_true(XGetWindowAttributes(other, w, &attrs) != 0);
    assert_int_equal(attrs.width, WIDTH);

    send_key(other, w, XK_Up);
    send_key(other, w, XK_n);
    send_key(other, w, XK_F5);                 /* not in the mapping: no event */
    send_key(other, w, XK_a);
    send_close(other, w);
    XSync(other, False);
    struct input_event ev[8];
    /* one at a time: what does not fit waits in the queue */
    assert_int_equal(collect(s, ev, 1), 1);
    assert_int_equal(collect(s, ev + 1, 3), 3);
    assert_int_equal(ev[0].kind, INPUT_KNOB);
    assert_int_equal(ev[0].knob, INPUT_KNOB_SPEED);
    assert_int_equal(ev[0].counts, 1);
    assert_int_equal(ev[1].kind, INPUT_ACTION);
    assert_int_equal(ev[1].action, KIOSK_ACTION_NEXT_SCENE);
    assert_int_equal(ev[2].kind, INPUT_KNOB);
    assert_int_equal(ev[2].knob, INPUT_KNOB_MASS);
    assert_int_equal(ev[2].counts, -1);
    assert_int_equal(ev[3].kind, INPUT_QUIT);
    for (int i = 0; i < 4; i++) {
        assert_true(ev[i].t == 42.0);
        assert_int_equal(ev[i].source, -1);
        assert_int_equal(ev[i].bit, -1);
    }
    assert_int_equal(s->events(s, 43.0, ev, 8), 0);

    /* a resize (Xvfb has no window manager to refuse it) is followed */
    XResizeWindow(other, w, 200, 100);
    XSync(other, False);
    double deadline = monotonic_seconds() + 5.0;
    while (s->width != 200 && monotonic_seconds() < deadline)
        s->events(s, 44.0, ev, 8);
    assert_int_equal(s->width, 200);
    assert_int_equal(s->height, 100);
    clear_read_present(s, 10, 220, 40);
    XCloseDisplay(other);
    screen_close(s);
}

/* screen_open with backend auto passes over KMS (its device is missing) to X11 and says why. */
static void test_auto_passes_over_kms(void **state)
{
    (void)state;
    need_xvfb();
    struct kiosk_config c;
    config_of_size(&c, WIDTH, HEIGHT);
    snprintf(c.display.drm_device, sizeof c.display.drm_device, "%s", MISSING_DRM_DEVICE);
    struct error e;
    struct screen *s = screen_open(&c.display, c.kiosk.width, c.kiosk.height, "auto", &e);
    if (!s)
        fail_msg("screen_open (auto): %s", e.message);
    assert_string_equal(s->name, "x11");
    print_message("passed over: %s\n", e.message);
    assert_non_null(strstr(e.message, "kms: " MISSING_DRM_DEVICE));
    assert_int_equal(e.status, ERROR_NONE);
    screen_close(s);
}

/* ---- back-ends that cannot open --------------------------------------------------------------- */

static void test_x11_without_display(void **state)
{
    (void)state;
    char *saved = getenv("DISPLAY") ? strdup(getenv("DISPLAY")) : NULL;
    unsetenv("DISPLAY");
    struct kiosk_config c;
    config_of_size(&c, WIDTH, HEIGHT);
    struct error e;
    struct screen *s = screen_open_x11(&c.display, c.kiosk.width, c.kiosk.height, &e);
    if (saved) {
        setenv("DISPLAY", saved, 1);
        free(saved);
    }
    assert_null(s);
    print_message("%s\n", e.message);
    assert_non_null(strstr(e.message, "DISPLAY is not set"));
}

static void test_kms_missing_device(void **state)
{
    (void)state;
    struct kiosk_config c;
    config_of_size(&c, WIDTH, HEIGHT);
    snprintf(c.display.drm_device, sizeof c.display.drm_device, "%s", MISSING_DRM_DEVICE);
    struct error e;
    assert_null(screen_open_kms(&c.display, &e));
    print_message("%s\n", e.message);
    assert_non_null(strstr(e.message, MISSING_DRM_DEVICE));
    /* the device the configuration names is not there: the user's */
    assert_int_equal(e.status, ERROR_INPUT);
    c.display.backend = KIOSK_BACKEND_KMS;
    error_clear(&e);
    assert_null(screen_open(&c.display, c.kiosk.width, c.kiosk.height, "auto", &e));
    assert_non_null(strstr(e.message, MISSING_DRM_DEVICE));
    /* a device that is there but drives no display */
    snprintf(c.display.drm_device, sizeof c.display.drm_device, "/dev/null");
    error_clear(&e);
    assert_null(screen_open_kms(&c.display, &e));
    print_message("%s\n", e.message);
    assert_non_null(strstr(e.message, "/dev/null: not a display controller"));
    assert_int_equal(e.status, ERROR_RUNTIME);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_x11_without_display),
        cmocka_unit_test(test_kms_missing_device),
        cmocka_unit_test(test_x11_frame_reads_back),
        cmocka_unit_test(test_x11_events),
        cmocka_unit_test(test_auto_passes_over_kms),
    };
    return cmocka_run_group_tests(tests, group_setup, group_teardown);
}
