/* The named limits that stand before allocations (docs/LIMITS.md): the image's pixel count from
 * the scene, --set and --size; PNG sizes declared in their headers, found where the scene names the
 * file; the magnitude of scene numbers; dump headers; and the BT_FAULT test hook's word matching. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cli/options.h"
#include "gl/caps.h"
#include "results/dump.h"
#include "scene/scene.h"
#include "scene/scene_keys.h"

/* ---- files under one temporary directory ---------------------------------------------------- */

static char dir[64];

static int make_dir(void **state)
{
    (void)state;
    strcpy(dir, "/tmp/bentray_limits_XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int remove_dir(void **state)
{
    char cmd[128];
    (void)state;
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd) == 0 ? 0 : -1;
}

static const char *file_in_dir(const char *name, const void *bytes, size_t len)
{
    static char path[8][128];
    static int next;
    char *p = path[next++ % 8];
    snprintf(p, sizeof path[0], "%s/%s", dir, name);
    FILE *f = fopen(p, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(bytes, 1, len, f), len);
    assert_int_equal(fclose(f), 0);
    return p;
}

static const char *scene_file(const char *name, const char *text)
{
    return file_in_dir(name, text, strlen(text));
}

static void put_be32(unsigned char *p, unsigned long v)
{
    p[0] = (unsigned char)(v >> 24), p[1] = (unsigned char)(v >> 16), p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

/* The start of a PNG file: signature and IHDR declaring width x height, and nothing else: the scene
 * loader reads only the header, so no pixel data is needed to prove the limit. */
static void png_header(const char *name, unsigned long width, unsigned long height)
{
    unsigned char head[33] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R'};
    put_be32(head + 16, width);
    put_be32(head + 20, height);
    head[24] = 8;   /* bit depth */
    head[25] = 6;   /* RGBA */
    file_in_dir(name, head, sizeof head);
}

static void assert_contains(const char *text, const char *part)
{
    if (!strstr(text, part))
        fail_msg("\"%s\" does not contain \"%s\"", text, part);
}

/* ---- the image's pixel count ------------------------------------------------------------------ */

static void test_size_option(void **state)
{
    int w = 0, h = 0;
    (void)state;
    assert_int_equal(option_parse_size("8192x1024", &w, &h), 0);     /* exactly SCENE_MAX_PIXELS */
    assert_int_equal((long)w * h, SCENE_MAX_PIXELS);
    assert_int_equal(option_parse_size("3840x2160", &w, &h), 0);
    assert_int_equal(option_parse_size("8192x1025", &w, &h), -1);
    assert_int_equal(option_parse_size("8192x8192", &w, &h), -1);
    assert_int_equal(option_parse_size("8193x1", &w, &h), -1);
    assert_int_equal(option_parse_size("0x10", &w, &h), -1);
    assert_int_equal(option_parse_size("99999999999999999999x1", &w, &h), -1);
    assert_int_equal(option_parse_size("-5x10", &w, &h), -1);
}

static void test_pixels_in_scene_file(void **state)
{
    struct scene s;
    struct error err;
    (void)state;
    assert_int_equal(scene_load(&s, scene_file("edge.scene", "[render]\nwidth = 8192\nheight = 1024\n"), &err), 0);
    assert_int_equal((long)s.render.width * s.render.height, SCENE_MAX_PIXELS);

    /* the side that crosses the limit is the line named, whichever comes first */
    const char *path = scene_file("wide.scene", "[render]\nwidth = 8192\nheight = 1025\n");
    assert_int_equal(scene_load(&s, path, &err), -1);
    assert_contains(err.where, ":3");
    assert_contains(err.message, "8192x1025");
    assert_contains(err.message, "8388608");
    path = scene_file("tall.scene", "[render]\nheight = 8192\n\nwidth = 8192\n");
    assert_int_equal(scene_load(&s, path, &err), -1);
    assert_contains(err.where, ":4");
    assert_contains(err.message, "key 'width'");
}

static void test_pixels_by_set_and_validate(void **state)
{
    struct scene s;
    struct error err;
    (void)state;
    assert_int_equal(scene_load(&s, scene_file("small.scene", "[render]\nwidth = 64\nheight = 48\n"), &err), 0);
    assert_int_equal(scene_set(&s, "render.width=8192", &err), 0);
    assert_int_equal(scene_set(&s, "render.height=8192", &err), -1);
    assert_contains(err.where, "--set render.height=8192");
    assert_contains(err.message, "8388608");
    assert_int_equal(s.render.height, 48);      /* a refused value is not stored */

    /* a scene changed in code is caught by scene_validate */
    s.render.width = 4096;
    s.render.height = 4096;
    assert_int_equal(scene_validate(&s, &err), -1);
    assert_contains(err.message, "4096x4096");
    s.render.height = 0;
    assert_int_equal(scene_validate(&s, &err), -1);
    assert_contains(err.message, "from 1 to 8192");
    s.render.height = 2048;
    s.camera.position = v3(0, 0, 5);
    assert_int_equal(scene_validate(&s, &err), 0);
}

/* ---- numbers the GPU can hold ------------------------------------------------------------------ */

static void test_number_magnitude(void **state)
{
    struct scene s;
    struct error err;
    (void)state;
    assert_int_equal(scene_load(&s, scene_file("edge.scene", "[light a]\nposition = 1e18 -1e18 0\n"), &err), 0);
    const char *path = scene_file("far.scene", "[camera]\nfov = 40\n[light a]\nposition = 0 1.0001e18 0\n");
    assert_int_equal(scene_load(&s, path, &err), -1);
    assert_contains(err.where, ":4");
    assert_contains(err.message, "1e18");
    path = scene_file("huge.scene", "[render]\nbound_radius = 1e300\n");
    assert_int_equal(scene_load(&s, path, &err), -1);
    assert_contains(err.where, ":2");
    assert_contains(err.message, "32-bit floats");
    assert_int_equal(scene_load(&s, scene_file("ok.scene", "[render]\nwidth = 16\n"), &err), 0);
    assert_int_equal(scene_set(&s, "camera.look_at=0 0 -2e18", &err), -1);
    assert_int_equal(scene_set(&s, "render.step=inf", &err), -1);
    assert_contains(err.message, "not a finite number");
}

/* ---- textures and sky faces, as their PNG headers declare them ----------------------------------- */

static void test_texture_size_from_header(void **state)
{
    struct scene s;
    struct error err;
    (void)state;
    png_header("big.png", 100000, 100000);
    png_header("edge.png", SCENE_MAX_TEXTURE_SIZE, SCENE_MAX_TEXTURE_SIZE);
    png_header("long.png", SCENE_MAX_TEXTURE_SIZE + 1, 1);
    file_in_dir("other.png", "not a PNG", strlen("not a PNG"));

    const char *path = scene_file("big.scene", "[object a]\ntype = sphere\n\ntexture = big.png\n");
    assert_int_equal(scene_load(&s, path, &err), -1);
    assert_contains(err.where, ":4");
    assert_contains(err.message, "100000x100000");
    assert_contains(err.message, "at most 8192 pixels a side");
    path = scene_file("long.scene", "[object a]\ntype = sphere\ntexture = long.png\n");
    assert_int_equal(scene_load(&s, path, &err), -1);
    assert_contains(err.where, ":3");
    path = scene_file("edge.scene", "[object a]\ntype = sphere\ntexture = edge.png\n"
                                    "[object b]\ntype = rect\ntexture = other.png\n");
    assert_int_equal(scene_load(&s, path, &err), 0);
    assert_int_equal(s.n_textures, 2);
}

static void test_cubemap_faces(void **state)
{
    static const char *const faces[6] = {"px", "nx", "py", "ny", "pz", "nz"};
    struct scene s;
    struct error err;
    char name[32];
    (void)state;
    for (int i = 0; i < 6; i++) {
        snprintf(name, sizeof name, "sq_%s.png", faces[i]);
        png_header(name, 64, 64);
        snprintf(name, sizeof name, "mixed_%s.png", faces[i]);
        png_header(name, i == 3 ? 32 : 64, i == 3 ? 32 : 64);
        snprintf(name, sizeof name, "flat_%s.png", faces[i]);
        png_header(name, 64, i == 0 ? 32 : 64);
        snprintf(name, sizeof name, "vast_%s.png", faces[i]);
        png_header(name, 65536, 65536);
    }
    assert_int_equal(scene_load(&s, scene_file("sq.scene", "[sky]\ntype = cubemap\ncubemap = sq\n"), &err), 0);

    const char *path = scene_file("mixed.scene", "[sky]\ntype = cubemap\ncubemap = mixed\n");
    assert_int_equal(scene_load(&s, path, &err), -1);
    assert_contains(err.where, ":3");
    assert_contains(err.message, "mixed_ny.png");
    assert_contains(err.message, "same size");
    path = scene_file("flat.scene", "[sky]\ntype = cubemap\ncubemap = flat\n");
    assert_int_equal(scene_load(&s, path, &err), -1);
    assert_contains(err.message, "must be square");
    path = scene_file("vast.scene", "[sky]\ntype = cubemap\ncubemap = vast\n");
    assert_int_equal(scene_load(&s, path, &err), -1);
    assert_contains(err.message, "65536x65536");
    assert_contains(err.message, "at most 8192");
}

/* ---- dump headers ------------------------------------------------------------------------------ */

static void put_le32(unsigned char *p, uint32_t v)
{
    for (int i = 0; i < 4; i++)
        p[i] = (unsigned char)(v >> (8 * i));
}

static const char *dump_header(const char *name, uint32_t width, uint32_t height)
{
    unsigned char header[DUMP_HEADER_SIZE] = {0};
    memcpy(header, DUMP_MAGIC, 8);
    put_le32(header + 8, DUMP_VERSION);
    put_le32(header + 12, width);
    put_le32(header + 16, height);
    put_le32(header + 20, DUMP_RECORD_SIZE);
    return file_in_dir(name, header, sizeof header);
}

static void test_dump_header_limits(void **state)
{
    struct dump d;
    struct error e;
    (void)state;
    /* both sides allowed, their product not: refused on the header alone */
    assert_int_equal(dump_read(dump_header("square.dump", 4096, 4096), &d, &e), -1);
    assert_contains(e.message, "unsupported dump");
    assert_contains(e.message, "8388608 pixels");
    assert_int_equal(e.status, ERROR_INPUT);
    assert_null(d.records);
    assert_int_equal(dump_read(dump_header("side.dump", 8193, 1), &d, &e), -1);
    assert_contains(e.message, "unsupported dump");
    /* within the limits but without its records: refused before the records are allocated */
    assert_int_equal(dump_read(dump_header("short.dump", 8192, 1024), &d, &e), -1);
    assert_contains(e.message, "truncated: 0 of 8388608 records");
    assert_int_equal(e.status, ERROR_INPUT);
    assert_null(d.records);
}

/* ---- the fault hook ----------------------------------------------------------------------------- */

static void test_fault_words(void **state)
{
    (void)state;
    unsetenv("BT_FAULT");
    assert_false(gl_fault("fbo_incomplete"));
    setenv("BT_FAULT", "fbo_incomplete", 1);
    assert_true(gl_fault("fbo_incomplete"));
    assert_false(gl_fault("half_fbo_incomplete"));
    assert_false(gl_fault("float_render"));
    setenv("BT_FAULT", "float_render,half_fbo_incomplete", 1);
    assert_true(gl_fault("float_render"));
    assert_true(gl_fault("half_fbo_incomplete"));
    assert_false(gl_fault("fbo_incomplete"));
    assert_false(gl_fault("half_float_render"));
    setenv("BT_FAULT", "float_renderer fbo_incomplete", 1);
    assert_false(gl_fault("float_render"));
    assert_true(gl_fault("fbo_incomplete"));
    assert_false(gl_fault(""));
    unsetenv("BT_FAULT");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_size_option),
        cmocka_unit_test(test_pixels_in_scene_file),
        cmocka_unit_test(test_pixels_by_set_and_validate),
        cmocka_unit_test(test_number_magnitude),
        cmocka_unit_test(test_texture_size_from_header),
        cmocka_unit_test(test_cubemap_faces),
        cmocka_unit_test(test_dump_header_limits),
        cmocka_unit_test(test_fault_words),
    };
    return cmocka_run_group_tests(tests, make_dir, remove_dir);
}
