/* Private to src/scene: every key a scene may hold, described once in a table that conf/conf_key.h
 * applies for the file loader and --set alike, so that both accept exactly the same text. */
#ifndef BT_SCENE_KEYS_H
#define BT_SCENE_KEYS_H
#include <stddef.h>
#include "conf/conf_key.h"
#include "scene/scene.h"

/* No honest scene file comes near this; refusing earlier keeps a wrong path (a video, a disk image)
 * from being read into memory. */
#define SCENE_MAX_FILE_BYTES (1L << 20)
/* Rectangle half-edges may deviate from a right angle by this much (cosine of their angle). */
#define SCENE_RECT_ORTHO_TOL 1e-6
/* An accretion disk's centre may sit this far (relative to its radius) from the mass: roundings of
 * the scene's numbers. */
#define SCENE_ACCRETION_CENTRE_TOL 1e-9
/* Capacity of per-key bookkeeping arrays; the table is checked against it at compile time. */
#define SCENE_KEY_TABLE_MAX 160

enum scene_section_kind {
    SECTION_SCENE,
    SECTION_CAMERA,
    SECTION_OBSERVER,
    SECTION_RENDER,
    SECTION_MODEL,
    SECTION_LIGHTING,
    SECTION_LIGHT,      /* named: [light NAME] */
    SECTION_SKY,
    SECTION_OBJECT,     /* named: [object NAME] */
    SECTION_QUALITY,
    SECTION_KIOSK,
    SECTION_COUNT
};

/* The table of every key a scene may hold (conf/conf_key.h), and what only a scene knows: its
 * sections, the types of models and primitives, where relative paths start, the largest number. */
extern const struct conf_key scene_keys[];
extern const int scene_key_count;
extern const struct conf_key_table scene_key_table;

const char *scene_section_name(enum scene_section_kind section);
/* Section kind called NAME, -1 if there is none. */
int scene_section_find(const char *name);
/* Sections that stand for one of several instances and carry a name: [light NAME], [object NAME]. */
int scene_section_named(enum scene_section_kind section);
/* "scene, camera, ..., object NAME", for messages. */
const char *scene_section_list(void);
/* "[camera]" or "[object earth]"; instance is the light or object index of named sections. */
void scene_section_label(const struct scene *s, enum scene_section_kind section, int instance,
                         char *buf, size_t len);

/* Index of the first table entry of SECTION called NAME (a name may have one entry per model
 * type it applies to), -1 when the section has no such key. */
int scene_key_find(enum scene_section_kind section, const char *name);
/* Parse VALUE for key NAME of a section instance and store it. 0, or -1 with the full message in e
 * (ERROR_INPUT, no place). */
int scene_key_apply(struct scene *s, enum scene_section_kind section, int instance,
                    const char *name, const char *value, struct error *e);

const char *scene_model_type_name(enum model_type type);
const char *scene_primitive_name(enum primitive_type type);
/* Object and light names: 1 to SCENE_NAME_LEN - 1 of letters, digits, '_' and '-', so that they
 * survive being written as object.NAME.key on a command line. */
int scene_instance_name_ok(const char *name);
/* REL against the scene file's directory (absolute paths are kept). -1 if it does not fit. */
int scene_resolve_path(const struct scene *s, const char *rel, char *out, size_t out_len);

void scene_object_defaults(struct object *o, const char *name);
void scene_light_defaults(struct light *l, const char *name);

#endif
