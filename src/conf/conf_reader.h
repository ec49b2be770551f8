/* Reading an INI-style configuration file: the scene files and the kiosk configuration share this
 * reader, and each brings only its schema (its sections and keys, and what a key's value sets).
 *
 * The reader takes the whole file (bounded in size, a regular file only: io/text_file.h), hands
 * its lines to inih one at a time so that every message knows its line, and reads section headers
 * itself (inih would cut long names and skip empty sections silently). What it settles the same
 * way for every schema, with the first error at FILE:LINE:
 *   - headers: '[kind]' or '[kind NAME]', nothing but a comment after ']', a known kind (else
 *     the kinds, and the nearest within two edits as "did you mean"), a name exactly where the
 *     kind takes one, a section given twice;
 *   - lines: a NUL byte, a line too long for inih's buffer (refused, never cut), a key before any
 *     section, '=' without a key, anything that is neither a pair, a header nor a comment;
 *   - keys: a key given twice in one section, a key before the 'type' of a section whose type
 *     decides its other keys, the value itself (applied through the schema's key table,
 *     conf/conf_key.h), a section that ends without its type or a key it requires;
 *   - continuation lines: a key whose value the schema lets go on takes the indented lines after
 *     it, one item each (a comment line leaves one out; a blank, unindented or '=' line ends it).
 * Indentation is otherwise only layout. */
#ifndef BT_CONF_READER_H
#define BT_CONF_READER_H
#include <stddef.h>
#include "conf/conf_key.h"
#include "io/error.h"

/* Keys a schema's table may hold (conf_key_table.count); sections per file; bytes of
 * an instance name with its NUL (a schema keeps names no longer). */
#define CONF_MAX_KEYS 256
#define CONF_MAX_SECTIONS 256
#define CONF_NAME_MAX 64

/* Errors are the one error type (io/error.h): where is "FILE:LINE", or FILE alone for a problem with
 * the whole file; status is ERROR_INPUT. */

struct conf_schema {
    const char *what;                  /* "scene file": names the file in messages */
    long max_bytes;                    /* larger files are refused */
    const char *long_line_hint;        /* added to the message for a line too long, or NULL */
    int n_kinds;                       /* section kinds 0 .. n_kinds - 1 */
    const char *(*kind_name)(int kind);
    int (*kind_named)(int kind);       /* 1: '[kind NAME]', 0: '[kind]' */
    const char *(*kind_list)(void);    /* "scene, camera, ...": the kinds, for messages */
    int (*name_ok)(const char *name);  /* an instance name the schema can keep */
    int name_max;                      /* its longest, for the message */
    /* every key of every section, applied by conf/conf_key.h: what a key's value sets, the types
     * a key applies to (a section with types takes its 'type' first), the required keys */
    const struct conf_key_table *keys;
    /* a section starts at line: its instance (index of a named kind's instances, else 0); -1 with
     * the reason in e when the schema has no room for another */
    int (*open)(void *target, int kind, const char *name, int line, int *instance, struct error *e);
    /* NULL, or: the section ended (next header or end of file) with its required keys, checked
     * first: -1 with the reason in e, told at its header's line. key_line[k]: where key k (its index
     * in the table) was set in it, 0 where not. */
    int (*close)(void *target, int kind, int instance, const int *key_line, struct error *e);
    /* NULL, or: key (its index in the table) was set at line in the section: where it came from,
     * for a message about it later */
    void (*applied)(void *target, int kind, int instance, int key, int line);
    /* NULL, or 1 where the key's value goes on over indented lines, each handed to continuation
     * (-1 with the reason in e, told as "key 'KEY' in LABEL: REASON") */
    int (*continues)(int kind, const char *key);
    int (*continuation)(void *target, int kind, int instance, const char *key, const char *item, struct error *e);
};

/* Reads path into target by schema: 0, or -1 with the first error in err. */
int conf_read(const char *path, const struct conf_schema *schema, void *target, struct error *err);

/* p without its leading and trailing white space (cut in place). */
char *conf_trim(char *p);

/* The kind name within two edits of name (and nearer than its length), or NULL. */
const char *conf_kind_guess(const struct conf_schema *schema, const char *name);

#endif
