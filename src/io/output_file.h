/* Files bentray writes (images, dumps): each is written to a temporary beside its final name and
 * moved into place only once it is complete and on disk, so that a full disk, a file-size limit,
 * a write error or a signal never truncates or deletes what was there. Only a regular file is
 * ever replaced, or a symbolic link, which is replaced itself and never followed; a directory, a
 * device, a FIFO or a socket at the path is refused. */
#ifndef BENTRAY_OUTPUT_FILE_H
#define BENTRAY_OUTPUT_FILE_H

#include <stddef.h>
#include <stdio.h>

#include "io/error.h"

struct output_file {
    FILE *fp;                 /* write here */
    char *tmp;                /* the temporary, removed unless committed */
    const char *path;
    int overwrite;
};

/* Whether PATH can be written before any work is done: its directory exists, and nothing is
 * there, or (with OVERWRITE) a regular file or a link. 0, or -1 with the message in *e:
 * ERROR_INPUT for a refused path, ERROR_RUNTIME for a failure of the machine. */
int output_check(const char *path, int overwrite, struct error *e);
/* 1 when the two paths name the same file (the same text, or the same directory and name, or
 * the same existing file through links). */
int output_same(const char *a, const char *b);
/* Opens the temporary for PATH. 0, or -1 with the message in *e (as output_check). */
int output_open(struct output_file *o, const char *path, int overwrite, struct error *e);
/* Flushes, syncs and closes the temporary and moves it to its name (without overwrite, only if
 * that name is still free). On failure the temporary is removed and the old file kept: -1 with
 * the message in *e (ERROR_RUNTIME for a write that failed, ERROR_INPUT for a name taken or
 * turned into something else meanwhile). */
int output_commit(struct output_file *o, struct error *e);
/* Closes and removes the temporary: nothing is written. */
void output_abort(struct output_file *o);

#endif
