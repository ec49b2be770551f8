/* The memory the kiosk's images take: every scene's textures and sky faces are decoded at start
 * and kept for the whole run (io/image_cache.h), 4 bytes a texel, each file once. Their total,
 * read from the PNG headers before any is decoded, is held to [kiosk] image_memory. */
#ifndef BT_KIOSK_IMAGES_H
#define BT_KIOSK_IMAGES_H
#include <stddef.h>
#include "io/error.h"
#include "kiosk_config/kiosk_config.h"
#include "scene/scene.h"

/* Bytes the images of scenes[0 .. n-1] take decoded; the largest one's path and size. */
double kiosk_image_bytes(const struct scene *scenes, int n, char *largest, size_t largest_len, unsigned long *width,
                         unsigned long *height);
/* 0, or -1 with e (ERROR_INPUT; where "CONFIG:LINE", message "[kiosk] image_memory = ...") when
 * they take more than allowed. */
int kiosk_image_memory_check(const struct kiosk_config *c, const struct scene *scenes, struct error *e);

#endif
