/* Scene textures and the sky cube map, uploaded once per renderer. */
#include "io/image_cache.h"
#include "gl/texture.h"
#include "render/stages.h"
#include "results/star_light.h"
#include "results/tone.h"
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
    glTexImage2D(target, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    size[0] = w;
    size[1] = h;
    if (owned)
        free((void *)rgba);
    return 0;
}

/* The GPU's star pass (render.star_pass = gpu, or auto where the rays' state cannot be read back): the star map of the sky's catalogue, one texture
 * (results/star_map.h), read with NEAREST from texel centres. */
static int star_map_load(struct renderer *r, struct error *e)
{
    const struct scene *s = r->scene;
    int gpu = s->render.star_pass == STAR_PASS_GPU || (s->render.star_pass == STAR_PASS_AUTO && r->path.image_only);
    if (!gpu || !star_sky_wanted(s))
        return 0;
    int cells = STAR_MAP_CELLS;
    while (cells > STAR_CHROMA_TEXELS / (2 * STAR_MAP_SLOTS) && 2 * STAR_MAP_SLOTS * cells > r->caps.max_texture_size)
        cells /= 2;
    /* a GPU without derivatives takes the footprints from the neighbouring rays (stage_sky.glsl) */
    if (!r->caps.fragment_fp32 || 2 * STAR_MAP_SLOTS * cells > r->caps.max_texture_size)
        return error_set(e, ERROR_RUNTIME, NULL, "render.star_pass = gpu: this GPU %s (bentray render draws the "
                         "stars with render.star_pass = cpu; the kiosk draws them on the GPU only: give the scene a "
                         "cube-map sky there)", !r->caps.fragment_fp32 ? "computes its fragment shaders in less "
                         "than 32-bit floats" : "holds no texture large enough for the star map");
    struct star_sky *sky = malloc(sizeof *sky);
    if (!sky)
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory for the stars of the sky");
    if (star_sky_init(sky, s, e) != 0) {
        free(sky);
        return -1;
    }
    int rc = star_map_build(&r->star_layout, &sky->catalogue, cells);
    r->galactic_pole = sky->catalogue.pole;
    r->galactic_x = sky->catalogue.x_axis;
    r->galactic_y = sky->catalogue.y_axis;
    star_sky_free(sky);
    free(sky);
    if (rc != 0)
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory for the star map");
    r->star_map = texture_name_nearest();   /* bound, clamped at its edges */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, r->star_layout.width, r->star_layout.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 r->star_layout.texels);
    star_map_free(&r->star_layout);
    return gl_check("uploading the star map", e);
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
    if (gl_check("uploading textures", e) != 0)
        return -1;
    return star_map_load(r, e);
}

void textures_release(struct renderer *r)
{
    if (r->star_map)
        glDeleteTextures(1, &r->star_map);
    for (int i = 0; i < r->scene->n_textures; i++)
        if (r->textures[i])
            glDeleteTextures(1, &r->textures[i]);
    if (r->sky_cubemap)
        glDeleteTextures(1, &r->sky_cubemap);
}
