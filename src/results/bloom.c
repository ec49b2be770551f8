#include "results/bloom.h"
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

/* img (w x h) blurred by the kernel along x into tmp, then along y back into img; near an edge
 * the taps inside the image are weighted to sum to 1, so an evenly lit image stays even. */
static void gaussian(float *img, float *tmp, int w, int h, const double *kernel, int radius)
{
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double acc[CHANNELS] = {0.0, 0.0, 0.0}, total = 0.0;
            for (int i = x - radius < 0 ? -x : -radius; i <= radius && x + i < w; i++) {
                double k = kernel[i < 0 ? -i : i];
                const float *v = img + ((size_t)y * w + x + i) * CHANNELS;
                total += k;
                for (int c = 0; c < CHANNELS; c++)
                    acc[c] += k * v[c];
            }
            for (int c = 0; c < CHANNELS; c++)
                tmp[((size_t)y * w + x) * CHANNELS + c] = (float)(acc[c] / total);
        }
    size_t stride = (size_t)w * CHANNELS;
    for (int y = 0; y < h; y++) {
        int lo = y - radius < 0 ? -y : -radius, hi = y + radius >= h ? h - 1 - y : radius;
        double total = 0.0;
        for (int i = lo; i <= hi; i++)
            total += kernel[i < 0 ? -i : i];
        float *dst = img + (size_t)y * stride;
        for (size_t j = 0; j < stride; j++) {
            double acc = 0.0;
            for (int i = lo; i <= hi; i++)
                acc += kernel[i < 0 ? -i : i] * tmp[(size_t)(y + i) * stride + j];
            dst[j] = (float)(acc / total);
        }
    }
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

/* A grid's positions along x and y (coarse_positions). */
struct coarse_grid {
    int cw, ch;
    int *x_lo, *y_lo;
    float *x_frac, *y_frac;
};

/* Image k of the pyramid from the full image (w x h): each full pixel's light shared between the
 * two nearest pixels of image k along x, then along y, by the weights with which add_upsampled
 * interpolates them back (its transpose), and each pixel of image k the mean of what it received.
 * So a point of light keeps its centre and its light through the pyramid (the weights are linear
 * in position), and an evenly lit image stays even. g->cw x g->ch pixels into out; acc holds
 * g->cw x h of them, weight max(cw, ch) numbers. */
static void downsampled(const float *in, int w, int h, const struct coarse_grid *g, float *out, float *acc,
                        float *weight)
{
    int cw = g->cw, ch = g->ch;
    size_t row = (size_t)cw * CHANNELS;
    memset(acc, 0, row * h * sizeof *acc);
    memset(weight, 0, (size_t)(cw > ch ? cw : ch) * sizeof *weight);
    for (int x = 0; x < w; x++) {
        weight[g->x_lo[x]] += 1.0f - g->x_frac[x];
        weight[g->x_lo[x] + (g->x_frac[x] > 0.0f)] += g->x_frac[x];
    }
    for (int y = 0; y < h; y++) {
        const float *v = in + (size_t)y * w * CHANNELS;
        float *a = acc + (size_t)y * row;
        for (int x = 0; x < w; x++, v += CHANNELS) {
            float f = g->x_frac[x];
            float *lo = a + (size_t)g->x_lo[x] * CHANNELS, *hi = lo + (f > 0.0f ? CHANNELS : 0);
            for (int c = 0; c < CHANNELS; c++) {
                lo[c] += (1.0f - f) * v[c];
                hi[c] += f * v[c];
            }
        }
        for (int x = 0; x < cw; x++)
            for (int c = 0; c < CHANNELS; c++)
                a[x * CHANNELS + c] /= weight[x];
    }
    memset(out, 0, row * ch * sizeof *out);
    memset(weight, 0, (size_t)(cw > ch ? cw : ch) * sizeof *weight);
    for (int y = 0; y < h; y++) {
        float f = g->y_frac[y];
        weight[g->y_lo[y]] += 1.0f - f;
        weight[g->y_lo[y] + (f > 0.0f)] += f;
        const float *src = acc + (size_t)y * row;
        float *lo = out + (size_t)g->y_lo[y] * row, *hi = lo + (f > 0.0f ? row : 0);
        for (size_t i = 0; i < row; i++) {
            lo[i] += (1.0f - f) * src[i];
            hi[i] += f * src[i];
        }
    }
    for (int y = 0; y < ch; y++)
        for (size_t i = 0; i < row; i++)
            out[(size_t)y * row + i] /= weight[y];
}

/* out (w x h) += weight x the image of grid g interpolated bilinearly to w x h; line holds a
 * coarse row. */
static void add_upsampled(const float *coarse, const struct coarse_grid *g, float weight, float *out, int w, int h,
                          float *line)
{
    size_t row = (size_t)g->cw * CHANNELS;
    for (int y = 0; y < h; y++) {
        const float *r0 = coarse + (size_t)g->y_lo[y] * row, *r1 = g->y_lo[y] + 1 < g->ch ? r0 + row : r0;
        float fy = g->y_frac[y];
        for (size_t i = 0; i < row; i++)
            line[i] = weight * (r0[i] + fy * (r1[i] - r0[i]));
        float *o = out + (size_t)y * w * CHANNELS;
        for (int x = 0; x < w; x++, o += CHANNELS) {
            const float *a = line + (size_t)g->x_lo[x] * CHANNELS;
            const float *b = g->x_lo[x] + 1 < g->cw ? a + CHANNELS : a;
            float fx = g->x_frac[x];
            for (int c = 0; c < CHANNELS; c++)
                o[c] += a[c] + fx * (b[c] - a[c]);
        }
    }
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
    float *weight = floats + w + h;
    struct coarse_grid g = {0, 0, ints, ints + w, floats, floats + w};
    double sigma[BLOOM_LEVELS], keep = 1.0 - r->bloom;
    float spread = (float)(r->bloom / BLOOM_LEVELS);
    bloom_sigmas(r, h, sigma);
    for (size_t i = 0; i < n; i++)
        out[i] = (float)(keep * in[i]);
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
        g.cw = (int)ceil(w / scale);
        g.ch = (int)ceil(h / scale);
        coarse_positions(w, j, g.cw, g.x_lo, g.x_frac);
        coarse_positions(h, j, g.ch, g.y_lo, g.y_frac);
        if (j == 0)
            memcpy(level, in, n * sizeof *level);
        else
            downsampled(in, w, h, &g, level, acc, weight);
        double s2 = sigma[k] * sigma[k] / (scale * scale) - (j > 0 ? 1.0 / 3.0 : 0.0), kernel[KERNEL_MAX + 1];
        /* a sigma under a tenth of a pixel moves no light beyond the pixel */
        if (s2 > 0.01)
            gaussian(level, tmp, g.cw, g.ch, kernel, gaussian_kernel(sqrt(s2), kernel));
        add_upsampled(level, &g, spread, out, w, h, tmp);
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
    for (size_t i = 0; i < pixels; i++)
        for (int c = 0; c < CHANNELS; c++)
            lin[CHANNELS * i + c] = decoded(codes, color[4 * i + c]);
    int rc = bloom_linear(r, w, h, lin, bloomed), tone = tone_active(r);
    for (size_t i = 0; i < pixels && rc == 0; i++) {
        double rgb[CHANNELS];
        for (int c = 0; c < CHANNELS; c++)
            rgb[c] = bloomed[CHANNELS * i + c];
        if (tone)
            tone_map_linear(r, rgb);
        for (int c = 0; c < CHANNELS; c++)
            rgba[4 * i + c] = code_of(codes, rgb[c]);
        rgba[4 * i + 3] = unorm8(color[4 * i + 3]);
    }
    free(lin);
    free(bloomed);
    free(codes);
    return rc;
}
