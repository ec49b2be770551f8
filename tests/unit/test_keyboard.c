/* The keyboard input, fed through a pipe in place of the terminal: keys and arrows become the
 * fixed mapping's events, an arrow split across two reads is still an arrow (not Escape, which
 * would stop the kiosk), a lone Escape is Escape once nothing follows it, and the end of input ends
 * the source. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include "kiosk_config/kiosk_config.h"
#include "input/input.h"
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static struct kiosk_config config;
static int write_end;
static struct input_source *src;

static int open_keyboard(void **state)
{
    (void)state;
    kiosk_config_defaults(&config);
    config.n_inputs = 1;
    snprintf(config.inputs[0].name, sizeof config.inputs[0].name, "keys");
    config.inputs[0].type = KIOSK_INPUT_KEYBOARD;
    int p[2];
    assert_int_equal(pipe(p), 0);
    assert_true(dup2(p[0], STDIN_FILENO) >= 0);
    close(p[0]);
    write_end = p[1];
    src = input_open(&config.inputs[0], 0, stderr, 0.0);
    assert_non_null(src);
    assert_true(src->present);
    return 0;
}

static int close_keyboard(void **state)
{
    (void)state;
    input_close(src);
    return 0;
}

static int type_and_drain(const char *bytes, struct input_event *ev, int max)
{
    if (*bytes)
        assert_int_equal(write(write_end, bytes, strlen(bytes)), (ssize_t)strlen(bytes));
    return src->drain(src, 1.0, ev, max);
}

static void test_keys(void **state)
{
    (void)state;
    struct input_event ev[16];
    int n = type_and_drain("n\x1b[Aa", ev, 16);
    assert_int_equal(n, 3);
    assert_int_equal(ev[0].kind, INPUT_ACTION);
    assert_int_equal(ev[0].action, KIOSK_ACTION_NEXT_SCENE);
    assert_int_equal(ev[1].kind, INPUT_KNOB);
    assert_int_equal(ev[1].knob, INPUT_KNOB_SPEED);
    assert_int_equal(ev[1].counts, 1);
    assert_int_equal(ev[2].knob, INPUT_KNOB_MASS);
    assert_int_equal(ev[2].counts, -1);
    assert_int_equal(ev[0].source, 0);
    assert_true(ev[0].t == 1.0);
    /* staff mode: i */
    n = type_and_drain("i", ev, 16);
    assert_int_equal(n, 1);
    assert_int_equal(ev[0].kind, INPUT_ACTION);
    assert_int_equal(ev[0].action, KIOSK_ACTION_STAFF_MODE);
}

static void test_arrow_split_across_reads(void **state)
{
    (void)state;
    struct input_event ev[16];
    assert_int_equal(type_and_drain("\x1b", ev, 16), 0);       /* held back: more may follow */
    assert_int_equal(type_and_drain("[", ev, 16), 0);
    int n = type_and_drain("B", ev, 16);
    assert_int_equal(n, 1);
    assert_int_equal(ev[0].kind, INPUT_KNOB);                   /* Down: speed -1, no Escape */
    assert_int_equal(ev[0].counts, -1);
}

static void test_lone_escape(void **state)
{
    (void)state;
    struct input_event ev[16];
    assert_int_equal(type_and_drain("\x1b", ev, 16), 0);
    int n = type_and_drain("", ev, 16);                         /* nothing followed */
    assert_int_equal(n, 1);
    assert_int_equal(ev[0].kind, INPUT_QUIT);
}

static void test_no_room_no_loss(void **state)
{
    (void)state;
    struct input_event ev[16];
    /* fewer than three slots: nothing is read, so nothing read can be dropped */
    assert_int_equal(type_and_drain("rv", ev, 2), 0);
    int n = type_and_drain("", ev, 16);
    assert_int_equal(n, 2);
    assert_int_equal(ev[0].action, KIOSK_ACTION_RESET);
    assert_int_equal(ev[1].action, KIOSK_ACTION_PIPELINE_VIEW);
}

static void test_end_of_input(void **state)
{
    (void)state;
    struct input_event ev[16];
    close(write_end);
    assert_int_equal(src->drain(src, 2.0, ev, 16), 0);
    assert_true(src->finished);
    struct pollfd fds[INPUT_MAX_FDS];
    assert_int_equal(src->fds(src, fds, INPUT_MAX_FDS), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_keys),
        cmocka_unit_test(test_arrow_split_across_reads),
        cmocka_unit_test(test_lone_escape),
        cmocka_unit_test(test_no_room_no_loss),
        cmocka_unit_test(test_end_of_input),
    };
    return cmocka_run_group_tests(tests, open_keyboard, close_keyboard);
}
