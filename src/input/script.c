/* The scripted-input file: parsed whole before the kiosk starts, so that a bad script is refused
 * before anything is shown. */
#include "input/script.h"
#include "io/text_file.h"
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SCRIPT_LINE_MAX 256

#define ACTION_WORD(id, name) name,
static const char *const action_words[KIOSK_ACTION_COUNT] = {KIOSK_ACTIONS(ACTION_WORD)};
#undef ACTION_WORD

__attribute__((format(printf, 4, 5)))
static int refuse(struct error *e, const char *path, int line, const char *fmt, ...)
{
    e->status = ERROR_INPUT;
    snprintf(e->where, sizeof e->where, "%s:%d", path, line);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(e->message, sizeof e->message, fmt, ap);
    va_end(ap);
    return -1;
}

static int parse_event(struct script_event *ev, char *text, const char *path, int line, struct error *e)
{
    char *save = NULL;
    char *time_word = strtok_r(text, " \t", &save), *kind = strtok_r(NULL, " \t", &save);
    char *a = strtok_r(NULL, " \t", &save), *b = strtok_r(NULL, " \t", &save);
    char *extra = strtok_r(NULL, " \t", &save);
    char *end;
    errno = 0;
    ev->t = strtod(time_word, &end);
    if (*end || errno || !isfinite(ev->t) || ev->t < 0.0 || ev->t > SCRIPT_MAX_SECONDS)
        return refuse(e, path, line, "expected a time in seconds from 0 to %.0f, got \"%s\"",
                      SCRIPT_MAX_SECONDS, time_word);
    ev->line = line;
    if (!kind)
        return refuse(e, path, line, "expected an event after the time: turn, press or frame");
    if (strcmp(kind, "frame") == 0) {
        ev->kind = SCRIPT_FRAME;
        extra = a;
    } else if (strcmp(kind, "press") == 0) {
        ev->kind = SCRIPT_PRESS;
        int found = -1;
        for (int i = 0; a && i < KIOSK_ACTION_COUNT; i++)
            found = strcmp(a, action_words[i]) == 0 ? i : found;
        if (found < 0)
            return refuse(e, path, line, "press: expected next_scene, previous_scene, cycle_effects, "
                          "reset or pipeline_view, got \"%s\"", a ? a : "");
        ev->action = (enum kiosk_action)found;
        extra = b;
    } else if (strcmp(kind, "turn") == 0) {
        ev->kind = SCRIPT_TURN;
        if (!a || (strcmp(a, "speed") != 0 && strcmp(a, "mass") != 0))
            return refuse(e, path, line, "turn: expected the knob speed or mass, got \"%s\"", a ? a : "");
        ev->knob = strcmp(a, "speed") == 0 ? SCRIPT_KNOB_SPEED : SCRIPT_KNOB_MASS;
        errno = 0;
        long counts = b ? strtol(b, &end, 10) : 0;
        /* compared on both sides: labs() of LONG_MIN is undefined */
        if (!b || *end || errno || counts < -SCRIPT_MAX_COUNTS || counts > SCRIPT_MAX_COUNTS)
            return refuse(e, path, line, "turn %s: expected counts from -%d to +%d, got \"%s\"", a,
                          SCRIPT_MAX_COUNTS, SCRIPT_MAX_COUNTS, b ? b : "");
        ev->counts = counts;
    } else {
        return refuse(e, path, line, "unknown event \"%s\": expected turn, press or frame", kind);
    }
    if (extra)
        return refuse(e, path, line, "unexpected \"%s\" after the event", extra);
    return 0;
}

int script_load(struct script *sc, const char *path, struct error *e)
{
    sc->n = 0;
    size_t size;
    char *text = text_file_read(path, SCRIPT_MAX_BYTES, "script", &size, e);
    if (!text)
        return -1;
    /* lines end with LF or CR LF; a UTF-8 byte-order mark may open the file; a NUL byte is refused
     * (text_lines_next), and so is a carriage return inside a line, where a file with CR line ends
     * would otherwise lose every event after its first line */
    struct text_lines lines = {.text = text, .len = size};
    const char *start;
    size_t n;
    int rc = 0, more;
    struct error why;
    while (rc == 0 && (more = text_lines_next(&lines, &start, &n, &why)) != 0) {
        int line = lines.line;
        if (more < 0) {
            rc = refuse(e, path, line, "%s", why.message);
            break;
        }
        if (n > SCRIPT_LINE_MAX) {
            rc = refuse(e, path, line, "line longer than %d characters", SCRIPT_LINE_MAX);
            break;
        }
        if (memchr(start, '\r', n)) {
            rc = refuse(e, path, line, "a carriage return inside the line (a file with CR line ends?): "
                        "end each line with LF or CR LF");
            break;
        }
        char buf[SCRIPT_LINE_MAX + 1];
        memcpy(buf, start, n);
        buf[n] = '\0';
        char *p = buf + strspn(buf, " \t");
        if (*p == '\0' || *p == '#' || *p == ';')
            continue;
        if (sc->n == SCRIPT_MAX_EVENTS) {
            rc = refuse(e, path, line, "more than %d events", SCRIPT_MAX_EVENTS);
            break;
        }
        struct script_event *ev = &sc->events[sc->n];
        rc = parse_event(ev, p, path, line, e);
        if (rc == 0 && sc->n > 0 && ev->t < sc->events[sc->n - 1].t)
            rc = refuse(e, path, line, "time %g goes back (the previous event is at %g)", ev->t,
                        sc->events[sc->n - 1].t);
        sc->n += rc == 0;
    }
    free(text);
    return rc;
}
