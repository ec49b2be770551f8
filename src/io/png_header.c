#include "io/png_header.h"
#include <stdio.h>
#include <string.h>

/* The size a PNG file declares in its header (the IHDR chunk, which must come first), read
 * without decoding: a scene refuses a texture too large at the line that names it, and the kiosk
 * adds up what its scenes' images will take before it decodes any. 0 with the size; 1 when the
 * file does not start like a PNG: that is left to the PNG reader, which says so when the image is
 * loaded. */
int png_declared_size(const char *path, unsigned long *width, unsigned long *height)
{
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    unsigned char head[24];
    FILE *f = fopen(path, "rb");
    size_t n = f ? fread(head, 1, sizeof head, f) : 0;
    if (f)
        fclose(f);
    if (n != sizeof head || memcmp(head, signature, 8) != 0 || memcmp(head + 12, "IHDR", 4) != 0)
        return 1;
    *width = (unsigned long)head[16] << 24 | (unsigned long)head[17] << 16 | (unsigned long)head[18] << 8 | head[19];
    *height = (unsigned long)head[20] << 24 | (unsigned long)head[21] << 16 | (unsigned long)head[22] << 8 | head[23];
    return 0;
}
