/* One key of a configuration file, described once in its file kind's table (section, name, kind,
 * range, choices, the types it applies to, where it is stored), and the one function that applies a
 * value to it. Scenes (src/scene/scene_keys.c) and the kiosk's configuration
 * (src/kiosk_config/kiosk_config_keys.c) keep only their tables and the setters of what a field copy
 * cannot store; finding the key, "did you mean", the types a key belongs to, parsing, ranges and the
 * words of every message are here, so that both files read values the same way. */
#ifndef BT_CONF_KEY_H
#define BT_CONF_KEY_H
#include <stddef.h>
#include <stdint.h>
#include "conf/conf_value.h"
#include "io/error.h"

enum conf_kind {
    CONF_NUMBER,        /* one double in [lo, hi] */
    CONF_INTEGER,       /* one int in [lo, hi] */
    CONF_INT64,         /* one int64_t in [lo, hi] */
    CONF_VECTOR,        /* "x y z", any finite components (CONF_NONZERO: not all zero) */
    CONF_COLOR,         /* "r g b", each component in [lo, hi] */
    CONF_TEXCOORD,      /* "u v" */
    CONF_CHOICE,        /* one of the names in choices, stored as its int value */
    CONF_HEX16,         /* 0x0000 .. 0xffff, written with 0x (USB ids) */
    CONF_NAME,          /* letters, digits, '_' and '-': a reference to a named section */
    CONF_WORD,          /* any text without blanks (GPIO chips, line names, connectors) */
    CONF_TEXT,          /* lo..hi bytes, stored in a char array of hi + 1 */
    CONF_PATH,          /* a path relative to the file's directory; the setter checks and stores it */
    CONF_FILE,          /* a readable regular file, relative to the file's directory, stored joined */
    CONF_DIR,           /* an existing directory, likewise */
    CONF_SPECIAL        /* the text as written, parsed and stored by the setter */
};

/* A vector that gives a direction: not all components zero. */
#define CONF_NONZERO 8u

struct conf_choice {
    const char *name;
    int value;
};

/* A value as parsed for its key's kind. */
union conf_parsed {
    double number;      /* CONF_NUMBER */
    int integer;        /* CONF_INTEGER, CONF_CHOICE (the choice's value), CONF_HEX16 */
    int64_t int64;      /* CONF_INT64 */
    double v[3];        /* CONF_VECTOR, CONF_COLOR, CONF_TEXCOORD (two) */
    const char *text;   /* CONF_NAME, CONF_WORD, CONF_TEXT, CONF_PATH, CONF_SPECIAL: as written;
                           CONF_FILE, CONF_DIR: joined with the file's directory */
};

/* Stores a parsed value where a plain field copy is not enough (a check against other keys, a
 * file to look at, an enumeration's own defaults). owner is the whole configuration (the scene,
 * the kiosk's configuration), target the section instance's struct (the owner, an object, an
 * input). On failure it returns -1 with why in e (ERROR_INPUT, no place); the caller adds the key
 * and the section. */
typedef int (*conf_setter)(void *owner, void *target, const union conf_parsed *v, struct error *e);

struct conf_key {
    int section;                        /* the file kind's section enumeration */
    const char *name;
    enum conf_kind kind;
    double lo, hi;                      /* the range; for CONF_TEXT the length */
    unsigned flags;                     /* CONF_ABOVE_LO, CONF_BELOW_HI, CONF_REQUIRED, CONF_NONZERO */
    const struct conf_choice *choices;  /* CONF_CHOICE: ends with a NULL name */
    unsigned applies;                   /* bits of the section's type (a model, a primitive, an
                                           input type); 0: every type. One name may have one entry
                                           per group of types, next to each other. */
    size_t offset;                      /* where the value goes in target, when set is NULL */
    conf_setter set;                    /* stores the value instead of the field copy */
    const char *hint;                   /* added to the message when the value is refused */
};

/* A file kind's keys: the table, and what only that kind knows (its sections' labels and types,
 * where its paths start, its largest number). */
struct conf_key_table {
    const struct conf_key *keys;
    int count;
    size_t name_len;                    /* CONF_NAME and CONF_WORD: fewer bytes than this */
    size_t path_len;                    /* paths: fewer bytes than this */
    double max_abs;                     /* numbers larger in magnitude are refused (0: no limit) */
    const char *max_abs_reason;         /* and the message says why */
    const char *relative_note;          /* where relative paths start, for a missing file */
    /* "[camera]" or "[object earth]" */
    void (*label)(const void *owner, int section, int instance, char *buf, size_t len);
    /* The struct a key of the section instance is stored in. */
    void *(*target)(void *owner, int section, int instance);
    /* Sections whose keys depend on a type: the word for it ("model", "input type"), NULL for
     * sections without types. */
    const char *(*type_word)(int section);
    /* The instance's type, 0 .. 15; only asked for sections with a type_word. */
    int (*type_of)(const void *owner, int section, int instance);
    /* The name of type t of the section. */
    const char *(*type_name)(int section, int t);
    /* REL against the file's directory (absolute paths are kept): 0, or -1 if it does not fit. */
    int (*resolve_path)(const void *owner, const char *rel, char *out, size_t len);
};

/* Index of the first entry of SECTION called NAME, -1 when the section has no such key. */
int conf_key_find(const struct conf_key_table *table, int section, const char *name);
/* The entry of NAME that applies to the section instance's type; NULL when the key does not exist
 * or does not apply (then conf_key_apply says which). */
const struct conf_key *conf_key_for(const struct conf_key_table *table, const void *owner, int section,
                                    int instance, const char *name);
/* Parse VALUE for key NAME of a section instance and store it: 0, or -1 with the whole message in
 * e ("unknown key 'x' in [camera] (did you mean 'fov'?)", "key 'fov' in [camera]: expected ...,
 * got ..."; ERROR_INPUT, no place: the caller knows the file and line, or the option). */
int conf_key_apply(const struct conf_key_table *table, void *owner, int section, int instance,
                   const char *name, const char *value, struct error *e);
/* The same for a number that comes as a number (a knob), checked as a number written in the file
 * would be: finite, a normal double, within the table's limit and the key's range. The key must
 * be a CONF_NUMBER. */
int conf_key_apply_number(const struct conf_key_table *table, void *owner, int section, int instance,
                          const char *name, double value, struct error *e);
/* "a number from 0 to 1", "one of off, on", for messages and help. */
void conf_key_expected(const struct conf_key_table *table, const struct conf_key *k, char *buf, size_t len);
/* For a section that ended: 0 when every CONF_REQUIRED key of its type was given (key_line[k]:
 * where key k, its index in the table, was set; 0 where not), else -1 with the message in e: "[input
 * knob] has no type: add 'type = powermate', ... or 'script'" for a section with types, then
 * "[input knob] of type 'hid' needs 'vid'", "[button b] needs 'action'". */
int conf_key_check_required(const struct conf_key_table *table, const void *owner, int section, int instance,
                            const int *key_line, struct error *e);
/* The name of choice VALUE among CHOICES, "?" if none has it. */
const char *conf_choice_name(const struct conf_choice *choices, int value);

#endif
