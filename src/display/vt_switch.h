/* Console switching for the KMS screen. The kiosk takes its virtual terminal (the unit's tty1) in
 * graphics mode, so that no console text or cursor shows over the picture, and in VT_PROCESS mode:
 * a switch to another console (Ctrl+Alt+F2, chvt 2) waits until the kiosk has dropped DRM master
 * and said so (VT_RELDISP), so that the console can show itself; a switch back gives the display
 * to the kiosk again, which sets its mode and draws. Both modes are put back at close. The kernel
 * announces the switches by signals (VT_RELEASE_SIGNAL away, VT_ACQUIRE_SIGNAL back); a stray
 * signal, with no switch waiting, changes nothing. */
#ifndef BT_KIOSK_VT_SWITCH_H
#define BT_KIOSK_VT_SWITCH_H
#include <signal.h>
#include <stddef.h>

#define VT_RELEASE_SIGNAL SIGUSR1
#define VT_ACQUIRE_SIGNAL SIGUSR2

/* The console's ioctls and the DRM master behind pointers, as kmscube's back-ends are, so that
 * tests/unit/test_vt_switch.c can play the kernel's part. Each returns 0, or -1 with errno. */
struct vt_ops {
    int (*get_kd_mode)(int tty, int *mode);                    /* KDGETMODE: fails on no console */
    int (*set_kd_mode)(int tty, int mode);                     /* KDSETMODE: KD_TEXT or KD_GRAPHICS */
    int (*set_vt_mode)(int tty, int process, int release_signal, int acquire_signal); /* VT_SETMODE */
    int (*release_display)(int tty, int how);                  /* VT_RELDISP: 1, or VT_ACKACQ */
    int (*drop_master)(int drm);
    int (*set_master)(int drm);
};
extern const struct vt_ops vt_linux;

enum vt_request { VT_REQUEST_RELEASE = 1, VT_REQUEST_ACQUIRE = 2 };

struct vt_switch {
    const struct vt_ops *ops;
    int tty, drm;
    int engaged;             /* VT_PROCESS is set: a switch waits for the kiosk */
    int showing;             /* the kiosk's console is in front and the kiosk holds the display */
    int returning;           /* switched back, DRM master not yet taken again */
    int kd_mode;             /* the console's mode before, put back at close */
    struct sigaction saved[2]; /* the two signals' actions before, put back at close */
};

/* Take the console on tty for the KMS screen on drm. 1 when engaged; 0 when tty is no virtual
 * terminal or refuses the modes (the screen works, switches are not handled), with the reason in
 * note. Either way v->showing is 1. */
int vt_switch_open(struct vt_switch *v, const struct vt_ops *ops, int tty, int drm, char *note, size_t notelen);
/* The requests (enum vt_request bits) the signals brought since the last call; cleared. */
int vt_switch_pending(void);
/* Serve requests, at every turn of the loop (0 for none): a release drops DRM master and lets the
 * switch go; an acquire acknowledges it and takes the master back (again at later turns while
 * another program holds it). What was done goes to note ("" for nothing). 1 when the display has
 * come back (the screen must set its mode and draw a frame), else 0. */
int vt_switch_serve(struct vt_switch *v, int requests, char *note, size_t notelen);
/* The console's modes and the signals' actions as they were. */
void vt_switch_close(struct vt_switch *v);

#endif
