/* Stage 3, ray-object intersection with local illumination (paper sections 3.3 and 3.4): the
 * objects in batches of render.batch per pass, in scene order (batch 1 is the paper's crossbar).
 * A batch holds only the primitive types it contains; its program is cached by that list. */
#include "physics/relativity.h"
#include "render/stages.h"
#include "scene/texture_wrap.h"
#include "scene/object_bound.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

#define GEOMETRY_VECS 5
#define MATERIAL_VECS 5         /* stages.h: intersect_pack_material */
#define MOTION_VECS 2
#define CHORD_VECS 3            /* the integrated single pass's cull: ball, plane, scales */
#define ORBIT_CULL_VECS 4       /* the orbit frame's: ball, plane, the ball about the mass, across */
/* how much larger than an object the orbit frame's cull takes its ball: of its distance from the
 * mass and its radius (cull_group_meets in shaders_es/stage_intersect.glsl) */
#define ORBIT_CULL_MARGIN 1e-4
/* shaders_es/stage_intersect.glsl's CHORD_CULL_POSITION_MARGIN */
#define CHORD_CULL_POSITION_MARGIN 1e-5
/* uniform vectors a pass needs besides its objects: lights, ambient, segment, sizes, camera, observer
 * and black-body table (rounded up) */
#define RESERVED_UNIFORM_VECS (20 + 3 * SCENE_MAX_LIGHTS)
/* ... and the orbit table's (orbit_table.glsl), where hits are found again on the orbit */
#define ORBIT_UNIFORM_VECS 16
/* ... and the single pass's, for the integration (model, step control, bounds, rounded up) */
#define FRAME_UNIFORM_VECS 16
/* texture units 0-3 (0-4) carry the ray state, the black-body table UNIT_BLACKBODY; object textures
 * start above it */
#define FIRST_OBJECT_UNIT(r) (UNIT_BLACKBODY(r) + 1)

static const char *const prim_files[PRIM_COUNT] = {"prim_sphere.glsl", "prim_triangle.glsl", "prim_disk.glsl",
                                                   "prim_rect.glsl"};
static const char *const prim_defines[PRIM_COUNT] = {"SPHERE", "TRIANGLE", "DISK", "RECT"};


static void pack3(float *out, vec3d v, double w)
{
    out[0] = (float)v.x;
    out[1] = (float)v.y;
    out[2] = (float)v.z;
    out[3] = (float)w;
}

/* The geometry vectors of one object, as shaders_es/stage_intersect.glsl reads them. */
static void pack_geometry(const struct object *o, float g[GEOMETRY_VECS][4])
{
    memset(g, 0, sizeof(float) * GEOMETRY_VECS * 4);
    switch (o->type) {
    case PRIM_SPHERE: {
        vec3d pole = v3_normalize(o->pole);
        pack3(g[0], o->center, o->radius);
        pack3(g[1], v3_perpendicular(pole), 0.0);
        pack3(g[2], pole, 0.0);
        break;
    }
    case PRIM_TRIANGLE:
        for (int k = 0; k < 3; k++)
            pack3(g[k], o->vertex[k], 0.0);
        g[3][0] = (float)o->uv[0][0], g[3][1] = (float)o->uv[0][1];
        g[3][2] = (float)o->uv[1][0], g[3][3] = (float)o->uv[1][1];
        g[4][0] = (float)o->uv[2][0], g[4][1] = (float)o->uv[2][1];
        break;
    case PRIM_DISK: {
        vec3d n = v3_normalize(o->normal);
        pack3(g[0], o->center, o->radius);
        pack3(g[1], n, o->inner_radius);
        pack3(g[2], v3_perpendicular(n), 0.0);
        break;
    }
    case PRIM_RECT:
        pack3(g[0], o->center, 0.0);
        pack3(g[1], o->axis_u, 0.0);
        pack3(g[2], o->axis_v, 0.0);
        break;
    default:
        break;
    }
}

/* The ball and plane of one object for the single passes' culls (chord_near and cull_group_meets
 * in shaders_es/stage_intersect.glsl, which say what they bound): computed once a frame here, in
 * double, rather than in every pixel. The shader reads none of them for an object that moves: its
 * slot is near every chord. */
static void chord_cull_pack(const struct object *o, float ball[4], float plane[4], float scale[2])
{
    struct object_bound bound;
    object_bound(o, &bound);
    vec3d c = bound.centre;
    pack3(ball, c, bound.radius);
    pack3(plane, bound.normal, bound.flat ? 1.0 : 0.0);
    scale[0] = (float)(1.0 / fmax(bound.radius, 1e-30));
    scale[1] = (float)(CHORD_CULL_POSITION_MARGIN * (fabs(c.x) + fabs(c.y) + fabs(c.z)));
}

/* The same ball about the mass for the orbit frame's cull (cull_group_meets): its centre less the
 * mass's (c), its radius with ORBIT_CULL_MARGIN, and c x e1 and e1 . c, where e1 is the unit vector
 * from the mass to the camera (every ray's orbit plane holds it): with a ray's own e2 they give the
 * disc the ball cuts from that plane, two dot products a test. */
static void orbit_cull_pack(const struct scene *s, const struct object *o, float ball[4], float across[4])
{
    struct object_bound bound;
    object_bound(o, &bound);
    vec3d c = v3_sub(bound.centre, s->model.center);
    vec3d e1 = v3_normalize(v3_sub(s->camera.position, s->model.center));
    double radius = bound.radius + ORBIT_CULL_MARGIN * (v3_len(c) + bound.radius);
    pack3(ball, c, radius);
    pack3(across, v3_cross(c, e1), v3_dot(e1, c));
}

void intersect_pack_material(const struct renderer *r, const struct object *o, int object_id,
                             float out[MATERIAL_VECS][4])
{
    const struct material *m = &o->material;
    /* the size of the object's texture along each coordinate that goes round, 0 along one that
     * does not (scene/texture_wrap.h; texture_wrapped in shade.glsl) */
    int wraps[2];
    texture_wraps(o->type, wraps);
    pack3(out[0], m->color, m->checker);
    pack3(out[1], m->emission, object_id);
    out[2][0] = (float)m->ambient, out[2][1] = (float)m->diffuse;
    out[2][2] = (float)m->specular, out[2][3] = (float)m->shininess;
    pack3(out[3], m->checker_color, m->clock_period);
    out[4][0] = (float)m->temperature;
    out[4][1] = m->accretion ? (float)o->inner_radius : 0.0f;    /* shade.glsl: an accretion disk's inner edge */
    for (int k = 0; k < 2; k++)
        out[4][2 + k] = m->texture >= 0 && wraps[k] ? (float)r->texture_size[m->texture][k] : 0.0f;
}

/* beta, gamma and the rest frame's origin (shaders_es/stage_intersect.glsl); gamma 1 at rest */
static int pack_motion(const struct object *o, float out[MOTION_VECS][4])
{
    struct object_motion m = {{0.0, 0.0, 0.0}, 1.0, {0.0, 0.0, 0.0}};
    int moving = object_motion(o, &m);
    pack3(out[0], m.beta, m.gamma);
    pack3(out[1], m.origin, 0.0);
    return moving;
}

static int batch_moves(const struct object_batch *b)
{
    struct object_motion m;
    for (int i = 0; i < b->count; i++)
        if (object_motion(&b->r->scene->objects[b->object[i]], &m))
            return 1;
    return 0;
}

static int batch_accretes(const struct object_batch *b)
{
    int accretes = 0;
    for (int i = 0; i < b->count; i++)
        accretes |= b->r->scene->objects[b->object[i]].material.accretion;
    return accretes;
}

static int batch_clocks(const struct object_batch *b)
{
    int clocks = 0;
    for (int i = 0; i < b->count; i++)
        clocks |= b->r->scene->objects[b->object[i]].material.clock_period > 0.0;
    return clocks;
}

void object_batch_set_uniforms(const struct program_uniforms *p, const void *arg)
{
    const struct object_batch *b = arg;
    const struct scene *s = b->r->scene;
    float geometry[OBJECT_BATCH_MAX][GEOMETRY_VECS][4], material[OBJECT_BATCH_MAX][MATERIAL_VECS][4];
    float motion[OBJECT_BATCH_MAX][MOTION_VECS][4];
    GLint units[OBJECT_BATCH_MAX];
    int unit = FIRST_OBJECT_UNIT(b->r);
    for (int i = 0; i < b->count; i++) {
        const struct object *o = &s->objects[b->object[i]];
        struct object rest;
        object_rest_geometry(o, &rest);
        pack_geometry(&rest, geometry[i]);
        pack_motion(o, motion[i]);
        intersect_pack_material(b->r, o, b->object[i], material[i]);
        units[i] = FIRST_OBJECT_UNIT(b->r);
        if (o->material.texture >= 0) {
            glActiveTexture(GL_TEXTURE0 + unit);
            glBindTexture(GL_TEXTURE_2D, b->r->textures[o->material.texture]);
            units[i] = unit++;
        }
    }
    glUniform4fv(program_uniform(p, "u_geometry"), GEOMETRY_VECS * b->count, &geometry[0][0][0]);
    glUniform4fv(program_uniform(p, "u_materials"), MATERIAL_VECS * b->count, &material[0][0][0]);
    if (batch_moves(b)) {
        glUniform4fv(program_uniform(p, "u_motion"), MOTION_VECS * b->count, &motion[0][0][0]);
    }
    /* the single passes' culls (CHORD_CULL, and the orbit frame's groups): only the programs that
     * read them (GL ignores a location of -1) */
    GLint balls = program_uniform(p, "u_object_ball");
    if (balls >= 0) {
        float ball[OBJECT_BATCH_MAX][4], plane[OBJECT_BATCH_MAX][4], chord_scale[OBJECT_BATCH_MAX][2];
        for (int i = 0; i < b->count; i++)
            chord_cull_pack(&s->objects[b->object[i]], ball[i], plane[i], chord_scale[i]);
        glUniform4fv(balls, b->count, &ball[0][0]);
        glUniform4fv(program_uniform(p, "u_object_plane"), b->count, &plane[0][0]);
        glUniform2fv(program_uniform(p, "u_chord_scale"), b->count, &chord_scale[0][0]);
    }
    GLint cull_balls = program_uniform(p, "u_cull_ball");
    if (cull_balls >= 0) {
        float ball[OBJECT_BATCH_MAX][4], across[OBJECT_BATCH_MAX][4];
        for (int i = 0; i < b->count; i++)
            orbit_cull_pack(s, &s->objects[b->object[i]], ball[i], across[i]);
        glUniform4fv(cull_balls, b->count, &ball[0][0]);
        glUniform4fv(program_uniform(p, "u_cull_across"), b->count, &across[0][0]);
    }
    GLint textures = program_uniform(p, "u_textures");
    if (textures >= 0)
        glUniform1iv(textures, b->count, units);
    uniform_float(p, "u_segment_index", b->segment);
    uniform_vec3(p, "u_ambient_light", s->ambient_light);
    if (b->r->exact_orbits)       /* hits found again on the orbit */
        orbit_set_uniforms(p, b->r, b->segment);
    /* the camera and the time: for the Doppler colours, moving objects and clocks only */
    if (doppler_colour(s) || batch_moves(b) || batch_clocks(b))
        observer_set_uniforms(p, b->r);
    for (int i = 0; i < s->n_lights; i++) {
        char name[48];
        snprintf(name, sizeof name, "u_light_position[%d]", i);
        uniform_vec3(p, name, s->lights[i].position);
        snprintf(name, sizeof name, "u_light_color[%d]", i);
        uniform_vec3(p, name, s->lights[i].color);
        snprintf(name, sizeof name, "u_light_temperature[%d]", i);
        uniform_float(p, name, s->lights[i].temperature);
    }
}

/* Variant defines of a batch: its size, its primitive list in order, its textured slots. */
int object_batch_defines(const struct object_batch *b, char *out, size_t len)
{
    const struct scene *s = b->r->scene;
    int has[PRIM_COUNT] = {0}, textured = 0, moving[OBJECT_BATCH_MAX] = {0};
    size_t used = (size_t)snprintf(out, len, "#define BATCH_SIZE %d\n#define LIGHT_COUNT %d\n#define BATCH_TESTS",
                                   b->count, s->n_lights);
    struct object_motion m;
    for (int i = 0; i < b->count && used < len; i++) {
        const struct object *o = &s->objects[b->object[i]];
        has[o->type] = 1;
        textured |= o->material.texture >= 0;
        moving[i] = object_motion(o, &m);
        if (moving[i])
            used += (size_t)snprintf(out + used, len - used, " MOVING_TEST(%d, TEST_%s(%d))", i,
                                     prim_defines[o->type], i);
        else
            used += (size_t)snprintf(out + used, len - used, " TEST_%s(%d)", prim_defines[o->type], i);
    }
    if (batch_moves(b) && used < len)
        used += (size_t)snprintf(out + used, len - used, "\n#define MOVING_OBJECTS 1");
    if (batch_clocks(b) && used < len)
        used += (size_t)snprintf(out + used, len - used, "\n#define CLOCKS 1");
    if (batch_accretes(b) && used < len)
        used += (size_t)snprintf(out + used, len - used, "\n#define ACCRETION 1");
    if (textured && used < len) {
        used += (size_t)snprintf(out + used, len - used, "\n#define TEXTURED 1\n#define BATCH_TEXTURES");
        for (int i = 0; i < b->count && used < len; i++)
            if (s->objects[b->object[i]].material.texture >= 0)
                used += (size_t)snprintf(out + used, len - used, " SAMPLE_TEXTURE(%d)", i);
    }
    /* each kind of primitive's slots, and the moving ones: the lists candidate_surface selects the
     * shaded object's geometry and motion from (SELECT_SLOT, SELECT_MOVING in stage_intersect.glsl) */
    for (int t = 0; t < PRIM_COUNT && used < len; t++) {
        if (!has[t])
            continue;
        used += (size_t)snprintf(out + used, len - used, "\n#define HAS_PRIM_%s 1\n#define BATCH_SLOTS_%s",
                                 prim_defines[t], prim_defines[t]);
        for (int i = 0; i < b->count && used < len; i++)
            if (s->objects[b->object[i]].type == (enum primitive_type)t)
                used += (size_t)snprintf(out + used, len - used, " SELECT_SLOT(%d)", i);
    }
    if (batch_moves(b) && used < len) {
        used += (size_t)snprintf(out + used, len - used, "\n#define BATCH_SLOTS_MOVING");
        for (int i = 0; i < b->count && used < len; i++)
            if (moving[i])
                used += (size_t)snprintf(out + used, len - used, " SELECT_MOVING(%d)", i);
    }
    if (b->r->exact_orbits && used < len) {
        /* the orbit walk's culls, object by object (stage_intersect.glsl): each object's wedge about
         * the mass from its bounding ball (WEDGE_OF_<PRIMITIVE>), and whether a group of chords can
         * meet it (GROUP_MEETS), a flat object's plane included */
        used += (size_t)snprintf(out + used, len - used, "\n#define ORBIT_HITS 1\n#define BATCH_WEDGES");
        for (int i = 0; i < b->count && used < len; i++)
            used += (size_t)snprintf(out + used, len - used, " WEDGE_OF_%s(%d)",
                                     prim_defines[s->objects[b->object[i]].type], i);
        used += used < len ? (size_t)snprintf(out + used, len - used, "\n#define BATCH_GROUP_CULLS") : 0;
        for (int i = 0; i < b->count && used < len; i++) {
            struct object_bound bound;
            object_bound(&s->objects[b->object[i]], &bound);
            used += (size_t)snprintf(out + used, len - used, " GROUP_MEETS(%d, %s)", i, bound.flat ? "true" : "false");
        }
    }
    if (used < len)
        used += (size_t)snprintf(out + used, len - used, "\n%s", b->r->observer_defines);
    if (used + 2 >= len)
        return -1;
    strcat(out, "\n");
    return 0;
}

/* Texture units left for object textures: above the ray state and the black-body table, below the
 * orbit table (the last unit) when rays follow exact orbits. */
static int object_texture_units(const struct renderer *r)
{
    return r->caps.max_texture_units - FIRST_OBJECT_UNIT(r) - (r->exact_orbits ? 1 : 0);
}

int object_batch_files(const struct object_batch *b, const char **files, int n)
{
    int seen[PRIM_COUNT] = {0};
    for (int i = 0; i < b->count; i++) {
        enum primitive_type t = b->r->scene->objects[b->object[i]].type;
        if (!seen[t]++)
            files[n++] = prim_files[t];
    }
    return n;
}

int object_batch_all(const struct renderer *r, struct object_batch *b)
{
    const struct scene *s = r->scene;
    memset(b, 0, sizeof *b);
    b->r = r;
    int textured = 0;
    if (s->n_objects > frame_object_limit(r))
        return -1;
    for (int i = 0; i < s->n_objects; i++) {
        if (polygons_draw_object(r, i))
            return -1;
        textured += s->objects[i].material.texture >= 0;
        b->object[b->count++] = i;
    }
    return textured <= object_texture_units(r) ? 0 : -1;
}

/* Objects one pass can hold on this GPU, whatever render.batch asks: its fragment uniform vectors
 * after the pass's own (the single pass adds the integration's: model, step control, bounds). */
static int pass_capacity(const struct renderer *r, int single_pass)
{
    int per_object = GEOMETRY_VECS + MATERIAL_VECS + (scene_has_moving_objects(r->scene) ? MOTION_VECS : 0) +
                     (single_pass ? (r->exact_orbits ? ORBIT_CULL_VECS : CHORD_VECS) : 0);
    int reserved = RESERVED_UNIFORM_VECS + (r->exact_orbits ? ORBIT_UNIFORM_VECS : 0) +
                   (single_pass ? FRAME_UNIFORM_VECS + far_step_uniform_vecs(r) : 0);
    int by_uniforms = (r->caps.max_fragment_uniform_vectors - reserved) / per_object;
    int most = single_pass ? OBJECT_BATCH_MAX : SCENE_MAX_BATCH;
    int limit = by_uniforms < most ? by_uniforms : most;
    return limit < 1 ? 1 : limit;
}

int intersect_batch_limit(const struct renderer *r)
{
    int capacity = pass_capacity(r, 0);
    return r->scene->render.batch < capacity ? r->scene->render.batch : capacity;
}

int frame_object_limit(const struct renderer *r)
{
    return pass_capacity(r, 1);
}

int hit_shading_separate(const struct renderer *r)
{
    switch (r->scene->render.hit_shading) {
    case HIT_SHADING_SEPARATE: return 1;
    case HIT_SHADING_INLINE: return 0;
    default: return !r->path.mrt && r->path.fp32 && !r->caps.cpu_rasterizer;
    }
}

/* The batch's program: the stage in one pass (step NULL), or one of its passes when the hit is
 * shaded in a pass of its own (step "HIT_CHORD", "HIT_ORBIT", "HIT_ENDS" or "HIT_SHADE"). */
static const struct stage_program *batch_program(struct renderer *r, const struct object_batch *b, const char *step,
                                                 struct error *e)
{
    char defines[BATCH_DEFINES_LEN + 32];
    int used = step ? snprintf(defines, sizeof defines, "#define %s 1\n", step) : 0;
    if (object_batch_defines(b, defines + used, sizeof defines - (size_t)used) != 0) {
        error_set(e, ERROR_RUNTIME, NULL, "internal: the defines of an object batch do not fit");
        return NULL;
    }
    const char *files[PRIM_COUNT + 9] = {"common.glsl"};
    int n = object_batch_files(b, files, 1);
    files[n++] = "observer.glsl";
    if (r->exact_orbits) {
        files[n++] = "bounds.glsl";
        files[n++] = "model_schwarzschild.glsl";
        files[n++] = "orbit_table.glsl";
    }
    files[n++] = "shade.glsl";
    files[n++] = "stage_intersect.glsl";
    files[n] = NULL;
    int one_target = step && (strcmp(step, "HIT_CHORD") == 0 || strcmp(step, "HIT_ORBIT") == 0);
    return program_cache_get(r->programs, files, defines, !one_target, e);
}

/* The hit of one batch shaded in a pass of its own (hit_shading_separate): the closest hit on the
 * segment's chord found first (HIT_CHORD); on exact orbits found again on the orbit (HIT_ORBIT), and
 * the short chord that carries it written (HIT_ENDS); then shaded (HIT_SHADE), each pass a program
 * of its own (shaders_es/stage_intersect.glsl). */
static int intersect_batch_separate(struct renderer *r, const struct object_batch *b, int segment_start,
                                    struct error *e)
{
    struct raystate *rs = &r->rs;
    if (!r->path.fp32)
        return error_set(e, ERROR_INPUT, NULL, "render.hit_shading = separate: the hit found would be kept between "
                         "passes in 16-bit floats (render path %s), which round it; use render.hit_shading = inline "
                         "or auto", r->path.name);
    const struct pass_input segment[] = {
        {"u_segment_start", rs->position[segment_start]},
        {"u_segment_end", rs->position[rs->cur_position]},
    };
    struct pass_input chord_in[] = {segment[0], segment[1], {"u_hit", rs->hit[rs->cur_hit]}};
    const struct stage_program *sp = batch_program(r, b, "HIT_CHORD", e);
    if (!sp || pass_run(r, sp, rs->hit_found[0], 0, chord_in, 3, object_batch_set_uniforms, b, e) != 0)
        return -1;
    struct pass_input shade_in[] = {
        {"u_hit", rs->hit[rs->cur_hit]},
        {"u_image", rs->image[rs->cur_hit]},
        {"u_hit_found", rs->hit_found[0]},
        {"u_hit_chord_start", segment[0].texture},
        {"u_hit_chord_end", segment[1].texture},
    };
    if (r->exact_orbits) {
        struct pass_input orbit_in[] = {segment[0], segment[1], {"u_hit_found", rs->hit_found[0]}};
        sp = batch_program(r, b, "HIT_ORBIT", e);
        if (!sp || pass_run(r, sp, rs->hit_found[1], 0, orbit_in, 3, object_batch_set_uniforms, b, e) != 0)
            return -1;
        struct pass_input ends_in[] = {segment[0], segment[1], {"u_hit_found", rs->hit_found[1]}};
        sp = batch_program(r, b, "HIT_ENDS", e);
        if (!sp || pass_run(r, sp, rs->hit_chord[0], rs->hit_chord[1], ends_in, 3, object_batch_set_uniforms, b,
                            e) != 0)
            return -1;
        shade_in[2].texture = rs->hit_found[1];
        shade_in[3].texture = rs->hit_chord[0];
        shade_in[4].texture = rs->hit_chord[1];
    }
    sp = batch_program(r, b, "HIT_SHADE", e);
    int out = 1 - rs->cur_hit;
    if (!sp || pass_run(r, sp, rs->hit[out], rs->image[out], shade_in, 5, object_batch_set_uniforms, b, e) != 0)
        return -1;
    rs->cur_hit = out;
    return 0;
}

/* The paper's intersection stage for one batch: the closest hit of its objects on each ray's
 * segment, shaded, in one pass (or in passes of their own, above). */
static int intersect_batch(struct renderer *r, const struct object_batch *b, int segment_start, struct error *e)
{
    if (hit_shading_separate(r))
        return intersect_batch_separate(r, b, segment_start, e);
    struct raystate *rs = &r->rs;
    const struct stage_program *sp = batch_program(r, b, NULL, e);
    if (!sp)
        return -1;
    int out = 1 - rs->cur_hit;
    struct pass_input in[] = {
        {"u_segment_start", rs->position[segment_start]},
        {"u_segment_end", rs->position[rs->cur_position]},
        {"u_hit", rs->hit[rs->cur_hit]},
        {"u_image", rs->image[rs->cur_hit]},
    };
    if (pass_run(r, sp, rs->hit[out], rs->image[out], in, 4, object_batch_set_uniforms, b, e) != 0)
        return -1;
    rs->cur_hit = out;
    return 0;
}

int stage_intersect_all(struct renderer *r, int segment, int segment_start, struct error *e)
{
    const struct scene *s = r->scene;
    int limit = intersect_batch_limit(r);
    int max_textured = object_texture_units(r);
    int next = 0;
    while (next < s->n_objects) {
        struct object_batch b = {.r = r, .count = 0, .segment = segment};
        int textured = 0;
        for (; next < s->n_objects && b.count < limit; next++) {
            if (polygons_draw_object(r, next))
                continue;          /* drawn as transformed triangles after the rays (stage_polygons.c) */
            int needs = s->objects[next].material.texture >= 0;
            if (textured + needs > max_textured && b.count > 0)
                break;
            textured += needs;
            b.object[b.count++] = next;
        }
        if (b.count > 0 && intersect_batch(r, &b, segment_start, e) != 0)
            return -1;
    }
    return gl_check("ray-object intersection", e);
}
