/* libFuzzer harness: the kiosk's scripted-input files (tests and the attract tour; exhibition staff
 * write the tour). The input is a script file: script_load(), as the kiosk does at start. Beyond
 * the sanitizers:
 *  - every refusal says why and is the user's (ERROR_INPUT): a NUL-terminated place that names the
 *    file, and a NUL-terminated message;
 *  - what is accepted can be replayed: at most SCRIPT_MAX_EVENTS events, times finite, from 0 and
 *    never decreasing, counts within SCRIPT_MAX_COUNTS, known actions; and the player hands every
 *    event out exactly once, in order, however the clock advances.
 * script_load() reads a path: the input goes to one temporary file per process (fuzz_input_file.h). */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "fuzz_input_file.h"
#include "input/script_player.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static struct script script;         /* about 200 KB: not on the stack */

static void check_accepted(const struct script *sc)
{
    if (sc->n < 0 || sc->n > SCRIPT_MAX_EVENTS)
        __builtin_trap();
    for (int i = 0; i < sc->n; i++) {
        const struct script_event *e = &sc->events[i];
        if (!isfinite(e->t) || e->t < 0.0 || (i > 0 && e->t < sc->events[i - 1].t))
            __builtin_trap();
        if (e->kind == SCRIPT_TURN && (e->counts > SCRIPT_MAX_COUNTS || e->counts < -SCRIPT_MAX_COUNTS))
            __builtin_trap();
        if (e->kind == SCRIPT_PRESS && ((unsigned)e->action >= KIOSK_ACTION_COUNT))
            __builtin_trap();
    }
    /* replayed against a clock that jumps: every event once, in order */
    struct script_player p;
    struct input_event out[7];
    script_player_start(&p, sc, 0.0, 0);
    int seen = 0;
    for (double now = 0.0; seen < sc->n && now < 1e12; now = now * 2.0 + 0.37) {
        int n = script_player_due(&p, now, 0, out, 7);
        for (int k = 0; k < n; k++)
            if (out[k].t > now || out[k].t != sc->events[seen + k].t)
                __builtin_trap();
        seen += n;
    }
    int n = script_player_due(&p, INFINITY, 0, out, 7);
    while (n > 0) {
        seen += n;
        n = script_player_due(&p, INFINITY, 0, out, 7);
    }
    if (seen != sc->n || !script_player_done(&p))
        __builtin_trap();
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    tmp_create("script");
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    tmp_write(data, size);
    struct error e;
    memset(&e, 0, sizeof e);
    if (script_load(&script, tmp_path, &e) != 0) {
        if (memchr(e.where, '\0', sizeof e.where) == NULL || memchr(e.message, '\0', sizeof e.message) == NULL ||
            strstr(e.where, tmp_path) != e.where || e.status != ERROR_INPUT)
            __builtin_trap();
        return 0;
    }
    check_accepted(&script);
    return 0;
}
