/* The kiosk's input decoders on recorded sequences: quadrature edges to detents, a button's edges
 * to presses and releases, per-line event streams merged by time, and HID reports (PowerMate and
 * layouts) to knob readings, with the wrapping position counters of absolute encoders. */
#include <limits.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "input/debounce.h"
#include "input/event_merge.h"
#include "input/hid_report.h"
#include "input/quadrature.h"

#define MS 1000000ull
#define STABLE_NS (20 * MS)

/* ---------------------------------------------------------------- quadrature */

/* Feeds a recorded sequence of line levels written "AB AB ...", e.g. "10 11 01 00"; writes the
 * detents each edge emitted to emitted[] (when not NULL) and returns their sum. */
static long feed(struct quadrature *q, const char *levels, int *emitted)
{
    long sum = 0;
    size_t n = 0;
    for (const char *p = levels; *p != '\0'; p++) {
        if (*p == ' ')
            continue;
        int a = p[0] == '1', b = p[1] == '1';
        int d = quadrature_edge(q, a, b);
        if (emitted != NULL)
            emitted[n] = d;
        n++;
        sum += d;
        p++;
    }
    return sum;
}

/* one clockwise Gray cycle from 00 (A leads B), and the same turned back */
#define CW_CYCLE "10 11 01 00"
#define CCW_CYCLE "01 11 10 00"

static void test_quadrature_slow_turns(void **state)
{
    (void)state;
    static const int counts[] = {1, 2, 4};
    for (size_t c = 0; c < sizeof counts / sizeof counts[0]; c++) {
        int cpd = counts[c];
        struct quadrature q;
        assert_int_equal(quadrature_init(&q, cpd, 0, 0), 0);
        int emitted[8];
        long sum = feed(&q, CW_CYCLE " " CW_CYCLE, emitted);
        for (int i = 0; i < 8; i++) {
            int expected = (i + 1) % cpd == 0 ? 1 : 0;  /* a detent on every cpd-th transition */
            if (emitted[i] != expected)
                fail_msg("%d counts per detent, clockwise transition %d: emitted %d, expected %d", cpd, i,
                         emitted[i], expected);
        }
        assert_int_equal(sum, 8 / cpd);
        assert_true(q.detents == 8 / cpd);
        sum = feed(&q, CCW_CYCLE " " CCW_CYCLE, emitted);
        for (int i = 0; i < 8; i++) {
            int expected = (i + 1) % cpd == 0 ? -1 : 0;
            if (emitted[i] != expected)
                fail_msg("%d counts per detent, counter-clockwise transition %d: emitted %d, expected %d", cpd,
                         i, emitted[i], expected);
        }
        assert_int_equal(sum, -8 / cpd);
        assert_true(q.detents == 0);
        assert_true(q.invalid == 0);
        assert_int_equal(q.accumulated, 0);
    }
}

static void test_quadrature_bounce_on_one_line(void **state)
{
    (void)state;
    struct quadrature q;
    /* A chatters 0-1-0-1 while B stays low: back and forth about one position */
    assert_int_equal(quadrature_init(&q, 4, 0, 0), 0);
    int emitted[5];
    assert_int_equal(feed(&q, "10 00 10 00 10", emitted), 0);
    for (int i = 0; i < 5; i++)
        assert_int_equal(emitted[i], 0);
    assert_int_equal(q.accumulated, 1);  /* settled one quarter step on, as the line did */
    /* the turn goes on and completes exactly one detent, neither lost nor doubled by the bounce */
    assert_int_equal(feed(&q, "11 01 00", emitted), 1);
    assert_int_equal(emitted[2], 1);
    assert_true(q.invalid == 0);

    /* with a detent per transition the chatter emits +1 -1 +1 -1: nothing net */
    assert_int_equal(quadrature_init(&q, 1, 0, 0), 0);
    assert_int_equal(feed(&q, "10 00 10 00", NULL), 0);
    assert_true(q.detents == 0);
}

static void test_quadrature_missed_edge(void **state)
{
    (void)state;
    struct quadrature q;
    assert_int_equal(quadrature_init(&q, 4, 0, 0), 0);
    assert_int_equal(quadrature_edge(&q, 1, 1), 0);  /* 00 -> 11: which way is unknown */
    assert_true(q.invalid == 1);
    assert_int_equal(q.accumulated, 0);
    assert_true(q.detents == 0);
    assert_int_equal(q.ab, 3);  /* read on from the lines' truth */
    assert_int_equal(feed(&q, "01", NULL), 0);  /* 11 -> 01 is a clockwise step */
    assert_int_equal(q.accumulated, 1);
    assert_int_equal(quadrature_edge(&q, 1, 0), 0);  /* 01 -> 10: both lines again */
    assert_true(q.invalid == 2);
    assert_int_equal(q.accumulated, 1);
    /* no change at all is no step and no error */
    assert_int_equal(quadrature_edge(&q, 1, 0), 0);
    assert_true(q.invalid == 2);
    assert_int_equal(q.accumulated, 1);
}

static void test_quadrature_direction_reversal(void **state)
{
    (void)state;
    struct quadrature q;
    int emitted[4];
    assert_int_equal(quadrature_init(&q, 4, 0, 0), 0);
    /* a quarter step either way and back: the count goes back too */
    assert_int_equal(feed(&q, "01 00", emitted), 0);
    assert_int_equal(emitted[0], 0);
    assert_int_equal(emitted[1], 0);
    assert_int_equal(feed(&q, "10 00", NULL), 0);
    /* three quarters on and back from just short of the detent */
    assert_int_equal(feed(&q, "10 11 01 11 10 00", NULL), 0);
    assert_int_equal(q.accumulated, 0);
    /* a full detent, a wobble back and forth about it, then the whole detent back */
    assert_int_equal(feed(&q, CW_CYCLE, emitted), 1);
    assert_int_equal(emitted[3], 1);
    assert_int_equal(feed(&q, "01 00", NULL), 0);
    assert_int_equal(feed(&q, CCW_CYCLE, emitted), -1);
    assert_int_equal(emitted[0], 0);
    assert_int_equal(emitted[2], 0);
    assert_int_equal(emitted[3], -1);
    assert_true(q.detents == 0);
}

static void test_quadrature_fast_spin(void **state)
{
    (void)state;
    enum { DETENTS = 1000 };
    static const uint8_t cw[4] = {2, 3, 1, 0};  /* the clockwise cycle from 00, as (A << 1) | B */
    static uint8_t recorded[4 * DETENTS];
    static const int counts[] = {1, 2, 4};
    for (size_t c = 0; c < sizeof counts / sizeof counts[0]; c++) {
        int cpd = counts[c];
        size_t n = (size_t)DETENTS * (size_t)cpd;
        for (size_t i = 0; i < n; i++)
            recorded[i] = cw[i % 4];
        struct quadrature q;
        assert_int_equal(quadrature_init(&q, cpd, 0, 0), 0);
        long forward = 0;
        for (size_t i = 0; i < n; i++)
            forward += quadrature_edge(&q, recorded[i] >> 1, recorded[i] & 1);
        long back = 0;
        for (size_t i = n; i-- > 0;) {  /* the same recording played backwards, down to 00: the spin undone */
            uint8_t ab = i > 0 ? recorded[i - 1] : 0;
            back += quadrature_edge(&q, ab >> 1, ab & 1);
        }
        print_message("%d counts per detent: %zu transitions, %ld detents forward, %ld back\n", cpd, n, forward,
                      back);
        if (forward != DETENTS || back != -DETENTS)
            fail_msg("%d counts per detent: %ld forward and %ld back, expected %d each way", cpd, forward, back,
                     DETENTS);
        assert_true(q.detents == 0);
        assert_true(q.invalid == 0);
    }
}

static void test_quadrature_init_rejects(void **state)
{
    (void)state;
    struct quadrature q;
    memset(&q, 0x5a, sizeof q);
    static const int bad[] = {3, 0, -4, 8};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        assert_int_equal(quadrature_init(&q, bad[i], 0, 0), -1);
    assert_int_equal(q.counts_per_detent, 0x5a5a5a5a);  /* untouched */
    assert_int_equal(quadrature_init(&q, 2, 1, 0), 0);
    assert_int_equal(q.ab, 2);
}

static void test_quadrature_long_totals(void **state)
{
    (void)state;
    struct quadrature q;
    assert_int_equal(quadrature_init(&q, 4, 0, 0), 0);
    q.detents = INT32_MAX;  /* as after 2^31 - 1 detents */
    assert_int_equal(feed(&q, CW_CYCLE " " CW_CYCLE, NULL), 2);
    assert_true(q.detents == (int64_t)INT32_MAX + 2);
    q.detents = INT32_MIN;
    assert_int_equal(feed(&q, CCW_CYCLE, NULL), -1);
    assert_true(q.detents == (int64_t)INT32_MIN - 1);
    /* the total wraps at 2^63; differences of totals stay right across it */
    q.detents = INT64_MAX;
    int64_t seen = q.detents;
    assert_int_equal(feed(&q, CW_CYCLE, NULL), 1);
    assert_true(q.detents == INT64_MIN);
    assert_true(quadrature_detents_since(&q, seen) == 1);
    assert_int_equal(feed(&q, CCW_CYCLE CCW_CYCLE CCW_CYCLE, NULL), -3);
    assert_true(quadrature_detents_since(&q, seen) == -2);
}

/* ---------------------------------------------------------------- debounce */

/* a button wired with a pull-up: released high, pressed low */
static void pull_up_button(struct debounce *d)
{
    assert_int_equal(debounce_init(d, STABLE_NS, 0, 1), 0);
}

static void assert_no_event(struct debounce *d, uint64_t now_ns)
{
    enum button_event e = BUTTON_NONE;
    if (debounce_poll(d, now_ns, &e) != 0)
        fail_msg("poll at %.6f ms: event %d, expected none", (double)now_ns / (double)MS, (int)e);
}

static void assert_event(struct debounce *d, uint64_t now_ns, enum button_event expected)
{
    enum button_event e = BUTTON_NONE;
    if (debounce_poll(d, now_ns, &e) != 1 || e != expected)
        fail_msg("poll at %.6f ms: event %d, expected %d", (double)now_ns / (double)MS, (int)e, (int)expected);
}

static void test_debounce_clean_press_and_release(void **state)
{
    (void)state;
    struct debounce d;
    enum button_event e = BUTTON_NONE;
    pull_up_button(&d);
    assert_no_event(&d, 50 * MS);
    assert_int_equal(debounce_edge(&d, 0, 100 * MS, &e), 0);
    assert_no_event(&d, 100 * MS);
    assert_event(&d, 120 * MS, BUTTON_PRESS);
    assert_no_event(&d, 121 * MS);  /* reported once */
    assert_no_event(&d, 400 * MS);
    assert_int_equal(debounce_edge(&d, 1, 500 * MS, &e), 0);
    assert_event(&d, 530 * MS, BUTTON_RELEASE);
    assert_no_event(&d, 600 * MS);
    assert_true(d.rejected == 0);
}

static void test_debounce_bouncy_press(void **state)
{
    (void)state;
    /* a recorded press: five edges within 3 ms, ending low */
    static const struct {
        uint64_t t_ns;
        int level;
    } bouncy[] = {
        {1000 * MS, 0}, {1000 * MS + 700000, 1}, {1001 * MS + 500000, 0}, {1002 * MS + 200000, 1}, {1003 * MS, 0},
    };
    struct debounce d;
    enum button_event e = BUTTON_NONE;
    pull_up_button(&d);
    for (size_t i = 0; i < sizeof bouncy / sizeof bouncy[0]; i++) {
        assert_int_equal(debounce_edge(&d, bouncy[i].level, bouncy[i].t_ns, &e), 0);
        assert_no_event(&d, bouncy[i].t_ns + 100000);
    }
    uint64_t last = bouncy[4].t_ns;
    assert_no_event(&d, last + STABLE_NS - 1);  /* the window counts from the last edge, not the first */
    assert_event(&d, last + STABLE_NS, BUTTON_PRESS);
    assert_no_event(&d, last + 5 * STABLE_NS);
}

static void test_debounce_glitch(void **state)
{
    (void)state;
    struct debounce d;
    enum button_event e = BUTTON_NONE;
    pull_up_button(&d);
    /* low for 5 ms, shorter than the window, and back: neither level was ever stable */
    assert_int_equal(debounce_edge(&d, 0, 100 * MS, &e), 0);
    assert_no_event(&d, 103 * MS);
    assert_int_equal(debounce_edge(&d, 1, 105 * MS, &e), 0);
    assert_no_event(&d, 125 * MS);
    assert_no_event(&d, 1000 * MS);
    assert_int_equal(d.settled, 1);
}

static void test_debounce_out_of_order(void **state)
{
    (void)state;
    struct debounce d;
    enum button_event e = BUTTON_NONE;
    pull_up_button(&d);
    assert_int_equal(debounce_edge(&d, 0, 100 * MS, &e), 0);
    assert_int_equal(debounce_edge(&d, 1, 99 * MS, &e), -1);  /* older than the edge before it */
    assert_true(d.rejected == 1);
    assert_int_equal(d.raw, 0);
    assert_event(&d, 120 * MS, BUTTON_PRESS);  /* the rejected edge did not restart the window */
    assert_int_equal(debounce_edge(&d, 1, 90 * MS, &e), -1);
    assert_true(d.rejected == 2);
    assert_int_equal(debounce_edge(&d, 1, 100 * MS, &e), 0);  /* the same time is not out of order */
    assert_event(&d, 120 * MS, BUTTON_RELEASE);
}

static void test_debounce_poll_before_window_ends(void **state)
{
    (void)state;
    struct debounce d;
    enum button_event e = BUTTON_NONE;
    pull_up_button(&d);
    assert_int_equal(debounce_edge(&d, 0, 200 * MS, &e), 0);
    assert_no_event(&d, 200 * MS + STABLE_NS - 1);
    assert_no_event(&d, 150 * MS);  /* "now" read before the edge's stamp */
    assert_event(&d, 200 * MS + STABLE_NS, BUTTON_PRESS);
}

static void test_debounce_edge_reports_unpolled_press(void **state)
{
    (void)state;
    struct debounce d;
    enum button_event e = BUTTON_NONE;
    pull_up_button(&d);
    /* held 200 ms while the loop was busy: the release's edge reports the press it ends */
    assert_int_equal(debounce_edge(&d, 0, 100 * MS, &e), 0);
    assert_int_equal(debounce_edge(&d, 1, 300 * MS, &e), 1);
    assert_int_equal(e, BUTTON_PRESS);
    assert_no_event(&d, 310 * MS);
    assert_event(&d, 320 * MS, BUTTON_RELEASE);
}

static void test_debounce_across_the_clock_wrap(void **state)
{
    (void)state;
    struct debounce d;
    enum button_event e = BUTTON_NONE;
    pull_up_button(&d);
    uint64_t t = UINT64_MAX - 5 * MS + 1;  /* 5 ms before the 64-bit count wraps */
    assert_int_equal(debounce_edge(&d, 0, t, &e), 0);
    assert_no_event(&d, 14 * MS);
    assert_event(&d, 15 * MS, BUTTON_PRESS);
    assert_int_equal(debounce_edge(&d, 1, 16 * MS, &e), 0);  /* after the wrap, not older */
    assert_true(d.rejected == 0);
    assert_event(&d, 36 * MS, BUTTON_RELEASE);
}

/* ---------------------------------------------------------------- event_merge */

static void assert_events(const struct line_event *got, size_t n, const struct line_event *expected)
{
    for (size_t i = 0; i < n; i++)
        if (got[i].t_ns != expected[i].t_ns || got[i].line != expected[i].line || got[i].level != expected[i].level)
            fail_msg("event %zu: t %llu line %d level %d, expected t %llu line %d level %d", i,
                     (unsigned long long)got[i].t_ns, got[i].line, got[i].level,
                     (unsigned long long)expected[i].t_ns, expected[i].line, expected[i].level);
}

static void test_merge_interleaved(void **state)
{
    (void)state;
    static const struct line_event a[] = {{10, 0, 1}, {40, 0, 0}, {60, 0, 1}};
    static const struct line_event b[] = {{20, 1, 1}, {30, 1, 0}, {70, 1, 1}};
    const struct line_event *const streams[] = {a, b};
    const size_t counts[] = {3, 3};
    static const struct line_event expected[] = {{10, 0, 1}, {20, 1, 1}, {30, 1, 0},
                                                 {40, 0, 0}, {60, 0, 1}, {70, 1, 1}};
    struct line_event out[8];
    assert_int_equal(event_merge(streams, counts, 2, out, 8), 6);
    assert_events(out, 6, expected);
    /* either order of the streams gives the same times */
    const struct line_event *const swapped[] = {b, a};
    assert_int_equal(event_merge(swapped, counts, 2, out, 8), 6);
    assert_events(out, 6, expected);
}

static void test_merge_equal_times_keep_stream_order(void **state)
{
    (void)state;
    static const struct line_event a[] = {{50, 0, 1}, {50, 0, 0}, {90, 0, 1}};
    static const struct line_event b[] = {{30, 1, 1}, {50, 1, 0}, {50, 1, 1}};
    static const struct line_event c[] = {{50, 2, 1}};
    const struct line_event *const streams[] = {a, NULL, b, c};
    const size_t counts[] = {3, 0, 3, 1};
    static const struct line_event expected[] = {{30, 1, 1}, {50, 0, 1}, {50, 0, 0}, {50, 1, 0},
                                                 {50, 1, 1}, {50, 2, 1}, {90, 0, 1}};
    struct line_event out[8];
    assert_int_equal(event_merge(streams, counts, 4, out, 8), 7);
    assert_events(out, 7, expected);
}

static void test_merge_truncates_at_out_cap(void **state)
{
    (void)state;
    static const struct line_event a[] = {{1, 0, 1}, {4, 0, 0}, {5, 0, 1}};
    static const struct line_event b[] = {{2, 1, 1}, {3, 1, 0}, {6, 1, 1}};
    const struct line_event *const streams[] = {a, b};
    const size_t counts[] = {3, 3};
    static const struct line_event expected[] = {{1, 0, 1}, {2, 1, 1}, {3, 1, 0}, {4, 0, 0}};
    enum { CAP = 4, GUARD = 3 };
    struct line_event out[CAP + GUARD];
    memset(out, 0xa5, sizeof out);
    struct line_event untouched;
    memset(&untouched, 0xa5, sizeof untouched);
    assert_int_equal(event_merge(streams, counts, 2, out, CAP), CAP);
    assert_events(out, CAP, expected);  /* the earliest ones */
    for (int i = CAP; i < CAP + GUARD; i++)
        if (memcmp(&out[i], &untouched, sizeof untouched) != 0)
            fail_msg("out[%d], beyond out_cap %d, was written", i, CAP);
    assert_int_equal(event_merge(streams, counts, 2, out, 0), 0);
    assert_int_equal(event_merge(streams, counts, 0, out, CAP), 0);
}

/* ---------------------------------------------------------------- HID reports */

/* a heap copy of exactly len bytes, so that a sanitizer or valgrind catches a read past the end */
static uint8_t *exact(const uint8_t *bytes, size_t len)
{
    uint8_t *p = malloc(len > 0 ? len : 1);
    assert_non_null(p);
    memcpy(p, bytes, len);
    return p;
}

static int decode_powermate(uint8_t button_byte, uint8_t rotation, struct knob_reading *r)
{
    const uint8_t bytes[6] = {button_byte, rotation, 0, 0, 0, 0};
    uint8_t *report = exact(bytes, sizeof bytes);
    int n = powermate_decode(report, sizeof bytes, r);
    free(report);
    return n;
}

static void test_powermate(void **state)
{
    (void)state;
    struct knob_reading r;
    assert_int_equal(decode_powermate(0x01, 0x00, &r), 1);
    assert_int_equal(r.buttons, 1u);
    assert_true(r.has_delta);
    assert_int_equal(r.delta, 0);
    assert_false(r.has_position);
    assert_int_equal(decode_powermate(0xfe, 0x00, &r), 1);  /* only bit 0 is the button */
    assert_int_equal(r.buttons, 0u);
    static const struct {
        uint8_t byte;
        long delta;
    } rotations[] = {{0x01, 1}, {0xff, -1}, {0x80, -128}, {0x7f, 127}, {0x00, 0}, {0xfe, -2}};
    for (size_t i = 0; i < sizeof rotations / sizeof rotations[0]; i++) {
        assert_int_equal(decode_powermate(0x00, rotations[i].byte, &r), 1);
        if (r.delta != rotations[i].delta)
            fail_msg("rotation byte 0x%02x: delta %ld, expected %ld", rotations[i].byte, r.delta,
                     rotations[i].delta);
    }
    const uint8_t one[1] = {0x01};
    uint8_t *short_report = exact(one, 1);
    assert_int_equal(powermate_decode(short_report, 1, &r), -1);
    free(short_report);
    assert_int_equal(powermate_decode(one, 0, &r), -1);
}

static struct hid_layout layout_none(size_t report_len, uint8_t report_id)
{
    struct hid_layout l;
    memset(&l, 0, sizeof l);
    l.report_id = report_id;
    l.report_len = report_len;
    return l;
}

/* decodes a copy of exactly len bytes */
static int decode(const struct hid_layout *l, const uint8_t *bytes, size_t len, struct knob_reading *r)
{
    uint8_t *report = exact(bytes, len);
    int n = hid_decode(l, report, len, r);
    free(report);
    return n;
}

static void test_hid_report_id(void **state)
{
    (void)state;
    struct hid_layout l = layout_none(3, 2);
    l.axis = (struct hid_axis){HID_AXIS_RELATIVE, 1, 1, 1, 0, 0};
    struct error why;
    assert_int_equal(hid_layout_check(&l, &why), 0);
    struct knob_reading r;
    memset(&r, 0x5a, sizeof r);
    struct knob_reading untouched = r;
    assert_int_equal(decode(&l, (const uint8_t[]){3, 0x05, 0}, 3, &r), 0);  /* another report of the device */
    assert_int_equal(decode(&l, (const uint8_t[]){3}, 1, &r), 0);
    assert_memory_equal(&r, &untouched, sizeof r);
    assert_int_equal(decode(&l, (const uint8_t[]){2, 0x05, 0}, 3, &r), 1);
    assert_int_equal(r.delta, 5);
    assert_int_equal(decode(&l, (const uint8_t[]){2}, 1, &r), -1);  /* ours, but cut short */
    /* the axis may not sit on the id byte */
    l.axis.offset = 0;
    assert_int_equal(hid_layout_check(&l, &why), -1);
    assert_non_null(strstr(why.message, "axis.offset"));
}

static void test_hid_relative_16_bit_signed(void **state)
{
    (void)state;
    struct hid_layout l = layout_none(3, 0);
    l.axis = (struct hid_axis){HID_AXIS_RELATIVE, 1, 2, 1, 0, 0};
    struct knob_reading r;
    static const struct {
        uint8_t lo, hi;
        long delta;
    } cases[] = {{0xfe, 0xff, -2}, {0x34, 0x12, 0x1234}, {0x00, 0x80, -32768}, {0xff, 0x7f, 32767}, {0x01, 0x00, 1}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        assert_int_equal(decode(&l, (const uint8_t[]){0x00, cases[i].lo, cases[i].hi}, 3, &r), 1);
        if (!r.has_delta || r.has_position || r.delta != cases[i].delta)
            fail_msg("bytes %02x %02x: delta %ld (has_delta %d), expected %ld", cases[i].lo, cases[i].hi, r.delta,
                     r.has_delta, cases[i].delta);
    }
    l.axis.is_signed = 0;
    assert_int_equal(decode(&l, (const uint8_t[]){0x00, 0xfe, 0xff}, 3, &r), 1);
    assert_int_equal(r.delta, 65534);
    /* four bytes, little-endian, signed */
    l = layout_none(5, 0);
    l.axis = (struct hid_axis){HID_AXIS_RELATIVE, 1, 4, 1, 0, 0};
    assert_int_equal(decode(&l, (const uint8_t[]){0, 0xff, 0xff, 0xff, 0xff}, 5, &r), 1);
    assert_int_equal(r.delta, -1);
    assert_int_equal(decode(&l, (const uint8_t[]){0, 0x00, 0x00, 0x00, 0x80}, 5, &r), 1);
    assert_true(r.delta == -2147483647L - 1);
}

static void test_hid_absolute_8_bit(void **state)
{
    (void)state;
    struct hid_layout l = layout_none(2, 0);
    l.axis = (struct hid_axis){HID_AXIS_ABSOLUTE, 1, 1, 0, 10, 210};
    static const struct {
        uint8_t value;
        double position;
    } cases[] = {{10, 0.0}, {110, 0.5}, {210, 1.0}, {60, 0.25}, {0, 0.0}, {255, 1.0}};  /* beyond: clamped */
    struct knob_reading r;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        assert_int_equal(decode(&l, (const uint8_t[]){0x00, cases[i].value}, 2, &r), 1);
        print_message("value %3u -> position %.4f\n", cases[i].value, r.position);
        if (!r.has_position || r.has_delta || r.position != cases[i].position)
            fail_msg("value %u: position %.17g (has_position %d), expected %g", cases[i].value, r.position,
                     r.has_position, cases[i].position);
    }
    /* a signed absolute axis, -100..100 */
    l.axis = (struct hid_axis){HID_AXIS_ABSOLUTE, 1, 1, 1, -100, 100};
    assert_int_equal(decode(&l, (const uint8_t[]){0x00, 0x9c}, 2, &r), 1);  /* -100 */
    assert_true(r.position == 0.0);
    /* 32-bit unsigned over its whole range */
    l = layout_none(4, 0);
    l.axis = (struct hid_axis){HID_AXIS_ABSOLUTE, 0, 4, 0, 0, UINT32_MAX};
    assert_int_equal(decode(&l, (const uint8_t[]){0xff, 0xff, 0xff, 0xff}, 4, &r), 1);
    assert_true(r.position == 1.0);
}

static void test_hid_buttons(void **state)
{
    (void)state;
    struct hid_layout l = layout_none(4, 0);
    l.n_buttons = 3;
    l.buttons[0] = (struct hid_button_bit){0, 0};
    l.buttons[1] = (struct hid_button_bit){0, 7};
    l.buttons[2] = (struct hid_button_bit){3, 2};
    static const struct {
        uint8_t report[4];
        unsigned buttons;
    } cases[] = {
        {{0x00, 0xff, 0xff, 0x00}, 0u},    /* other bytes' bits are not buttons */
        {{0x01, 0x00, 0x00, 0x00}, 1u},
        {{0x80, 0x00, 0x00, 0x00}, 2u},
        {{0x7e, 0x00, 0x00, 0xfb}, 0u},    /* every bit but the buttons' */
        {{0x81, 0x00, 0x00, 0x04}, 7u},
        {{0x00, 0x00, 0x00, 0x04}, 4u},
    };
    struct knob_reading r;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        assert_int_equal(decode(&l, cases[i].report, 4, &r), 1);
        if (r.buttons != cases[i].buttons || r.has_delta || r.has_position)
            fail_msg("report %zu: buttons 0x%x, expected 0x%x", i, r.buttons, cases[i].buttons);
    }
}

static void test_hid_short_report(void **state)
{
    (void)state;
    /* the axis in the last two bytes: a report one byte short would end inside it */
    struct hid_layout l = layout_none(4, 0);
    l.axis = (struct hid_axis){HID_AXIS_RELATIVE, 2, 2, 1, 0, 0};
    l.n_buttons = 1;
    l.buttons[0] = (struct hid_button_bit){3, 0};
    const uint8_t bytes[4] = {0, 0, 0xfe, 0xff};
    struct knob_reading r;
    memset(&r, 0x5a, sizeof r);
    struct knob_reading untouched = r;
    assert_int_equal(decode(&l, bytes, 3, &r), -1);
    assert_int_equal(decode(&l, bytes, 0, &r), -1);
    assert_memory_equal(&r, &untouched, sizeof r);
    assert_int_equal(decode(&l, bytes, 4, &r), 1);
    assert_int_equal(r.delta, -2);
    assert_int_equal(r.buttons, 1u);
    /* a longer report than declared is read as far as the layout goes */
    assert_int_equal(decode(&l, (const uint8_t[]){0, 0, 3, 0, 0}, 5, &r), 1);
    assert_int_equal(r.delta, 3);
}

static void assert_refused(const struct hid_layout *l, const char *field)
{
    struct error why;
    if (hid_layout_check(l, &why) != -1)
        fail_msg("a layout with a bad %s passed the check", field);
    print_message("refused: %s\n", why.message);
    assert_int_equal(why.status, ERROR_INPUT);
    if (strstr(why.message, field) == NULL)
        fail_msg("the reason \"%s\" does not name %s", why.message, field);
    struct knob_reading r;
    const uint8_t bytes[16] = {0};
    assert_int_equal(decode(l, bytes, sizeof bytes, &r), -1);  /* nor does decoding use it */
}

static void test_hid_layout_check(void **state)
{
    (void)state;
    struct hid_layout good = layout_none(6, 1);
    good.axis = (struct hid_axis){HID_AXIS_ABSOLUTE, 4, 2, 0, 0, 1023};
    good.n_buttons = 2;
    good.buttons[0] = (struct hid_button_bit){1, 0};
    good.buttons[1] = (struct hid_button_bit){5, 7};
    struct error why;
    error_set(&why, ERROR_RUNTIME, "stale", "stale");
    assert_int_equal(hid_layout_check(&good, &why), 0);
    assert_string_equal(why.message, "");
    assert_int_equal(why.status, ERROR_NONE);
    assert_int_equal(hid_layout_check(&good, NULL), 0);

    struct hid_layout l = good;
    l.axis.size = 3;
    assert_refused(&l, "axis.size");
    l = good;
    l.axis.offset = 5;  /* two bytes from 5 end past a 6-byte report */
    assert_refused(&l, "axis.offset");
    l = good;
    l.axis.offset = 100;
    assert_refused(&l, "axis.offset");
    l = good;
    l.buttons[1].bit = 8;
    assert_refused(&l, "buttons[1].bit");
    l = good;
    l.buttons[0].bit = -1;
    assert_refused(&l, "buttons[0].bit");
    l = good;
    l.buttons[1].offset = 6;
    assert_refused(&l, "buttons[1].offset");
    l = good;
    l.axis.logical_min = 1023;
    assert_refused(&l, "axis.logical_min");
    l = good;
    l.axis.logical_min = 2000;
    assert_refused(&l, "axis.logical_min");
    l = good;
    l.n_buttons = HID_MAX_BUTTONS + 1;
    assert_refused(&l, "n_buttons");
    /* min and max mean nothing on a relative axis */
    l = good;
    l.axis.kind = HID_AXIS_RELATIVE;
    l.axis.logical_min = 5;
    l.axis.logical_max = 5;
    assert_int_equal(hid_layout_check(&l, &why), 0);
    /* a refusal without an error to fill: the same answer */
    l = good;
    l.axis.size = 3;
    assert_int_equal(hid_layout_check(&l, NULL), -1);
}

static void test_counter_delta(void **state)
{
    (void)state;
    static const struct {
        uint32_t previous, current;
        int bits;
        long delta;
    } cases[] = {
        {250, 3, 8, 9},
        {3, 250, 8, -9},
        {255, 0, 8, 1},
        {0, 255, 8, -1},
        {7, 7, 8, 0},
        {0, 127, 8, 127},
        {0, 129, 8, -127},
        {0, 128, 8, -128},  /* the tie, half the counter: negative */
        {128, 0, 8, -128},
        {0x1ff, 0x200, 8, 1},  /* bits above the counter's are not its */
        {65530, 5, 16, 11},
        {5, 65530, 16, -11},
        {0, 32767, 16, 32767},
        {0, 32768, 16, -32768},
        {40000, 7232, 16, -32768},
        {0xffffffffu, 0, 32, 1},
        {0, 0x80000000u, 32, -2147483647L - 1},
        {1, 0, 1, -1},
        {5, 6, 0, 0},  /* no such counter */
        {5, 6, 33, 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        long d = counter_delta(cases[i].previous, cases[i].current, cases[i].bits);
        if (d != cases[i].delta)
            fail_msg("%u -> %u on %d bits: %ld, expected %ld", cases[i].previous, cases[i].current, cases[i].bits, d,
                     cases[i].delta);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_quadrature_slow_turns),
        cmocka_unit_test(test_quadrature_bounce_on_one_line),
        cmocka_unit_test(test_quadrature_missed_edge),
        cmocka_unit_test(test_quadrature_direction_reversal),
        cmocka_unit_test(test_quadrature_fast_spin),
        cmocka_unit_test(test_quadrature_init_rejects),
        cmocka_unit_test(test_quadrature_long_totals),
        cmocka_unit_test(test_debounce_clean_press_and_release),
        cmocka_unit_test(test_debounce_bouncy_press),
        cmocka_unit_test(test_debounce_glitch),
        cmocka_unit_test(test_debounce_out_of_order),
        cmocka_unit_test(test_debounce_poll_before_window_ends),
        cmocka_unit_test(test_debounce_edge_reports_unpolled_press),
        cmocka_unit_test(test_debounce_across_the_clock_wrap),
        cmocka_unit_test(test_merge_interleaved),
        cmocka_unit_test(test_merge_equal_times_keep_stream_order),
        cmocka_unit_test(test_merge_truncates_at_out_cap),
        cmocka_unit_test(test_powermate),
        cmocka_unit_test(test_hid_report_id),
        cmocka_unit_test(test_hid_relative_16_bit_signed),
        cmocka_unit_test(test_hid_absolute_8_bit),
        cmocka_unit_test(test_hid_buttons),
        cmocka_unit_test(test_hid_short_report),
        cmocka_unit_test(test_hid_layout_check),
        cmocka_unit_test(test_counter_delta),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
