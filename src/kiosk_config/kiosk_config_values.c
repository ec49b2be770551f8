/* Applying a value to a key of the kiosk's configuration (through conf/conf_key.h, which parses it
 * as the table says and words every message), and the setters of what a field copy cannot store. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "kiosk_config/kiosk_config_keys.h"

static int word_ok(const char *text)
{
    size_t n = strlen(text);
    if (n == 0 || n >= KIOSK_NAME_LEN)
        return 0;
    for (size_t i = 0; i < n; i++)
        if (!isgraph((unsigned char)text[i]))
            return 0;
    return 1;
}

int kiosk_key_apply(struct kiosk_config *c, enum kiosk_section section, int instance,
                    const char *name, const char *value, struct error *e)
{
    return conf_key_apply(&kiosk_key_table, c, (int)section, instance, name, value, e);
}

/* ---- setters ------------------------------------------------------------------------------- */

/* Resolved once the whole file is read, since [kiosk] scenes may come after it. */
int kiosk_set_start_scene(void *owner, void *t, const union conf_parsed *v, struct error *e)
{
    struct kiosk_config *c = owner;
    (void)t;
    if (!word_ok(v->text)) {
        error_set(e, ERROR_INPUT, NULL, "expected a scene's index (0 is the first) or its name, got \"%.*s\"",
                 CONF_QUOTE_MAX, v->text);
        return -1;
    }
    snprintf(c->kiosk.start_scene_name, sizeof c->kiosk.start_scene_name, "%s", v->text);
    return 0;
}

/* "1920x1080" */
int kiosk_set_mode(void *owner, void *t, const union conf_parsed *v, struct error *e)
{
    struct kiosk_config *c = owner;
    const char *value = v->text;
    char *x, *end = NULL;
    long w = 0, h = 0;
    (void)t;
    if (isdigit((unsigned char)value[0])) {
        w = strtol(value, &x, 10);
        if (*x == 'x' && isdigit((unsigned char)x[1]))
            h = strtol(x + 1, &end, 10);
    }
    if (!end || *end != '\0' || w < KIOSK_MIN_SIZE || w > KIOSK_MAX_SIZE || h < KIOSK_MIN_SIZE ||
        h > KIOSK_MAX_SIZE) {
        error_set(e, ERROR_INPUT, NULL, "expected WIDTHxHEIGHT such as 1920x1080, each from %d to %d, got "
                 "\"%.*s\"", KIOSK_MIN_SIZE, KIOSK_MAX_SIZE, CONF_QUOTE_MAX, value);
        return -1;
    }
    c->display.mode_width = (int)w;
    c->display.mode_height = (int)h;
    return 0;
}

/* Each type starts from its own defaults: the PowerMate's USB ids. */
int kiosk_set_input_type(void *owner, void *t, const union conf_parsed *v, struct error *e)
{
    struct kiosk_input *in = t;
    (void)owner, (void)e;
    in->type = (enum kiosk_input_type)v->integer;
    if (in->type == KIOSK_INPUT_POWERMATE) {
        in->vid = KIOSK_POWERMATE_VID;
        in->pid = KIOSK_POWERMATE_PID;
    }
    return 0;
}
