/* The time a user waits: `bentray render` of schwarzschild.scene as a user runs it, a fresh process
 * each time (this program itself, started from its own path), against the start of such a process
 * (a 2x2 frame of starflight.scene) and the frame drawn warm in a running process. The difference
 * is what a fresh process pays besides its frame: the GL context, shaders (compiled, or loaded from
 * Mesa's cache), the orbit table (begun before the context, render/frame.c), the outcomes read back
 * for the summary, the PNG. An interrupt from the terminal reaches the child too (one process
 * group); its image file has no name, so nothing is left behind. */
#include <errno.h>
#include <fcntl.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include "bench/bench.h"
#include "io/clock.h"
#include "io/tree_file.h"

extern char **environ;

/* What a fresh process is timed doing. */
enum wait_run { WAIT_START, WAIT_FRESH, WAIT_SMALL, WAIT_COLD, WAIT_RUNS };
static const char *const wait_what[WAIT_RUNS] = {
    "process start: `bentray render` of starflight.scene at 2x2",
    "fresh `bentray render`, the PNG written fast (the default)",
    "the same with `--compression small`",
    "the same with Mesa's shader cache off (`MESA_SHADER_CACHE_DISABLE=true`: a first run on a new machine)",
};

/* What a run needs: this program, the two scenes, and the files its PNG and its summary go to (its
 * standard output and error: temporary files without a name, so that an interrupted bench leaves
 * nothing behind). */
struct wait_paths {
    char self[4096], start_scene[4096], scene[4096];
    int image_fd, summary_fd;
};

/* The seconds of rendering that the last `time:` line of the summary in fd says, or -1: read from
 * its last 8 KB, where the summary ends, however long the progress or warnings before it. */
static double summary_frame_seconds(int fd)
{
    char text[8192];
    struct stat st;
    if (fstat(fd, &st) != 0)
        return -1.0;
    off_t from = st.st_size > (off_t)sizeof text - 1 ? st.st_size - (off_t)(sizeof text - 1) : 0;
    ssize_t n = pread(fd, text, sizeof text - 1, from);
    if (n <= 0)
        return -1.0;
    text[n] = '\0';
    double seconds = -1.0;
    /* a line cut by the start of the window is not one */
    char *first = from == 0 ? text : strchr(text, '\n') ? strchr(text, '\n') + 1 : NULL;
    for (char *line = first; line; line = strchr(line, '\n') ? strchr(line, '\n') + 1 : NULL) {
        double v;
        if (strncmp(line, "time: ", 6) == 0 && sscanf(line + 6, "%lf s rendering", &v) == 1)
            seconds = v;
    }
    return seconds;
}

/* Runs ARGV (this program) with standard input on /dev/null, its output into the image file and its
 * error into the summary file, both emptied first, COLD adding the variable that turns Mesa's shader
 * cache off; its wall time in *seconds. 0, or -1 with e. */
static int run_wall(const struct wait_paths *p, char *const argv[], int cold, double *seconds, struct error *e)
{
    if (ftruncate(p->image_fd, 0) != 0 || lseek(p->image_fd, 0, SEEK_SET) != 0 ||
        ftruncate(p->summary_fd, 0) != 0 || lseek(p->summary_fd, 0, SEEK_SET) != 0)
        return error_set(e, ERROR_RUNTIME, NULL, "cannot empty the image and summary files: %s", strerror(errno));
    size_t n_env = 0;
    while (environ[n_env])
        n_env++;
    char **env = calloc(n_env + 2, sizeof *env);
    if (!env)
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory");
    /* the cache as the bench's own environment has it, but where the run is cold: off, whatever
     * that environment says (the first of two settings would win) */
    static const char cache_key[] = "MESA_SHADER_CACHE_DISABLE=";
    static char cache_off[] = "MESA_SHADER_CACHE_DISABLE=true";
    size_t n = 0;
    for (size_t i = 0; i < n_env; i++)
        if (!cold || strncmp(environ[i], cache_key, sizeof cache_key - 1) != 0)
            env[n++] = environ[i];
    if (cold)
        env[n++] = cache_off;
    posix_spawn_file_actions_t fa;
    int rc = posix_spawn_file_actions_init(&fa);
    if (rc == 0 && (posix_spawn_file_actions_addopen(&fa, STDIN_FILENO, "/dev/null", O_RDONLY, 0) != 0 ||
                    posix_spawn_file_actions_adddup2(&fa, p->image_fd, STDOUT_FILENO) != 0 ||
                    posix_spawn_file_actions_adddup2(&fa, p->summary_fd, STDERR_FILENO) != 0)) {
        posix_spawn_file_actions_destroy(&fa);
        rc = ENOMEM;
    }
    if (rc != 0) {
        free(env);
        return error_set(e, ERROR_RUNTIME, NULL, "cannot start %s: %s", p->self, strerror(rc));
    }
    pid_t pid;
    double t0 = clock_seconds();
    rc = posix_spawn(&pid, p->self, &fa, NULL, argv, env);
    posix_spawn_file_actions_destroy(&fa);
    free(env);
    if (rc != 0)
        return error_set(e, ERROR_RUNTIME, NULL, "cannot start %s: %s", p->self, strerror(rc));
    int status;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            return error_set(e, ERROR_RUNTIME, NULL, "waiting for %s: %s", p->self, strerror(errno));
    *seconds = clock_seconds() - t0;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return error_set(e, ERROR_RUNTIME, NULL, "%s render --scene %s exited %d (run it by hand to see why)",
                         p->self, argv[3], WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status));
    return 0;
}

/* The median wall time of `runs` runs of WHICH, and of the rendering its own `time:` line says (-1
 * where it says none); the image's size in *bytes. 0, or -1 with e. */
static int time_run(struct bench *b, const struct wait_paths *p, enum wait_run which, const struct scene *s,
                    double *median, double *frame_median, long *bytes, struct error *e)
{
    char size[32];
    snprintf(size, sizeof size, which == WAIT_START ? "2x2" : "%dx%d", s->render.width, s->render.height);
    char *argv[16];
    int n = 0;
    argv[n++] = (char *)p->self;
    argv[n++] = "render";
    argv[n++] = "--scene";
    argv[n++] = (char *)(which == WAIT_START ? p->start_scene : p->scene);
    argv[n++] = "--size";
    argv[n++] = size;
    argv[n++] = "--backend";
    argv[n++] = b->backend;
    argv[n++] = "--out";
    argv[n++] = "-";
    if (which == WAIT_SMALL) {
        argv[n++] = "--compression";
        argv[n++] = "small";
    }
    argv[n] = NULL;
    double times[64], frames[64];
    int runs = b->runs < 1 ? 1 : b->runs < 64 ? b->runs : 64;
    for (int k = 0; k < runs; k++) {
        if (run_wall(p, argv, which == WAIT_COLD, &times[k], e) != 0)
            return -1;
        frames[k] = summary_frame_seconds(p->summary_fd);
    }
    *median = bench_median(times, runs);
    *frame_median = bench_median(frames, runs);
    struct stat st;
    *bytes = fstat(p->image_fd, &st) == 0 ? (long)st.st_size : -1;
    return 0;
}

/* A file without a name, above the standard descriptors (a bench started with one closed would
 * hand out 0, 1 or 2, which the child's own set-up replaces) and closed in the child, which writes
 * to its dup2 alone. 0, or -1 with e. */
static int unnamed_file(const char *what, int *out, struct error *e)
{
    const char *tmp = getenv("TMPDIR");
    char name[BENCH_PATH_LEN];
    snprintf(name, sizeof name, "%s/bentray-wait-XXXXXX", tmp && *tmp ? tmp : "/tmp");
    int fd = mkstemp(name);
    if (fd < 0)
        return error_set(e, ERROR_RUNTIME, NULL, "cannot make a file for the %s (%s): %s", what, name, strerror(errno));
    unlink(name);
    *out = fcntl(fd, F_DUPFD_CLOEXEC, 3);
    int saved = errno;
    close(fd);
    if (*out < 0)
        return error_set(e, ERROR_RUNTIME, NULL, "cannot keep a file for the %s: %s", what, strerror(saved));
    return 0;
}

/* The paths of P, its image and summary files made. 0, or -1 with e. */
static int wait_paths_find(struct wait_paths *p, struct error *e)
{
    ssize_t n = readlink("/proc/self/exe", p->self, sizeof p->self - 1);
    if (n <= 0 || (size_t)n >= sizeof p->self - 1)
        return error_set(e, ERROR_RUNTIME, NULL, "cannot find this program's own path (/proc/self/exe)");
    p->self[n] = '\0';
    if (tree_file_find("assets/scenes/starflight.scene", p->start_scene, sizeof p->start_scene) != 0 ||
        tree_file_find("assets/scenes/schwarzschild.scene", p->scene, sizeof p->scene) != 0)
        return error_set(e, ERROR_INPUT, NULL, "assets/scenes/starflight.scene and schwarzschild.scene: not found "
                         "beside this program or installed");
    if (unnamed_file("images", &p->image_fd, e) != 0)
        return -1;
    if (unnamed_file("summaries", &p->summary_fd, e) != 0) {
        close(p->image_fd);
        return -1;
    }
    return 0;
}

static const char *verdict(int met) { return met ? "met" : "MISSED"; }

/* The section, its scene (schwarzschild at the bench's size) loaded into S. */
static int wait_on(struct bench *b, struct scene *s, struct error *e)
{
    if (bench_load_scene(s, "schwarzschild", b->width, b->height, e) != 0)
        return -1;
    struct wait_paths p;
    if (wait_paths_find(&p, e) != 0)
        return -1;
    bench_progress(b, "wait: the warm frame of schwarzschild at %dx%d", s->render.width, s->render.height);
    struct bench_timing warm;
    int rc = bench_time(b, s, b->runs, &warm, NULL, e);
    b->done++;
    double seconds[WAIT_RUNS] = {0}, own[WAIT_RUNS] = {0};
    long bytes[WAIT_RUNS] = {0};
    for (int k = 0; k < WAIT_RUNS && rc == 0; k++) {
        bench_progress(b, "wait: %s", wait_what[k]);
        rc = time_run(b, &p, (enum wait_run)k, s, &seconds[k], &own[k], &bytes[k], e);
        b->done++;
    }
    close(p.image_fd);
    close(p.summary_fd);
    if (rc != 0)
        return -1;
    FILE *csv = bench_data_file(b, "wait.csv", e);
    if (!csv)
        return -1;
    fprintf(csv, "what,seconds,png_bytes\nwarm_frame,%.5f,\n", warm.median);
    static const char *const keys[WAIT_RUNS] = {"process_start", "fresh_fast", "fresh_small", "fresh_cache_off"};
    for (int k = 0; k < WAIT_RUNS; k++)
        fprintf(csv, "%s,%.5f,%ld\n", keys[k], seconds[k], k == WAIT_START ? 0L : bytes[k]);
    fprintf(csv, "fresh_fast_own_frame,%.5f,\n", own[WAIT_FRESH]);
    fclose(csv);
    fprintf(b->md, "## The time a user waits\n\n`bentray render --scene schwarzschild.scene --size %dx%d` run as a "
                   "user runs it, a fresh process each time (wall time from its start to its exit, the PNG "
                   "written to standard output, a file, the summary to standard error), against the warm frame, the image alone drawn in a running process "
                   "(as the kiosk draws it, `bentray bench`'s own timing). Median of %d runs. What a fresh "
                   "process adds to its frame: the GL context, the shaders (loaded from Mesa's cache, or "
                   "compiled where it is off), the orbit table (built on a second thread while the context "
                   "is made), the rays' outcomes read back for the summary, the PNG.\n\n| what | seconds | PNG bytes |\n|---|---|---|\n",
            s->render.width, s->render.height, b->runs);
    fprintf(b->md, "| the warm frame (%s, %ld pass%s) | %.3f | |\n", warm.path, warm.passes, warm.passes == 1 ? "" : "es",
            warm.median);
    for (int k = 0; k < WAIT_RUNS; k++) {
        char png[32] = "";
        if (k != WAIT_START && bytes[k] >= 0)
            snprintf(png, sizeof png, "%ld", bytes[k]);
        fprintf(b->md, "| %s | %.3f | %s |\n", wait_what[k], seconds[k], png);
        if (k == WAIT_FRESH)
            fprintf(b->md, "| its frame, as the fresh render's own `time:` line says (the orbit table's wait and "
                           "the shaders' first draws included) | %.3f | |\n", own[k]);
    }
    double start = seconds[WAIT_START], fresh = seconds[WAIT_FRESH];
    double warm15 = start + 1.5 * warm.median, warm12 = start + 1.2 * warm.median, own12 = start + 1.2 * own[WAIT_FRESH];
    fprintf(b->md, "\nTargets for the fresh render: at most the process start plus 1.5 times the warm frame "
                   "(%.3f s): **%s**; at most the process start plus 1.2 times its own frame (%.3f s): **%s**; "
                   "stricter, at most the process start plus 1.2 times the warm frame (%.3f s): **%s**. "
                   "What the fresh process adds beyond its start and the warm frame: %.3f s.\n\n",
            warm15, verdict(fresh <= warm15), own12, verdict(own[WAIT_FRESH] > 0.0 && fresh <= own12), warm12,
            verdict(fresh <= warm12), fresh - start - warm.median);
    return 0;
}

int bench_wait(struct bench *b, struct error *e)
{
    return bench_with_scene(b, wait_on, e);
}
