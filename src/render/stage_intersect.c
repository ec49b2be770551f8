/* Stage 3, ray-object intersection with local illumination (paper sections 3.3 and 3.4):
 * one pass per object against the current segment of every ray (the paper's crossbar). */
#include "render/stages.h"
#include <stdio.h>

static const char *const prim_files[PRIM_COUNT] = {"prim_sphere.glsl", "prim_triangle.glsl", "prim_disk.glsl",
                                                   "prim_rect.glsl"};
static const char *const prim_defines[PRIM_COUNT] = {"PRIM_SPHERE", "PRIM_TRIANGLE", "PRIM_DISK", "PRIM_RECT"};

struct intersect_args {
    const struct renderer *r;
    const struct object *object;
    int object_id, segment;
};

static void set_object(GLuint p, const void *arg)
{
    const struct intersect_args *a = arg;
    const struct object *o = a->object;
    const struct material *m = &o->material;
    const struct scene *s = a->r->scene;
    uniform_float(p, "u_segment_index", a->segment);
    uniform_float(p, "u_object_id", a->object_id);
    uniform_vec3(p, "u_center", o->center);
    uniform_float(p, "u_radius", o->radius);
    uniform_float(p, "u_inner_radius", o->inner_radius);
    switch (o->type) {
    case PRIM_SPHERE: {
        vec3d pole = v3_normalize(o->pole);
        uniform_vec3(p, "u_axis_u", v3_perpendicular(pole));
        uniform_vec3(p, "u_axis_v", pole);
        break;
    }
    case PRIM_DISK: {
        vec3d n = v3_normalize(o->normal);
        uniform_vec3(p, "u_normal", n);
        uniform_vec3(p, "u_axis_u", v3_perpendicular(n));
        break;
    }
    case PRIM_RECT:
        uniform_vec3(p, "u_axis_u", o->axis_u);
        uniform_vec3(p, "u_axis_v", o->axis_v);
        break;
    case PRIM_TRIANGLE:
        uniform_vec3(p, "u_vertex0", o->vertex[0]);
        uniform_vec3(p, "u_vertex1", o->vertex[1]);
        uniform_vec3(p, "u_vertex2", o->vertex[2]);
        glUniform2f(glGetUniformLocation(p, "u_uv0"), (float)o->uv[0][0], (float)o->uv[0][1]);
        glUniform2f(glGetUniformLocation(p, "u_uv1"), (float)o->uv[1][0], (float)o->uv[1][1]);
        glUniform2f(glGetUniformLocation(p, "u_uv2"), (float)o->uv[2][0], (float)o->uv[2][1]);
        break;
    default:
        break;
    }
    uniform_vec3(p, "u_color", m->color);
    uniform_vec3(p, "u_emission", m->emission);
    glUniform4f(glGetUniformLocation(p, "u_material"), (float)m->ambient, (float)m->diffuse, (float)m->specular,
                (float)m->shininess);
    uniform_float(p, "u_checker", m->checker);
    uniform_vec3(p, "u_checker_color", m->checker_color);
    uniform_vec3(p, "u_ambient_light", s->ambient_light);
    for (int i = 0; i < s->n_lights; i++) {
        char name[48];
        snprintf(name, sizeof name, "u_light_position[%d]", i);
        uniform_vec3(p, name, s->lights[i].position);
        snprintf(name, sizeof name, "u_light_color[%d]", i);
        uniform_vec3(p, name, s->lights[i].color);
    }
    if (m->texture >= 0) {
        glActiveTexture(GL_TEXTURE0 + UNIT_OBJECT_TEXTURE);
        glBindTexture(GL_TEXTURE_2D, a->r->textures[m->texture]);
        glUniform1i(glGetUniformLocation(p, "u_texture"), UNIT_OBJECT_TEXTURE);
    }
}

int stage_intersect(struct renderer *r, int object, int segment, int segment_start, char *err, size_t errlen)
{
    const struct object *o = &r->scene->objects[object];
    struct raystate *rs = &r->rs;
    char defines[160];
    snprintf(defines, sizeof defines, "#define %s 1\n#define LIGHT_COUNT %d\n%s", prim_defines[o->type],
             r->scene->n_lights, o->material.texture >= 0 ? "#define TEXTURED 1\n" : "");
    const char *const files[] = {"common.glsl", prim_files[o->type], "shade.glsl", "stage_intersect.glsl", NULL};
    const struct stage_program *sp = program_cache_get(&r->programs, files, defines, 1, err, errlen);
    if (!sp)
        return -1;
    struct intersect_args a = {r, o, object, segment};
    int out = 1 - rs->cur_hit;
    struct pass_input in[] = {
        {"u_segment_start", rs->position[segment_start]},
        {"u_segment_end", rs->position[rs->cur_position]},
        {"u_hit", rs->hit[rs->cur_hit]},
        {"u_image", rs->image[rs->cur_hit]},
    };
    if (pass_run(r, sp, rs->hit[out], rs->image[out], in, 4, set_object, &a, err, errlen) != 0)
        return -1;
    rs->cur_hit = out;
    return 0;
}
