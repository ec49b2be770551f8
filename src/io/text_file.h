/* What the scene loader and the kiosk configuration share before any key is read: the whole file
 * read with a size limit, its lines split one by one (CR, NUL bytes, a UTF-8 byte-order mark on
 * the first line), and the edit distance that turns a misspelt key into a suggestion. */
#ifndef BT_TEXT_FILE_H
#define BT_TEXT_FILE_H
#include <stddef.h>

#include <stdio.h>

#include "io/error.h"

/* Opens path for reading only if it is a regular file: a FIFO, device, socket or directory is
 * refused at once (the open itself never blocks: O_NONBLOCK, then fstat). NULL with e: its place
 * the path, its message "cannot open the WHAT: ..." or "cannot read the WHAT: ...", its status the
 * user's (ERROR_INPUT) where the path is refused, the machine's where the system fails
 * (error_status_of_errno). */
FILE *regular_file_open(const char *path, const char *what, struct error *e);

/* The file's bytes (NUL-terminated for convenience) and their count, or NULL with e as
 * regular_file_open sets it: it cannot be opened or read, it is larger than max_bytes ("not a
 * WHAT?", the user's), or there is no memory for it (the machine's). what names the kind of file in
 * the messages ("scene file"). */
char *text_file_read(const char *path, long max_bytes, const char *what, size_t *len, struct error *e);

/* A cursor over a text's lines. */
struct text_lines {
    const char *text;
    size_t len, pos;
    int line;               /* number of the line last returned, from 1 */
};

/* The next line without its end (LF or CRLF), and on the first line without a byte-order mark.
 * 1 with *start and *n set, 0 at the end, -1 with e (ERROR_INPUT, no place: the caller knows the
 * file and t->line) for a NUL byte: not text. */
int text_lines_next(struct text_lines *t, const char **start, size_t *n, struct error *e);

/* Levenshtein distance of two short names; a large number for names longer than max_len. */
int edit_distance(const char *a, const char *b, size_t max_len);

#endif
