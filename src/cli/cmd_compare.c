/* bentray compare: error metrics of one dump against a reference dump (docs/ERRORS.md). */
#include "cli/commands.h"
#include "cli/options.h"
#include "results/compare.h"
#include <stdio.h>
#include <string.h>

static void usage(FILE *out)
{
    fprintf(out, "usage: bentray compare A.dump B.dump [--json] [--help]\n"
                 "Compare the per-pixel dump A (under test) with B (the reference) of the same scene and\n"
                 "size: pixels whose outcome differs, hit-point error, sky-direction angle, image PSNR.\n"
                 "Prints a table, or JSON with --json. Metrics are defined in docs/ERRORS.md.\n");
}

/* Read and check one dump; the messages of dump_read name the file already. EXIT_OK, or the exit
 * code of the error's status: EXIT_USAGE for a bad dump (or a path refused), EXIT_RUNTIME where
 * the machine fails (too little memory for a good dump, a read error). */
static int load(const char *path, struct dump *d)
{
    struct error e;
    if (dump_read(path, d, &e) != 0) {
        fprintf(stderr, "bentray compare: %s\n", e.message);
        return exit_code_of(&e);
    }
    if (compare_dump_check(d, &e) != 0) {
        fprintf(stderr, "bentray compare: %s: %s\n", path, e.message);
        dump_free(d);
        return exit_code_of(&e);
    }
    return EXIT_OK;
}

/* The two dump paths and --json; 1 after --help, -1 on bad usage, else 0. */
static int parse(int argc, char **argv, const char *paths[2], int *json)
{
    int n = 0;
    enum { JSON };
    static const struct option_spec specs[] = {{"--json", NULL, JSON}, {NULL, NULL, 0}};
    struct option_reader rd = {.cmd = "compare", .own = specs,
                               .usage = usage, .argc = argc, .argv = argv, .arguments = 1};
    const struct option_spec *sp;
    const char *v;
    int got;
    while ((got = option_read(&rd, &sp, &v)) > 0) {
        if (sp->id == JSON) {
            *json = 1;
        } else if (n == 2) {
            fprintf(stderr, "bentray compare: unexpected third file '%s'\n", v);
            usage(stderr);
            return -1;
        } else {
            paths[n++] = v;
        }
    }
    if (got < 0)
        return rd.exit_code == EXIT_OK ? 1 : -1;
    if (n < 2) {
        fprintf(stderr, "bentray compare: expected two dumps, A (under test) and B (reference)\n");
        usage(stderr);
        return -1;
    }
    return 0;
}

int cmd_compare(int argc, char **argv)
{
    const char *paths[2];
    int json = 0;
    int p = parse(argc, argv, paths, &json);
    if (p != 0)
        return p > 0 ? EXIT_OK : EXIT_USAGE;
    struct dump a, b;
    int loaded = load(paths[0], &a);
    if (loaded != EXIT_OK)
        return loaded;
    loaded = load(paths[1], &b);
    if (loaded != EXIT_OK) {
        dump_free(&a);
        return loaded;
    }
    struct compare_result r;
    struct error e;
    int rc = compare_dumps(&a, &b, &r, &e);
    if (rc != 0)
        fprintf(stderr, "bentray compare: %s: %s (reference: %s)\n", paths[0], e.message, paths[1]);
    else if (json)
        compare_print_json(stdout, &r);
    else
        compare_print_table(stdout, &r);
    dump_free(&a);
    dump_free(&b);
    return rc == 0 ? EXIT_OK : exit_code_of(&e);
}
