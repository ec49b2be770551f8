/* PNG input/output: round trips, the no-overwrite rule, and damaged or foreign input. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dirent.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "io/image_cache.h"
#include "io/png_io.h"

static char tmpdir[64];

static void path_in_tmp(char *out, size_t len, const char *name)
{
    snprintf(out, len, "%s/%s", tmpdir, name);
}

/* Entries in the scratch directory: leftovers of a failed write would show up here. */
static int count_entries(void)
{
    DIR *d = opendir(tmpdir);
    assert_non_null(d);
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0)
            n++;
    closedir(d);
    return n;
}

static int setup(void **state)
{
    (void)state;
    snprintf(tmpdir, sizeof tmpdir, "/tmp/bentray_png_XXXXXX");
    return mkdtemp(tmpdir) ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    DIR *d = opendir(tmpdir);
    if (!d)
        return -1;
    struct dirent *e;
    char p[512];
    while ((e = readdir(d)) != NULL) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        path_in_tmp(p, sizeof p, e->d_name);
        unlink(p);
    }
    closedir(d);
    return rmdir(tmpdir);
}

/* A pattern with every channel varying, alpha included, so that a swapped or dropped channel
 * cannot go unnoticed. */
static unsigned char *make_pattern(int w, int h, unsigned seed)
{
    unsigned char *px = malloc((size_t)w * h * 4);
    assert_non_null(px);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            unsigned char *p = px + ((size_t)y * w + x) * 4;
            p[0] = (unsigned char)(x * 7 + seed);
            p[1] = (unsigned char)(y * 11 + seed * 3);
            p[2] = (unsigned char)((x ^ y) * 5);
            p[3] = (unsigned char)(255 - (x + y + seed) % 256);
        }
    return px;
}

static unsigned char *read_bytes(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *buf = malloc((size_t)n + 1);
    assert_non_null(buf);
    assert_int_equal(fread(buf, 1, (size_t)n, f), (size_t)n);
    fclose(f);
    *len = (size_t)n;
    return buf;
}

static void write_bytes(const char *path, const unsigned char *buf, size_t len)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(buf, 1, len, f), len);
    assert_int_equal(fclose(f), 0);
}

/* Reads PATH and checks it holds exactly W x H pixels PX. */
static void assert_png_equals(const char *path, int w, int h, const unsigned char *px)
{
    struct error e;
    int rw = 0, rh = 0;
    unsigned char *got = NULL;
    assert_int_equal(png_read_rgba8(path, 4096, &rw, &rh, &got, &e), 0);
    assert_int_equal(rw, w);
    assert_int_equal(rh, h);
    assert_memory_equal(got, px, (size_t)w * h * 4);
    free(got);
}

static void test_round_trip(void **state)
{
    (void)state;
    char path[256];
    struct error e;
    path_in_tmp(path, sizeof path, "round.png");
    const int w = 37, h = 23; /* odd sizes catch row-stride mistakes */
    unsigned char *px = make_pattern(w, h, 1);
    assert_int_equal(png_write_rgba8(path, w, h, px, 0, PNG_COMPRESSION_SMALL, &e), 0);
    assert_png_equals(path, w, h, px);
    free(px);
    unlink(path);
    assert_int_equal(count_entries(), 0);
}

/* Both compressions give back the same pixels; SMALL gives the smaller file of a smooth image (a
 * render's sky and gradients), FAST the larger. */
static void test_compressions(void **state)
{
    (void)state;
    char fast[256], small[256];
    struct error e;
    path_in_tmp(fast, sizeof fast, "fast.png");
    path_in_tmp(small, sizeof small, "small.png");
    const int w = 160, h = 90;
    unsigned char *px = malloc((size_t)w * h * 4);
    assert_non_null(px);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            unsigned char *p = px + 4 * ((size_t)y * w + x);
            p[0] = (unsigned char)(x * 255 / (w - 1));
            p[1] = (unsigned char)(y * 255 / (h - 1));
            p[2] = (unsigned char)((x * y) % 251);
            p[3] = 255;
        }
    assert_int_equal(png_write_rgba8(fast, w, h, px, 0, PNG_COMPRESSION_FAST, &e), 0);
    assert_int_equal(png_write_rgba8(small, w, h, px, 0, PNG_COMPRESSION_SMALL, &e), 0);
    assert_png_equals(fast, w, h, px);
    assert_png_equals(small, w, h, px);
    size_t fast_len, small_len;
    free(read_bytes(fast, &fast_len));
    free(read_bytes(small, &small_len));
    print_message("%dx%d gradient: fast %zu bytes, small %zu bytes\n", w, h, fast_len, small_len);
    assert_true(small_len < fast_len);
    free(px);
    unlink(fast);
    unlink(small);
    assert_int_equal(count_entries(), 0);
}

static void test_refuses_overwrite(void **state)
{
    (void)state;
    char path[256];
    struct error e;
    path_in_tmp(path, sizeof path, "keep.png");
    unsigned char *a = make_pattern(16, 8, 1), *b = make_pattern(16, 8, 2);
    assert_int_equal(png_write_rgba8(path, 16, 8, a, 0, PNG_COMPRESSION_SMALL, &e), 0);
    size_t len_before, len_after;
    unsigned char *before = read_bytes(path, &len_before);

    assert_int_equal(png_write_rgba8(path, 16, 8, b, 0, PNG_COMPRESSION_SMALL, &e), -1);
    assert_non_null(strstr(e.message, path));
    assert_non_null(strstr(e.message, "--force"));
    assert_int_equal(e.status, ERROR_INPUT);   /* the user's: the file is there */

    unsigned char *after = read_bytes(path, &len_after);
    assert_int_equal(len_after, len_before);
    assert_memory_equal(after, before, len_before);
    assert_int_equal(count_entries(), 1);

    free(before);
    free(after);
    free(a);
    free(b);
    unlink(path);
}

static void test_overwrite_with_flag(void **state)
{
    (void)state;
    char path[256];
    struct error e;
    path_in_tmp(path, sizeof path, "replace.png");
    unsigned char *a = make_pattern(16, 8, 1), *b = make_pattern(20, 10, 2);
    assert_int_equal(png_write_rgba8(path, 16, 8, a, 0, PNG_COMPRESSION_SMALL, &e), 0);
    assert_int_equal(png_write_rgba8(path, 20, 10, b, 1, PNG_COMPRESSION_SMALL, &e), 0);
    assert_png_equals(path, 20, 10, b);
    assert_int_equal(count_entries(), 1);
    free(a);
    free(b);
    unlink(path);
}

static void test_truncated_and_corrupt(void **state)
{
    (void)state;
    char path[256], cut[256];
    struct error e;
    path_in_tmp(path, sizeof path, "whole.png");
    path_in_tmp(cut, sizeof cut, "cut.png");
    unsigned char *px = make_pattern(64, 64, 3);
    assert_int_equal(png_write_rgba8(path, 64, 64, px, 0, PNG_COMPRESSION_SMALL, &e), 0);
    size_t len;
    unsigned char *whole = read_bytes(path, &len);
    assert_true(len > 100);

    /* Cuts inside the signature, the header, the pixel data and the end chunk. */
    size_t cuts[] = {0, 5, 8, 20, 33, 45, len / 2, len - 13, len - 1};
    for (size_t k = 0; k < sizeof cuts / sizeof cuts[0]; k++) {
        write_bytes(cut, whole, cuts[k]);
        int w = -7, h = -7;
        unsigned char *got = (unsigned char *)&w;
        error_clear(&e);
        assert_int_equal(png_read_rgba8(cut, 4096, &w, &h, &got, &e), -1);
        assert_non_null(strstr(e.message, cut));
        assert_non_null(strstr(e.message, cuts[k] < 8 ? "not a PNG" : "truncated"));
        assert_int_equal(e.status, ERROR_INPUT);
        /* outputs untouched on failure */
        assert_int_equal(w, -7);
        assert_ptr_equal(got, (unsigned char *)&w);
    }

    /* A flipped byte in the middle of the pixel data fails its CRC. */
    unsigned char *bad = malloc(len);
    assert_non_null(bad);
    memcpy(bad, whole, len);
    bad[len / 2] ^= 0x5a;
    write_bytes(cut, bad, len);
    int w, h;
    unsigned char *got = NULL;
    assert_int_equal(png_read_rgba8(cut, 4096, &w, &h, &got, &e), -1);
    assert_null(got);
    assert_int_equal(e.status, ERROR_INPUT);

    free(bad);
    free(whole);
    free(px);
    unlink(path);
    unlink(cut);
}

static void test_not_png(void **state)
{
    (void)state;
    char path[256];
    struct error e;
    path_in_tmp(path, sizeof path, "scene.txt");
    const char text[] = "[camera]\nposition = 0 0 10\nlook_at = 0 0 0\n";
    write_bytes(path, (const unsigned char *)text, sizeof text - 1);
    int w, h;
    unsigned char *got = NULL;
    assert_int_equal(png_read_rgba8(path, 4096, &w, &h, &got, &e), -1);
    assert_null(got);
    assert_non_null(strstr(e.message, path));
    assert_non_null(strstr(e.message, "not a PNG"));
    assert_int_equal(e.status, ERROR_INPUT);   /* the user's file, not the machine */
    unlink(path);

    path_in_tmp(path, sizeof path, "absent.png");
    assert_int_equal(png_read_rgba8(path, 4096, &w, &h, &got, &e), -1);
    assert_non_null(strstr(e.message, "No such file"));
    assert_int_equal(e.status, ERROR_INPUT);

    /* a directory where the image should be */
    assert_int_equal(png_read_rgba8(tmpdir, 4096, &w, &h, &got, &e), -1);
    assert_non_null(strstr(e.message, "directory"));
    assert_int_equal(e.status, ERROR_INPUT);
}

static void test_max_size(void **state)
{
    (void)state;
    char path[256];
    struct error e;
    path_in_tmp(path, sizeof path, "big.png");
    unsigned char *px = make_pattern(64, 32, 4);
    assert_int_equal(png_write_rgba8(path, 64, 32, px, 0, PNG_COMPRESSION_SMALL, &e), 0);

    int w, h;
    unsigned char *got = NULL;
    assert_int_equal(png_read_rgba8(path, 63, &w, &h, &got, &e), -1);
    assert_null(got);
    assert_non_null(strstr(e.message, path));
    assert_non_null(strstr(e.message, "63"));
    assert_non_null(strstr(e.message, "64 x 32"));
    assert_int_equal(e.status, ERROR_INPUT);

    /* The limit applies to each side, and is inclusive. */
    assert_int_equal(png_read_rgba8(path, 64, &w, &h, &got, &e), 0);
    assert_int_equal(w, 64);
    assert_int_equal(h, 32);
    free(got);
    free(px);
    unlink(path);
}

static void test_missing_directory(void **state)
{
    (void)state;
    char path[256], want[600];
    struct error e;
    path_in_tmp(path, sizeof path, "no/such/dir/out.png");
    unsigned char *px = make_pattern(4, 4, 5);
    assert_int_equal(png_write_rgba8(path, 4, 4, px, 1, PNG_COMPRESSION_SMALL, &e), -1);
    /* the message names the directory that is missing */
    char dir[256];
    snprintf(dir, sizeof dir, "%.*s", (int)(strrchr(path, '/') - path), path);
    snprintf(want, sizeof want, "cannot write %s: directory %s: No such file or directory", path, dir);
    assert_string_equal(e.message, want);
    assert_int_equal(e.status, ERROR_INPUT);
    assert_int_equal(count_entries(), 0);
    free(px);
}

/* Writes W x H pixels of the given simplified-API format with libpng directly, so the reader
 * meets files it did not write itself. */
static void write_format(const char *path, int w, int h, png_uint_32 format, const void *buf,
                         const void *colormap, int colormap_entries)
{
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    img.width = (png_uint_32)w;
    img.height = (png_uint_32)h;
    img.format = format;
    img.colormap_entries = (png_uint_32)colormap_entries;
    assert_int_not_equal(png_image_write_to_file(&img, path, 0, buf, 0, colormap), 0);
}

/* The kiosk's kept images (io/image_cache.h): once read, a file cut short, rewritten or removed on
 * disk does not change what is read again; each reader's size limit still applies; without
 * keeping, every read decodes the file as it is now. */
static void test_image_cache(void **state)
{
    (void)state;
    char path[256];
    struct error e;
    path_in_tmp(path, sizeof path, "kept.png");
    unsigned char *px = make_pattern(20, 10, 2), *other = make_pattern(20, 10, 3);
    assert_int_equal(png_write_rgba8(path, 20, 10, px, 0, PNG_COMPRESSION_SMALL, &e), 0);
    int w, h, owned;
    const unsigned char *got;
    image_cache_keep(1);
    assert_int_equal(image_read(path, 4096, &w, &h, &got, &owned, &e), 0);
    assert_int_equal(owned, 0);
    assert_memory_equal(got, px, 20 * 10 * 4);
    /* cut short on disk: still the kept pixels */
    assert_int_equal(truncate(path, 40), 0);
    assert_int_equal(image_read(path, 4096, &w, &h, &got, &owned, &e), 0);
    assert_int_equal(w, 20);
    assert_int_equal(h, 10);
    assert_memory_equal(got, px, 20 * 10 * 4);
    assert_int_equal(image_read(path, 19, &w, &h, &got, &owned, &e), -1);
    assert_non_null(strstr(e.message, "20 x 10"));
    assert_int_equal(e.status, ERROR_INPUT);
    /* removed, then another image under the same name: still the first */
    unlink(path);
    assert_int_equal(png_write_rgba8(path, 20, 10, other, 0, PNG_COMPRESSION_SMALL, &e), 0);
    assert_int_equal(image_read(path, 4096, &w, &h, &got, &owned, &e), 0);
    assert_memory_equal(got, px, 20 * 10 * 4);
    /* not kept: the file as it is now, owned by the caller */
    image_cache_release();
    assert_int_equal(image_read(path, 4096, &w, &h, &got, &owned, &e), 0);
    assert_int_equal(owned, 1);
    assert_memory_equal(got, other, 20 * 10 * 4);
    free((void *)got);
    free(px);
    free(other);
    unlink(path);
}

static void test_reads_other_formats(void **state)
{
    (void)state;
    char path[256];
    path_in_tmp(path, sizeof path, "fmt.png");
    enum { W = 5, H = 3 };
    unsigned char want[W * H * 4];

    /* 8-bit grey */
    unsigned char grey[W * H];
    for (int k = 0; k < W * H; k++) {
        grey[k] = (unsigned char)(k * 17);
        memset(want + k * 4, grey[k], 3);
        want[k * 4 + 3] = 255;
    }
    write_format(path, W, H, PNG_FORMAT_GRAY, grey, NULL, 0);
    assert_png_equals(path, W, H, want);
    unlink(path);

    /* 16-bit grey and RGB: multiples of 257 scale to exact 8-bit values, with no gamma change */
    uint16_t grey16[W * H], rgb16[W * H * 3];
    for (int k = 0; k < W * H; k++) {
        unsigned v = (unsigned)(k * 17);
        grey16[k] = (uint16_t)(v * 257);
        for (int c = 0; c < 3; c++)
            rgb16[k * 3 + c] = (uint16_t)(((v + (unsigned)c * 60) % 256) * 257);
    }
    write_format(path, W, H, PNG_FORMAT_LINEAR_Y, grey16, NULL, 0);
    assert_png_equals(path, W, H, want);
    unlink(path);
    for (int k = 0; k < W * H; k++) {
        for (int c = 0; c < 3; c++)
            want[k * 4 + c] = (unsigned char)(rgb16[k * 3 + c] / 257);
        want[k * 4 + 3] = 255;
    }
    write_format(path, W, H, PNG_FORMAT_LINEAR_RGB, rgb16, NULL, 0);
    assert_png_equals(path, W, H, want);
    unlink(path);

    /* palette with transparency */
    const unsigned char palette[4 * 4] = {255, 0, 0, 255, 0, 255, 0, 128,
                                          0, 0, 255, 0,   250, 200, 100, 255};
    unsigned char index[W * H];
    for (int k = 0; k < W * H; k++) {
        index[k] = (unsigned char)(k % 4);
        memcpy(want + k * 4, palette + index[k] * 4, 4);
    }
    write_format(path, W, H, PNG_FORMAT_RGBA_COLORMAP, index, palette, 4);
    assert_png_equals(path, W, H, want);
    unlink(path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_round_trip),
        cmocka_unit_test(test_compressions),
        cmocka_unit_test(test_refuses_overwrite),
        cmocka_unit_test(test_overwrite_with_flag),
        cmocka_unit_test(test_truncated_and_corrupt),
        cmocka_unit_test(test_not_png),
        cmocka_unit_test(test_max_size),
        cmocka_unit_test(test_missing_directory),
        cmocka_unit_test(test_reads_other_formats),
        cmocka_unit_test(test_image_cache),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
