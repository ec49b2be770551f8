/* Filling and printing the one error type. */
#include <errno.h>
#include <stdarg.h>
#include <string.h>
#include "io/error.h"

int error_set(struct error *e, enum error_status status, const char *where, const char *fmt, ...)
{
    va_list ap;
    e->status = status;
    snprintf(e->where, sizeof e->where, "%s", where ? where : "");
    va_start(ap, fmt);
    vsnprintf(e->message, sizeof e->message, fmt, ap);
    va_end(ap);
    return -1;
}

void error_clear(struct error *e)
{
    memset(e, 0, sizeof *e);
}

void error_print(const struct error *e, const char *program, FILE *out)
{
    fprintf(out, "%s%s%s%serror: %s\n", program ? program : "", program ? ": " : "", e->where,
            e->where[0] ? ": " : "", e->message);
}

int error_format(const struct error *e, char *buf, size_t len)
{
    if (e->where[0])
        snprintf(buf, len, "%s: %s", e->where, e->message);
    else
        snprintf(buf, len, "%s", e->message);
    return -1;
}

enum error_status error_status_of_errno(int errnum)
{
    switch (errnum) {
    case 0: case EACCES: case EPERM: case ENOENT: case ENOTDIR: case EISDIR: case ENXIO: case EROFS:
    case ENAMETOOLONG: case ELOOP:
        return ERROR_INPUT;
    default:
        return ERROR_RUNTIME;
    }
}
