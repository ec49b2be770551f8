/* The HUD's words and its layout. Every length is a fraction of the screen's height, so that the
 * HUD covers the same share of the picture at 720p and at 1080p and reads the same from the
 * visitor's distance. */
#include "kiosk/hud.h"
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "kiosk/pipeline_layout.h"
#include "physics/relativity.h"

/* Text heights as fractions of the screen's height: body text h/30 is 24 px at 720p, 36 at 1080p. */
#define BODY_TEXT_DIVISOR 30
#define TITLE_TEXT_DIVISOR 20
/* A visitor's block is smaller, in a corner: body h/40 (18 px at 720p, 27 at 1080p), title h/26;
 * with its title, a caption of up to three rows and three lines it keeps within the top 30% of
 * the screen. */
#define VISITOR_BODY_DIVISOR 40
#define VISITOR_TITLE_DIVISOR 26
/* Below this FreeType's glyphs stop being legible; a tiny preview window still gets text. */
#define MIN_TEXT_PX 8
/* Row pitch over text height: room for descenders (DejaVu's reach 0.24 em) and a gap. */
#define ROW_PITCH_NUM 4
#define ROW_PITCH_DEN 3
/* A visitor's block of lines wraps within this share of the screen's width (staff's: all of it). */
#define VISITOR_WIDTH_NUM 10
#define VISITOR_WIDTH_DEN 20
#define VISITOR_MIN_EMS 30
/* A long explanation wraps into this many rows at most, for the whole block. */
#define MAX_ROWS (2 * HUD_MAX_LINES)

/* The indicator: a bar a third of the screen wide, its bottom a tenth of the height up. */
#define BAR_WIDTH_DIVISOR 3
#define BAR_HEIGHT_DIVISOR 72
#define BAR_LIFT_DIVISOR 10

/* Straight-alpha colours. The band is dark and translucent: the picture shows through, the text
 * stays legible over a bright star or the accretion disc. */
static const unsigned char band_color[4] = {8, 10, 16, 170};
static const unsigned char title_color[4] = {255, 228, 170, 255};
static const unsigned char body_color[4] = {235, 238, 245, 255};
static const unsigned char notice_color[4] = {255, 170, 90, 255};
static const unsigned char track_color[4] = {70, 74, 86, 230};
static const unsigned char fill_color[4] = {120, 200, 255, 255};

enum line_kind { LINE_TITLE, LINE_BODY, LINE_NOTICE };

/* Formats one line; when it is cut at HUD_LINE_LEN, a character split by the cut is dropped whole,
 * so the line stays valid UTF-8. */
static void put_line(char *line, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(line, HUD_LINE_LEN, fmt, ap);
    va_end(ap);
    if (n < HUD_LINE_LEN)
        return;
    size_t end = strlen(line);
    size_t start = end;
    while (start > 0 && ((unsigned char)line[start - 1] & 0xC0) == 0x80)
        start--;
    if (start == 0)
        return;
    unsigned lead = (unsigned char)line[start - 1];
    size_t need = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 1;
    if (end - (start - 1) < need)
        line[start - 1] = '\0';
}

static int present(const char *s)
{
    return s && s[0];
}

/* v/c with as many decimals as it takes not to read as c itself: 0.995 c is not "1.00 c". */
static int speed_decimals(double v)
{
    int decimals = 2;
    while (decimals < 6 && fabs(v) < 1.0 && fabs(v) >= 1.0 - 0.5 * pow(10.0, -decimals))
        decimals++;
    return decimals;
}

static void format_speed(char *out, size_t len, double v)
{
    snprintf(out, len, "%.*f", speed_decimals(v), v);
}

/* "v = 0.90 c   γ = 2.29": the Lorentz factor is what the visitor sees change (time dilation,
 * aberration), v alone hides how close 0.99 c is to c. */
static void format_speed_pair(char *out, size_t len, double v)
{
    char vs[16];
    format_speed(vs, sizeof vs, v);
    if (fabs(v) < 1.0)
        snprintf(out, len, "v = %s c   γ = %.2f", vs, lorentz_gamma(v3(v, 0.0, 0.0)));
    else
        snprintf(out, len, "v = %s c   (nothing with mass reaches c)", vs);
}

/* A mass or a length in the scene's unit: two decimals, more significant digits when small. */
static void format_amount(char *out, size_t len, double x)
{
    if (fabs(x) >= 0.1 || x == 0.0)
        snprintf(out, len, "%.2f", x);
    else
        snprintf(out, len, "%.2g", x);
}

/* v/c as a visitor reads it: "90%", "99.5%": the digits format_speed shows, as a percentage. */
static void format_percent_of_light(char *out, size_t len, double v)
{
    snprintf(out, len, "%.*f%%", speed_decimals(v) - 2, 100.0 * v);
}

/* The effects (enum relativity_effects: geometry, Doppler colour, searchlight), without and with
 * gravity's shift: staff's names and a visitor's words. */
static const char *const effects_names[2][3] = {
    {"geometry", "Doppler colour", "Doppler colour + searchlight"},
    {"geometry", "Doppler colour + gravitational shift", "Doppler colour + searchlight + gravitational shift"},
};
static const char *const effects_words[2][3] = {
    {"Colours: as the light left its source", "Colours: shifted by motion",
     "Colours: shifted by motion, brighter where light comes towards you"},
    {"Colours: as the light left its source", "Colours: shifted by motion and gravity",
     "Colours: shifted by motion and gravity, brighter where light comes towards you"},
};

static int effects_known(int effects)
{
    return effects >= 0 && effects < 3;
}

/* A visitor's knob line: the knob in words and what it is at; `brief`: the indicator's short form
 * (without the clocks, or flat space's why). */
static void visitor_knob(char *out, size_t len, const struct hud_view *v, enum hud_knob knob, double value,
                         int brief)
{
    char a[48], g[32];
    if (knob == HUD_KNOB_SPEED && !present(v->speed_key)) {
        const char *label = present(v->speed_label) ? v->speed_label : "Speed";
        format_percent_of_light(a, sizeof a, value);
        if (value == 0.0)
            snprintf(out, len, "%s: at rest", label);
        else if (fabs(value) < 1.0 && !brief) {
            snprintf(g, sizeof g, "%.2f", lorentz_gamma(v3(value, 0.0, 0.0)));
            snprintf(out, len, "%s: %s of light speed, clocks %s× slower", label, a, g);
        } else
            snprintf(out, len, "%s: %s of light speed", label, a);
        return;
    }
    if (knob == HUD_KNOB_MASS && !present(v->mass_key)) {
        const char *label = present(v->mass_label) ? v->mass_label : "Black hole";
        double share = 100.0 * v->shadow_share;
        if (value == 0.0)
            snprintf(out, len, brief ? "%s: none" : "%s: none, light goes straight", label);
        else if (share >= 100.0)
            snprintf(out, len, "%s: its shadow fills the view", label);
        else if (share >= 1.0)
            snprintf(out, len, "%s: shadow %.0f%% of the view's height", label, share);
        else
            snprintf(out, len, "%s: shadow under 1%% of the view", label);
        return;
    }
    /* a knob mapped to a key: how far along its range, not the key's number */
    const char *label = knob == HUD_KNOB_SPEED ? v->speed_label : v->mass_label;
    const double *range = knob == HUD_KNOB_SPEED ? v->speed_range : v->mass_range;
    double span = range[1] - range[0];
    double along = span > 0.0 ? 100.0 * (value - range[0]) / span : 0.0;
    along = isnan(along) ? 0.0 : along < 0.0 ? 0.0 : along > 100.0 ? 100.0 : along;
    snprintf(out, len, "%s: %.0f%%", present(label) ? label : knob == HUD_KNOB_SPEED ? "Speed knob" : "Mass knob",
             along);
}

static int collect_lines(const struct hud_view *v, char lines[][HUD_LINE_LEN], enum line_kind *kinds, int max)
{
    int n = 0;
    char a[32], b[32], knob[HUD_LINE_LEN];
#define LINE(kind, ...)                                        \
    do {                                                       \
        if (n < max) {                                         \
            put_line(lines[n], __VA_ARGS__);                   \
            if (kinds)                                         \
                kinds[n] = (kind);                             \
            n++;                                               \
        }                                                      \
    } while (0)
    if (!v->staff) {
        /* a visitor's words: no file, key or symbol, nothing the knobs contradict */
        if (present(v->title))
            LINE(LINE_TITLE, "%s", v->title);
        if (present(v->caption))
            LINE(LINE_BODY, "%s", v->caption);
        if (v->has_speed || present(v->speed_key)) {
            visitor_knob(knob, sizeof knob, v, HUD_KNOB_SPEED, present(v->speed_key) ? v->speed_param : v->speed, 0);
            LINE(LINE_BODY, "%s", knob);
        }
        if (v->has_mass || present(v->mass_key)) {
            visitor_knob(knob, sizeof knob, v, HUD_KNOB_MASS, present(v->mass_key) ? v->mass_param : v->mass, 0);
            LINE(LINE_BODY, "%s", knob);
        }
        if (effects_known(v->effects))
            LINE(LINE_BODY, "%s", effects_words[v->gravitational_shift != 0][v->effects]);
        if (present(v->notice))
            LINE(LINE_NOTICE, "%s", v->notice);
        return n;
    }
    if (present(v->name))
        LINE(LINE_TITLE, "%s", v->name);
    if (present(v->explanation))
        LINE(LINE_BODY, "%s", v->explanation);
    const char *const keys[2] = {v->speed_key, v->mass_key}, *const knobs[2] = {"speed", "mass"};
    const double params[2] = {v->speed_param, v->mass_param};
    for (int i = 0; i < 2; i++)
        if (present(keys[i])) {
            format_amount(a, sizeof a, params[i]);
            LINE(LINE_BODY, "%s = %s   (the %s knob)", keys[i], a, knobs[i]);
        }
    if (v->has_speed) {
        char pair[96];
        format_speed_pair(pair, sizeof pair, v->speed);
        LINE(LINE_BODY, "%s", pair);
    }
    if (v->has_mass) {
        format_amount(b, sizeof b, v->camera_distance);
        if (v->mass == 0.0) {
            LINE(LINE_BODY, "M = 0: flat space, no horizon, light goes straight   camera at distance %s", b);
        } else {
            /* the camera stays put while M changes: the shadow (edge at 3√3 M) grows on screen */
            format_amount(a, sizeof a, v->mass);
            char rs[32];
            format_amount(rs, sizeof rs, 2.0 * v->mass);
            LINE(LINE_BODY, "M = %s   horizon r_s = 2M = %s   camera at r = %s (fixed: the shadow grows with M)", a,
                 rs, b);
        }
    }
    if (effects_known(v->effects))
        LINE(LINE_BODY, "effects: %s", effects_names[v->gravitational_shift != 0][v->effects]);
    /* no rate while none was drawn in the last second: "0.0 frames/s" reads as broken */
    if (v->fps > 0.0 && v->refining)
        LINE(LINE_BODY, "staff mode   %.1f frames/s   refining...", v->fps);
    else if (v->fps > 0.0)
        LINE(LINE_BODY, "staff mode   %.1f frames/s", v->fps);
    else if (v->refining)
        LINE(LINE_BODY, "staff mode   refining...");
    else
        LINE(LINE_BODY, "staff mode");
    if (present(v->notice))
        LINE(LINE_NOTICE, "%s", v->notice);
#undef LINE
    return n;
}

int hud_lines(const struct hud_view *v, char lines[][HUD_LINE_LEN], int max)
{
    if (!v || !lines || max <= 0)
        return 0;
    return collect_lines(v, lines, NULL, max);
}

/* h / divisor rounded, never below legibility */
static int scaled(int h, int divisor)
{
    int px = (h + divisor / 2) / divisor;
    return px < MIN_TEXT_PX ? MIN_TEXT_PX : px;
}

/* Writes colour over the rectangle's pixels inside the image (no blending: the HUD is drawn
 * back to front on a cleared image, each layer opaque over the one below or precomposed). */
static void fill_rect(unsigned char *rgba, int w, int h, int x0, int y0, int x1, int y1, const unsigned char c[4])
{
    x0 = x0 < 0 ? 0 : x0;
    y0 = y0 < 0 ? 0 : y0;
    x1 = x1 > w ? w : x1;
    y1 = y1 > h ? h : y1;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++)
            memcpy(rgba + ((size_t)y * (size_t)w + (size_t)x) * 4, c, 4);
}

struct row {
    char text[HUD_LINE_LEN];
    int px;
    const unsigned char *color;
    int width;
};

/* The longest head of text, cut where cut_here allows, that fits in avail pixels; 0 for none. */
static size_t longest_fit(struct hud_font *font, int px, const char *text, size_t len, int avail,
                          int (*cut_here)(const char *text, size_t i, size_t len))
{
    char head[HUD_LINE_LEN];
    size_t best = 0;
    for (size_t i = 1; i <= len; i++) {
        if (!cut_here(text, i, len))
            continue;
        memcpy(head, text, i);
        head[i] = '\0';
        if (hud_text_width(font, px, head) > avail)
            break;
        best = i;
    }
    return best;
}

static int at_space(const char *text, size_t i, size_t len)
{
    return i < len && text[i] == ' ';
}

/* not inside a UTF-8 character */
static int at_character(const char *text, size_t i, size_t len)
{
    return i == len || ((unsigned char)text[i] & 0xC0) != 0x80;
}

/* Bytes of text that fit in avail pixels: up to a space where one does, otherwise as many whole
 * characters as fit, and always at least one, so that wrapping moves on. */
static size_t fitting_head(struct hud_font *font, int px, const char *text, int avail)
{
    size_t len = strlen(text);
    if (hud_text_width(font, px, text) <= avail)
        return len;
    size_t best = longest_fit(font, px, text, len, avail, at_space);
    if (best > 0)
        return best;
    best = longest_fit(font, px, text, len, avail, at_character);
    if (best > 0)
        return best;
    size_t one = 1;
    while (one < len && ((unsigned char)text[one] & 0xC0) == 0x80)
        one++;
    return one;
}

/* Lines into rows no wider than avail pixels, wrapped at spaces; returns the number of rows. */
static int wrap_rows(struct hud_font *font, const struct hud_view *v, int h, int avail, struct row *rows)
{
    char lines[HUD_MAX_LINES][HUD_LINE_LEN];
    enum line_kind kinds[HUD_MAX_LINES];
    int n_lines = collect_lines(v, lines, kinds, HUD_MAX_LINES), n = 0;
    for (int l = 0; l < n_lines && n < MAX_ROWS; l++) {
        int title = v->staff ? TITLE_TEXT_DIVISOR : VISITOR_TITLE_DIVISOR;
        int body = v->staff ? BODY_TEXT_DIVISOR : VISITOR_BODY_DIVISOR;
        int px = scaled(h, kinds[l] == LINE_TITLE ? title : body);
        const unsigned char *color = kinds[l] == LINE_TITLE    ? title_color
                                     : kinds[l] == LINE_NOTICE ? notice_color
                                                               : body_color;
        const char *rest = lines[l];
        while (*rest && n < MAX_ROWS) {
            size_t take = fitting_head(font, px, rest, avail);
            struct row *r = &rows[n++];
            memcpy(r->text, rest, take);
            r->text[take] = '\0';
            r->px = px;
            r->color = color;
            r->width = hud_text_width(font, px, r->text);
            rest += take;
            while (*rest == ' ')
                rest++;
        }
    }
    return n;
}

/* The block of lines in the top-left corner, on its band. */
static void draw_lines(struct hud_font *font, unsigned char *rgba, int w, int h, const struct hud_view *v)
{
    int body_px = scaled(h, v->staff ? BODY_TEXT_DIVISOR : VISITOR_BODY_DIVISOR);
    int margin = body_px / 2, pad = body_px / 2;
    struct row rows[MAX_ROWS];
    /* a visitor's lines keep to a corner: wrapped within VISITOR_WIDTH_NUM / VISITOR_WIDTH_DEN of the
     * width, or VISITOR_MIN_EMS text heights where that is more (a small window, whose text stays at
     * its smallest legible size), never wider than the screen */
    int corner = w * VISITOR_WIDTH_NUM / VISITOR_WIDTH_DEN;
    corner = corner < VISITOR_MIN_EMS * body_px ? VISITOR_MIN_EMS * body_px : corner;
    corner = corner > w ? w : corner;
    int avail = (v->staff ? w : corner) - 2 * margin - 2 * pad;
    int n = wrap_rows(font, v, h, avail, rows);
    if (n == 0)
        return;
    int widest = 0, height = 0;
    for (int i = 0; i < n; i++) {
        widest = rows[i].width > widest ? rows[i].width : widest;
        height += rows[i].px * ROW_PITCH_NUM / ROW_PITCH_DEN;
    }
    fill_rect(rgba, w, h, margin, margin, margin + widest + 2 * pad, margin + height + 2 * pad, band_color);
    int top = margin + pad;
    for (int i = 0; i < n; i++) {
        /* DejaVu's ascent is 0.93 em: a baseline one text height down clears the row's top */
        hud_text_draw(font, rgba, w, h, margin + pad, top + rows[i].px, rows[i].px, rows[i].text, rows[i].color);
        top += rows[i].px * ROW_PITCH_NUM / ROW_PITCH_DEN;
    }
}

/* The knob just turned: its name and value above a bar from indicator_min to indicator_max, with
 * the two range numbers at the bar's ends. */
static void draw_indicator(struct hud_font *font, unsigned char *rgba, int w, int h, const struct hud_view *v)
{
    char label[HUD_LINE_LEN], lo[48], hi[48], value[96], number[32];
    const char *key = v->indicator == HUD_KNOB_SPEED ? v->speed_key : v->mass_key;
    if (!v->staff) {
        /* the knob in words over its bar; the ends: the speed's range, a mapped knob's 0% and
         * 100%, or no black hole and a large one */
        visitor_knob(label, sizeof label, v, v->indicator, v->indicator_value, 1);
        if (present(key)) {
            snprintf(lo, sizeof lo, "0%%");
            snprintf(hi, sizeof hi, "100%%");
        } else if (v->indicator == HUD_KNOB_SPEED) {
            format_percent_of_light(lo, sizeof lo, v->indicator_min);
            format_percent_of_light(hi, sizeof hi, v->indicator_max);
        } else {
            snprintf(lo, sizeof lo, "%s", v->indicator_min == 0.0 ? "none" : "small");
            snprintf(hi, sizeof hi, "large");
        }
    } else if (present(key)) {
        format_amount(number, sizeof number, v->indicator_value);
        snprintf(label, sizeof label, "%s knob   %s = %s", v->indicator == HUD_KNOB_SPEED ? "speed" : "mass", key,
                 number);
        format_amount(lo, sizeof lo, v->indicator_min);
        format_amount(hi, sizeof hi, v->indicator_max);
    } else if (v->indicator == HUD_KNOB_SPEED) {
        format_speed_pair(value, sizeof value, v->indicator_value);
        snprintf(label, sizeof label, "speed   %s", value);
        format_speed(number, sizeof number, v->indicator_min);
        snprintf(lo, sizeof lo, "%s c", number);
        format_speed(number, sizeof number, v->indicator_max);
        snprintf(hi, sizeof hi, "%s c", number);
    } else {
        format_amount(value, sizeof value, v->indicator_value);
        snprintf(label, sizeof label, "mass   M = %s", value);
        format_amount(lo, sizeof lo, v->indicator_min);
        format_amount(hi, sizeof hi, v->indicator_max);
    }
    int px = scaled(h, BODY_TEXT_DIVISOR), pad = px / 2, gap = px / 2;
    int bar_w = w / BAR_WIDTH_DIVISOR, bar_h = scaled(h, BAR_HEIGHT_DIVISOR);
    int bar_x = (w - bar_w) / 2, bar_y = h - h / BAR_LIFT_DIVISOR - bar_h;
    int label_base = bar_y - px / 2;
    /* range numbers centred on the bar: a digit's height is about 0.73 em */
    int range_base = bar_y + bar_h / 2 + px * 3 / 8;
    int lo_w = hud_text_width(font, px, lo), hi_w = hud_text_width(font, px, hi);
    int label_w = hud_text_width(font, px, label);
    int left = bar_x - gap - lo_w - pad;
    int right = bar_x + bar_w + gap + hi_w + pad;
    if (bar_x + label_w + pad > right)
        right = bar_x + label_w + pad;
    int bottom = range_base + px / 3 > bar_y + bar_h ? range_base + px / 3 : bar_y + bar_h;
    fill_rect(rgba, w, h, left, label_base - px - pad, right, bottom + pad, band_color);

    double span = v->indicator_max - v->indicator_min;
    double share = span > 0.0 ? (v->indicator_value - v->indicator_min) / span : 1.0;
    share = isnan(share) ? 0.0 : share < 0.0 ? 0.0 : share > 1.0 ? 1.0 : share;
    fill_rect(rgba, w, h, bar_x, bar_y, bar_x + bar_w, bar_y + bar_h, track_color);
    fill_rect(rgba, w, h, bar_x, bar_y, bar_x + (int)lround(share * bar_w), bar_y + bar_h, fill_color);

    hud_text_draw(font, rgba, w, h, bar_x, label_base, px, label, body_color);
    hud_text_draw(font, rgba, w, h, bar_x - gap - lo_w, range_base, px, lo, body_color);
    hud_text_draw(font, rgba, w, h, bar_x + bar_w + gap, range_base, px, hi, body_color);
}

const char *const hud_pipeline_labels[HUD_PIPELINE_PANELS] = {
    "image", "ray positions", "ray directions", "segment of the hit", "step size",
    "outcome",
};
const char *const hud_pipeline_table_label = "orbit table: 1/r along each orbit";
const char *const hud_pipeline_steps_label = "steps taken";
const char *const hud_pipeline_path_label = "path travelled";

/* What the colour scales and the legend below the panels say (kiosk_pipeline.glsl draws them):
 * the ends of each scale, the outcome's five colours in the legend's order, and how the positions
 * and directions take their colours. */
static const char *const scale_ends[5][2] = {{"first", "last segment"},
                                             {"shorter", "longer than the step"},
                                             {"far", "at the horizon"},
                                             {"none", "every step a ray has"},
                                             {"none", "the whole path a ray has"}};
static const char *const outcome_words[5] = {"object", "sky", "fell in", "unfinished", "failed"};
static const char *const colour_axes = "x, y, z as red, green, blue";
#define LEGEND_TEXT_DIVISOR 45

/* The words under panel k: under its colour scale's ends, its legend's colours, or on their own. */
static void draw_panel_legend(struct hud_font *font, unsigned char *rgba, int w, int h, const struct hud_view *v, int k)
{
    int x, y, lw, lh;
    if (k == 0 || pipeline_legend_rect(v->canvas_w, v->canvas_h, k, &x, &y, &lw, &lh) != 0)
        return;
    int px = scaled(h, LEGEND_TEXT_DIVISOR);
    x += v->canvas_x;
    int base = v->canvas_y + y + (k <= 2 ? px : lh + px + px / 4);
    if (k <= 2) {
        hud_text_draw(font, rgba, w, h, x, base, px, colour_axes, body_color);
    } else if (k < 5) {
        int table = k == HUD_PIPELINE_TABLE_PANEL && v->orbit_table;
        int steps = k == HUD_PIPELINE_TABLE_PANEL && !v->orbit_table && v->fixed_steps;
        const char *const *ends = scale_ends[table ? 2 : steps ? (v->far_steps ? 4 : 3) : k - 3];
        hud_text_draw(font, rgba, w, h, x, base, px, ends[0], body_color);
        int right = hud_text_width(font, px, ends[1]);
        hud_text_draw(font, rgba, w, h, x + lw - right, base, px, ends[1], body_color);
    } else {
        for (int i = 0; i < 5; i++) {
            int tw = hud_text_width(font, px, outcome_words[i]);
            hud_text_draw(font, rgba, w, h, x + (2 * i + 1) * lw / 10 - tw / 2, base, px, outcome_words[i],
                          body_color);
        }
    }
}

/* Each panel's label on a band of its own in the panel's top-left corner, cut to the panel's width. */
static void draw_panel_labels(struct hud_font *font, unsigned char *rgba, int w, int h, const struct hud_view *v)
{
    int px = scaled(h, BODY_TEXT_DIVISOR), pad = px / 3;
    int pw = v->canvas_w / 3, ph = v->canvas_h / 2;
    for (int p = 0; p < HUD_PIPELINE_PANELS; p++) {
        int x0 = v->canvas_x + (p % 3) * pw, y0 = v->canvas_y + (p / 3) * ph;
        char text[HUD_LINE_LEN];
        if (p == 0 && v->title)
            snprintf(text, sizeof text, "image: %s", v->title);
        else
            snprintf(text, sizeof text, "%s",
                     p != HUD_PIPELINE_TABLE_PANEL ? hud_pipeline_labels[p]
                     : v->orbit_table              ? hud_pipeline_table_label
                     : v->far_steps                ? hud_pipeline_path_label
                     : v->fixed_steps              ? hud_pipeline_steps_label
                                                   : hud_pipeline_labels[p]);
        size_t take = fitting_head(font, px, text, pw - 2 * pad);
        text[take] = '\0';
        int tw = hud_text_width(font, px, text);
        fill_rect(rgba, w, h, x0, y0, x0 + tw + 2 * pad, y0 + px * ROW_PITCH_NUM / ROW_PITCH_DEN + pad, band_color);
        hud_text_draw(font, rgba, w, h, x0 + pad, y0 + px, px, text, body_color);
        draw_panel_legend(font, rgba, w, h, v, p);
    }
}

void hud_draw(struct hud_font *font, unsigned char *rgba, int w, int h, const struct hud_view *v)
{
    if (!rgba || w <= 0 || h <= 0)
        return;
    memset(rgba, 0, (size_t)w * (size_t)h * 4);
    if (!font || !v)
        return;
    if (v->pipeline_view && v->canvas_w >= 3 && v->canvas_h >= 2)
        draw_panel_labels(font, rgba, w, h, v);
    else
        draw_lines(font, rgba, w, h, v);
    if (v->indicator == HUD_KNOB_SPEED || v->indicator == HUD_KNOB_MASS)
        draw_indicator(font, rgba, w, h, v);
}
