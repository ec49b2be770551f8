/* Console switching for the KMS screen (vt_switch.h). */
#include "display/vt_switch.h"
#include <errno.h>
#include <linux/kd.h>
#include <linux/vt.h>
#include <stdio.h>
#include <string.h>
#include <sys/ioctl.h>
#include <xf86drm.h>

static int linux_get_kd_mode(int tty, int *mode)
{
    int m = 0;
    if (ioctl(tty, KDGETMODE, &m) != 0)
        return -1;
    *mode = m;
    return 0;
}

static int linux_set_kd_mode(int tty, int mode)
{
    return ioctl(tty, KDSETMODE, (unsigned long)mode);
}

static int linux_set_vt_mode(int tty, int process, int release_signal, int acquire_signal)
{
    struct vt_mode m;
    memset(&m, 0, sizeof m);
    m.mode = process ? VT_PROCESS : VT_AUTO;
    m.relsig = (short)(process ? release_signal : 0);
    m.acqsig = (short)(process ? acquire_signal : 0);
    return ioctl(tty, VT_SETMODE, &m);
}

static int linux_release_display(int tty, int how)
{
    return ioctl(tty, VT_RELDISP, (unsigned long)how);
}

static int linux_drop_master(int drm)
{
    return drmDropMaster(drm) == 0 ? 0 : -1;
}

static int linux_set_master(int drm)
{
    return drmSetMaster(drm) == 0 ? 0 : -1;
}

const struct vt_ops vt_linux = {
    .get_kd_mode = linux_get_kd_mode,
    .set_kd_mode = linux_set_kd_mode,
    .set_vt_mode = linux_set_vt_mode,
    .release_display = linux_release_display,
    .drop_master = linux_drop_master,
    .set_master = linux_set_master,
};

static volatile sig_atomic_t requested;

static void on_release(int sig)
{
    (void)sig;
    requested |= VT_REQUEST_RELEASE;
}

static void on_acquire(int sig)
{
    (void)sig;
    requested |= VT_REQUEST_ACQUIRE;
}

/* No SA_RESTART, as the kiosk's other signals: the loop's poll() returns at once. */
static void catch_signal(int sig, void (*handler)(int), struct sigaction *saved)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = handler;
    sigemptyset(&sa.sa_mask);
    sigaction(sig, &sa, saved);
}

int vt_switch_open(struct vt_switch *v, const struct vt_ops *ops, int tty, int drm, char *note, size_t notelen)
{
    memset(v, 0, sizeof *v);
    v->ops = ops;
    v->tty = tty;
    v->drm = drm;
    v->showing = 1;
    note[0] = '\0';
    if (ops->get_kd_mode(tty, &v->kd_mode) != 0) {
        snprintf(note, notelen, "console switches are not handled: standard input is no virtual terminal (%s); "
                 "run the kiosk on one (the unit's TTYPath) for them", strerror(errno));
        return 0;
    }
    requested = 0;
    catch_signal(VT_RELEASE_SIGNAL, on_release, &v->saved[0]);
    catch_signal(VT_ACQUIRE_SIGNAL, on_acquire, &v->saved[1]);
    if (ops->set_vt_mode(tty, 1, VT_RELEASE_SIGNAL, VT_ACQUIRE_SIGNAL) != 0) {
        int e = errno;
        sigaction(VT_RELEASE_SIGNAL, &v->saved[0], NULL);
        sigaction(VT_ACQUIRE_SIGNAL, &v->saved[1], NULL);
        snprintf(note, notelen, "console switches are not handled: the terminal refuses VT_PROCESS (%s)", strerror(e));
        return 0;
    }
    v->engaged = 1;
    if (ops->set_kd_mode(tty, KD_GRAPHICS) != 0)
        snprintf(note, notelen, "console switches handled; the console stays in text mode (KDSETMODE: %s)",
                 strerror(errno));
    else
        snprintf(note, notelen, "console switches handled: the console in graphics mode, switches by VT_PROCESS");
    return 1;
}

int vt_switch_pending(void)
{
    int r = requested;
    requested = 0;
    return r;
}

int vt_switch_serve(struct vt_switch *v, int requests, char *note, size_t notelen)
{
    note[0] = '\0';
    if (!v->engaged)
        return 0;
    if ((requests & VT_REQUEST_RELEASE) && (v->showing || v->returning)) {
        /* the display first, then the switch: the console must find the card without a master */
        int dropped = v->showing && v->ops->drop_master(v->drm) == 0;
        if (v->ops->release_display(v->tty, 1) == 0) {
            snprintf(note, notelen, "console switch: the display is handed to the other console%s",
                     v->showing && !dropped ? " (dropping DRM master failed)" : "");
            v->showing = 0;
            v->returning = 0;
        } else {
            /* no switch waits: a signal from someone else */
            int e = errno;
            if (dropped)
                v->ops->set_master(v->drm);
            snprintf(note, notelen, "a release signal with no console switch waiting (VT_RELDISP: %s): ignored",
                     strerror(e));
        }
    }
    if ((requests & VT_REQUEST_ACQUIRE) && !v->showing && !v->returning) {
        if (v->ops->release_display(v->tty, VT_ACKACQ) != 0)
            snprintf(note, notelen, "console switch back: VT_RELDISP VT_ACKACQ failed (%s)", strerror(errno));
        v->returning = 1;
    }
    if (!v->returning)
        return 0;
    /* back on the kiosk's console: the display again, at this turn or, where another program
     * holds the card for a moment, at a later one */
    if (v->ops->set_master(v->drm) != 0) {
        if (requests & VT_REQUEST_ACQUIRE)
            snprintf(note, notelen, "console switch back: cannot take the display (DRM master: %s); trying again "
                     "each turn", strerror(errno));
        return 0;
    }
    v->returning = 0;
    v->showing = 1;
    if (!note[0])
        snprintf(note, notelen, "console switch back: the kiosk draws again");
    return 1;
}

void vt_switch_close(struct vt_switch *v)
{
    if (!v->engaged)
        return;
    v->ops->set_vt_mode(v->tty, 0, 0, 0);
    v->ops->set_kd_mode(v->tty, v->kd_mode);
    sigaction(VT_RELEASE_SIGNAL, &v->saved[0], NULL);
    sigaction(VT_ACQUIRE_SIGNAL, &v->saved[1], NULL);
    v->engaged = 0;
}
