/* Paths named by a configuration: joined with the directory of the file that names them, and
 * checked for what they name. */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include "conf/conf_path.h"

void conf_path_dir(const char *path, char *dir, size_t len)
{
    const char *slash = strrchr(path, '/');
    if (!slash)
        snprintf(dir, len, ".");
    else if (slash == path)
        snprintf(dir, len, "/");
    else
        snprintf(dir, len, "%.*s", (int)(slash - path), path);
}

int conf_path_join(const char *dir, const char *rel, char *out, size_t len)
{
    int n;
    if (rel[0] == '/' || dir[0] == '\0' || strcmp(dir, ".") == 0)
        n = snprintf(out, len, "%s", rel);
    else if (strcmp(dir, "/") == 0)
        n = snprintf(out, len, "/%s", rel);
    else
        n = snprintf(out, len, "%s/%s", dir, rel);
    return n < 0 || (size_t)n >= len ? -1 : 0;
}

/* A directory opens fine with fopen on Linux, so regular files are asked for explicitly. */
int conf_check_file(const char *path, const char *note, struct error *e)
{
    struct stat st;
    FILE *f;
    if (stat(path, &st) != 0) {
        error_set(e, ERROR_INPUT, NULL, "cannot read \"%s\": %s%s%s%s", path, strerror(errno), note ? " (" : "",
                 note ? note : "", note ? ")" : "");
        return -1;
    }
    if (!S_ISREG(st.st_mode)) {
        error_set(e, ERROR_INPUT, NULL, "\"%s\" is not a regular file", path);
        return -1;
    }
    f = fopen(path, "rb");
    if (!f) {
        error_set(e, ERROR_INPUT, NULL, "cannot read \"%s\": %s", path, strerror(errno));
        return -1;
    }
    fclose(f);
    return 0;
}

int conf_check_dir(const char *path, const char *note, struct error *e)
{
    struct stat st;
    if (stat(path, &st) != 0) {
        error_set(e, ERROR_INPUT, NULL, "no directory \"%s\": %s%s%s%s", path, strerror(errno), note ? " (" : "",
                 note ? note : "", note ? ")" : "");
        return -1;
    }
    if (!S_ISDIR(st.st_mode)) {
        error_set(e, ERROR_INPUT, NULL, "\"%s\" is not a directory", path);
        return -1;
    }
    return 0;
}
