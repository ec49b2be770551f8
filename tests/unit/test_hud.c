/* The kiosk's head-up display: its words (gamma, the horizon, flat space at M = 0), FreeType text
 * that lands inside its box and nowhere else, and a layout that scales with the screen. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <dirent.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <ft2build.h>
#include FT_FREETYPE_H
#include "kiosk/hud.h"
#include "kiosk/pipeline_layout.h"

/* fonts-dejavu-core, one of the project's Debian packages */
#define FONT_PATH "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"

static struct hud_font *font;
static const unsigned char white[4] = {255, 255, 255, 255};

static int open_font(void **state)
{
    (void)state;
    struct error e;
    font = hud_font_open(FONT_PATH, &e);
    if (!font)
        print_error("%s: %s\n", e.where, e.message);
    return font ? 0 : -1;
}

static int close_font(void **state)
{
    (void)state;
    hud_font_close(font);
    return 0;
}

/* the Schwarzschild scene as the kiosk shows it: moving at 0.9 c towards a hole of mass 0.5 */
static struct hud_view schwarzschild_view(void)
{
    struct hud_view v = {
        .staff = 1,
        .title = "A black hole bends light",
        .caption = "Light passing close to the hole bends around it.",
        .name = "Schwarzschild black hole",
        .explanation = "Light bends around the mass; inside the dark disc no ray escapes.",
        .has_speed = 1,
        .speed = 0.9,
        .has_mass = 1,
        .mass = 0.5,
        .camera_distance = 9.0,
        .shadow_share = 0.27,
        .effects = 0,
        .gravitational_shift = 1,
        .fps = 12.34,
        .refining = 0,
        .indicator = HUD_KNOB_NONE,
    };
    return v;
}

static int find_line(char lines[][HUD_LINE_LEN], int n, const char *needle)
{
    for (int i = 0; i < n; i++)
        if (strstr(lines[i], needle))
            return i;
    return -1;
}

static void test_lines_schwarzschild(void **state)
{
    (void)state;
    struct hud_view v = schwarzschild_view();
    char lines[HUD_MAX_LINES][HUD_LINE_LEN];
    int n = hud_lines(&v, lines, HUD_MAX_LINES);
    assert_int_equal(n, 6);
    assert_string_equal(lines[0], v.name);
    assert_string_equal(lines[1], v.explanation);

    int s = find_line(lines, n, "v = 0.90 c");
    assert_true(s >= 0);
    const char *g = strstr(lines[s], "γ = ");
    assert_non_null(g);
    double gamma = atof(g + strlen("γ = "));
    assert_true(fabs(gamma - 1.0 / sqrt(1.0 - 0.81)) <= 0.005);   /* 2.294 */
    assert_non_null(strstr(lines[s], "γ = 2.29"));

    int m = find_line(lines, n, "M = 0.50");
    assert_true(m >= 0);
    assert_non_null(strstr(lines[m], "r_s = 2M = 1.00"));
    assert_non_null(strstr(lines[m], "r = 9.0"));
    assert_null(strstr(lines[m], "flat"));
    assert_true(find_line(lines, n, "effects: geometry") >= 0);
    assert_true(find_line(lines, n, "staff mode   12.3 frames/s") >= 0);
    assert_int_equal(find_line(lines, n, "refining"), -1);

    /* near c the digits must not round to c itself, and gamma keeps growing */
    v.speed = 0.99;
    n = hud_lines(&v, lines, HUD_MAX_LINES);
    assert_true(find_line(lines, n, "γ = 7.09") >= 0);
    v.speed = 0.995;
    n = hud_lines(&v, lines, HUD_MAX_LINES);
    assert_int_equal(find_line(lines, n, "1.00 c"), -1);
    assert_true(find_line(lines, n, "γ = 10.01") >= 0);
}

static void test_lines_flat_space(void **state)
{
    (void)state;
    struct hud_view v = schwarzschild_view();
    v.mass = 0.0;
    char lines[HUD_MAX_LINES][HUD_LINE_LEN];
    int n = hud_lines(&v, lines, HUD_MAX_LINES);
    int m = find_line(lines, n, "M = 0: flat space");
    assert_true(m >= 0);
    assert_null(strstr(lines[m], "r_s"));
}

static void test_lines_optional(void **state)
{
    (void)state;
    struct hud_view v = schwarzschild_view();
    v.has_speed = 0;
    v.effects = -1;
    v.fps = -1.0;
    v.refining = 1;
    v.notice = "the hole cannot grow further: the camera would be inside its horizon";
    char lines[HUD_MAX_LINES][HUD_LINE_LEN];
    int n = hud_lines(&v, lines, HUD_MAX_LINES);
    assert_int_equal(n, 5);
    assert_true(find_line(lines, n, "staff mode   refining...") >= 0);
    assert_int_equal(find_line(lines, n, "v = "), -1);
    assert_int_equal(find_line(lines, n, "γ"), -1);
    assert_int_equal(find_line(lines, n, "effects"), -1);
    assert_int_equal(find_line(lines, n, "frames/s"), -1);
    assert_true(find_line(lines, n, "refining...") >= 0);
    assert_string_equal(lines[n - 1], v.notice);
    assert_int_equal(hud_lines(&v, lines, 2), 2);
    /* refining while no frame was drawn in the last second: no "0.0 frames/s" */
    v.fps = 0.0;
    n = hud_lines(&v, lines, HUD_MAX_LINES);
    assert_int_equal(find_line(lines, n, "frames/s"), -1);
    assert_true(find_line(lines, n, "refining...") >= 0);

    v.has_mass = 0;
    n = hud_lines(&v, lines, HUD_MAX_LINES);
    assert_int_equal(find_line(lines, n, "M = "), -1);

    /* a title longer than a line is cut, and never in the middle of a character */
    char title[2 * HUD_LINE_LEN + 1] = "";
    for (int i = 0; i < HUD_LINE_LEN; i++)
        strcat(title, "γ");
    v.name = title;
    n = hud_lines(&v, lines, HUD_MAX_LINES);
    size_t len = strlen(lines[0]);
    assert_true(len > 0 && len < HUD_LINE_LEN && len % 2 == 0);
}

/* What a visitor reads (staff mode off): the title and caption, the knobs in words, the colours;
 * no file or key name, no symbol, no figure number, no frame rate. */
static void test_lines_visitor(void **state)
{
    (void)state;
    struct hud_view v = schwarzschild_view();
    v.staff = 0;
    v.effects = 1;
    v.refining = 1;
    char lines[HUD_MAX_LINES][HUD_LINE_LEN];
    int n = hud_lines(&v, lines, HUD_MAX_LINES);
    for (int i = 0; i < n; i++)
        printf("  %s\n", lines[i]);
    assert_int_equal(n, 5);
    assert_string_equal(lines[0], v.title);
    assert_string_equal(lines[1], v.caption);
    assert_true(find_line(lines, n, "Speed: 90% of light speed, clocks 2.29× slower") >= 0);
    assert_true(find_line(lines, n, "Black hole: shadow 27% of the view's height") >= 0);
    assert_true(find_line(lines, n, "Colours: shifted by motion and gravity") >= 0);
    /* the effects button's layer before gravity's: motion's shift alone */
    v.gravitational_shift = 0;
    n = hud_lines(&v, lines, HUD_MAX_LINES);
    assert_true(find_line(lines, n, "Colours: shifted by motion") >= 0);
    assert_int_equal(find_line(lines, n, "gravity"), -1);
    v.gravitational_shift = 1;
    n = hud_lines(&v, lines, HUD_MAX_LINES);
    static const char *const developer_words[] = {"frames/s", "staff", "M = ", "r_s", "γ", "v = ", "effects:",
                                                  "Schwarzschild black hole", "Light bends around the mass",
                                                  "model.", "Figure", "refining"};
    for (size_t w = 0; w < sizeof developer_words / sizeof developer_words[0]; w++)
        if (find_line(lines, n, developer_words[w]) >= 0)
            fail_msg("a visitor reads '%s'", developer_words[w]);

    /* at rest, no black hole, near c, a shadow that fills the view; the scene's own words */
    v.speed = 0.0;
    v.mass = 0.0;
    n = hud_lines(&v, lines, HUD_MAX_LINES);
    assert_true(find_line(lines, n, "Speed: at rest") >= 0);
    assert_true(find_line(lines, n, "Black hole: none, light goes straight") >= 0);
    v.speed = 0.995;
    v.mass = 0.5;
    v.shadow_share = 1.3;
    v.speed_label = "Your speed";
    v.mass_label = "The hole";
    n = hud_lines(&v, lines, HUD_MAX_LINES);
    assert_true(find_line(lines, n, "Your speed: 99.5% of light speed") >= 0);
    assert_true(find_line(lines, n, "The hole: its shadow fills the view") >= 0);
    v.shadow_share = 0.004;
    n = hud_lines(&v, lines, HUD_MAX_LINES);
    assert_true(find_line(lines, n, "The hole: shadow under 1% of the view") >= 0);

    /* knobs mapped to keys: their words and how far along the range, not the key or its number */
    struct hud_view m = {.title = "Light in a chaotic flow", .speed_key = "model.strength", .speed_param = 0.004,
                         .speed_range = {0.0, 0.01}, .mass_key = "model.rho", .mass_param = 34.0,
                         .mass_range = {0.0, 50.0}, .mass_label = "Chaos of the flow", .effects = -1};
    n = hud_lines(&m, lines, HUD_MAX_LINES);
    assert_int_equal(n, 3);
    assert_true(find_line(lines, n, "Speed knob: 40%") >= 0);
    assert_true(find_line(lines, n, "Chaos of the flow: 68%") >= 0);
    assert_int_equal(find_line(lines, n, "model."), -1);
    assert_int_equal(find_line(lines, n, "34"), -1);
}

static void test_text_width(void **state)
{
    (void)state;
    int short_w = hud_text_width(font, 24, "v = 0.9");
    int long_w = hud_text_width(font, 24, "v = 0.9 c, γ ≈ 2.29 · M");
    assert_true(short_w > 0);
    assert_true(long_w > short_w);
    int big_w = hud_text_width(font, 36, "v = 0.9 c, γ ≈ 2.29 · M");
    assert_true(big_w > long_w);
    assert_true(fabs((double)big_w / long_w - 1.5) <= 0.03);
    assert_int_equal(hud_text_width(font, 24, ""), 0);
    assert_int_equal(hud_text_width(NULL, 24, "text"), 0);
    assert_int_equal(hud_text_width(font, 0, "text"), 0);
    /* more sizes than the cache keeps: the evicted size comes back the same */
    for (int px = 10; px < 20; px++)
        assert_true(hud_text_width(font, px, "ÄÖÜ äöü ß é") > 0);
    assert_int_equal(hud_text_width(font, 24, "v = 0.9 c, γ ≈ 2.29 · M"), long_w);
    /* malformed UTF-8 is drawn as replacement characters, not read past */
    assert_true(hud_text_width(font, 24, "a\xC3") > hud_text_width(font, 24, "a"));
    assert_true(hud_text_width(font, 24, "\xE2\x89") > 0);
}

/* Each of these is one character of the font, not replacement boxes for its UTF-8 bytes: its
 * width is FreeType's own advance for that code point. */
static void test_text_characters(void **state)
{
    (void)state;
    const struct {
        const char *utf8;
        unsigned long codepoint;
    } chars[] = {{"é", 0xE9}, {"ß", 0xDF}, {"·", 0xB7}, {"γ", 0x3B3}, {"≈", 0x2248}, {"√", 0x221A}};
    FT_Library library;
    FT_Face face;
    assert_int_equal(FT_Init_FreeType(&library), 0);
    assert_int_equal(FT_New_Face(library, FONT_PATH, 0, &face), 0);
    assert_int_equal(FT_Set_Pixel_Sizes(face, 0, 48), 0);
    for (size_t i = 0; i < sizeof chars / sizeof chars[0]; i++) {
        FT_UInt index = FT_Get_Char_Index(face, chars[i].codepoint);
        assert_int_not_equal(index, 0);
        assert_int_equal(FT_Load_Glyph(face, index, FT_LOAD_TARGET_LIGHT), 0);
        double advance = face->glyph->linearHoriAdvance / 65536.0;
        int width = hud_text_width(font, 48, chars[i].utf8);
        if (fabs(width - advance) > 1.0)
            fail_msg("%s is %d pixels wide, U+%04lX advances %.1f", chars[i].utf8, width, chars[i].codepoint, advance);
    }
    FT_Done_Face(face);
    FT_Done_FreeType(library);
}

static int alpha_at(const unsigned char *rgba, int w, int x, int y)
{
    return rgba[((size_t)y * (size_t)w + (size_t)x) * 4 + 3];
}

static void test_text_draw_inside_its_box(void **state)
{
    (void)state;
    enum { W = 240, H = 60, X = 10, Y = 40, PX = 24 };
    const char *text = "Hxgjγ≈·ÉA";
    unsigned char *rgba = calloc((size_t)W * H, 4);
    assert_non_null(rgba);
    int advance = hud_text_draw(font, rgba, W, H, X, Y, PX, text, white);
    assert_int_equal(advance, hud_text_width(font, PX, text));
    int inked = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            if (!alpha_at(rgba, W, x, y))
                continue;
            inked++;
            /* above: nothing over one text height (the font's ascent is 0.93 em);
             * below: descenders reach 0.24 em; sideways: bearings of a pixel or two */
            if (y < Y - PX || y >= Y + PX / 3 || x < X - 2 || x >= X + advance + 2)
                fail_msg("ink at (%d, %d), outside the text's box", x, y);
        }
    assert_true(inked > 100);
    for (int y = 0; y < Y - PX; y++)
        for (int x = 0; x < W; x++)
            assert_int_equal(alpha_at(rgba, W, x, y), 0);

    /* over an opaque picture: white text blends in, the picture stays opaque, and a transparent
     * colour changes nothing */
    for (size_t i = 0; i < (size_t)W * H; i++)
        memcpy(rgba + 4 * i, (unsigned char[4]){200, 20, 20, 255}, 4);
    const unsigned char clear[4] = {0, 255, 0, 0};
    hud_text_draw(font, rgba, W, H, X, Y, PX, text, clear);
    for (size_t i = 0; i < (size_t)W * H; i++)
        assert_memory_equal(rgba + 4 * i, ((unsigned char[4]){200, 20, 20, 255}), 4);
    hud_text_draw(font, rgba, W, H, X, Y, PX, text, white);
    int full = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        assert_int_equal(rgba[4 * i + 3], 255);
        full += rgba[4 * i] == 255 && rgba[4 * i + 1] == 255 && rgba[4 * i + 2] == 255;
    }
    assert_true(full > 20);
    free(rgba);
}

static void test_text_clipped(void **state)
{
    (void)state;
    enum { W = 40, H = 20, GUARD = 256 };
    const char *text = "Wgγ clipped at every edge";
    size_t size = (size_t)W * H * 4;
    unsigned char *buf = malloc(size + 2 * GUARD);
    assert_non_null(buf);
    memset(buf, 0x5A, size + 2 * GUARD);
    unsigned char *rgba = buf + GUARD;
    memset(rgba, 0, size);
    int width = hud_text_width(font, 24, text);
    const int at[][2] = {{-15, 5}, {30, 30}, {-1000, 10}, {35, -3}, {0, 200}, {INT_MAX / 2, 10}, {-5, 12}};
    for (size_t i = 0; i < sizeof at / sizeof at[0]; i++)
        assert_int_equal(hud_text_draw(font, rgba, W, H, at[i][0], at[i][1], 24, text, white), width);
    assert_int_equal(hud_text_draw(font, rgba, W, H, 0, 10, 600, "W", white), hud_text_width(font, 600, "W"));
    for (size_t i = 0; i < GUARD; i++) {
        assert_int_equal(buf[i], 0x5A);
        assert_int_equal(buf[GUARD + size + i], 0x5A);
    }
    int near_left = 0;   /* the text started left of the image still shows its clipped part */
    for (int y = 0; y < H; y++)
        for (int x = 0; x < 4; x++)
            near_left += alpha_at(rgba, W, x, y) != 0;
    assert_true(near_left > 0);
    free(buf);
}

struct rect {
    int x0, y0, x1, y1;   /* half open */
};

/* The band grown from the first non-transparent pixel: right along its row, down its column. */
static struct rect band_of(const unsigned char *rgba, int w, int h)
{
    struct rect r = {-1, -1, -1, -1};
    for (int y = 0; y < h && r.x0 < 0; y++)
        for (int x = 0; x < w; x++)
            if (alpha_at(rgba, w, x, y)) {
                r.x0 = x, r.y0 = y;
                break;
            }
    assert_true(r.x0 >= 0);
    r.x1 = r.x0, r.y1 = r.y0;
    while (r.x1 < w && alpha_at(rgba, w, r.x1, r.y0))
        r.x1++;
    while (r.y1 < h && alpha_at(rgba, w, r.x0, r.y1))
        r.y1++;
    return r;
}

static struct rect draw_and_check_band(int w, int h, const struct hud_view *v)
{
    unsigned char *rgba = malloc((size_t)w * h * 4);
    assert_non_null(rgba);
    memset(rgba, 0x77, (size_t)w * h * 4);   /* the previous frame's HUD must go */
    hud_draw(font, rgba, w, h, v);
    struct rect b = band_of(rgba, w, h);
    assert_true(b.x0 < h / 20 && b.y0 < h / 20);
    assert_true(b.x1 < w && b.y1 < h / 2);
    int text = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int inside = x >= b.x0 && x < b.x1 && y >= b.y0 && y < b.y1;
            const unsigned char *p = rgba + ((size_t)y * (size_t)w + (size_t)x) * 4;
            if (inside != (p[3] != 0))
                fail_msg("%dx%d: pixel (%d, %d) alpha %d, band [%d, %d) x [%d, %d)", w, h, x, y, p[3], b.x0, b.x1,
                         b.y0, b.y1);
            text += inside && p[0] > 200 && p[1] > 200 && p[2] > 200;
        }
    assert_true(text > 100);   /* light text on the dark band */
    free(rgba);
    return b;
}

/* The visitor's block at w x h reaches no further than the top 30% of the screen (what make
 * vm-test's screen comparison leaves to the HUD) and 60% of its width (half of a wide screen; on a
 * narrower one, about 55 characters). */
static void check_corner(const struct hud_view *v, int w, int h)
{
    struct rect b = draw_and_check_band(w, h, v);
    if (b.y1 > 3 * h / 10 || b.x1 > 6 * w / 10 || (w * 9 >= h * 16 && b.x1 > w / 2))
        fail_msg("%dx%d: the visitor's block reaches (%d, %d) with the caption \"%s\"", w, h, b.x1, b.y1,
                 v->caption);
}

/* A visitor's block keeps to a corner: with both knobs and the colours, and the caption of every
 * shipped scene, at 720p, 1080p and 1024x768; the longest caption a scene may have (96 bytes),
 * in wide letters, on the wide screens. */
static void test_visitor_band_in_a_corner(void **state)
{
    (void)state;
    struct hud_view v = schwarzschild_view();
    v.staff = 0;
    v.effects = 2;
    static const int sizes[][2] = {{1280, 720}, {1920, 1080}, {1024, 768}};
    DIR *dir = opendir("assets/scenes");
    assert_non_null(dir);
    struct dirent *d;
    int captions = 0;
    while ((d = readdir(dir)) != NULL) {
        size_t len = strlen(d->d_name);
        if (len < 7 || strcmp(d->d_name + len - 6, ".scene") != 0)
            continue;
        char path[512], line[512];
        snprintf(path, sizeof path, "assets/scenes/%s", d->d_name);
        FILE *f = fopen(path, "r");
        assert_non_null(f);
        while (fgets(line, sizeof line, f))
            if (strncmp(line, "caption = ", 10) == 0) {
                line[strcspn(line, "\n")] = '\0';
                v.caption = line + 10;
                for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++)
                    check_corner(&v, sizes[i][0], sizes[i][1]);
                captions++;
            }
        fclose(f);
    }
    closedir(dir);
    assert_true(captions >= 6);
    v.caption = "Wow, WWW, MMM: Newton's gravity bends light only half as much as Einstein's; the eclipse showed.";
    assert_int_equal(strlen(v.caption), 96);
    check_corner(&v, 1280, 720);
    check_corner(&v, 1920, 1080);
}

static void test_hud_scales_with_height(void **state)
{
    (void)state;
    struct hud_view v = schwarzschild_view();
    struct rect small = draw_and_check_band(1280, 720, &v);
    struct rect large = draw_and_check_band(1920, 1080, &v);
    double hs = (double)(small.y1 - small.y0), hl = (double)(large.y1 - large.y0);
    double ws = (double)(small.x1 - small.x0), wl = (double)(large.x1 - large.x0);
    print_message("band %.0fx%.0f at 720p, %.0fx%.0f at 1080p\n", ws, hs, wl, hl);
    assert_true(fabs(hl / hs - 1.5) <= 0.02);
    assert_true(fabs(wl / ws - 1.5) <= 0.02);
    /* six lines of text about h/30 high: the band is at least that */
    assert_true(hs >= 6 * 720 / 30);

    /* an explanation too long for the screen wraps, at the same word at both sizes */
    v.explanation = "Light passing the mass bends towards it; rays that come closer than 3√3 M (about "
                    "2.6 r_s) fall in, which is the dark disc you see, larger than the horizon itself.";
    struct rect wrapped_small = draw_and_check_band(1280, 720, &v);
    struct rect wrapped_large = draw_and_check_band(1920, 1080, &v);
    double ws2 = wrapped_small.y1 - wrapped_small.y0, wl2 = wrapped_large.y1 - wrapped_large.y0;
    assert_true(ws2 > hs);
    assert_true(fabs(wl2 / ws2 - 1.5) <= 0.02);
}

/* The length of the run of pixels in row y, from x, where a and b differ. */
static int differing_run(const unsigned char *a, const unsigned char *b, int w, int y, int x)
{
    int n = 0;
    while (x + n < w && memcmp(a + ((size_t)y * w + x + n) * 4, b + ((size_t)y * w + x + n) * 4, 4) != 0)
        n++;
    return n;
}

static unsigned char *draw_indicator(int w, int h, enum hud_knob knob, double lo, double hi, double value)
{
    struct hud_view v = schwarzschild_view();
    v.indicator = knob;
    v.indicator_min = lo;
    v.indicator_max = hi;
    v.indicator_value = value;
    unsigned char *rgba = malloc((size_t)w * h * 4);
    assert_non_null(rgba);
    hud_draw(font, rgba, w, h, &v);
    return rgba;
}

/* The bar fills in proportion to the value within its range: found as the longest run of pixels
 * that differ between the knob at its minimum and at its maximum, then measured at other values. */
static void check_bar(int w, int h, enum hud_knob knob, double lo, double hi)
{
    unsigned char *empty = draw_indicator(w, h, knob, lo, hi, lo);
    unsigned char *full = draw_indicator(w, h, knob, lo, hi, hi);
    int bar_x = 0, bar_y = 0, bar_w = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int n = differing_run(empty, full, w, y, x);
            if (n > bar_w)
                bar_w = n, bar_x = x, bar_y = y;
            x += n;
        }
    assert_true(bar_y > h / 2);
    assert_true(bar_w >= w / 5);
    const double shares[] = {0.25, 0.5, 0.75, 1.5};
    for (size_t i = 0; i < sizeof shares / sizeof shares[0]; i++) {
        unsigned char *part = draw_indicator(w, h, knob, lo, hi, lo + shares[i] * (hi - lo));
        double filled = differing_run(empty, part, w, bar_y, bar_x);
        double expected = fmin(shares[i], 1.0) * bar_w;   /* beyond the range: full, not past it */
        if (fabs(filled - expected) > 1.0)
            fail_msg("%dx%d: %.2f of the range fills %.0f of %d pixels", w, h, shares[i], filled, bar_w);
        free(part);
    }
    free(empty);
    free(full);
}

static void test_indicator_bar(void **state)
{
    (void)state;
    check_bar(1280, 720, HUD_KNOB_SPEED, 0.0, 0.99);
    check_bar(1920, 1080, HUD_KNOB_MASS, 0.0, 2.0);
    check_bar(1920, 1080, HUD_KNOB_MASS, 0.01, 5.0);
}

static void test_font_errors(void **state)
{
    (void)state;
    struct error e;
    const char *missing = "/nonexistent/fonts/NoSuchFont.ttf";
    assert_null(hud_font_open(missing, &e));
    assert_string_equal(e.where, missing);
    assert_int_equal(e.status, ERROR_INPUT);

    char path[] = "/tmp/bt_hud_not_a_font_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    const char text[] = "[kiosk]\nhud = on\n";
    assert_int_equal(write(fd, text, sizeof text - 1), (int)(sizeof text - 1));
    close(fd);
    error_clear(&e);
    struct hud_font *f = hud_font_open(path, &e);
    unlink(path);
    assert_null(f);
    assert_string_equal(e.where, path);
    assert_non_null(strstr(e.message, "not a"));
    assert_int_equal(e.status, ERROR_INPUT);
    hud_font_close(NULL);
}

/* The font file is read whole at open: cut short and overwritten on disk afterwards, the font still
 * draws glyphs it has not drawn yet, at sizes it has not used yet. A FIFO is refused at once. */
static void test_font_read_once(void **state)
{
    (void)state;
    char path[] = "/tmp/bt_hud_font_XXXXXX";
    struct error e;
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *src = fopen(FONT_PATH, "rb");
    assert_non_null(src);
    char buf[65536];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, src)) > 0)
        assert_int_equal(write(fd, buf, n), (ssize_t)n);
    fclose(src);
    close(fd);
    struct hud_font *f = hud_font_open(path, &e);
    assert_non_null(f);
    int before = hud_text_width(f, 40, "Mass");
    assert_true(before > 0);
    /* the file now holds 100 bytes of something else */
    FILE *over = fopen(path, "wb");
    assert_non_null(over);
    for (int i = 0; i < 100; i++)
        fputc('x', over);
    fclose(over);
    int later = hud_text_width(f, 57, "Zq&");
    print_message("widths after the file changed: %d (40 px, seen before), %d (57 px, new glyphs)\n",
                  hud_text_width(f, 40, "Mass"), later);
    assert_int_equal(hud_text_width(f, 40, "Mass"), before);
    assert_true(later > 0);
    hud_font_close(f);
    unlink(path);

    char fifo[] = "/tmp/bt_hud_fifo_XXXXXX";
    fd = mkstemp(fifo);
    assert_true(fd >= 0);
    close(fd);
    unlink(fifo);
    assert_int_equal(mkfifo(fifo, 0600), 0);
    assert_null(hud_font_open(fifo, &e));
    assert_non_null(strstr(e.message, "not a regular file"));
    assert_int_equal(e.status, ERROR_INPUT);
    unlink(fifo);
}

static void test_draw_without_font_clears(void **state)
{
    (void)state;
    enum { W = 64, H = 36 };
    unsigned char rgba[W * H * 4];
    memset(rgba, 0xAB, sizeof rgba);
    struct hud_view v = schwarzschild_view();
    v.indicator = HUD_KNOB_SPEED;
    v.indicator_max = 0.99;
    hud_draw(NULL, rgba, W, H, &v);
    for (size_t i = 0; i < sizeof rgba; i++)
        assert_int_equal(rgba[i], 0);
    /* a window too small for the layout still draws without writing outside it */
    hud_draw(font, rgba, W, H, &v);
}

/* Staff mode: a knob the scene maps to one of its keys shows that key and its value, not speed or
 * mass. */
static void test_lines_mapped_knobs(void **state)
{
    (void)state;
    struct hud_view v = {.staff = 1, .name = "lorenz", .speed_key = "model.strength", .speed_param = 0.004,
                         .mass_key = "model.rho", .mass_param = 34.0, .fps = -1.0};
    char lines[HUD_MAX_LINES][HUD_LINE_LEN];
    int n = hud_lines(&v, lines, HUD_MAX_LINES);
    assert_true(find_line(lines, n, "model.strength = 0.004   (the speed knob)") >= 0);
    assert_true(find_line(lines, n, "model.rho = 34.00   (the mass knob)") >= 0);
    assert_true(find_line(lines, n, "v = ") < 0);
    assert_true(find_line(lines, n, "M = ") < 0);
}

/* The pipeline view: each of the six panels has its label in its cell's top-left corner, above the
 * panel, the scene's name in the image panel's, and nothing of the HUD covers a panel (the block of
 * lines used to cover most of the top row); the canvas may be letterboxed anywhere on the screen. */
static void test_pipeline_labels(void **state)
{
    (void)state;
    enum { W = 1280, H = 720 };
    unsigned char *rgba = malloc((size_t)W * H * 4);
    struct hud_view v = schwarzschild_view();
    v.pipeline_view = 1;
    v.canvas_x = 40;
    v.canvas_y = 20;
    v.canvas_w = 1200;
    v.canvas_h = 680;
    hud_draw(font, rgba, W, H, &v);
    /* a label's band: a row of body text (h / 30) with its pitch (4 / 3) and a third of a row of pad */
    int pw = v.canvas_w / 3, ph = v.canvas_h / 2, label_rows = H / 15;
    for (int p = 0; p < HUD_PIPELINE_PANELS; p++) {
        int x0 = v.canvas_x + (p % 3) * pw, y0 = v.canvas_y + (p / 3) * ph;
        int label = 0, covered = 0;
        for (int y = y0; y < y0 + label_rows; y++)
            for (int x = x0; x < x0 + pw / 4; x++)
                label += alpha_at(rgba, W, x, y) != 0;
        int px, py, panel_w, panel_h;
        pipeline_panel_rect(v.canvas_w, v.canvas_h, p, &px, &py, &panel_w, &panel_h);
        assert_true(v.canvas_y + py >= y0 + label_rows);
        for (int y = v.canvas_y + py; y < v.canvas_y + py + panel_h; y++)
            for (int x = v.canvas_x + px; x < v.canvas_x + px + panel_w; x++)
                covered += alpha_at(rgba, W, x, y) != 0;
        printf("  panel %d (%s): %d label pixels, %d on the panel\n", p, hud_pipeline_labels[p], label, covered);
        assert_true(label > 100);
        assert_int_equal(covered, 0);
    }
    /* the words of the colour scales and the legend, in the bands below the panels but the image's */
    for (int p = 0; p < HUD_PIPELINE_PANELS; p++) {
        int x, y, w, h, words = 0;
        pipeline_panel_rect(v.canvas_w, v.canvas_h, p, &x, &y, &w, &h);
        int cell_bottom = (p / PIPELINE_COLUMNS + 1) * (v.canvas_h / PIPELINE_ROWS);
        for (int yy = v.canvas_y + y + h; yy < v.canvas_y + cell_bottom; yy++)
            for (int xx = v.canvas_x + x; xx < v.canvas_x + x + w; xx++)
                words += alpha_at(rgba, W, xx, yy) != 0;
        printf("  panel %d: %d pixels of words below it\n", p, words);
        if (p == 0)
            assert_int_equal(words, 0);
        else
            assert_true(words > 100);
    }
    /* outside the canvas nothing */
    for (int y = 0; y < v.canvas_y; y++)
        for (int x = 0; x < W; x++)
            assert_int_equal(alpha_at(rgba, W, x, y), 0);
    free(rgba);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pipeline_labels),
        cmocka_unit_test(test_lines_schwarzschild),
        cmocka_unit_test(test_lines_flat_space),
        cmocka_unit_test(test_lines_optional),
        cmocka_unit_test(test_lines_mapped_knobs),
        cmocka_unit_test(test_lines_visitor),
        cmocka_unit_test(test_visitor_band_in_a_corner),
        cmocka_unit_test(test_text_width),
        cmocka_unit_test(test_text_characters),
        cmocka_unit_test(test_text_draw_inside_its_box),
        cmocka_unit_test(test_text_clipped),
        cmocka_unit_test(test_hud_scales_with_height),
        cmocka_unit_test(test_indicator_bar),
        cmocka_unit_test(test_font_errors),
        cmocka_unit_test(test_font_read_once),
        cmocka_unit_test(test_draw_without_font_clears),
    };
    return cmocka_run_group_tests(tests, open_font, close_font);
}
