/* Files and directories named by the configuration: joined with the configuration file's
 * directory, so the kiosk can be started from anywhere, and checked when they are read, so that a
 * missing file is reported at its line instead of when a visitor first reaches it. */
/* realpath() is X/Open, beyond the POSIX base the project builds against */
#define _XOPEN_SOURCE 700
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>
#include "kiosk_config/kiosk_config_keys.h"
#include "conf/conf_path.h"

/* What a list entry may be separated by. */
#define SCENE_SEPARATORS ", \t"

int kiosk_resolve_path(const struct kiosk_config *c, const char *rel, char *out, size_t out_len)
{
    return conf_path_join(c->dir, rel, out, out_len);
}

int kiosk_path_inside(const char *path, const char *root, struct error *e)
{
    char *real_path = realpath(path, NULL), *real_root = realpath(root, NULL);
    int inside = -1;
    if (!real_path || !real_root) {
        error_set(e, ERROR_INPUT, NULL, "cannot resolve \"%s\": %s", real_path ? root : path, strerror(errno));
    } else {
        size_t n = strlen(real_root);
        /* "/srv/assets2" is not inside "/srv/assets": the match has to end at a '/' */
        inside = strcmp(real_root, "/") == 0 ||
                 (strncmp(real_path, real_root, n) == 0 && real_path[n] == '/');
        if (!inside)
            error_set(e, ERROR_INPUT, NULL, "\"%s\" is \"%s\", outside assets_root \"%s\"", path, real_path,
                     real_root);
    }
    free(real_path);
    free(real_root);
    return inside;
}

/* ---- setters ------------------------------------------------------------------------------- */

/* "a.scene, b.scene c.scene": commas or blanks between entries. An empty entry between two commas
 * is a slip (a deleted name), not a separator; a comma at the end of a line is not, since the list
 * may go on on the next. Paths with blanks cannot be listed. */
int kiosk_scenes_append(struct kiosk_config *c, const char *text, struct error *e)
{
    struct kiosk_main *k = &c->kiosk;
    const char *p = text;
    int after_comma = 0;

    while (*p) {
        size_t word = strcspn(p, SCENE_SEPARATORS);
        if (word == 0) {
            if (*p == ',' && after_comma) {
                error_set(e, ERROR_INPUT, NULL, "empty entry in the list after scene %d: remove the extra ','",
                         k->n_scenes);
                return -1;
            }
            if (*p == ',')
                after_comma = 1;
            p++;
            continue;
        }
        if (k->n_scenes >= KIOSK_MAX_SCENES) {
            error_set(e, ERROR_INPUT, NULL, "more than %d scenes", KIOSK_MAX_SCENES);
            return -1;
        }
        char rel[KIOSK_PATH_LEN];
        struct error why;
        char *path = k->scenes[k->n_scenes];
        int number = k->n_scenes + 1;
        if (word < sizeof rel) {
            memcpy(rel, p, word);
            rel[word] = '\0';
        }
        if (word >= sizeof rel || kiosk_resolve_path(c, rel, path, KIOSK_PATH_LEN) != 0) {
            error_set(e, ERROR_INPUT, NULL, "scene %d: the path is longer than %d characters", number,
                     KIOSK_PATH_LEN - 1);
            return -1;
        }
        if (conf_check_file(path, KIOSK_RELATIVE_NOTE, &why) != 0) {
            error_set(e, ERROR_INPUT, NULL, "scene %d: %s", number, why.message);
            return -1;
        }
        k->n_scenes++;
        after_comma = 0;
        p += word;
    }
    return 0;
}

int kiosk_set_scenes(void *owner, void *t, const union conf_parsed *v, struct error *e)
{
    struct kiosk_config *c = owner;
    const char *value = v->text;
    (void)t;
    c->kiosk.n_scenes = 0;
    return kiosk_scenes_append(c, value, e);
}

/* A log file need not exist yet, but the directory it goes into must. */
int kiosk_set_log(void *owner, void *t, const union conf_parsed *v, struct error *e)
{
    struct kiosk_config *c = owner;
    const char *value = v->text;
    char path[KIOSK_PATH_LEN], dir[KIOSK_PATH_LEN];
    struct stat st;
    const char *slash;
    (void)t;
    if (strcmp(value, "stderr") == 0) {
        snprintf(c->kiosk.log, sizeof c->kiosk.log, "stderr");
        return 0;
    }
    if (kiosk_resolve_path(c, value, path, sizeof path) != 0) {
        error_set(e, ERROR_INPUT, NULL, "the path is longer than %d characters", KIOSK_PATH_LEN - 1);
        return -1;
    }
    slash = strrchr(path, '/');
    if (!slash)
        snprintf(dir, sizeof dir, ".");
    else
        snprintf(dir, sizeof dir, "%.*s", slash == path ? 1 : (int)(slash - path), path);
    if (conf_check_dir(dir, KIOSK_RELATIVE_NOTE, e) != 0)
        return -1;
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
        error_set(e, ERROR_INPUT, NULL, "\"%s\" exists and is not a regular file", path);
        return -1;
    }
    memcpy(c->kiosk.log, path, sizeof path);
    return 0;
}

/* Not looked for here: at boot the card may appear after the kiosk's configuration is read, and the
 * display code says so when it opens it. */
int kiosk_set_device(void *owner, void *t, const union conf_parsed *v, struct error *e)
{
    struct kiosk_config *c = owner;
    const char *value = v->text;
    (void)t;
    if (value[0] != '/' || strlen(value) >= sizeof c->display.drm_device) {
        error_set(e, ERROR_INPUT, NULL, "expected an absolute device path such as /dev/dri/card0 (at most %d "
                 "characters), got \"%.80s\"", KIOSK_PATH_LEN - 1, value);
        return -1;
    }
    snprintf(c->display.drm_device, sizeof c->display.drm_device, "%s", value);
    return 0;
}

int kiosk_scene_find(const struct kiosk_config *c, const char *name)
{
    int found = -1;
    for (int i = 0; i < c->kiosk.n_scenes; i++) {
        const char *slash = strrchr(c->kiosk.scenes[i], '/');
        const char *base = slash ? slash + 1 : c->kiosk.scenes[i];
        const char *dot = strrchr(base, '.');
        size_t n = dot && dot != base ? (size_t)(dot - base) : strlen(base);
        if (strlen(name) == n && strncmp(base, name, n) == 0) {
            if (found >= 0)
                return -2;
            found = i;
        }
    }
    return found;
}

#define KIOSK_CONFIG_IN_TREE "kiosk/kiosk.conf"
#define KIOSK_CONFIG_INSTALLED "/etc/bentray/kiosk.conf"

int kiosk_config_default_path(char *out, size_t len, struct error *e)
{
    char exe[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n > 0) {
        exe[n] = '\0';
        for (int up = 0; up <= 3; up++) {
            char *slash = strrchr(exe, '/');
            if (!slash)
                break;
            *slash = '\0';
            if (snprintf(out, len, "%s/%s", exe, KIOSK_CONFIG_IN_TREE) < (int)len && access(out, R_OK) == 0)
                return 0;
        }
    }
    if (access(KIOSK_CONFIG_INSTALLED, R_OK) == 0 && snprintf(out, len, "%s", KIOSK_CONFIG_INSTALLED) < (int)len)
        return 0;
    return error_set(e, ERROR_INPUT, NULL, "no kiosk configuration found: none at %s beside this program or above it, "
                     "none at %s (kiosk/install.sh puts one there); name one with --config FILE",
                     KIOSK_CONFIG_IN_TREE, KIOSK_CONFIG_INSTALLED);
}
