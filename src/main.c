/* bentray: light on curved paths, traced on the GPU (Weiskopf, Schafhitzel, Ertl 2004). */
#include "cli/commands.h"
#include "io/stderr_filter.h"
#include "io/std_streams.h"
#include "io/clock.h"
#include <stdio.h>
#include <string.h>

static void usage(FILE *out)
{
    fprintf(out,
            "usage: bentray COMMAND [options]\n"
            "\n"
            "commands:\n"
            "  render   render a scene headless to a PNG (and optionally a per-pixel dump)\n"
            "  animate  render a sequence of frames (keys moving, the camera orbiting) and a video\n"
            "  trace    print one ray's polyline and result as JSON\n"
            "  info     probe the GL back-ends: versions, float formats, MRT, render path\n"
            "  compare  error metrics of one per-pixel dump against a reference dump\n"
            "  error    render a scene on the GPU and on the CPU reference and compare them\n"
            "  bench    measure speed, and speed against error, into a report (docs/BENCH.md)\n"
            "  kiosk    the exhibition kiosk: knobs, buttons, preview and refined frames, HUD\n"
            "\n"
            "bentray COMMAND --help shows the options of a command; an option's value may follow it\n"
            "or be joined to it with '=' (--scene=FILE), and an option may be shortened to any\n"
            "beginning of its name that no other option of the command shares (--sam for --samples).\n"
            "bentray --version prints the version.\n"
            "exit codes: 0 ok, 1 runtime failure, 2 bad usage or input, 3 a scene missed its own [quality]\n"
            "(bentray error --check)\n");
}

#ifndef BENTRAY_VERSION
#define BENTRAY_VERSION "unknown"
#endif

int main(int argc, char **argv)
{
    clock_mark_start();
    std_streams_guard();
    stderr_escape_controls();
    if (argc >= 2 && strcmp(argv[1], "--version") == 0) {
        if (argc > 2) {
            fprintf(stderr, "bentray --version: unexpected argument '%s'\n", argv[2]);
            return EXIT_USAGE;
        }
        printf("bentray %s\n", BENTRAY_VERSION);
        return EXIT_OK;
    }
    if (argc < 2) {
        usage(stderr);
        return EXIT_USAGE;
    }
    const char *cmd = argv[1];
    if (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0 || strcmp(cmd, "help") == 0) {
        usage(stdout);
        return EXIT_OK;
    }
    if (strcmp(cmd, "info") == 0)
        return cmd_info(argc - 1, argv + 1);
    if (strcmp(cmd, "render") == 0)
        return cmd_render(argc - 1, argv + 1);
    if (strcmp(cmd, "animate") == 0)
        return cmd_animate(argc - 1, argv + 1);
    if (strcmp(cmd, "trace") == 0)
        return cmd_trace(argc - 1, argv + 1);
    if (strcmp(cmd, "compare") == 0)
        return cmd_compare(argc - 1, argv + 1);
    if (strcmp(cmd, "error") == 0)
        return cmd_error(argc - 1, argv + 1);
    if (strcmp(cmd, "bench") == 0)
        return cmd_bench(argc - 1, argv + 1);
    if (strcmp(cmd, "kiosk") == 0)
        return cmd_kiosk(argc - 1, argv + 1);
    fprintf(stderr, "bentray: unknown command '%s'\n", cmd);
    usage(stderr);
    return EXIT_USAGE;
}
