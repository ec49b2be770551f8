/* The benchmark's scenes: the committed scenes with the paper's settings applied. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "bench/bench.h"
#include "io/tree_file.h"
#include "scene/scene_keys.h"

const char *const bench_accel_names[ACCEL_COUNT] = {"none", "paper", "all", "single", "fused"};

void bench_apply_accel(struct scene *s, enum bench_accel a)
{
    struct render_settings *r = &s->render;
    /* none: the paper's original scheme (section 3): one step per pass, one object per pass */
    r->steps_per_pass = 1;
    r->batch = 1;
    r->early_z = 0;
    r->step_control = STEP_FIXED;
    /* the fixed steps' path: the adaptive configurations get the same budget */
    double path = render_path_budget(r);
    r->termination_interval = 1;
    r->pipeline = PIPELINE_MULTIPASS;
    if (a == ACCEL_NONE)
        return;
    /* paper (section 4): early ray termination and step doubling. The tolerance is a hundredth
     * of the fixed step's length: Euler's local error at that step is about h^2 |f'| / 2, so the
     * step grows where the rays are straight and shrinks where they bend. */
    r->early_z = 1;
    r->step_control = STEP_DOUBLING;
    r->tolerance = 1e-2 * r->step_size;
    r->max_path = path;
    if (a == ACCEL_PAPER)
        return;
    /* all: and the whole segment in one pass, every object in one pass */
    r->steps_per_pass = r->steps_per_segment <= SCENE_MAX_STEPS_PER_PASS ? r->steps_per_segment : 1;
    r->batch = SCENE_MAX_BATCH;
    if (a == ACCEL_ALL)
        return;
    /* single: the same settings, the whole ray in one pass (early-z and batches do not apply);
     * fused: one pass a segment (integrate, intersect, terminate), retired as the multipass scheme */
    r->pipeline = a == ACCEL_FUSED ? PIPELINE_FUSED : PIPELINE_SINGLE;
}

int bench_with_scene(struct bench *b, bench_scene_section section, struct error *e)
{
    struct scene *s = scene_new(e);
    if (!s)
        return -1;
    int rc = section(b, s, e);
    scene_free(s);
    return rc;
}

int bench_load_scene(struct scene *s, const char *name, int w, int h, struct error *e)
{
    char rel[256], path[4096];
    snprintf(rel, sizeof rel, "assets/scenes/%s.scene", name);
    /* the project's scenes wherever the bench runs from; where none is found, the error names rel */
    if (tree_file_find(rel, path, sizeof path) != 0)
        snprintf(path, sizeof path, "%s", rel);
    if (scene_load(s, path, e) != 0)
        return -1;
    if (w > 0 && h > 0) {
        s->render.width = w;
        s->render.height = h;
    }
    return 0;
}

void bench_spheres(struct scene *s, int n)
{
    vec3d view = v3_sub(s->camera.look_at, s->camera.position);
    double d = v3_len(view);
    vec3d forward = v3_scale(view, 1.0 / d);
    vec3d right = v3_normalize(v3_cross(forward, s->camera.up));
    vec3d up = v3_cross(right, forward);
    s->n_objects = 0;
    for (int i = 0; i < n && i < SCENE_MAX_OBJECTS; i++) {
        struct object *o = &s->objects[s->n_objects++];
        char name[32];
        snprintf(name, sizeof name, "sphere%d", i);
        scene_object_defaults(o, name);
        o->type = PRIM_SPHERE;
        /* a ring of spheres a third of the view distance around look_at, alternately nearer */
        double angle = 2.0 * 3.14159265358979 * i / (n > 0 ? n : 1);
        double ring = 0.3 * d, depth = (i % 2 ? 0.15 : -0.15) * d;
        o->center = v3_add(s->camera.look_at, v3_add(v3_scale(right, ring * cos(angle)),
                                                     v3_add(v3_scale(up, ring * sin(angle)),
                                                            v3_scale(forward, depth))));
        o->radius = 0.07 * d;
        o->material.color = v3(0.3 + 0.7 * (i % 3 == 0), 0.3 + 0.7 * (i % 3 == 1), 0.3 + 0.7 * (i % 3 == 2));
    }
}

void bench_paper_steps(struct scene *s, int n_segs, int n_steps, double path)
{
    struct render_settings *r = &s->render;
    r->segments = n_segs;
    r->max_path = 0.0;
    r->steps_per_segment = n_steps / n_segs;
    r->step_size = path / n_steps;
    r->method = METHOD_EULER;     /* the paper's integrator (section 3.2) */
}
