/* Reading a scene file and --set overrides. inih splits "key = value" lines and strips comments;
 * this file feeds it lines itself, so that every message knows its line number, headers are
 * checked here (inih would truncate long section names and skip empty sections silently), and
 * the first error stops the parse. */
#include <ctype.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <ini.h>
#include "scene/scene.h"
#include "scene/scene_keys.h"
#include "io/text_file.h"

/* inih wants room for '\r', '\n' and '\0' in its line buffer. */
#define LINE_RESERVE 3
/* Enough for every section a valid scene can hold; more are refused before this fills up. */
#define MAX_SECTIONS (SECTION_COUNT + SCENE_MAX_OBJECTS + SCENE_MAX_LIGHTS)

struct seen_section {
    enum scene_section_kind kind;
    char name[SCENE_NAME_LEN];
    int line;
};

struct scene_reader {
    struct scene *s;
    struct scene_error *err;
    const char *text;
    size_t len, pos;
    int line;                    /* line last handed to inih */
    int at_end;
    int failed;
    int error_line;
    /* the section being read */
    int section;                 /* enum scene_section_kind, -1 before the first header */
    int instance;                /* object or light index */
    int header_line;
    int type_line;               /* where this section's 'type' was set, 0 if not yet */
    int key_line[SCENE_KEY_TABLE_MAX];
    struct seen_section seen[MAX_SECTIONS];
    int n_seen;
};

__attribute__((format(printf, 3, 4)))
static int fail(struct scene_reader *r, int line, const char *fmt, ...)
{
    va_list ap;
    if (r->failed)
        return -1;
    r->failed = 1;
    r->error_line = line;
    snprintf(r->err->where, sizeof r->err->where, "%s:%d", r->s->path, line);
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

/* A typed section's keys are only known once its type is; a section that never got one is an
 * object nobody can draw. */
static int finish_section(struct scene_reader *r)
{
    if (r->section == SECTION_OBJECT && r->type_line == 0)
        return fail(r, r->header_line,
                    "[object %s] has no type: add 'type = sphere', 'triangle', 'disk' or 'rect'",
                    r->s->objects[r->instance].name);
    return 0;
}

static int open_section(struct scene_reader *r, enum scene_section_kind kind, const char *name)
{
    struct scene *s = r->s;
    for (int i = 0; i < r->n_seen; i++) {
        if (r->seen[i].kind == kind && strcmp(r->seen[i].name, name) == 0)
            return fail(r, r->line, "section [%s%s%s] appears twice (lines %d and %d): "
                        "give each its own name or merge them", scene_section_name(kind),
                        *name ? " " : "", name, r->seen[i].line, r->line);
    }
    if (kind == SECTION_OBJECT) {
        if (s->n_objects >= SCENE_MAX_OBJECTS)
            return fail(r, r->line, "too many objects: a scene holds at most %d", SCENE_MAX_OBJECTS);
        r->instance = s->n_objects++;
        scene_object_defaults(&s->objects[r->instance], name);
    } else if (kind == SECTION_LIGHT) {
        if (s->n_lights >= SCENE_MAX_LIGHTS)
            return fail(r, r->line, "too many lights: a scene holds at most %d", SCENE_MAX_LIGHTS);
        r->instance = s->n_lights++;
        scene_light_defaults(&s->lights[r->instance], name);
    } else {
        r->instance = 0;
    }
    r->seen[r->n_seen].kind = kind;
    snprintf(r->seen[r->n_seen].name, sizeof r->seen[r->n_seen].name, "%s", name);
    r->seen[r->n_seen].line = r->line;
    r->n_seen++;
    r->section = (int)kind;
    r->header_line = r->line;
    r->type_line = 0;
    memset(r->key_line, 0, sizeof r->key_line);
    return 0;
}

/* "[object earth]": the kind, then for lights and objects a name. */
static int read_header(struct scene_reader *r, char *line)
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
        return fail(r, r->line, "unexpected text \"%s\" after the section header", rest);
    inner = trim(line + 1);
    if (*inner == '\0')
        return fail(r, r->line, "empty section header []: expected one of %s", scene_section_list());
    name = inner;
    while (*name && !isspace((unsigned char)*name))
        name++;
    if (*name)
        *name++ = '\0';
    name = trim(name);
    kind = scene_section_find(inner);
    if (kind < 0)
        return fail(r, r->line, "unknown section [%s] (sections: %s)", inner, scene_section_list());
    if (scene_section_named(kind) && *name == '\0')
        return fail(r, r->line, "[%s] needs a name: [%s NAME]", inner, inner);
    if (!scene_section_named(kind) && *name)
        return fail(r, r->line, "section [%s] takes no name, got \"%s\"", inner, name);
    if (*name && !scene_instance_name_ok(name))
        return fail(r, r->line, "bad %s name \"%s\": expected 1 to %d letters, digits, '_' or '-'",
                    inner, name, SCENE_NAME_LEN - 1);
    return open_section(r, (enum scene_section_kind)kind, name);
}

/* inih's line source. Each call hands over one line, so the line count here is the line inih is
 * working on when it calls on_pair(). */
static char *next_line(char *buf, int size, void *stream)
{
    struct scene_reader *r = stream;
    const char *start;
    size_t len;
    int limit = size - LINE_RESERVE;

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
        fail(r, r->line, "line is %zu characters long, at most %d are allowed", len, limit);
        return NULL;
    }
    /* Without leading blanks inih never takes a line for the continuation of the previous value,
     * so indentation is only layout. */
    while (len > 0 && (*start == ' ' || *start == '\t')) {
        start++;
        len--;
    }
    memcpy(buf, start, len);
    buf[len] = '\0';
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
    struct scene_reader *r = user;
    enum scene_section_kind section = (enum scene_section_kind)r->section;
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
    key = scene_key_find(section, name);
    if (key >= 0) {
        char label[SCENE_NAME_LEN + 16];
        scene_section_label(r->s, section, r->instance, label, sizeof label);
        if (r->key_line[key]) {
            fail(r, r->line, "key '%s' in %s is already set at line %d", name, label, r->key_line[key]);
            return 0;
        }
        if (scene_section_type_first(section) && r->type_line == 0 && strcmp(name, "type") != 0) {
            fail(r, r->line, "key '%s' in %s comes before 'type': set type first", name, label);
            return 0;
        }
    }
    /* unknown keys too: the message (with its guess at what was meant) is made in one place */
    if (scene_key_apply(r->s, section, r->instance, name, value, msg, sizeof msg) != 0 || key < 0) {
        fail(r, r->line, "%s", msg);
        return 0;
    }
    r->key_line[key] = r->line;
    if (strcmp(name, "type") == 0)
        r->type_line = r->line;
    /* where each image came from, for a file that turns out unreadable only when it is decoded */
    struct scene *s = r->s;
    if (section == SECTION_OBJECT && strcmp(name, "texture") == 0 && s->n_objects > 0) {
        int t = s->objects[s->n_objects - 1].material.texture;
        if (t >= 0 && s->texture_line[t] == 0)
            s->texture_line[t] = r->line;
    }
    if (section == SECTION_SKY && strcmp(name, "cubemap") == 0)
        s->cubemap_line = r->line;
    return 1;
}

/* The whole file at once: its size is bounded, and lines then come without further I/O errors. */
/* Directory and base name of the scene file: assets resolve against the first, the second names
 * the scene until [scene] name says otherwise. */
static void split_path(struct scene *s, const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    size_t base_len = dot && dot != base ? (size_t)(dot - base) : strlen(base);

    if (!slash)
        snprintf(s->dir, sizeof s->dir, ".");
    else if (slash == path)
        snprintf(s->dir, sizeof s->dir, "/");
    else
        snprintf(s->dir, sizeof s->dir, "%.*s", (int)(slash - path), path);
    if (base_len >= sizeof s->name)
        base_len = sizeof s->name - 1;
    if (base_len > 0)
        snprintf(s->name, sizeof s->name, "%.*s", (int)base_len, base);
}

int scene_load(struct scene *s, const char *path, struct scene_error *err)
{
    struct scene_reader *r;
    char *text;
    size_t len;
    int rc;

    size_t path_len = strlen(path);

    memset(err, 0, sizeof *err);
    scene_defaults(s);
    if (path_len >= sizeof s->path) {
        memcpy(err->where, path, 64);
        strcpy(err->where + 64, "...");
        snprintf(err->message, sizeof err->message, "the path is longer than %d characters",
                 SCENE_PATH_LEN - 1);
        return -1;
    }
    memcpy(s->path, path, path_len + 1);
    memcpy(err->where, path, path_len + 1);
    split_path(s, path);

    text = text_file_read(path, SCENE_MAX_FILE_BYTES, "scene file", &len, err->message, sizeof err->message);
    if (!text)
        return -1;
    r = calloc(1, sizeof *r);
    if (!r) {
        free(text);
        snprintf(err->message, sizeof err->message, "out of memory");
        return -1;
    }
    r->s = s;
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
    rc = r->failed ? -1 : 0;
    free(r);
    free(text);
    return rc == 0 ? scene_kiosk_validate(s, err) : rc;
}

/* ---- --set ----------------------------------------------------------------------------------- */

static int find_instance(const struct scene *s, enum scene_section_kind kind, const char *name)
{
    if (kind == SECTION_OBJECT) {
        for (int i = 0; i < s->n_objects; i++)
            if (strcmp(s->objects[i].name, name) == 0)
                return i;
    } else {
        for (int i = 0; i < s->n_lights; i++)
            if (strcmp(s->lights[i].name, name) == 0)
                return i;
    }
    return -1;
}

__attribute__((format(printf, 2, 3)))
static int set_fail(struct scene_error *err, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->message, sizeof err->message, fmt, ap);
    va_end(ap);
    return -1;
}

int scene_set(struct scene *s, const char *assignment, struct scene_error *err)
{
    char path[128], *section, *key, *name = NULL, *dot;
    char *value;
    const char *eq = strchr(assignment, '=');
    size_t path_len;
    int kind, instance = 0, rc;

    memset(err, 0, sizeof *err);
    snprintf(err->where, sizeof err->where, "--set %.*s", (int)sizeof err->where - 16, assignment);
    if (!eq)
        return set_fail(err, "expected section.key=value (objects and lights: object.NAME.key=value)");
    path_len = (size_t)(eq - assignment);
    if (path_len >= sizeof path)
        return set_fail(err, "the key path before '=' is longer than %d characters", (int)sizeof path - 1);
    memcpy(path, assignment, path_len);
    path[path_len] = '\0';
    section = trim(path);
    dot = strchr(section, '.');
    if (!dot)
        return set_fail(err, "expected section.key=value, got no '.' before '='");
    *dot = '\0';
    key = dot + 1;
    kind = scene_section_find(section);
    if (kind < 0)
        return set_fail(err, "unknown section [%s] (sections: %s)", section, scene_section_list());
    if (scene_section_named(kind)) {
        name = key;
        dot = strchr(name, '.');
        if (!dot)
            return set_fail(err, "expected %s.NAME.key=value", section);
        *dot = '\0';
        key = dot + 1;
        instance = find_instance(s, (enum scene_section_kind)kind, name);
        if (instance < 0)
            return set_fail(err, "the scene has no %s named '%s'", section, name);
    }
    value = strdup(eq + 1);
    if (!value)
        return set_fail(err, "out of memory");
    rc = scene_key_apply(s, (enum scene_section_kind)kind, instance, key, trim(value), err->message,
                         sizeof err->message);
    free(value);
    /* An override of a fixed step's budget replaces the file's other way of giving it (a file
     * that gives both is refused by scene_validate). */
    struct render_settings *r = &s->render;
    if (rc == 0 && kind == SECTION_RENDER && r->step_control == STEP_FIXED) {
        if (strcmp(key, "segments") == 0 && r->segments > 0)
            r->max_path = 0.0;
        else if (strcmp(key, "max_path") == 0 && r->max_path > 0.0)
            r->segments = 0;
    }
    return rc;
}
