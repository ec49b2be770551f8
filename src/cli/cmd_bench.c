/* bentray bench: speed and speed against error, written to OUT/BENCH.md with CSV files and gnuplot
 * scripts in OUT/bench/ (src/bench/). Benchmarks are never timed tests. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "io/clock.h"
#include "bench/bench.h"
#include "cli/commands.h"
#include "cli/options.h"
#include "render/renderer.h"

/* --runs: timed runs per configuration; bench_time() keeps their times in an array of 64. */
#define BENCH_MAX_RUNS 63

static const char *const section_names[] = {"table1", "figure5", "unrolling", "batching", "early-z", "pareto",
                                            "pipelines", "limit", "relativity", "antialias", "light", "stars",
                                            "wait", "kiosk"};
#define N_SECTIONS (int)(sizeof section_names / sizeof section_names[0])
static int (*const sections[N_SECTIONS])(struct bench *, struct error *) = {
    bench_table1, bench_figure5, bench_unrolling, bench_batching, bench_early_z, bench_pareto, bench_pipelines,
    bench_limit, bench_relativity, bench_antialias, bench_light, bench_stars, bench_wait, bench_kiosk};
/* configurations each section times (for the progress count); the pareto and pipelines sections
 * count their own tables', the kiosk's adds its configuration's scenes when it has read them */
static int section_steps[N_SECTIONS] = {20, 20, 5, 4, 6, 0 /* bench_pareto_count */, 0 /* bench_pipelines_count */,
                                        2, 9, 6, 7, 8, 5, 0};
static int section_steps_quick[N_SECTIONS] = {20, 10, 5, 4, 6, 3, 0 /* bench_pipelines_count */, 2, 4, 3, 6, 1, 5, 0};

static void usage(FILE *out)
{
    fprintf(out,
            "usage: bentray bench --out DIR [options]\n"
            "Measure the renderer: the paper's Table 1 and Figure 5, unrolling, objects per pass, early-z,\n"
            "speed against error against the CPU reference, the machine's limit, and relativity (moving\n"
            "objects as rays and as polygons, the observer's effects). Writes DIR/BENCH.md,\n"
            "and CSV files and gnuplot scripts in DIR/bench/ (`make bench` draws the plots).\n"
            "  --out DIR            where to write (DIR must exist)\n"
            "  --force              overwrite an existing DIR/BENCH.md and its data files\n"
            "  --runs N             timed runs per configuration, the median is reported (1-63, default 3)\n"
            "  --size WxH           frame size of the paper's measurements (default 800x600)\n"
            "  --only S[,S...]      sections: table1, figure5, unrolling, batching, early-z, pareto, pipelines, limit,\n"
            "                       relativity, antialias, light, stars, wait, kiosk\n"
            "  --kiosk              the kiosk's section alone (previews per second for each knob, orbit-table\n"
            "                       milliseconds per detent, first frame, time to the refined frame); without\n"
            "                       --out its table goes to standard output, no file written\n"
            "  --config FILE        the kiosk configuration whose scenes the kiosk's section measures (default:\n"
            "                       kiosk/kiosk.conf of the source tree this program was built in, else\n"
            "                       /etc/bentray/kiosk.conf)\n"
            "  --quick              tiny frames and few configurations: proves the command works, measures nothing\n"
            "  --backend NAME       egl, osmesa or auto (default)\n"
            "exit codes: 0 ok, 1 runtime failure, 2 bad usage or input (a data file refused)\n");
}

static int parse_only(const char *list, int *wanted)
{
    char buf[256];
    snprintf(buf, sizeof buf, "%s", list);
    if (strspn(buf, ", ") == strlen(buf)) {
        fprintf(stderr, "bentray bench: --only: name at least one section (sections: table1, figure5, unrolling, "
                        "batching, early-z, pareto, pipelines, limit, relativity, antialias, light, stars, wait, kiosk)\n");
        return -1;
    }
    for (char *save = NULL, *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        int found = 0;
        for (int k = 0; k < N_SECTIONS; k++)
            if (strcmp(tok, section_names[k]) == 0)
                wanted[k] = found = 1;
        if (!found) {
            fprintf(stderr, "bentray bench: --only: unknown section '%s' (sections: table1, figure5, unrolling, "
                            "batching, early-z, pareto, pipelines, limit, relativity, antialias, light, stars, wait, kiosk)\n", tok);
            return -1;
        }
    }
    return 0;
}

static void machine_line(FILE *md, const struct bench *b)
{
    char cpu[256] = "unknown CPU", line[256];
    FILE *f = fopen("/proc/cpuinfo", "r");
    while (f && fgets(line, sizeof line, f))
        if (strncmp(line, "model name", 10) == 0) {
            const char *colon = strchr(line, ':');
            snprintf(cpu, sizeof cpu, "%s", colon ? colon + 2 : line);
            cpu[strcspn(cpu, "\n")] = '\0';
            break;
        }
    if (f)
        fclose(f);
    fprintf(md, "Machine: %s, %ld cores. GL: %s on %s. Frame size %dx%d; %d timed runs per configuration "
                "after one warm-up, median reported. Times on a shared machine are noisy: compare "
                "configurations within one run of the bench.\n\n",
            cpu, sysconf(_SC_NPROCESSORS_ONLN), b->renderer, b->backend, b->width, b->height, b->runs);
}

/* DIR/BENCH.md and DIR/bench/: checked, and the data directory made. */
static int prepare_out(struct bench *b, const char *out, int force, char *md_path, size_t md_len)
{
    snprintf(b->out_dir, sizeof b->out_dir, "%s", out);
    snprintf(b->data_dir, sizeof b->data_dir, "%s/bench", out);
    snprintf(md_path, md_len, "%s/BENCH.md", out);
    struct stat st;
    if (stat(out, &st) != 0 || !S_ISDIR(st.st_mode)) {
        fprintf(stderr, "bentray bench: --out: %s is not a directory\n", out);
        return EXIT_USAGE;
    }
    if (!force && stat(md_path, &st) == 0) {
        fprintf(stderr, "bentray bench: %s exists; pass --force to overwrite it and its data in %s\n", md_path,
                b->data_dir);
        return EXIT_USAGE;
    }
    if (mkdir(b->data_dir, 0755) != 0 && errno != EEXIST) {
        fprintf(stderr, "bentray bench: cannot create %s: %s\n", b->data_dir, strerror(errno));
        return EXIT_RUNTIME;
    }
    return EXIT_OK;
}

/* The section "On the GPUs of an exhibit" that make shader-stats wrote into DIR/bench/shader_stats.md
 * (the drivers' compilers are not on every machine that runs the bench): copied in as it is, or a line
 * that says how to make it. */
static void include_shader_stats(struct bench *b)
{
    char path[BENCH_PATH_LEN + 32];
    snprintf(path, sizeof path, "%s/shader_stats.md", b->data_dir);
    FILE *f = fopen(path, "r");
    if (!f) {
        fprintf(b->md, "## On the GPUs of an exhibit\n\nNot measured in this run: `make shader-stats` writes this "
                       "section (%s), from the real compilers of the exhibit's GPUs.\n\n", path);
        return;
    }
    char buf[4096];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, f)) > 0)
        fwrite(buf, 1, n, b->md);
    fclose(f);
    fprintf(b->md, "\n");
}

int cmd_bench(int argc, char **argv)
{
    static struct bench b;
    const char *out = NULL, *backend = "auto";
    int force = 0, wanted[N_SECTIONS] = {0}, any = 0, kiosk_only = 0;
    long runs = 3;
    b.width = 800;
    b.height = 600;
    enum { FORCE, QUICK, KIOSK, OUT, BACKEND, RUNS, SIZE, ONLY, CONFIG };
    static const struct option_spec specs[] = {
        {"--force", NULL, FORCE}, {"--quick", NULL, QUICK}, {"--kiosk", NULL, KIOSK}, {"--out", "DIR", OUT},
        {"--backend", "NAME", BACKEND}, {"--runs", "N", RUNS}, {"--size", "WxH", SIZE}, {"--only", "S[,S...]", ONLY},
        {"--config", "FILE", CONFIG}, {NULL, NULL, 0},
    };
    struct option_reader rd = {.cmd = "bench", .own = specs, .usage = usage, .argc = argc, .argv = argv};
    const struct option_spec *sp;
    const char *v;
    int got;
    while ((got = option_read(&rd, &sp, &v)) > 0) {
        switch (sp->id) {
        case FORCE:
            force = 1;
            break;
        case QUICK:
            b.quick = 1;
            break;
        case KIOSK:
            wanted[N_SECTIONS - 1] = any = kiosk_only = 1;   /* the kiosk's section is the last */
            break;
        case OUT:
            out = v;
            break;
        case BACKEND:
            backend = v;
            if (!option_backend_valid(backend)) {
                fprintf(stderr, "bentray bench: --backend: expected egl, osmesa or auto, got '%s'\n", backend);
                return EXIT_USAGE;
            }
            break;
        case RUNS:
            if (option_parse_int(v, 1, BENCH_MAX_RUNS, &runs) != 0) {
                fprintf(stderr, "bentray bench: --runs: expected an integer from 1 to %d, got '%s'\n", BENCH_MAX_RUNS, v);
                return EXIT_USAGE;
            }
            break;
        case SIZE:
            if (option_parse_size(v, &b.width, &b.height) != 0 || b.width < 16 || b.height < 16) {
                fprintf(stderr, "bentray bench: --size: expected WxH, each from 16 to %d, W x H at most %ld pixels, "
                        "got '%s'\n", SCENE_MAX_SIZE, SCENE_MAX_PIXELS, v);
                return EXIT_USAGE;
            }
            break;
        case CONFIG:
            if (strlen(v) >= sizeof b.kiosk_config) {
                fprintf(stderr, "bentray bench: --config: the path is longer than %d characters\n",
                        (int)sizeof b.kiosk_config - 1);
                return EXIT_USAGE;
            }
            snprintf(b.kiosk_config, sizeof b.kiosk_config, "%s", v);
            break;
        case ONLY:
            if (parse_only(v, wanted) != 0)
                return EXIT_USAGE;
            any = 1;
            break;
        }
    }
    if (got < 0)
        return rd.exit_code;
    int only_given = 0;
    for (int k = 0; k < N_SECTIONS - 1; k++)
        only_given |= wanted[k];
    if (kiosk_only && only_given) {
        fprintf(stderr, "bentray bench: --kiosk runs the kiosk's section alone, --only names others: give one or the "
                        "other (--only kiosk,... for several)\n");
        return EXIT_USAGE;
    }
    if (!out && !kiosk_only) {
        fprintf(stderr, "bentray bench: --out DIR is required\n");
        usage(stderr);
        return EXIT_USAGE;
    }
    if (!any)
        for (int k = 0; k < N_SECTIONS; k++)
            wanted[k] = 1;
    b.runs = (int)runs;
    if (b.quick) {
        b.width = 32;
        b.height = 24;
        b.runs = 1;
    }
    char md_path[BENCH_PATH_LEN + 16] = "";
    int prepared = out ? prepare_out(&b, out, force, md_path, sizeof md_path) : EXIT_OK;
    if (prepared != EXIT_OK)
        return prepared;
    struct error e;
    b.ctx = gl_context_create(backend, &e);
    if (!b.ctx) {
        fprintf(stderr, "bentray bench: %s\n", e.message);
        return EXIT_RUNTIME;
    }
    snprintf(b.backend, sizeof b.backend, "%s", b.ctx->backend);
    snprintf(b.renderer, sizeof b.renderer, "%s", (const char *)glGetString(GL_RENDERER));
    struct error md_err;
    /* without --out the report goes to standard output, also only whole: kept in memory until the
     * bench has succeeded */
    char *report = NULL;
    size_t report_len = 0;
    b.md = out ? bench_file(&b, md_path, &md_err) : open_memstream(&report, &report_len);
    if (!b.md) {
        if (out)
            fprintf(stderr, "bentray bench: %s\n", md_err.message);
        else
            fprintf(stderr, "bentray bench: out of memory for the report\n");
        gl_context_destroy(b.ctx);
        return out ? exit_code_of(&md_err) : EXIT_RUNTIME;
    }
    section_steps[5] = bench_pareto_count;
    section_steps[6] = section_steps_quick[6] = bench_pipelines_count;
    for (int k = 0; k < N_SECTIONS; k++)
        b.total += wanted[k] ? (b.quick ? section_steps_quick : section_steps)[k] : 0;
    b.started = clock_seconds();
    fprintf(b.md, "# Benchmarks\n\nWritten by `make bench` (`bentray bench --out docs --force`, then gnuplot on "
                  "the scripts in `docs/bench/`); every figure below comes from that run.%s\n\n",
            b.quick ? " **Quick mode: tiny frames, the figures mean nothing.**" : "");
    machine_line(b.md, &b);
    /* a section that fails ends the bench with its error's status: 2 for a data file the system
     * refuses (a directory in its place), 1 where the machine fails */
    int rc = EXIT_OK;
    error_clear(&e);
    for (int k = 0; k < N_SECTIONS && rc == EXIT_OK; k++)
        if (wanted[k] && sections[k](&b, &e) != 0) {
            fprintf(stderr, "bentray bench: %s: %s%s%s\n", section_names[k], e.where, e.where[0] ? ": " : "",
                    e.message);
            rc = exit_code_of(&e);
        }
    if (out && rc == EXIT_OK && !kiosk_only)
        include_shader_stats(&b);
    fprintf(b.md, "Total bench time: %.0f s.\n", clock_seconds() - b.started);
    fclose(b.md);
    if (!out) {
        if (rc == EXIT_OK && report && (fwrite(report, 1, report_len, stdout) != report_len || fflush(stdout) != 0)) {
            fprintf(stderr, "bentray bench: writing the report to standard output: %s\n", strerror(errno));
            rc = EXIT_RUNTIME;
        }
        free(report);
    }
    gl_context_destroy(b.ctx);
    /* the report and its data are written only whole: a bench that failed or was interrupted
     * leaves the earlier ones as they were */
    if (rc != EXIT_OK) {
        bench_files_drop(&b);
    } else if (bench_files_write(&b, &e) != 0) {
        fprintf(stderr, "bentray bench: %s\n", e.message);
        rc = exit_code_of(&e);
    } else if (out) {
        fprintf(stderr, "bentray bench: wrote %s and %s/\n", md_path, b.data_dir);
    }
    return rc;
}
