/* Reading the kiosk configuration file. As in src/scene/scene_load.c, inih splits "key = value"
 * lines and strips comments, but this file hands it the lines itself: every message knows its line,
 * headers are read here (inih would truncate long ones and skip empty sections silently), a line
 * too long for inih's buffer is refused instead of cut, and the first error stops the parse. */
#include <ctype.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <ini.h>
#include "kiosk/kiosk_config.h"
#include "kiosk/kiosk_config_keys.h"
#include "io/text_file.h"

/* inih wants room for '\r', '\n' and '\0' in its line buffer. */
#define LINE_RESERVE 3
/* Every section a valid file can hold; more are refused before this fills up. */
#define MAX_SECTIONS (KIOSK_SINGLE_SECTIONS + KIOSK_MAX_BUTTONS + KIOSK_MAX_INPUTS)

struct seen_section {
    enum kiosk_section kind;
    char name[KIOSK_NAME_LEN];
    int line;
};

struct reader {
    struct kiosk_config *c;
    struct kiosk_config_error *err;
    const char *text;
    size_t len, pos;
    int line;                    /* line last handed to inih */
    int at_end;
    int failed;
    int error_line;
    int section;                 /* enum kiosk_section, -1 before the first header */
    int instance;                /* button or input index */
    int header_line;
    int continuing;              /* the last pair was 'scenes': indented lines add to the list */
    struct seen_section seen[MAX_SECTIONS];
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
    snprintf(r->err->where, sizeof r->err->where, "%s:%d", r->c->path, line);
    va_start(ap, fmt);
    vsnprintf(r->err->message, sizeof r->err->message, fmt, ap);
    va_end(ap);
    return -1;
}

static char *trim(char *p)
{
    char *end;
    while (isspace((unsigned char)*p))
        p++;
    end = p + strlen(p);
    while (end > p && isspace((unsigned char)end[-1]))
        *--end = '\0';
    return p;
}

static int *key_lines(struct reader *r)
{
    return r->c->source.key[kiosk_slot((enum kiosk_section)r->section, r->instance)];
}

/* A button or input without its required keys cannot work; said at its header, where it starts. */
static int finish_section(struct reader *r)
{
    char label[KIOSK_NAME_LEN + 16];
    const char *missing;
    if (r->section < 0)
        return 0;
    kiosk_section_label(r->c, (enum kiosk_section)r->section, r->instance, label, sizeof label);
    if (r->section == KSEC_INPUT && key_lines(r)[kiosk_key_find(KSEC_INPUT, "type")] == 0)
        return fail(r, r->header_line, "%s has no type: add 'type = powermate', 'hid', "
                    "'gpio_encoder', 'gpio_button', 'keyboard' or 'script'", label);
    missing = kiosk_key_missing(r->c, (enum kiosk_section)r->section, r->instance);
    if (missing && r->section == KSEC_INPUT)
        return fail(r, r->header_line, "%s of type '%s' needs '%s'", label,
                    kiosk_input_type_name(r->c->inputs[r->instance].type), missing);
    if (missing)
        return fail(r, r->header_line, "%s needs '%s'", label, missing);
    return 0;
}

static int open_section(struct reader *r, enum kiosk_section kind, const char *name)
{
    struct kiosk_config *c = r->c;
    for (int i = 0; i < r->n_seen; i++) {
        if (r->seen[i].kind == kind && strcmp(r->seen[i].name, name) == 0)
            return fail(r, r->line, "section [%s%s%s] appears twice (lines %d and %d): %s",
                        kiosk_section_name(kind), *name ? " " : "", name, r->seen[i].line, r->line,
                        *name ? "give each its own name" : "merge them");
    }
    if (kind == KSEC_BUTTON) {
        if (c->n_buttons >= KIOSK_MAX_BUTTONS)
            return fail(r, r->line, "too many buttons: at most %d", KIOSK_MAX_BUTTONS);
        r->instance = c->n_buttons++;
        kiosk_button_defaults(&c->buttons[r->instance], name);
    } else if (kind == KSEC_INPUT) {
        if (c->n_inputs >= KIOSK_MAX_INPUTS)
            return fail(r, r->line, "too many inputs: at most %d", KIOSK_MAX_INPUTS);
        r->instance = c->n_inputs++;
        kiosk_input_defaults(&c->inputs[r->instance], name);
    } else {
        r->instance = 0;
    }
    r->seen[r->n_seen].kind = kind;
    snprintf(r->seen[r->n_seen].name, sizeof r->seen[r->n_seen].name, "%s", name);
    r->seen[r->n_seen].line = r->line;
    r->n_seen++;
    r->section = (int)kind;
    r->header_line = r->line;
    c->source.header[kiosk_slot(kind, r->instance)] = r->line;
    return 0;
}

/* "[input knob]": the kind, then for buttons and inputs a name. */
static int read_header(struct reader *r, char *line)
{
    char *close, *inner, *name, *rest;
    int kind;

    if (finish_section(r) != 0)
        return -1;
    close = strchr(line, ']');
    if (!close)
        return fail(r, r->line, "section header without ']': expected [section] or [section NAME]");
    *close = '\0';
    rest = trim(close + 1);
    if (*rest && *rest != ';' && *rest != '#')
        return fail(r, r->line, "unexpected text \"%.80s\" after the section header", rest);
    inner = trim(line + 1);
    if (*inner == '\0')
        return fail(r, r->line, "empty section header []: expected one of %s", kiosk_section_list());
    name = inner;
    while (*name && !isspace((unsigned char)*name))
        name++;
    if (*name)
        *name++ = '\0';
    name = trim(name);
    kind = kiosk_section_find(inner);
    if (kind < 0) {
        const char *guess = kiosk_section_guess(inner);
        if (guess)
            return fail(r, r->line, "unknown section [%.80s] (did you mean [%s]?; sections: %s)", inner,
                        guess, kiosk_section_list());
        return fail(r, r->line, "unknown section [%.80s] (sections: %s)", inner, kiosk_section_list());
    }
    if (kiosk_section_named(kind) && *name == '\0')
        return fail(r, r->line, "[%s] needs a name: [%s NAME]", inner, inner);
    if (!kiosk_section_named(kind) && *name)
        return fail(r, r->line, "section [%s] takes no name, got \"%.80s\"", inner, name);
    if (*name && !kiosk_name_ok(name))
        return fail(r, r->line, "bad %s name \"%.80s\": expected 1 to %d letters, digits, '_' or '-'",
                    inner, name, KIOSK_NAME_LEN - 1);
    return open_section(r, (enum kiosk_section)kind, name);
}

/* A scene list longer than inih's line limit goes on over indented lines; a comment line inside it
 * leaves a scene out, and a blank or unindented line, or one with '=' (an indented key), ends it.
 * LINE holds one such line, its indentation removed; inih gets a blank line in its place. */
static char *continue_list(struct reader *r, char *line)
{
    char reason[sizeof r->err->message], *cut;
    if (*line == ';' || *line == '#') {
        *line = '\0';
        return line;
    }
    /* inih's rule for comments after a value: ';' after a blank */
    for (cut = line; (cut = strchr(cut, ';')) != NULL; cut++) {
        if (cut > line && isspace((unsigned char)cut[-1])) {
            *cut = '\0';
            break;
        }
    }
    if (kiosk_scenes_append(r->c, trim(line), reason, sizeof reason) != 0) {
        fail(r, r->line, "key 'scenes' in [kiosk]: %s", reason);
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
    char why[128];
    int got = text_lines_next(&lines, &start, &len, why, sizeof why);
    r->pos = lines.pos;
    r->line = lines.line;
    if (got < 0) {
        fail(r, r->line, "%s", why);
        return NULL;
    }
    if (len > (size_t)limit) {
        fail(r, r->line, "line is %zu characters long, at most %d are allowed: shorten it "
             "(a long 'scenes' list goes on over indented lines)", len, limit);
        return NULL;
    }
    indented = len > 0 && (*start == ' ' || *start == '\t');
    /* Without leading blanks inih never takes a line for the continuation of the previous value,
     * so indentation is only layout, except where continue_list() says. */
    while (len > 0 && (*start == ' ' || *start == '\t')) {
        start++;
        len--;
    }
    memcpy(buf, start, len);
    buf[len] = '\0';
    if (r->continuing && (len == 0 || (!indented && *buf != ';' && *buf != '#') || *buf == '[' ||
                          strchr(buf, '=')))
        r->continuing = 0;
    if (r->continuing)
        return continue_list(r, buf);
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
    enum kiosk_section section = (enum kiosk_section)r->section;
    char msg[sizeof r->err->message];
    int key;
    (void)inih_section;  /* tracked by read_header(), which keeps names inih would truncate */

    if (r->failed)
        return 0;
    if (r->section < 0) {
        fail(r, r->line, "key '%s' comes before any section: put it under a [section]", name);
        return 0;
    }
    if (*name == '\0') {
        fail(r, r->line, "missing key name before '='");
        return 0;
    }
    key = kiosk_key_find(section, name);
    if (key >= 0) {
        char label[KIOSK_NAME_LEN + 16];
        kiosk_section_label(r->c, section, r->instance, label, sizeof label);
        if (key_lines(r)[key]) {
            fail(r, r->line, "key '%s' in %s is already set at line %d", name, label, key_lines(r)[key]);
            return 0;
        }
        /* which keys an input takes depends on its type */
        if (section == KSEC_INPUT && strcmp(name, "type") != 0 &&
            key_lines(r)[kiosk_key_find(KSEC_INPUT, "type")] == 0) {
            fail(r, r->line, "key '%s' in %s comes before 'type': set type first", name, label);
            return 0;
        }
    }
    /* unknown keys too: the message (with its guess at what was meant) is made in one place */
    if (kiosk_key_apply(r->c, section, r->instance, name, value, msg, sizeof msg) != 0 || key < 0) {
        fail(r, r->line, "%s", msg);
        return 0;
    }
    key_lines(r)[key] = r->line;
    r->continuing = section == KSEC_KIOSK && strcmp(name, "scenes") == 0;
    return 1;
}

/* The whole file at once: its size is bounded, and lines then come without further I/O errors. */
static void set_dir(struct kiosk_config *c, const char *path)
{
    const char *slash = strrchr(path, '/');
    if (!slash)
        snprintf(c->dir, sizeof c->dir, ".");
    else if (slash == path)
        snprintf(c->dir, sizeof c->dir, "/");
    else
        snprintf(c->dir, sizeof c->dir, "%.*s", (int)(slash - path), path);
}

/* What can only be settled once the whole file is read: start_scene may come before scenes, and a
 * knob's start follows its min unless given. */
static int finish_file(struct reader *r)
{
    struct kiosk_config *c = r->c;
    const char *want = c->kiosk.start_scene_name;
    int line = kiosk_key_line(c, KSEC_KIOSK, 0, "start_scene");

    if (kiosk_key_line(c, KSEC_SPEED, 0, "start") == 0)
        c->speed.start = c->speed.min;
    if (kiosk_key_line(c, KSEC_MASS, 0, "start") == 0)
        c->mass.start = c->mass.min;
    if (*want == '\0')
        return 0;
    if (strspn(want, "0123456789") == strlen(want)) {
        long index = strtol(want, NULL, 10);
        if (strlen(want) > 4 || index >= c->kiosk.n_scenes)
            return fail(r, line, "key 'start_scene' in [kiosk]: index %.8s is past the end of "
                        "'scenes', which lists %d (0 is the first)", want, c->kiosk.n_scenes);
        c->kiosk.start_scene = (int)index;
        return 0;
    }
    int found = kiosk_scene_find(c, want);
    if (found == -1)
        return fail(r, line, "key 'start_scene' in [kiosk]: no scene in 'scenes' is called '%s' "
                    "(a scene's name is its file name without the extension)", want);
    if (found == -2)
        return fail(r, line, "key 'start_scene' in [kiosk]: more than one scene is called '%s': "
                    "give its index instead", want);
    c->kiosk.start_scene = found;
    return 0;
}

int kiosk_config_load(struct kiosk_config *c, const char *path, struct kiosk_config_error *err)
{
    struct reader *r;
    char *text;
    size_t len, path_len = strlen(path);
    int rc;

    memset(err, 0, sizeof *err);
    kiosk_config_defaults(c);
    if (path_len >= sizeof c->path) {
        snprintf(err->where, sizeof err->where, "%.64s...", path);
        snprintf(err->message, sizeof err->message, "the path is longer than %d characters",
                 KIOSK_PATH_LEN - 1);
        return -1;
    }
    memcpy(c->path, path, path_len + 1);
    memcpy(err->where, path, path_len + 1);
    set_dir(c, path);

    text = text_file_read(path, KIOSK_MAX_FILE_BYTES, "kiosk configuration", &len, err->message,
                          sizeof err->message);
    if (!text)
        return -1;
    r = calloc(1, sizeof *r);
    if (!r) {
        free(text);
        snprintf(err->message, sizeof err->message, "out of memory");
        return -1;
    }
    r->c = c;
    r->err = err;
    r->text = text;
    r->len = len;
    r->section = -1;

    rc = ini_parse_stream(next_line, r, on_pair, r);
    /* inih reports the first line it could not parse; errors found here stop at their own line,
     * and whichever comes first in the file is the one to tell. */
    if (rc > 0 && (!r->failed || rc < r->error_line)) {
        r->failed = 0;
        fail(r, rc, "syntax error: expected 'key = value', '[section]' or a comment "
             "(';' or '#' at the start of the line)");
    } else if (rc < 0 && !r->failed) {
        fail(r, 0, "the parser ran out of memory");
    }
    if (!r->failed)
        finish_file(r);
    rc = r->failed ? -1 : 0;
    free(r);
    free(text);
    return rc;
}
