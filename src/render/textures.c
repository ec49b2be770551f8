/* Scene textures and the sky cube map, uploaded once per renderer. */
#include "io/image_cache.h"
#include "render/stages.h"
#include <stdio.h>
#include <stdlib.h>

/* A texture that cannot be decoded is the scene's bad input: the message names the scene file and
 * the line of the key that named it (the validation read only the PNG's header). */
static int upload(GLenum target, const struct scene *s, const char *key, int line, const char *path, int max_size,
                  int size[2], struct error *e)
{
    int w, h, owned = 0;
    const unsigned char *rgba = NULL;
    struct error fe;
    if (image_read(path, max_size, &w, &h, &rgba, &owned, &fe) != 0) {
        if (line > 0)
            return error_set(e, ERROR_INPUT, NULL, "%s:%d: %s: %s", s->path, line, key, fe.message);
        return error_set(e, ERROR_INPUT, NULL, "%s: %s: %s", s->path, key, fe.message);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(target, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    size[0] = w;
    size[1] = h;
    if (owned)
        free((void *)rgba);
    return 0;
}

int textures_load(struct renderer *r, struct error *e)
{
    const struct scene *s = r->scene;
    int max_size = r->caps.max_texture_size < SCENE_MAX_TEXTURE_SIZE ? r->caps.max_texture_size : SCENE_MAX_TEXTURE_SIZE;
    for (int i = 0; i < s->n_textures; i++) {
        glGenTextures(1, &r->textures[i]);
        glBindTexture(GL_TEXTURE_2D, r->textures[i]);
        /* ES2 allows GL_REPEAT only for power-of-two sizes; texture coordinates stay in [0,1] */
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        if (upload(GL_TEXTURE_2D, s, "texture", s->texture_line[i], s->textures[i], max_size, r->texture_size[i],
                   e) != 0)
            return -1;
    }
    if (s->sky.type == SKY_CUBEMAP) {
        glGenTextures(1, &r->sky_cubemap);
        glBindTexture(GL_TEXTURE_CUBE_MAP, r->sky_cubemap);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        for (int f = 0; f < SCENE_CUBEMAP_FACES; f++) {
            char path[SCENE_PATH_LEN + 16];
            scene_cubemap_face_path(s->sky.cubemap, f, path, sizeof path);
            int face_size[2];
            if (upload(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, s, "cubemap", s->cubemap_line, path, max_size, face_size,
                       e) != 0)
                return -1;
        }
    }
    return gl_check("uploading textures", e);
}

void textures_release(struct renderer *r)
{
    for (int i = 0; i < r->scene->n_textures; i++)
        if (r->textures[i])
            glDeleteTextures(1, &r->textures[i]);
    if (r->sky_cubemap)
        glDeleteTextures(1, &r->sky_cubemap);
}
