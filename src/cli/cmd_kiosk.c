/* bentray kiosk: the exhibition kiosk (src/kiosk/), or a check of its inputs. */
#include "cli/commands.h"
#include "cli/options.h"
#include "input/keymap.h"
#include "kiosk/kiosk_loop.h"
#include "kiosk_config/kiosk_config_keys.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define KIOSK_DEFAULT_CONFIG "/etc/bentray/kiosk.conf"

static void usage(FILE *out)
{
    fprintf(out,
            "usage: bentray kiosk [--config FILE] [--display auto|kms|x11|headless] [--backend egl|osmesa|auto]\n"
            "                     [--out DIR] [--frames N] [--force] [--stats] [--check-inputs]\n"
            "Run the exhibition kiosk: knobs for the observer's speed and the central mass, buttons for\n"
            "scenes and effects, a preview while a knob turns and the refined frame once it rests.\n"
            "  --config FILE    the kiosk's configuration (every key: kiosk/kiosk.conf); default %s\n"
            "  --display NAME   overrides [display] backend\n"
            "  --backend NAME   GL back-end of the headless screen (default auto: EGL, then OSMesa)\n"
            "  --out DIR        headless: overrides [display] headless_out\n"
            "  --frames N       headless: overrides [display] headless_frames\n"
            "  --force          headless: frames may replace the files of an earlier run\n"
            "  --stats          the log gets each refined frame's times: its previews (average, longest)\n"
            "                   and its bands, as in staff mode (the staff_mode action, key i)\n"
            "  --check-inputs   print every event of every configured input, one line each, and one\n"
            "                   line per missing device; no display. Stops on Ctrl-C or SIGTERM.\n"
            "%s"
            "exit codes: 0 stopped, 1 failure while running, 2 bad configuration or option,\n"
            "3 this GPU can draw none of the scenes (the service then does not restart)\n",
            KIOSK_DEFAULT_CONFIG, keymap_help);
}

/* One configuration travels from the laptop to the exhibit: --display takes another screen than the
 * file's, whose keys for its own screen (a KMS connector, vsync, headless_out) are set aside with a
 * note instead of refused. */
static void note_aside(char *list, size_t len, const char *name)
{
    size_t used = strlen(list);
    snprintf(list + used, len - used, "%s%s", used ? ", " : "", name);
}

static void set_aside_screen_keys(struct kiosk_config *c, const char *display)
{
    struct kiosk_display *d = &c->display;
    char aside[160] = "";
    int kms = d->backend == KIOSK_BACKEND_KMS || d->backend == KIOSK_BACKEND_AUTO;
    int headless = d->backend == KIOSK_BACKEND_HEADLESS || d->backend == KIOSK_BACKEND_AUTO;
    if (!kms && d->drm_device[0]) {
        note_aside(aside, sizeof aside, "drm_device");
        d->drm_device[0] = '\0';
    }
    if (!kms && d->connector[0]) {
        note_aside(aside, sizeof aside, "connector");
        d->connector[0] = '\0';
    }
    if (!kms && d->mode_width) {
        note_aside(aside, sizeof aside, "mode");
        d->mode_width = d->mode_height = 0;
    }
    if (d->backend == KIOSK_BACKEND_HEADLESS && kiosk_key_line(c, KSEC_DISPLAY, 0, "vsync"))
        note_aside(aside, sizeof aside, "vsync");
    if (!headless && d->headless_out[0]) {
        note_aside(aside, sizeof aside, "headless_out");
        d->headless_out[0] = '\0';
    }
    if (!headless && d->headless_frames) {
        note_aside(aside, sizeof aside, "headless_frames");
        d->headless_frames = 0;
    }
    d->backend_overridden = 1;
    if (aside[0])
        fprintf(stderr, "bentray kiosk: --display %s: [display] %s set aside (for the file's own screen)\n", display,
                aside);
}

static int parse_display(const char *name, enum kiosk_backend *out)
{
    static const char *const names[] = {"auto", "kms", "x11", "headless"};
    for (int i = 0; i < 4; i++)
        if (strcmp(name, names[i]) == 0) {
            *out = (enum kiosk_backend)i;
            return 0;
        }
    return -1;
}

int cmd_kiosk(int argc, char **argv)
{
    const char *config = KIOSK_DEFAULT_CONFIG, *display = NULL, *out_dir = NULL, *backend = "auto";
    long frames = -1;
    int force = 0, check_inputs = 0, stats = 0;
    enum { CONFIG, DISPLAY, BACKEND, OUT, FRAMES, FORCE, STATS, CHECK_INPUTS };
    static const struct option_spec specs[] = {
        {"--config", "FILE", CONFIG}, {"--display", "D", DISPLAY}, {"--backend", "B", BACKEND},
        {"--out", "DIR", OUT},        {"--frames", "N", FRAMES},   {"--force", NULL, FORCE},
        {"--stats", NULL, STATS},    {"--check-inputs", NULL, CHECK_INPUTS}, {NULL, NULL, 0},
    };
    struct option_reader rd = {.cmd = "kiosk", .own = specs, .usage = usage, .argc = argc, .argv = argv};
    const struct option_spec *sp;
    const char *v;
    int got;
    while ((got = option_read(&rd, &sp, &v)) > 0) {
        switch (sp->id) {
        case CONFIG:
            config = v;
            break;
        case DISPLAY:
            display = v;
            break;
        case BACKEND:
            backend = v;
            break;
        case OUT:
            out_dir = v;
            break;
        case FRAMES:
            if (option_parse_int(v, 0, 1000000, &frames) != 0) {
                fprintf(stderr, "bentray kiosk: --frames: expected a whole number from 0 to 1000000, got '%s'\n", v);
                return EXIT_USAGE;
            }
            break;
        case FORCE:
            force = 1;
            break;
        case STATS:
            stats = 1;
            break;
        case CHECK_INPUTS:
            check_inputs = 1;
            break;
        }
    }
    if (got < 0)
        return rd.exit_code;
    if (!option_backend_valid(backend)) {
        fprintf(stderr, "bentray kiosk: --backend: unknown back-end '%s' (expected egl, osmesa or auto)\n", backend);
        return EXIT_USAGE;
    }
    static struct kiosk_config c;
    struct error e;
    if (kiosk_config_load(&c, config, &e) != 0) {
        fprintf(stderr, "bentray kiosk: %s: %s\n", e.where, e.message);
        return EXIT_USAGE;
    }
    enum kiosk_backend from_file = c.display.backend;
    if (display && parse_display(display, &c.display.backend) != 0) {
        fprintf(stderr, "bentray kiosk: --display: unknown display '%s' (expected auto, kms, x11 or headless)\n",
                display);
        return EXIT_USAGE;
    }
    if (display && c.display.backend != from_file)
        set_aside_screen_keys(&c, display);
    if (out_dir) {
        if (strlen(out_dir) >= sizeof c.display.headless_out) {
            fprintf(stderr, "bentray kiosk: --out: the path is longer than %zu characters\n",
                    sizeof c.display.headless_out - 1);
            return EXIT_USAGE;
        }
        snprintf(c.display.headless_out, sizeof c.display.headless_out, "%s", out_dir);
    }
    if (frames >= 0)
        c.display.headless_frames = (int)frames;
    /* after the options, which stand in for keys of the file */
    if (kiosk_config_check(&c, &e) != 0) {
        fprintf(stderr, "bentray kiosk: %s: %s\n", e.where, e.message);
        return EXIT_USAGE;
    }
    if (check_inputs)
        return kiosk_check_inputs(&c, stdout, stderr);
    FILE *log = stderr;
    if (strcmp(c.kiosk.log, "stderr") != 0) {
        log = fopen(c.kiosk.log, "a");
        if (!log) {
            fprintf(stderr, "bentray kiosk: %s: [kiosk] log: cannot open %s for appending: %s\n", c.path, c.kiosk.log,
                    strerror(errno));
            return EXIT_USAGE;
        }
    }
    setvbuf(log, NULL, _IOLBF, 0);
    struct kiosk_run_options o = {.gl_backend = backend, .force = force, .stats = stats, .log = log};
    enum kiosk_status status = kiosk_run(&c, &o);
    if (log != stderr)
        fclose(log);
    /* the kiosk's statuses are its exit codes (kiosk_loop.h) */
    return (int)status;
}
