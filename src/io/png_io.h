/* Reading and writing 8-bit RGBA PNG images, rows top-down, 4 bytes a pixel, no padding. */
#ifndef BENTRAY_PNG_IO_H
#define BENTRAY_PNG_IO_H

#include <stddef.h>
#include <stdio.h>

#include "io/error.h"

/* How hard a PNG is compressed: FAST (the default of render, animate and the kiosk; libpng's
 * PNG_IMAGE_FLAG_FAST) writes quickly into a larger file; SMALL is libpng's own default deflate,
 * for a file to keep or send (both timed in docs/BENCH.md, "The time a user waits"). */
enum png_compression { PNG_COMPRESSION_FAST, PNG_COMPRESSION_SMALL };

/* Writes PATH. An existing file is replaced only when OVERWRITE != 0, and then only once the
 * new image is complete: a failed write never leaves a truncated PNG behind.
 * Returns 0, or -1 with the message in *e: ERROR_INPUT for a refused path (output_check's rules),
 * ERROR_RUNTIME for a write that failed. */
int png_write_rgba8(const char *path, int width, int height, const unsigned char *rgba_top_down,
                    int overwrite, enum png_compression compression, struct error *e);

/* The same 8-bit image into fp (standard output). 0, or -1 with the message in *e (ERROR_RUNTIME). */
int png_write_rgba8_stream(FILE *fp, int width, int height, const unsigned char *rgba_top_down,
                           enum png_compression compression, struct error *e);
/* A 16-bit RGBA PNG with an sRGB chunk into fp, from RGBA floats top-down (sRGB-encoded colour and
 * alpha, clamped to [0, 1]). 0, or -1 with the message in *e (ERROR_RUNTIME). */
int png_write_rgba16_stream(FILE *fp, int width, int height, const float *color, enum png_compression compression,
                            struct error *e);

/* Reads any PNG (palette, grey, 16-bit, with or without alpha) as RGBA8. Images wider or
 * taller than MAX_SIZE are refused before any pixel memory is allocated.
 * Returns 0 with *RGBA_TOP_DOWN to be released with free(), or -1 with the message in *e
 * and the outputs left untouched: ERROR_INPUT for a file that is missing, unreadable, not a PNG,
 * damaged or too large, ERROR_RUNTIME for a failure of the machine (out of memory, an I/O error). */
int png_read_rgba8(const char *path, int max_size, int *width, int *height,
                   unsigned char **rgba_top_down, struct error *e);

#endif
