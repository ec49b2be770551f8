/* Reading float render targets back, whatever the context allows. */
#ifndef BT_READBACK_H
#define BT_READBACK_H
#include "gl/gl_api.h"
#include <stddef.h>
/* Read the RGBA pixels of the bound framebuffer's colour attachment 0 as floats.
 * ES3 and desktop GL accept RGBA/FLOAT for float buffers; ES2 may insist on its
 * implementation read type (half floats), converted here. 0 ok, -1 when no float read works. */
int read_float_pixels(int x, int y, int w, int h, float *rgba);
float half_to_float(unsigned short h);
/* Turn an image of `rows` rows of row_bytes each upside down in place: GL reads rows bottom-up,
 * images and dumps run top-down. 0, or -1 without memory for one row. */
int rows_flip(void *pixels, size_t row_bytes, int rows);
#endif
