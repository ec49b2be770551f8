#include "gl/readback.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

float half_to_float(unsigned short h)
{
    int sign = (h >> 15) & 1, exponent = (h >> 10) & 31, mantissa = h & 1023;
    float v;
    if (exponent == 0)
        v = ldexpf((float)mantissa, -24);
    else if (exponent == 31)
        v = mantissa ? NAN : INFINITY;
    else
        v = ldexpf((float)(mantissa | 1024), exponent - 25);
    return sign ? -v : v;
}

int read_float_pixels(int x, int y, int w, int h, float *rgba)
{
    while (glGetError() != GL_NO_ERROR) {
    }
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(x, y, w, h, GL_RGBA, GL_FLOAT, rgba);
    if (glGetError() == GL_NO_ERROR)
        return 0;
    GLint format = 0, type = 0;
    glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_FORMAT, &format);
    glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_TYPE, &type);
    if (format != GL_RGBA || (type != GL_HALF_FLOAT_OES && type != GL_HALF_FLOAT))
        return -1;
    size_t n = (size_t)w * (size_t)h * 4;
    unsigned short *half = malloc(n * sizeof *half);
    if (!half)
        return -1;
    glReadPixels(x, y, w, h, GL_RGBA, (GLenum)type, half);
    int ok = glGetError() == GL_NO_ERROR;
    for (size_t i = 0; ok && i < n; i++)
        rgba[i] = half_to_float(half[i]);
    free(half);
    return ok ? 0 : -1;
}

int rows_flip(void *pixels, size_t row_bytes, int rows)
{
    unsigned char *row = malloc(row_bytes ? row_bytes : 1), *p = pixels;
    if (!row)
        return -1;
    for (int top = 0, bottom = rows - 1; top < bottom; top++, bottom--) {
        memcpy(row, p + (size_t)top * row_bytes, row_bytes);
        memcpy(p + (size_t)top * row_bytes, p + (size_t)bottom * row_bytes, row_bytes);
        memcpy(p + (size_t)bottom * row_bytes, row, row_bytes);
    }
    free(row);
    return 0;
}
