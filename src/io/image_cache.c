#include "io/image_cache.h"
#include "io/png_io.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct kept_image {
    char *path;
    int width, height;
    unsigned char *rgba;
};

static struct {
    int on;
    struct kept_image *images;
    size_t count, capacity;
} cache;

void image_cache_keep(int on) { cache.on = on; }

static const struct kept_image *find(const char *path)
{
    for (size_t i = 0; i < cache.count; i++)
        if (strcmp(cache.images[i].path, path) == 0)
            return &cache.images[i];
    return NULL;
}

/* Decodes path once, at the largest size a scene may use; each reader applies its own limit. */
static const struct kept_image *keep(const char *path, int max_size, struct error *e)
{
    if (cache.count == cache.capacity) {
        size_t capacity = cache.capacity ? 2 * cache.capacity : 16;
        struct kept_image *grown = realloc(cache.images, capacity * sizeof *grown);
        if (!grown) {
            error_set(e, ERROR_RUNTIME, NULL, "out of memory keeping %s", path);
            return NULL;
        }
        cache.images = grown;
        cache.capacity = capacity;
    }
    struct kept_image im = {.path = strdup(path)};
    if (!im.path) {
        error_set(e, ERROR_RUNTIME, NULL, "out of memory keeping %s", path);
        return NULL;
    }
    if (png_read_rgba8(path, max_size, &im.width, &im.height, &im.rgba, e) != 0) {
        free(im.path);
        return NULL;
    }
    cache.images[cache.count] = im;
    return &cache.images[cache.count++];
}

int image_read(const char *path, int max_size, int *width, int *height, const unsigned char **rgba, int *owned,
               struct error *e)
{
    if (!cache.on) {
        unsigned char *pixels;
        if (png_read_rgba8(path, max_size, width, height, &pixels, e) != 0)
            return -1;
        *rgba = pixels;
        *owned = 1;
        return 0;
    }
    const struct kept_image *im = find(path);
    if (!im && !(im = keep(path, max_size, e)))
        return -1;
    if (im->width > max_size || im->height > max_size)
        return error_set(e, ERROR_INPUT, NULL, "image is %d x %d, larger than the limit of %d pixels a side",
                         im->width, im->height, max_size);
    *width = im->width;
    *height = im->height;
    *rgba = im->rgba;
    *owned = 0;
    return 0;
}

void image_cache_release(void)
{
    for (size_t i = 0; i < cache.count; i++) {
        free(cache.images[i].path);
        free(cache.images[i].rgba);
    }
    free(cache.images);
    memset(&cache, 0, sizeof cache);
}
