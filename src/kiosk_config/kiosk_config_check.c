/* Checks that involve more than one key or section, run once the whole file is read (one key's
 * range is checked where it is read). Each message points at the line of the key that has to
 * change, so that whoever edits the kiosk's file on site finds it. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "kiosk_config/kiosk_config.h"
#include "kiosk_config/kiosk_config_keys.h"
#include "io/output_file.h"
#include "scene/scene.h"

#define NO_BIT (-1)

__attribute__((format(printf, 4, 5)))
static int bad(const struct kiosk_config *c, struct error *err, int line, const char *fmt, ...)
{
    va_list ap;
    const char *file = c->path[0] ? c->path : "kiosk configuration";
    err->status = ERROR_INPUT;
    if (line > 0)
        snprintf(err->where, sizeof err->where, "%s:%d", file, line);
    else
        snprintf(err->where, sizeof err->where, "%s", file);
    va_start(ap, fmt);
    vsnprintf(err->message, sizeof err->message, fmt, ap);
    va_end(ap);
    return -1;
}

/* The key's line, else its section's, else 0 (built in code, or the section is not in the file). */
static int line_of(const struct kiosk_config *c, enum kiosk_section section, int instance, const char *key)
{
    int line = key ? kiosk_key_line(c, section, instance, key) : 0;
    return line ? line : c->source.header[kiosk_slot(section, instance)];
}

/* A message about KEY of a section instance, at the key's line: "key 'KEY' in [LABEL]" and FMT,
 * which starts with ": " or " applies ...". */
__attribute__((format(printf, 6, 7)))
static int bad_key(const struct kiosk_config *c, struct error *err, enum kiosk_section section,
                   int instance, const char *key, const char *fmt, ...)
{
    char label[KIOSK_NAME_LEN + 16], detail[sizeof err->message];
    va_list ap;
    kiosk_section_label(c, section, instance, label, sizeof label);
    va_start(ap, fmt);
    vsnprintf(detail, sizeof detail, fmt, ap);
    va_end(ap);
    return bad(c, err, line_of(c, section, instance, key), "key '%s' in %s%s", key, label, detail);
}

const struct kiosk_input *kiosk_config_input(const struct kiosk_config *c, const char *name)
{
    for (int i = 0; i < c->n_inputs; i++)
        if (strcmp(c->inputs[i].name, name) == 0)
            return &c->inputs[i];
    return NULL;
}

/* ---- [kiosk] and [display] ----------------------------------------------------------------- */

static int size_ok(int w, int h)
{
    return w >= KIOSK_MIN_SIZE && w <= KIOSK_MAX_SIZE && h >= KIOSK_MIN_SIZE && h <= KIOSK_MAX_SIZE;
}

static int check_kiosk(const struct kiosk_config *c, struct error *err)
{
    const struct kiosk_main *k = &c->kiosk;
    struct error outside;

    if (k->n_scenes < 1)
        return bad(c, err, line_of(c, KSEC_KIOSK, 0, NULL), "[kiosk] lists no scenes: set 'scenes' "
                   "to 1 to %d scene files", KIOSK_MAX_SCENES);
    if (k->start_scene < 0 || k->start_scene >= k->n_scenes)
        return bad_key(c, err, KSEC_KIOSK, 0, "start_scene", ": %d is not one of the %d scenes "
                       "(0 is the first)", k->start_scene, k->n_scenes);
    if (!size_ok(k->width, k->height))
        return bad_key(c, err, KSEC_KIOSK, 0, "width", ": the frame %dx%d: width and height must be "
                       "from %d to %d", k->width, k->height, KIOSK_MIN_SIZE, KIOSK_MAX_SIZE);
    /* the refined frame is a scene's image: the renderer's own limit on pixels applies */
    if ((long)k->width * k->height > SCENE_MAX_PIXELS)
        return bad_key(c, err, KSEC_KIOSK, 0, "width", ": the frame %dx%d has more than %ld pixels, the "
                       "renderer's limit (docs/LIMITS.md)", k->width, k->height, (long)SCENE_MAX_PIXELS);
    if (!size_ok(k->preview_width, k->preview_height))
        return bad_key(c, err, KSEC_KIOSK, 0, "preview_width", ": the preview %dx%d: width and height "
                       "must be from %d to %d", k->preview_width, k->preview_height, KIOSK_MIN_SIZE,
                       KIOSK_MAX_SIZE);
    /* the preview is the cheap frame drawn while a knob turns: larger than the refined one, it
     * would be slower than what it stands in for */
    if (k->preview_width > k->width || k->preview_height > k->height) {
        const char *key = k->preview_width > k->width ? "preview_width" : "preview_height";
        return bad_key(c, err, KSEC_KIOSK, 0, key, ": the preview %dx%d is larger than the refined "
                       "frame %dx%d (width, height): make it smaller", k->preview_width,
                       k->preview_height, k->width, k->height);
    }
    if (k->assets_root[0] == '\0')
        return 0;
    for (int i = 0; i < k->n_scenes; i++) {
        int inside = kiosk_path_inside(k->scenes[i], k->assets_root, &outside);
        if (inside != 1)
            return bad_key(c, err, KSEC_KIOSK, 0, "scenes", ": scene %d: %s", i + 1, outside.message);
    }
    return 0;
}

static int check_display(const struct kiosk_config *c, struct error *err)
{
    const struct kiosk_display *d = &c->display;
    /* the keys of one backend given for another would be ignored, and whoever set them would
     * wonder why they change nothing */
    static const char *const kms_keys[] = {"drm_device", "connector", "mode"};
    static const char *const headless_keys[] = {"headless_out", "headless_frames"};
    int kms_given[3] = {d->drm_device[0] != '\0', d->connector[0] != '\0', d->mode_width != 0};
    int headless_given[2] = {d->headless_out[0] != '\0', d->headless_frames != 0};
    const char *backend = d->backend == KIOSK_BACKEND_X11 ? "x11"
                        : d->backend == KIOSK_BACKEND_KMS ? "kms" : "headless";

    /* a screen chosen on the command line: the file's keys for its own screen were set aside */
    if (d->backend_overridden)
        ;
    else if (d->backend == KIOSK_BACKEND_X11 || d->backend == KIOSK_BACKEND_HEADLESS)
        for (int i = 0; i < 3; i++)
            if (kms_given[i])
                return bad_key(c, err, KSEC_DISPLAY, 0, kms_keys[i], " applies to backend kms (or "
                               "auto), not to '%s': remove it", backend);
    if (!d->backend_overridden && (d->backend == KIOSK_BACKEND_X11 || d->backend == KIOSK_BACKEND_KMS))
        for (int i = 0; i < 2; i++)
            if (headless_given[i])
                return bad_key(c, err, KSEC_DISPLAY, 0, headless_keys[i], " applies to backend "
                               "headless (or auto), not to '%s': remove it", backend);
    if (!d->backend_overridden && d->backend == KIOSK_BACKEND_HEADLESS && kiosk_key_line(c, KSEC_DISPLAY, 0, "vsync"))
        return bad_key(c, err, KSEC_DISPLAY, 0, "vsync", " applies to backends that show frames on a "
                       "screen, not to 'headless': remove it");
    if (d->backend == KIOSK_BACKEND_HEADLESS && d->headless_out[0] == '\0')
        return bad_key(c, err, KSEC_DISPLAY, 0, "backend", ": headless writes its frames as PNG "
                       "files: set 'headless_out' to a directory");
    if (d->mode_width != 0 && !size_ok(d->mode_width, d->mode_height))
        return bad_key(c, err, KSEC_DISPLAY, 0, "mode", ": %dx%d: width and height must be from %d "
                       "to %d", d->mode_width, d->mode_height, KIOSK_MIN_SIZE, KIOSK_MAX_SIZE);
    return 0;
}

/* ---- knobs and buttons --------------------------------------------------------------------- */

/* "pm, enc": the inputs there are, for a reference to one that is not. */
static void list_inputs(const struct kiosk_config *c, char *buf, size_t len)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < c->n_inputs && used < len; i++)
        used += (size_t)snprintf(buf + used, len - used, "%s%s", i ? ", " : "", c->inputs[i].name);
    if (c->n_inputs == 0)
        snprintf(buf, len, "none");
}

/* The input a knob or button names, or NULL with the message. */
static const struct kiosk_input *find_referenced(const struct kiosk_config *c,
                                                 struct error *err,
                                                 enum kiosk_section section, int instance, const char *name)
{
    char label[KIOSK_NAME_LEN + 16], names[KIOSK_MAX_INPUTS * (KIOSK_NAME_LEN + 2)];
    const struct kiosk_input *in;
    if (name[0] == '\0') {
        kiosk_section_label(c, section, instance, label, sizeof label);
        bad(c, err, line_of(c, section, instance, NULL), "%s has no input: set 'input' to the name of "
            "an [input NAME] section", label);
        return NULL;
    }
    in = kiosk_config_input(c, name);
    if (!in) {
        list_inputs(c, names, sizeof names);
        bad_key(c, err, section, instance, "input", ": there is no [input %s] section (inputs: %s)", name,
                names);
    }
    return in;
}

/* A knob's range in the unit its step is counted in. */
static double curve_span(const struct kiosk_knob *k)
{
    if (k->curve == KIOSK_CURVE_RAPIDITY)
        return atanh(k->max) - atanh(k->min);
    if (k->curve == KIOSK_CURVE_LOG)
        return log(k->max / k->min);
    return k->max - k->min;
}

static int check_knob(const struct kiosk_config *c, struct error *err,
                      enum kiosk_section section)
{
    const struct kiosk_knob *k = section == KSEC_SPEED ? &c->speed : &c->mass;
    double top = section == KSEC_SPEED ? KIOSK_SPEED_MAX : KIOSK_MASS_MAX;
    const struct kiosk_input *in = find_referenced(c, err, section, 0, k->input);

    if (!in)
        return -1;
    if (in->type == KIOSK_INPUT_GPIO_BUTTON)
        return bad_key(c, err, section, 0, "input", ": [input %s] is a gpio_button and cannot turn a knob",
                       in->name);
    if (!(k->min >= 0.0 && k->max <= top))
        return bad_key(c, err, section, 0, "max", ": the range %g to %g must lie within 0 to %g", k->min,
                       k->max, top);
    if (!(k->min < k->max))
        return bad_key(c, err, section, 0, "max", ": %g is not above min (%g)", k->max, k->min);
    if (!(k->start >= k->min && k->start <= k->max))
        return bad_key(c, err, section, 0, "start", ": %g is outside min..max (%g to %g)", k->start, k->min,
                       k->max);
    if (k->curve == KIOSK_CURVE_LOG && !(k->min > 0.0))
        return bad_key(c, err, section, 0, "curve", ": log needs min > 0 (the logarithm of 0 has no "
                       "value): raise min or use curve linear");
    if (!(k->step > 0.0) || k->step > curve_span(k))
        return bad_key(c, err, section, 0, "step", ": %g is not above 0 and at most the whole range, %g "
                       "in the curve's unit", k->step, curve_span(k));
    return 0;
}

/* A press is told apart by input and, for HID, bit: two buttons on one would fire together. */
static int same_press(const struct kiosk_button *a, const struct kiosk_button *b,
                      const struct kiosk_input *in)
{
    if (strcmp(a->input, b->input) != 0)
        return 0;
    if (in->type == KIOSK_INPUT_HID)
        return a->bit == b->bit;
    return in->type == KIOSK_INPUT_POWERMATE || in->type == KIOSK_INPUT_GPIO_BUTTON;
}

static int check_button(const struct kiosk_config *c, struct error *err, int i)
{
    const struct kiosk_button *b = &c->buttons[i];
    const struct kiosk_input *in = find_referenced(c, err, KSEC_BUTTON, i, b->input);

    if (!in)
        return -1;
    if (in->type == KIOSK_INPUT_GPIO_ENCODER)
        return bad_key(c, err, KSEC_BUTTON, i, "input", ": [input %s] is a gpio_encoder, which has no "
                       "button: give the button its own gpio_button input", in->name);
    /* never ignored: these send actions by name themselves, so a button on them could never fire */
    if (in->type == KIOSK_INPUT_KEYBOARD || in->type == KIOSK_INPUT_SCRIPT)
        return bad_key(c, err, KSEC_BUTTON, i, "input", ": [input %s] is a %s, which presses actions by name "
                       "(%s): this button would never fire; remove it", in->name, kiosk_input_type_name(in->type),
                       in->type == KIOSK_INPUT_KEYBOARD ? "its fixed keys" : "'press ACTION'");
    /* never ignored: a bit on an input without button bits would be a press nobody can make */
    if (in->type != KIOSK_INPUT_HID && b->bit != NO_BIT)
        return bad_key(c, err, KSEC_BUTTON, i, "bit", " does not apply to input type '%s' of [input %s] "
                       "(only to hid): remove it", kiosk_input_type_name(in->type), in->name);
    if (in->type == KIOSK_INPUT_HID && b->bit == NO_BIT)
        return bad(c, err, line_of(c, KSEC_BUTTON, i, NULL), "[button %s] uses hid input [input %s]: "
                   "set 'bit' to the button's bit (0 to 7)", b->name, in->name);
    if (in->type == KIOSK_INPUT_HID && b->bit >= in->buttons)
        return bad_key(c, err, KSEC_BUTTON, i, "bit", ": bit %d, but [input %s] declares buttons = %d "
                       "(bits 0 to %d)", b->bit, in->name, in->buttons, in->buttons - 1);
    for (int j = 0; j < i; j++)
        if (same_press(&c->buttons[j], b, in))
            return bad_key(c, err, KSEC_BUTTON, i, "input", ": the same press of [input %s] as "
                           "[button %s]: one press would do both", in->name, c->buttons[j].name);
    return 0;
}

/* ---- inputs -------------------------------------------------------------------------------- */

static int check_hid(const struct kiosk_config *c, struct error *err, int i)
{
    const struct kiosk_input *in = &c->inputs[i];
    int first = in->report_id ? 1 : 0;   /* numbered reports start with their id byte */
    int last = in->report_length - 1;

    if (in->axis_offset < first || in->axis_offset + in->axis_size - 1 > last)
        return bad_key(c, err, KSEC_INPUT, i, "axis_offset", ": the axis at bytes %d to %d is outside the "
                       "report's data (bytes %d to %d of report_length %d)", in->axis_offset,
                       in->axis_offset + in->axis_size - 1, first, last, in->report_length);
    if (in->buttons > 0 && (in->button_offset < first || in->button_offset > last))
        return bad_key(c, err, KSEC_INPUT, i, "button_offset", ": %d is outside the report's data (bytes "
                       "%d to %d)", in->button_offset, first, last);
    if (in->axis_mode == KIOSK_AXIS_RELATIVE) {
        int given_min = kiosk_key_line(c, KSEC_INPUT, i, "axis_min") || in->axis_min;
        int given_max = kiosk_key_line(c, KSEC_INPUT, i, "axis_max") || in->axis_max;
        if (given_min || given_max)
            return bad_key(c, err, KSEC_INPUT, i, given_min ? "axis_min" : "axis_max", " applies to "
                           "axis_mode absolute only: a relative axis reports counts, not a position");
        return 0;
    }
    if (!(in->axis_min < in->axis_max))
        return bad_key(c, err, KSEC_INPUT, i, "axis_max", ": axis_mode absolute needs axis_min < axis_max "
                       "(the raw values at the knob's two ends), got %lld and %lld",
                       (long long)in->axis_min, (long long)in->axis_max);
    return 0;
}

static int check_gpio_encoder(const struct kiosk_config *c, struct error *err, int i)
{
    const struct kiosk_input *in = &c->inputs[i];
    int offsets = (in->line_a >= 0) + (in->line_b >= 0);
    int names = (in->line_a_name[0] != '\0') + (in->line_b_name[0] != '\0');

    if (offsets && names) {
        /* point at a name: for the usual slip, one line changed to the other way */
        const char *key = in->line_b_name[0] ? "line_b_name" : "line_a_name";
        return bad_key(c, err, KSEC_INPUT, i, key, ": the encoder's lines are given by offset (line_a, "
                       "line_b) and by name (line_a_name, line_b_name) at once: give both lines the "
                       "same way");
    }
    if (offsets != 2 && names != 2)
        return bad(c, err, line_of(c, KSEC_INPUT, i, NULL), "[input %s] needs both lines of the "
                   "encoder: line_a and line_b, or line_a_name and line_b_name", in->name);
    if (offsets == 2 ? in->line_a == in->line_b : strcmp(in->line_a_name, in->line_b_name) == 0)
        return bad_key(c, err, KSEC_INPUT, i, offsets == 2 ? "line_b" : "line_b_name", ": line A and "
                       "line B are the same line");
    return 0;
}

static int check_gpio_button(const struct kiosk_config *c, struct error *err, int i)
{
    const struct kiosk_input *in = &c->inputs[i];
    if (in->line >= 0 && in->line_name[0])
        return bad_key(c, err, KSEC_INPUT, i, "line_name", ": the line is given both by offset ('line') "
                       "and by name: keep one");
    if (in->line < 0 && !in->line_name[0])
        return bad(c, err, line_of(c, KSEC_INPUT, i, NULL), "[input %s] needs its line: 'line' (an "
                   "offset) or 'line_name'", in->name);
    return 0;
}

/* Whether inputs A and B claim a common GPIO line (by offset or by name) of the same chip. */
static int shares_line(const struct kiosk_input *a, const struct kiosk_input *b)
{
    const int a_off[3] = {a->line_a, a->line_b, a->line}, b_off[3] = {b->line_a, b->line_b, b->line};
    const char *a_name[3] = {a->line_a_name, a->line_b_name, a->line_name};
    const char *b_name[3] = {b->line_a_name, b->line_b_name, b->line_name};
    int a_gpio = a->type == KIOSK_INPUT_GPIO_ENCODER || a->type == KIOSK_INPUT_GPIO_BUTTON;
    int b_gpio = b->type == KIOSK_INPUT_GPIO_ENCODER || b->type == KIOSK_INPUT_GPIO_BUTTON;
    if (!a_gpio || !b_gpio)
        return 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            /* line names are unique across chips on a well-made board */
            if (a_name[i][0] && strcmp(a_name[i], b_name[j]) == 0)
                return 1;
            if (a_off[i] >= 0 && a_off[i] == b_off[j] && strcmp(a->chip, b->chip) == 0)
                return 1;
        }
    return 0;
}

static int check_input(const struct kiosk_config *c, struct error *err, int i)
{
    const struct kiosk_input *in = &c->inputs[i];
    int rc = 0;
    if (in->type == KIOSK_INPUT_HID)
        rc = check_hid(c, err, i);
    else if (in->type == KIOSK_INPUT_GPIO_ENCODER)
        rc = check_gpio_encoder(c, err, i);
    else if (in->type == KIOSK_INPUT_GPIO_BUTTON)
        rc = check_gpio_button(c, err, i);
    if (rc != 0)
        return rc;
    for (int j = 0; j < i; j++)
        if (shares_line(&c->inputs[j], in))
            return bad(c, err, line_of(c, KSEC_INPUT, i, NULL), "[input %s] uses a GPIO line that "
                       "[input %s] already uses", in->name, c->inputs[j].name);
    return 0;
}

/* The log is appended to: a file the kiosk reads (this configuration, a scene, the tour, the font)
 * would take its lines and fail the next start. */
static int check_log(const struct kiosk_config *c, struct error *err)
{
    const struct kiosk_main *k = &c->kiosk;
    if (!k->log[0] || strcmp(k->log, "stderr") == 0)
        return 0;
    const char *what = NULL, *file = NULL;
    if (c->path[0] && output_same(k->log, c->path))
        what = "this configuration", file = c->path;
    for (int i = 0; i < k->n_scenes && !what; i++)
        if (output_same(k->log, k->scenes[i]))
            what = "a scene of the list", file = k->scenes[i];
    if (!what && c->attract.script[0] && output_same(k->log, c->attract.script))
        what = "the attract tour", file = c->attract.script;
    if (!what && k->font[0] && output_same(k->log, k->font))
        what = "the HUD's font", file = k->font;
    if (!what)
        return 0;
    return bad_key(c, err, KSEC_KIOSK, 0, "log", ": %s is %s (%s), which the kiosk reads: log lines would be "
                   "appended to it; name a file of its own, or stderr (the journal)", k->log, what, file);
}

int kiosk_config_check(const struct kiosk_config *c, struct error *err)
{
    memset(err, 0, sizeof *err);
    if (check_kiosk(c, err) != 0 || check_log(c, err) != 0 || check_display(c, err) != 0)
        return -1;
    for (int i = 0; i < c->n_inputs; i++)
        if (check_input(c, err, i) != 0)
            return -1;
    if (check_knob(c, err, KSEC_SPEED) != 0 || check_knob(c, err, KSEC_MASS) != 0)
        return -1;
    for (int i = 0; i < c->n_buttons; i++)
        if (check_button(c, err, i) != 0)
            return -1;
    if (c->attract.enabled && c->attract.script[0] == '\0')
        return bad_key(c, err, KSEC_ATTRACT, 0, "enabled", ": on, but there is no 'script': give the "
                       "tour's file, or set enabled = off");
    return 0;
}
