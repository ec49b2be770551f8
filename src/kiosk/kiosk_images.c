/* The memory the kiosk's images take (kiosk_images.h). */
#include "kiosk/kiosk_images.h"
#include "io/png_header.h"
#include "kiosk_config/kiosk_config_keys.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { IMAGE_PATH_LEN = SCENE_PATH_LEN + 16 };

/* Image k of scene s (its textures, then its sky's faces) into path; 0 when it has none. */
static int image_path(const struct scene *s, int k, char *path)
{
    if (k < s->n_textures) {
        snprintf(path, IMAGE_PATH_LEN, "%s", s->textures[k]);
        return 1;
    }
    k -= s->n_textures;
    if (s->sky.type != SKY_CUBEMAP || k >= SCENE_CUBEMAP_FACES)
        return 0;
    scene_cubemap_face_path(s->sky.cubemap, k, path, IMAGE_PATH_LEN);
    return 1;
}

/* Was the image at path counted already, as an image of scenes before (i, k)? */
static int counted(const struct scene *scenes, int i, int k, const char *path)
{
    char other[IMAGE_PATH_LEN];
    for (int j = 0; j <= i; j++)
        for (int m = 0; m < (j < i ? SCENE_MAX_TEXTURES + SCENE_CUBEMAP_FACES : k); m++)
            if (image_path(&scenes[j], m, other) && strcmp(other, path) == 0)
                return 1;
    return 0;
}

double kiosk_image_bytes(const struct scene *scenes, int n, char *largest, size_t largest_len, unsigned long *width,
                         unsigned long *height)
{
    double total = 0.0, most = -1.0;
    char path[IMAGE_PATH_LEN];
    largest[0] = '\0';
    *width = *height = 0;
    for (int i = 0; i < n; i++)
        for (int k = 0; image_path(&scenes[i], k, path); k++) {
            unsigned long w, h;
            /* a file that is no PNG takes nothing: the decoder refuses it with its line */
            if (counted(scenes, i, k, path) || png_declared_size(path, &w, &h) != 0)
                continue;
            double bytes = 4.0 * (double)w * (double)h;
            total += bytes;
            if (bytes > most) {
                most = bytes;
                snprintf(largest, largest_len, "%s", path);
                *width = w;
                *height = h;
            }
        }
    return total;
}

int kiosk_image_memory_check(const struct kiosk_config *c, const struct scene *scenes, struct error *e)
{
    char largest[IMAGE_PATH_LEN];
    unsigned long w, h;
    double bytes = kiosk_image_bytes(scenes, c->kiosk.n_scenes, largest, sizeof largest, &w, &h);
    double mb = bytes / 1048576.0;
    if (mb <= c->kiosk.image_memory)
        return 0;
    int line = kiosk_key_line(c, KSEC_KIOSK, 0, "image_memory");
    char where[KIOSK_PATH_LEN + 16];
    if (line > 0)
        snprintf(where, sizeof where, "%s:%d", c->path, line);
    else
        snprintf(where, sizeof where, "%s", c->path);
    return error_set(e, ERROR_INPUT, where, "[kiosk] image_memory = %d MB%s: the scenes' textures and sky faces take "
                     "%.0f MB decoded, kept for the whole run (the largest, %s, is %lux%lu); make them smaller or "
                     "raise image_memory", c->kiosk.image_memory, line > 0 ? "" : " (the default)", mb, largest, w, h);
}
