/* libFuzzer harness: the GPIO input decoders (src/input/quadrature.h, debounce.h, event_merge.h),
 * fed edge streams as a worn encoder, a bouncing button or a confused clock may produce them.
 *
 * Input, little-endian, missing bytes read as 0:
 *   cpd (1)        counts per detent 1 << (byte % 3); the byte as a signed number is also offered
 *                  to quadrature_init, which must refuse all but 1, 2 and 4 and leave the state alone
 *   flags (1)      bit 0, 1: lines A and B at start; bit 2: the button's level at start; bit 3: its
 *                  active level; bit 4: stable_ns is the raw 64 bits below (else (bits & 0xffff) us);
 *                  bit 5: event_merge gets a third, empty stream (NULL); bit 6: the detent total
 *                  starts at the value below instead of 0 (to cross its wrap)
 *   stable (8)     the debounce window
 *   base (8)       the clock at start (anywhere, across the 64-bit wrap too)
 *   total (8)      the detent total at start, when flag 6
 *   out_cap (2)    event_merge's capacity: this modulo (events + 3)
 *   events, 3 bytes each, at most MAX_EVENTS: op, delta (2):
 *                  op bits 0-1: 0 an edge of line A, 1 of line B, 2 of the button, 3 a poll of the
 *                  button; bit 2: the level after the edge; bit 3: the clock steps back by delta
 *                  (an edge older than the last one); bits 4-5: delta in ns, us, ms or 2^32 ns.
 *
 * Invariants, each a __builtin_trap() when broken:
 *  - quadrature: an edge emits -1, 0 or +1 detents; the total moves by exactly that; the count of
 *    quarter steps stays within +-(counts_per_detent - 1); the state is the lines' levels; a step
 *    forward or back in the Gray cycle counts one quarter step, both lines at once one invalid edge
 *    and nothing else, no change nothing; quadrature_detents_since() is the sum emitted;
 *  - debounce: presses and releases alternate (never two presses without a release between them),
 *    starting from the level at init; an edge older than the last is rejected and counted; a change
 *    is reported, once, exactly when the header says (edge or poll, the level held for stable_ns);
 *  - event_merge: two streams of these events (edges of A and of the button; of B and the polls),
 *    each in time order: the output is never longer than out_cap, holds min(out_cap, events) events,
 *    is in time order and is exactly the stable merge (stream 0 first at equal times, each stream's
 *    own order kept); nothing is written past out_cap. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "input/debounce.h"
#include "input/event_merge.h"
#include "input/quadrature.h"

#include "fuzz_bytes.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Each step of the clock is at most 2^48 ns, so all times of one input lie within 2^60 ns of each
 * other: well inside the 2^63 over which the decoders order times. */
#define MAX_EVENTS 4096


static int64_t as_int64(uint64_t u)
{
    return u <= (uint64_t)INT64_MAX ? (int64_t)u : -(int64_t)(UINT64_MAX - u) - 1;
}

/* a before b, by the sign of their difference modulo 2^64 (debounce.h) */
static int earlier(uint64_t a, uint64_t b)
{
    return a - b > (uint64_t)INT64_MAX;
}

/* ---- quadrature ------------------------------------------------------------------------------- */

/* Place of each state ab in the clockwise cycle 00 -> 10 -> 11 -> 01. */
static const int cycle_place[4] = {0, 3, 1, 2};

struct encoder {
    struct quadrature q;
    int a, b;
    int64_t start_total;
    int64_t emitted;        /* sum of what the edges returned; at most MAX_EVENTS in size */
};

static void encoder_edge(struct encoder *e)
{
    struct quadrature before = e->q;
    int now = e->a << 1 | e->b;
    int ret = quadrature_edge(&e->q, e->a, e->b);
    int cpd = e->q.counts_per_detent;

    if (ret < -1 || ret > 1)
        __builtin_trap();
    if (e->q.ab != now || cpd != before.counts_per_detent)
        __builtin_trap();
    if (e->q.accumulated <= -cpd || e->q.accumulated >= cpd)
        __builtin_trap();
    if ((uint64_t)e->q.detents != (uint64_t)before.detents + (uint64_t)(int64_t)ret)
        __builtin_trap();

    int turn = (cycle_place[now] - cycle_place[before.ab & 3] + 4) % 4;
    if (turn == 0 || turn == 2) {
        /* no change, or both lines at once: nothing counted but the missed edge */
        if (ret != 0 || e->q.accumulated != before.accumulated ||
            e->q.invalid != before.invalid + (turn == 2))
            __builtin_trap();
    } else {
        int step = turn == 1 ? 1 : -1;
        int sum = before.accumulated + step;
        int want_ret = sum == cpd ? 1 : sum == -cpd ? -1 : 0;
        if (e->q.invalid != before.invalid || ret != want_ret ||
            e->q.accumulated != (want_ret != 0 ? 0 : sum))
            __builtin_trap();
    }
    e->emitted += ret;
    if (quadrature_detents_since(&e->q, e->start_total) != e->emitted)
        __builtin_trap();
}

/* ---- debounce --------------------------------------------------------------------------------- */

/* What debounce.h says the decoder knows, kept here apart from it. */
struct button {
    struct debounce d;
    uint64_t stable;
    int active;
    int reported;           /* the level last reported, or the one at init */
    int raw;
    int has_edge;
    uint64_t last;
    uint64_t rejected;
    int pressed;            /* from the events alone */
};

static void button_event(struct button *b, enum button_event ev)
{
    if (ev == BUTTON_PRESS) {
        if (b->pressed)
            __builtin_trap();   /* two presses without a release between them */
        b->pressed = 1;
    } else if (ev == BUTTON_RELEASE) {
        if (!b->pressed)
            __builtin_trap();   /* two releases without a press between them */
        b->pressed = 0;
    } else {
        __builtin_trap();       /* a change reported as no event */
    }
}

/* Whether a change is due at t, and which. */
static int button_due(const struct button *b, uint64_t t, enum button_event *ev)
{
    if (!b->has_edge || earlier(t, b->last) || t - b->last < b->stable || b->raw == b->reported)
        return 0;
    *ev = b->raw == b->active ? BUTTON_PRESS : BUTTON_RELEASE;
    return 1;
}

static void button_edge(struct button *b, int level, uint64_t t)
{
    enum button_event ev = BUTTON_NONE, want_ev = BUTTON_NONE;
    int want;
    if (b->has_edge && earlier(t, b->last)) {
        want = -1;
        b->rejected++;
    } else {
        want = button_due(b, t, &want_ev);
        if (want)
            b->reported = b->raw;
        b->raw = level;
        b->last = t;
        b->has_edge = 1;
    }
    int rc = debounce_edge(&b->d, level, t, &ev);
    if (rc != want || b->d.rejected != b->rejected)
        __builtin_trap();
    if (rc == 1) {
        if (ev != want_ev)
            __builtin_trap();
        button_event(b, ev);
    }
}

static void button_poll(struct button *b, uint64_t t)
{
    enum button_event ev = BUTTON_NONE, want_ev = BUTTON_NONE;
    int want = button_due(b, t, &want_ev);
    if (want)
        b->reported = b->raw;
    int rc = debounce_poll(&b->d, t, &ev);
    if (rc != want)
        __builtin_trap();
    if (rc == 1) {
        if (ev != want_ev)
            __builtin_trap();
        button_event(b, ev);
        if (debounce_poll(&b->d, t, &ev) != 0)     /* each change is reported once */
            __builtin_trap();
    }
}

/* ---- event_merge ------------------------------------------------------------------------------ */

static struct line_event staged[2][MAX_EVENTS];

static void check_merge(const size_t n[2], unsigned flags, uint64_t cap_sel)
{
    struct line_event *s[2] = {NULL, NULL};
    /* exactly as long as they are, so that ASan sees a read past a stream's end */
    for (int k = 0; k < 2; k++)
        if (n[k] > 0) {
            s[k] = malloc(n[k] * sizeof *s[k]);
            if (s[k] == NULL)
                abort();
            memcpy(s[k], staged[k], n[k] * sizeof *s[k]);
        }
    size_t total = n[0] + n[1];
    size_t out_cap = (size_t)(cap_sel % (total + 3));
    size_t room = out_cap > 0 ? out_cap : 1;
    struct line_event *out = malloc(room * sizeof *out);
    if (out == NULL)
        abort();
    memset(out, 0xee, room * sizeof *out);
    const struct line_event *streams[3] = {s[0], s[1], NULL};
    const size_t counts[3] = {n[0], n[1], 0};

    size_t got = event_merge(streams, counts, flags & 32u ? 3 : 2, out, out_cap);

    size_t want = out_cap < total ? out_cap : total;
    if (got > out_cap || got != want)
        __builtin_trap();
    if (out_cap == 0) {
        const unsigned char *p = (const unsigned char *)out;
        for (size_t i = 0; i < sizeof *out; i++)
            if (p[i] != 0xee)
                __builtin_trap();   /* written with no room */
    }
    size_t i = 0, j = 0;
    for (size_t k = 0; k < got; k++) {
        if (k > 0 && earlier(out[k].t_ns, out[k - 1].t_ns))
            __builtin_trap();       /* out of time order */
        const struct line_event *next;
        if (i < n[0] && (j >= n[1] || !earlier(s[1][j].t_ns, s[0][i].t_ns)))
            next = &s[0][i++];
        else
            next = &s[1][j++];
        if (out[k].t_ns != next->t_ns || out[k].line != next->line || out[k].level != next->level)
            __builtin_trap();       /* not the stable merge */
    }
    free(out);
    free(s[0]);
    free(s[1]);
}

/* ---- the input -------------------------------------------------------------------------------- */

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct bytes in = {data, size};
    struct encoder enc;
    struct button btn;

    unsigned cpd_byte = (unsigned)take(&in, 1);
    unsigned flags = (unsigned)take(&in, 1);
    uint64_t stable_raw = take(&in, 8);
    uint64_t t = take(&in, 8);
    uint64_t total_start = take(&in, 8);
    uint64_t cap_sel = take(&in, 2);

    /* quadrature_init refuses what is not 1, 2 or 4, and then leaves q as it was */
    {
        struct quadrature q, untouched;
        int asked = cpd_byte >= 128 ? (int)cpd_byte - 256 : (int)cpd_byte;
        memset(&q, 0x5a, sizeof q);
        untouched = q;
        int rc = quadrature_init(&q, asked, 0, 0);
        int valid = asked == 1 || asked == 2 || asked == 4;
        if (rc != (valid ? 0 : -1) || (!valid && memcmp(&q, &untouched, sizeof q) != 0))
            __builtin_trap();
    }
    memset(&enc, 0, sizeof enc);
    enc.a = (int)(flags & 1u);
    enc.b = (int)(flags >> 1 & 1u);
    if (quadrature_init(&enc.q, 1 << (cpd_byte % 3), enc.a, enc.b) != 0)
        __builtin_trap();
    if (enc.q.ab != (enc.a << 1 | enc.b) || enc.q.accumulated != 0 || enc.q.detents != 0 ||
        enc.q.invalid != 0)
        __builtin_trap();
    if (flags & 64u)
        enc.q.detents = as_int64(total_start);
    enc.start_total = enc.q.detents;

    /* debounce_init refuses windows of 2^63 ns and more, and then leaves d as it was */
    memset(&btn, 0, sizeof btn);
    btn.stable = flags & 16u ? stable_raw : (stable_raw & 0xffffu) * 1000u;
    btn.active = (int)(flags >> 3 & 1u);
    btn.reported = btn.raw = (int)(flags >> 2 & 1u);
    {
        struct debounce untouched;
        memset(&btn.d, 0x5a, sizeof btn.d);
        untouched = btn.d;
        int rc = debounce_init(&btn.d, btn.stable, btn.active, btn.reported);
        if (btn.stable > (uint64_t)INT64_MAX) {
            if (rc != -1 || memcmp(&btn.d, &untouched, sizeof btn.d) != 0)
                __builtin_trap();
            btn.stable &= (uint64_t)INT64_MAX;
            rc = debounce_init(&btn.d, btn.stable, btn.active, btn.reported);
        }
        if (rc != 0)
            __builtin_trap();
    }
    btn.pressed = btn.reported == btn.active;

    size_t n[2] = {0, 0};
    uint64_t merge_t = t;
    for (int e = 0; e < MAX_EVENTS && in.n > 0; e++) {
        unsigned op = (unsigned)take(&in, 1);
        uint64_t delta = take(&in, 2);
        static const uint64_t scale[4] = {1u, 1000u, 1000000u, 0};
        delta = (op >> 4 & 3u) == 3 ? delta << 32 : delta * scale[op >> 4 & 3u];
        t = op & 8u ? t - delta : t + delta;
        merge_t += delta;
        int level = (int)(op >> 2 & 1u);
        int kind = (int)(op & 3u);

        switch (kind) {
        case 0:
            enc.a = level;
            encoder_edge(&enc);
            break;
        case 1:
            enc.b = level;
            encoder_edge(&enc);
            break;
        case 2:
            button_edge(&btn, level, t);
            break;
        default:
            button_poll(&btn, t);
            break;
        }
        int stream = kind & 1;
        struct line_event *ev = &staged[stream][n[stream]];
        ev->t_ns = merge_t;
        ev->line = stream << 16 | (int)n[stream];    /* which event this is, for the check */
        ev->level = level;
        n[stream]++;
    }
    check_merge(n, flags, cap_sel);
    return 0;
}
