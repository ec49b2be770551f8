/* Files of the project found from the program's own place, so that a command works from any
 * directory: in the source tree the binary was built in (its directory or up to three above: the
 * sanitizer build lives in build/asan/), or where `make install` / kiosk/install.sh put them. */
#ifndef BT_TREE_FILE_H
#define BT_TREE_FILE_H
#include <stddef.h>

/* The first readable of: rel from the working directory; rel beside the program or up to three
 * directories above it; installed (PREFIX/share/bentray/, with a leading "assets/" of rel dropped).
 * 0 with its path in out, -1 where none is. */
int tree_file_find(const char *rel, char *out, size_t len);

#endif
