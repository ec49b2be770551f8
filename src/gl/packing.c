/* Floats packed into RGBA8 texels, round trips on the GPU (packing.h). */
#include "gl/packing.h"
#include "gl/quad.h"
#include "gl/texture.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int gl_pack_round_trip(const struct shader_target *t, const uint32_t *in, int side, float factor,
                       uint32_t *out, struct error *e)
{
    static const char *const vs[] = {"quad_vertex.glsl", NULL};
    static const char *const fs[] = {"common.glsl", "probe_fragment.glsl", NULL};
    GLuint prog = shader_program_build(t, "#define PROBE_PACKING 1\n#define BT_TARGET 0\n", vs, fs, e);
    if (!prog)
        return -1;
    size_t n = (size_t)side * side;
    unsigned char *bytes = malloc(4 * n);
    if (!bytes) {
        glDeleteProgram(prog);
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory for %d packed floats", side * side);
    }
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 4; k++)
            bytes[4 * i + k] = (unsigned char)(in[i] >> (24 - 8 * k));
    GLuint source = texture_create_nearest(GL_RGBA, GL_RGBA, GL_UNSIGNED_BYTE, side, side);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, side, side, GL_RGBA, GL_UNSIGNED_BYTE, bytes);
    GLuint target, fbo;
    int complete = texture_rgba8_target(side, side, &target, &fbo);
    if (complete) {
        glViewport(0, 0, side, side);
        glUseProgram(prog);
        /* u_value: the factor, and the texel's size in texture coordinates (a power of two) */
        glUniform4f(glGetUniformLocation(prog, "u_value"), factor, 1.0f / (float)side, 0.0f, 0.0f);
        glUniform1i(glGetUniformLocation(prog, "u_source"), 0);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, source);
        quad_draw(prog, 0.0f);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, side, side, GL_RGBA, GL_UNSIGNED_BYTE, bytes);
        for (size_t i = 0; i < n; i++)
            out[i] = (uint32_t)bytes[4 * i] << 24 | (uint32_t)bytes[4 * i + 1] << 16 |
                     (uint32_t)bytes[4 * i + 2] << 8 | bytes[4 * i + 3];
    }
    texture_rgba8_target_release(target, fbo);
    glDeleteTextures(1, &source);
    glDeleteProgram(prog);
    free(bytes);
    while (glGetError() != GL_NO_ERROR) {
    }
    return complete ? 0 : error_set(e, ERROR_RUNTIME, NULL, "the packing's RGBA8 target is incomplete");
}

uint32_t packed_product(uint32_t x, float factor, uint32_t *also)
{
    float v;
    memcpy(&v, &x, sizeof v);
    uint32_t exponent = x >> 23 & 0xff;
    /* what unpacking gives: a subnormal is zero, an infinity or NaN is infinity of its sign */
    if (exponent == 0xff)
        v = copysignf(INFINITY, v);
    if (exponent == 0)
        v = 0.0f;
    volatile float product = v * factor;
    float p = product;
    uint32_t bits;
    memcpy(&bits, &p, sizeof bits);
    *also = bits;
    if (isinf(p) || isnan(p))
        return (bits & 0x80000000u) | 0x7f800000u;
    /* a product below the smallest normal float: zero (the GPU flushes it, before or after
     * rounding), or where rounding took it up to the smallest normal, that */
    if (fabs((double)v * factor) < 0x1p-126) {
        *also = fpclassify(p) == FP_NORMAL ? bits & 0x7fffffffu : 0u;
        return 0;
    }
    return bits;
}

/* Whether got is what packed_product allows: want, or also; a zero of either sign. */
int packed_as_allowed(uint32_t got, uint32_t want, uint32_t also)
{
    uint32_t magnitude = got & 0x7fffffffu;
    if (magnitude == 0)
        return want == 0 || also == 0;
    return got == want || (want == 0 && magnitude == also);
}

/* The probe's floats: every exponent with a mantissa from a fixed sequence, and the edges. */
static uint32_t probe_value(int i)
{
    static const uint32_t edges[] = {
        0x3f800000u, /* 1 */         0xbf800000u, /* -1 */         0x00800000u, /* 2^-126 */
        0x807fffffu, /* -subnormal */ 0x7f7fffffu, /* largest */    0xff7fffffu,
        0x3f800001u, /* 1 + 2^-23 */ 0x3fffffffu, /* 2 - 2^-23 */  0x40490fdbu, /* pi */
        0x476a6000u, /* NO_HIT 60000 */ 0x7f800000u, /* infinity */ 0x00000000u, /* zero */
    };
    int n_edges = (int)(sizeof edges / sizeof edges[0]);
    if (i < n_edges)
        return edges[i];
    uint32_t mantissa = (uint32_t)i * 2654435761u >> 9;
    uint32_t exponent = 1 + (uint32_t)(i - n_edges) % 254;
    return (uint32_t)(i & 1) << 31 | exponent << 23 | mantissa;
}

void probe_packing(struct gl_caps *c)
{
    enum { N = PACKING_PROBE_SIDE * PACKING_PROBE_SIDE };
    uint32_t in[N], out[N];
    for (int i = 0; i < N; i++)
        in[i] = probe_value(i);
    static const float factors[] = {1.0f, -2.0f};
    c->packing = 0;
    for (int f = 0; f < 2; f++) {
        struct error e;
        if (gl_pack_round_trip(&c->shader, in, PACKING_PROBE_SIDE, factors[f], out, &e) != 0) {
            snprintf(c->packing_why, sizeof c->packing_why, "the packing probe fails: %.120s", e.message);
            return;
        }
        for (int i = 0; i < N; i++) {
            uint32_t also, want = packed_product(in[i], factors[f], &also);
            if (!packed_as_allowed(out[i], want, also) || gl_fault("packing")) {
                snprintf(c->packing_why, sizeof c->packing_why, "0x%08x times %g packed as 0x%08x, not 0x%08x%s",
                         (unsigned)in[i], factors[f], (unsigned)out[i], (unsigned)want,
                         gl_fault("packing") ? " (BT_FAULT=packing)" : "");
                return;
            }
        }
    }
    c->packing = 1;
    snprintf(c->packing_why, sizeof c->packing_why, "%d floats of every exponent unpacked, times 1 and -2, and "
             "packed again bit for bit", N);
}

/* The byte offset of float c of texel (x, y) in the packed layout of a width-texel-wide texture. */
static size_t packed_offset(int width, int x, int y, int c)
{
    return 4 * ((size_t)(2 * y + c / 2) * 2 * width + 2 * x + c % 2);
}

void packed_from_floats(const float *texels, int width, int height, unsigned char *bytes)
{
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++)
            for (int c = 0; c < 4; c++) {
                uint32_t bits;
                memcpy(&bits, &texels[4 * ((size_t)y * width + x) + c], sizeof bits);
                unsigned char *b = bytes + packed_offset(width, x, y, c);
                for (int k = 0; k < 4; k++)
                    b[k] = (unsigned char)(bits >> (24 - 8 * k));
            }
}

void packed_to_floats(const unsigned char *bytes, int width, int height, float *texels)
{
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++)
            for (int c = 0; c < 4; c++) {
                const unsigned char *b = bytes + packed_offset(width, x, y, c);
                uint32_t bits = (uint32_t)b[0] << 24 | (uint32_t)b[1] << 16 | (uint32_t)b[2] << 8 | b[3];
                memcpy(&texels[4 * ((size_t)y * width + x) + c], &bits, sizeof bits);
            }
}
