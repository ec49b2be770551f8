/* The one error type (io/error.h): filled and printed the same way by every module, and the status
 * that decides the exit code set by the readers of what users write (scenes, --set, the kiosk's
 * configuration) to ERROR_INPUT, and by a machine's failure to ERROR_RUNTIME. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "io/error.h"
#include "kiosk_config/kiosk_config.h"
#include "scene/scene.h"

static void test_set_and_print(void **state)
{
    (void)state;
    struct error e;
    error_clear(&e);
    assert_int_equal(e.status, ERROR_NONE);
    assert_int_equal(error_set(&e, ERROR_INPUT, "a.scene:3", "key '%s' in [%s]", "fov", "camera"), -1);
    assert_int_equal(e.status, ERROR_INPUT);
    assert_string_equal(e.where, "a.scene:3");
    assert_string_equal(e.message, "key 'fov' in [camera]");
    char text[256] = "";
    FILE *f = fmemopen(text, sizeof text, "w");
    assert_non_null(f);
    error_print(&e, "bentray render", f);
    error_set(&e, ERROR_RUNTIME, NULL, "no GPU");
    error_print(&e, NULL, f);
    fclose(f);
    assert_string_equal(text, "bentray render: a.scene:3: error: key 'fov' in [camera]\nerror: no GPU\n");
}

/* Into a caller's buffer: "WHERE: MESSAGE", the message alone without a place, cut to the buffer. */
static void test_format(void **state)
{
    (void)state;
    struct error e;
    char buf[64], tiny[8];
    error_set(&e, ERROR_INPUT, "font.ttf", "not a regular file");
    assert_int_equal(error_format(&e, buf, sizeof buf), -1);
    assert_string_equal(buf, "font.ttf: not a regular file");
    error_set(&e, ERROR_RUNTIME, NULL, "out of memory");
    error_format(&e, buf, sizeof buf);
    assert_string_equal(buf, "out of memory");
    error_format(&e, tiny, sizeof tiny);
    assert_string_equal(tiny, "out of ");
}

/* Each reader of what a user writes says the failure is the user's. */
/* A path the user named and the system refused is the user's to fix (exit code 2); a failure of the
 * machine under it is not (exit code 1). */
static void test_status_of_errno(void **state)
{
    (void)state;
    static const int input[] = {0, ENOENT, EACCES, EPERM, ENOTDIR, EISDIR, EROFS, ENAMETOOLONG, ELOOP, ENXIO};
    static const int runtime[] = {ENOMEM, EIO, ENOSPC, EMFILE, EDQUOT, EFBIG};
    for (size_t k = 0; k < sizeof input / sizeof input[0]; k++)
        assert_int_equal(error_status_of_errno(input[k]), ERROR_INPUT);
    for (size_t k = 0; k < sizeof runtime / sizeof runtime[0]; k++)
        assert_int_equal(error_status_of_errno(runtime[k]), ERROR_RUNTIME);
}

static void test_readers_set_input_status(void **state)
{
    (void)state;
    static struct scene s;
    static struct kiosk_config c;
    struct error e;
    assert_int_equal(scene_load(&s, "tests/scenes_bad/bad_choice.scene", &e), -1);
    assert_int_equal(e.status, ERROR_INPUT);
    assert_non_null(strstr(e.where, "bad_choice.scene:"));
    assert_int_equal(scene_load(&s, "tests/scenes_bad/camera_in_horizon.scene", &e), 0);
    assert_int_equal(scene_validate(&s, &e), -1);
    assert_int_equal(e.status, ERROR_INPUT);  /* a whole-scene check */
    assert_int_equal(scene_load(&s, "tests/scenes_bad/no-such-file.scene", &e), -1);
    assert_int_equal(e.status, ERROR_INPUT);
    assert_int_equal(scene_load(&s, "assets/scenes/schwarzschild.scene", &e), 0);
    assert_int_equal(e.status, ERROR_NONE);
    assert_int_equal(scene_set(&s, "model.mass=heavy", &e), -1);
    assert_int_equal(e.status, ERROR_INPUT);
    assert_string_equal(e.where, "--set model.mass=heavy");
    assert_int_equal(scene_set(&s, "camera", &e), -1);
    assert_int_equal(e.status, ERROR_INPUT);
    assert_int_equal(scene_set_number(&s, "model.mass", -1.0, &e), -1);
    assert_int_equal(e.status, ERROR_INPUT);
    assert_int_equal(scene_set_number(&s, "model.mass", 2.0, &e), 0);
    assert_int_equal(e.status, ERROR_NONE);
    assert_int_equal(kiosk_config_load(&c, "tests/scenes_bad/bad_choice.scene", &e), -1);
    assert_int_equal(e.status, ERROR_INPUT);
    assert_int_equal(kiosk_config_load(&c, "kiosk/kiosk.conf", &e), 0);
    assert_int_equal(e.status, ERROR_NONE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_set_and_print),
        cmocka_unit_test(test_format),
        cmocka_unit_test(test_readers_set_input_status),
        cmocka_unit_test(test_status_of_errno),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
