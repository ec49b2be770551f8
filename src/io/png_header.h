/* What a PNG file says of itself in its first bytes, read without libpng (and so without decoding
 * anything): the scene's checks and the kiosk's image memory bound use it before any image is
 * loaded, and the fuzz harnesses, which link no PNG code, with them. */
#ifndef BT_PNG_HEADER_H
#define BT_PNG_HEADER_H

/* The size PATH declares in its PNG header, without decoding: 0, or 1 when it does not start like
 * a PNG (or cannot be read). */
int png_declared_size(const char *path, unsigned long *width, unsigned long *height);

#endif
