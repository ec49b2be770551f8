/* Files that a configuration names: relative paths start at the directory of the file that names
 * them (so that an exhibit or a scene can be started from anywhere), and what they name is looked at
 * when the file is read, so that a missing file is reported at its line. */
#ifndef BT_CONF_PATH_H
#define BT_CONF_PATH_H
#include <stddef.h>
#include "io/error.h"

/* The directory of the file at PATH: "." for a bare name, "/" for a file in the root. */
void conf_path_dir(const char *path, char *dir, size_t len);
/* REL against DIR (an absolute REL is kept; DIR "" or "." leaves REL as it is): 0, or -1 if it
 * does not fit in LEN bytes. */
int conf_path_join(const char *dir, const char *rel, char *out, size_t len);
/* PATH is a readable regular file (an existing directory): 0, or -1 with the reason in e
 * (ERROR_INPUT, no place), which quotes the path and, when it does not exist, adds NOTE (where
 * relative paths start; NULL: nothing). */
int conf_check_file(const char *path, const char *note, struct error *e);
int conf_check_dir(const char *path, const char *note, struct error *e);

#endif
