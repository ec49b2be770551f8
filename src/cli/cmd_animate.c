/* bentray animate: a sequence of frames of one scene with keys moving between two values and the
 * camera orbiting its look_at point, written as numbered PNGs (and a video through ffmpeg where it
 * is installed). Every frame is `bentray render` of the scene with the --set values printed for
 * it, byte for byte: each frame's values are set as the same text. */
#include <errno.h>
#include <signal.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include "io/clock.h"
#include "cli/commands.h"
#include "cli/measure.h"
#include "cli/options.h"
#include "io/output_file.h"
#include "io/png_io.h"
#include "io/progress.h"
#include "scene/scene_keys.h"
#include "conf/conf_value.h"

#define ANIMATE_MAX_FRAMES 10000
#define ANIMATE_MAX_RANGES 16
#define ANIMATE_MAX_COMPONENTS 4
/* --fps of the video */
#define ANIMATE_MAX_FPS 240

static void usage(FILE *out)
{
    fprintf(out,
            "usage: bentray animate --scene FILE --frames N --out DIR [options]\n"
            "Render a sequence of frames into DIR/frame_0001.png ... (and a video with --video): keys\n"
            "moving between two values, the camera orbiting. Each frame prints the bentray render\n"
            "command that makes the same image, byte for byte.\n"
            "  --frames N           frames (1 to 10000)\n"
            "  --set-range KEY=FROM:TO  a number or vector key from FROM at the first frame to TO at\n"
            "                       the last, linearly (repeatable), e.g. model.mass=0:0.2 or\n"
            "                       camera.position=0 1 9:0 1 5; integer keys are rounded\n"
            "  --orbit DEGREES      the camera turns about its look_at point, around camera.up, by\n"
            "                       DEGREES in all: frame k of N at DEGREES x k / N (so 360 loops)\n"
            "  --orbit-axis \"X Y Z\"  the orbit's axis instead of camera.up (a fly-over: \"1 0 0\");\n"
            "                       camera.up turns with the camera\n"
            "  --out DIR            where the frames go (made if missing; its parent must exist)\n"
            "  --force              replace frames of an earlier run\n"
            "  --video FILE         also FILE.webm, .mp4 or .gif from the frames through ffmpeg\n"
            "  --fps F              frames per second of the video (default 24)\n"
            "  --quiet              print only the frames' paths\n"
            "Options of render: --size, --samples, --set, --engine, --backend, --precision, --no-mrt,\n"
            "--shader-dir, --rtol, --threads.\n"
            "exit codes: 0 ok, 1 runtime failure (ffmpeg missing for --video included), 2 bad usage or input\n");
}

struct range {
    const char *key;                  /* "section.key" as given */
    int kind;                         /* enum scene_key_kind */
    int n;                            /* components */
    double from[ANIMATE_MAX_COMPONENTS], to[ANIMATE_MAX_COMPONENTS];
};

struct animation {
    int frames;
    int n_ranges;
    struct range ranges[ANIMATE_MAX_RANGES];
    double orbit_deg;
    int orbit;
    vec3d orbit_axis;                /* --orbit-axis; camera.up where not given */
    int orbit_axis_given;
};

/* The kind of the key at PATH ("section.key" or "section.NAME.key"), -1 when there is none. */
static int key_kind(const char *path)
{
    char buf[128];
    snprintf(buf, sizeof buf, "%s", path);
    char *dot = strchr(buf, '.');
    if (!dot)
        return -1;
    *dot = '\0';
    int section = scene_section_find(buf);
    if (section < 0)
        return -1;
    const char *key = dot + 1;
    if (scene_section_named((enum scene_section_kind)section)) {
        const char *second = strchr(key, '.');
        if (!second)
            return -1;
        key = second + 1;
    }
    int k = scene_key_find((enum scene_section_kind)section, key);
    return k < 0 ? -1 : (int)scene_keys[k].kind;
}

/* Up to ANIMATE_MAX_COMPONENTS numbers separated by blanks; their count, or -1. */
static int parse_numbers(const char *text, double *out)
{
    int n = 0;
    const char *p = text;
    for (;;) {
        while (*p == ' ' || *p == '\t')
            p++;
        if (*p == '\0')
            return n;
        if (n == ANIMATE_MAX_COMPONENTS)
            return -1;
        char *end;
        errno = 0;
        double v = strtod(p, &end);
        if (end == p || errno || !isfinite(v))
            return -1;
        out[n++] = v;
        p = end;
    }
}

static int parse_range(const char *arg, struct range *r)
{
    static char text[ANIMATE_MAX_RANGES][256];
    static int used;
    const char *eq = strchr(arg, '=');
    const char *colon = eq ? strchr(eq + 1, ':') : NULL;
    if (!eq || !colon || strchr(colon + 1, ':') || (size_t)(eq - arg) >= 128 || used == ANIMATE_MAX_RANGES) {
        fprintf(stderr, "bentray animate: --set-range: expected KEY=FROM:TO, e.g. model.mass=0:0.2, got '%s'\n", arg);
        return -1;
    }
    char *key = text[used++];
    snprintf(key, 128, "%.*s", (int)(eq - arg), arg);
    r->key = key;
    r->kind = key_kind(key);
    if (r->kind != CONF_NUMBER && r->kind != CONF_INTEGER && r->kind != CONF_VECTOR && r->kind != CONF_COLOR &&
        r->kind != CONF_TEXCOORD) {
        fprintf(stderr, "bentray animate: --set-range %s: %s\n", arg,
                r->kind < 0 ? "no such key (keys: docs/SCENES.md; objects and lights: object.NAME.key)"
                            : "only a number, vector or colour key can move between two values");
        return -1;
    }
    char from[128], to[128];
    snprintf(from, sizeof from, "%.*s", (int)(colon - eq - 1), eq + 1);
    snprintf(to, sizeof to, "%s", colon + 1);
    int nf = parse_numbers(from, r->from), nt = parse_numbers(to, r->to);
    if (nf <= 0 || nf != nt) {
        fprintf(stderr, "bentray animate: --set-range %s: FROM and TO must be the same number of finite numbers "
                        "(at most %d)\n", arg, ANIMATE_MAX_COMPONENTS);
        return -1;
    }
    r->n = nf;
    return 0;
}

/* The shortest of %.15g, %.16g and %.17g that reads back as v exactly. */
static int exact_number(char *out, size_t len, double v)
{
    int n = 0;
    for (int digits = 15; digits <= 17; digits++) {
        n = snprintf(out, len, "%.*g", digits, v);
        if (strtod(out, NULL) == v)
            break;
    }
    return n;
}

/* The text of range r at fraction t of the sequence: "KEY=V", exact: parsing it gives the very
 * double the frame was rendered with. */
static void range_text(const struct range *r, double t, char *out, size_t len)
{
    size_t used = (size_t)snprintf(out, len, "%s=", r->key);
    for (int c = 0; c < r->n && used < len; c++) {
        double v = r->from[c] + t * (r->to[c] - r->from[c]);
        if (t >= 1.0)
            v = r->to[c];
        if (r->kind == CONF_INTEGER)
            used += (size_t)snprintf(out + used, len - used, "%s%.0f", c ? " " : "", floor(v + 0.5));
        else {
            if (c && used + 1 < len)
                out[used++] = ' ';
            used += (size_t)exact_number(out + used, len - used, v);
        }
    }
}

/* v turned by angle a around the unit axis (Rodrigues). */
static vec3d turn_about(vec3d v, vec3d axis, double a)
{
    return v3_add(v3_add(v3_scale(v, cos(a)), v3_scale(v3_cross(axis, v), sin(a))),
                  v3_scale(axis, v3_dot(axis, v) * (1.0 - cos(a))));
}

static void vector_text(const char *key, vec3d q, char *out, size_t len)
{
    size_t used = (size_t)snprintf(out, len, "%s=", key);
    double c[3] = {q.x, q.y, q.z};
    for (int i = 0; i < 3 && used + 1 < len; i++) {
        if (i)
            out[used++] = ' ';
        used += (size_t)exact_number(out + used, len - used, c[i]);
    }
}

/* camera.position=... of frame k: turned about look_at around the orbit's axis (camera.up unless
 * --orbit-axis); with an axis of its own, camera.up turns with it, so that a fly-over keeps its
 * horizon across the poles. */
static int orbit_text(const struct animation *an, const struct scene *s, double degrees, char out[][384])
{
    double a = degrees * PI_D / 180.0;
    vec3d axis = v3_normalize(an->orbit_axis_given ? an->orbit_axis : s->camera.up);
    vec3d p = v3_sub(s->camera.position, s->camera.look_at);
    vector_text("camera.position", v3_add(s->camera.look_at, turn_about(p, axis, a)), out[0], 384);
    if (!an->orbit_axis_given)
        return 1;
    vector_text("camera.up", turn_about(s->camera.up, axis, a), out[1], 384);
    return 2;
}

/* The --set texts of frame k (after the command line's own --set), into sets[]; their count. */
static int frame_sets(const struct animation *a, const struct scene *base, int k, char sets[][384])
{
    double t = a->frames > 1 ? (double)k / (a->frames - 1) : 0.0;
    int n = 0;
    for (int i = 0; i < a->n_ranges; i++)
        range_text(&a->ranges[i], t, sets[n++], 384);
    if (a->orbit)
        n += orbit_text(a, base, a->orbit_deg * k / a->frames, sets + n);
    return n;
}

/* The scene of frame k: the command line's, then the frame's sets, validated. 0, or EXIT_USAGE
 * with the message printed. */
static int frame_scene(const struct animation *a, const struct scene *base, int k, struct scene *s, char sets[][384],
                       int *n_sets)
{
    *s = *base;
    *n_sets = frame_sets(a, base, k, sets);
    struct error err;
    for (int i = 0; i < *n_sets; i++)
        if (scene_set(s, sets[i], &err) != 0) {
            fprintf(stderr, "bentray animate: frame %d: %s: error: %s\n", k + 1, err.where, err.message);
            return EXIT_USAGE;
        }
    if (scene_validate(s, &err) != 0) {
        fprintf(stderr, "bentray animate: frame %d (%s%s): %s: error: %s\n", k + 1, *n_sets ? "--set " : "",
                *n_sets ? sets[0] : "the scene", err.where, err.message);
        return EXIT_USAGE;
    }
    return 0;
}

/* A word for a POSIX shell: as it is when plain, else in single quotes. */
static void shell_word(FILE *f, const char *w)
{
    int plain = *w != '\0';
    for (const char *c = w; *c; c++)
        if (!strchr("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_./=:,+-@%", *c))
            plain = 0;
    if (plain) {
        fputs(w, f);
        return;
    }
    fputc('\'', f);
    for (const char *c = w; *c; c++)
        if (*c == '\'')
            fputs("'\\''", f);
        else
            fputc(*c, f);
    fputc('\'', f);
}

/* Where a frame goes: DIR/frame_0001.png, five digits from 10000 frames on. */
static void frame_path(const char *dir, int k, int frames, char *out, size_t len)
{
    if (frames >= 10000)
        snprintf(out, len, "%s/frame_%05d.png", dir, (k + 1) % 100000);
    else
        snprintf(out, len, "%s/frame_%04d.png", dir, (k + 1) % 10000);
}

/* Whether `ffmpeg` is a program on PATH. */
static int have_ffmpeg(void)
{
    const char *path = getenv("PATH");
    if (!path)
        return 0;
    char buf[4096];
    snprintf(buf, sizeof buf, "%s", path);
    for (char *save = NULL, *dir = strtok_r(buf, ":", &save); dir; dir = strtok_r(NULL, ":", &save)) {
        char exe[4200];
        snprintf(exe, sizeof exe, "%s/ffmpeg", *dir ? dir : ".");
        if (access(exe, X_OK) == 0)
            return 1;
    }
    return 0;
}

/* The video's kind from its extension: 0 webm, 1 mp4, 2 gif, -1 none of them. */
static int video_kind(const char *path)
{
    const char *dot = strrchr(path, '.');
    if (!dot)
        return -1;
    return strcmp(dot, ".webm") == 0 ? 0 : strcmp(dot, ".mp4") == 0 ? 1 : strcmp(dot, ".gif") == 0 ? 2 : -1;
}

/* ffmpeg's arguments for the video, into argv (NULL-terminated); fps_text (32 bytes) holds the frame
 * rate and, from its 17th byte, the frame count. */
static void ffmpeg_args(const char *dir, int frames, double fps, const char *video, char *fps_text, char *pattern,
                        const char **argv)
{
    static const char *const codec[3][6] = {
        {"-c:v", "libvpx-vp9", "-b:v", "0", "-crf", "32"},
        {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "20"},
        {"-vf", "split[a][b];[a]palettegen[p];[b][p]paletteuse", NULL, NULL, NULL, NULL},
    };
    int kind = video_kind(video), n = 0;
    snprintf(fps_text, 32, "%g", fps);
    /* the directory's own '%' written as ffmpeg's pattern reads it, "%%" */
    size_t used = 0;
    for (const char *c = dir; *c && used + 3 < 4200 - 32; c++) {
        if (*c == '%')
            pattern[used++] = '%';
        pattern[used++] = *c;
    }
    snprintf(pattern + used, 4200 - used, "/frame_%%0%dd.png", frames >= 10000 ? 5 : 4);
    snprintf(fps_text + 16, 16, "%d", frames);
    argv[n++] = "ffmpeg";
    argv[n++] = "-nostdin";           /* the caller's standard input is not ffmpeg's to read */
    argv[n++] = "-loglevel";
    argv[n++] = "error";
    argv[n++] = "-y";
    argv[n++] = "-framerate";
    argv[n++] = fps_text;
    argv[n++] = "-i";
    argv[n++] = pattern;
    argv[n++] = "-frames:v";          /* this run's frames only, not those an earlier run left after them */
    argv[n++] = fps_text + 16;
    for (int i = 0; i < 6 && codec[kind][i]; i++)
        argv[n++] = codec[kind][i];
    argv[n++] = video;
    argv[n] = NULL;
}

static void print_ffmpeg(FILE *f, const char *const *argv)
{
    for (int i = 0; argv[i]; i++) {
        if (i)
            fputc(' ', f);
        shell_word(f, argv[i]);
    }
}

/* While ffmpeg runs: a signal that ends bentray stops it and removes its temporary first. */
static volatile pid_t video_child;
static char video_tmp[4200];

static void stop_video(int sig)
{
    if (video_child > 0)
        kill(video_child, SIGTERM);
    unlink(video_tmp);
    signal(sig, SIG_DFL);
    raise(sig);
}

/* ffmpeg writes the video to a temporary beside it, moved into place when complete. */
static int make_video(const char *dir, int frames, double fps, const char *video, int force)
{
    char fps_text[32], pattern[4200], tmp[4200];
    const char *argv[24];
    const char *dot = strrchr(video, '.');
    snprintf(tmp, sizeof tmp, "%.*s.tmp-%ld%s", (int)(dot - video), video, (long)getpid(), dot);
    ffmpeg_args(dir, frames, fps, tmp, fps_text, pattern, argv);
    snprintf(video_tmp, sizeof video_tmp, "%s", tmp);
    static const int stops[] = {SIGINT, SIGTERM, SIGHUP};
    struct sigaction sa, previous[3];
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = stop_video;
    sigemptyset(&sa.sa_mask);
    for (int i = 0; i < 3; i++)
        sigaction(stops[i], &sa, &previous[i]);
    pid_t pid = fork();
    if (pid > 0)
        video_child = pid;
    if (pid < 0) {
        fprintf(stderr, "bentray animate: --video: cannot start ffmpeg: %s\n", strerror(errno));
        for (int i = 0; i < 3; i++)
            sigaction(stops[i], &previous[i], NULL);
        return EXIT_RUNTIME;
    }
    if (pid == 0) {
        execvp("ffmpeg", (char *const *)argv);
        _exit(127);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        ;
    video_child = 0;
    for (int i = 0; i < 3; i++)
        sigaction(stops[i], &previous[i], NULL);
    struct error fe;
    error_clear(&fe);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        unlink(tmp);
        fprintf(stderr, "bentray animate: --video: ffmpeg failed (%s %d); the frames are in %s\n",
                WIFEXITED(status) ? "exit" : "signal", WIFEXITED(status) ? WEXITSTATUS(status) : WTERMSIG(status), dir);
        return EXIT_RUNTIME;
    }
    if (output_check(video, force, &fe) != 0 || rename(tmp, video) != 0) {
        unlink(tmp);
        fprintf(stderr, "bentray animate: --video %s: %s\n", video, fe.message[0] ? fe.message : strerror(errno));
        return EXIT_RUNTIME;
    }
    return EXIT_OK;
}

/* Where and how the frames go: the options of the command line besides the animation's own. */
struct animate_out {
    const char *dir, *video;
    int force, quiet;
    double fps;
    const char *const *echo;          /* the command line's own options for render */
    int n_echo;
};

/* Loads BASE from O, checks every frame's scene (in S) and file, then renders and writes them. */
static int animate(const struct common_options *o, const struct animation *a, const struct animate_out *out,
                   struct scene *base, struct scene *s)
{
    int rc = options_load_scene(o, "animate", base);
    if (rc)
        return rc;
    /* everything checked before any work: every frame's scene, the directory, each frame's file */
    static char sets[ANIMATE_MAX_RANGES + 2][384];
    int n_sets;
    for (int k = 0; k < a->frames; k++)
        if ((rc = frame_scene(a, base, k, s, sets, &n_sets)) != 0)
            return rc;
    struct stat st;
    if (stat(out->dir, &st) != 0) {
        if (errno != ENOENT || mkdir(out->dir, 0777) != 0) {
            fprintf(stderr, "bentray animate: --out %s: %s\n", out->dir, strerror(errno));
            return EXIT_USAGE;
        }
    } else if (!S_ISDIR(st.st_mode)) {
        fprintf(stderr, "bentray animate: --out %s: not a directory\n", out->dir);
        return EXIT_USAGE;
    }
    char path[4200];
    struct error why;
    char which[SCENE_PATH_LEN + 64];
    for (int k = 0; k < a->frames; k++) {
        frame_path(out->dir, k, a->frames, path, sizeof path);
        if (output_check(path, out->force, &why) != 0) {
            fprintf(stderr, "bentray animate: --out: %s\n", why.message);
            return exit_code_of(&why);
        }
        if (scene_input_named(base, path, which, sizeof which)) {
            fprintf(stderr, "bentray animate: --out: frame %s is %s, which the animation reads: name another "
                            "directory\n", path, which);
            return EXIT_USAGE;
        }
    }
    if (out->video && scene_input_named(base, out->video, which, sizeof which)) {
        fprintf(stderr, "bentray animate: --video %s is %s, which the animation reads: name another file\n",
                out->video, which);
        return EXIT_USAGE;
    }
    if (out->video && output_check(out->video, out->force, &why) != 0) {
        fprintf(stderr, "bentray animate: --video: %s\n", why.message);
        return exit_code_of(&why);
    }
    struct progress p;
    progress_begin(&p, PROGRESS_NONE);
    for (int k = 0; k < a->frames; k++) {
        frame_scene(a, base, k, s, sets, &n_sets);
        frame_path(out->dir, k, a->frames, path, sizeof path);
        struct measured m;
        struct error e;
        int failed;
        if (options_engine_cpu(o)) {
            struct cpu_render_options opt;
            options_cpu(o, s, &opt);
            opt.progress = PROGRESS_NONE;
            failed = measure_cpu(s, &opt, &m, &e);
        } else {
            failed = measure_gpu(s, o->backend, 0, PROGRESS_NONE, 0, &m, &e);
        }
        if (failed) {
            fprintf(stderr, "bentray animate: frame %d: %s\n", k + 1, e.message);
            return exit_code_of(&e);
        }
        /* render's default compression, so that each frame's printed command makes it byte for byte */
        if (png_write_rgba8(path, m.dump.width, m.dump.height, m.rgba, out->force, PNG_COMPRESSION_FAST, &e) != 0) {
            fprintf(stderr, "bentray animate: frame %d: %s\n", k + 1, e.message);
            measured_free(&m);
            return exit_code_of(&e);
        }
        measured_free(&m);
        double elapsed = clock_seconds() - p.start, left = elapsed * (a->frames - k - 1) / (k + 1);
        if (out->quiet) {
            printf("%s\n", path);
        } else {
            printf("frame %d/%d (%.1f s, about %.0f s left): bentray render", k + 1, a->frames, elapsed, left);
            for (int i = 0; i < out->n_echo; i++) {
                putchar(' ');
                shell_word(stdout, out->echo[i]);
            }
            for (int i = 0; i < n_sets; i++) {
                fputs(" --set ", stdout);
                shell_word(stdout, sets[i]);
            }
            fputs(" --out ", stdout);
            shell_word(stdout, path);
            putchar('\n');
        }
        fflush(stdout);
    }
    if (out->video && rc == EXIT_OK && !have_ffmpeg()) {
        /* the frames are made: the video is one command away, once ffmpeg is there */
        fprintf(stderr, "bentray animate: --video: ffmpeg is not installed (Debian: apt-get install ffmpeg); the "
                        "frames are in %s, and this makes the video from them:\n  ", out->dir);
        char fps_text[32], pattern[4200];
        const char *args[24];
        ffmpeg_args(out->dir, a->frames, out->fps, out->video, fps_text, pattern, args);
        print_ffmpeg(stderr, args);
        fprintf(stderr, "\n");
        return EXIT_RUNTIME;
    }
    if (out->video && rc == EXIT_OK) {
        rc = make_video(out->dir, a->frames, out->fps, out->video, out->force);
        if (rc == EXIT_OK && !out->quiet)
            printf("video: %s (%d frames at %g per second)\n", out->video, a->frames, out->fps);
    }
    return rc;
}

int cmd_animate(int argc, char **argv)
{
    struct common_options o = {.backend = "auto"};
    static struct animation a;
    memset(&a, 0, sizeof a);
    const char *dir = NULL, *video = NULL;
    int force = 0, quiet = 0, fps_given = 0;
    double fps = 24.0;
    /* the command line's own options for render, echoed in each frame's command */
    const char *echo[2 * OPTIONS_MAX_SETS + 64];
    int n_echo = 0;
    enum { FRAMES, SET_RANGE, ORBIT, FPS, OUT, VIDEO, FORCE, QUIET, ORBIT_AXIS };
    static const struct option_spec specs[] = {
        {"--frames", "N", FRAMES}, {"--set-range", "SECTION.KEY=A:B", SET_RANGE}, {"--orbit", "DEGREES", ORBIT},
        {"--fps", "F", FPS},       {"--out", "DIR", OUT},                         {"--video", "FILE", VIDEO},
        {"--force", NULL, FORCE},  {"--quiet", NULL, QUIET},                      {"--orbit-axis", "X Y Z", ORBIT_AXIS},
        {NULL, NULL, 0},
    };
    struct option_reader rd = {.cmd = "animate", .own = specs, .common = common_option_specs,
                               .usage = usage, .argc = argc, .argv = argv};
    const struct option_spec *sp;
    const char *v;
    int got;
    while ((got = option_read(&rd, &sp, &v)) > 0) {
        long n;
        char *end;
        switch (sp->id) {
        case FRAMES:
            if (option_parse_int(v, 1, ANIMATE_MAX_FRAMES, &n) != 0) {
                fprintf(stderr, "bentray animate: --frames: expected 1 to %d, got '%s'\n", ANIMATE_MAX_FRAMES, v);
                return EXIT_USAGE;
            }
            a.frames = (int)n;
            break;
        case SET_RANGE:
            if (a.n_ranges == ANIMATE_MAX_RANGES) {
                fprintf(stderr, "bentray animate: --set-range: at most %d\n", ANIMATE_MAX_RANGES);
                return EXIT_USAGE;
            }
            if (parse_range(v, &a.ranges[a.n_ranges++]) != 0)
                return EXIT_USAGE;
            break;
        case ORBIT:
            errno = 0;
            a.orbit_deg = strtod(v, &end);
            if (end == v || *end || errno || !(fabs(a.orbit_deg) <= 36000.0)) {
                fprintf(stderr, "bentray animate: --orbit: expected degrees from -36000 to 36000, got '%s'\n", v);
                return EXIT_USAGE;
            }
            a.orbit = 1;
            break;
        case ORBIT_AXIS: {
            double x[3];
            const char *why = "";
            if (conf_parse_numbers(v, x, 3, &why) != 0 || !(fabs(x[0]) + fabs(x[1]) + fabs(x[2]) > 0.0)) {
                fprintf(stderr, "bentray animate: --orbit-axis: expected a direction \"X Y Z\", not all zero, got "
                                "'%s'\n", v);
                return EXIT_USAGE;
            }
            a.orbit_axis = v3(x[0], x[1], x[2]);
            a.orbit_axis_given = 1;
            break;
        }
        case FPS:
            errno = 0;
            fps = strtod(v, &end);
            if (end == v || *end || errno || !(fps > 0.0 && fps <= ANIMATE_MAX_FPS)) {
                fprintf(stderr, "bentray animate: --fps: expected frames per second above 0, at most %d, got '%s'\n",
                        ANIMATE_MAX_FPS, v);
                return EXIT_USAGE;
            }
            fps_given = 1;
            break;
        case OUT:
            dir = v;
            break;
        case VIDEO:
            video = v;
            break;
        case FORCE:
            force = 1;
            break;
        case QUIET:
            quiet = 1;
            break;
        default:
            if (options_common(&o, "animate", sp->id, v) != 0)
                return EXIT_USAGE;
            /* the command line's own options for render, echoed in each frame's command under
             * their full names (an abbreviation on this line may be ambiguous to render) */
            if (n_echo + 2 <= (int)(sizeof echo / sizeof echo[0])) {
                echo[n_echo++] = sp->name;
                if (v)
                    echo[n_echo++] = v;
            }
        }
    }
    if (got < 0)
        return rd.exit_code;
    if (!a.frames || !dir) {
        fprintf(stderr, "bentray animate: %s is required\n", !a.frames ? "--frames N" : "--out DIR");
        return EXIT_USAGE;
    }
    if (fps_given && !video) {
        fprintf(stderr, "bentray animate: --fps sets the video's frame rate and goes with --video FILE\n");
        return EXIT_USAGE;
    }
    /* one value a key: two ranges, or a range and a --set, of one key would fight */
    for (int i = 0; i < a.n_ranges; i++) {
        size_t len = strlen(a.ranges[i].key);
        for (int j = i + 1; j < a.n_ranges; j++)
            if (strcmp(a.ranges[i].key, a.ranges[j].key) == 0) {
                fprintf(stderr, "bentray animate: --set-range %s given twice: give one range a key\n",
                        a.ranges[i].key);
                return EXIT_USAGE;
            }
        for (int j = 0; j < o.n_sets; j++)
            if (strncmp(o.sets[j], a.ranges[i].key, len) == 0 && (o.sets[j][len] == '=' || o.sets[j][len] == ' ')) {
                fprintf(stderr, "bentray animate: --set %s and --set-range %s: the range sets the key in every "
                                "frame; give one or the other\n", o.sets[j], a.ranges[i].key);
                return EXIT_USAGE;
            }
    }
    if (a.orbit_axis_given && !a.orbit) {
        fprintf(stderr, "bentray animate: --orbit-axis gives the axis of --orbit DEGREES, which is missing\n");
        return EXIT_USAGE;
    }
    /* the orbit turns the scene's own camera: a range that moves it too would fight it */
    for (int i = 0; i < a.n_ranges && a.orbit; i++)
        if (strncmp(a.ranges[i].key, "camera.", 7) == 0 && strcmp(a.ranges[i].key, "camera.fov") != 0) {
            fprintf(stderr, "bentray animate: --orbit and --set-range %s: the orbit moves the camera itself; give "
                            "one or the other (camera.fov may move with the orbit)\n", a.ranges[i].key);
            return EXIT_USAGE;
        }
    if (video && video_kind(video) < 0) {
        fprintf(stderr, "bentray animate: --video %s: give the file the extension .webm, .mp4 or .gif\n", video);
        return EXIT_USAGE;
    }
    struct animate_out out = {dir, video, force, quiet, fps, echo, n_echo};
    struct scene *base = options_scene_new("animate"), *s = base ? options_scene_new("animate") : NULL;
    int rc = s ? animate(&o, &a, &out, base, s) : EXIT_RUNTIME;
    scene_free(s);
    scene_free(base);
    return rc;
}
