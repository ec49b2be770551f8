/* The polygon method for moving objects (Müller, Grottel and Weiskopf 2010, section 3.2), for
 * comparison with tracing them per pixel: with render.moving_objects = polygons the intersection
 * stage leaves the moving objects out, and this stage rasterises their tessellated surfaces with
 * every vertex moved to where it is seen (shaders_es/polygon_vertex.glsl) into the retired results,
 * before the sky stage. Objects at rest stay traced; a closer traced hit hides a polygon. */
#include "gl/quad.h"
#include "physics/relativity.h"
#include "render/polygon_mesh.h"
#include "render/stages.h"
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

/* texture unit of a polygon object's texture: the one above the black-body table's */
#define UNIT_POLYGON_TEXTURE(r) (UNIT_BLACKBODY(r) + 1)

int polygons_draw_object(const struct renderer *r, int k)
{
    struct object_motion m;
    return r->scene->render.moving_objects == MOVING_POLYGONS && object_motion(&r->scene->objects[k], &m);
}

int polygons_load(struct renderer *r, struct error *e)
{
    const struct scene *s = r->scene;
    for (int k = 0; k < s->n_objects; k++) {
        if (!polygons_draw_object(r, k))
            continue;
        struct object rest;
        struct polygon_mesh mesh;
        object_rest_geometry(&s->objects[k], &rest);
        if (polygon_mesh_build(&rest, s->render.polygon_subdivision, &mesh) != 0) {
            return error_set(e, ERROR_RUNTIME, NULL, "out of memory for the mesh of [object %s]", s->objects[k].name);
        }
        glGenBuffers(2, r->mesh_buffers[k]);
        glBindBuffer(GL_ARRAY_BUFFER, r->mesh_buffers[k][0]);
        glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(sizeof *mesh.vertices * (size_t)mesh.n_vertices), mesh.vertices,
                     GL_STATIC_DRAW);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, r->mesh_buffers[k][1]);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(sizeof *mesh.indices * (size_t)mesh.n_indices),
                     mesh.indices, GL_STATIC_DRAW);
        r->mesh_indices[k] = mesh.n_indices;
        polygon_mesh_free(&mesh);
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    quad_bind();
    return gl_check("uploading the moving objects' meshes", e);
}

void polygons_release(struct renderer *r)
{
    for (int k = 0; k < SCENE_MAX_OBJECTS; k++)
        if (r->mesh_buffers[k][0])
            glDeleteBuffers(2, r->mesh_buffers[k]);
    memset(r->mesh_buffers, 0, sizeof r->mesh_buffers);
}

static int polygons_present(const struct renderer *r)
{
    for (int k = 0; k < r->scene->n_objects; k++)
        if (polygons_draw_object(r, k))
            return 1;
    return 0;
}

static void attribute(GLuint p, const char *name, int size, size_t offset)
{
    GLint loc = glGetAttribLocation(p, name);
    if (loc < 0)
        return;
    glVertexAttribPointer((GLuint)loc, size, GL_FLOAT, GL_FALSE, sizeof(struct mesh_vertex), (const void *)offset);
    glEnableVertexAttribArray((GLuint)loc);
}

static void draw_object(struct renderer *r, const struct program_uniforms *p, int k)
{
    const struct scene *s = r->scene;
    const struct object *o = &s->objects[k];
    struct object_motion m;
    object_motion(o, &m);
    float material[5][4];
    intersect_pack_material(r, o, k, material);
    glUniform4fv(program_uniform(p, "u_material"), 5, &material[0][0]);
    uniform_float(p, "u_object_id", k);
    glUniform4f(program_uniform(p, "u_body_motion"), (float)m.beta.x, (float)m.beta.y, (float)m.beta.z,
                (float)m.gamma);
    uniform_vec3(p, "u_body_origin", m.origin);
    /* Eq. 5: the observation event in the rest frame */
    uniform_vec3(p, "u_observer_rest", rest_position(&m, s->observer.time, s->camera.position));
    uniform_float(p, "u_observer_rest_time", proper_time(&m, s->observer.time, s->camera.position));
    if (o->material.texture >= 0) {
        glActiveTexture(GL_TEXTURE0 + UNIT_POLYGON_TEXTURE(r));
        glBindTexture(GL_TEXTURE_2D, r->textures[o->material.texture]);
        glUniform1i(program_uniform(p, "u_texture"), UNIT_POLYGON_TEXTURE(r));
    }
    glBindBuffer(GL_ARRAY_BUFFER, r->mesh_buffers[k][0]);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, r->mesh_buffers[k][1]);
    attribute(p->id, "a_rest_position", 3, offsetof(struct mesh_vertex, rest));
    attribute(p->id, "a_rest_normal", 3, offsetof(struct mesh_vertex, normal));
    attribute(p->id, "a_uv", 2, offsetof(struct mesh_vertex, uv));
    double first = pass_draw_begin(r, p->id);
    glDrawElements(GL_TRIANGLES, r->mesh_indices[k], GL_UNSIGNED_SHORT, 0);
    pass_draw_end(r, first);
    r->passes++;
}

/* One object's program: its variant (textured, clock) on top of the observer's. */
static const struct stage_program *object_program(struct renderer *r, const struct object *o, struct error *e)
{
    static const char *const vertex[] = {"polygon_vertex.glsl", NULL};
    char defines[512];
    snprintf(defines, sizeof defines, "#define LIGHT_COUNT %d\n#define MOVING_OBJECTS 1\n%s%s%s", r->scene->n_lights,
             o->material.texture >= 0 ? "#define TEXTURED 1\n" : "",
             o->material.clock_period > 0.0 ? "#define CLOCKS 1\n" : "", r->observer_defines);
    const char *const files[] = {"common.glsl", "observer.glsl", "shade.glsl", "polygon_fragment.glsl", NULL};
    return program_cache_get_vertex(r->programs, vertex, files, defines, 1, e);
}

int stage_polygons(struct renderer *r, struct error *e)
{
    if (!polygons_present(r))
        return 0;
    const struct scene *s = r->scene;
    struct raystate *rs = &r->rs;
    /* one depth buffer (distance from the eye) for the polygons of every moving object */
    GLuint first = raystate_fbo(rs, rs->result_hit, 0, e);
    if (!first)
        return -1;
    glBindFramebuffer(GL_FRAMEBUFFER, first);
    glDepthMask(GL_TRUE);
    glClearDepthf(1.0f);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    for (int k = 0; k < s->n_objects; k++) {
        if (!polygons_draw_object(r, k))
            continue;
        const struct stage_program *sp = object_program(r, &s->objects[k], e);
        if (!sp)
            return -1;
        for (int t = 0; t < sp->n_programs; t++) {
            GLuint out0 = sp->n_programs == 1 || t == 0 ? rs->result_hit : rs->result_image;
            GLuint fbo = raystate_fbo(rs, out0, sp->n_programs == 1 ? rs->result_image : 0, e);
            if (!fbo)
                return -1;
            const struct program_uniforms *p = &sp->program[t];
            glBindFramebuffer(GL_FRAMEBUFFER, fbo);
            glViewport(0, 0, rs->width, rs->height);
            glUseProgram(p->id);
            glUniform2f(program_uniform(p, "u_inv_size"), 1.0f / (float)rs->width, 1.0f / (float)rs->height);
            if (raystate_storage(rs, rs->hit[rs->cur_hit], e) != 0 ||
                raystate_storage(rs, rs->position[rs->cur_position], e) != 0)
                return -1;
            glActiveTexture(GL_TEXTURE0);
            glBindTexture(GL_TEXTURE_2D, rs->hit[rs->cur_hit]);
            glUniform1i(program_uniform(p, "u_hit"), 0);
            glActiveTexture(GL_TEXTURE1);
            glBindTexture(GL_TEXTURE_2D, rs->position[rs->cur_position]);
            glUniform1i(program_uniform(p, "u_segment_end"), 1);
            observer_set_uniforms(p, r);
            uniform_float(p, "u_far", 4.0 * s->render.bound_radius);
            uniform_vec3(p, "u_ambient_light", s->ambient_light);
            for (int i = 0; i < s->n_lights; i++) {
                char name[48];
                snprintf(name, sizeof name, "u_light_position[%d]", i);
                uniform_vec3(p, name, s->lights[i].position);
                snprintf(name, sizeof name, "u_light_color[%d]", i);
                uniform_vec3(p, name, s->lights[i].color);
                snprintf(name, sizeof name, "u_light_temperature[%d]", i);
                uniform_float(p, name, s->lights[i].temperature);
            }
            /* without MRT the second target's pass draws the same triangles at the same depth */
            glDepthFunc(t == 0 ? GL_LESS : GL_LEQUAL);
            draw_object(r, p, k);
        }
    }
    glDepthMask(GL_FALSE);
    glDisable(GL_DEPTH_TEST);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    quad_bind();
    return gl_check("moving objects as polygons", e);
}
