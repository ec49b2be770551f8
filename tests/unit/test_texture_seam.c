/* Texture coordinates that go round (src/scene/texture_wrap.h): the sphere's longitude and the
 * disk's angle meet themselves at a seam, where the texels at the two ends of the coordinate are
 * neighbours. Both engines filter across it as GL_REPEAT would, so a texture of two texels along
 * that coordinate, black and white, runs through grey across the seam instead of jumping from white
 * to black (as clamping to the texture's edges did), and the GPU gives the CPU reference's colours. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdlib.h>
#include "hard_cases.h"
#include "io/png_io.h"

#define SIDE 64
/* Beside the seam, neighbouring pixels differ by the texture's slope (two texels over half a turn,
 * about 8 levels a pixel here); the jump at the seam that clamping made was 255. */
#define MOST_STEP 40
/* GPU against the CPU reference, levels of 255: float against double texture coordinates */
#define MOST_DIFFERENCE 4

/* A texture of two texels along one coordinate (s: columns, t: rows), black then white, two wide
 * across it. */
static void write_texture(const char *path, int along_t)
{
    unsigned char rgba[2 * 2 * 4];
    for (int y = 0; y < 2; y++)
        for (int x = 0; x < 2; x++) {
            /* png rows are top down: row 0 is t = 1 (the last texel row) */
            int white = along_t ? y == 0 : x == 1;
            unsigned char *p = rgba + 4 * (y * 2 + x);
            p[0] = p[1] = p[2] = white ? 255 : 0;
            p[3] = 255;
        }
    struct error e;
    if (png_write_rgba8(path, 2, 2, rgba, 1, PNG_COMPRESSION_FAST, &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
}

/* A scene of one textured object, lit by ambient light alone, seen from camera towards the origin. */
static void load(struct scene *s, const char *path, const char *camera, const char *object)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fprintf(f, "[scene]\nname = seam\n[camera]\nposition = %s\nlook_at = 0 0 0\nup = 0 1 0\nfov = 40\n"
               "[render]\nwidth = %d\nheight = %d\n[model]\ntype = flat\n[sky]\ntype = color\ncolor = 0 0 0\n"
               "[lighting]\nambient = 1 1 1\n[object thing]\n%sambient = 1\ndiffuse = 0\nspecular = 0\n",
            camera, SIDE, SIDE, object);
    fclose(f);
    struct error e;
    if (scene_load(s, path, &e) != 0 || scene_validate(s, &e) != 0)
        fail_msg("%s: %s", e.where, e.message);
}

/* Pixel (x, y)'s grey level, top row first. */
static int grey(const unsigned char *rgba, int x, int y)
{
    return rgba[4 * (y * SIDE + x) + 1];
}

/* Along image row y, from x0 to x1: every step between neighbours small, no pixel off the object,
 * and the GPU's the CPU's. */
static void check_row(const char *what, const struct scene *s, int y, int x0, int x1)
{
    struct cpu_image cpu;
    struct hc_gpu gpu;
    hc_cpu_render(s, &cpu);
    hc_gpu_render(s, &gpu);
    int steepest = 0, farthest = 0, darkest = 255, lightest = 0;
    for (int x = x0; x <= x1; x++) {
        int g = grey(gpu.res.rgba, x, y), c = grey(cpu.rgba, x, y);
        assert_true(gpu.dump.records[y * SIDE + x].outcome == 0);
        farthest = abs(g - c) > farthest ? abs(g - c) : farthest;
        darkest = g < darkest ? g : darkest;
        lightest = g > lightest ? g : lightest;
        if (x < x1) {
            int step = abs(grey(gpu.res.rgba, x + 1, y) - g);
            steepest = step > steepest ? step : steepest;
        }
    }
    print_message("%s: row %d, x %d..%d: grey %d..%d, steepest step %d, GPU against CPU at most %d\n", what, y, x0,
                  x1, darkest, lightest, steepest, farthest);
    if (steepest > MOST_STEP)
        fail_msg("%s: a step of %d levels across the seam", what, steepest);
    assert_true(farthest <= MOST_DIFFERENCE);
    /* the seam lies between the two texels' centres: grey there, neither end reached */
    assert_true(darkest > 40 && lightest < 215);
    free(cpu.rgba);
    free(cpu.color);
    dump_free(&cpu.dump);
    hc_gpu_free(&gpu);
}

static void test_sphere_seam(void **state)
{
    (void)state;
    static struct scene s;
    write_texture("build/test_seam_s.png", 0);
    /* pole (0, 1, 0): longitude 0 along +z, its seam on the -z side, facing this camera */
    load(&s, "build/test_seam_sphere.scene", "0 0 -4",
         "type = sphere\ncenter = 0 0 0\nradius = 1\npole = 0 1 0\ntexture = test_seam_s.png\n");
    check_row("sphere", &s, SIDE / 2, SIDE / 2 - 6, SIDE / 2 + 6);
}

static void test_disk_seam(void **state)
{
    (void)state;
    static struct scene s;
    write_texture("build/test_seam_t.png", 1);
    /* normal (0, 0, 1): angle 0 along -y, its seam along +y from the centre, above it on the image */
    load(&s, "build/test_seam_disk.scene", "0 0 4",
         "type = disk\ncenter = 0 0 0\nnormal = 0 0 1\nradius = 1.2\ninner_radius = 0.5\n"
         "texture = test_seam_t.png\n");
    check_row("disk", &s, SIDE / 2 - 16, SIDE / 2 - 5, SIDE / 2 + 5);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sphere_seam),
        cmocka_unit_test(test_disk_seam),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
