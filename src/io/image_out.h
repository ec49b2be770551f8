/* The image of `bentray render` and `bentray animate` in the format its name asks for:
 *   NAME.png  8-bit sRGB RGBA (the default), or 16 bits a channel with --depth 16;
 *   NAME.pfm  Portable Float Map: linear-light RGB float32, colours brighter than white kept;
 *   -         a PNG on standard output.
 * Files are written through io/output_file.h (a temporary moved into place when complete). Alpha is
 * render.sky_alpha where rays reached the sky (PFM has none). 16-bit and PFM images need the
 * renderer's float colour (renderer_set_hdr, cpu_render_options.hdr). */
#ifndef BENTRAY_IMAGE_OUT_H
#define BENTRAY_IMAGE_OUT_H
#include <stddef.h>
#include <stdio.h>

#include "io/error.h"
#include "io/png_io.h"

enum image_format { IMAGE_PNG8, IMAGE_PNG16, IMAGE_PFM };

/* The format for PATH and --depth (8 or 16). 0, or -1 with why in *e (ERROR_INPUT). */
int image_format_of(const char *path, int depth, enum image_format *format, struct error *e);
/* Whether the format is written from the float colour. */
int image_format_float(enum image_format format);
/* rgba8: RGBA8 rows top-down; color: RGBA floats (sRGB-encoded colour, alpha), needed for PNG16 and
 * PFM; COMPRESSION applies to PNG. 0, or -1 with the message in *e: ERROR_INPUT for a refused path (output_check's rules),
 * ERROR_RUNTIME for a write that failed. */
int image_write(const char *path, enum image_format format, int width, int height, const unsigned char *rgba8,
                const float *color, int overwrite, enum png_compression compression, struct error *e);

#endif
