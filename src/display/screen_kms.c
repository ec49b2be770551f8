/* The kiosk on a display with no window system, as in kmscube: a DRM/KMS card drives one connector
 * in one mode, EGL draws into a GBM surface, each frame is scanned out by a page flip. What was on
 * the CRTC before (the console) is put back at close. Console switches (vt_switch.h): while
 * another console is in front, frames are drawn but not shown; back in front, the mode is set
 * again and the next frame shows. */
#include "display/screen.h"
#include "gl/egl.h"
#include "display/vt_switch.h"
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <gbm.h>
#include <poll.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <xf86drm.h>
#include <xf86drmMode.h>

#define KMS_DRI_DIR "/dev/dri"
#define KMS_MAX_CARDS 16
/* ms: a page flip comes within one refresh (17 ms at 60 Hz); a driver that lost it must not stop the loop */
#define KMS_FLIP_TIMEOUT_MS 1000

struct kms {
    char path[KIOSK_PATH_LEN];
    int fd;
    uint32_t connector_id, crtc_id;
    drmModeModeInfo mode;
    drmModeCrtc *saved_crtc;         /* the console's state of the CRTC, put back at close */
    struct gbm_device *gbm;
    struct gbm_surface *surface;
    struct gbm_bo *shown_bo;         /* on the screen now */
    struct gbm_bo *flip_bo;          /* queued by a page flip that has not completed */
    int mode_set;                    /* the first frame went out with drmModeSetCrtc */
    int vsync;
    int async_flip;                  /* the driver flips without waiting for vertical blank */
    struct vt_switch vt;             /* the console the kiosk runs on (standard input) */
};

/* ---- choosing the card, the connector and the mode ------------------------------------------ */

static void connector_name(const drmModeConnector *conn, char *out, size_t outlen)
{
    const char *type = drmModeGetConnectorTypeName(conn->connector_type);
    snprintf(out, outlen, "%s-%u", type ? type : "Unknown", conn->connector_type_id);
}

static int connected(const drmModeConnector *conn)
{
    return conn->connection == DRM_MODE_CONNECTED && conn->count_modes > 0;
}

static const char *open_reason(int e)
{
    if (e == EACCES || e == EPERM)
        return "permission denied: add the user to group video";
    if (e == ENOENT)
        return "no such device";
    return strerror(e);
}

/* The connector to drive on an open card: the one named (connected), else the first connected.
 * NULL with a reason naming the card. */
static drmModeConnector *find_connector(int fd, const char *path, const drmModeRes *res, const char *want,
                                        struct error *e)
{
    char names[256] = "";
    size_t used = 0;
    for (int i = 0; i < res->count_connectors; i++) {
        drmModeConnector *conn = drmModeGetConnector(fd, res->connectors[i]);
        if (!conn)
            continue;
        char name[KIOSK_NAME_LEN];
        connector_name(conn, name, sizeof name);
        if (*want && strcmp(name, want) == 0) {
            if (connected(conn))
                return conn;
            error_set(e, ERROR_RUNTIME, NULL, "%s: connector %s is not connected (no display on it, or it reports no "
                      "modes)", path, name);
            drmModeFreeConnector(conn);
            return NULL;
        }
        if (!*want && connected(conn))
            return conn;
        if (used < sizeof names) {
            int n = snprintf(names + used, sizeof names - used, "%s%s%s", used ? ", " : "", name,
                             *want && !connected(conn) ? " (disconnected)" : "");
            if (n > 0)
                used += (size_t)n;
        }
        drmModeFreeConnector(conn);
    }
    if (*want)
        error_set(e, ERROR_INPUT, NULL, "%s: no connector %s; it has %s", path, want, used ? names : "none");
    else
        error_set(e, ERROR_RUNTIME, NULL, "%s: no connected connector%s%s%s", path, used ? " (it has " : "", names,
                  used ? ")" : "");
    return NULL;
}

/* The configured mode, else the preferred one, else the largest. -1 with the modes it has. */
static int choose_mode(const drmModeConnector *conn, const char *path, int width, int height,
                       drmModeModeInfo *mode, struct error *e)
{
    const drmModeModeInfo *best = NULL;
    for (int i = 0; i < conn->count_modes; i++) {
        const drmModeModeInfo *m = &conn->modes[i];
        if (width > 0) {
            if (m->hdisplay != width || m->vdisplay != height)
                continue;
            /* among equal sizes the list comes fastest refresh first; keep the preferred if it is one */
            if (!best || (m->type & DRM_MODE_TYPE_PREFERRED))
                best = m;
        } else if (m->type & DRM_MODE_TYPE_PREFERRED) {
            best = m;
            break;
        } else if (!best || m->hdisplay * m->vdisplay > best->hdisplay * best->vdisplay) {
            best = m;
        }
    }
    if (best) {
        *mode = *best;
        return 0;
    }
    char name[KIOSK_NAME_LEN], modes[512] = "";
    size_t used = 0;
    connector_name(conn, name, sizeof name);
    for (int i = 0; i < conn->count_modes && used < sizeof modes; i++) {
        int n = snprintf(modes + used, sizeof modes - used, "%s%s@%u", i ? ", " : "", conn->modes[i].name,
                         conn->modes[i].vrefresh);
        if (n > 0)
            used += (size_t)n;
    }
    return error_set(e, ERROR_INPUT, NULL, "%s: %s has no mode %dx%d; its modes: %s", path, name, width, height,
                     modes);
}

/* The CRTC already driving the connector (the console's), else a free one its encoders can use. */
static uint32_t find_crtc(int fd, const drmModeRes *res, const drmModeConnector *conn)
{
    if (conn->encoder_id) {
        drmModeEncoder *enc = drmModeGetEncoder(fd, conn->encoder_id);
        if (enc) {
            uint32_t crtc = enc->crtc_id;
            drmModeFreeEncoder(enc);
            if (crtc)
                return crtc;
        }
    }
    for (int i = 0; i < conn->count_encoders; i++) {
        drmModeEncoder *enc = drmModeGetEncoder(fd, conn->encoders[i]);
        if (!enc)
            continue;
        uint32_t possible = enc->possible_crtcs;
        drmModeFreeEncoder(enc);
        for (int j = 0; j < res->count_crtcs && j < 32; j++)
            if (possible & (1u << j))
                return res->crtcs[j];
    }
    return 0;
}

/* Opens PATH and takes its connector, mode and CRTC into k. -1 with a reason naming PATH. */
static int try_card(struct kms *k, const char *path, const struct kiosk_display *d, struct error *e)
{
    int fd = open(path, O_RDWR | O_CLOEXEC);
    if (fd < 0) {
        int en = errno;
        return error_set(e, error_status_of_errno(en), NULL, "%s: %s", path, open_reason(en));
    }
    drmModeRes *res = drmModeGetResources(fd);
    if (!res) {
        error_set(e, ERROR_RUNTIME, NULL, "%s: not a display controller (drmModeGetResources: %s)", path,
                  strerror(errno));
        close(fd);
        return -1;
    }
    /* The first opener of a card is its master; anyone else (a display server) may not set modes. */
    if (!drmIsMaster(fd) && drmSetMaster(fd) != 0) {
        error_set(e, ERROR_RUNTIME, NULL, "%s: another program (a display server?) is driving the display: stop it, "
                  "or use [display] backend = x11", path);
        drmModeFreeResources(res);
        close(fd);
        return -1;
    }
    drmModeConnector *conn = find_connector(fd, path, res, d->connector, e);
    int ok = conn != NULL;
    if (ok)
        ok = choose_mode(conn, path, d->mode_width, d->mode_height, &k->mode, e) == 0;
    if (ok) {
        k->crtc_id = find_crtc(fd, res, conn);
        if (!k->crtc_id) {
            char name[KIOSK_NAME_LEN];
            connector_name(conn, name, sizeof name);
            error_set(e, ERROR_RUNTIME, NULL, "%s: no CRTC can drive %s", path, name);
            ok = 0;
        }
    }
    if (ok)
        k->connector_id = conn->connector_id;
    drmModeFreeConnector(conn);
    drmModeFreeResources(res);
    if (!ok) {
        close(fd);
        return -1;
    }
    k->fd = fd;
    snprintf(k->path, sizeof k->path, "%s", path);
    return 0;
}

static int card_number(const char *name)
{
    return strncmp(name, "card", 4) == 0 && name[4] >= '0' && name[4] <= '9' ? atoi(name + 4) : -1;
}

static int by_number(const void *a, const void *b)
{
    return *(const int *)a - *(const int *)b;
}

/* The configured card, else the first /dev/dri/cardN (by N) that drives a connected display. */
static int open_card(struct kms *k, const struct kiosk_display *d, struct error *e)
{
    if (*d->drm_device)
        return try_card(k, d->drm_device, d, e);
    DIR *dir = opendir(KMS_DRI_DIR);
    if (!dir)
        return error_set(e, ERROR_RUNTIME, NULL, "no DRM device: %s: %s (no GPU driver with display support is "
                         "loaded)", KMS_DRI_DIR, strerror(errno));
    int cards[KMS_MAX_CARDS], n = 0;
    for (struct dirent *ent; (ent = readdir(dir)) != NULL && n < KMS_MAX_CARDS;)
        if (card_number(ent->d_name) >= 0)
            cards[n++] = card_number(ent->d_name);
    closedir(dir);
    if (n == 0)
        return error_set(e, ERROR_RUNTIME, NULL, "no DRM device: no card in %s", KMS_DRI_DIR);
    qsort(cards, (size_t)n, sizeof cards[0], by_number);
    error_clear(e);
    size_t used = 0;
    for (int i = 0; i < n; i++) {
        char path[64];
        struct error why;
        snprintf(path, sizeof path, "%s/card%d", KMS_DRI_DIR, cards[i]);
        if (try_card(k, path, d, &why) == 0)
            return 0;
        if (used < sizeof e->message) {
            /* each card's reason cut at 383 characters, to leave room for the others' */
            int m = snprintf(e->message + used, sizeof e->message - used, "%s%.383s", used ? "; " : "", why.message);
            if (m > 0)
                used += (size_t)m;
        }
    }
    /* no card here drives a display: the machine's, whatever each card's reason */
    e->status = ERROR_RUNTIME;
    return -1;
}

/* ---- scan-out buffers ------------------------------------------------------------------------ */

struct kms_fb {
    int fd;
    uint32_t fb_id;
};

static void kms_fb_destroy(struct gbm_bo *bo, void *data)
{
    (void)bo;
    struct kms_fb *fb = data;
    if (fb->fb_id)
        drmModeRmFB(fb->fd, fb->fb_id);
    free(fb);
}

/* The DRM framebuffer of a GBM buffer, made once and kept with it (GBM reuses its few buffers). */
static uint32_t fb_of(struct kms *k, struct gbm_bo *bo, struct error *e)
{
    struct kms_fb *fb = gbm_bo_get_user_data(bo);
    if (fb)
        return fb->fb_id;
    fb = calloc(1, sizeof *fb);
    if (!fb) {
        error_set(e, ERROR_RUNTIME, NULL, "%s: out of memory", k->path);
        return 0;
    }
    fb->fd = k->fd;
    uint32_t width = gbm_bo_get_width(bo), height = gbm_bo_get_height(bo);
    uint32_t handles[4] = {gbm_bo_get_handle(bo).u32}, strides[4] = {gbm_bo_get_stride(bo)}, offsets[4] = {0};
    if (drmModeAddFB2(k->fd, width, height, gbm_bo_get_format(bo), handles, strides, offsets, &fb->fb_id, 0) != 0 &&
        drmModeAddFB(k->fd, width, height, 24, 32, strides[0], handles[0], &fb->fb_id) != 0) {
        error_set(e, ERROR_RUNTIME, NULL, "%s: cannot make a framebuffer of a %ux%u buffer (%s)", k->path, width,
                  height, strerror(errno));
        free(fb);
        return 0;
    }
    gbm_bo_set_user_data(bo, fb, kms_fb_destroy);
    return fb->fb_id;
}

static void page_flip_done(int fd, unsigned frame, unsigned sec, unsigned usec, void *data)
{
    (void)fd, (void)frame, (void)sec, (void)usec;
    struct kms *k = data;
    if (k->shown_bo)
        gbm_surface_release_buffer(k->surface, k->shown_bo);
    k->shown_bo = k->flip_bo;
    k->flip_bo = NULL;
}

/* Until the queued flip is on the screen, at most KMS_FLIP_TIMEOUT_MS. */
static int wait_flip(struct kms *k, struct error *e)
{
    drmEventContext events = {.version = 2, .page_flip_handler = page_flip_done};
    while (k->flip_bo) {
        struct pollfd p = {.fd = k->fd, .events = POLLIN};
        int r = poll(&p, 1, KMS_FLIP_TIMEOUT_MS);
        if (r < 0 && errno == EINTR)
            continue;
        if (r < 0)
            return error_set(e, ERROR_RUNTIME, NULL, "%s: waiting for a page flip: %s", k->path, strerror(errno));
        if (r == 0)
            return error_set(e, ERROR_RUNTIME, NULL, "%s: a page flip did not complete within %d ms", k->path,
                             KMS_FLIP_TIMEOUT_MS);
        if (drmHandleEvent(k->fd, &events) != 0)
            return error_set(e, ERROR_RUNTIME, NULL, "%s: reading the page flip event failed: %s", k->path,
                             strerror(errno));
    }
    return 0;
}

/* ---- the screen ------------------------------------------------------------------------------ */

static int kms_present(struct screen *s, struct error *e)
{
    struct kms *k = s->priv;
    if (!k->vt.showing)
        return 0;
    /* A flip that timed out last time may have completed since: its buffer is needed back. */
    if (k->flip_bo && wait_flip(k, e) != 0)
        return -1;
    if (egl_swap(s->gl, e) != 0)
        return -1;
    struct gbm_bo *bo = gbm_surface_lock_front_buffer(k->surface);
    if (!bo)
        return error_set(e, ERROR_RUNTIME, NULL, "%s: no front buffer after the swap (gbm_surface_lock_front_buffer)",
                         k->path);
    uint32_t fb = fb_of(k, bo, e);
    if (!fb) {
        gbm_surface_release_buffer(k->surface, bo);
        return -1;
    }
    if (!k->mode_set) {
        if (drmModeSetCrtc(k->fd, k->crtc_id, fb, 0, 0, &k->connector_id, 1, &k->mode) != 0) {
            int en = errno;
            gbm_surface_release_buffer(k->surface, bo);
            return error_set(e, ERROR_RUNTIME, NULL, "%s: cannot set mode %s (%s)%s", k->path, k->mode.name,
                             strerror(en), en == EACCES || en == EPERM ? ": another program (a display server?) is "
                             "driving the display" : "");
        }
        k->mode_set = 1;
        if (k->shown_bo)
            gbm_surface_release_buffer(k->surface, k->shown_bo);
        k->shown_bo = bo;
        return 0;
    }
    int async = !k->vsync && k->async_flip;
    int flipped = drmModePageFlip(k->fd, k->crtc_id, fb, DRM_MODE_PAGE_FLIP_EVENT |
                                  (async ? DRM_MODE_PAGE_FLIP_ASYNC : 0), k) == 0;
    if (!flipped && async && errno == EINVAL) {
        /* the capability can be there while this plane's format or modifier cannot flip at once */
        k->async_flip = 0;
        flipped = drmModePageFlip(k->fd, k->crtc_id, fb, DRM_MODE_PAGE_FLIP_EVENT, k) == 0;
    }
    if (!flipped) {
        int en = errno;
        gbm_surface_release_buffer(k->surface, bo);
        return error_set(e, ERROR_RUNTIME, NULL, "%s: page flip failed (%s)", k->path, strerror(en));
    }
    k->flip_bo = bo;
    /* Without vsync the flip is asynchronous where the driver can, and completes at once; waiting
     * for it either way leaves no event behind on the descriptor the loop polls. */
    return wait_flip(k, e);
}

/* No input of its own: the console switches the signals announced, served at every turn. */
static int kms_events(struct screen *s, double now, struct input_event *out, int max)
{
    (void)now, (void)out, (void)max;
    struct kms *k = s->priv;
    char note[sizeof s->note];
    if (vt_switch_serve(&k->vt, vt_switch_pending(), note, sizeof note)) {
        /* the console set its own mode meanwhile: the next frame sets the kiosk's again */
        k->mode_set = 0;
        s->redraw = 1;
    }
    if (note[0] && s->log)
        fprintf(s->log, "bentray kiosk: %s\n", note);
    return 0;
}

static int kms_fd(struct screen *s)
{
    struct kms *k = s->priv;
    return k->fd;
}

static void kms_close(struct screen *s)
{
    if (!s)
        return;
    struct kms *k = s->priv;
    if (k && k->fd >= 0) {
        /* the console back first: removing a framebuffer that is still scanned out turns the CRTC off */
        if (k->flip_bo) {
            struct error ignored;
            wait_flip(k, &ignored);
        }
        /* on another console, the display is that console's */
        if (k->mode_set && k->vt.showing) {
            drmModeCrtc *c = k->saved_crtc;
            if (c && c->mode_valid)
                drmModeSetCrtc(k->fd, c->crtc_id, c->buffer_id, c->x, c->y, &k->connector_id, 1, &c->mode);
            else
                drmModeSetCrtc(k->fd, k->crtc_id, 0, 0, 0, NULL, 0, NULL);
        }
        if (k->surface) {
            if (k->flip_bo)
                gbm_surface_release_buffer(k->surface, k->flip_bo);
            if (k->shown_bo)
                gbm_surface_release_buffer(k->surface, k->shown_bo);
        }
    }
    /* the console's text mode back once its picture is */
    if (k)
        vt_switch_close(&k->vt);
    /* the EGL surface owns the GBM buffers and their framebuffers: it goes before the GBM surface */
    if (s->gl)
        s->gl->destroy(s->gl);
    if (k) {
        if (k->surface)
            gbm_surface_destroy(k->surface);
        if (k->gbm)
            gbm_device_destroy(k->gbm);
        if (k->saved_crtc)
            drmModeFreeCrtc(k->saved_crtc);
        if (k->fd >= 0)
            close(k->fd);
        free(k);
    }
    free(s);
}

/* The EGL config whose native visual is the scan-out format: the first one that merely has 8-bit
 * channels may have alpha, and the CRTC would be given a format the GBM surface does not have. */
static int config_for_format(EGLDisplay dpy, uint32_t format, EGLConfig *out)
{
    static const EGLint attribs[] = {EGL_SURFACE_TYPE, EGL_WINDOW_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8,
                                     EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 0, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT,
                                     EGL_NONE};
    EGLint n = 0;
    if (!eglChooseConfig(dpy, attribs, NULL, 0, &n) || n < 1)
        return -1;
    EGLConfig *configs = calloc((size_t)n, sizeof *configs);
    if (!configs)
        return -1;
    int found = -1;
    if (eglChooseConfig(dpy, attribs, configs, n, &n))
        for (int i = 0; i < n && found < 0; i++) {
            EGLint id = 0;
            if (eglGetConfigAttrib(dpy, configs[i], EGL_NATIVE_VISUAL_ID, &id) && (uint32_t)id == format) {
                *out = configs[i];
                found = 0;
            }
        }
    free(configs);
    return found;
}

/* EGL on the GBM device, drawing into the GBM surface, an ES2 context current on it. On failure
 * the caller's close frees what was made. */
static int init_egl_gbm(struct screen *s, struct kms *k, struct error *e)
{
    static const struct egl_platform gbm = {EGL_PLATFORM_GBM_KHR, "GBM", "GBM", "EGL_KHR_platform_gbm",
                                            "EGL_MESA_platform_gbm", "install Mesa's EGL (libegl-mesa0)"};
    char version_label[48];
    snprintf(version_label, sizeof version_label, "GBM, %.32s", k->path);
    s->gl = egl_open(&gbm, k->gbm, k->path, version_label, e);
    if (!s->gl)
        return -1;
    EGLConfig config;
    if (config_for_format(egl_display(s->gl), GBM_FORMAT_XRGB8888, &config) != 0)
        return error_set(e, ERROR_RUNTIME, NULL, "%s: no EGL config renders XRGB8888 for scan-out", k->path);
    return egl_attach_window(s->gl, config, k->surface, e);
}

struct screen *screen_open_kms(const struct kiosk_display *d, struct error *e)
{
    struct screen *s = calloc(1, sizeof *s);
    struct kms *k = calloc(1, sizeof *k);
    if (!s || !k) {
        free(s);
        free(k);
        error_set(e, ERROR_RUNTIME, NULL, "kms: out of memory");
        return NULL;
    }
    k->fd = -1;
    k->vsync = d->vsync;
    s->name = "kms";
    s->priv = k;
    s->framebuffer = 0;
    s->fd = kms_fd;
    s->events = kms_events;
    s->present = kms_present;
    s->close = kms_close;
    if (open_card(k, d, e) != 0) {
        kms_close(s);
        return NULL;
    }
    uint64_t cap = 0;
    k->async_flip = drmGetCap(k->fd, DRM_CAP_ASYNC_PAGE_FLIP, &cap) == 0 && cap;
    k->saved_crtc = drmModeGetCrtc(k->fd, k->crtc_id);
    s->width = k->mode.hdisplay;
    s->height = k->mode.vdisplay;
    k->gbm = gbm_create_device(k->fd);
    if (!k->gbm) {
        error_set(e, ERROR_RUNTIME, NULL, "%s: cannot create a GBM device on it", k->path);
        kms_close(s);
        return NULL;
    }
    k->surface = gbm_surface_create(k->gbm, (uint32_t)s->width, (uint32_t)s->height, GBM_FORMAT_XRGB8888,
                                    GBM_BO_USE_SCANOUT | GBM_BO_USE_RENDERING);
    if (!k->surface) {
        error_set(e, ERROR_RUNTIME, NULL, "%s: cannot create a %dx%d XRGB8888 scan-out surface (gbm_surface_create)",
                  k->path, s->width, s->height);
        kms_close(s);
        return NULL;
    }
    if (init_egl_gbm(s, k, e) != 0) {
        kms_close(s);
        return NULL;
    }
    vt_switch_open(&k->vt, &vt_linux, STDIN_FILENO, k->fd, s->note, sizeof s->note);
    return s;
}
