/* The KMS screen's console switches (src/display/vt_switch.c) against a stand-in for the kernel: the
 * console's modes at open and close, a switch away (DRM master dropped before the switch is let
 * go), a switch back (acknowledged, master taken again, the screen told to draw), a stray signal
 * (nothing changes), a master that another program holds for a while (taken at a later turn), and
 * the signals themselves. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <errno.h>
#include <linux/kd.h>
#include <linux/vt.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include "display/vt_switch.h"

/* The kernel's side: the console's state and a log of the calls, one letter each. */
static struct {
    int is_vt;                 /* KDGETMODE works */
    int kd_mode;
    int process;               /* VT_PROCESS set */
    int release_signal, acquire_signal;
    int switch_waiting;        /* a switch away waits for VT_RELDISP 1 */
    int master;                /* the kiosk holds DRM master */
    int master_busy;           /* set_master fails this many more times */
    char calls[64];
} k;

static void called(char c)
{
    size_t n = strlen(k.calls);
    if (n + 1 < sizeof k.calls)
        k.calls[n] = c, k.calls[n + 1] = '\0';
}

static int fake_get_kd_mode(int tty, int *mode)
{
    (void)tty;
    called('g');
    if (!k.is_vt) {
        errno = ENOTTY;
        return -1;
    }
    *mode = k.kd_mode;
    return 0;
}

static int fake_set_kd_mode(int tty, int mode)
{
    (void)tty;
    called(mode == KD_GRAPHICS ? 'G' : 'T');
    k.kd_mode = mode;
    return 0;
}

static int fake_set_vt_mode(int tty, int process, int release_signal, int acquire_signal)
{
    (void)tty;
    called(process ? 'P' : 'A');
    k.process = process;
    k.release_signal = release_signal;
    k.acquire_signal = acquire_signal;
    return 0;
}

static int fake_release_display(int tty, int how)
{
    (void)tty;
    called(how == VT_ACKACQ ? 'a' : 'r');
    if (how == 1 && !k.switch_waiting) {
        errno = EINVAL;
        return -1;
    }
    if (how == 1)
        k.switch_waiting = 0;
    return 0;
}

static int fake_drop_master(int drm)
{
    (void)drm;
    called('d');
    k.master = 0;
    return 0;
}

static int fake_set_master(int drm)
{
    (void)drm;
    called('m');
    if (k.master_busy > 0) {
        k.master_busy--;
        errno = EBUSY;
        return -1;
    }
    k.master = 1;
    return 0;
}

static const struct vt_ops fake = {fake_get_kd_mode, fake_set_kd_mode, fake_set_vt_mode, fake_release_display,
                                   fake_drop_master, fake_set_master};

static int setup(void **state)
{
    (void)state;
    memset(&k, 0, sizeof k);
    k.is_vt = 1;
    k.kd_mode = KD_TEXT;
    k.master = 1;
    signal(VT_RELEASE_SIGNAL, SIG_IGN);
    signal(VT_ACQUIRE_SIGNAL, SIG_IGN);
    return 0;
}

static void test_not_a_console(void **state)
{
    (void)state;
    k.is_vt = 0;
    struct vt_switch v;
    char note[256];
    assert_int_equal(vt_switch_open(&v, &fake, 0, 3, note, sizeof note), 0);
    assert_non_null(strstr(note, "no virtual terminal"));
    assert_int_equal(v.showing, 1);
    assert_string_equal(k.calls, "g");
    /* nothing to serve, nothing to put back */
    assert_int_equal(vt_switch_serve(&v, VT_REQUEST_RELEASE, note, sizeof note), 0);
    assert_int_equal(v.showing, 1);
    vt_switch_close(&v);
    assert_string_equal(k.calls, "g");
}

static void test_open_and_close(void **state)
{
    (void)state;
    struct vt_switch v;
    char note[256];
    assert_int_equal(vt_switch_open(&v, &fake, 0, 3, note, sizeof note), 1);
    assert_true(k.process);
    assert_int_equal(k.release_signal, VT_RELEASE_SIGNAL);
    assert_int_equal(k.acquire_signal, VT_ACQUIRE_SIGNAL);
    assert_int_equal(k.kd_mode, KD_GRAPHICS);
    assert_non_null(strstr(note, "handled"));
    vt_switch_close(&v);
    assert_false(k.process);
    assert_int_equal(k.kd_mode, KD_TEXT);
    assert_string_equal(k.calls, "gPGAT");
}

static void test_switch_away_and_back(void **state)
{
    (void)state;
    struct vt_switch v;
    char note[256];
    vt_switch_open(&v, &fake, 0, 3, note, sizeof note);
    k.calls[0] = '\0';
    /* Ctrl+Alt+F2: the kernel waits for the kiosk */
    k.switch_waiting = 1;
    assert_int_equal(vt_switch_serve(&v, VT_REQUEST_RELEASE, note, sizeof note), 0);
    assert_string_equal(k.calls, "dr");          /* master dropped before the switch is let go */
    assert_false(k.master);
    assert_false(k.switch_waiting);
    assert_int_equal(v.showing, 0);
    assert_non_null(strstr(note, "handed to the other console"));
    /* turns on the other console do nothing */
    assert_int_equal(vt_switch_serve(&v, 0, note, sizeof note), 0);
    assert_string_equal(note, "");
    assert_string_equal(k.calls, "dr");
    /* back: acknowledged, master taken, the screen must draw */
    assert_int_equal(vt_switch_serve(&v, VT_REQUEST_ACQUIRE, note, sizeof note), 1);
    assert_string_equal(k.calls, "dram");
    assert_true(k.master);
    assert_int_equal(v.showing, 1);
    assert_non_null(strstr(note, "draws again"));
    vt_switch_close(&v);
}

static void test_stray_signals(void **state)
{
    (void)state;
    struct vt_switch v;
    char note[256];
    vt_switch_open(&v, &fake, 0, 3, note, sizeof note);
    k.calls[0] = '\0';
    /* a release signal with no switch waiting: the display stays the kiosk's */
    assert_int_equal(vt_switch_serve(&v, VT_REQUEST_RELEASE, note, sizeof note), 0);
    assert_int_equal(v.showing, 1);
    assert_true(k.master);
    assert_non_null(strstr(note, "ignored"));
    /* an acquire while in front: nothing */
    k.calls[0] = '\0';
    assert_int_equal(vt_switch_serve(&v, VT_REQUEST_ACQUIRE, note, sizeof note), 0);
    assert_string_equal(k.calls, "");
    assert_string_equal(note, "");
    vt_switch_close(&v);
}

static void test_master_taken_later(void **state)
{
    (void)state;
    struct vt_switch v;
    char note[256];
    vt_switch_open(&v, &fake, 0, 3, note, sizeof note);
    k.switch_waiting = 1;
    vt_switch_serve(&v, VT_REQUEST_RELEASE, note, sizeof note);
    k.master_busy = 2;
    assert_int_equal(vt_switch_serve(&v, VT_REQUEST_ACQUIRE, note, sizeof note), 0);
    assert_non_null(strstr(note, "trying again"));
    assert_int_equal(v.showing, 0);
    assert_int_equal(vt_switch_serve(&v, 0, note, sizeof note), 0);
    assert_string_equal(note, "");
    assert_int_equal(vt_switch_serve(&v, 0, note, sizeof note), 1);
    assert_int_equal(v.showing, 1);
    assert_true(k.master);
    /* away again before the master came back: the switch is let go without a master to drop */
    k.switch_waiting = 1;
    vt_switch_serve(&v, VT_REQUEST_RELEASE, note, sizeof note);
    k.master_busy = 1;
    vt_switch_serve(&v, VT_REQUEST_ACQUIRE, note, sizeof note);
    k.switch_waiting = 1;
    k.calls[0] = '\0';
    assert_int_equal(vt_switch_serve(&v, VT_REQUEST_RELEASE, note, sizeof note), 0);
    assert_string_equal(k.calls, "r");
    assert_int_equal(v.showing, 0);
    assert_int_equal(v.returning, 0);
    vt_switch_close(&v);
}

static void test_signals(void **state)
{
    (void)state;
    struct vt_switch v;
    char note[256];
    vt_switch_open(&v, &fake, 0, 3, note, sizeof note);
    assert_int_equal(vt_switch_pending(), 0);
    raise(VT_RELEASE_SIGNAL);
    raise(VT_ACQUIRE_SIGNAL);
    assert_int_equal(vt_switch_pending(), VT_REQUEST_RELEASE | VT_REQUEST_ACQUIRE);
    assert_int_equal(vt_switch_pending(), 0);
    vt_switch_close(&v);
    /* the actions before are back: ignored, as the kiosk sets them */
    raise(VT_RELEASE_SIGNAL);
    raise(VT_ACQUIRE_SIGNAL);
    assert_int_equal(vt_switch_pending(), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_not_a_console, setup),
        cmocka_unit_test_setup(test_open_and_close, setup),
        cmocka_unit_test_setup(test_switch_away_and_back, setup),
        cmocka_unit_test_setup(test_stray_signals, setup),
        cmocka_unit_test_setup(test_master_taken_later, setup),
        cmocka_unit_test_setup(test_signals, setup),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
