/* A private Xvfb server for the tests of the kiosk's X11 screen: started on a free display number
 * and stopped by the test itself, so that no desktop's server is ever drawn on. A machine without
 * Xvfb gives a reason to skip instead. */
#ifndef BT_TESTS_XVFB_H
#define BT_TESTS_XVFB_H
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <X11/Xlib.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#define XVFB "Xvfb"
#define XVFB_FIRST_DISPLAY 50
#define XVFB_LAST_DISPLAY 250
#define XVFB_TRIES 5                 /* display numbers taken meanwhile by someone else */
#define XVFB_START_SECONDS 10.0

struct xvfb {
    pid_t pid;                       /* -1: no server */
    char display[16];                /* ":N" */
    const char *missing;             /* why there is no server to test on (skip), or NULL */
};

static inline double monotonic_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static inline int xvfb_on_path(const char *program)
{
    const char *path = getenv("PATH");
    char dirs[4096], file[4352];
    snprintf(dirs, sizeof dirs, "%s", path && *path ? path : "/usr/bin:/bin");
    char *save = NULL;
    for (char *d = strtok_r(dirs, ":", &save); d; d = strtok_r(NULL, ":", &save)) {
        snprintf(file, sizeof file, "%s/%s", d, program);
        if (access(file, X_OK) == 0)
            return 1;
    }
    return 0;
}

static inline int xvfb_display_in_use(int n)
{
    char socket_path[64], lock_path[64];
    struct stat st;
    snprintf(socket_path, sizeof socket_path, "/tmp/.X11-unix/X%d", n);
    snprintf(lock_path, sizeof lock_path, "/tmp/.X%d-lock", n);
    return stat(socket_path, &st) == 0 || stat(lock_path, &st) == 0;
}

/* Xvfb on :N; 0 once its socket is there, 1 if it exited first (the number was taken meanwhile),
 * -1 if it neither listened nor exited in time. */
static inline int xvfb_start_on(struct xvfb *x, int n)
{
    char number[16], socket_path[64];
    snprintf(number, sizeof number, ":%d", n);
    snprintf(socket_path, sizeof socket_path, "/tmp/.X11-unix/X%d", n);
    pid_t pid = fork();
    if (pid < 0) {
        fprintf(stderr, "fork for %s: %s\n", XVFB, strerror(errno));
        return -1;
    }
    if (pid == 0) {
#ifdef __linux__
        prctl(PR_SET_PDEATHSIG, SIGTERM);    /* a test that crashes leaves no server behind */
#endif
        int devnull = open("/dev/null", O_RDWR);
        if (devnull >= 0) {
            dup2(devnull, STDIN_FILENO);
            dup2(devnull, STDOUT_FILENO);
            dup2(devnull, STDERR_FILENO);
        }
        execlp(XVFB, XVFB, number, "-screen", "0", "1280x720x24", "-nolisten", "tcp", "-noreset", (char *)NULL);
        _exit(127);
    }
    double deadline = monotonic_seconds() + XVFB_START_SECONDS;
    while (monotonic_seconds() < deadline) {
        struct stat st;
        if (waitpid(pid, NULL, WNOHANG) == pid)
            return 1;
        if (stat(socket_path, &st) == 0 && S_ISSOCK(st.st_mode)) {
            x->pid = pid;
            snprintf(x->display, sizeof x->display, ":%d", n);
            return 0;
        }
        struct timespec pause = {0, 10 * 1000 * 1000};
        nanosleep(&pause, NULL);
    }
    kill(pid, SIGKILL);
    waitpid(pid, NULL, 0);
    fprintf(stderr, "%s %s did not create %s within %.0f s\n", XVFB, number, socket_path, XVFB_START_SECONDS);
    return -1;
}

/* 0 with a server running, or with x->missing set where Xvfb is not installed (the caller skips);
 * -1 (said on stderr) where Xvfb is there but does not start. */
static inline int xvfb_start(struct xvfb *x)
{
    memset(x, 0, sizeof *x);
    x->pid = -1;
    if (!xvfb_on_path(XVFB)) {
        x->missing = XVFB " is not installed (Debian package xvfb): the X11 screen is not tested";
        return 0;
    }
    int tries = 0;
    for (int n = XVFB_FIRST_DISPLAY; n < XVFB_LAST_DISPLAY && tries < XVFB_TRIES; n++) {
        if (xvfb_display_in_use(n))
            continue;
        tries++;
        int rc = xvfb_start_on(x, n);
        if (rc <= 0)
            return rc;
    }
    fprintf(stderr, "cannot start %s on a free display between :%d and :%d\n", XVFB, XVFB_FIRST_DISPLAY,
            XVFB_LAST_DISPLAY);
    return -1;
}

static inline void xvfb_stop(struct xvfb *x)
{
    if (x->pid > 0) {
        kill(x->pid, SIGTERM);
        waitpid(x->pid, NULL, 0);
        x->pid = -1;
    }
}

/* The window called title under w (depth first), 0 if there is none. */
static inline Window xvfb_find_window(Display *dpy, Window w, const char *title)
{
    char *name = NULL;
    if (XFetchName(dpy, w, &name) && name) {
        int match = strcmp(name, title) == 0;
        XFree(name);
        if (match)
            return w;
    }
    Window root, parent, *children = NULL, found = 0;
    unsigned n = 0;
    if (XQueryTree(dpy, w, &root, &parent, &children, &n)) {
        for (unsigned i = 0; i < n && !found; i++)
            found = xvfb_find_window(dpy, children[i], title);
        if (children)
            XFree(children);
    }
    return found;
}

#endif
