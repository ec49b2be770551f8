#include "conf/conf_reader.h"
#include "io/text_file.h"
#include <ctype.h>
#include <ini.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* inih wants room for '\r', '\n' and '\0' in its line buffer. */
#define LINE_RESERVE 3

struct seen_section {
    int kind;
    char name[CONF_NAME_MAX];
    int line;
};

struct reader {
    const struct conf_schema *schema;
    void *target;
    const char *path;
    struct error *err;
    const char *text;
    size_t len, pos;
    int line;                    /* line last handed to inih */
    int at_end;
    int failed;
    int error_line;
    /* the section being read */
    int kind;                    /* -1 before the first header */
    int instance;
    int header_line;
    int key_line[CONF_MAX_KEYS];
    char continuing[CONF_NAME_MAX];  /* the key whose indented lines are being read, or "" */
    struct seen_section seen[CONF_MAX_SECTIONS];
    int n_seen;
};

__attribute__((format(printf, 3, 4)))
static int fail(struct reader *r, int line, const char *fmt, ...)
{
    va_list ap;
    if (r->failed)
        return -1;
    r->failed = 1;
    r->error_line = line;
    r->err->status = ERROR_INPUT;
    snprintf(r->err->where, sizeof r->err->where, "%s:%d", r->path, line);
    va_start(ap, fmt);
    vsnprintf(r->err->message, sizeof r->err->message, fmt, ap);
    va_end(ap);
    return -1;
}

char *conf_trim(char *p)
{
    char *end;
    while (isspace((unsigned char)*p))
        p++;
    end = p + strlen(p);
    while (end > p && isspace((unsigned char)end[-1]))
        *--end = '\0';
    return p;
}

const char *conf_kind_guess(const struct conf_schema *schema, const char *name)
{
    const char *best = NULL;
    int best_d = 3;
    for (int k = 0; k < schema->n_kinds; k++) {
        const char *kind = schema->kind_name(k);
        int d = edit_distance(name, kind, CONF_NAME_MAX);
        if (d < best_d && (size_t)d < strlen(name)) {
            best_d = d;
            best = kind;
        }
    }
    return best;
}

static int finish_section(struct reader *r)
{
    struct error e;
    if (r->kind < 0)
        return 0;
    if (conf_key_check_required(r->schema->keys, r->target, r->kind, r->instance, r->key_line, &e) != 0)
        return fail(r, r->header_line, "%s", e.message);
    if (r->schema->close && r->schema->close(r->target, r->kind, r->instance, r->key_line, &e) != 0)
        return fail(r, r->header_line, "%s", e.message);
    return 0;
}

static int open_section(struct reader *r, int kind, const char *name)
{
    struct error e;
    for (int i = 0; i < r->n_seen; i++) {
        if (r->seen[i].kind == kind && strcmp(r->seen[i].name, name) == 0)
            return fail(r, r->line, "section [%s%s%s] appears twice (lines %d and %d): %s", r->schema->kind_name(kind),
                        *name ? " " : "", name, r->seen[i].line, r->line,
                        *name ? "give each its own name" : "merge them");
    }
    if (r->n_seen == CONF_MAX_SECTIONS)
        return fail(r, r->line, "too many sections: a %s holds at most %d", r->schema->what, CONF_MAX_SECTIONS);
    if (r->schema->open(r->target, kind, name, r->line, &r->instance, &e) != 0)
        return fail(r, r->line, "%s", e.message);
    r->seen[r->n_seen].kind = kind;
    snprintf(r->seen[r->n_seen].name, sizeof r->seen[r->n_seen].name, "%s", name);
    r->seen[r->n_seen].line = r->line;
    r->n_seen++;
    r->kind = kind;
    r->header_line = r->line;
    memset(r->key_line, 0, sizeof r->key_line);
    return 0;
}

static int find_kind(const struct conf_schema *schema, const char *name)
{
    for (int k = 0; k < schema->n_kinds; k++)
        if (strcmp(schema->kind_name(k), name) == 0)
            return k;
    return -1;
}

/* "[object earth]": the kind, then for named kinds a name. */
static int read_header(struct reader *r, char *line)
{
    const struct conf_schema *schema = r->schema;
    char *close, *inner, *name, *rest;

    if (finish_section(r) != 0)
        return -1;
    close = strchr(line, ']');
    if (!close)
        return fail(r, r->line, "section header without ']': expected [section] or [section NAME]");
    *close = '\0';
    rest = conf_trim(close + 1);
    if (*rest && *rest != ';' && *rest != '#')
        return fail(r, r->line, "unexpected text \"%.80s\" after the section header", rest);
    inner = conf_trim(line + 1);
    if (*inner == '\0')
        return fail(r, r->line, "empty section header []: expected one of %s", schema->kind_list());
    name = inner;
    while (*name && !isspace((unsigned char)*name))
        name++;
    if (*name)
        *name++ = '\0';
    name = conf_trim(name);
    int kind = find_kind(schema, inner);
    if (kind < 0) {
        const char *guess = conf_kind_guess(schema, inner);
        if (guess)
            return fail(r, r->line, "unknown section [%.80s] (did you mean [%s]?; sections: %s)", inner, guess,
                        schema->kind_list());
        return fail(r, r->line, "unknown section [%.80s] (sections: %s)", inner, schema->kind_list());
    }
    if (schema->kind_named(kind) && *name == '\0')
        return fail(r, r->line, "[%s] needs a name: [%s NAME]", inner, inner);
    if (!schema->kind_named(kind) && *name)
        return fail(r, r->line, "section [%s] takes no name, got \"%.80s\"", inner, name);
    if (*name && (strlen(name) >= CONF_NAME_MAX || !schema->name_ok(name)))
        return fail(r, r->line, "bad %s name \"%.80s\": expected 1 to %d letters, digits, '_' or '-'", inner, name,
                    schema->name_max);
    return open_section(r, kind, name);
}

/* One indented line of a value that goes on: a comment line leaves an item out; inih's rule for a
 * comment after a value (';' after a blank) holds. LINE, its indentation removed, becomes a blank
 * line for inih. */
static char *continue_value(struct reader *r, char *line)
{
    char label[CONF_NAME_MAX + 16], *cut;
    struct error e;
    if (*line == ';' || *line == '#') {
        *line = '\0';
        return line;
    }
    for (cut = line; (cut = strchr(cut, ';')) != NULL; cut++) {
        if (cut > line && isspace((unsigned char)cut[-1])) {
            *cut = '\0';
            break;
        }
    }
    if (r->schema->continuation(r->target, r->kind, r->instance, r->continuing, conf_trim(line), &e) != 0) {
        r->schema->keys->label(r->target, r->kind, r->instance, label, sizeof label);
        fail(r, r->line, "key '%s' in %s: %s", r->continuing, label, e.message);
        return NULL;
    }
    *line = '\0';
    return line;
}

/* inih's line source. Each call hands over one line, so the line count here is the line inih is
 * working on when it calls on_pair(). */
static char *next_line(char *buf, int size, void *stream)
{
    struct reader *r = stream;
    const char *start;
    size_t len;
    int limit = size - LINE_RESERVE, indented;

    if (r->failed || r->at_end)
        return NULL;
    if (r->pos >= r->len) {
        r->at_end = 1;
        finish_section(r);
        return NULL;
    }
    struct text_lines lines = {r->text, r->len, r->pos, r->line};
    struct error why;
    int got = text_lines_next(&lines, &start, &len, &why);
    r->pos = lines.pos;
    r->line = lines.line;
    if (got < 0) {
        fail(r, r->line, "%s", why.message);
        return NULL;
    }
    if (len > (size_t)limit) {
        fail(r, r->line, "line is %zu characters long, at most %d are allowed%s", len, limit,
             r->schema->long_line_hint ? r->schema->long_line_hint : "");
        return NULL;
    }
    indented = len > 0 && (*start == ' ' || *start == '\t');
    /* Without leading blanks inih never takes a line for the continuation of the previous value,
     * so indentation is only layout, except after a key whose value goes on. */
    while (len > 0 && (*start == ' ' || *start == '\t')) {
        start++;
        len--;
    }
    memcpy(buf, start, len);
    buf[len] = '\0';
    if (*r->continuing && (len == 0 || (!indented && *buf != ';' && *buf != '#') || *buf == '[' || strchr(buf, '=')))
        *r->continuing = '\0';
    if (*r->continuing)
        return continue_value(r, buf);
    if (buf[0] == '[') {
        if (read_header(r, buf) != 0)
            return NULL;
        buf[0] = '\0';   /* handled here; inih sees a blank line */
    }
    return buf;
}

/* inih's handler: nonzero to go on. After the first error it only declines. */
static int on_pair(void *user, const char *inih_section, const char *name, const char *value)
{
    struct reader *r = user;
    const struct conf_schema *schema = r->schema;
    struct error e;
    (void)inih_section;  /* tracked by read_header(), which keeps names inih would cut */

    if (r->failed)
        return 0;
    if (r->kind < 0) {
        fail(r, r->line, "key '%s' comes before any section: put it under a [section]", name);
        return 0;
    }
    if (*name == '\0') {
        fail(r, r->line, "missing key name before '='");
        return 0;
    }
    const struct conf_key_table *keys = schema->keys;
    int key = conf_key_find(keys, r->kind, name);
    if (key >= CONF_MAX_KEYS)
        key = -1;
    if (key >= 0) {
        char label[CONF_NAME_MAX + 16];
        keys->label(r->target, r->kind, r->instance, label, sizeof label);
        if (r->key_line[key]) {
            fail(r, r->line, "key '%s' in %s is already set at line %d", name, label, r->key_line[key]);
            return 0;
        }
        int type = conf_key_find(keys, r->kind, "type");
        if (keys->type_word && keys->type_word(r->kind) && type >= 0 && type < CONF_MAX_KEYS && r->key_line[type] == 0 &&
            strcmp(name, "type") != 0) {
            fail(r, r->line, "key '%s' in %s comes before 'type': set type first", name, label);
            return 0;
        }
    }
    /* unknown keys too: one place words the message (with its guess at what was meant) */
    if (conf_key_apply(keys, r->target, r->kind, r->instance, name, value, &e) != 0 || key < 0) {
        fail(r, r->line, "%s", e.message);
        return 0;
    }
    r->key_line[key] = r->line;
    if (schema->applied)
        schema->applied(r->target, r->kind, r->instance, key, r->line);
    if (schema->continues && schema->continues(r->kind, name)) {
        snprintf(r->continuing, sizeof r->continuing, "%s", name);
    }
    return 1;
}

int conf_read(const char *path, const struct conf_schema *schema, void *target, struct error *err)
{
    size_t len;
    error_clear(err);
    char *text = text_file_read(path, schema->max_bytes, schema->what, &len, err);
    if (!text)
        return -1;                      /* its status set where the failure is known */
    struct reader *r = calloc(1, sizeof *r);
    if (!r) {
        free(text);
        return error_set(err, ERROR_RUNTIME, path, "out of memory");
    }
    r->schema = schema;
    r->target = target;
    r->path = path;
    r->err = err;
    r->text = text;
    r->len = len;
    r->kind = -1;

    int rc = ini_parse_stream(next_line, r, on_pair, r);
    /* inih reports the first line it could not parse; errors found here stop at their own line,
     * and whichever comes first in the file is the one to tell. */
    if (rc > 0 && (!r->failed || rc < r->error_line)) {
        r->failed = 0;
        fail(r, rc, "syntax error: expected 'key = value', '[section]' or a comment "
             "(';' or '#' at the start of the line)");
    } else if (rc < 0 && !r->failed) {
        fail(r, 0, "the parser ran out of memory");
    }
    rc = r->failed ? -1 : 0;
    free(r);
    free(text);
    return rc;
}
