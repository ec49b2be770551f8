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
#define MAX_BOXES 3
#define MAX_BOOKS 8
struct store {
    char label[32];
    char books[MAX_BOOKS][32];
    int n_books;
    struct { char name[CONF_NAME_MAX], type[16]; int size, size_line; } boxes[MAX_BOXES];
    int n_boxes, opened, closed;
};

static const char *kind_name(int kind) { return kind == SHELF ? "shelf" : "box"; }
static int kind_named(int kind) { return kind == BOX; }
static const char *kind_list(void) { return "shelf, box NAME"; }
static int name_ok(const char *name) { return strspn(name, "abcdefghijklmnopqrstuvwxyz_-0123456789") == strlen(name); }
static int type_first(int kind) { return kind == BOX; }

static int key_find(int kind, const char *key)
{
    static const char *const shelf[] = {"label", "books"}, *const box[] = {"type", "size"};
    for (int k = 0; k < 2; k++)
        if (strcmp(key, kind == SHELF ? shelf[k] : box[k]) == 0)
            return k;
    return -1;
}

static void label(const void *target, int kind, int instance, char *buf, size_t len)
{
    const struct store *s = target;
    if (kind == SHELF)
        snprintf(buf, len, "[shelf]");
    else
        snprintf(buf, len, "[box %s]", s->boxes[instance].name);
}

static int open_section(void *target, int kind, const char *name, int line, int *instance, char *msg, size_t msglen)
{
    struct store *s = target;
    (void)line;
    s->opened++;
    *instance = 0;
    if (kind == BOX) {
        if (s->n_boxes == MAX_BOXES) {
            snprintf(msg, msglen, "too many boxes");
            return -1;
        }
        *instance = s->n_boxes++;
        snprintf(s->boxes[*instance].name, sizeof s->boxes[*instance].name, "%s", name);
    }
    return 0;
}

static int close_section(void *target, int kind, int instance, const int *key_line, char *msg, size_t msglen)
{
    struct store *s = target;
    s->closed++;
    if (kind == BOX && key_line[1] == 0) {
        snprintf(msg, msglen, "[box %s] needs 'size'", s->boxes[instance].name);
        return -1;
    }
    return 0;
}

static int set_pair(void *target, int kind, int instance, const char *key, const char *value, int line, char *msg,
                    size_t msglen)
{
    struct store *s = target;
    int k = key_find(kind, key);
    if (k < 0) {
        snprintf(msg, msglen, "unknown key '%s'", key);
        return -1;
    }
    if (kind == SHELF && k == 0)
        snprintf(s->label, sizeof s->label, "%s", value);
    else if (kind == BOX && k == 0)
        snprintf(s->boxes[instance].type, sizeof s->boxes[instance].type, "%s", value);
    else if (kind == BOX) {
        s->boxes[instance].size = atoi(value);
        s->boxes[instance].size_line = line;
    } else if (*value) {
        snprintf(s->books[s->n_books++], sizeof s->books[0], "%s", value);
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
    if (s->n_books == MAX_BOOKS) {
        snprintf(msg, msglen, "at most %d books", MAX_BOOKS);
        return -1;
    }
    snprintf(s->books[s->n_books++], sizeof s->books[0], "%s", item);
    return 0;
}

static const struct conf_schema schema = {
    .what = "store file", .max_bytes = 4096, .long_line_hint = ": split the list",
    .n_kinds = KINDS, .kind_name = kind_name, .kind_named = kind_named, .kind_list = kind_list,
    .name_ok = name_ok, .name_max = CONF_NAME_MAX - 1, .type_first = type_first, .key_find = key_find,
    .label = label, .open = open_section, .close = close_section, .pair = set_pair,
    .continues = continues, .continuation = continuation,
};

static char path[64];

/* Writes len bytes of text to a file of its own and reads it. */
static int read_text(const char *text, size_t len, struct store *s, struct conf_error *err)
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
    struct conf_error err;
    if (read_text(text, sizeof text - 1, &s, &err) != 0)
        fail_msg("%s: %s", err.where, err.message);
    assert_string_equal(s.label, "front");
    assert_int_equal(s.n_books, 3);
    assert_string_equal(s.books[0], "Principia");
    assert_string_equal(s.books[1], "Opticks");
    assert_string_equal(s.books[2], "Dialogo");
    assert_int_equal(s.n_boxes, 1);
    assert_string_equal(s.boxes[0].name, "b-1");
    assert_string_equal(s.boxes[0].type, "wood");
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
    {"named section twice", "[box a]\ntype=x\nsize=1\n[box a]\n", 4, "appears twice (lines 1 and 4): give each its own name"},
    {"schema has no room", "[box a]\ntype=x\nsize=1\n[box b]\ntype=x\nsize=1\n[box c]\ntype=x\nsize=1\n[box d]\n", 10,
     "too many boxes"},
    {"key twice", "[shelf]\nlabel = a\nlabel = b\n", 3, "key 'label' in [shelf] is already set at line 2"},
    {"key before type", "[box a]\nsize = 1\ntype = x\n", 2, "key 'size' in [box a] comes before 'type': set type first"},
    {"unknown key", "[shelf]\ncolour = red\n", 2, "unknown key 'colour'"},
    {"close at its header", "[box a]\ntype = x\n\n[shelf]\n", 1, "[box a] needs 'size'"},
    {"close at the end", "[shelf]\n[box a]\ntype = x\n", 2, "[box a] needs 'size'"},
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
        struct conf_error err;
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
    struct conf_error err;
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
    struct conf_error err;
    char big[5000];
    memset(big, ';', sizeof big);
    assert_int_equal(read_text(big, sizeof big, &s, &err), -1);
    print_message("%s: %s\n", err.where, err.message);
    assert_string_equal(err.where, path);
    assert_non_null(strstr(err.message, "store file"));
    memset(&s, 0, sizeof s);
    assert_int_equal(conf_read("/nonexistent/store", &schema, &s, &err), -1);
    assert_string_equal(err.where, "/nonexistent/store");
    assert_int_equal(s.opened, 0);
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
