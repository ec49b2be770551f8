/* The libFuzzer harnesses whose readers take a path: the input goes to one temporary file per
 * process, made at start in $BT_FUZZ_TMPDIR (else $TMPDIR, else /tmp), rewritten for every input
 * and removed at exit. Header-only: each harness is linked on its own. */
#ifndef BT_FUZZ_INPUT_FILE_H
#define BT_FUZZ_INPUT_FILE_H
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <unistd.h>

static char tmp_path[4096];
static int tmp_fd = -1;

static void tmp_remove(void)
{
    if (tmp_fd >= 0)
        close(tmp_fd);
    if (tmp_path[0] != '\0')
        unlink(tmp_path);
}

static void tmp_create(const char *tag)
{
    const char *dir = getenv("BT_FUZZ_TMPDIR");
    if (dir == NULL || *dir == '\0')
        dir = getenv("TMPDIR");
    if (dir == NULL || *dir == '\0')
        dir = "/tmp";
    int n = snprintf(tmp_path, sizeof tmp_path, "%s/bt_fuzz_%s_XXXXXX", dir, tag);
    if (n < 0 || (size_t)n >= sizeof tmp_path) {
        fprintf(stderr, "fuzz: temporary directory name too long: %s\n", dir);
        exit(2);
    }
    tmp_fd = mkstemp(tmp_path);
    if (tmp_fd < 0) {
        fprintf(stderr, "fuzz: cannot create %s: %s\n", tmp_path, strerror(errno));
        tmp_path[0] = '\0';
        exit(2);
    }
    atexit(tmp_remove);
}

static void tmp_write(const uint8_t *data, size_t size)
{
    size_t done = 0;
    while (done < size) {
        ssize_t n = pwrite(tmp_fd, data + done, size - done, (off_t)done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            fprintf(stderr, "fuzz: cannot write %s: %s\n", tmp_path, strerror(errno));
            abort();
        }
        done += (size_t)n;
    }
    if (ftruncate(tmp_fd, (off_t)size) != 0) {
        fprintf(stderr, "fuzz: cannot truncate %s: %s\n", tmp_path, strerror(errno));
        abort();
    }
}

#endif
