/* 32-bit floats packed into RGBA8 texels on the GPU (shaders_es/common.glsl, pack_float, src/gl/packing.h): the
 * way to a ray state on a GPU without float textures. Every normal float of every exponent comes
 * back bit for bit from a round trip through the GPU, scaled by powers of two into the subnormal
 * range and past the largest float; the probe says so on both back-ends, and finds the packing
 * broken where the fragment shader computes in 16-bit floats (mediump on llvmpipe). */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "gl/caps.h"
#include "gl/context.h"
#include "gl/packing.h"

#define SIDE 1024

static struct gl_context *context(const char *backend, struct gl_caps *caps)
{
    struct error err;
    struct gl_context *ctx = gl_context_create(backend, &err);
    if (!ctx)
        fail_msg("%s context: %s", backend, err.message);
    if (gl_caps_probe(caps, ctx, &err) != 0)
        fail_msg("%s probe: %s", backend, err.message);
    probe_packing(caps);
    return ctx;
}

/* SIDE^2 floats: every exponent (0 to 255: subnormals, infinities and NaN too), both signs, the
 * mantissa's edges (0, 1, all ones, the high bit alone) and the rest from a fixed sequence. */
static void floats(uint32_t *in)
{
    static const uint32_t edges[] = {0x000000u, 0x000001u, 0x7fffffu, 0x400000u};
    for (int i = 0; i < SIDE * SIDE; i++) {
        uint32_t exponent = (uint32_t)i % 256, k = (uint32_t)i / 256;
        uint32_t mantissa = k < 8 ? edges[k / 2] : (k * 2654435761u + 12345u) >> 9;
        in[i] = (k & 1u) << 31 | exponent << 23 | mantissa;
    }
}

/* How many of the SIDE^2 floats times factor do not come back as 32-bit arithmetic gives them; the
 * first few printed. */
static int mismatches(const struct shader_target *t, const uint32_t *in, float factor)
{
    static uint32_t out[SIDE * SIDE];
    struct error e;
    if (gl_pack_round_trip(t, in, SIDE, factor, out, &e) != 0)
        fail_msg("round trip: %s", e.message);
    int bad = 0;
    for (int i = 0; i < SIDE * SIDE; i++) {
        uint32_t also, want = packed_product(in[i], factor, &also);
        if (!packed_as_allowed(out[i], want, also) && bad++ < 3)
            printf("  0x%08x times %g: 0x%08x, not 0x%08x\n", (unsigned)in[i], factor, (unsigned)out[i],
                   (unsigned)want);
    }
    return bad;
}

static void round_trips(const char *backend)
{
    struct gl_caps caps;
    struct gl_context *ctx = context(backend, &caps);
    static uint32_t in[SIDE * SIDE];
    floats(in);
    /* as they are; a power of two that only moves the exponent; ones that take the smallest
     * exponents into the subnormals (zero) and the largest past the largest float (infinity) */
    static const float factors[] = {1.0f, -2.0f, 0.5f, 9.5367431640625e-07f /* 2^-20 */,
                                    1099511627776.0f /* 2^40 */};
    for (size_t f = 0; f < sizeof factors / sizeof factors[0]; f++) {
        int bad = mismatches(&caps.shader, in, factors[f]);
        printf("%s: %d floats of every exponent times %g: %d not bit for bit\n", backend, SIDE * SIDE,
               factors[f], bad);
        assert_int_equal(bad, 0);
    }
    gl_context_destroy(ctx);
}

static void test_round_trips_egl(void **state)
{
    (void)state;
    round_trips("egl");
}

static void test_round_trips_osmesa(void **state)
{
    (void)state;
    round_trips("osmesa");
}

/* The probe (bentray info's) finds the packing exact here, on both back-ends; BT_FAULT=packing
 * takes it away. */
static void test_probe(void **state)
{
    (void)state;
    const char *const backends[] = {"egl", "osmesa"};
    for (int b = 0; b < 2; b++) {
        struct gl_caps caps;
        struct gl_context *ctx = context(backends[b], &caps);
        printf("%s: packing %s: %s\n", backends[b], caps.packing ? "yes" : "no", caps.packing_why);
        assert_int_equal(caps.packing, 1);
        gl_context_destroy(ctx);
    }
    setenv("BT_FAULT", "packing", 1);
    struct gl_caps caps;
    struct gl_context *ctx = context("egl", &caps);
    unsetenv("BT_FAULT");
    assert_int_equal(caps.packing, 0);
    assert_non_null(strstr(caps.packing_why, "BT_FAULT=packing"));
    gl_context_destroy(ctx);
}

/* Where the fragment shader computes in 16-bit floats the packing cannot be exact: the shaders
 * declared mediump, which llvmpipe computes in 16 bits as Mali-400 does all its floats. */
static void test_16_bit_arithmetic_breaks_it(void **state)
{
    (void)state;
    struct gl_caps caps;
    struct gl_context *ctx = context("egl", &caps);
    struct shader_target mediump = caps.shader;
    mediump.fragment_highp = 0;
    static uint32_t in[SIDE * SIDE];
    floats(in);
    int bad = mismatches(&mediump, in, 1.0f);
    printf("egl, mediump: %d of %d floats not bit for bit\n", bad, SIDE * SIDE);
    assert_true(bad > SIDE * SIDE / 2);
    gl_context_destroy(ctx);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_round_trips_egl),
        cmocka_unit_test(test_round_trips_osmesa),
        cmocka_unit_test(test_probe),
        cmocka_unit_test(test_16_bit_arithmetic_breaks_it),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
