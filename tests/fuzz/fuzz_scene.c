/* libFuzzer harness: scene files as exhibition staff may leave them, and --set overrides.
 *
 * The input is a scene file. It goes through what `bentray render` does with one: scene_load(),
 * then scene_validate(); and one override through scene_set() (then scene_validate() again, as the
 * command line does after its --set options). The override is the text of the input's last line
 * that starts with ";set " (a comment to the loader, so the file still loads), else the input's
 * last line; when the file did not load, the override goes to a scene of defaults.
 *
 * Beyond the sanitizers: every refusal must say why (a NUL-terminated, non-empty message), since
 * the kiosk shows it to whoever edited the file.
 *
 * scene_load() reads a path: the input goes to one temporary file per process, made at start in
 * $BT_FUZZ_TMPDIR (else $TMPDIR, else /tmp), rewritten for every input and removed at exit. Its
 * directory is where relative texture and sky paths resolve. */
#include <errno.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <unistd.h>
#include "fuzz_input_file.h"
#include "scene/scene.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* ---- the harness ------------------------------------------------------------------------------ */

static struct scene scene;          /* tens of KB: not on the stack */
static struct error err;

/* A refusal names its place and its reason, each a terminated string. */
static void check_refusal(const struct error *e)
{
    if (memchr(e->where, '\0', sizeof e->where) == NULL ||
        memchr(e->message, '\0', sizeof e->message) == NULL || e->message[0] == '\0')
        __builtin_trap();
}

/* The override: the last ";set " line's text, else the last line; cut at a NUL or '\r'. */
static void override_line(const uint8_t *data, size_t size, char *out, size_t cap)
{
    static const char marker[] = ";set ";
    const size_t mlen = sizeof marker - 1;
    size_t start = 0, from = 0;
    int marked = 0;
    for (size_t i = 0; i <= size; i++) {
        if (i < size && data[i] != '\n')
            continue;
        /* a line [from, i) */
        if (i - from >= mlen && memcmp(data + from, marker, mlen) == 0) {
            start = from + mlen;
            marked = 1;
        } else if (!marked && i > from) {
            start = from;
        }
        from = i + 1;
    }
    size_t n = 0;
    while (start + n < size && data[start + n] != '\n' && data[start + n] != '\r' &&
           data[start + n] != '\0' && n + 1 < cap)
        n++;
    memcpy(out, data + start, n);
    out[n] = '\0';
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    tmp_create("scene");
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char line[1024];

    tmp_write(data, size);
    int loaded = scene_load(&scene, tmp_path, &err) == 0;
    if (!loaded)
        check_refusal(&err);
    else if (scene_validate(&scene, &err) != 0)
        check_refusal(&err);

    if (!loaded)
        scene_defaults(&scene);
    override_line(data, size, line, sizeof line);
    if (scene_set(&scene, line, &err) != 0)
        check_refusal(&err);
    else if (scene_validate(&scene, &err) != 0)
        check_refusal(&err);
    return 0;
}
