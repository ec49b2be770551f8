/* A long kiosk run: thousands of frames of random knob turns and button presses (the pipeline view
 * included), three times over in one process. The heap in use must not grow from run to run: a
 * leak of a few hundred bytes per frame would show. Under `make test-sanitize` the same run checks
 * every access instead (AddressSanitizer keeps freed memory aside, so the heap is not measured). */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include "kiosk_config/kiosk_config.h"
#include "kiosk/kiosk_loop.h"
#include <malloc.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* one per frame of the virtual clock: 50 s of a busy visitor; fewer under AddressSanitizer, which
 * checks accesses rather than the heap and runs several times slower */
#if defined(__SANITIZE_ADDRESS__)
#define SOAK_EVENTS 400
#else
#define SOAK_EVENTS 1500
#endif
#define SOAK_RUNS 3
/* bound: what the runs after the first may add to the heap in use. Each run opens and closes its
 * own GL context, so every run starts from the same state; a leak of 250 bytes per frame would
 * add 750 kB over two runs */
#define SOAK_GROWTH_BOUND_KB 700

#if defined(__SANITIZE_ADDRESS__)
#define SOAK_MEASURES_HEAP 0
#else
#define SOAK_MEASURES_HEAP 1
#endif

static long heap_in_use_kb(void)
{
    struct mallinfo2 m = mallinfo2();
    return (long)((m.uordblks + m.hblkhd) / 1024);
}

/* A visitor who never stops: every frame a knob turns or a button is pressed. */
static void write_script(const char *path)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    static const char *const actions[] = {"next_scene", "previous_scene", "cycle_effects", "reset", "pipeline_view"};
    unsigned seed = 12345;
    for (int i = 0; i < SOAK_EVENTS; i++) {
        seed = seed * 1103515245u + 12345u;
        unsigned r = (seed >> 16) & 0x7fff;
        double t = (i + 1) / KIOSK_VIRTUAL_FPS;
        if (r % 10 == 0)
            fprintf(f, "%.4f press %s\n", t, actions[(r / 10) % 5]);
        else
            fprintf(f, "%.4f turn %s %+d\n", t, r % 2 ? "speed" : "mass", (int)(r % 11) - 5);
    }
    fprintf(f, "%.4f frame\n", (SOAK_EVENTS + 2) / KIOSK_VIRTUAL_FPS);
    fclose(f);
}

static void test_memory_does_not_grow(void **state)
{
    (void)state;
    char dir[] = "/tmp/bt_soak_XXXXXX", cwd[512], path[1024];
    assert_non_null(mkdtemp(dir));
    assert_non_null(getcwd(cwd, sizeof cwd));
    snprintf(path, sizeof path, "%s/visitor.events", dir);
    write_script(path);
    snprintf(path, sizeof path, "%s/kiosk.conf", dir);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fprintf(f, "[kiosk]\nscenes = %s/assets/scenes/schwarzschild.scene, %s/assets/scenes/cube_approach.scene\n"
               "preview_width = 32\npreview_height = 18\nwidth = 64\nheight = 36\nhud = on\n"
               "[display]\nbackend = headless\nheadless_out = %s\nheadless_frames = 1\n"
               "[speed]\ninput = replay\n[mass]\ninput = replay\nmax = 1\nstart = 0.12\n"
               "[input replay]\ntype = script\npath = visitor.events\n",
            cwd, cwd, dir);
    fclose(f);
    static struct kiosk_config c;
    struct error e;
    if (kiosk_config_load(&c, path, &e) != 0 || kiosk_config_check(&c, &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
    long after[SOAK_RUNS];
    for (int run = 0; run < SOAK_RUNS; run++) {
        FILE *log = tmpfile();
        struct kiosk_run_options o = {.gl_backend = "egl", .force = 1, .log = log};
        assert_int_equal(kiosk_run(&c, &o), 0);
        fclose(log);
        after[run] = heap_in_use_kb();
        print_message("run %d: heap in use %ld kB\n", run + 1, after[run]);
    }
    if (SOAK_MEASURES_HEAP) {
        assert_true(after[0] > 0);
        assert_true(after[SOAK_RUNS - 1] - after[0] <= SOAK_GROWTH_BOUND_KB);
    }
    snprintf(path, sizeof path, "%s/frame_0001.png", dir);
    assert_int_equal(unlink(path), 0);
    snprintf(path, sizeof path, "%s/visitor.events", dir);
    unlink(path);
    snprintf(path, sizeof path, "%s/kiosk.conf", dir);
    unlink(path);
    rmdir(dir);
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_memory_does_not_grow)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
