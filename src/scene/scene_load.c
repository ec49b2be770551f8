/* Reading a scene file and --set overrides. The file is read by the shared configuration reader
 * (conf/conf_reader.h: lines, headers, duplicates, FILE:LINE); this file brings the scene's schema,
 * its sections and what their keys set (scene_keys.c). */
#include <assert.h>
#include <ctype.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "conf/conf_path.h"
#include "conf/conf_reader.h"
#include "scene/scene.h"
#include "scene/scene_keys.h"

static_assert(SECTION_COUNT + SCENE_MAX_OBJECTS + SCENE_MAX_LIGHTS <= CONF_MAX_SECTIONS, "sections of a scene");
static_assert(SCENE_KEY_TABLE_MAX <= CONF_MAX_KEYS && SCENE_NAME_LEN <= CONF_NAME_MAX, "keys and names of a scene");

static const char *kind_name(int kind) { return scene_section_name((enum scene_section_kind)kind); }
static int kind_named(int kind) { return scene_section_named((enum scene_section_kind)kind); }

static int open_section(void *target, int kind, const char *name, int line, int *instance, struct error *e)
{
    struct scene *s = target;
    (void)line;
    *instance = 0;
    if (kind == SECTION_OBJECT) {
        if (s->n_objects >= SCENE_MAX_OBJECTS) {
            error_set(e, ERROR_INPUT, NULL, "too many objects: a scene holds at most %d", SCENE_MAX_OBJECTS);
            return -1;
        }
        *instance = s->n_objects++;
        scene_object_defaults(&s->objects[*instance], name);
    } else if (kind == SECTION_LIGHT) {
        if (s->n_lights >= SCENE_MAX_LIGHTS) {
            error_set(e, ERROR_INPUT, NULL, "too many lights: a scene holds at most %d", SCENE_MAX_LIGHTS);
            return -1;
        }
        *instance = s->n_lights++;
        scene_light_defaults(&s->lights[*instance], name);
    }
    return 0;
}

/* Where each image came from, for a file that turns out unreadable only when it is decoded. */
static void applied(void *target, int kind, int instance, int key, int line)
{
    struct scene *s = target;
    if (kind == SECTION_OBJECT && key == scene_key_find(SECTION_OBJECT, "texture")) {
        int t = s->objects[instance].material.texture;
        if (t >= 0 && s->texture_line[t] == 0)
            s->texture_line[t] = line;
    }
    if (kind == SECTION_SKY && key == scene_key_find(SECTION_SKY, "cubemap"))
        s->cubemap_line = line;
}

static const struct conf_schema scene_schema = {
    .what = "scene file",
    .max_bytes = SCENE_MAX_FILE_BYTES,
    .n_kinds = SECTION_COUNT,
    .kind_name = kind_name,
    .kind_named = kind_named,
    .kind_list = scene_section_list,
    .name_ok = scene_instance_name_ok,
    .name_max = SCENE_NAME_LEN - 1,
    .keys = &scene_key_table,
    .open = open_section,
    .applied = applied,
};

/* Directory and base name of the scene file: assets resolve against the first, the second names
 * the scene until [scene] name says otherwise. */
static void split_path(struct scene *s, const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    size_t base_len = dot && dot != base ? (size_t)(dot - base) : strlen(base);

    conf_path_dir(path, s->dir, sizeof s->dir);
    if (base_len >= sizeof s->name)
        base_len = sizeof s->name - 1;
    if (base_len > 0)
        snprintf(s->name, sizeof s->name, "%.*s", (int)base_len, base);
}

int scene_load(struct scene *s, const char *path, struct error *err)
{
    size_t path_len = strlen(path);

    memset(err, 0, sizeof *err);
    scene_defaults(s);
    if (path_len >= sizeof s->path) {
        char where[80];
        snprintf(where, sizeof where, "%.64s...", path);
        return error_set(err, ERROR_INPUT, where, "the path is longer than %d characters", SCENE_PATH_LEN - 1);
    }
    memcpy(s->path, path, path_len + 1);
    split_path(s, path);

    if (conf_read(path, &scene_schema, s, err) != 0)
        return -1;
    memcpy(err->where, path, path_len + 1);
    scene_default_method(s);
    return scene_kiosk_validate(s, err);
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
static int set_fail(struct error *err, const char *fmt, ...)
{
    va_list ap;
    err->status = ERROR_INPUT;
    va_start(ap, fmt);
    vsnprintf(err->message, sizeof err->message, fmt, ap);
    va_end(ap);
    return -1;
}

int scene_set(struct scene *s, const char *assignment, struct error *err)
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
    section = conf_trim(path);
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
    /* an object's geometry is its type's keys: another type would keep none of them and draw the
     * new type's defaults, silently somewhere else */
    if (kind == SECTION_OBJECT && strcmp(conf_trim(key), "type") == 0)
        return set_fail(err, "an object's type is not changed with --set: its geometry is written with the keys "
                        "of its type; give the object of the other type in the scene file");
    value = strdup(eq + 1);
    if (!value)
        return set_fail(err, "out of memory");
    char where[sizeof err->where];
    memcpy(where, err->where, sizeof where);
    rc = scene_key_apply(s, (enum scene_section_kind)kind, instance, key, conf_trim(value), err);
    free(value);
    /* the option is where the value came from */
    memcpy(err->where, where, sizeof where);
    /* a model or a step control set here may change what an unnamed method defaults to */
    scene_default_method(s);
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
