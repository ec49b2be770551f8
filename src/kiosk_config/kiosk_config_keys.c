/* The table of kiosk configuration keys. A key is described once here (section, name, kind, range,
 * the input types it belongs to, where it is stored); conf/conf_key.c parses and stores values by
 * this description, so the loader and the checks cannot disagree about a key. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "kiosk_config/kiosk_config_keys.h"
#include "io/text_file.h"

/* ---- choices, and the names of enumerations ------------------------------------------------ */

static const struct conf_choice switch_choices[] = {{"off", 0}, {"on", 1}, {NULL, 0}};
static const struct conf_choice ahead_choices[] = {
    {"auto", KIOSK_AHEAD_AUTO}, {"on", KIOSK_AHEAD_ON}, {"off", KIOSK_AHEAD_OFF}, {NULL, 0}
};
static const struct conf_choice backend_choices[] = {
    {"auto", KIOSK_BACKEND_AUTO}, {"kms", KIOSK_BACKEND_KMS}, {"x11", KIOSK_BACKEND_X11},
    {"headless", KIOSK_BACKEND_HEADLESS}, {NULL, 0}
};
static const struct conf_choice speed_curves[] = {
    {"linear", KIOSK_CURVE_LINEAR}, {"rapidity", KIOSK_CURVE_RAPIDITY}, {NULL, 0}
};
static const struct conf_choice mass_curves[] = {
    {"linear", KIOSK_CURVE_LINEAR}, {"log", KIOSK_CURVE_LOG}, {NULL, 0}
};
#define ACTION_CHOICE(id, name) {name, KIOSK_ACTION_##id},
static const struct conf_choice action_choices[] = {KIOSK_ACTIONS(ACTION_CHOICE) {NULL, 0}};
#undef ACTION_CHOICE
static const struct conf_choice type_choices[] = {
    {"powermate", KIOSK_INPUT_POWERMATE}, {"hid", KIOSK_INPUT_HID},
    {"gpio_encoder", KIOSK_INPUT_GPIO_ENCODER}, {"gpio_button", KIOSK_INPUT_GPIO_BUTTON},
    {"keyboard", KIOSK_INPUT_KEYBOARD}, {"script", KIOSK_INPUT_SCRIPT}, {NULL, 0}
};
static const struct conf_choice axis_mode_choices[] = {
    {"relative", KIOSK_AXIS_RELATIVE}, {"absolute", KIOSK_AXIS_ABSOLUTE}, {NULL, 0}
};
static const struct conf_choice axis_size_choices[] = {{"1", 1}, {"2", 2}, {"4", 4}, {NULL, 0}};
static const struct conf_choice counts_choices[] = {{"1", 1}, {"2", 2}, {"4", 4}, {NULL, 0}};

_Static_assert(sizeof action_choices / sizeof action_choices[0] == KIOSK_ACTION_COUNT + 1,
               "one name per action");
_Static_assert(sizeof type_choices / sizeof type_choices[0] == KIOSK_INPUT_TYPE_COUNT + 1,
               "one name per input type");
/* choices are stored as int into enum fields */
_Static_assert(sizeof(enum kiosk_backend) == sizeof(int) && sizeof(enum kiosk_curve) == sizeof(int) &&
               sizeof(enum kiosk_action) == sizeof(int) && sizeof(enum kiosk_input_type) == sizeof(int) &&
               sizeof(enum kiosk_axis_mode) == sizeof(int), "enums are stored as int");

const char *kiosk_action_name(enum kiosk_action action)
{
    return (unsigned)action < KIOSK_ACTION_COUNT ? action_choices[action].name : "?";
}

const char *kiosk_input_type_name(enum kiosk_input_type type)
{
    return (unsigned)type < KIOSK_INPUT_TYPE_COUNT ? type_choices[type].name : "?";
}

/* ---- sections ---------------------------------------------------------------------------- */

static const struct {
    const char *name;
    int named;
} sections[KSEC_COUNT] = {
    [KSEC_KIOSK] = {"kiosk", 0},
    [KSEC_DISPLAY] = {"display", 0},
    [KSEC_SPEED] = {"speed", 0},
    [KSEC_MASS] = {"mass", 0},
    [KSEC_ATTRACT] = {"attract", 0},
    [KSEC_BUTTON] = {"button", 1},
    [KSEC_INPUT] = {"input", 1},
};

_Static_assert(KSEC_BUTTON == KIOSK_SINGLE_SECTIONS, "single sections come first, one slot each");

const char *kiosk_section_name(enum kiosk_section section) { return sections[section].name; }
int kiosk_section_named(enum kiosk_section section) { return sections[section].named; }

const char *kiosk_section_list(void)
{
    return "kiosk, display, speed, mass, attract, button NAME, input NAME";
}

void kiosk_section_label(const struct kiosk_config *c, enum kiosk_section section, int instance,
                         char *buf, size_t len)
{
    if (section == KSEC_BUTTON)
        snprintf(buf, len, "[button %s]", c->buttons[instance].name);
    else if (section == KSEC_INPUT)
        snprintf(buf, len, "[input %s]", c->inputs[instance].name);
    else
        snprintf(buf, len, "[%s]", sections[section].name);
}

int kiosk_slot(enum kiosk_section section, int instance)
{
    if (section == KSEC_BUTTON)
        return KIOSK_SINGLE_SECTIONS + instance;
    if (section == KSEC_INPUT)
        return KIOSK_SINGLE_SECTIONS + KIOSK_MAX_BUTTONS + instance;
    return (int)section;
}

int kiosk_name_ok(const char *name)
{
    size_t n = strlen(name);
    if (n == 0 || n >= KIOSK_NAME_LEN)
        return 0;
    for (size_t i = 0; i < n; i++) {
        unsigned char ch = (unsigned char)name[i];
        if (!isalnum(ch) && ch != '_' && ch != '-')
            return 0;
    }
    return 1;
}

/* ---- the table ----------------------------------------------------------------------------- */

#define AT_CONFIG(field) offsetof(struct kiosk_config, field)
#define AT_BUTTON(field) offsetof(struct kiosk_button, field)
#define AT_INPUT(field) offsetof(struct kiosk_input, field)
#define FOR(type) (1u << (type))
#define POWERMATE FOR(KIOSK_INPUT_POWERMATE)
#define HID FOR(KIOSK_INPUT_HID)
#define ENCODER FOR(KIOSK_INPUT_GPIO_ENCODER)
#define GPIO_BUTTON FOR(KIOSK_INPUT_GPIO_BUTTON)
#define SCRIPT FOR(KIOSK_INPUT_SCRIPT)

#define SIZE_RANGE .lo = KIOSK_MIN_SIZE, .hi = KIOSK_MAX_SIZE
#define SWITCH .kind = CONF_CHOICE, .choices = switch_choices
#define CHOOSE(list) .kind = CONF_CHOICE, .choices = list
/* GPIO line offsets: far above any real chip's line count, low enough to catch a pin's name typed
 * as a number */
#define GPIO_LINE_MAX 1023
/* HID reports of knobs and button boxes are a few bytes; 64 is a full-speed interrupt packet. */
#define HID_REPORT_MAX 64
/* Raw axis values: whatever a 4-byte field holds, signed or not. */
#define AXIS_RANGE .lo = -2147483648.0, .hi = 4294967295.0
/* Upper bound of a knob's step in any unit: more than a whole range per count is a typo. */
#define KNOB_STEP_MAX 10.0
/* Above the fastest kiosk frame rate; more means nobody would see the preview. */
#define HEADLESS_FRAMES_MAX 1000000

static const char speed_hint[] = "speeds are fractions of c: 0.99 at most (gamma 7); c itself is "
                                 "out of reach for the observer";

/* The two knobs take the same keys with their own ranges and curves. */
#define KNOB_KEYS(sec, knob, top, curves, hint_text)                                                 \
    {sec, "input", CONF_NAME, .offset = AT_CONFIG(knob.input)},                                        \
    {sec, "min", CONF_NUMBER, .lo = 0.0, .hi = top, .flags = CONF_BELOW_HI, .offset = AT_CONFIG(knob.min), \
     .hint = hint_text},                                                                             \
    {sec, "max", CONF_NUMBER, .lo = 0.0, .hi = top, .flags = CONF_ABOVE_LO, .offset = AT_CONFIG(knob.max), \
     .hint = hint_text},                                                                             \
    {sec, "step", CONF_NUMBER, .lo = 0.0, .hi = KNOB_STEP_MAX, .flags = CONF_ABOVE_LO,                   \
     .offset = AT_CONFIG(knob.step)},                                                                \
    {sec, "curve", CHOOSE(curves), .offset = AT_CONFIG(knob.curve)},                                 \
    {sec, "start", CONF_NUMBER, .lo = 0.0, .hi = top, .offset = AT_CONFIG(knob.start), .hint = hint_text}

const struct conf_key kiosk_keys[] = {
    {KSEC_KIOSK, "scenes", CONF_SPECIAL, .set = kiosk_set_scenes},
    {KSEC_KIOSK, "start_scene", CONF_SPECIAL, .set = kiosk_set_start_scene},
    {KSEC_KIOSK, "idle_seconds", CONF_INTEGER, .lo = 10, .hi = 86400, .offset = AT_CONFIG(kiosk.idle_seconds)},
    {KSEC_KIOSK, "preview_width", CONF_INTEGER, SIZE_RANGE, .offset = AT_CONFIG(kiosk.preview_width)},
    {KSEC_KIOSK, "preview_height", CONF_INTEGER, SIZE_RANGE, .offset = AT_CONFIG(kiosk.preview_height)},
    {KSEC_KIOSK, "width", CONF_INTEGER, SIZE_RANGE, .offset = AT_CONFIG(kiosk.width)},
    {KSEC_KIOSK, "height", CONF_INTEGER, SIZE_RANGE, .offset = AT_CONFIG(kiosk.height)},
    {KSEC_KIOSK, "refine_frames", CONF_INTEGER, .lo = 1, .hi = 60, .offset = AT_CONFIG(kiosk.refine_frames)},
    {KSEC_KIOSK, "refine_samples", CONF_INTEGER, .lo = 1, .hi = KIOSK_MAX_REFINE_SAMPLES,
     .offset = AT_CONFIG(kiosk.refine_samples)},
    {KSEC_KIOSK, "preview_rate", CONF_INTEGER, .lo = 0, .hi = 240, .offset = AT_CONFIG(kiosk.preview_rate)},
    {KSEC_KIOSK, "image_memory", CONF_INTEGER, .lo = 1, .hi = 65536, .offset = AT_CONFIG(kiosk.image_memory)},
    {KSEC_KIOSK, "hud", SWITCH, .offset = AT_CONFIG(kiosk.hud)},
    {KSEC_KIOSK, "compile_ahead", CHOOSE(ahead_choices), .offset = AT_CONFIG(kiosk.compile_ahead)},
    {KSEC_KIOSK, "font", CONF_FILE, .offset = AT_CONFIG(kiosk.font)},
    {KSEC_KIOSK, "log", CONF_SPECIAL, .set = kiosk_set_log},
    {KSEC_KIOSK, "assets_root", CONF_DIR, .offset = AT_CONFIG(kiosk.assets_root)},

    {KSEC_DISPLAY, "backend", CHOOSE(backend_choices), .offset = AT_CONFIG(display.backend)},
    {KSEC_DISPLAY, "drm_device", CONF_SPECIAL, .set = kiosk_set_device},
    {KSEC_DISPLAY, "connector", CONF_WORD, .offset = AT_CONFIG(display.connector)},
    {KSEC_DISPLAY, "mode", CONF_SPECIAL, .set = kiosk_set_mode},
    {KSEC_DISPLAY, "vsync", SWITCH, .offset = AT_CONFIG(display.vsync)},
    {KSEC_DISPLAY, "headless_out", CONF_DIR, .offset = AT_CONFIG(display.headless_out)},
    {KSEC_DISPLAY, "headless_frames", CONF_INTEGER, .lo = 0, .hi = HEADLESS_FRAMES_MAX,
     .offset = AT_CONFIG(display.headless_frames)},

    KNOB_KEYS(KSEC_SPEED, speed, KIOSK_SPEED_MAX, speed_curves, speed_hint),
    KNOB_KEYS(KSEC_MASS, mass, KIOSK_MASS_MAX, mass_curves, NULL),

    {KSEC_ATTRACT, "enabled", SWITCH, .offset = AT_CONFIG(attract.enabled)},
    {KSEC_ATTRACT, "script", CONF_FILE, .offset = AT_CONFIG(attract.script)},

    {KSEC_BUTTON, "action", CHOOSE(action_choices), .flags = CONF_REQUIRED, .offset = AT_BUTTON(action)},
    {KSEC_BUTTON, "input", CONF_NAME, .flags = CONF_REQUIRED, .offset = AT_BUTTON(input)},
    {KSEC_BUTTON, "bit", CONF_INTEGER, .lo = 0, .hi = 7, .offset = AT_BUTTON(bit)},

    {KSEC_INPUT, "type", CHOOSE(type_choices), .flags = CONF_REQUIRED, .offset = AT_INPUT(type),
     .set = kiosk_set_input_type},
    /* a name may have one entry per group of types: USB ids are optional for the PowerMate */
    {KSEC_INPUT, "vid", CONF_HEX16, .applies = POWERMATE, .offset = AT_INPUT(vid)},
    {KSEC_INPUT, "vid", CONF_HEX16, .applies = HID, .flags = CONF_REQUIRED, .offset = AT_INPUT(vid)},
    {KSEC_INPUT, "pid", CONF_HEX16, .applies = POWERMATE, .offset = AT_INPUT(pid)},
    {KSEC_INPUT, "pid", CONF_HEX16, .applies = HID, .flags = CONF_REQUIRED, .offset = AT_INPUT(pid)},
    {KSEC_INPUT, "report_id", CONF_INTEGER, .lo = 0, .hi = 255, .applies = HID, .offset = AT_INPUT(report_id)},
    {KSEC_INPUT, "report_length", CONF_INTEGER, .lo = 1, .hi = HID_REPORT_MAX, .applies = HID,
     .offset = AT_INPUT(report_length)},
    {KSEC_INPUT, "axis_offset", CONF_INTEGER, .lo = 0, .hi = HID_REPORT_MAX - 1, .applies = HID,
     .offset = AT_INPUT(axis_offset)},
    {KSEC_INPUT, "axis_size", CHOOSE(axis_size_choices), .applies = HID, .offset = AT_INPUT(axis_size)},
    {KSEC_INPUT, "axis_signed", SWITCH, .applies = HID, .offset = AT_INPUT(axis_signed)},
    {KSEC_INPUT, "axis_mode", CHOOSE(axis_mode_choices), .applies = HID, .offset = AT_INPUT(axis_mode)},
    {KSEC_INPUT, "axis_min", CONF_INT64, AXIS_RANGE, .applies = HID, .offset = AT_INPUT(axis_min)},
    {KSEC_INPUT, "axis_max", CONF_INT64, AXIS_RANGE, .applies = HID, .offset = AT_INPUT(axis_max)},
    {KSEC_INPUT, "button_offset", CONF_INTEGER, .lo = 0, .hi = HID_REPORT_MAX - 1, .applies = HID,
     .offset = AT_INPUT(button_offset)},
    {KSEC_INPUT, "buttons", CONF_INTEGER, .lo = 0, .hi = 8, .applies = HID, .offset = AT_INPUT(buttons)},
    {KSEC_INPUT, "chip", CONF_WORD, .applies = ENCODER | GPIO_BUTTON, .flags = CONF_REQUIRED,
     .offset = AT_INPUT(chip)},
    {KSEC_INPUT, "line_a", CONF_INTEGER, .lo = 0, .hi = GPIO_LINE_MAX, .applies = ENCODER,
     .offset = AT_INPUT(line_a)},
    {KSEC_INPUT, "line_b", CONF_INTEGER, .lo = 0, .hi = GPIO_LINE_MAX, .applies = ENCODER,
     .offset = AT_INPUT(line_b)},
    {KSEC_INPUT, "line_a_name", CONF_WORD, .applies = ENCODER, .offset = AT_INPUT(line_a_name)},
    {KSEC_INPUT, "line_b_name", CONF_WORD, .applies = ENCODER, .offset = AT_INPUT(line_b_name)},
    {KSEC_INPUT, "counts_per_detent", CHOOSE(counts_choices), .applies = ENCODER,
     .offset = AT_INPUT(counts_per_detent)},
    {KSEC_INPUT, "line", CONF_INTEGER, .lo = 0, .hi = GPIO_LINE_MAX, .applies = GPIO_BUTTON,
     .offset = AT_INPUT(line)},
    {KSEC_INPUT, "line_name", CONF_WORD, .applies = GPIO_BUTTON, .offset = AT_INPUT(line_name)},
    {KSEC_INPUT, "active_low", SWITCH, .applies = GPIO_BUTTON, .offset = AT_INPUT(active_low)},
    {KSEC_INPUT, "debounce_ms", CONF_INTEGER, .lo = 1, .hi = 200, .applies = GPIO_BUTTON,
     .offset = AT_INPUT(debounce_ms)},
    {KSEC_INPUT, "path", CONF_FILE, .applies = SCRIPT, .flags = CONF_REQUIRED, .offset = AT_INPUT(path)},
};

const int kiosk_key_count = (int)(sizeof kiosk_keys / sizeof kiosk_keys[0]);
_Static_assert(sizeof kiosk_keys / sizeof kiosk_keys[0] <= KIOSK_KEY_TABLE_MAX,
               "raise KIOSK_KEY_TABLE_MAX");
_Static_assert(KIOSK_INPUT_TYPE_COUNT <= 16, "type masks are unsigned bit sets");

/* ---- what only the kiosk's configuration knows about its keys ------------------------------ */

static void label(const void *owner, int section, int instance, char *buf, size_t len)
{
    kiosk_section_label(owner, (enum kiosk_section)section, instance, buf, len);
}

static void *target(void *owner, int section, int instance)
{
    struct kiosk_config *c = owner;
    if (section == KSEC_BUTTON)
        return &c->buttons[instance];
    if (section == KSEC_INPUT)
        return &c->inputs[instance];
    return c;
}

static const char *type_word(int section)
{
    return section == KSEC_INPUT ? "input type" : NULL;
}

static int type_of(const void *owner, int section, int instance)
{
    (void)section;
    return (int)((const struct kiosk_config *)owner)->inputs[instance].type;
}

static const char *type_name(int section, int t)
{
    (void)section;
    return kiosk_input_type_name((enum kiosk_input_type)t);
}

static int resolve_path(const void *owner, const char *rel, char *out, size_t len)
{
    return kiosk_resolve_path(owner, rel, out, len);
}

const struct conf_key_table kiosk_key_table = {
    .keys = kiosk_keys,
    .count = sizeof kiosk_keys / sizeof kiosk_keys[0],
    .name_len = KIOSK_NAME_LEN,
    .path_len = KIOSK_PATH_LEN,
    .relative_note = KIOSK_RELATIVE_NOTE,
    .label = label,
    .target = target,
    .type_word = type_word,
    .type_of = type_of,
    .type_name = type_name,
    .resolve_path = resolve_path,
};

int kiosk_key_find(enum kiosk_section section, const char *name)
{
    return conf_key_find(&kiosk_key_table, (int)section, name);
}

int kiosk_key_line(const struct kiosk_config *c, enum kiosk_section section, int instance,
                   const char *name)
{
    int key = kiosk_key_find(section, name);
    return key < 0 ? 0 : c->source.key[kiosk_slot(section, instance)][key];
}

/* ---- defaults: the values kiosk/kiosk.conf documents; change both together ----------------- */

void kiosk_config_defaults(struct kiosk_config *c)
{
    memset(c, 0, sizeof *c);
    c->kiosk.idle_seconds = 120;
    c->kiosk.preview_width = 320;
    c->kiosk.preview_height = 180;
    c->kiosk.width = 1280;
    c->kiosk.height = 720;
    c->kiosk.refine_frames = 4;
    c->kiosk.refine_samples = 4;
    c->kiosk.preview_rate = 30;
    c->kiosk.image_memory = KIOSK_IMAGE_MEMORY_MB;
    c->kiosk.hud = 1;
    snprintf(c->kiosk.font, sizeof c->kiosk.font, "%s", KIOSK_DEFAULT_FONT);
    snprintf(c->kiosk.log, sizeof c->kiosk.log, "stderr");
    c->display.backend = KIOSK_BACKEND_AUTO;
    c->display.vsync = 1;
    /* speed: from rest to 0.99 c (gamma 7) in about 2.65 / 0.05 = 53 counts */
    c->speed.max = 0.99;
    c->speed.step = 0.05;
    c->speed.curve = KIOSK_CURVE_RAPIDITY;
    c->mass.max = 10.0;
    c->mass.step = 0.1;
    c->mass.curve = KIOSK_CURVE_LINEAR;
}

void kiosk_button_defaults(struct kiosk_button *b, const char *name)
{
    memset(b, 0, sizeof *b);
    snprintf(b->name, sizeof b->name, "%s", name);
    b->bit = -1;
}

/* HID: a one-byte relative knob and no buttons until the file says more. The PowerMate's USB ids
 * are set with its type. */
void kiosk_input_defaults(struct kiosk_input *in, const char *name)
{
    memset(in, 0, sizeof *in);
    snprintf(in->name, sizeof in->name, "%s", name);
    in->type = KIOSK_INPUT_KEYBOARD;
    in->report_length = 8;
    in->axis_size = 1;
    in->axis_signed = 1;
    in->axis_mode = KIOSK_AXIS_RELATIVE;
    in->line_a = in->line_b = in->line = -1;
    in->counts_per_detent = 4;
    in->active_low = 1;
    in->debounce_ms = 20;
}
