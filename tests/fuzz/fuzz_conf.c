/* libFuzzer harness: the configuration reader that scene files and the kiosk configuration share
 * (conf/conf_reader.h), the keys' apply function (conf/conf_key.h) and the values both read alike
 * (conf/conf_value.h), on a small schema of the harness's own, so that what they settle for every
 * file kind is fuzzed once, apart from the two schemas (fuzz_scene.c, fuzz_kiosk_config.c).
 *
 * The schema: [shelf] (one, unnamed) with 'label' (text), 'books' (goes on over indented lines,
 * at most 8), 'width' (a number > 0 and < 100), 'count' (an integer from -5 to 5), 'colour' (three
 * numbers), 'finish' (one of matt, gloss); [box NAME] (up to 3) with 'type' (wood or card) first and
 * 'size' (an integer) required.
 *
 * Beyond the sanitizers: every refusal names its place and says why (terminated, non-empty
 * strings); a number the value parser accepts is finite and not a denormal; an integer it accepts
 * is written as decimal digits; a range it accepts holds. */
#include <ctype.h>
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "conf/conf_reader.h"
#include "conf/conf_value.h"
#include "fuzz_input_file.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

enum { SHELF, BOX, KINDS };
#define MAX_BOXES 3
#define MAX_BOOKS 8

struct box {
    char name[CONF_NAME_MAX];
    int type, size;
};

struct store {
    char label[32];
    int n_books, n_boxes, finish;
    double width, colour[3];
    long long count;
    struct box boxes[MAX_BOXES];
};

static struct store store;
static struct error err;

static const char *kind_name(int kind) { return kind == SHELF ? "shelf" : "box"; }
static int kind_named(int kind) { return kind == BOX; }
static const char *kind_list(void) { return "shelf, box NAME"; }
static int name_ok(const char *name) { return strspn(name, "abcdefghijklmnopqrstuvwxyz_-0123456789") == strlen(name); }

/* A number the value parser took: finite, zero or normal, and within the range it checked. */
static void check_number(double x, double lo, double hi, unsigned flags)
{
    if (!isfinite(x) || (x != 0.0 && fabs(x) < DBL_MIN) || !conf_in_range(x, lo, hi, flags))
        __builtin_trap();
}

static int add_book(struct store *s, struct error *e)
{
    if (s->n_books == MAX_BOOKS) {
        error_set(e, ERROR_INPUT, NULL, "at most %d books", MAX_BOOKS);
        return -1;
    }
    s->n_books++;
    return 0;
}

static int set_books(void *owner, void *target, const union conf_parsed *v, struct error *e)
{
    (void)target, (void)v;
    return add_book(owner, e);
}

static int set_width(void *owner, void *target, const union conf_parsed *v, struct error *e)
{
    (void)target, (void)e;
    check_number(v->number, 0.0, 100.0, CONF_ABOVE_LO | CONF_BELOW_HI);
    ((struct store *)owner)->width = v->number;
    return 0;
}

/* the integer parser on the text itself: what it took is decimal digits after an optional minus
 * sign, then blanks at most */
static int set_count(void *owner, void *target, const union conf_parsed *v, struct error *e)
{
    const char *value = v->text;
    long long n;
    (void)target;
    if (conf_parse_integer(value, &n) != 0 || !conf_in_range((double)n, -5.0, 5.0, 0)) {
        error_set(e, ERROR_INPUT, NULL, "expected an integer from -5 to 5");
        return -1;
    }
    size_t d = value[0] == '-';
    if (!isdigit((unsigned char)value[d]))
        __builtin_trap();
    d += strspn(value + d, "0123456789");
    if (value[d + strspn(value + d, " \t\r\n\v\f")] != '\0')
        __builtin_trap();
    ((struct store *)owner)->count = n;
    return 0;
}

static int set_colour(void *owner, void *target, const union conf_parsed *v, struct error *e)
{
    (void)target, (void)e;
    for (int i = 0; i < 3; i++) {
        check_number(v->v[i], -INFINITY, INFINITY, 0);
        ((struct store *)owner)->colour[i] = v->v[i];
    }
    return 0;
}

static const struct conf_choice finishes[] = {{"matt", 0}, {"gloss", 1}, {NULL, 0}};
static const struct conf_choice box_types[] = {{"wood", 0}, {"card", 1}, {NULL, 0}};

static const struct conf_key keys[] = {
    {SHELF, "label", CONF_TEXT, .lo = 0, .hi = 31, .offset = offsetof(struct store, label)},
    {SHELF, "books", CONF_SPECIAL, .set = set_books},
    {SHELF, "width", CONF_NUMBER, .lo = 0.0, .hi = 100.0, .flags = CONF_ABOVE_LO | CONF_BELOW_HI, .set = set_width},
    {SHELF, "count", CONF_SPECIAL, .set = set_count},
    {SHELF, "colour", CONF_VECTOR, .lo = -INFINITY, .hi = INFINITY, .set = set_colour},
    {SHELF, "finish", CONF_CHOICE, .choices = finishes, .offset = offsetof(struct store, finish)},
    {BOX, "type", CONF_CHOICE, .choices = box_types, .flags = CONF_REQUIRED, .offset = offsetof(struct box, type)},
    {BOX, "size", CONF_INTEGER, .lo = -1e9, .hi = 1e9, .flags = CONF_REQUIRED, .offset = offsetof(struct box, size)},
};

static void label(const void *target, int kind, int instance, char *buf, size_t len)
{
    const struct store *s = target;
    if (kind == SHELF)
        snprintf(buf, len, "[shelf]");
    else
        snprintf(buf, len, "[box %s]", s->boxes[instance].name);
}

static void *key_target(void *owner, int kind, int instance)
{
    struct store *s = owner;
    return kind == BOX ? (void *)&s->boxes[instance] : owner;
}
static const char *type_word(int kind) { return kind == BOX ? "box type" : NULL; }
static int type_of(const void *owner, int kind, int instance)
{
    (void)kind;
    return ((const struct store *)owner)->boxes[instance].type;
}
static const char *type_name(int kind, int t)
{
    (void)kind;
    return conf_choice_name(box_types, t);
}

static const struct conf_key_table key_table = {
    .keys = keys, .count = sizeof keys / sizeof keys[0], .name_len = CONF_NAME_MAX, .path_len = 256,
    .label = label, .target = key_target, .type_word = type_word, .type_of = type_of, .type_name = type_name,
};

static int open_section(void *target, int kind, const char *name, int line, int *instance, struct error *e)
{
    struct store *s = target;
    (void)line;
    *instance = 0;
    if (kind == BOX) {
        if (s->n_boxes == MAX_BOXES) {
            error_set(e, ERROR_INPUT, NULL, "at most %d boxes", MAX_BOXES);
            return -1;
        }
        *instance = s->n_boxes++;
        snprintf(s->boxes[*instance].name, sizeof s->boxes[*instance].name, "%s", name);
    }
    return 0;
}

static int continues(int kind, const char *key) { return kind == SHELF && strcmp(key, "books") == 0; }

static int continuation(void *target, int kind, int instance, const char *key, const char *item, struct error *e)
{
    (void)kind, (void)instance, (void)key, (void)item;
    return add_book(target, e);
}

static const struct conf_schema schema = {
    .what = "shelf file",
    .max_bytes = 1L << 16,
    .n_kinds = KINDS,
    .kind_name = kind_name,
    .kind_named = kind_named,
    .kind_list = kind_list,
    .name_ok = name_ok,
    .name_max = CONF_NAME_MAX - 1,
    .keys = &key_table,
    .open = open_section,
    .continues = continues,
    .continuation = continuation,
};

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    tmp_create("conf");
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    tmp_write(data, size);
    memset(&store, 0, sizeof store);
    memset(&err, 0, sizeof err);
    if (conf_read(tmp_path, &schema, &store, &err) != 0) {
        if (memchr(err.where, '\0', sizeof err.where) == NULL || err.where[0] == '\0' ||
            memchr(err.message, '\0', sizeof err.message) == NULL || err.message[0] == '\0')
            __builtin_trap();
    }
    return 0;
}
