/* Applying a value to a key as its table's table describes it, and the message when that cannot
 * be done: what is wrong, what was expected, the value as written. */
#include <ctype.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "conf/conf_key.h"
#include "conf/conf_path.h"
#include "io/text_file.h"

/* A near miss of a real name within this many edits is nearly always a typo. */
#define GUESS_MAX_EDITS 2
/* USB vendor and product ids are 16 bits. */
#define HEX16_MAX 0xffff
/* Room for a path in a reason, and for the reason in a message. */
#define REASON_LEN 4608
/* Room for a message with its key, section and reason, cut to struct error's when it is set. */
#define MESSAGE_ROOM (REASON_LEN + 512)

/* ---- finding a key ------------------------------------------------------------------------- */

int conf_key_find(const struct conf_key_table *table, int section, const char *name)
{
    for (int i = 0; i < table->count; i++)
        if (table->keys[i].section == section && strcmp(table->keys[i].name, name) == 0)
            return i;
    return -1;
}

/* The type bit of a section instance, 0 for sections without types. */
static unsigned type_bit(const struct conf_key_table *table, const void *owner, int section, int instance)
{
    if (!table->type_word || !table->type_word(section))
        return 0;
    return 1u << table->type_of(owner, section, instance);
}

static int applies_to(const struct conf_key *k, unsigned bit)
{
    return k->applies == 0 || bit == 0 || (k->applies & bit);
}

static const struct conf_key *applicable(const struct conf_key_table *table, int first, unsigned bit)
{
    const struct conf_key *f = &table->keys[first];
    for (int i = first; i < table->count; i++) {
        const struct conf_key *k = &table->keys[i];
        if (k->section == f->section && strcmp(k->name, f->name) == 0 && applies_to(k, bit))
            return k;
    }
    return NULL;
}

const struct conf_key *conf_key_for(const struct conf_key_table *table, const void *owner, int section,
                                    int instance, const char *name)
{
    int first = conf_key_find(table, section, name);
    return first < 0 ? NULL : applicable(table, first, type_bit(table, owner, section, instance));
}

/* Keys of the instance's own type are preferred: "axis_sise" on a PowerMate still points at the key
 * that exists, and the next message then says it does not apply. */
static const char *closest_key(const struct conf_key_table *table, int section, const char *name, unsigned bit)
{
    const char *best = NULL;
    int best_d = GUESS_MAX_EDITS + 1, best_fits = 0;
    for (int i = 0; i < table->count; i++) {
        const struct conf_key *k = &table->keys[i];
        if (k->section != section)
            continue;
        int d = edit_distance(name, k->name, table->name_len), fits = applies_to(k, bit);
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

/* "lorenz, rossler": the types that have key NAME, for a key used with the wrong type. */
static void list_owners(const struct conf_key_table *table, int section, const char *name, char *buf, size_t len)
{
    unsigned mask = 0;
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < table->count; i++)
        if (table->keys[i].section == section && strcmp(table->keys[i].name, name) == 0)
            mask |= table->keys[i].applies;
    for (int t = 0; t < 16 && used < len; t++)
        if (mask & (1u << t))
            used += (size_t)snprintf(buf + used, len - used, "%s%s", used ? ", " : "",
                                     table->type_name(section, t));
}

/* ---- parsing ------------------------------------------------------------------------------- */

static int in_range(const struct conf_key *k, double x)
{
    return conf_in_range(x, k->lo, k->hi, k->flags);
}

/* COUNT numbers as every configuration reads them (conf/conf_value.h), each within the table's
 * limit. */
static int parse_numbers(const struct conf_key_table *table, const char *text, double *out, int count,
                         const char **why)
{
    if (conf_parse_numbers(text, out, count, why) != 0)
        return -1;
    for (int i = 0; i < count; i++)
        if (table->max_abs > 0.0 && fabs(out[i]) > table->max_abs) {
            *why = table->max_abs_reason;
            return -1;
        }
    return 0;
}

/* "0x077d": the prefix is required, so that 0410 cannot be read as decimal 410. */
static int parse_hex16(const char *text, int *out)
{
    size_t n = strlen(text);
    if (n < 3 || n > 6 || text[0] != '0' || (text[1] != 'x' && text[1] != 'X'))
        return -1;
    for (size_t i = 2; i < n; i++)
        if (!isxdigit((unsigned char)text[i]))
            return -1;
    long x = strtol(text + 2, NULL, 16);
    if (x > HEX16_MAX)
        return -1;
    *out = (int)x;
    return 0;
}

static int name_ok(const char *text, size_t name_len, int any_graph)
{
    size_t n = strlen(text);
    if (n == 0 || n >= name_len)
        return 0;
    for (size_t i = 0; i < n; i++) {
        unsigned char ch = (unsigned char)text[i];
        if (any_graph ? !isgraph(ch) : !isalnum(ch) && ch != '_' && ch != '-')
            return 0;
    }
    return 1;
}

/* TEXT as K's kind says, into v (PATH holds the joined path of FILE and DIR keys). -1 when it is
 * not that; *why may then say more than the expected form. */
static int parse_value(const struct conf_key_table *table, const void *owner, const struct conf_key *k,
                       const char *text, union conf_parsed *v, char *path, const char **why)
{
    long long x;
    size_t n = strlen(text);
    switch (k->kind) {
    case CONF_NUMBER:
        return parse_numbers(table, text, &v->number, 1, why) == 0 && in_range(k, v->number) ? 0 : -1;
    case CONF_INTEGER:
        if (conf_parse_integer(text, &x) != 0 || x < -2147483647LL - 1 || x > 2147483647LL ||
            !in_range(k, (double)x))
            return -1;
        v->integer = (int)x;
        return 0;
    case CONF_INT64:
        if (conf_parse_integer(text, &x) != 0 || !in_range(k, (double)x))
            return -1;
        v->int64 = (int64_t)x;
        return 0;
    case CONF_VECTOR:
        if (parse_numbers(table, text, v->v, 3, why) != 0)
            return -1;
        return (k->flags & CONF_NONZERO) && v->v[0] == 0.0 && v->v[1] == 0.0 && v->v[2] == 0.0 ? -1 : 0;
    case CONF_COLOR:
        if (parse_numbers(table, text, v->v, 3, why) != 0)
            return -1;
        for (int i = 0; i < 3; i++)
            if (!in_range(k, v->v[i]))
                return -1;
        return 0;
    case CONF_TEXCOORD:
        return parse_numbers(table, text, v->v, 2, why);
    case CONF_CHOICE:
        for (int i = 0; k->choices[i].name; i++)
            if (strcmp(k->choices[i].name, text) == 0) {
                v->integer = k->choices[i].value;
                return 0;
            }
        return -1;
    case CONF_HEX16:
        return parse_hex16(text, &v->integer);
    case CONF_NAME:
    case CONF_WORD:
        v->text = text;
        return name_ok(text, table->name_len, k->kind == CONF_WORD) ? 0 : -1;
    case CONF_TEXT:
        v->text = text;
        return n >= (size_t)k->lo && n <= (size_t)k->hi ? 0 : -1;
    case CONF_PATH:
        v->text = text;
        return n > 0 && n < table->path_len ? 0 : -1;
    case CONF_SPECIAL:
        v->text = text;  /* the setter reads it, however long (a list of scenes) */
        return 0;
    case CONF_FILE:
    case CONF_DIR:
        v->text = path;
        return n > 0 && table->resolve_path(owner, text, path, table->path_len) == 0 ? 0 : -1;
    }
    return -1;
}

/* The field copy of a key without a setter. */
static void store_value(const struct conf_key *k, void *target, const union conf_parsed *v)
{
    char *field = (char *)target + k->offset;
    switch (k->kind) {
    case CONF_NUMBER:
        memcpy(field, &v->number, sizeof v->number);
        break;
    case CONF_INTEGER:
    case CONF_CHOICE:
    case CONF_HEX16:
        memcpy(field, &v->integer, sizeof v->integer);
        break;
    case CONF_INT64:
        memcpy(field, &v->int64, sizeof v->int64);
        break;
    case CONF_VECTOR:
    case CONF_COLOR:
        memcpy(field, v->v, 3 * sizeof v->v[0]);
        break;
    case CONF_TEXCOORD:
        memcpy(field, v->v, 2 * sizeof v->v[0]);
        break;
    case CONF_NAME:
    case CONF_WORD:
    case CONF_TEXT:
    case CONF_PATH:
    case CONF_FILE:
    case CONF_DIR:
        memcpy(field, v->text, strlen(v->text) + 1);
        break;
    case CONF_SPECIAL:
        break;  /* always has a setter */
    }
}

/* ---- messages ------------------------------------------------------------------------------ */

void conf_key_expected(const struct conf_key_table *table, const struct conf_key *k, char *buf, size_t len)
{
    char range[96];
    size_t used;
    conf_describe_range(k->lo, k->hi, k->flags, range, sizeof range);
    switch (k->kind) {
    case CONF_NUMBER:
        snprintf(buf, len, "a number%s", range);
        break;
    case CONF_INTEGER:
    case CONF_INT64:
        snprintf(buf, len, "an integer%s", range);
        break;
    case CONF_VECTOR:
        snprintf(buf, len, "3 numbers \"x y z\"%s", k->flags & CONF_NONZERO ? ", not all zero" : "");
        break;
    case CONF_COLOR:
        snprintf(buf, len, "3 numbers \"r g b\", each%s", range);
        break;
    case CONF_TEXCOORD:
        snprintf(buf, len, "2 numbers \"u v\"");
        break;
    case CONF_CHOICE:
        used = (size_t)snprintf(buf, len, "one of");
        for (int i = 0; k->choices[i].name && used < len; i++)
            used += (size_t)snprintf(buf + used, len - used, "%s %s", i ? "," : "", k->choices[i].name);
        break;
    case CONF_HEX16:
        snprintf(buf, len, "a hexadecimal number from 0x0000 to 0xffff, written with 0x");
        break;
    case CONF_NAME:
        snprintf(buf, len, "a section name: 1 to %zu letters, digits, '_' or '-'", table->name_len - 1);
        break;
    case CONF_WORD:
        snprintf(buf, len, "1 to %zu characters without blanks", table->name_len - 1);
        break;
    case CONF_TEXT:
        if (k->lo > 0)
            snprintf(buf, len, "text of %g to %g characters", k->lo, k->hi);
        else
            snprintf(buf, len, "text of at most %g characters", k->hi);
        break;
    case CONF_PATH:
    case CONF_FILE:
    case CONF_DIR:
    case CONF_SPECIAL:
        snprintf(buf, len, "a path of 1 to %zu characters", table->path_len - 1);
        break;
    }
}

const char *conf_choice_name(const struct conf_choice *choices, int value)
{
    for (int i = 0; choices[i].name; i++)
        if (choices[i].value == value)
            return choices[i].name;
    return "?";
}

/* ---- applying ------------------------------------------------------------------------------ */

/* The key of NAME for the section instance, or -1 with the message that says why there is none. */
static const struct conf_key *key_or_message(const struct conf_key_table *table, const void *owner, int section,
                                             int instance, const char *name, const char *label,
                                             char *msg, size_t msg_len)
{
    unsigned bit = type_bit(table, owner, section, instance);
    int first = conf_key_find(table, section, name);
    if (first < 0) {
        const char *guess = closest_key(table, section, name, bit);
        if (guess)
            snprintf(msg, msg_len, "unknown key '%s' in %s (did you mean '%s'?)", name, label, guess);
        else
            snprintf(msg, msg_len, "unknown key '%s' in %s", name, label);
        return NULL;
    }
    const struct conf_key *k = applicable(table, first, bit);
    if (!k) {
        char owners[128];
        int t = table->type_of(owner, section, instance);
        list_owners(table, section, name, owners, sizeof owners);
        snprintf(msg, msg_len, "key '%s' in %s does not apply to %s '%s' (only to %s)", name, label,
                 table->type_word(section), table->type_name(section, t), owners);
    }
    return k;
}

/* The setter, or the field copy and the check of what a FILE or DIR names. */
static int store(const struct conf_key_table *table, void *owner, void *target, const struct conf_key *k,
                 const union conf_parsed *v, struct error *e)
{
    if (k->set)
        return k->set(owner, target, v, e);
    /* what a path names is looked at now, so the message can point at this line */
    if (k->kind == CONF_FILE && conf_check_file(v->text, table->relative_note, e) != 0)
        return -1;
    if (k->kind == CONF_DIR && conf_check_dir(v->text, table->relative_note, e) != 0)
        return -1;
    store_value(k, target, v);
    return 0;
}

/* conf_key_apply's message into msg */
static int apply_text(const struct conf_key_table *table, void *owner, int section, int instance,
                      const char *name, const char *value, char *msg, size_t msg_len)
{
    char label[160], expected[192], path[REASON_LEN];
    struct error reason;
    const char *why = NULL;
    union conf_parsed v;

    table->label(owner, section, instance, label, sizeof label);
    const struct conf_key *k = key_or_message(table, owner, section, instance, name, label, msg, msg_len);
    if (!k)
        return -1;
    if (*value == '\0' && !(k->kind == CONF_TEXT && k->lo == 0)) {
        snprintf(msg, msg_len, "key '%s' in %s has an empty value: give one, or leave the key out "
                 "(comment it out) for its default", name, label);
        return -1;
    }
    if (table->path_len > sizeof path)
        return snprintf(msg, msg_len, "key '%s' in %s: paths of the table are too long", name, label), -1;
    if (parse_value(table, owner, k, value, &v, path, &why) != 0) {
        char quoted[CONF_QUOTE_MAX + 8];
        conf_key_expected(table, k, expected, sizeof expected);
        conf_quote(value, quoted, sizeof quoted);
        snprintf(msg, msg_len, "key '%s' in %s: expected %s, got %s%s%s%s%s%s", name, label, expected, quoted,
                 why ? " (" : "", why ? why : "", why ? ")" : "", k->hint && !why ? ": " : "",
                 k->hint && !why ? k->hint : "");
        if (strchr(value, '#'))
            snprintf(msg + strlen(msg), msg_len - strlen(msg),
                     " (a comment after a value starts with ' ;', not '#')");
        return -1;
    }
    error_clear(&reason);
    if (store(table, owner, table->target(owner, section, instance), k, &v, &reason) != 0) {
        snprintf(msg, msg_len, "key '%s' in %s: %s", name, label, reason.message);
        return -1;
    }
    return 0;
}

int conf_key_apply(const struct conf_key_table *table, void *owner, int section, int instance,
                   const char *name, const char *value, struct error *e)
{
    char msg[MESSAGE_ROOM];
    if (apply_text(table, owner, section, instance, name, value, msg, sizeof msg) != 0)
        return error_set(e, ERROR_INPUT, NULL, "%s", msg);
    return 0;
}

/* conf_key_apply_number's message into msg */
static int apply_number_text(const struct conf_key_table *table, void *owner, int section, int instance,
                             const char *name, double value, char *msg, size_t msg_len)
{
    char label[160];
    struct error reason;
    table->label(owner, section, instance, label, sizeof label);
    const struct conf_key *k = key_or_message(table, owner, section, instance, name, label, msg, msg_len);
    if (!k)
        return -1;
    if (k->kind != CONF_NUMBER) {
        snprintf(msg, msg_len, "key '%s' in %s is not a number", name, label);
        return -1;
    }
    /* what parse_value checks of a number written in a file */
    const char *why = !isfinite(value)                                         ? "not a finite number"
                      : table->max_abs > 0.0 && fabs(value) > table->max_abs ? table->max_abs_reason
                      : value != 0.0 && fabs(value) < DBL_MIN                  ? "too large or too small for a double"
                                                                               : NULL;
    if (why || !in_range(k, value)) {
        char expected[192];
        conf_key_expected(table, k, expected, sizeof expected);
        snprintf(msg, msg_len, "key '%s' in %s: expected %s, got %.17g%s%s%s", name, label, expected, value,
                 why ? " (" : "", why ? why : "", why ? ")" : "");
        return -1;
    }
    union conf_parsed v = {.number = value};
    error_clear(&reason);
    if (store(table, owner, table->target(owner, section, instance), k, &v, &reason) != 0) {
        snprintf(msg, msg_len, "key '%s' in %s: %s", name, label, reason.message);
        return -1;
    }
    return 0;
}

int conf_key_apply_number(const struct conf_key_table *table, void *owner, int section, int instance,
                          const char *name, double value, struct error *e)
{
    char msg[MESSAGE_ROOM];
    if (apply_number_text(table, owner, section, instance, name, value, msg, sizeof msg) != 0)
        return error_set(e, ERROR_INPUT, NULL, "%s", msg);
    return 0;
}

/* "'type = sphere', 'triangle', 'disk' or 'rect'" */
static void describe_types(const struct conf_key *type, char *buf, size_t len)
{
    size_t used = 0;
    int n = 0;
    while (type->choices[n].name)
        n++;
    buf[0] = '\0';
    for (int i = 0; i < n && used < len; i++)
        used += (size_t)snprintf(buf + used, len - used, "%s'%s%s'", i == 0 ? "" : i == n - 1 ? " or " : ", ",
                                 i == 0 ? "type = " : "", type->choices[i].name);
}

/* conf_key_check_required's message into msg */
static int check_required_text(const struct conf_key_table *table, const void *owner, int section, int instance,
                               const int *key_line, char *msg, size_t msg_len)
{
    char label[160];
    table->label(owner, section, instance, label, sizeof label);
    int typed = table->type_word && table->type_word(section);
    int type = conf_key_find(table, section, "type");
    /* before its type is known, the keys a section needs are not */
    if (typed && type >= 0 && (table->keys[type].flags & CONF_REQUIRED) && key_line[type] == 0) {
        char types[256] = "";
        if (table->keys[type].kind == CONF_CHOICE)
            describe_types(&table->keys[type], types, sizeof types);
        snprintf(msg, msg_len, "%s has no type%s%s", label, *types ? ": add " : "", types);
        return -1;
    }
    unsigned bit = type_bit(table, owner, section, instance);
    for (int i = 0; i < table->count; i++) {
        const struct conf_key *k = &table->keys[i];
        if (k->section != section || !(k->flags & CONF_REQUIRED) || !applies_to(k, bit) ||
            key_line[conf_key_find(table, section, k->name)] != 0)
            continue;
        if (typed)
            snprintf(msg, msg_len, "%s of type '%s' needs '%s'", label,
                     table->type_name(section, table->type_of(owner, section, instance)), k->name);
        else
            snprintf(msg, msg_len, "%s needs '%s'", label, k->name);
        return -1;
    }
    return 0;
}

int conf_key_check_required(const struct conf_key_table *table, const void *owner, int section, int instance,
                            const int *key_line, struct error *e)
{
    char msg[MESSAGE_ROOM];
    if (check_required_text(table, owner, section, instance, key_line, msg, sizeof msg) != 0)
        return error_set(e, ERROR_INPUT, NULL, "%s", msg);
    return 0;
}
