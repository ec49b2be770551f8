/* Shared helpers of the "hard cases" tests (tests/unit/test_hard_*.c): the same scene through the
 * GPU renderer on EGL (default path: fp32+MRT on llvmpipe) and through the double-precision CPU
 * reference. Every tests/unit/test_*.c is its own binary linked only with the library, so all of
 * this is static inline. Include after <cmocka.h>. */
#ifndef BT_TEST_HARD_CASES_H
#define BT_TEST_HARD_CASES_H
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl/context.h"
#include "results/compare.h"
#include "results/dump.h"
#include "ref/engine_cpu.h"
#include "ref/reference.h"
#include "ref/straight.h"
#include "render/frame.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "fixture.h"

/* Critical impact parameter of Schwarzschild photon orbits, in units of M. */
#define HC_B_CRIT (3.0 * 1.7320508075688772)

/* One EGL context per test binary, made on first use and never destroyed (the process ends). */
static inline struct gl_context *hc_context(void)
{
    static struct gl_context *ctx;
    if (!ctx) {
        struct error err;
        ctx = gl_context_create("egl", &err);
        if (!ctx)
            fail_msg("EGL context: %s", err.message);
    }
    return ctx;
}

/* A committed scene at a small size, with optional "section.key=value" overrides. */
static inline void hc_load(struct scene *s, const char *name, int width, int height, const char *const *sets)
{
    fixture_load_scene(s, name, width, height, sets);
}

static inline void hc_validate(const struct scene *s)
{
    struct error err;
    if (scene_validate(s, &err) != 0)
        fail_msg("%s: %s", err.where, err.message);
}

/* Camera at p looking along the unit direction dir (a 1x1 image's only ray is exactly dir). */
static inline void hc_aim(struct scene *s, vec3d p, vec3d dir)
{
    s->camera.position = p;
    s->camera.look_at = v3_add(p, dir);
    s->camera.up = fabs(dir.y) < 0.9 ? v3(0.0, 1.0, 0.0) : v3(1.0, 0.0, 0.0);
}

/* Append an object with plain material (no texture) to s; the caller sets its geometry. */
static inline struct object *hc_add_object(struct scene *s, enum primitive_type type, const char *name)
{
    assert_true(s->n_objects < SCENE_MAX_OBJECTS);
    struct object *o = &s->objects[s->n_objects++];
    scene_object_defaults(o, name);
    o->type = type;
    return o;
}

/* Every position of the scene moved by t (camera, look_at, model centre, bound, lights, objects);
 * directions, sizes and the lights' colours unchanged: the same picture, far from the origin. */
static inline void hc_translate(struct scene *s, vec3d t)
{
    s->camera.position = v3_add(s->camera.position, t);
    s->camera.look_at = v3_add(s->camera.look_at, t);
    s->model.center = v3_add(s->model.center, t);
    s->render.bound_center = v3_add(s->render.bound_center, t);
    for (int i = 0; i < s->n_lights; i++)
        s->lights[i].position = v3_add(s->lights[i].position, t);
    for (int i = 0; i < s->n_objects; i++) {
        struct object *o = &s->objects[i];
        o->center = v3_add(o->center, t);
        for (int v = 0; v < 3; v++)
            o->vertex[v] = v3_add(o->vertex[v], t);
    }
}

struct hc_gpu {
    struct render_result res;  /* with the ray state */
    struct dump dump;
    char path[16];             /* render path name, "fp32+mrt" by default on llvmpipe */
};

/* Per-segment hook for hc_gpu_render_hook (NULL for none). */
static inline void hc_gpu_render_hook(const struct scene *s, struct hc_gpu *g, segment_hook hook, void *arg)
{
    struct error gl_err, e;
    struct renderer *r = renderer_create(hc_context(), s, &gl_err);
    if (!r)
        fail_msg("renderer: %s", gl_err.message);
    renderer_set_reads(r, RENDER_READ_STATE);
    if (renderer_run(r, s, 0, 0, s->render.width, s->render.height, hook, arg, &e) != 0 ||
        renderer_read(r, &g->res, RENDER_READ_STATE, &e) != 0)
        fail_msg("render: %s", e.message);
    snprintf(g->path, sizeof g->path, "%s", renderer_path(r)->name);
    char engine[32];
    snprintf(engine, sizeof engine, "gpu %s", g->path);
    assert_int_equal(result_to_dump(&g->res, s, engine, &g->dump), 0);
    renderer_destroy(r);
}

static inline void hc_gpu_render(const struct scene *s, struct hc_gpu *g)
{
    hc_gpu_render_hook(s, g, NULL, NULL);
}

/* The frame as `bentray render` draws it (render_frame: its samples, the CPU's stars, the bloom),
 * read with `reads`, on the default back-end. */
static inline void hc_frame(const struct scene *s, enum render_read reads, struct render_result *res)
{
    struct frame_info info;
    struct error e;
    if (render_frame(s, &(struct frame_request){"auto", reads, PROGRESS_NONE, 0}, res, &info, &e) != 0)
        fail_msg("render: %s", e.message);
}

static inline void hc_gpu_free(struct hc_gpu *g)
{
    render_result_free(&g->res);
    dump_free(&g->dump);
}

/* Non-finite floats anywhere in the ray state read back (position, velocity, hit, image). */
static inline long hc_gpu_nonfinite(const struct hc_gpu *g)
{
    long n = 0;
    size_t count = (size_t)g->res.width * g->res.height * 4;
    const float *arrays[4] = {g->res.position, g->res.velocity, g->res.hit, g->res.image};
    for (int a = 0; a < 4; a++)
        for (size_t i = 0; i < count; i++)
            n += !isfinite(arrays[a][i]);
    return n;
}

/* Final GPU state of pixel i (image order, top row first) in double. */
static inline vec3d hc_gpu_x(const struct hc_gpu *g, int i)
{
    const float *p = g->res.position + 4 * i;
    return v3(p[0], p[1], p[2]);
}
static inline vec3d hc_gpu_v(const struct hc_gpu *g, int i)
{
    const float *p = g->res.velocity + 4 * i;
    return v3(p[0], p[1], p[2]);
}

/* The whole image on the CPU reference (default options: rtol 1e-10, atol 1e-10 * bound radius). */
static inline void hc_cpu_render(const struct scene *s, struct cpu_image *img)
{
    struct cpu_render_options o = {.threads = 0, .progress = 0};
    struct error e;
    ref_options_default(&o.ref, s);
    if (cpu_render(s, &o, img, &e) != 0)
        fail_msg("cpu render: %s", e.message);
}

/* s at width x height, validated, on both engines. */
static inline void hc_render_both(struct scene *s, int width, int height, struct cpu_image *cpu, struct hc_gpu *g)
{
    s->render.width = width;
    s->render.height = height;
    hc_validate(s);
    hc_cpu_render(s, cpu);
    hc_gpu_render(s, g);
}

/* The ray from the camera in viewing direction dir (unit), as cpu_render traces a pixel. */
static inline void hc_cpu_ray(const struct scene *s, vec3d dir, struct ref_ray *ray)
{
    struct ref_options o;
    ref_options_default(&o, s);
    vec3d x0 = s->camera.position;
    ref_trace(s, &o, x0, model_initial_velocity(&s->model, x0, dir), ray, 0.0, NULL, NULL);
}

/* Records with a non-finite float among hit, position or direction. */
static inline long hc_dump_nonfinite(const struct dump *d)
{
    long n = 0;
    for (long i = 0; i < (long)d->width * d->height; i++) {
        const struct dump_record *r = &d->records[i];
        for (int k = 0; k < 3; k++)
            n += !isfinite(r->hit[k]) || !isfinite(r->position[k]) || !isfinite(r->direction[k]);
        n += !isfinite(r->depth);
    }
    return n;
}

static inline long hc_count_outcome(const struct dump *d, int32_t outcome)
{
    long n = 0;
    for (long i = 0; i < (long)d->width * d->height; i++)
        n += d->records[i].outcome == outcome;
    return n;
}

static inline double hc_dist3f(const float *a, const float *b)
{
    double dx = (double)a[0] - b[0], dy = (double)a[1] - b[1], dz = (double)a[2] - b[2];
    return sqrt(dx * dx + dy * dy + dz * dz);
}

static inline void hc_compare(const struct dump *a, const struct dump *b, struct compare_result *r)
{
    struct error e;
    if (compare_dumps(a, b, r, &e) != 0)
        fail_msg("compare: %s", e.message);
}

/* Unit normal of object o at a point p on it (as the shaders compute it). */
static inline vec3d hc_object_normal(const struct object *o, vec3d p)
{
    switch (o->type) {
    case PRIM_SPHERE: return v3_normalize(v3_sub(p, o->center));
    case PRIM_RECT: return v3_normalize(v3_cross(o->axis_u, o->axis_v));
    case PRIM_DISK: return v3_normalize(o->normal);
    default: break;
    }
    return v3_normalize(v3_cross(v3_sub(o->vertex[1], o->vertex[0]), v3_sub(o->vertex[2], o->vertex[0])));
}

/* Distance from x to the next float away from zero: the resolution of a float coordinate of size |x|. */
static inline double hc_ulp(double x)
{
    float f = (float)fabs(x);
    return (double)nextafterf(f, INFINITY) - (double)f;
}

#endif
