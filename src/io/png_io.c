/* PNG input and output through libpng.
 *
 * Writing uses the simplified API (png_image): it is short and always produces 8-bit RGBA.
 * Reading uses the full API because the simplified one assumes that 16-bit files without a
 * gAMA chunk hold linear light and gamma-encodes them on the way to 8 bits, which would
 * brighten ordinary 16-bit textures. Here 16-bit samples are only rescaled and, as for every
 * other format, no gamma conversion is applied: textures are used as stored. */
#include "io/png_io.h"
#include "io/output_file.h"
#include "io/text_file.h"

#include <errno.h>
#include <math.h>
#include <fcntl.h>
#include <png.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int png_write_rgba8(const char *path, int width, int height, const unsigned char *rgba_top_down,
                    int overwrite, enum png_compression compression, struct error *e)
{
    if (!path || !*path || !rgba_top_down || width <= 0 || height <= 0 ||
        width > INT32_MAX / 4)
        return error_set(e, ERROR_RUNTIME, NULL, "cannot write %s: invalid image (%d x %d)",
                         path ? path : "(null)", width, height);
    struct output_file o;
    if (output_open(&o, path, overwrite, e) != 0)
        return -1;
    struct error why;
    if (png_write_rgba8_stream(o.fp, width, height, rgba_top_down, compression, &why) != 0) {
        error_set(e, why.status, NULL, "cannot write %s: %s", path, why.message);
        output_abort(&o);
        return -1;
    }
    return output_commit(&o, e);
}

int png_write_rgba8_stream(FILE *fp, int width, int height, const unsigned char *rgba_top_down,
                           enum png_compression compression, struct error *e)
{
    png_image image;
    memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    image.width = (png_uint_32)width;
    image.height = (png_uint_32)height;
    image.format = PNG_FORMAT_RGBA;
    image.flags = compression == PNG_COMPRESSION_FAST ? PNG_IMAGE_FLAG_FAST : 0;
    errno = 0;
    int ok = png_image_write_to_stdio(&image, fp, 0, rgba_top_down, 0, NULL) != 0;
    if (!ok)
        error_set(e, ERROR_RUNTIME, NULL, "%s%s%s", image.message, errno ? ": " : "", errno ? strerror(errno) : "");
    png_image_free(&image);
    return ok ? 0 : -1;
}

/* libpng's state and what its callbacks report, for reading and for the 16-bit writer. */
struct png_ctx {
    FILE *fp;
    int max_size;
    png_structp png;
    png_infop info;
    unsigned char *pixels;
    png_bytep *rows;
    png_uint_32 width, height;
    char msg[200];
    enum error_status status;   /* whose failure msg is, for a reader (a damaged file: ERROR_INPUT) */
};

static void on_png_error(png_structp png, png_const_charp msg)
{
    struct png_ctx *ctx = png_get_error_ptr(png);
    snprintf(ctx->msg, sizeof ctx->msg, "%s", msg);
    /* libpng's own allocations fail with "Out of memory", "Insufficient memory ...": the machine's */
    if (strstr(msg, "memory"))
        ctx->status = ERROR_RUNTIME;
    png_longjmp(png, 1);
}

/* Warnings (unknown chunks, odd sRGB profiles) are not the caller's business. */
static void on_png_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg;
}

/* libpng's own reader says only "Read Error" when the file ends early; truncation is the
 * common case (an interrupted copy or download), so it gets a message of its own. */
static void read_data(png_structp png, png_bytep data, size_t length)
{
    struct png_ctx *ctx = png_get_io_ptr(png);
    if (fread(data, 1, length, ctx->fp) != length) {
        if (!feof(ctx->fp))
            ctx->status = ERROR_RUNTIME;   /* an I/O error, not the file's content */
        png_error(png, feof(ctx->fp) ? "the file is truncated" : strerror(errno));
    }
}

/* Kept apart from png_read_rgba8 so that everything changed after setjmp lives in *ctx, outside
 * this stack frame, and keeps its value when libpng jumps back. */
static int read_image(struct png_ctx *ctx)
{
    if (setjmp(png_jmpbuf(ctx->png)))
        return -1;

    png_set_read_fn(ctx->png, ctx, read_data);
    png_read_info(ctx->png, ctx->info);

    ctx->width = png_get_image_width(ctx->png, ctx->info);
    ctx->height = png_get_image_height(ctx->png, ctx->info);
    if (ctx->width > (png_uint_32)ctx->max_size || ctx->height > (png_uint_32)ctx->max_size) {
        snprintf(ctx->msg, sizeof ctx->msg,
                 "image is %lu x %lu, larger than the limit of %d pixels a side",
                 (unsigned long)ctx->width, (unsigned long)ctx->height, ctx->max_size);
        return -1;
    }

    int color_type = png_get_color_type(ctx->png, ctx->info);
    int bit_depth = png_get_bit_depth(ctx->png, ctx->info);
    int has_trns = png_get_valid(ctx->png, ctx->info, PNG_INFO_tRNS) != 0;

    if (color_type == PNG_COLOR_TYPE_PALETTE)
        png_set_palette_to_rgb(ctx->png);
    if (color_type == PNG_COLOR_TYPE_GRAY && bit_depth < 8)
        png_set_expand_gray_1_2_4_to_8(ctx->png);
    if (has_trns)
        png_set_tRNS_to_alpha(ctx->png);
    if (bit_depth == 16)
        png_set_scale_16(ctx->png);
    if (color_type == PNG_COLOR_TYPE_GRAY || color_type == PNG_COLOR_TYPE_GRAY_ALPHA)
        png_set_gray_to_rgb(ctx->png);
    if (!(color_type & PNG_COLOR_MASK_ALPHA) && !has_trns)
        png_set_add_alpha(ctx->png, 0xff, PNG_FILLER_AFTER);
    png_set_interlace_handling(ctx->png);
    png_read_update_info(ctx->png, ctx->info);

    size_t rowbytes = png_get_rowbytes(ctx->png, ctx->info);
    if (rowbytes != (size_t)ctx->width * 4) {
        snprintf(ctx->msg, sizeof ctx->msg, "unsupported pixel layout (%zu bytes a row)", rowbytes);
        return -1;
    }
    ctx->pixels = malloc(rowbytes * ctx->height);
    ctx->rows = malloc(sizeof *ctx->rows * ctx->height);
    if (!ctx->pixels || !ctx->rows) {
        snprintf(ctx->msg, sizeof ctx->msg, "out of memory");
        ctx->status = ERROR_RUNTIME;
        return -1;
    }
    for (png_uint_32 y = 0; y < ctx->height; y++)
        ctx->rows[y] = ctx->pixels + rowbytes * y;
    png_read_image(ctx->png, ctx->rows);
    png_read_end(ctx->png, NULL);
    return 0;
}

int png_read_rgba8(const char *path, int max_size, int *width, int *height,
                   unsigned char **rgba_top_down, struct error *e)
{
    if (!path || !width || !height || !rgba_top_down || max_size <= 0)
        return error_set(e, ERROR_RUNTIME, NULL, "cannot read %s: invalid arguments", path ? path : "(null)");
    struct png_ctx ctx;
    memset(&ctx, 0, sizeof ctx);
    ctx.max_size = max_size;
    ctx.status = ERROR_INPUT;

    struct error why;
    ctx.fp = regular_file_open(path, "image", &why);
    if (!ctx.fp)
        return error_set(e, why.status, NULL, "%s: %s", path, why.message);
    /* Checking the signature ourselves gives a plain message instead of libpng's. */
    unsigned char sig[8];
    if (fread(sig, 1, sizeof sig, ctx.fp) != sizeof sig || png_sig_cmp(sig, 0, sizeof sig) != 0) {
        error_set(e, ERROR_INPUT, NULL, "cannot read %s: not a PNG file", path);
        fclose(ctx.fp);
        return -1;
    }
    ctx.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &ctx, on_png_error, on_png_warning);
    if (ctx.png)
        ctx.info = png_create_info_struct(ctx.png);
    if (!ctx.png || !ctx.info) {
        error_set(e, ERROR_RUNTIME, NULL, "cannot read %s: out of memory", path);
        png_destroy_read_struct(ctx.png ? &ctx.png : NULL, NULL, NULL);
        fclose(ctx.fp);
        return -1;
    }
    png_set_sig_bytes(ctx.png, sizeof sig);

    int rc = read_image(&ctx);
    png_destroy_read_struct(&ctx.png, &ctx.info, NULL);
    fclose(ctx.fp);
    free(ctx.rows);
    if (rc != 0) {
        free(ctx.pixels);
        error_set(e, ctx.status, NULL, "cannot read %s: %s", path, ctx.msg);
        return -1;
    }
    *width = (int)ctx.width;
    *height = (int)ctx.height;
    *rgba_top_down = ctx.pixels;
    return 0;
}

/* 16-bit code of an sRGB-encoded value, clamped, rounded to nearest, big-endian as PNG stores it. */
static void put16(png_bytep at, double encoded)
{
    encoded = encoded < 0.0 ? 0.0 : encoded > 1.0 ? 1.0 : encoded;
    long v = lrint(encoded * 65535.0);
    at[0] = (png_byte)(v >> 8);
    at[1] = (png_byte)(v & 0xff);
}

/* Kept apart, as read_image is, so that what changes after setjmp lives in *ctx. */
static int write_rows16(struct png_ctx *ctx, int width, int height, const float *color, png_bytep row,
                        enum png_compression compression)
{
    if (setjmp(png_jmpbuf(ctx->png)))
        return -1;
    png_init_io(ctx->png, ctx->fp);
    if (compression == PNG_COMPRESSION_FAST) {
        /* as the simplified writer's PNG_IMAGE_FLAG_FAST: one cheap filter, a fast deflate */
        png_set_filter(ctx->png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
        png_set_compression_level(ctx->png, 3);
    }
    png_set_IHDR(ctx->png, ctx->info, (png_uint_32)width, (png_uint_32)height, 16, PNG_COLOR_TYPE_RGB_ALPHA,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB_gAMA_and_cHRM(ctx->png, ctx->info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(ctx->png, ctx->info);
    for (int y = 0; y < height; y++) {
        const float *src = color + (size_t)y * width * 4;
        for (int x = 0; x < width; x++)
            for (int c = 0; c < 4; c++)
                put16(row + 8 * x + 2 * c, src[4 * x + c]);
        png_write_row(ctx->png, row);
    }
    png_write_end(ctx->png, NULL);
    return 0;
}

int png_write_rgba16_stream(FILE *fp, int width, int height, const float *color, enum png_compression compression,
                            struct error *e)
{
    struct png_ctx ctx;
    memset(&ctx, 0, sizeof ctx);
    ctx.fp = fp;
    png_bytep row = malloc((size_t)width * 8);
    ctx.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &ctx, on_png_error, on_png_warning);
    ctx.info = ctx.png ? png_create_info_struct(ctx.png) : NULL;
    int rc = -1;
    if (!row || !ctx.png || !ctx.info)
        error_set(e, ERROR_RUNTIME, NULL, "out of memory writing a 16-bit PNG");
    else if ((rc = write_rows16(&ctx, width, height, color, row, compression)) != 0)
        error_set(e, ERROR_RUNTIME, NULL, "%s%s%s", ctx.msg, errno ? ": " : "", errno ? strerror(errno) : "");
    png_destroy_write_struct(&ctx.png, ctx.info ? &ctx.info : NULL);
    free(row);
    return rc;
}
