/* Reading the kiosk configuration file. The file is read by the shared configuration reader
 * (conf/conf_reader.h: lines, headers, duplicates, continuation lines, FILE:LINE), as scene files
 * are; this file brings the kiosk's schema (kiosk_config_keys.c), the required keys, the scene
 * list that goes on over indented lines, and what can only be settled once the whole file is read. */
#include <assert.h>
#include <ctype.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "conf/conf_path.h"
#include "conf/conf_reader.h"
#include "kiosk_config/kiosk_config.h"
#include "kiosk_config/kiosk_config_keys.h"

static_assert(KIOSK_SINGLE_SECTIONS + KIOSK_MAX_BUTTONS + KIOSK_MAX_INPUTS <= CONF_MAX_SECTIONS, "sections");
static_assert(KIOSK_KEY_TABLE_MAX <= CONF_MAX_KEYS && KIOSK_NAME_LEN <= CONF_NAME_MAX, "keys and names");

static const char *kind_name(int kind) { return kiosk_section_name((enum kiosk_section)kind); }
static int kind_named(int kind) { return kiosk_section_named((enum kiosk_section)kind); }

static int open_section(void *target, int kind, const char *name, int line, int *instance, struct error *e)
{
    struct kiosk_config *c = target;
    *instance = 0;
    if (kind == KSEC_BUTTON) {
        if (c->n_buttons >= KIOSK_MAX_BUTTONS) {
            error_set(e, ERROR_INPUT, NULL, "too many buttons: at most %d", KIOSK_MAX_BUTTONS);
            return -1;
        }
        *instance = c->n_buttons++;
        kiosk_button_defaults(&c->buttons[*instance], name);
    } else if (kind == KSEC_INPUT) {
        if (c->n_inputs >= KIOSK_MAX_INPUTS) {
            error_set(e, ERROR_INPUT, NULL, "too many inputs: at most %d", KIOSK_MAX_INPUTS);
            return -1;
        }
        *instance = c->n_inputs++;
        kiosk_input_defaults(&c->inputs[*instance], name);
    }
    c->source.header[kiosk_slot((enum kiosk_section)kind, *instance)] = line;
    return 0;
}

/* Where each key was set: the checks after the file and the kiosk's messages point at it. */
static void applied(void *target, int kind, int instance, int key, int line)
{
    struct kiosk_config *c = target;
    c->source.key[kiosk_slot((enum kiosk_section)kind, instance)][key] = line;
}

/* A scene list longer than inih's line limit goes on over indented lines. */
static int continues(int kind, const char *key) { return kind == KSEC_KIOSK && strcmp(key, "scenes") == 0; }

static int continuation(void *target, int kind, int instance, const char *key, const char *item, struct error *e)
{
    (void)kind;
    (void)instance;
    (void)key;
    return kiosk_scenes_append(target, item, e);
}

static const struct conf_schema kiosk_schema = {
    .what = "kiosk configuration",
    .max_bytes = KIOSK_MAX_FILE_BYTES,
    .long_line_hint = ": shorten it (a long 'scenes' list goes on over indented lines)",
    .n_kinds = KSEC_COUNT,
    .kind_name = kind_name,
    .kind_named = kind_named,
    .kind_list = kiosk_section_list,
    .name_ok = kiosk_name_ok,
    .name_max = KIOSK_NAME_LEN - 1,
    .keys = &kiosk_key_table,
    .open = open_section,
    .applied = applied,
    .continues = continues,
    .continuation = continuation,
};

__attribute__((format(printf, 4, 5)))
static int fail(struct error *err, const char *path, int line, const char *fmt, ...)
{
    va_list ap;
    err->status = ERROR_INPUT;
    snprintf(err->where, sizeof err->where, "%s:%d", path, line);
    va_start(ap, fmt);
    vsnprintf(err->message, sizeof err->message, fmt, ap);
    va_end(ap);
    return -1;
}

/* What can only be settled once the whole file is read: start_scene may come before scenes, and a
 * knob's start follows its min unless given. */
static int finish_file(struct kiosk_config *c, struct error *err)
{
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
            return fail(err, c->path, line, "key 'start_scene' in [kiosk]: index %.8s is past the end of "
                        "'scenes', which lists %d (0 is the first)", want, c->kiosk.n_scenes);
        c->kiosk.start_scene = (int)index;
        return 0;
    }
    int found = kiosk_scene_find(c, want);
    if (found == -1)
        return fail(err, c->path, line, "key 'start_scene' in [kiosk]: no scene in 'scenes' is called '%s' "
                    "(a scene's name is its file name without the extension)", want);
    if (found == -2)
        return fail(err, c->path, line, "key 'start_scene' in [kiosk]: more than one scene is called '%s': "
                    "give its index instead", want);
    c->kiosk.start_scene = found;
    return 0;
}

int kiosk_config_load(struct kiosk_config *c, const char *path, struct error *err)
{
    size_t path_len = strlen(path);

    memset(err, 0, sizeof *err);
    kiosk_config_defaults(c);
    if (path_len >= sizeof c->path) {
        char where[80];
        snprintf(where, sizeof where, "%.64s...", path);
        return error_set(err, ERROR_INPUT, where, "the path is longer than %d characters", KIOSK_PATH_LEN - 1);
    }
    memcpy(c->path, path, path_len + 1);
    conf_path_dir(path, c->dir, sizeof c->dir);

    if (conf_read(path, &kiosk_schema, c, err) != 0)
        return -1;
    memcpy(err->where, path, path_len + 1);
    return finish_file(c, err);
}
