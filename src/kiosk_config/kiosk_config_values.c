/* Parsing and storing one value as the key table describes it, and the message when it cannot be:
 * what is wrong, what was expected, the value as written. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "kiosk_config/kiosk_config_keys.h"
#include "io/text_file.h"

/* Values are quoted back as given, shortened: a whole line of junk helps nobody. */

/* A near miss of a real name within this many edits is nearly always a typo. */
#define GUESS_MAX_EDITS 2
/* USB vendor and product ids are 16 bits. */
#define USB_ID_MAX 0xffff

/* ---- numbers ------------------------------------------------------------------------------- */

/* Numbers and integers as every configuration reads them (conf/conf_value.h). */
static int parse_int64(const char *text, int64_t *out)
{
    long long x;
    if (conf_parse_integer(text, &x) != 0)
        return -1;
    *out = (int64_t)x;
    return 0;
}

static int parse_number(const char *text, double *out, const char **why)
{
    return conf_parse_numbers(text, out, 1, why);
}

/* "0x077d": the prefix is required, so that 0410 cannot be read as decimal 410. */
static int parse_hex(const char *text, int *out)
{
    size_t n = strlen(text);
    long x;
    if (n < 3 || n > 6 || text[0] != '0' || (text[1] != 'x' && text[1] != 'X'))
        return -1;
    for (size_t i = 2; i < n; i++)
        if (!isxdigit((unsigned char)text[i]))
            return -1;
    x = strtol(text + 2, NULL, 16);
    if (x > USB_ID_MAX)
        return -1;
    *out = (int)x;
    return 0;
}

static int in_range(const struct kiosk_key *k, double x)
{
    return conf_in_range(x, k->lo, k->hi, k->flags);
}

static int word_ok(const char *text)
{
    size_t n = strlen(text);
    if (n == 0 || n >= KIOSK_NAME_LEN)
        return 0;
    for (size_t i = 0; i < n; i++)
        if (!isgraph((unsigned char)text[i]))
            return 0;
    return 1;
}

/* ---- messages ------------------------------------------------------------------------------ */

static void describe_range(const struct kiosk_key *k, char *buf, size_t len)
{
    conf_describe_range(k->lo, k->hi, k->flags, buf, len);
}

static void describe_expected(const struct kiosk_key *k, char *buf, size_t len)
{
    char range[96];
    size_t used;
    describe_range(k, range, sizeof range);
    switch (k->kind) {
    case KK_INT:
    case KK_INT64:
        snprintf(buf, len, "an integer%s", range);
        break;
    case KK_NUMBER:
        snprintf(buf, len, "a number%s", range);
        break;
    case KK_CHOICE:
        used = (size_t)snprintf(buf, len, "one of");
        for (int i = 0; k->choices[i].name && used < len; i++)
            used += (size_t)snprintf(buf + used, len - used, "%s %s", i ? "," : "", k->choices[i].name);
        break;
    case KK_HEX:
        snprintf(buf, len, "a hexadecimal number from 0x0000 to 0xffff, written with 0x");
        break;
    case KK_NAME:
        snprintf(buf, len, "a section name: 1 to %d letters, digits, '_' or '-'", KIOSK_NAME_LEN - 1);
        break;
    case KK_WORD:
        snprintf(buf, len, "1 to %d characters without blanks", KIOSK_NAME_LEN - 1);
        break;
    case KK_FILE:
    case KK_DIR:
    case KK_SPECIAL:
        snprintf(buf, len, "a path of 1 to %d characters", KIOSK_PATH_LEN - 1);
        break;
    }
}

static int applies_to(const struct kiosk_key *k, unsigned type_bit)
{
    return k->applies == 0 || type_bit == 0 || (k->applies & type_bit);
}

/* Keys of the input's own type are preferred: "axis_sise" on a PowerMate still points at the key
 * that exists, and the next message then says it does not apply. */
static const char *closest_key(enum kiosk_section section, const char *name, unsigned type_bit)
{
    const char *best = NULL;
    int best_d = GUESS_MAX_EDITS + 1, best_fits = 0;
    for (int i = 0; i < kiosk_key_count; i++) {
        const struct kiosk_key *k = &kiosk_keys[i];
        if (k->section != section)
            continue;
        int d = edit_distance(name, k->name, KIOSK_NAME_LEN), fits = applies_to(k, type_bit);
        if (d > GUESS_MAX_EDITS || (size_t)d >= strlen(name))
            continue;
        if (d < best_d || (d == best_d && fits && !best_fits)) {
            best_d = d;
            best = k->name;
            best_fits = fits;
        }
    }
    return best;
}

/* "hid, gpio_encoder": the input types that have key NAME. */
static void list_owners(const char *name, char *buf, size_t len)
{
    unsigned mask = 0;
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < kiosk_key_count; i++)
        if (kiosk_keys[i].section == KSEC_INPUT && strcmp(kiosk_keys[i].name, name) == 0)
            mask |= kiosk_keys[i].applies;
    for (int t = 0; t < KIOSK_INPUT_TYPE_COUNT && used < len; t++)
        if (mask & (1u << t))
            used += (size_t)snprintf(buf + used, len - used, "%s%s", used ? ", " : "",
                                     kiosk_input_type_name((enum kiosk_input_type)t));
}

/* The entry of NAME that fits the input's type; NULL if none does. */
static const struct kiosk_key *applicable_key(int first, unsigned type_bit)
{
    for (int i = first; i < kiosk_key_count; i++) {
        const struct kiosk_key *k = &kiosk_keys[i];
        if (k->section == kiosk_keys[first].section && strcmp(k->name, kiosk_keys[first].name) == 0 &&
            applies_to(k, type_bit))
            return k;
    }
    return NULL;
}

static unsigned section_type_bit(const struct kiosk_config *c, enum kiosk_section section, int instance)
{
    return section == KSEC_INPUT ? 1u << c->inputs[instance].type : 0;
}

/* ---- storing ------------------------------------------------------------------------------- */

/* Parses TEXT as K says and stores it at FIELD. -1 leaves the field as it was. */
static int parse_store(const struct kiosk_key *k, struct kiosk_config *c, void *target, const char *text,
                       const char **why)
{
    char *field = (char *)target + k->offset;
    char path[KIOSK_PATH_LEN];
    int64_t i64;
    double x;
    int i;

    switch (k->kind) {
    case KK_INT:
    case KK_INT64:
        if (parse_int64(text, &i64) != 0 || !in_range(k, (double)i64))
            return -1;
        if (k->kind == KK_INT) {
            i = (int)i64;
            memcpy(field, &i, sizeof i);
        } else {
            memcpy(field, &i64, sizeof i64);
        }
        return 0;
    case KK_NUMBER:
        if (parse_number(text, &x, why) != 0 || !in_range(k, x))
            return -1;
        memcpy(field, &x, sizeof x);
        return 0;
    case KK_CHOICE:
        for (int j = 0; k->choices[j].name; j++) {
            if (strcmp(k->choices[j].name, text) == 0) {
                memcpy(field, &k->choices[j].value, sizeof(int));
                return 0;
            }
        }
        return -1;
    case KK_HEX:
        if (parse_hex(text, &i) != 0)
            return -1;
        memcpy(field, &i, sizeof i);
        return 0;
    case KK_NAME:
    case KK_WORD:
        if (k->kind == KK_NAME ? !kiosk_name_ok(text) : !word_ok(text))
            return -1;
        memcpy(field, text, strlen(text) + 1);
        return 0;
    case KK_FILE:
    case KK_DIR:
        if (kiosk_resolve_path(c, text, path, sizeof path) != 0)
            return -1;
        memcpy(field, path, strlen(path) + 1);
        return 0;
    case KK_SPECIAL:
        break;
    }
    return -1;
}

int kiosk_key_apply(struct kiosk_config *c, enum kiosk_section section, int instance,
                    const char *name, const char *value, char *msg, size_t msg_len)
{
    char label[KIOSK_NAME_LEN + 16], expected[192], reason[KIOSK_PATH_LEN + 192];
    unsigned type_bit = section_type_bit(c, section, instance);
    const char *why = NULL;
    const struct kiosk_key *k;
    void *target = c;
    int first;

    kiosk_section_label(c, section, instance, label, sizeof label);
    first = kiosk_key_find(section, name);
    if (first < 0) {
        const char *guess = closest_key(section, name, type_bit);
        if (guess)
            snprintf(msg, msg_len, "unknown key '%s' in %s (did you mean '%s'?)", name, label, guess);
        else
            snprintf(msg, msg_len, "unknown key '%s' in %s", name, label);
        return -1;
    }
    k = applicable_key(first, type_bit);
    if (!k) {
        char owners[128];
        list_owners(name, owners, sizeof owners);
        snprintf(msg, msg_len, "key '%s' in %s does not apply to input type '%s' (only to %s)", name,
                 label, kiosk_input_type_name(c->inputs[instance].type), owners);
        return -1;
    }
    if (*value == '\0') {
        snprintf(msg, msg_len, "key '%s' in %s has an empty value: give one, or leave the key out "
                 "(comment it out) for its default", name, label);
        return -1;
    }
    if (section == KSEC_BUTTON)
        target = &c->buttons[instance];
    else if (section == KSEC_INPUT)
        target = &c->inputs[instance];

    reason[0] = '\0';
    if (k->kind == KK_SPECIAL) {
        if (k->set(c, target, value, reason, sizeof reason) != 0)
            goto refused;
        return 0;
    }
    if (parse_store(k, c, target, value, &why) != 0) {
        char quoted[CONF_QUOTE_MAX + 8];
        describe_expected(k, expected, sizeof expected);
        conf_quote(value, quoted, sizeof quoted);
        snprintf(msg, msg_len, "key '%s' in %s: expected %s, got %s%s%s%s%s%s", name, label, expected, quoted,
                 why ? " (" : "", why ? why : "", why ? ")" : "",
                 k->hint && !why ? ": " : "", k->hint && !why ? k->hint : "");
        if (strchr(value, '#'))
            snprintf(msg + strlen(msg), msg_len - strlen(msg),
                     " (a comment after a value starts with ' ;', not '#')");
        return -1;
    }
    /* paths are stored joined with the config's directory; what is there is checked now, so the
     * message can point at this line */
    if (k->kind == KK_FILE && kiosk_check_file((char *)target + k->offset, reason, sizeof reason) != 0)
        goto refused;
    if (k->kind == KK_DIR && kiosk_check_dir((char *)target + k->offset, reason, sizeof reason) != 0)
        goto refused;
    if (k->set && k->set(c, target, value, reason, sizeof reason) != 0)
        goto refused;
    return 0;

refused:
    snprintf(msg, msg_len, "key '%s' in %s: %s", name, label, reason);
    return -1;
}

const char *kiosk_key_missing(const struct kiosk_config *c, enum kiosk_section section, int instance)
{
    unsigned type_bit = section_type_bit(c, section, instance);
    for (int i = 0; i < kiosk_key_count; i++) {
        const struct kiosk_key *k = &kiosk_keys[i];
        if (k->section != section || !(k->flags & CONF_REQUIRED) || !applies_to(k, type_bit))
            continue;
        if (kiosk_key_line(c, section, instance, k->name) == 0)
            return k->name;
    }
    return NULL;
}

/* ---- setters ------------------------------------------------------------------------------- */

/* Resolved once the whole file is read, since [kiosk] scenes may come after it. */
int kiosk_set_start_scene(struct kiosk_config *c, void *t, const char *value, char *reason, size_t len)
{
    (void)t;
    if (!word_ok(value)) {
        snprintf(reason, len, "expected a scene's index (0 is the first) or its name, got \"%.*s\"",
                 CONF_QUOTE_MAX, value);
        return -1;
    }
    snprintf(c->kiosk.start_scene_name, sizeof c->kiosk.start_scene_name, "%s", value);
    return 0;
}

/* "1920x1080" */
int kiosk_set_mode(struct kiosk_config *c, void *t, const char *value, char *reason, size_t len)
{
    char *x, *end = NULL;
    long w = 0, h = 0;
    (void)t;
    if (isdigit((unsigned char)value[0])) {
        w = strtol(value, &x, 10);
        if (*x == 'x' && isdigit((unsigned char)x[1]))
            h = strtol(x + 1, &end, 10);
    }
    if (!end || *end != '\0' || w < KIOSK_MIN_SIZE || w > KIOSK_MAX_SIZE || h < KIOSK_MIN_SIZE ||
        h > KIOSK_MAX_SIZE) {
        snprintf(reason, len, "expected WIDTHxHEIGHT such as 1920x1080, each from %d to %d, got "
                 "\"%.*s\"", KIOSK_MIN_SIZE, KIOSK_MAX_SIZE, CONF_QUOTE_MAX, value);
        return -1;
    }
    c->display.mode_width = (int)w;
    c->display.mode_height = (int)h;
    return 0;
}

/* Each type starts from its own defaults: the PowerMate's USB ids. */
int kiosk_set_input_type(struct kiosk_config *c, void *t, const char *value, char *reason, size_t len)
{
    struct kiosk_input *in = t;
    (void)c, (void)value, (void)reason, (void)len;
    if (in->type == KIOSK_INPUT_POWERMATE) {
        in->vid = KIOSK_POWERMATE_VID;
        in->pid = KIOSK_POWERMATE_PID;
    }
    return 0;
}
