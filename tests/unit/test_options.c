/* option_read (src/cli/options.c), the command line of every command on glibc's getopt_long: values
 * after an option or joined with '=', unique abbreviations, and every refusal with its message and
 * exit code. Each case is a reader of its own in this one process: each starts getopt afresh. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include "cli/commands.h"
#include "cli/options.h"

enum { SHOUT, OUT, PAIR, LOUD };
static const struct option_spec own[] = {
    {"--out", "FILE", OUT}, {"--force", NULL, SHOUT}, {"--pair", "I J", PAIR}, {"--scene", "OTHER", LOUD},
    {NULL, NULL, 0},
};

static int usages;
static void usage(FILE *out)
{
    (void)out;
    usages++;
}

/* What one command line gave: each option as "ID=VALUE" (or "ID" for a flag, "ARG=VALUE" for an
 * argument) joined by spaces, what option_read returned last, its exit code, and stderr. */
struct outcome {
    char got[512];
    int last, exit_code;
    char err[2048];
};

/* The arguments after the command's name, up to a NULL. */
static void read_line(int arguments, const struct option_spec *common, struct outcome *o, ...)
{
    char *argv[32];
    int argc = 1;
    va_list ap;
    va_start(ap, o);
    argv[0] = "cmd";
    while (argc < 31 && (argv[argc] = va_arg(ap, char *)) != NULL)
        argc++;
    va_end(ap);
    argv[argc] = NULL;
    memset(o, 0, sizeof *o);
    usages = 0;

    fflush(stderr);
    FILE *tmp = tmpfile();
    assert_non_null(tmp);
    int saved = dup(2);
    dup2(fileno(tmp), 2);
    struct option_reader rd = {.cmd = "cmd", .own = own, .common = common, .usage = usage, .argc = argc,
                               .argv = argv, .arguments = arguments};
    const struct option_spec *sp;
    const char *v;
    size_t n = 0;
    while ((o->last = option_read(&rd, &sp, &v)) > 0) {
        n += (size_t)snprintf(o->got + n, sizeof o->got - n, "%s%d%s%s", n ? " " : "", sp->id, v ? "=" : "",
                              v ? v : "");
        if (sp->id == PAIR && rd.next < argc) {      /* the second value, as trace --pixel takes it */
            n += (size_t)snprintf(o->got + n, sizeof o->got - n, ",%s", argv[rd.next]);
            rd.next++;
        }
    }
    o->exit_code = o->last < 0 ? rd.exit_code : -1;
    fflush(stderr);
    dup2(saved, 2);
    close(saved);
    rewind(tmp);
    size_t len = fread(o->err, 1, sizeof o->err - 1, tmp);
    o->err[len] = '\0';
    fclose(tmp);
}

#define EXPECT_ERR(o, text) assert_non_null(strstr((o).err, (text)))

static void test_values(void **state)
{
    (void)state;
    struct outcome o;
    char want[128];
    read_line(0, NULL, &o, "--out", "a.png", "--force", NULL);
    snprintf(want, sizeof want, "%d=a.png %d", OUT, SHOUT);
    assert_string_equal(o.got, want);
    assert_int_equal(o.last, 0);
    assert_string_equal(o.err, "");
    /* joined with '=': the first '=' splits, the value may hold more */
    read_line(0, common_option_specs, &o, "--set=camera.position=-1 0 0", "--out=x=y.png", NULL);
    snprintf(want, sizeof want, "%d=camera.position=-1 0 0 %d=x=y.png", OPT_SET, OUT);
    assert_string_equal(o.got, want);
    /* a value that begins with '-' is a value, "--" alone too */
    read_line(0, common_option_specs, &o, "--rtol", "-1", "--set", "-x", "--out", "--", "--samples=--4", NULL);
    snprintf(want, sizeof want, "%d=-1 %d=-x %d=-- %d=--4", OPT_RTOL, OPT_SET, OUT, OPT_SAMPLES);
    assert_string_equal(o.got, want);
    /* own before common, as it always was */
    read_line(0, common_option_specs, &o, "--scene", "s", NULL);
    snprintf(want, sizeof want, "%d=s", LOUD);
    assert_string_equal(o.got, want);
    /* a second value read by the command itself, through next */
    read_line(0, NULL, &o, "--pair", "-1", "5", "--out", "o", NULL);
    snprintf(want, sizeof want, "%d=-1,5 %d=o", PAIR, OUT);
    assert_string_equal(o.got, want);
    read_line(0, NULL, &o, NULL);
    assert_string_equal(o.got, "");
    assert_int_equal(o.last, 0);
}

static void test_abbreviations(void **state)
{
    (void)state;
    struct outcome o;
    char want[128];
    read_line(0, common_option_specs, &o, "--sam", "4", "--fo", "--ou=x", NULL);
    snprintf(want, sizeof want, "%d=4 %d %d=x", OPT_SAMPLES, SHOUT, OUT);
    assert_string_equal(o.got, want);
    /* an exact name wins over the longer ones it begins */
    read_line(0, common_option_specs, &o, "--set", "a.b=1", NULL);
    snprintf(want, sizeof want, "%d=a.b=1", OPT_SET);
    assert_string_equal(o.got, want);
    /* the help's abbreviation is help */
    read_line(0, NULL, &o, "--he", NULL);
    assert_int_equal(o.last, -1);
    assert_int_equal(o.exit_code, EXIT_OK);
    assert_int_equal(usages, 1);

    read_line(0, common_option_specs, &o, "--s", "x", NULL);
    assert_int_equal(o.last, -1);
    assert_int_equal(o.exit_code, EXIT_USAGE);
    EXPECT_ERR(o, "bentray cmd: option '--s' is ambiguous (--scene, --shader-dir, --size, --samples, --set); "
                  "give more of its name\n");
    read_line(0, common_option_specs, &o, "--p=fp16", NULL);
    assert_int_equal(o.exit_code, EXIT_USAGE);
    EXPECT_ERR(o, "option '--p' is ambiguous (--pair, --precision)");
}

static void test_refusals(void **state)
{
    (void)state;
    struct outcome o;
    read_line(0, common_option_specs, &o, "--scnee", "x", NULL);
    assert_int_equal(o.exit_code, EXIT_USAGE);
    assert_string_equal(o.err, "bentray cmd: unknown option '--scnee' (did you mean --scene?)\n");
    assert_int_equal(usages, 1);
    read_line(0, common_option_specs, &o, "--scnee=x", NULL);
    EXPECT_ERR(o, "unknown option '--scnee=x' (did you mean --scene?)");
    read_line(0, NULL, &o, "--frobnicate", NULL);
    assert_string_equal(o.err, "bentray cmd: unknown option '--frobnicate'\n");
    /* one dash: bentray has no short options but -h */
    read_line(0, NULL, &o, "-out", NULL);
    assert_int_equal(o.exit_code, EXIT_USAGE);
    EXPECT_ERR(o, "unknown option '-out' (did you mean --out?)");
    read_line(0, NULL, &o, "-hx", NULL);
    assert_int_equal(o.exit_code, EXIT_USAGE);
    EXPECT_ERR(o, "unknown option '-hx'");
    /* "--" ends nothing: it is an unknown option, as it always was */
    read_line(1, NULL, &o, "--", "a", NULL);
    assert_int_equal(o.exit_code, EXIT_USAGE);
    assert_string_equal(o.got, "");
    assert_string_equal(o.err, "bentray cmd: unknown option '--'\n");

    read_line(0, NULL, &o, "--out", NULL);
    assert_int_equal(o.exit_code, EXIT_USAGE);
    assert_string_equal(o.err, "bentray cmd: option --out needs a value (FILE)\n");
    assert_int_equal(usages, 0);
    read_line(0, NULL, &o, "--out", "--force", NULL);
    assert_int_equal(o.exit_code, EXIT_USAGE);
    assert_string_equal(o.err, "bentray cmd: option --out needs a value (FILE), not the option '--force'\n");
    read_line(0, NULL, &o, "--force=1", NULL);
    assert_int_equal(o.exit_code, EXIT_USAGE);
    assert_string_equal(o.err, "bentray cmd: option --force takes no value, got '--force=1'\n");
    read_line(0, NULL, &o, "--help=1", NULL);
    assert_int_equal(o.exit_code, EXIT_USAGE);

    read_line(0, NULL, &o, "--force", "extra", NULL);
    assert_int_equal(o.exit_code, EXIT_USAGE);
    assert_string_equal(o.err, "bentray cmd: unexpected argument 'extra' (options begin with --)\n");
    assert_int_equal(usages, 1);
}

static void test_arguments_and_help(void **state)
{
    (void)state;
    struct outcome o;
    char want[128];
    /* arguments in their order among the options; "-" alone is one */
    read_line(1, NULL, &o, "a", "--force", "-", "b", NULL);
    snprintf(want, sizeof want, "%d=a %d %d=- %d=b", OPT_ARGUMENT, SHOUT, OPT_ARGUMENT, OPT_ARGUMENT);
    assert_string_equal(o.got, want);
    assert_int_equal(o.last, 0);
    read_line(0, NULL, &o, "-", NULL);
    assert_int_equal(o.exit_code, EXIT_USAGE);
    EXPECT_ERR(o, "unexpected argument '-'");
    read_line(0, NULL, &o, "--force", "-h", "--bad", NULL);
    assert_int_equal(o.exit_code, EXIT_OK);
    assert_int_equal(usages, 1);
    assert_string_equal(o.err, "");
    read_line(0, NULL, &o, "--help", "x", NULL);
    assert_int_equal(o.exit_code, EXIT_OK);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_values),
        cmocka_unit_test(test_abbreviations),
        cmocka_unit_test(test_refusals),
        cmocka_unit_test(test_arguments_and_help),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
