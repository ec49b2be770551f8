#include "io/tree_file.h"
#include <limits.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static int readable(const char *path) { return access(path, R_OK) == 0; }

int tree_file_find(const char *rel, char *out, size_t len)
{
    if (snprintf(out, len, "%s", rel) < (int)len && readable(out))
        return 0;
    char exe[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0)
        return -1;
    exe[n] = '\0';
    char *slash = strrchr(exe, '/');
    if (!slash)
        return -1;
    *slash = '\0';
    char bin[PATH_MAX];
    snprintf(bin, sizeof bin, "%s", exe);
    for (int up = 0; up <= 3; up++) {
        if (snprintf(out, len, "%s/%s", exe, rel) < (int)len && readable(out))
            return 0;
        slash = strrchr(exe, '/');
        if (!slash)
            break;
        *slash = '\0';
    }
    const char *installed = strncmp(rel, "assets/", 7) == 0 ? rel + 7 : rel;
    if (snprintf(out, len, "%s/../share/bentray/%s", bin, installed) < (int)len && readable(out))
        return 0;
    return -1;
}
