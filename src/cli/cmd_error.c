/* bentray error: render a scene on the GPU and on the CPU reference, and report the error of the
 * GPU image against the reference with both times: speed against error for one configuration. */
#include "cli/commands.h"
#include "cli/measure.h"
#include "cli/options.h"
#include "results/compare.h"
#include "results/quality.h"
#include <stdio.h>
#include <string.h>

static void usage(FILE *out)
{
    fprintf(out,
            "usage: bentray error --scene FILE [options]\n"
            "Render the scene with the GPU engine and with the CPU reference, and compare them\n"
            "(metrics in docs/ERRORS.md). GPU options: --backend, --precision, --no-mrt, --shader-dir;\n"
            "CPU options: --rtol, --threads; both: --size, --samples N, --set SECTION.KEY=V.\n"
            "  --json               print JSON instead of the table\n"
            "  --check              hold the error against the scene's [quality] bounds (stated for its\n"
            "                       own settings and size); exit 3 when one is missed\n"
            "exit codes: 0 ok (without --check a large error is not a failure), 1 runtime failure,\n"
            "2 bad usage or input (--check on a scene without [quality] included), 3 [quality] missed\n");
}

static void print_times(FILE *f, const struct measured *gpu, const struct measured *cpu, int json)
{
    if (json)
        fprintf(f, "{\"gpu_seconds\": %.6g, \"gpu_passes\": %ld, \"cpu_seconds\": %.6g, \"cpu_steps\": %ld,\n"
                   " \"comparison\": ", gpu->seconds, gpu->work, cpu->seconds, cpu->work);
    else
        fprintf(f, "time: %s %.3f s (%ld passes); %s %.3f s (%ld steps)\n", gpu->engine, gpu->seconds, gpu->work,
                cpu->engine, cpu->seconds, cpu->work);
}

/* Renders S (loaded here from O) on both engines and reports the error; the command's exit code. */
static int error_scene(const struct common_options *o, int json, int check, struct scene *s)
{
    int rc = options_load_scene(o, "error", s);
    if (rc)
        return rc;
    if (check && !quality_stated(&s->quality)) {
        fprintf(stderr, "bentray error: --check: %s states no [quality] (differing_percent, exit_p99, hit_p99)\n",
                s->path);
        return EXIT_USAGE;
    }
    struct cpu_render_options cpu_opt;
    options_cpu(o, s, &cpu_opt);
    struct measured gpu, cpu;
    struct error e;
    if (measure_gpu(s, o->backend, 1, PROGRESS_AUTO, 0, &gpu, &e) != 0) {
        fprintf(stderr, "bentray error: GPU engine: %s\n", e.message);
        return exit_code_of(&e);
    }
    if (measure_cpu(s, &cpu_opt, &cpu, &e) != 0) {
        fprintf(stderr, "bentray error: CPU reference: %s\n", e.message);
        measured_free(&gpu);
        return exit_code_of(&e);
    }
    struct compare_result r;
    rc = EXIT_OK;
    if (compare_dumps(&gpu.dump, &cpu.dump, &r, &e) != 0) {
        fprintf(stderr, "bentray error: %s\n", e.message);
        rc = exit_code_of(&e);
    } else if (json) {
        print_times(stdout, &gpu, &cpu, 1);
        compare_print_json(stdout, &r);
        printf("}\n");
    } else {
        compare_print_table(stdout, &r);
        print_times(stdout, &gpu, &cpu, 0);
    }
    if (rc == EXIT_OK && check) {
        char report[512];
        int missed = quality_check(&s->quality, &r, report, sizeof report);
        fprintf(json ? stderr : stdout, "quality of %s:\n%s", s->path, report);
        if (missed > 0) {
            fprintf(stderr, "bentray error: %s misses %d of its [quality] bounds\n", s->path, missed);
            rc = EXIT_QUALITY;
        }
    }
    measured_free(&gpu);
    measured_free(&cpu);
    return rc;
}

int cmd_error(int argc, char **argv)
{
    struct common_options o = {.backend = "auto", .both_engines = 1};
    int json = 0, check = 0;
    enum { JSON, CHECK };
    static const struct option_spec specs[] = {{"--json", NULL, JSON}, {"--check", NULL, CHECK}, {NULL, NULL, 0}};
    struct option_reader rd = {.cmd = "error", .own = specs, .common = common_option_specs,
                               .usage = usage, .argc = argc, .argv = argv};
    const struct option_spec *sp;
    const char *v;
    int got;
    while ((got = option_read(&rd, &sp, &v)) > 0) {
        switch (sp->id) {
        case JSON:
            json = 1;
            break;
        case CHECK:
            check = 1;
            break;
        default:
            if (options_common(&o, "error", sp->id, v) != 0)
                return EXIT_USAGE;
        }
    }
    if (got < 0)
        return rd.exit_code;
    struct scene *s = options_scene_new("error");
    if (!s)
        return EXIT_RUNTIME;
    int rc = error_scene(&o, json, check, s);
    scene_free(s);
    return rc;
}
