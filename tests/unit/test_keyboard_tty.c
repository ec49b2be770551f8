/* The keyboard input on a real terminal (a pseudo-terminal here, as tty1 under the kiosk's unit):
 * no key waiting is not the end of input, keys still arrive after idle drains, and only a hang-up
 * ends the source. */
#define _XOPEN_SOURCE 600
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include "kiosk_config/kiosk_config.h"
#include "input/input.h"
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

static void pause_10ms(void)
{
    struct timespec ts = {0, 10000000};
    nanosleep(&ts, NULL);
}

static void test_idle_terminal_stays_open(void **state)
{
    (void)state;
    int master = posix_openpt(O_RDWR | O_NOCTTY);
    assert_true(master >= 0);
    assert_int_equal(grantpt(master), 0);
    assert_int_equal(unlockpt(master), 0);
    int slave = open(ptsname(master), O_RDWR | O_NOCTTY);
    assert_true(slave >= 0);
    assert_true(dup2(slave, STDIN_FILENO) >= 0);
    close(slave);
    static struct kiosk_config config;
    kiosk_config_defaults(&config);
    config.n_inputs = 1;
    snprintf(config.inputs[0].name, sizeof config.inputs[0].name, "keys");
    config.inputs[0].type = KIOSK_INPUT_KEYBOARD;
    struct input_source *src = input_open(&config.inputs[0], 0, stderr, 0.0);
    assert_non_null(src);
    assert_true(src->present);
    struct input_event ev[16];
    /* nothing typed, several drains: no events, and the keyboard is still read */
    for (int k = 0; k < 3; k++) {
        assert_int_equal(src->drain(src, 1.0, ev, 16), 0);
        assert_false(src->finished);
    }
    /* q, typed after the idle drains, arrives (the service key that stops the kiosk) */
    assert_int_equal(write(master, "q", 1), 1);
    int n = 0;
    for (int tries = 0; tries < 200 && n == 0; tries++) {
        n = src->drain(src, 2.0, ev, 16);
        if (n == 0)
            pause_10ms();
    }
    assert_int_equal(n, 1);
    assert_int_equal(ev[0].kind, INPUT_QUIT);
    assert_false(src->finished);
    /* the terminal hangs up: now the keyboard ends */
    close(master);
    for (int tries = 0; tries < 200 && !src->finished; tries++) {
        src->drain(src, 3.0, ev, 16);
        if (!src->finished)
            pause_10ms();
    }
    assert_true(src->finished);
    input_close(src);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_idle_terminal_stays_open),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
