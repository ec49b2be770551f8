/* The files a scene is read from, so that no command writes over one of them. */
#include "scene/scene.h"
#include "io/output_file.h"
#include <stdio.h>

int scene_input_named(const struct scene *s, const char *path, char *which, size_t len)
{
    if (!path || !*path || (path[0] == '-' && path[1] == '\0'))
        return 0;
    if (s->path[0] && output_same(path, s->path)) {
        snprintf(which, len, "the scene file %s", s->path);
        return 1;
    }
    for (int i = 0; i < s->n_textures; i++)
        if (output_same(path, s->textures[i])) {
            snprintf(which, len, "the scene's texture %s", s->textures[i]);
            return 1;
        }
    const char *catalogues[] = {s->sky.catalogue, s->sky.catalogue_colours};
    for (int i = 0; i < 2; i++)
        if (catalogues[i][0] && output_same(path, catalogues[i])) {
            snprintf(which, len, "the sky's star catalogue %s", catalogues[i]);
            return 1;
        }
    if (s->sky.type == SKY_CUBEMAP)
        for (int f = 0; f < SCENE_CUBEMAP_FACES; f++) {
            char face[SCENE_PATH_LEN + 8];
            scene_cubemap_face_path(s->sky.cubemap, f, face, sizeof face);
            if (output_same(path, face)) {
                snprintf(which, len, "the sky's cube face %s", face);
                return 1;
            }
        }
    return 0;
}
