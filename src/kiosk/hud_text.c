/* FreeType text for the HUD. Each glyph is rasterised once per pixel size and kept as a coverage
 * map: the HUD redraws the same few dozen characters every frame at two or three sizes, and
 * rasterising them each time would cost more than everything else it does. */
#include "kiosk/hud_text.h"
#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <ft2build.h>
#include FT_FREETYPE_H

/* The HUD draws a title, body text and the indicator; a fourth size spares a rebuild while the
 * screen's height changes. */
#define SIZE_SLOTS 4
/* Largest font file read (docs/LIMITS.md): the CJK outline fonts Debian ships stay below it. */
#define HUD_FONT_MAX_BYTES (64 * 1024 * 1024)
/* Beyond this a request is a mistake, not HUD text (a 4K screen's title is about 110 px). */
#define MAX_PIXEL_HEIGHT 1024
#define FIRST_TABLE_SLOTS 128
#define REPLACEMENT_CHARACTER 0xFFFDu

struct glyph {
    uint32_t codepoint;          /* 0: free slot (a C string never holds U+0000) */
    FT_UInt index;               /* the face's glyph, for kerning */
    FT_Pos advance;              /* pen advance, 26.6 pixels, unhinted */
    int width, rows;             /* coverage map size in pixels */
    int left, top;               /* map's top-left corner from the pen on the baseline, y up */
    unsigned char *coverage;     /* width x rows, top row first; NULL when empty (a space) */
};

struct size_cache {
    int pixel_height;            /* 0: slot unused */
    unsigned long last_use;
    struct glyph *table;         /* open addressing, capacity a power of two */
    size_t capacity, count;
};

struct hud_font {
    FT_Library library;
    FT_Face face;
    unsigned char *file;         /* the font file, read whole at open: FreeType reads glyphs from it */
    int face_pixel_height;       /* the size the face is scaled to now; 0: none yet */
    unsigned long uses;
    struct size_cache sizes[SIZE_SLOTS];
};

static void size_cache_clear(struct size_cache *c)
{
    for (size_t i = 0; i < c->capacity; i++)
        free(c->table[i].coverage);
    free(c->table);
    memset(c, 0, sizeof *c);
}

/* The whole font file, read once: a font replaced or cut short on disk while the kiosk runs does
 * not reach the glyphs it draws later (FreeType would read them from the file as needed). A FIFO
 * or a device is refused, and so is a file beyond HUD_FONT_MAX_BYTES. */
static unsigned char *read_font_file(const char *path, long *size, struct error *e)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        int en = errno;
        error_set(e, error_status_of_errno(en), path, "%s", strerror(en));
        return NULL;
    }
    struct stat st;
    unsigned char *data = NULL;
    int stat_failed = fstat(fd, &st) != 0, stat_errno = stat_failed ? errno : 0;
    if (stat_failed || !S_ISREG(st.st_mode)) {
        error_set(e, error_status_of_errno(stat_errno), path, "not a regular file");
    } else if (st.st_size <= 0 || st.st_size > HUD_FONT_MAX_BYTES) {
        error_set(e, ERROR_INPUT, path, "%lld bytes; a font file has 1 to %d", (long long)st.st_size,
                  HUD_FONT_MAX_BYTES);
    } else if (!(data = malloc((size_t)st.st_size))) {
        error_set(e, ERROR_RUNTIME, path, "out of memory");
    } else {
        long got = 0;
        while (got < st.st_size) {
            ssize_t n = read(fd, data + got, (size_t)(st.st_size - got));
            if (n < 0 && errno == EINTR)
                continue;
            if (n <= 0)
                break;
            got += n;
        }
        if (got != st.st_size) {
            error_set(e, ERROR_RUNTIME, path, "read %ld of %lld bytes", got, (long long)st.st_size);
            free(data);
            data = NULL;
        }
        *size = got;
    }
    close(fd);
    return data;
}

struct hud_font *hud_font_open(const char *path, struct error *e)
{
    long size = 0;
    unsigned char *file = read_font_file(path, &size, e);
    if (!file)
        return NULL;
    struct hud_font *f = calloc(1, sizeof *f);
    if (!f) {
        error_set(e, ERROR_RUNTIME, path, "out of memory");
        free(file);
        return NULL;
    }
    f->file = file;
    FT_Error fe = FT_Init_FreeType(&f->library);
    if (fe) {
        error_set(e, ERROR_RUNTIME, path, "FreeType cannot start (error %d)", fe);
        free(f->file);
        free(f);
        return NULL;
    }
    fe = FT_New_Memory_Face(f->library, f->file, (FT_Long)size, 0, &f->face);
    if (fe) {
        if (fe == FT_Err_Unknown_File_Format)
            error_set(e, ERROR_INPUT, path, "not a font (FreeType knows no such format)");
        else
            error_set(e, ERROR_INPUT, path, "not a readable font (FreeType error %d)", fe);
        f->face = NULL;
        hud_font_close(f);
        return NULL;
    }
    if (!FT_IS_SCALABLE(f->face)) {
        error_set(e, ERROR_INPUT, path, "a bitmap font; the HUD scales its text with the screen, give an outline font");
        hud_font_close(f);
        return NULL;
    }
    if (FT_Select_Charmap(f->face, FT_ENCODING_UNICODE)) {
        error_set(e, ERROR_INPUT, path, "the font has no Unicode character map");
        hud_font_close(f);
        return NULL;
    }
    return f;
}

void hud_font_close(struct hud_font *f)
{
    if (!f)
        return;
    for (int i = 0; i < SIZE_SLOTS; i++)
        size_cache_clear(&f->sizes[i]);
    if (f->face)
        FT_Done_Face(f->face);
    FT_Done_FreeType(f->library);
    free(f->file);
    free(f);
}

/* The next character of s from *i. A malformed byte reads as U+FFFD on its own, so that a line cut
 * in the middle of a character still shows the rest. */
static uint32_t next_codepoint(const unsigned char *s, size_t *i)
{
    unsigned lead = s[*i];
    int more;
    uint32_t cp, smallest;
    if (lead < 0x80) {
        (*i)++;
        return lead;
    } else if ((lead & 0xE0) == 0xC0) {
        more = 1, cp = lead & 0x1F, smallest = 0x80;
    } else if ((lead & 0xF0) == 0xE0) {
        more = 2, cp = lead & 0x0F, smallest = 0x800;
    } else if ((lead & 0xF8) == 0xF0) {
        more = 3, cp = lead & 0x07, smallest = 0x10000;
    } else {
        (*i)++;
        return REPLACEMENT_CHARACTER;
    }
    /* a NUL is no continuation byte, so this never reads past the string's end */
    for (int k = 1; k <= more; k++) {
        unsigned next = s[*i + k];
        if ((next & 0xC0) != 0x80) {
            (*i)++;
            return REPLACEMENT_CHARACTER;
        }
        cp = cp << 6 | (next & 0x3F);
    }
    *i += (size_t)more + 1;
    if (cp < smallest || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
        return REPLACEMENT_CHARACTER;
    return cp;
}

static struct size_cache *size_cache_for(struct hud_font *f, int pixel_height)
{
    struct size_cache *oldest = &f->sizes[0];
    for (int i = 0; i < SIZE_SLOTS; i++) {
        struct size_cache *c = &f->sizes[i];
        if (c->pixel_height == pixel_height) {
            c->last_use = ++f->uses;
            return c;
        }
        if (c->pixel_height == 0 || (oldest->pixel_height != 0 && c->last_use < oldest->last_use))
            oldest = c;
    }
    size_cache_clear(oldest);
    oldest->pixel_height = pixel_height;
    oldest->last_use = ++f->uses;
    return oldest;
}

static size_t slot_of(uint32_t codepoint, size_t capacity)
{
    return (size_t)(codepoint * 2654435761u) & (capacity - 1);   /* Knuth's multiplicative hash */
}

static struct glyph *find_slot(struct glyph *table, size_t capacity, uint32_t codepoint)
{
    size_t i = slot_of(codepoint, capacity);
    while (table[i].codepoint != 0 && table[i].codepoint != codepoint)
        i = (i + 1) & (capacity - 1);
    return &table[i];
}

/* Keeps the table at most half full, so that probes stay short. */
static int make_room(struct size_cache *c)
{
    if (c->capacity != 0 && 2 * (c->count + 1) <= c->capacity)
        return 0;
    size_t capacity = c->capacity ? 2 * c->capacity : FIRST_TABLE_SLOTS;
    struct glyph *table = calloc(capacity, sizeof *table);
    if (!table)
        return -1;
    for (size_t i = 0; i < c->capacity; i++)
        if (c->table[i].codepoint != 0)
            *find_slot(table, capacity, c->table[i].codepoint) = c->table[i];
    free(c->table);
    c->table = table;
    c->capacity = capacity;
    return 0;
}

/* Copies FreeType's bitmap (grey or one bit per pixel, rows either way up) as 8-bit coverage. */
static unsigned char *copy_coverage(const FT_Bitmap *b)
{
    if (b->width == 0 || b->rows == 0)
        return NULL;
    if (b->pixel_mode != FT_PIXEL_MODE_GRAY && b->pixel_mode != FT_PIXEL_MODE_MONO)
        return NULL;
    unsigned char *out = malloc((size_t)b->width * b->rows);
    if (!out)
        return NULL;
    for (unsigned r = 0; r < b->rows; r++) {
        const unsigned char *row = b->pitch >= 0 ? b->buffer + (size_t)r * (size_t)b->pitch
                                                 : b->buffer + (size_t)(b->rows - 1 - r) * (size_t)-b->pitch;
        for (unsigned col = 0; col < b->width; col++) {
            unsigned char v;
            if (b->pixel_mode == FT_PIXEL_MODE_MONO)
                v = (row[col >> 3] >> (7 - (col & 7)) & 1) ? 255 : 0;
            else
                v = (unsigned char)(row[col] * 255u / (b->num_grays > 1 ? b->num_grays - 1u : 255u));
            out[(size_t)r * b->width + col] = v;
        }
    }
    return out;
}

/* The glyph for codepoint at the cache's size, rasterised on first use. A character the font
 * cannot render is kept as an empty glyph, so that it costs FreeType one attempt, not one a frame.
 * NULL only when memory runs out. */
static const struct glyph *glyph_for(struct hud_font *f, struct size_cache *c, uint32_t codepoint)
{
    if (c->capacity != 0) {
        struct glyph *g = find_slot(c->table, c->capacity, codepoint);
        if (g->codepoint == codepoint)
            return g;
    }
    if (make_room(c) != 0)
        return NULL;
    struct glyph *g = find_slot(c->table, c->capacity, codepoint);
    memset(g, 0, sizeof *g);
    g->codepoint = codepoint;
    c->count++;
    if (f->face_pixel_height != c->pixel_height) {
        if (FT_Set_Pixel_Sizes(f->face, 0, (FT_UInt)c->pixel_height))
            return g;
        f->face_pixel_height = c->pixel_height;
    }
    /* A character missing from the font loads glyph 0, the font's box: visibly not a space. Light
     * hinting snaps stems vertically only, and the pen moves by the unhinted advance: widths then
     * scale with the size, so a line wraps at the same word at 720p and at 1080p. */
    if (FT_Load_Char(f->face, codepoint, FT_LOAD_RENDER | FT_LOAD_TARGET_LIGHT))
        return g;
    FT_GlyphSlot slot = f->face->glyph;
    g->index = slot->glyph_index;
    g->advance = slot->linearHoriAdvance >> 10;   /* 16.16 to 26.6 */
    g->coverage = copy_coverage(&slot->bitmap);
    if (g->coverage) {
        g->width = (int)slot->bitmap.width;
        g->rows = (int)slot->bitmap.rows;
        g->left = slot->bitmap_left;
        g->top = slot->bitmap_top;
    }
    return g;
}

struct canvas {
    unsigned char *rgba;
    int w, h;
    const unsigned char *color;
};

/* Straight-alpha "over": the result's alpha is a + b (1 - a), its colour each side's colour weighted
 * by its share of that alpha. */
static void blend(unsigned char *px, unsigned coverage, const unsigned char color[4])
{
    float a = (float)coverage / 255.0f * (float)color[3] / 255.0f;
    if (a <= 0.0f)
        return;
    float b = (float)px[3] / 255.0f * (1.0f - a);
    float out = a + b;
    for (int k = 0; k < 3; k++)
        px[k] = (unsigned char)(((float)color[k] * a + (float)px[k] * b) / out + 0.5f);
    px[3] = (unsigned char)(out * 255.0f + 0.5f);
}

/* Blends a glyph's coverage with its top-left corner at (x0, y0), the parts inside the image only. */
static void stamp(const struct canvas *cv, const struct glyph *g, long x0, long y0)
{
    long c_begin = x0 < 0 ? -x0 : 0, c_end = g->width;
    long r_begin = y0 < 0 ? -y0 : 0, r_end = g->rows;
    if (x0 + c_end > cv->w)
        c_end = cv->w - x0;
    if (y0 + r_end > cv->h)
        r_end = cv->h - y0;
    for (long r = r_begin; r < r_end; r++) {
        const unsigned char *cov = g->coverage + r * g->width;
        unsigned char *row = cv->rgba + (size_t)(y0 + r) * (size_t)cv->w * 4;
        for (long col = c_begin; col < c_end; col++)
            if (cov[col])
                blend(row + (size_t)(x0 + col) * 4, cov[col], cv->color);
    }
}

/* Nearest whole pixel of a 26.6 position, the same way for both signs. */
static long whole_pixels(FT_Pos p)
{
    return p >= 0 ? (long)((p + 32) >> 6) : -(long)((-p + 32) >> 6);
}

/* A kerning adjustment in font units at pixel_height, in 26.6, unrounded like the advances. */
static FT_Pos kerning_26_6(FT_Face face, FT_Pos units, int pixel_height)
{
    double x = (double)units * pixel_height * 64.0 / face->units_per_EM;
    return (FT_Pos)(x >= 0 ? x + 0.5 : x - 0.5);
}

/* Sets the pen along utf8 and, with a canvas, draws each glyph at it; returns the advance in
 * pixels. One walk for both, so that a measured width is the drawn one. */
static int run_text(struct hud_font *f, int pixel_height, const char *utf8, const struct canvas *cv, int x,
                    int y)
{
    if (!f || !utf8 || pixel_height <= 0 || pixel_height > MAX_PIXEL_HEIGHT)
        return 0;
    struct size_cache *c = size_cache_for(f, pixel_height);
    int kerning = FT_HAS_KERNING(f->face);
    const unsigned char *s = (const unsigned char *)utf8;
    FT_Pos pen = 0;
    FT_UInt previous = 0;
    for (size_t i = 0; s[i];) {
        const struct glyph *g = glyph_for(f, c, next_codepoint(s, &i));
        if (!g)
            continue;
        if (kerning && previous && g->index) {
            /* in font units, scaled here: asking FreeType for scaled kerning would mean setting the
             * face's size again at every change of size, though every glyph is already cached */
            FT_Vector delta;
            if (FT_Get_Kerning(f->face, previous, g->index, FT_KERNING_UNSCALED, &delta) == 0 && delta.x != 0)
                pen += kerning_26_6(f->face, delta.x, pixel_height);
        }
        if (cv && g->coverage)
            stamp(cv, g, (long)x + whole_pixels(pen) + g->left, (long)y - g->top);
        pen += g->advance;
        previous = g->index;
    }
    long advance = whole_pixels(pen);
    return advance > INT32_MAX ? INT32_MAX : (int)advance;
}

int hud_text_width(struct hud_font *f, int pixel_height, const char *utf8)
{
    return run_text(f, pixel_height, utf8, NULL, 0, 0);
}

int hud_text_draw(struct hud_font *f, unsigned char *rgba, int w, int h, int x, int y, int pixel_height,
                  const char *utf8, const unsigned char color[4])
{
    if (!rgba || w <= 0 || h <= 0)
        return hud_text_width(f, pixel_height, utf8);
    struct canvas cv = {rgba, w, h, color};
    return run_text(f, pixel_height, utf8, &cv, x, y);
}
