/* Stage 2 without integration, for Schwarzschild (render.method = orbit_table): each segment is a
 * chord between exact points of the ray's orbit, read from the orbit table (physics/orbit_table.h)
 * that the CPU builds in double precision for the scene's mass and the camera's radius, and
 * builds again when either changes (the kiosk's mass knob, a moving camera), or takes from the
 * tables built ahead (render/orbit_store.h). */
#include "render/stages.h"
#include "scene/object_bound.h"
#include "gl/packing.h"
#include "gl/texture.h"
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Escaping orbits are tabulated this fraction beyond the farthest point of the bounding sphere. */
#define ORBIT_FAR_MARGIN 1e-3
/* An exit point is put this fraction outside the bounding sphere, 16 float roundings. */
#define ORBIT_OUTSIDE_MARGIN 1e-6

/* A lower bound of the distance from c to the object's points (0 when it may reach c): the
 * distance to its bounding ball, and for the flat primitives to their plane. */
static double object_distance(const struct object *o, vec3d c)
{
    struct object_bound b;
    object_bound(o, &b);
    double d = v3_len(v3_sub(b.centre, c)) - b.radius;
    if (b.flat && v3_len(b.normal) > 0.0)
        d = fmax(d, fabs(v3_dot(b.normal, v3_sub(c, b.centre))));
    return d;
}

/* The mass and the camera's radius as the table takes them: rounded to ORBIT_TABLE_BITS significant
 * bits (a relative step of 2^-40, 1e-12, far below a float texel's rounding). A camera turned about
 * the centre changes its radius in the last bits only, and so does a knob's value reached by another
 * sequence of detents (0.12 + 0.01 + 0.01 against 0.12 + 2 x 0.01): each finds the table it already
 * has, or one built ahead, and a fresh render of the same view builds the same one. Only a value
 * within a few roundings of a step's middle (about one in a thousand) falls on either side. */
#define ORBIT_TABLE_BITS 40
static double table_value(double x)
{
    int exponent;
    double m = frexp(x, &exponent);
    return ldexp(nearbyint(ldexp(m, ORBIT_TABLE_BITS)), exponent - ORBIT_TABLE_BITS);
}

void orbit_table_params_for(const struct scene *s, struct orbit_table_params *p)
{
    const struct render_settings *r = &s->render;
    memset(p, 0, sizeof *p);
    p->mass = table_value(s->model.mass);
    p->r_observer = table_value(v3_len(v3_sub(s->camera.position, s->model.center)));
    p->r_far = (v3_len(v3_sub(r->bound_center, s->model.center)) + r->bound_radius) * (1.0 + ORBIT_FAR_MARGIN);
    p->rows_per_side = r->orbit_rows;
    p->columns = r->orbit_columns;
    /* a ray that can meet nothing needs no chords but its end: one segment */
    p->chord_tolerance = s->n_objects > 0 ? r->chord_tolerance : INFINITY;
    p->max_segments = r->max_chords;
    p->clear_radius = INFINITY;
    for (int i = 0; i < s->n_objects; i++)
        p->clear_radius = fmin(p->clear_radius, object_distance(&s->objects[i], s->model.center));
    if (!(p->clear_radius > 0.0))
        p->clear_radius = 0.0;
}

static void swap_tables(struct renderer *r)
{
    struct orbit_table t = r->orbit;
    GLuint texture = r->orbit_texture;
    r->orbit = r->orbit_spare;
    r->orbit_texture = r->orbit_spare_texture;
    r->orbit_spare = t;
    r->orbit_spare_texture = texture;
}

static void release_table(struct orbit_table *t, GLuint *texture)
{
    if (*texture)
        glDeleteTextures(1, texture);
    *texture = 0;
    orbit_table_free(t);
}

/* The table on the packed path: each texel's four floats in a 2x2 block of RGBA8 texels, their bytes
 * high first, as the ray state is packed (shaders_es/common.glsl, orbit_table.glsl). */
static int upload_packed(struct renderer *r, const struct orbit_table *t, struct error *e)
{
    int w = 2 * t->width, h = 2 * t->height;
    unsigned char *bytes = malloc((size_t)4 * w * h);
    if (!bytes)
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory packing the orbit table");
    packed_from_floats(t->texels, t->width, t->height, bytes);
    r->orbit_texture = texture_create_nearest(GL_RGBA, GL_RGBA, GL_UNSIGNED_BYTE, w, h);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, bytes);
    free(bytes);
    return 0;
}

/* The renderer keeps two tables on the GPU: the kiosk's coarse preview table and its refined
 * frame's, which alternate while the knobs rest, are each uploaded once. Any other comes from the
 * store: built ahead where the kiosk asked for it (renderer_orbit_prefetch), else built now. */
int orbit_prepare(struct renderer *r, struct error *e)
{
    struct orbit_table_params p;
    orbit_table_params_for(r->scene, &p);
    if (r->orbit_texture && orbit_params_same(&p, &r->orbit.p))
        return 0;
    swap_tables(r);
    if (r->orbit_texture && orbit_params_same(&p, &r->orbit.p))
        return 0;
    release_table(&r->orbit, &r->orbit_texture);
    if (!r->orbit_store && !(r->orbit_store = orbit_store_create(ORBIT_STORE_BUDGET, e)))
        return -1;
    const struct orbit_table *t = orbit_store_get(r->orbit_store, &p, e);
    if (!t)
        return -1;
    int twice = r->path.packed ? 2 : 1;
    if (twice * t->width > r->caps.max_texture_size || twice * t->height > r->caps.max_texture_size)
        return error_set(e, ERROR_INPUT, NULL, "the orbit table (%dx%d%s) exceeds this GPU's texture limit %d: lower "
                         "render.orbit_rows or render.orbit_columns", twice * t->width, twice * t->height,
                         r->path.packed ? ", packed" : "", r->caps.max_texture_size);
    if (r->path.packed) {
        if (upload_packed(r, t, e) != 0)
            return -1;
    } else {
        const struct float_format *f = r->path.table_format;
        r->orbit_texture = texture_create_nearest(f->internal_format, f->format, GL_FLOAT, t->width, t->height);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, t->width, t->height, f->format, GL_FLOAT, t->texels);
    }
    r->orbit = *t;
    r->orbit.texels = NULL;
    return gl_check("uploading the orbit table", e);
}

int renderer_orbit_prefetch(struct renderer *r, const struct orbit_table_params *p, int n, struct error *e)
{
    if (!r->orbit_store && !(r->orbit_store = orbit_store_create(ORBIT_STORE_BUDGET, e)))
        return -1;
    orbit_store_prefetch(r->orbit_store, p, n);
    return 0;
}

struct orbit_store *renderer_orbit_ahead(const struct scene *s)
{
    if (!scene_on_exact_orbits(s))
        return NULL;
    struct error ignored;
    struct orbit_store *store = orbit_store_create(ORBIT_STORE_BUDGET, &ignored);
    if (store) {
        struct orbit_table_params p;
        orbit_table_params_for(s, &p);
        orbit_store_prefetch(store, &p, 1);
    }
    return store;
}

void renderer_orbit_store_give(struct renderer *r, struct orbit_store *store)
{
    if (!store)
        return;
    if (r->orbit_store)
        orbit_store_destroy(store);
    else
        r->orbit_store = store;
}

int renderer_orbit_pending(const struct renderer *r)
{
    return r->orbit_store ? orbit_store_pending(r->orbit_store) : 0;
}

int renderer_orbit_tables_built(const struct renderer *r)
{
    return r->orbit_store ? orbit_store_caller_builds(r->orbit_store) : 0;
}

double renderer_orbit_build_seconds(const struct renderer *r)
{
    return r->orbit_store ? orbit_store_caller_seconds(r->orbit_store) : 0.0;
}

void orbit_release(struct renderer *r)
{
    release_table(&r->orbit, &r->orbit_texture);
    release_table(&r->orbit_spare, &r->orbit_spare_texture);
    orbit_store_destroy(r->orbit_store);
    r->orbit_store = NULL;
}

struct orbit_args {
    const struct renderer *r;
    int segment;
};

static void set_orbit(const struct program_uniforms *p, const void *arg)
{
    const struct orbit_args *a = arg;
    orbit_set_uniforms(p, a->r, a->segment);
}

/* Below this cosine between the view direction and the radial axis the axis is not seen in the
 * image plane ahead (or too far out of it): chi is taken about the image centre instead. */
#define ORBIT_AXIS_SEEN_COSINE 0.1

/* The uniforms by which orbit_table.glsl measures each pixel's angle chi from the radial axis
 * (see there), in double here. */
static void set_orbit_axis(const struct program_uniforms *p, const struct renderer *r)
{
    const struct scene *s = r->scene;
    const struct orbit_table *t = &r->orbit;
    vec3d e1 = v3_normalize(v3_sub(s->camera.position, s->model.center));
    vec3d axis = t->critical_inward ? v3_scale(e1, -1.0) : e1;
    double chi_c = t->critical_from_axis;
    uniform_vec3(p, "u_orbit_axis", axis);
    glUniform2f(program_uniform(p, "u_orbit_critical_chi"), (float)chi_c, (float)(chi_c - (float)chi_c));
    uniform_float(p, "u_orbit_axis_sign", t->critical_inward ? 1.0 : -1.0);
    if (observer_moving(s))
        return;
    /* the camera basis of observer.glsl: direction F + x R + y U at ndc (x, y) */
    vec3d f = v3_normalize(v3_sub(s->camera.look_at, s->camera.position));
    vec3d right = v3_normalize(v3_cross(f, s->camera.up));
    vec3d up = v3_cross(right, f);
    double tan_half = tan(s->camera.fov_deg * PI_D / 360.0);
    double w = s->render.width, h = s->render.height;
    vec3d rx = v3_scale(right, tan_half * w / h), uy = v3_scale(up, tan_half);
    double alpha = v3_dot(axis, f), x0 = 0.0, y0 = 0.0;
    if (alpha > ORBIT_AXIS_SEEN_COSINE) {
        x0 = v3_dot(axis, rx) / (alpha * v3_dot(rx, rx));
        y0 = v3_dot(axis, uy) / (alpha * v3_dot(uy, uy));
    }
    vec3d w0 = v3_add(f, v3_add(v3_scale(rx, x0), v3_scale(uy, y0)));
    vec3d across0 = v3_sub(w0, v3_scale(axis, v3_dot(w0, axis)));
    if (alpha > ORBIT_AXIS_SEEN_COSINE)
        across0 = v3(0.0, 0.0, 0.0);    /* exactly: the axis is seen there */
    double px = (x0 + 1.0) * 0.5 * w, py = (y0 + 1.0) * 0.5 * h;
    glUniform2f(program_uniform(p, "u_orbit_axis_pixel_hi"), (float)px, (float)py);
    glUniform2f(program_uniform(p, "u_orbit_axis_pixel_lo"), (float)(px - (float)px), (float)(py - (float)py));
    glUniform2f(program_uniform(p, "u_orbit_pixel_scale"), (float)(2.0 / w), (float)(2.0 / h));
    uniform_vec3(p, "u_orbit_across0", across0);
    uniform_vec3(p, "u_orbit_across_x", v3_sub(rx, v3_scale(axis, v3_dot(rx, axis))));
    uniform_vec3(p, "u_orbit_across_y", v3_sub(uy, v3_scale(axis, v3_dot(uy, axis))));
    uniform_vec3(p, "u_orbit_along", v3(v3_dot(w0, axis), v3_dot(rx, axis), v3_dot(uy, axis)));
}

void orbit_set_uniforms(const struct program_uniforms *p, const struct renderer *r, int segment)
{
    const struct scene *s = r->scene;
    const struct orbit_table *t = &r->orbit;
    observer_set_uniforms(p, r);
    model_set_uniforms(p, &s->model);
    bounds_set_uniforms(p, s);
    uniform_float(p, "u_bound_outside", s->render.bound_radius * (1.0 + ORBIT_OUTSIDE_MARGIN));
    uniform_float(p, "u_segment_index", segment);
    glActiveTexture(GL_TEXTURE0 + UNIT_ORBIT(r));
    glBindTexture(GL_TEXTURE_2D, r->orbit_texture);
    glUniform1i(program_uniform(p, "u_orbit_table"), UNIT_ORBIT(r));
    int twice = r->path.packed ? 2 : 1;
    glUniform2f(program_uniform(p, "u_orbit_texel"), 1.0f / (float)(twice * t->width), 1.0f / (float)(twice * t->height));
    uniform_float(p, "u_orbit_rows", t->p.rows_per_side);
    uniform_float(p, "u_orbit_columns", t->p.columns);
    uniform_float(p, "u_orbit_warps", ORBIT_WARP_SAMPLES);
    set_orbit_axis(p, r);
    glUniform2f(program_uniform(p, "u_orbit_span"), (float)t->log_span[0], (float)t->log_span[1]);
    glUniform2f(program_uniform(p, "u_orbit_epsilon"), (float)t->epsilon[0], (float)t->epsilon[1]);
    uniform_float(p, "u_orbit_even_scale", ORBIT_EVEN_SCALE);
}

int stage_orbit(struct renderer *r, int segment, int segment_start, struct error *e)
{
    const char *const files[] = {"common.glsl", "bounds.glsl", "model_schwarzschild.glsl", "observer.glsl",
                                 "orbit_table.glsl", "stage_orbit.glsl", NULL};
    char defines[sizeof r->model_defines + sizeof r->observer_defines];
    snprintf(defines, sizeof defines, "%s%s", r->model_defines, r->observer_defines);
    const struct stage_program *sp = program_cache_get(r->programs, files, defines, 1, e);
    if (!sp)
        return -1;
    struct orbit_args a = {r, segment};
    if (pass_move_rays(r, sp, segment_start, set_orbit, &a, e) != 0)
        return -1;
    return gl_check("orbit segments", e);
}
