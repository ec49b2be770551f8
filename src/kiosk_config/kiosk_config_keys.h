/* The key table of the kiosk configuration (src/kiosk_config/; src/kiosk/kiosk_images.c asks it
 * for a key's line): every key the file may hold, described once (section, name, kind, range, the
 * input types it belongs to, where it is stored), applied by conf/conf_key.h, so that the loader,
 * the checks and the tests cannot disagree about a key. */
#ifndef BT_KIOSK_CONFIG_KEYS_H
#define BT_KIOSK_CONFIG_KEYS_H
#include <stddef.h>
#include "conf/conf_key.h"
#include "kiosk_config/kiosk_config.h"

/* No honest configuration comes near this; refusing earlier keeps a wrong path (a log, an image)
 * from being read into memory. */
#define KIOSK_MAX_FILE_BYTES (1L << 20)

enum kiosk_section {
    KSEC_KIOSK,
    KSEC_DISPLAY,
    KSEC_SPEED,
    KSEC_MASS,
    KSEC_ATTRACT,
    KSEC_BUTTON,        /* named: [button NAME] */
    KSEC_INPUT,         /* named: [input NAME], typed: its 'type' comes first */
    KSEC_COUNT
};

/* flags of the table's keys: CONF_ABOVE_LO, CONF_BELOW_HI and CONF_REQUIRED (conf/conf_key.h: the
 * section is incomplete without the key, for the input types it applies to) */

/* Where relative paths start, for the message about a file that is not there. */
#define KIOSK_RELATIVE_NOTE "relative paths start at the configuration file's directory"

extern const struct conf_key kiosk_keys[];
extern const int kiosk_key_count;
extern const struct conf_key_table kiosk_key_table;

const char *kiosk_section_name(enum kiosk_section section);
int kiosk_section_named(enum kiosk_section section);
/* "kiosk, display, ...", for messages. */
const char *kiosk_section_list(void);
/* "[speed]" or "[input knob]". */
void kiosk_section_label(const struct kiosk_config *c, enum kiosk_section section, int instance,
                         char *buf, size_t len);
/* Index into source.header and source.key of a section instance. */
int kiosk_slot(enum kiosk_section section, int instance);

/* Index of the table entry of SECTION called NAME, -1 when there is none. */
int kiosk_key_find(enum kiosk_section section, const char *name);
/* Line where the key was set in the file, 0 when it was not (or the key does not exist). */
int kiosk_key_line(const struct kiosk_config *c, enum kiosk_section section, int instance,
                   const char *name);
/* Parse VALUE for key NAME of a section instance and store it: 0, or -1 with the whole message in
 * e (ERROR_INPUT, no place). */
int kiosk_key_apply(struct kiosk_config *c, enum kiosk_section section, int instance,
                    const char *name, const char *value, struct error *e);

/* Section names: 1 to KIOSK_NAME_LEN - 1 of letters, digits, '_' and '-'. */
int kiosk_name_ok(const char *name);
/* REL against the config's directory (absolute paths are kept): 0, or -1 if it does not fit. */
int kiosk_resolve_path(const struct kiosk_config *c, const char *rel, char *out, size_t out_len);
/* Whether PATH, with ".." and symbolic links resolved, lies inside the directory ROOT: 1 inside,
 * 0 outside (with both resolved paths in e), -1 when either cannot be resolved (why, in e). */
int kiosk_path_inside(const char *path, const char *root, struct error *e);
/* Index of the scene called NAME (its file name without the extension), -1 if none is, -2 if
 * more than one is. */
int kiosk_scene_find(const struct kiosk_config *c, const char *name);

/* The table's setters (kiosk_config_values.c, kiosk_config_paths.c). */
int kiosk_set_scenes(void *owner, void *t, const union conf_parsed *v, struct error *e);
/* More scenes for the list, from a line that continues 'scenes'. */
int kiosk_scenes_append(struct kiosk_config *c, const char *text, struct error *e);
int kiosk_set_start_scene(void *owner, void *t, const union conf_parsed *v, struct error *e);
int kiosk_set_log(void *owner, void *t, const union conf_parsed *v, struct error *e);
int kiosk_set_device(void *owner, void *t, const union conf_parsed *v, struct error *e);
int kiosk_set_mode(void *owner, void *t, const union conf_parsed *v, struct error *e);
int kiosk_set_input_type(void *owner, void *t, const union conf_parsed *v, struct error *e);

void kiosk_button_defaults(struct kiosk_button *b, const char *name);
void kiosk_input_defaults(struct kiosk_input *in, const char *name);

#endif
