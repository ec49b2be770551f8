/* The one error type of bentray: what went wrong (message), where ("FILE:LINE", "--set
 * model.mass=x", a file alone, or "" where no place applies), and whose it is (status: the exit
 * code the command ends with). Every module fills it the same way, and one helper prints it as
 * "WHERE: error: MESSAGE". */
#ifndef BT_ERROR_H
#define BT_ERROR_H
#include <stdio.h>

/* The documented exit codes of a failure (docs/bentray.1): the machine's, or the user's input. */
enum error_status {
    ERROR_NONE = 0,
    ERROR_RUNTIME = 1,      /* the machine: no GPU, out of memory, a file that cannot be written */
    ERROR_INPUT = 2         /* the user: a bad scene, option or request, refused before any work */
};

struct error {
    enum error_status status;
    char where[600];
    char message[2048];         /* room for a shader's compile log */
};

/* Fills E (status, where, message from FMT) and returns -1, so that a failure is one statement:
 * `return error_set(e, ERROR_INPUT, path, "...", ...);`. WHERE may be NULL for none. */
__attribute__((format(printf, 4, 5)))
int error_set(struct error *e, enum error_status status, const char *where, const char *fmt, ...);
/* Whose failure it is when a path the user named cannot be checked, opened or read (errno of
 * stat, access or open; 0 where it is there but not a regular file): the user's where the path
 * itself is refused (missing, not a regular file, not readable or writable, a read-only file
 * system, too long, a loop of links, a device without its driver), else the machine's (no
 * memory, an I/O error, a full disk, too many open files). */
enum error_status error_status_of_errno(int errnum);
/* Clears E: no status, no place, no message. */
void error_clear(struct error *e);
/* "PROGRAM: WHERE: error: MESSAGE" (the parts that are there) on OUT. */
void error_print(const struct error *e, const char *program, FILE *out);
/* "WHERE: MESSAGE", or MESSAGE alone where E names no place, into BUF (cut to LEN bytes), for a
 * caller that writes the error into a line of its own. Returns -1, as error_set does. */
int error_format(const struct error *e, char *buf, size_t len);

#endif
