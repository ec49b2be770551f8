/* Safe output files: a temporary beside the final name, renamed into place when complete. */
/* realpath() is XSI */
#define _XOPEN_SOURCE 700
#include "io/output_file.h"

#include <errno.h>
#include <fcntl.h>
#include <libgen.h>
#include <limits.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- signals: a signal that ends the process removes the temporary being written ---- */

static const int fatal_signals[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGQUIT};
#define N_FATAL (int)(sizeof fatal_signals / sizeof fatal_signals[0])
static struct sigaction previous[N_FATAL], previous_xfsz;
static char *volatile current_tmp;   /* the one temporary open at a time (NULL: none) */

static void on_fatal(int sig)
{
    for (int i = 0; i < N_FATAL; i++) {
        if (fatal_signals[i] != sig)
            continue;
        void (*handler)(int) = previous[i].sa_handler;
        if (!(previous[i].sa_flags & SA_SIGINFO) && handler != SIG_DFL && handler != SIG_IGN && handler) {
            handler(sig);    /* the program's own handler (the kiosk's): it decides, the write goes on */
            return;
        }
        if (handler == SIG_IGN)
            return;
    }
    char *tmp = current_tmp;
    if (tmp)
        unlink(tmp);
    signal(sig, SIG_DFL);
    raise(sig);
}

static void guard(char *tmp)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_fatal;
    sigemptyset(&sa.sa_mask);
    for (int i = 0; i < N_FATAL; i++)
        sigaction(fatal_signals[i], &sa, &previous[i]);
    /* a file-size limit (ulimit -f) makes write() fail with EFBIG instead of ending the process */
    struct sigaction ignore;
    memset(&ignore, 0, sizeof ignore);
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    sigaction(SIGXFSZ, &ignore, &previous_xfsz);
    current_tmp = tmp;
}

static void unguard(void)
{
    current_tmp = NULL;
    for (int i = 0; i < N_FATAL; i++)
        sigaction(fatal_signals[i], &previous[i], NULL);
    sigaction(SIGXFSZ, &previous_xfsz, NULL);
}

/* ---- checks ---- */

static const char *kind_of(mode_t m)
{
    return S_ISDIR(m) ? "a directory" : S_ISCHR(m) ? "a character device" : S_ISBLK(m) ? "a block device"
         : S_ISFIFO(m) ? "a FIFO" : S_ISSOCK(m) ? "a socket" : "not a regular file";
}

static int exists_err(struct error *e, const char *path)
{
    return error_set(e, ERROR_INPUT, NULL, "refusing to replace existing file %s (use --force to overwrite it)",
                     path);
}

int output_check(const char *path, int overwrite, struct error *e)
{
    if (!path || !*path)
        return error_set(e, ERROR_INPUT, NULL, "an empty file name");
    struct stat st;
    if (lstat(path, &st) == 0) {
        if (!S_ISREG(st.st_mode) && !S_ISLNK(st.st_mode))
            return error_set(e, ERROR_INPUT, NULL, "%s is %s: bentray replaces only regular files", path,
                             kind_of(st.st_mode));
        if (!overwrite)
            return exists_err(e, path);
        return 0;
    }
    int en = errno;
    if (en != ENOENT)
        return error_set(e, error_status_of_errno(en), NULL, "cannot write %s: %s", path, strerror(en));
    char *copy = strdup(path);
    if (!copy)
        return error_set(e, ERROR_RUNTIME, NULL, "cannot write %s: out of memory", path);
    const char *dir = dirname(copy);
    int rc = 0;
    if (stat(dir, &st) != 0) {
        en = errno;
        rc = error_set(e, error_status_of_errno(en), NULL, "cannot write %s: directory %s: %s", path, dir,
                       strerror(en));
    } else if (!S_ISDIR(st.st_mode)) {
        rc = error_set(e, ERROR_INPUT, NULL, "cannot write %s: %s is not a directory", path, dir);
    } else if (access(dir, W_OK | X_OK) != 0) {
        en = errno;
        rc = error_set(e, error_status_of_errno(en), NULL, "cannot write %s: directory %s: %s", path, dir,
                       strerror(en));
    }
    free(copy);
    return rc;
}

/* The directory (resolved) and the name of a path, joined; NULL where the directory does not resolve. */
static char *canonical(const char *path)
{
    char *a = strdup(path), *b = strdup(path);
    char *out = NULL;
    if (a && b) {
        char resolved[PATH_MAX];
        if (realpath(dirname(a), resolved)) {
            const char *name = basename(b);
            size_t n = strlen(resolved) + strlen(name) + 2;
            out = malloc(n);
            if (out)
                snprintf(out, n, "%s/%s", resolved, name);
        }
    }
    free(a);
    free(b);
    return out;
}

int output_same(const char *a, const char *b)
{
    if (strcmp(a, b) == 0)
        return 1;
    struct stat sa, sb;
    if (stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino)
        return 1;
    char *ca = canonical(a), *cb = canonical(b);
    int same = ca && cb && strcmp(ca, cb) == 0;
    free(ca);
    free(cb);
    return same;
}

/* ---- writing ---- */

/* A new file next to PATH, so that the final rename stays within one file system and is atomic.
 * O_EXCL keeps two writers (or a stale leftover) from sharing a temporary. */
static int open_temp(const char *path, char *tmp, size_t tmplen)
{
    static unsigned counter;
    /* NAME.tmp-PID-N beside the file; where that name is longer than the file system allows (a
     * file's own name of 240 bytes or more), a short one in the same directory */
    const char *slash = strrchr(path, '/');
    int dir_len = slash ? (int)(slash - path + 1) : 0, short_name = 0;
    for (int attempt = 0; attempt < 100; attempt++) {
        int n = short_name ? snprintf(tmp, tmplen, "%.*s.bentray-%ld-%u.tmp", dir_len, path, (long)getpid(), counter++)
                           : snprintf(tmp, tmplen, "%s.tmp-%ld-%u", path, (long)getpid(), counter++);
        if (n < 0 || (size_t)n >= tmplen) {
            errno = ENAMETOOLONG;
            return -1;
        }
        int fd = open(tmp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0 && errno == ENAMETOOLONG && !short_name) {
            short_name = 1;
            continue;
        }
        if (fd >= 0 || errno != EEXIST)
            return fd;
    }
    errno = EEXIST;
    return -1;
}

int output_open(struct output_file *o, const char *path, int overwrite, struct error *e)
{
    memset(o, 0, sizeof *o);
    if (output_check(path, overwrite, e) != 0)
        return -1;
    size_t tmplen = strlen(path) + 48;
    o->tmp = malloc(tmplen);
    if (!o->tmp)
        return error_set(e, ERROR_RUNTIME, NULL, "cannot write %s: out of memory", path);
    guard(o->tmp);
    int fd = open_temp(path, o->tmp, tmplen);
    if (fd < 0) {
        int en = errno;
        error_set(e, error_status_of_errno(en), NULL, "cannot write %s: %s", path, strerror(en));
        unguard();
        free(o->tmp);
        o->tmp = NULL;
        return -1;
    }
    /* a file replaced keeps its permissions (a report kept private stays private); a link is
     * replaced by a file of the default mode, never followed */
    struct stat old;
    if (overwrite && lstat(path, &old) == 0 && S_ISREG(old.st_mode))
        (void)fchmod(fd, old.st_mode & 07777);
    o->fp = fdopen(fd, "wb");
    if (!o->fp) {
        error_set(e, ERROR_RUNTIME, NULL, "cannot write %s: %s", path, strerror(errno));
        close(fd);
        unlink(o->tmp);
        unguard();
        free(o->tmp);
        o->tmp = NULL;
        return -1;
    }
    o->path = path;
    o->overwrite = overwrite;
    return 0;
}

void output_abort(struct output_file *o)
{
    if (o->fp)
        fclose(o->fp);
    if (o->tmp) {
        unlink(o->tmp);
        unguard();
        free(o->tmp);
    }
    memset(o, 0, sizeof *o);
}

/* Moves the finished temporary into place. Without overwrite, link() is used because it fails
 * when the name exists, which closes the gap between the earlier check and the rename; file
 * systems without hard links fall back to check-then-rename. With overwrite, what is there now
 * must still be a regular file or a link. */
static int move_into_place(const char *tmp, const char *path, int overwrite, struct error *e)
{
    struct stat st;
    if (!overwrite) {
        if (link(tmp, path) == 0) {
            unlink(tmp);
            return 0;
        }
        int en = errno;
        if (en == EEXIST)
            return exists_err(e, path);
        if (en != EPERM && en != ENOTSUP && en != EOPNOTSUPP && en != ENOSYS && en != EMLINK)
            return error_set(e, ERROR_RUNTIME, NULL, "cannot write %s: %s", path, strerror(en));
        if (lstat(path, &st) == 0)
            return exists_err(e, path);
    } else if (lstat(path, &st) == 0 && !S_ISREG(st.st_mode) && !S_ISLNK(st.st_mode)) {
        return error_set(e, ERROR_INPUT, NULL, "%s is %s: bentray replaces only regular files", path,
                         kind_of(st.st_mode));
    }
    if (rename(tmp, path) != 0)
        return error_set(e, ERROR_RUNTIME, NULL, "cannot write %s: %s", path, strerror(errno));
    return 0;
}

int output_commit(struct output_file *o, struct error *e)
{
    int ok = 1;
    /* a full disk often shows only at flush or close time, so both are checked */
    if (ferror(o->fp) || fflush(o->fp) != 0 || fsync(fileno(o->fp)) != 0) {
        error_set(e, ERROR_RUNTIME, NULL, "cannot write %s: %s", o->path, strerror(errno ? errno : EIO));
        ok = 0;
    }
    if (fclose(o->fp) != 0 && ok) {
        error_set(e, ERROR_RUNTIME, NULL, "cannot write %s: %s", o->path, strerror(errno));
        ok = 0;
    }
    o->fp = NULL;
    if (ok && move_into_place(o->tmp, o->path, o->overwrite, e) != 0)
        ok = 0;
    if (!ok)
        unlink(o->tmp);
    unguard();
    free(o->tmp);
    memset(o, 0, sizeof *o);
    return ok ? 0 : -1;
}
