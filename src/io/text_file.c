/* Whole-file reading, line splitting and edit distance for the INI readers (scene, kiosk). */
#include "io/text_file.h"
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* edit_distance() keeps one row of this many columns on the stack */
#define EDIT_MAX_LEN 256
#define EDIT_TOO_FAR 1000

FILE *regular_file_open(const char *path, const char *what, struct error *e)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        int errnum = errno;
        error_set(e, error_status_of_errno(errnum), path, "cannot open the %s: %s", what, strerror(errnum));
        return NULL;
    }
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        /* fstat failing is the system's; a file that is not a regular one is the user's */
        int errnum = S_ISREG(st.st_mode) ? errno : 0;
        error_set(e, error_status_of_errno(errnum), path, "cannot read the %s: %s", what,
                  errnum ? strerror(errnum)
                  : S_ISFIFO(st.st_mode) ? "it is a FIFO, not a regular file"
                  : S_ISDIR(st.st_mode) ? "it is a directory, not a regular file"
                  : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "it is a device, not a regular file"
                  : S_ISSOCK(st.st_mode) ? "it is a socket, not a regular file" : "not a regular file");
        close(fd);
        return NULL;
    }
    /* a regular file never blocks; reads go on as usual */
    int flags = fcntl(fd, F_GETFL);
    if (flags >= 0)
        fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    FILE *f = fdopen(fd, "rb");
    if (!f) {
        int errnum = errno;
        error_set(e, ERROR_RUNTIME, path, "cannot open the %s: %s", what, strerror(errnum));
        close(fd);
    }
    return f;
}

char *text_file_read(const char *path, long max_bytes, const char *what, size_t *len, struct error *e)
{
    FILE *f = regular_file_open(path, what, e);
    if (!f)
        return NULL;
    char *text = malloc((size_t)max_bytes + 2);
    if (!text) {
        fclose(f);
        error_set(e, ERROR_RUNTIME, path, "out of memory reading the %s", what);
        return NULL;
    }
    size_t n = fread(text, 1, (size_t)max_bytes + 1, f);
    if (ferror(f)) {
        int errnum = errno;
        error_set(e, error_status_of_errno(errnum), path, "cannot read the %s: %s", what, strerror(errnum));
        free(text);
        text = NULL;
    } else if (n > (size_t)max_bytes) {
        error_set(e, ERROR_INPUT, path, "the file is larger than %ld bytes: not a %s?", max_bytes, what);
        free(text);
        text = NULL;
    } else {
        text[n] = '\0';
    }
    fclose(f);
    *len = n;
    return text;
}

int text_lines_next(struct text_lines *t, const char **start, size_t *n, struct error *e)
{
    if (t->pos >= t->len)
        return 0;
    const char *s = t->text + t->pos;
    const char *newline = memchr(s, '\n', t->len - t->pos);
    size_t raw = newline ? (size_t)(newline - s) : t->len - t->pos;
    t->pos += raw + (newline ? 1 : 0);
    t->line++;
    size_t len = raw;
    if (len > 0 && s[len - 1] == '\r')
        len--;
    if (memchr(s, '\0', len))
        return error_set(e, ERROR_INPUT, NULL, "the line holds a NUL byte: is this a text file?");
    if (t->line == 1 && len >= 3 && memcmp(s, "\xEF\xBB\xBF", 3) == 0) {
        s += 3;
        len -= 3;
    }
    *start = s;
    *n = len;
    return 1;
}

int edit_distance(const char *a, const char *b, size_t max_len)
{
    int row[EDIT_MAX_LEN + 1];
    size_t na = strlen(a), nb = strlen(b);
    if (na > max_len || nb > max_len || na > EDIT_MAX_LEN || nb > EDIT_MAX_LEN)
        return EDIT_TOO_FAR;
    for (size_t j = 0; j <= nb; j++)
        row[j] = (int)j;
    for (size_t i = 1; i <= na; i++) {
        int diag = row[0];
        row[0] = (int)i;
        for (size_t j = 1; j <= nb; j++) {
            int up = row[j];
            int best = diag + (a[i - 1] != b[j - 1]);
            if (up + 1 < best)
                best = up + 1;
            if (row[j - 1] + 1 < best)
                best = row[j - 1] + 1;
            row[j] = best;
            diag = up;
        }
    }
    return row[nb];
}
