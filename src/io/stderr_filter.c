/* stderr through a filter that shows control characters as \xNN (glibc's fopencookie). */
#define _GNU_SOURCE
#include "io/stderr_filter.h"
#include <errno.h>
#include <stdio.h>
#include <unistd.h>

/* All of buf to fd, across short writes and signals; 0 or -1. */
static int write_all(int fd, const char *buf, size_t n)
{
    while (n > 0) {
        ssize_t w = write(fd, buf, n);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return -1;
        buf += w;
        n -= (size_t)w;
    }
    return 0;
}

static ssize_t filtered_write(void *cookie, const char *buf, size_t size)
{
    int fd = *(const int *)cookie;
    char out[4 * 256];
    size_t done = 0;
    while (done < size) {
        size_t used = 0, taken = 0;
        while (done + taken < size && used + 4 <= sizeof out) {
            unsigned char c = (unsigned char)buf[done + taken++];
            if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7f) {
                static const char hex[] = "0123456789abcdef";
                out[used++] = '\\';
                out[used++] = 'x';
                out[used++] = hex[c >> 4];
                out[used++] = hex[c & 15];
            } else {
                out[used++] = (char)c;
            }
        }
        if (write_all(fd, out, used) != 0)
            return done > 0 ? (ssize_t)done : -1;
        done += taken;
    }
    return (ssize_t)size;
}

int stderr_escape_controls(void)
{
    static int fd;
    fd = dup(STDERR_FILENO);
    if (fd < 0)
        return -1;
    cookie_io_functions_t io = {.write = filtered_write};
    FILE *f = fopencookie(&fd, "w", io);
    if (!f) {
        close(fd);
        return -1;
    }
    setvbuf(f, NULL, _IONBF, 0);
    fflush(stderr);
    stderr = f;
    return 0;
}
