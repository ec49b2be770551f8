/* Reading and writing 8-bit RGBA PNG images, rows top-down, 4 bytes a pixel, no padding. */
#ifndef BENTRAY_PNG_IO_H
#define BENTRAY_PNG_IO_H

#include <stddef.h>
#include <stdio.h>

/* Writes PATH. An existing file is replaced only when OVERWRITE != 0, and then only once the
 * new image is complete: a failed write never leaves a truncated PNG behind.
 * Returns 0, or -1 with a message in ERR (ERRLEN bytes, may be 0). */
int png_write_rgba8(const char *path, int width, int height, const unsigned char *rgba_top_down,
                    int overwrite, char *err, size_t errlen);

/* The same 8-bit image into fp (standard output). 0, or -1 with a message in ERR. */
int png_write_rgba8_stream(FILE *fp, int width, int height, const unsigned char *rgba_top_down, char *err,
                           size_t errlen);
/* A 16-bit RGBA PNG with an sRGB chunk into fp, from RGBA floats top-down (sRGB-encoded colour and
 * alpha, clamped to [0, 1]). 0, or -1 with a message in ERR. */
int png_write_rgba16_stream(FILE *fp, int width, int height, const float *color, char *err, size_t errlen);

/* Reads any PNG (palette, grey, 16-bit, with or without alpha) as RGBA8. Images wider or
 * taller than MAX_SIZE are refused before any pixel memory is allocated.
 * Returns 0 with *RGBA_TOP_DOWN to be released with free(), or -1 with a message in ERR
 * and the outputs left untouched. */
int png_read_rgba8(const char *path, int max_size, int *width, int *height,
                   unsigned char **rgba_top_down, char *err, size_t errlen);

#endif
