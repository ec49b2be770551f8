/* The image of `bentray render` and `animate` in the format its name asks for (io/image_out.h). */
#include "io/image_out.h"
#include "io/output_file.h"
#include "io/png_io.h"
#include "io/sample_average.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

static int has_extension(const char *path, const char *ext)
{
    size_t n = strlen(path), e = strlen(ext);
    return n > e && strcasecmp(path + n - e, ext) == 0;
}

int image_format_of(const char *path, int depth, enum image_format *format, struct error *e)
{
    int to_stdout = strcmp(path, "-") == 0;
    if (to_stdout || has_extension(path, ".png")) {
        *format = depth == 16 ? IMAGE_PNG16 : IMAGE_PNG8;
        return 0;
    }
    if (has_extension(path, ".pfm")) {
        if (depth == 16)
            return error_set(e, ERROR_INPUT, NULL, "--depth 16 is for PNG; a PFM image holds 32-bit floats");
        *format = IMAGE_PFM;
        return 0;
    }
    return error_set(e, ERROR_INPUT, NULL, "bentray writes PNG (.png, 8 or 16 bits a channel: --depth) and PFM "
                                           "(.pfm, linear floats) images: give the file one of these extensions, "
                                           "or - for a PNG on standard output");
}

/* PFM (Portable Float Map): "PF", width and height, -1 for little-endian, then RGB float32 rows
 * from the bottom up, in linear light (the sRGB-encoded colour decoded, brighter than white kept). */
static int write_pfm(FILE *fp, int width, int height, const float *color, struct error *e)
{
    float *row = malloc((size_t)width * 3 * sizeof(float));
    if (!row)
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory writing a PFM image");
    int ok = fprintf(fp, "PF\n%d %d\n-1.0\n", width, height) > 0;
    for (int y = height - 1; y >= 0 && ok; y--) {
        const float *src = color + (size_t)y * width * 4;
        for (int x = 0; x < width; x++)
            for (int c = 0; c < 3; c++) {
                float v = (float)srgb_to_linear(src[4 * x + c] > 0.0f ? src[4 * x + c] : 0.0f);
                /* little-endian whatever the host */
                uint32_t bits;
                memcpy(&bits, &v, sizeof bits);
                unsigned char b[4] = {(unsigned char)bits, (unsigned char)(bits >> 8), (unsigned char)(bits >> 16),
                                      (unsigned char)(bits >> 24)};
                memcpy((unsigned char *)row + 4 * (3 * (size_t)x + c), b, 4);
            }
        ok = fwrite(row, sizeof(float), (size_t)width * 3, fp) == (size_t)width * 3;
    }
    free(row);
    if (!ok)
        error_set(e, ERROR_RUNTIME, NULL, "%s", strerror(errno ? errno : EIO));
    return ok ? 0 : -1;
}

/* The encoded image into fp. */
static int write_to(FILE *fp, enum image_format format, int width, int height, const unsigned char *rgba8,
                    const float *color, enum png_compression compression, struct error *e)
{
    if (format == IMAGE_PNG16)
        return png_write_rgba16_stream(fp, width, height, color, compression, e);
    if (format == IMAGE_PFM)
        return write_pfm(fp, width, height, color, e);
    return png_write_rgba8_stream(fp, width, height, rgba8, compression, e);
}

int image_write(const char *path, enum image_format format, int width, int height, const unsigned char *rgba8,
                const float *color, int overwrite, enum png_compression compression, struct error *e)
{
    error_clear(e);
    if (format != IMAGE_PNG8 && !color)
        return error_set(e, ERROR_RUNTIME, NULL, "cannot write %s: no float colour was rendered", path);
    if (strcmp(path, "-") == 0) {
        errno = 0;
        if (write_to(stdout, format, width, height, rgba8, color, compression, e) != 0 || fflush(stdout) != 0) {
            if (e->message[0] == '\0')
                error_set(e, ERROR_RUNTIME, NULL, "standard output: %s", strerror(errno ? errno : EIO));
            return -1;
        }
        return 0;
    }
    if (format == IMAGE_PNG8)
        return png_write_rgba8(path, width, height, rgba8, overwrite, compression, e);
    struct output_file o;
    if (output_open(&o, path, overwrite, e) != 0)
        return -1;
    struct error why;
    error_clear(&why);
    errno = 0;
    if (write_to(o.fp, format, width, height, rgba8, color, compression, &why) != 0) {
        error_set(e, ERROR_RUNTIME, NULL, "cannot write %s: %s", path, why.message);
        output_abort(&o);
        return -1;
    }
    return output_commit(&o, e);
}

int image_format_float(enum image_format format)
{
    return format != IMAGE_PNG8;
}
