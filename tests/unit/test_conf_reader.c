/* The configuration reader that scene files and the kiosk configuration share (conf/conf_reader.h),
 * on a small schema of its own: what it settles for every schema (headers, duplicates, the order
 * of 'type', continuation lines, the line of each error) is tested here once; test_scene.c and
 * test_kiosk_config.c test each schema's keys and values. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "conf/conf_reader.h"

/* [shelf] (one, unnamed): label, books (goes on over indented lines); [box NAME] (up to 3, 'type'
 * first, 'size' required). */
enum { SHELF, BOX, KINDS };
enum { WOOD, CARD };
#define MAX_BOXES 3
#define MAX_BOOKS 8
struct box {
    char name[CONF_NAME_MAX];
    int type, size, size_line;
};
struct store {
    char label[32];
    char books[MAX_BOOKS][32];
    int n_books;
    struct box boxes[MAX_BOXES];
    int n_boxes, opened, closed;
};

static const char *kind_name(int kind) { return kind == SHELF ? "shelf" : "box"; }
static int kind_named(int kind) { return kind == BOX; }
static const char *kind_list(void) { return "shelf, box NAME"; }
static int name_ok(const char *name) { return strspn(name, "abcdefghijklmnopqrstuvwxyz_-0123456789") == strlen(name); }

static int add_book(struct store *s, const char *item, struct error *e)
{
    if (s->n_books == MAX_BOOKS) {
        error_set(e, ERROR_INPUT, NULL, "at most %d books", MAX_BOOKS);
        return -1;
    }
    snprintf(s->books[s->n_books++], sizeof s->books[0], "%s", item);
    return 0;
}

static int set_books(void *owner, void *target, const union conf_parsed *v, struct error *e)
{
    (void)target;
    return add_book(owner, v->text, e);
}

static const struct conf_choice box_types[] = {{"wood", WOOD}, {"card", CARD}, {NULL, 0}};
static const struct conf_key keys[] = {
    {SHELF, "label", CONF_TEXT, .lo = 0, .hi = 31, .offset = offsetof(struct store, label)},
    {SHELF, "books", CONF_SPECIAL, .set = set_books},
    {BOX, "type", CONF_CHOICE, .choices = box_types, .flags = CONF_REQUIRED, .offset = offsetof(struct box, type)},
    {BOX, "size", CONF_INTEGER, .lo = 0, .hi = 1000, .flags = CONF_REQUIRED, .offset = offsetof(struct box, size)},
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
    s->opened++;
    *instance = 0;
    if (kind == BOX) {
        if (s->n_boxes == MAX_BOXES) {
            error_set(e, ERROR_INPUT, NULL, "too many boxes");
            return -1;
        }
        *instance = s->n_boxes++;
        memset(&s->boxes[*instance], 0, sizeof s->boxes[*instance]);
        snprintf(s->boxes[*instance].name, sizeof s->boxes[*instance].name, "%s", name);
    }
    return 0;
}

/* after the required keys: a box of card holds at most 10 */
static int close_section(void *target, int kind, int instance, const int *key_line, struct error *e)
{
    struct store *s = target;
    (void)key_line;
    s->closed++;
    if (kind == BOX && s->boxes[instance].type == CARD && s->boxes[instance].size > 10) {
        error_set(e, ERROR_INPUT, NULL, "[box %s] of card holds at most 10", s->boxes[instance].name);
        return -1;
    }
    return 0;
}

static void applied(void *target, int kind, int instance, int key, int line)
{
    struct store *s = target;
    if (kind == BOX && key == 3)
        s->boxes[instance].size_line = line;
}

static int continues(int kind, const char *key) { return kind == SHELF && strcmp(key, "books") == 0; }

static int continuation(void *target, int kind, int instance, const char *key, const char *item, struct error *e)
{
    (void)kind;
    (void)instance;
    (void)key;
    return add_book(target, item, e);
}

static const struct conf_schema schema = {
    .what = "store file", .max_bytes = 4096, .long_line_hint = ": split the list",
    .n_kinds = KINDS, .kind_name = kind_name, .kind_named = kind_named, .kind_list = kind_list,
    .name_ok = name_ok, .name_max = CONF_NAME_MAX - 1, .keys = &key_table,
    .open = open_section, .close = close_section, .applied = applied,
    .continues = continues, .continuation = continuation,
};

static char path[64];

/* Writes len bytes of text to a file of its own and reads it. */
static int read_text(const char *text, size_t len, struct store *s, struct error *err)
{
    snprintf(path, sizeof path, "/tmp/bt_conf_XXXXXX");
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    assert_int_equal(write(fd, text, len), (ssize_t)len);
    close(fd);
    memset(s, 0, sizeof *s);
    int rc = conf_read(path, &schema, s, err);
    unlink(path);
    return rc;
}

static void test_reads_a_file(void **state)
{
    (void)state;
    static const char text[] = "; a store\n"
                               "[shelf]\n"
                               "label = front  ; after a blank, a comment\n"
                               "books = Principia\n"
                               "  Opticks\n"
                               "  ; left out\n"
                               "\tDialogo ; with a comment\n"
                               "\n"
                               "  [box b-1]\n"
                               "type = wood\n"
                               "    size = 3\n";
    struct store s;
    struct error err;
    if (read_text(text, sizeof text - 1, &s, &err) != 0)
        fail_msg("%s: %s", err.where, err.message);
    assert_string_equal(s.label, "front");
    assert_int_equal(s.n_books, 3);
    assert_string_equal(s.books[0], "Principia");
    assert_string_equal(s.books[1], "Opticks");
    assert_string_equal(s.books[2], "Dialogo");
    assert_int_equal(s.n_boxes, 1);
    assert_string_equal(s.boxes[0].name, "b-1");
    assert_int_equal(s.boxes[0].type, WOOD);
    assert_int_equal(s.boxes[0].size, 3);
    assert_int_equal(s.boxes[0].size_line, 11);
    /* every section opened is closed, the last one at the end of the file */
    assert_int_equal(s.opened, 2);
    assert_int_equal(s.closed, 2);
}

static const struct {
    const char *what, *text;
    int line;                  /* 0: the message names the file alone */
    const char *words;
} bad[] = {
    {"key before any section", "label = x\n", 1, "key 'label' comes before any section"},
    {"missing key name", "[shelf]\n= x\n", 2, "missing key name before '='"},
    {"not a pair", "[shelf]\nlabel\n", 2, "syntax error: expected 'key = value'"},
    {"header without ]", "[shelf\n", 1, "section header without ']'"},
    {"text after header", "[shelf] x\n", 1, "unexpected text \"x\" after the section header"},
    {"comment after header", "[shelf] ; fine\nlabel =\n[box\n", 3, "without ']'"},
    {"empty header", "[ ]\n", 1, "empty section header []: expected one of shelf, box NAME"},
    {"unknown with a guess", "[shelv]\n", 1, "unknown section [shelv] (did you mean [shelf]?; sections:"},
    {"unknown without one", "[cupboard]\n", 1, "unknown section [cupboard] (sections: shelf, box NAME)"},
    {"named kind without a name", "[box]\n", 1, "[box] needs a name: [box NAME]"},
    {"unnamed kind with one", "[shelf top]\n", 1, "section [shelf] takes no name, got \"top\""},
    {"bad name", "[box B!]\n", 1, "bad box name \"B!\""},
    {"section twice", "[shelf]\n[shelf]\n", 2, "section [shelf] appears twice (lines 1 and 2): merge them"},
    {"named section twice", "[box a]\ntype=wood\nsize=1\n[box a]\n", 4, "appears twice (lines 1 and 4): give each its own name"},
    {"schema has no room", "[box a]\ntype=wood\nsize=1\n[box b]\ntype=wood\nsize=1\n[box c]\ntype=wood\nsize=1\n[box d]\n", 10,
     "too many boxes"},
    {"key twice", "[shelf]\nlabel = a\nlabel = b\n", 3, "key 'label' in [shelf] is already set at line 2"},
    {"key before type", "[box a]\nsize = 1\ntype = wood\n", 2, "key 'size' in [box a] comes before 'type': set type first"},
    {"unknown key", "[shelf]\ncolour = red\n", 2, "unknown key 'colour'"},
    {"close at its header", "[box a]\ntype = wood\n\n[shelf]\n", 1, "[box a] of type 'wood' needs 'size'"},
    {"close at the end", "[shelf]\n[box a]\ntype = wood\n", 2, "[box a] of type 'wood' needs 'size'"},
    {"no type", "[box a]\n[shelf]\n", 1, "[box a] has no type: add 'type = wood' or 'card'"},
    {"type first, then the rest", "[box a]\n", 1, "has no type"},
    {"the schema's close after them", "[box a]\ntype = card\nsize = 11\n", 1, "[box a] of card holds at most 10"},
    {"a value the table refuses", "[box a]\ntype = card\nsize = big\n", 3,
     "key 'size' in [box a]: expected an integer from 0 to 1000, got \"big\""},
    {"continuation refused", "[shelf]\nbooks = 1\n 2\n 3\n 4\n 5\n 6\n 7\n 8\n 9\n", 10,
     "key 'books' in [shelf]: at most 8 books"},
    {"continuation ends at '='", "[shelf]\nbooks = 1\n label = x\n label = y\n", 4, "already set at line 3"},
    {"NUL byte", "[shelf]\nlabel = a\0b\n", 2, "NUL"},
};

static void test_errors_name_their_line(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        struct store s;
        struct error err;
        /* the NUL case's length counts past its NUL */
        size_t len = strcmp(bad[i].what, "NUL byte") == 0 ? 20 : strlen(bad[i].text);
        int rc = read_text(bad[i].text, len, &s, &err);
        char where[96];
        snprintf(where, sizeof where, "%s:%d", path, bad[i].line);
        print_message("%-28s %s: %s\n", bad[i].what, err.where, err.message);
        assert_int_equal(rc, -1);
        assert_string_equal(err.where, where);
        if (!strstr(err.message, bad[i].words))
            fail_msg("%s: expected \"%s\" in \"%s\"", bad[i].what, bad[i].words, err.message);
    }
}

static void test_long_lines_are_refused_not_cut(void **state)
{
    (void)state;
    char text[1200];
    int n = snprintf(text, sizeof text, "[shelf]\nlabel = ");
    memset(text + n, 'x', 1000);
    text[n + 1000] = '\n';
    struct store s;
    struct error err;
    assert_int_equal(read_text(text, (size_t)n + 1001, &s, &err), -1);
    print_message("%s: %s\n", err.where, err.message);
    assert_non_null(strstr(err.where, ":2"));
    assert_non_null(strstr(err.message, "characters long, at most"));
    assert_non_null(strstr(err.message, ": split the list"));
}

static void test_whole_file_problems(void **state)
{
    (void)state;
    struct store s;
    struct error err;
    char big[5000];
    memset(big, ';', sizeof big);
    assert_int_equal(read_text(big, sizeof big, &s, &err), -1);
    print_message("%s: %s\n", err.where, err.message);
    assert_string_equal(err.where, path);
    assert_non_null(strstr(err.message, "store file"));
    assert_int_equal(err.status, ERROR_INPUT);
    memset(&s, 0, sizeof s);
    assert_int_equal(conf_read("/nonexistent/store", &schema, &s, &err), -1);
    assert_string_equal(err.where, "/nonexistent/store");
    assert_int_equal(err.status, ERROR_INPUT);
    assert_int_equal(s.opened, 0);
    /* a directory is the user's mistake too, said as such, its status set where it is found */
    assert_int_equal(conf_read("/tmp", &schema, &s, &err), -1);
    assert_string_equal(err.where, "/tmp");
    assert_non_null(strstr(err.message, "it is a directory, not a regular file"));
    assert_int_equal(err.status, ERROR_INPUT);
    /* a NUL byte in a line: not text, at its line */
    static const char nul[] = "[shelf]\nlabel = a\0b\n";
    assert_int_equal(read_text(nul, sizeof nul - 1, &s, &err), -1);
    print_message("%s: %s\n", err.where, err.message);
    assert_non_null(strstr(err.where, ":2"));
    assert_non_null(strstr(err.message, "NUL byte"));
    assert_int_equal(err.status, ERROR_INPUT);
}

static void test_kind_guess(void **state)
{
    (void)state;
    assert_string_equal(conf_kind_guess(&schema, "shlef"), "shelf");
    assert_string_equal(conf_kind_guess(&schema, "bx"), "box");
    assert_null(conf_kind_guess(&schema, "b"));          /* two edits from "box" is the whole name */
    assert_null(conf_kind_guess(&schema, "cupboard"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_reads_a_file),
        cmocka_unit_test(test_errors_name_their_line),
        cmocka_unit_test(test_long_lines_are_refused_not_cut),
        cmocka_unit_test(test_whole_file_problems),
        cmocka_unit_test(test_kind_guess),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
