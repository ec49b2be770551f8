/* The kiosk in a window under X11 (development, and exhibitions that keep a desktop): EGL on the
 * X11 platform with a window surface, keys through the fixed keyboard mapping, closing the window
 * stops the kiosk. */
#include "display/screen.h"
#include "input/keymap.h"
#include "gl/egl.h"
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <X11/Xlib.h>
#include <X11/Xatom.h>
#include <X11/Xutil.h>
#include <X11/keysym.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define X11_WINDOW_TITLE "bentray kiosk"
#define X11_WINDOW_CLASS_NAME "bentray-kiosk"
#define X11_WINDOW_CLASS "Bentray"

/* The window-system half. */
struct x11_window {
    Display *dpy;
    Window window;
    Colormap colormap;
    Atom wm_protocols, wm_delete_window;
};

static void x11_window_destroy(struct x11_window *w)
{
    if (!w)
        return;
    if (w->dpy) {
        if (w->window)
            XDestroyWindow(w->dpy, w->window);
        if (w->colormap)
            XFreeColormap(w->dpy, w->colormap);
        XCloseDisplay(w->dpy);
    }
    free(w);
}

static void x11_close(struct screen *s)
{
    if (!s)
        return;
    /* the GL half goes before the window and the connection it draws into */
    if (s->gl)
        s->gl->destroy(s->gl);
    x11_window_destroy(s->priv);
    free(s);
}

static int x11_fd(struct screen *s)
{
    struct x11_window *w = s->priv;
    return ConnectionNumber(w->dpy);
}

static int key_event(XKeyEvent *key, struct input_event *ev)
{
    char text[8];
    KeySym sym = NoSymbol;
    int len = XLookupString(key, text, sizeof text, &sym, NULL);
    switch (sym) {
    case XK_Up: case XK_KP_Up: return keymap_event(KEY_CODE_UP, 0, ev);
    case XK_Down: case XK_KP_Down: return keymap_event(KEY_CODE_DOWN, 0, ev);
    case XK_Left: case XK_KP_Left: return keymap_event(KEY_CODE_LEFT, 0, ev);
    case XK_Right: case XK_KP_Right: return keymap_event(KEY_CODE_RIGHT, 0, ev);
    case XK_Escape: return keymap_event(KEY_CODE_ESCAPE, 0, ev);
    default: break;
    }
    return len == 1 ? keymap_event(KEY_CODE_CHAR, (unsigned char)text[0], ev) : 0;
}

static int x11_events(struct screen *s, double now, struct input_event *out, int max)
{
    struct x11_window *w = s->priv;
    int n = 0;
    /* Only take an event from Xlib's queue when there is room for what it may give. */
    while (n < max && XPending(w->dpy) > 0) {
        XEvent e;
        XNextEvent(w->dpy, &e);
        struct input_event *ev = &out[n];
        int got = 0;
        switch (e.type) {
        case KeyPress:
            got = key_event(&e.xkey, ev);
            break;
        case ClientMessage:
            if (e.xclient.message_type == w->wm_protocols && e.xclient.format == 32 &&
                (Atom)e.xclient.data.l[0] == w->wm_delete_window) {
                memset(ev, 0, sizeof *ev);
                ev->kind = INPUT_QUIT;
                got = 1;
            }
            break;
        case ConfigureNotify:
            s->width = e.xconfigure.width;
            s->height = e.xconfigure.height;
            break;
        default:
            break;
        }
        if (got) {
            ev->t = now;
            ev->source = -1;
            ev->bit = -1;
            n++;
        }
    }
    return n;
}

static int x11_present(struct screen *s, struct error *e)
{
    return egl_swap(s->gl, e);
}

/* The window in the visual of the EGL config, an ES2 context current on it. The window is made
 * here, between the two steps of gl/egl.h, because its visual comes from the config. On
 * failure the caller's close frees the context and the window. */
/* What an exhibit's window is: fullscreen (EWMH's _NET_WM_STATE_FULLSCREEN, asked before it is
 * mapped; the compositor letterboxes the frame into whatever size the window manager gives it),
 * without a pointer over it, and named for the window manager and its rules (WM_CLASS
 * "bentray-kiosk", "Bentray"). The size asked for stays the frame's, for a server without a window
 * manager (Xvfb), where the frame's pixels then stay one to one. */
static void exhibit_window(Display *dpy, Window window, int width, int height)
{
    XSizeHints *hints = XAllocSizeHints();
    if (hints) {
        hints->flags = PSize;
        hints->width = width;
        hints->height = height;
        XSetWMNormalHints(dpy, window, hints);
        XFree(hints);
    }
    XClassHint *class_hint = XAllocClassHint();
    if (class_hint) {
        char name[] = X11_WINDOW_CLASS_NAME, class_name[] = X11_WINDOW_CLASS;
        class_hint->res_name = name;
        class_hint->res_class = class_name;
        XSetClassHint(dpy, window, class_hint);
        XFree(class_hint);
    }
    Atom state = XInternAtom(dpy, "_NET_WM_STATE", False);
    Atom fullscreen = XInternAtom(dpy, "_NET_WM_STATE_FULLSCREEN", False);
    XChangeProperty(dpy, window, state, XA_ATOM, 32, PropModeReplace, (unsigned char *)&fullscreen, 1);
    /* an invisible pointer: a cursor of one transparent pixel */
    static char blank_bits[1] = {0};
    Pixmap blank = XCreateBitmapFromData(dpy, window, blank_bits, 1, 1);
    if (blank) {
        XColor black = {0};
        Cursor none = XCreatePixmapCursor(dpy, blank, blank, &black, &black, 0, 0);
        XDefineCursor(dpy, window, none);
        XFreeCursor(dpy, none);
        XFreePixmap(dpy, blank);
    }
}

static int attach_window(struct screen *s, struct x11_window *w, int vsync, struct error *e)
{
    int width = s->width, height = s->height;
    EGLDisplay display = egl_display(s->gl);
    static const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_WINDOW_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8,
                                            EGL_BLUE_SIZE, 8, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT, EGL_NONE};
    EGLConfig config = NULL;
    EGLint n = 0;
    if (!eglChooseConfig(display, config_attribs, &config, 1, &n) || n < 1) {
        return error_set(e, ERROR_RUNTIME, NULL, "x11: no EGL config for an 8-bit RGB ES2 window (EGL error 0x%x)",
                         eglGetError());
    }
    EGLint visual_id = 0;
    eglGetConfigAttrib(display, config, EGL_NATIVE_VISUAL_ID, &visual_id);
    XVisualInfo want = {.visualid = (VisualID)visual_id}, *visual;
    int n_visuals = 0;
    visual = XGetVisualInfo(w->dpy, VisualIDMask, &want, &n_visuals);
    if (!visual || n_visuals < 1) {
        return error_set(e, ERROR_RUNTIME, NULL, "x11: the X server has no visual 0x%x for the EGL config",
                         (unsigned)visual_id);
    }
    Window root = RootWindow(w->dpy, visual->screen);
    w->colormap = XCreateColormap(w->dpy, root, visual->visual, AllocNone);
    XSetWindowAttributes attrs = {
        .colormap = w->colormap,
        .background_pixel = 0,
        .border_pixel = 0,
        .event_mask = KeyPressMask | StructureNotifyMask,
        /* A kiosk at rest draws nothing: what another window covered (a notification, a screen
         * saver) must come back without a redraw, so the server keeps the window's pixels. */
        .backing_store = Always,
    };
    w->window = XCreateWindow(w->dpy, root, 0, 0, (unsigned)width, (unsigned)height, 0, visual->depth, InputOutput,
                              visual->visual, CWColormap | CWBackPixel | CWBorderPixel | CWEventMask | CWBackingStore,
                              &attrs);
    XFree(visual);
    if (!w->window) {
        return error_set(e, ERROR_RUNTIME, NULL, "x11: cannot create a %dx%d window", width, height);
    }
    XStoreName(w->dpy, w->window, X11_WINDOW_TITLE);
    exhibit_window(w->dpy, w->window, width, height);
    XSetWMProtocols(w->dpy, w->window, &w->wm_delete_window, 1);
    XMapWindow(w->dpy, w->window);
    if (egl_attach_window(s->gl, config, &w->window, e) != 0)
        return -1;
    /* Advisory: a server without vertical blank (Xvfb) may refuse it, and frames still show. */
    eglSwapInterval(display, vsync ? 1 : 0);
    return 0;
}

struct screen *screen_open_x11(const struct kiosk_display *d, int width, int height, struct error *e)
{
    const char *name = getenv("DISPLAY");
    if (!name || !*name) {
        error_set(e, ERROR_RUNTIME, NULL, "x11: no X display: DISPLAY is not set");
        return NULL;
    }
    struct screen *s = calloc(1, sizeof *s);
    struct x11_window *w = calloc(1, sizeof *w);
    if (!s || !w) {
        free(s);
        free(w);
        error_set(e, ERROR_RUNTIME, NULL, "x11: out of memory");
        return NULL;
    }
    s->name = "x11";
    s->priv = w;
    s->width = width;
    s->height = height;
    s->framebuffer = 0;
    s->fd = x11_fd;
    s->events = x11_events;
    s->present = x11_present;
    s->close = x11_close;
    w->dpy = XOpenDisplay(NULL);
    if (!w->dpy) {
        error_set(e, ERROR_RUNTIME, NULL, "x11: cannot open the X display \"%s\" (is the X server running, may this "
                  "user connect to it: XAUTHORITY, xhost?)", name);
        x11_close(s);
        return NULL;
    }
    w->wm_protocols = XInternAtom(w->dpy, "WM_PROTOCOLS", False);
    w->wm_delete_window = XInternAtom(w->dpy, "WM_DELETE_WINDOW", False);
    static const struct egl_platform x11 = {EGL_PLATFORM_X11_KHR, "X11", "the X display", "EGL_KHR_platform_x11",
                                            "EGL_EXT_platform_x11", "install Mesa's EGL (libegl-mesa0)"};
    s->gl = egl_open(&x11, w->dpy, "x11", "X11", e);
    if (!s->gl || attach_window(s, w, d->vsync, e) != 0) {
        x11_close(s);
        return NULL;
    }
    XFlush(w->dpy);
    return s;
}
