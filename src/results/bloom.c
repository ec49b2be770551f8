#include "results/bloom.h"
#include "io/parallel.h"
#include "io/sample_average.h"
#include "results/tone.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define CHANNELS 3
/* The least sigma a Gaussian is drawn with on a coarser image of the pyramid, in that image's
 * pixels (bloom_linear). So a Gaussian is drawn with a sigma below sqrt(4 (COARSE_SIGMA_MIN^2 + 1/3)
 * - 1/3) = 2.24 pixels of its image, and its kernel, to 4 sigma, has at most KERNEL_MAX taps a
 * side; only where the pyramid ends at an image of a pixel or two is it wider than its image, and
 * the taps cover the whole of it. */
#define COARSE_SIGMA_MIN 1.0
#define KERNEL_MAX 12

int bloom_active(const struct render_settings *r)
{
    return r->bloom > 0.0;
}

void bloom_sigmas(const struct render_settings *r, int height, double sigma[BLOOM_LEVELS])
{
    for (int k = 0; k < BLOOM_LEVELS; k++)
        sigma[k] = r->bloom_radius * height * ldexp(1.0, k);
}

/* The weights of a Gaussian of sigma pixels, taps 0 to its radius (4 sigma, at most KERNEL_MAX),
 * into kernel; the radius. */
static int gaussian_kernel(double sigma, double kernel[KERNEL_MAX + 1])
{
    int radius = (int)ceil(4.0 * sigma);
    radius = radius > KERNEL_MAX ? KERNEL_MAX : radius;
    for (int i = 0; i <= radius; i++)
        kernel[i] = exp(-0.5 * i * i / (sigma * sigma));
    return radius;
}

/* Where the centres of a row of n pixels land on the grid of an image 2^k times coarser (coarse_n
 * pixels): for each, the coarse pixel below it and the weight of the one above, clamped at the
 * edges. */
static void coarse_positions(int n, int k, int coarse_n, int *lo, float *frac)
{
    double scale = ldexp(1.0, k);
    for (int i = 0; i < n; i++) {
        double u = (i + 0.5) / scale - 0.5;
        lo[i] = u <= 0.0 ? 0 : u >= coarse_n - 1 ? coarse_n - 1 : (int)u;
        frac[i] = u <= 0.0 || u >= coarse_n - 1 ? 0.0f : (float)(u - lo[i]);
    }
}

/* The total weight each coarse pixel of a row receives (coarse_positions' weights summed). */
static void coarse_weights(int n, const int *lo, const float *frac, int coarse_n, float *weight)
{
    memset(weight, 0, (size_t)coarse_n * sizeof *weight);
    for (int i = 0; i < n; i++) {
        weight[lo[i]] += 1.0f - frac[i];
        weight[lo[i] + (frac[i] > 0.0f)] += frac[i];
    }
}

/* One Gaussian of the bloom on its image of the pyramid, each step split into rows over the cores
 * (io/parallel.h): the full image (w x h), the coarse one (cw x ch, j levels down) and the
 * scratch the steps share. */
struct bloom_level {
    const float *in;
    float *out, *level, *tmp, *acc;
    int w, h, cw, ch, j;
    int *x_lo, *y_lo;
    float *x_frac, *y_frac, *x_weight, *y_weight;
    const double *kernel;
    int radius;
    float spread;
};

/* Image j of the pyramid from the full image: each full pixel's light shared between the two
 * nearest pixels of image j along x (rows of acc), then along y (rows of level), by the weights
 * with which the interpolation back (upsampled_rows) reads them (its transpose), and each pixel of
 * image j the mean of what it received. So a point of light keeps its centre and its light
 * through the pyramid (the weights are linear in position), and an evenly lit image stays even. */
static void shared_x_rows(void *arg, int part, int parts)
{
    const struct bloom_level *b = arg;
    size_t row = (size_t)b->cw * CHANNELS;
    for (int y = part; y < b->h; y += parts) {
        const float *v = b->in + (size_t)y * b->w * CHANNELS;
        float *a = b->acc + (size_t)y * row;
        memset(a, 0, row * sizeof *a);
        for (int x = 0; x < b->w; x++, v += CHANNELS) {
            float f = b->x_frac[x];
            float *lo = a + (size_t)b->x_lo[x] * CHANNELS, *hi = lo + (f > 0.0f ? CHANNELS : 0);
            for (int c = 0; c < CHANNELS; c++) {
                lo[c] += (1.0f - f) * v[c];
                hi[c] += f * v[c];
            }
        }
        for (int x = 0; x < b->cw; x++)
            for (int c = 0; c < CHANNELS; c++)
                a[x * CHANNELS + c] /= b->x_weight[x];
    }
}

/* Coarse row cy gathers the rows of acc whose share reaches it (the rows mapped to cy, and those
 * mapped to cy - 1 with a weight above 0: a run of rows, the mapping being monotonic). */
static void shared_y_rows(void *arg, int part, int parts)
{
    const struct bloom_level *b = arg;
    size_t row = (size_t)b->cw * CHANNELS;
    int scale = 1 << b->j;
    for (int cy = part; cy < b->ch; cy += parts) {
        float *dst = b->level + (size_t)cy * row;
        memset(dst, 0, row * sizeof *dst);
        int first = (cy - 1) * scale - scale, last = (cy + 2) * scale + scale;
        first = first < 0 ? 0 : first;
        last = last > b->h ? b->h : last;
        for (int y = first; y < last; y++) {
            float f = b->y_frac[y];
            float share = b->y_lo[y] == cy ? 1.0f - f : b->y_lo[y] == cy - 1 && f > 0.0f ? f : 0.0f;
            if (share == 0.0f)
                continue;
            const float *src = b->acc + (size_t)y * row;
            for (size_t i = 0; i < row; i++)
                dst[i] += share * src[i];
        }
        for (size_t i = 0; i < row; i++)
            dst[i] /= b->y_weight[cy];
    }
}

/* The Gaussian along x, level into tmp; near an edge the taps inside the image are weighted to
 * sum to 1, so an evenly lit image stays even. */
static void blur_x_rows(void *arg, int part, int parts)
{
    const struct bloom_level *b = arg;
    for (int y = part; y < b->ch; y += parts)
        for (int x = 0; x < b->cw; x++) {
            double acc[CHANNELS] = {0.0, 0.0, 0.0}, total = 0.0;
            for (int i = x - b->radius < 0 ? -x : -b->radius; i <= b->radius && x + i < b->cw; i++) {
                double k = b->kernel[i < 0 ? -i : i];
                const float *v = b->level + ((size_t)y * b->cw + x + i) * CHANNELS;
                total += k;
                for (int c = 0; c < CHANNELS; c++)
                    acc[c] += k * v[c];
            }
            for (int c = 0; c < CHANNELS; c++)
                b->tmp[((size_t)y * b->cw + x) * CHANNELS + c] = (float)(acc[c] / total);
        }
}

/* The same along y, tmp back into level. */
static void blur_y_rows(void *arg, int part, int parts)
{
    const struct bloom_level *b = arg;
    size_t stride = (size_t)b->cw * CHANNELS;
    for (int y = part; y < b->ch; y += parts) {
        int lo = y - b->radius < 0 ? -y : -b->radius, hi = y + b->radius >= b->ch ? b->ch - 1 - y : b->radius;
        double total = 0.0;
        for (int i = lo; i <= hi; i++)
            total += b->kernel[i < 0 ? -i : i];
        float *dst = b->level + (size_t)y * stride;
        for (size_t j = 0; j < stride; j++) {
            double acc = 0.0;
            for (int i = lo; i <= hi; i++)
                acc += b->kernel[i < 0 ? -i : i] * b->tmp[(size_t)(y + i) * stride + j];
            dst[j] = (float)(acc / total);
        }
    }
}

/* out += spread x level interpolated bilinearly to the full image; each part a coarse row of tmp
 * to hold the row between two of level. */
static void upsampled_rows(void *arg, int part, int parts)
{
    const struct bloom_level *b = arg;
    size_t row = (size_t)b->cw * CHANNELS;
    float *line = b->tmp + (size_t)part * row;
    for (int y = part; y < b->h; y += parts) {
        const float *r0 = b->level + (size_t)b->y_lo[y] * row, *r1 = b->y_lo[y] + 1 < b->ch ? r0 + row : r0;
        float fy = b->y_frac[y];
        for (size_t i = 0; i < row; i++)
            line[i] = b->spread * (r0[i] + fy * (r1[i] - r0[i]));
        float *o = b->out + (size_t)y * b->w * CHANNELS;
        for (int x = 0; x < b->w; x++, o += CHANNELS) {
            const float *a = line + (size_t)b->x_lo[x] * CHANNELS;
            const float *c = b->x_lo[x] + 1 < b->cw ? a + CHANNELS : a;
            float fx = b->x_frac[x];
            for (int ch = 0; ch < CHANNELS; ch++)
                o[ch] += a[ch] + fx * (c[ch] - a[ch]);
        }
    }
}

/* The parts an image of w x h pixels is split into: one a core, but none under BLOOM_PART_PIXELS
 * (a thread costs more than a small image's rows), and at most a row each. */
#define BLOOM_PART_PIXELS 16384
static int parts_for(int w, int h)
{
    size_t chunks = (size_t)w * h / BLOOM_PART_PIXELS + 1;
    return parallel_parts(chunks < (size_t)h ? (int)chunks : h, 64);
}

int bloom_linear(const struct render_settings *r, int w, int h, const float *in, float *out)
{
    size_t n = (size_t)w * h * CHANNELS;
    if (!bloom_active(r)) {
        memcpy(out, in, n * sizeof *out);
        return 0;
    }
    /* an image of the pyramid, the scratch of its blur and of its making, a grid's positions */
    float *level = malloc(n * sizeof *level), *tmp = malloc(n * sizeof *tmp), *acc = malloc(n * sizeof *acc);
    float *floats = malloc(((size_t)w + h) * 2 * sizeof *floats);
    int *ints = malloc(((size_t)w + h) * sizeof *ints);
    if (!level || !tmp || !acc || !floats || !ints) {
        free(level);
        free(tmp);
        free(acc);
        free(floats);
        free(ints);
        return -1;
    }
    struct bloom_level b = {in, out, level, tmp, acc, w, h, 0, 0, 0, ints, ints + w, floats, floats + w,
                            floats + w + h, floats + 2 * w + h, NULL, 0, (float)(r->bloom / BLOOM_LEVELS)};
    double sigma[BLOOM_LEVELS], keep = 1.0 - r->bloom, kernel[KERNEL_MAX + 1];
    bloom_sigmas(r, h, sigma);
    for (size_t i = 0; i < n; i++)
        out[i] = (float)(keep * in[i]);
    int parts = parts_for(w, h);
    for (int k = 0; k < BLOOM_LEVELS; k++) {
        /* Gaussian k is drawn on image j of the pyramid, 2^j times coarser than the full image: the
         * coarsest where it is still COARSE_SIGMA_MIN of that image's pixels wide. The sharing into
         * image j and the interpolation back are each a tent of 2^j full pixels a side (variance
         * 4^j / 6 of a full pixel, each), so the blur there is narrower by as much. */
        int j = 0, longest = w > h ? w : h;
        for (int next = 1; ldexp(1.0, next) < longest; next++)
            if (sigma[k] * sigma[k] / ldexp(1.0, 2 * next) - 1.0 / 3.0 >= COARSE_SIGMA_MIN * COARSE_SIGMA_MIN)
                j = next;
        double scale = ldexp(1.0, j);
        b.j = j;
        b.cw = (int)ceil(w / scale);
        b.ch = (int)ceil(h / scale);
        coarse_positions(w, j, b.cw, b.x_lo, b.x_frac);
        coarse_positions(h, j, b.ch, b.y_lo, b.y_frac);
        if (j == 0) {
            memcpy(level, in, n * sizeof *level);
        } else {
            coarse_weights(w, b.x_lo, b.x_frac, b.cw, b.x_weight);
            coarse_weights(h, b.y_lo, b.y_frac, b.ch, b.y_weight);
            parallel_run(parts, shared_x_rows, &b);
            parallel_run(parts_for(b.cw, b.ch), shared_y_rows, &b);
        }
        double s2 = sigma[k] * sigma[k] / (scale * scale) - (j > 0 ? 1.0 / 3.0 : 0.0);
        /* a sigma under a tenth of a pixel moves no light beyond the pixel */
        if (s2 > 0.01) {
            b.kernel = kernel;
            b.radius = gaussian_kernel(sqrt(s2), kernel);
            parallel_run(parts_for(b.cw, b.ch), blur_x_rows, &b);
            parallel_run(parts_for(b.cw, b.ch), blur_y_rows, &b);
        }
        parallel_run(parts, upsampled_rows, &b);
    }
    free(level);
    free(tmp);
    free(acc);
    free(floats);
    free(ints);
    return 0;
}

/* The sRGB decoding of [0, 1] at DECODE_STEPS + 1 points, interpolated between them (within 2e-7
 * of the curve, far below an 8-bit level of the image it becomes), and the curve itself beyond. */
#define DECODE_STEPS 4096
struct srgb_codes {
    float decode[DECODE_STEPS + 1];
    double level_top[256];   /* the linear light where each 8-bit code gives way to the next (255: none) */
    unsigned char first[DECODE_STEPS + 1];   /* the code of i / DECODE_STEPS of linear light */
};

static void srgb_codes_init(struct srgb_codes *s)
{
    for (int i = 0; i <= DECODE_STEPS; i++)
        s->decode[i] = (float)srgb_to_linear((double)i / DECODE_STEPS);
    for (int k = 0; k < 255; k++)
        s->level_top[k] = srgb_to_linear((k + 0.5) / 255.0);
    s->level_top[255] = HUGE_VAL;
    for (int i = 0, k = 0; i <= DECODE_STEPS; i++) {
        while ((double)i / DECODE_STEPS >= s->level_top[k])
            k++;
        s->first[i] = (unsigned char)k;
    }
}

static float decoded(const struct srgb_codes *s, float encoded)
{
    if (!(encoded > 0.0f))
        return 0.0f;   /* NaN too */
    if (encoded >= 1.0f)
        return (float)srgb_to_linear(encoded);
    float u = encoded * DECODE_STEPS;
    int i = (int)u;
    return s->decode[i] + (u - (float)i) * (s->decode[i + 1] - s->decode[i]);
}

/* The 8-bit code of linear light (clamped to [0, 1]), as unorm8(linear_to_srgb(lin)): the code at the table's
 * step below it, then up past each code's top it lies beyond. */
static unsigned char code_of(const struct srgb_codes *s, double lin)
{
    if (!(lin > 0.0))
        return 0;
    if (lin >= 1.0)
        return 255;
    int k = s->first[(int)(lin * DECODE_STEPS)];
    while (lin >= s->level_top[k])
        k++;
    return (unsigned char)k;
}

/* The 8-bit image from the bloomed light, and the light from the frame's colour, rows over the
 * cores. */
struct image_job {
    const struct render_settings *r;
    const struct srgb_codes *codes;
    int w, h;
    const float *color;
    float *lin, *bloomed;
    unsigned char *rgba;
};

static void decoded_rows(void *arg, int part, int parts)
{
    const struct image_job *q = arg;
    for (int y = part; y < q->h; y += parts)
        for (size_t i = (size_t)y * q->w; i < (size_t)(y + 1) * q->w; i++)
            for (int c = 0; c < CHANNELS; c++)
                q->lin[CHANNELS * i + c] = decoded(q->codes, q->color[4 * i + c]);
}

static void coded_rows(void *arg, int part, int parts)
{
    const struct image_job *q = arg;
    int tone = tone_active(q->r);
    for (int y = part; y < q->h; y += parts)
        for (size_t i = (size_t)y * q->w; i < (size_t)(y + 1) * q->w; i++) {
            double rgb[CHANNELS];
            for (int c = 0; c < CHANNELS; c++)
                rgb[c] = q->bloomed[CHANNELS * i + c];
            if (tone)
                tone_map_linear(q->r, rgb);
            for (int c = 0; c < CHANNELS; c++)
                q->rgba[4 * i + c] = code_of(q->codes, rgb[c]);
            q->rgba[4 * i + 3] = unorm8(q->color[4 * i + 3]);
        }
}

int bloom_image(const struct render_settings *r, int w, int h, const float *color, unsigned char *rgba)
{
    size_t pixels = (size_t)w * h;
    float *lin = malloc(pixels * CHANNELS * sizeof *lin), *bloomed = malloc(pixels * CHANNELS * sizeof *bloomed);
    struct srgb_codes *codes = malloc(sizeof *codes);
    if (!lin || !bloomed || !codes) {
        free(lin);
        free(bloomed);
        free(codes);
        return -1;
    }
    srgb_codes_init(codes);
    struct image_job q = {r, codes, w, h, color, lin, bloomed, rgba};
    int parts = parts_for(w, h);
    parallel_run(parts, decoded_rows, &q);
    int rc = bloom_linear(r, w, h, lin, bloomed);
    if (rc == 0)
        parallel_run(parts, coded_rows, &q);
    free(lin);
    free(bloomed);
    free(codes);
    return rc;
}
