/* libFuzzer harness: the configuration reader that scene files and the kiosk configuration share
 * (conf/conf_reader.h), and the values both read alike (conf/conf_value.h), on a small schema of
 * the harness's own, so that what the reader settles for every file kind is fuzzed once, apart
 * from the two schemas (fuzz_scene.c, fuzz_kiosk_config.c).
 *
 * The schema: [shelf] (one, unnamed) with 'label' (text), 'books' (goes on over indented lines,
 * at most 8), 'width' (a number > 0 and < 100), 'count' (an integer from -5 to 5), 'colour' (three
 * numbers), 'finish' (one of matt, gloss); [box NAME] (up to 3) with 'type' first and 'size' (an
 * integer) required.
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
enum { LABEL, BOOKS, WIDTH, COUNT, COLOUR, FINISH, SHELF_KEYS };
enum { TYPE, SIZE, BOX_KEYS };
#define MAX_BOXES 3
#define MAX_BOOKS 8

static const char *const shelf_keys[SHELF_KEYS] = {"label", "books", "width", "count", "colour", "finish"};
static const char *const box_keys[BOX_KEYS] = {"type", "size"};
static const char *const finishes[] = {"matt", "gloss", NULL};

struct store {
    char label[32];
    int n_books, n_boxes, finish;
    double width, colour[3];
    long long count;
    char boxes[MAX_BOXES][CONF_NAME_MAX];
};

static struct store store;
static struct conf_error err;

static const char *kind_name(int kind) { return kind == SHELF ? "shelf" : "box"; }
static int kind_named(int kind) { return kind == BOX; }
static const char *kind_list(void) { return "shelf, box NAME"; }
static int name_ok(const char *name) { return strspn(name, "abcdefghijklmnopqrstuvwxyz_-0123456789") == strlen(name); }
static int type_first(int kind) { return kind == BOX; }

static int key_find(int kind, const char *key)
{
    int n = kind == SHELF ? SHELF_KEYS : BOX_KEYS;
    for (int k = 0; k < n; k++)
        if (strcmp(key, kind == SHELF ? shelf_keys[k] : box_keys[k]) == 0)
            return k;
    return -1;
}

static void label(const void *target, int kind, int instance, char *buf, size_t len)
{
    const struct store *s = target;
    if (kind == SHELF)
        snprintf(buf, len, "[shelf]");
    else
        snprintf(buf, len, "[box %s]", s->boxes[instance]);
}

static int open_section(void *target, int kind, const char *name, int line, int *instance, char *msg, size_t msglen)
{
    struct store *s = target;
    (void)line;
    *instance = 0;
    if (kind == BOX) {
        if (s->n_boxes == MAX_BOXES) {
            snprintf(msg, msglen, "at most %d boxes", MAX_BOXES);
            return -1;
        }
        *instance = s->n_boxes++;
        snprintf(s->boxes[*instance], sizeof s->boxes[*instance], "%s", name);
    }
    return 0;
}

static int close_section(void *target, int kind, int instance, const int *key_line, char *msg, size_t msglen)
{
    (void)target;
    if (kind == BOX && key_line[SIZE] == 0) {
        snprintf(msg, msglen, "box %d needs 'size'", instance);
        return -1;
    }
    return 0;
}

/* A number the value parser took: finite, zero or normal, and within the range it checked. */
static void check_number(double x, double lo, double hi, unsigned flags)
{
    if (!isfinite(x) || (x != 0.0 && fabs(x) < DBL_MIN) || !conf_in_range(x, lo, hi, flags))
        __builtin_trap();
}

static int refused(char *msg, size_t msglen, const char *key, const char *value, const char *why)
{
    char quoted[CONF_QUOTE_MAX + 8];
    conf_quote(value, quoted, sizeof quoted);
    snprintf(msg, msglen, "key '%s': got %s%s%s%s", key, quoted, why ? " (" : "", why ? why : "", why ? ")" : "");
    return -1;
}

static int set_pair(void *target, int kind, int instance, const char *key, const char *value, int line, char *msg,
                    size_t msglen)
{
    struct store *s = target;
    const char *why = NULL;
    double x[3];
    long long n;
    (void)instance;
    (void)line;
    int k = key_find(kind, key);
    if (k < 0) {
        snprintf(msg, msglen, "unknown key '%s'", key);
        return -1;
    }
    if (kind == BOX) {
        if (k == SIZE && conf_parse_integer(value, &n) != 0)
            return refused(msg, msglen, key, value, NULL);
        return 0;
    }
    switch (k) {
    case LABEL:
        snprintf(s->label, sizeof s->label, "%s", value);
        return 0;
    case BOOKS:
        s->n_books += *value != '\0';
        return 0;
    case WIDTH:
        if (conf_parse_numbers(value, x, 1, &why) != 0 || !conf_in_range(x[0], 0.0, 100.0, CONF_ABOVE_LO | CONF_BELOW_HI))
            return refused(msg, msglen, key, value, why);
        check_number(x[0], 0.0, 100.0, CONF_ABOVE_LO | CONF_BELOW_HI);
        s->width = x[0];
        return 0;
    case COUNT: {
        if (conf_parse_integer(value, &n) != 0 || !conf_in_range((double)n, -5.0, 5.0, 0))
            return refused(msg, msglen, key, value, NULL);
        /* what it took: decimal digits after an optional minus sign, then blanks at most */
        size_t d = value[0] == '-';
        if (!isdigit((unsigned char)value[d]))
            __builtin_trap();
        d += strspn(value + d, "0123456789");
        if (value[d + strspn(value + d, " \t\r\n\v\f")] != '\0')
            __builtin_trap();
        s->count = n;
        return 0;
    }
    case COLOUR:
        if (conf_parse_numbers(value, s->colour, 3, &why) != 0)
            return refused(msg, msglen, key, value, why);
        for (int i = 0; i < 3; i++)
            check_number(s->colour[i], -INFINITY, INFINITY, 0);
        return 0;
    case FINISH:
        s->finish = conf_choice_find(finishes, value);
        if (s->finish < 0) {
            char expected[64];
            conf_describe_choices(finishes, expected, sizeof expected);
            snprintf(msg, msglen, "key 'finish': expected %s", expected);
            return -1;
        }
        return 0;
    }
    return 0;
}

static int continues(int kind, const char *key) { return kind == SHELF && strcmp(key, "books") == 0; }

static int continuation(void *target, int kind, int instance, const char *key, const char *item, char *msg,
                        size_t msglen)
{
    struct store *s = target;
    (void)kind;
    (void)instance;
    (void)key;
    (void)item;
    if (s->n_books == MAX_BOOKS) {
        snprintf(msg, msglen, "at most %d books", MAX_BOOKS);
        return -1;
    }
    s->n_books++;
    return 0;
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
    .type_first = type_first,
    .key_find = key_find,
    .label = label,
    .open = open_section,
    .close = close_section,
    .pair = set_pair,
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
