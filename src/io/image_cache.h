/* Decoded images kept in memory by path, for a program that must not read its assets again once
 * it has started (the kiosk): a texture changed, cut short or removed on disk after the start
 * does not reach it, and a scene change reads no file. Off until image_cache_keep(1): then every
 * image_read of a new path decodes it once (png_read_rgba8) and keeps it until
 * image_cache_release(). */
#ifndef BT_IMAGE_CACHE_H
#define BT_IMAGE_CACHE_H
#include <stddef.h>

#include "io/error.h"

void image_cache_keep(int on);
/* The image at path as RGBA8, top row first, under png_read_rgba8's rules (an image wider or
 * taller than max_size is refused). *rgba belongs to the cache while it keeps images (*owned 0),
 * else to the caller (*owned 1: free()). 0, or -1 with the message in *e (png_read_rgba8's
 * statuses; a kept image larger than max_size: ERROR_INPUT). */
int image_read(const char *path, int max_size, int *width, int *height, const unsigned char **rgba, int *owned,
               struct error *e);
/* Frees every kept image and stops keeping them. */
void image_cache_release(void);

#endif
