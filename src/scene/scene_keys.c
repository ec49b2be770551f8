/* The table of scene keys and the setters of what a field copy cannot store. A key is described
 * once here (section, name, type, range, the model or primitive types it belongs to, where it is
 * stored) and applied by conf/conf_key.c, so the file loader, --set and the tests cannot disagree
 * about what a scene may say. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "scene/scene_keys.h"
#include "conf/conf_path.h"
#include "io/png_header.h"
#include "io/text_file.h"
#include "physics/bright_stars.h"
#include "physics/star_catalogue.h"

/* ---- names of enumerations, in enum order ------------------------------------------------- */

static const struct conf_choice model_names[] = {{"flat", 0}, {"lorenz", 1}, {"rossler", 2}, {"potential", 3}, {"refraction", 4}, {"schwarzschild", 5}, {"newtonian", 6}, {NULL, 0}};
static const struct conf_choice primitive_names[] = {{"sphere", 0}, {"triangle", 1}, {"disk", 2}, {"rect", 3}, {NULL, 0}};
static const struct conf_choice method_names[] = {{"euler", 0}, {"rk4", 1}, {"dopri5", 2}, {"orbit_table", 3}, {NULL, 0}};
static const struct conf_choice step_control_names[] = {{"fixed", 0}, {"doubling", 1}, {"embedded", 2}, {NULL, 0}};
static const struct conf_choice switch_names[] = {{"off", 0}, {"on", 1}, {NULL, 0}};
static const struct conf_choice precision_names[] = {{"auto", 0}, {"fp32", 1}, {"fp16", 2}, {"packed", 3}, {NULL, 0}};
static const struct conf_choice mrt_names[] = {{"auto", 0}, {"on", 1}, {"off", 2}, {NULL, 0}};
static const struct conf_choice profile_names[] = {{"yukawa", 0}, {"polynomial", 1}, {NULL, 0}};
static const struct conf_choice sky_names[] = {{"color", 0}, {"cubemap", 1}, {NULL, 0}};
static const struct conf_choice effects_names[] = {{"geometry", 0}, {"doppler", 1}, {"searchlight", 2}, {NULL, 0}};
static const struct conf_choice exposure_names[] = {{"scene", 0}, {"paper", 1}, {NULL, 0}};
static const struct conf_choice moving_names[] = {{"rays", 0}, {"polygons", 1}, {NULL, 0}};
static const struct conf_choice pipeline_names[] = {{"auto", 0}, {"multipass", 1}, {"single", 2}, {"fused", 3}, {NULL, 0}};
static const struct conf_choice tone_curve_names[] = {{"clip", 0}, {"filmic", 1}, {NULL, 0}};
static const struct conf_choice star_pass_names[] = {{"cpu", 0}, {"gpu", 1}, {"auto", 2}, {NULL, 0}};
static const struct conf_choice orbit_walk_names[] = {{"auto", 0}, {"separate", 1}, {"inline", 2}, {NULL, 0}};
static const struct conf_choice hit_shading_names[] = {{"auto", 0}, {"separate", 1}, {"inline", 2}, {NULL, 0}};

_Static_assert(sizeof model_names / sizeof model_names[0] == MODEL_COUNT + 1,
               "one name per model type");
_Static_assert(sizeof primitive_names / sizeof primitive_names[0] == PRIM_COUNT + 1,
               "one name per primitive type");

const char *scene_model_type_name(enum model_type type)
{
    return (unsigned)type < MODEL_COUNT ? model_names[type].name : "?";
}

const char *scene_primitive_name(enum primitive_type type)
{
    return (unsigned)type < PRIM_COUNT ? primitive_names[type].name : "?";
}

/* ---- sections ---------------------------------------------------------------------------- */

static const struct {
    const char *name;
    int named;
} sections[SECTION_COUNT] = {
    [SECTION_SCENE] = {"scene", 0},
    [SECTION_CAMERA] = {"camera", 0},
    [SECTION_OBSERVER] = {"observer", 0},
    [SECTION_RENDER] = {"render", 0},
    [SECTION_MODEL] = {"model", 0},
    [SECTION_LIGHTING] = {"lighting", 0},
    [SECTION_LIGHT] = {"light", 1},
    [SECTION_SKY] = {"sky", 0},
    [SECTION_OBJECT] = {"object", 1},
    [SECTION_QUALITY] = {"quality", 0},
    [SECTION_KIOSK] = {"kiosk", 0},
};

const char *scene_section_name(enum scene_section_kind section) { return sections[section].name; }
int scene_section_named(enum scene_section_kind section) { return sections[section].named; }

int scene_section_find(const char *name)
{
    for (int i = 0; i < SECTION_COUNT; i++)
        if (strcmp(sections[i].name, name) == 0)
            return i;
    return -1;
}

const char *scene_section_list(void)
{
    return "scene, camera, observer, render, model, lighting, light NAME, sky, object NAME, quality, kiosk";
}

void scene_section_label(const struct scene *s, enum scene_section_kind section, int instance,
                         char *buf, size_t len)
{
    const char *name = NULL;
    if (section == SECTION_OBJECT)
        name = s->objects[instance].name;
    else if (section == SECTION_LIGHT)
        name = s->lights[instance].name;
    if (name)
        snprintf(buf, len, "[%s %s]", sections[section].name, name);
    else
        snprintf(buf, len, "[%s]", sections[section].name);
}

int scene_instance_name_ok(const char *name)
{
    size_t n = strlen(name);
    if (n == 0 || n >= SCENE_NAME_LEN)
        return 0;
    for (size_t i = 0; i < n; i++) {
        unsigned char c = (unsigned char)name[i];
        if (!isalnum(c) && c != '_' && c != '-')
            return 0;
    }
    return 1;
}

/* ---- files ------------------------------------------------------------------------------- */

int scene_resolve_path(const struct scene *s, const char *rel, char *out, size_t out_len)
{
    return conf_path_join(s->dir, rel, out, out_len);
}

/* A directory opens fine with fopen on Linux, so regular files are asked for explicitly. */
static int check_readable(const char *what, const char *path, struct error *e)
{
    struct stat st;
    FILE *f;
    if (stat(path, &st) != 0) {
        error_set(e, ERROR_INPUT, NULL, "cannot read %s \"%s\": %s (relative paths start at the scene "
                 "file's directory)", what, path, strerror(errno));
        return -1;
    }
    if (!S_ISREG(st.st_mode)) {
        error_set(e, ERROR_INPUT, NULL, "%s \"%s\" is not a regular file", what, path);
        return -1;
    }
    f = fopen(path, "rb");
    if (!f) {
        error_set(e, ERROR_INPUT, NULL, "cannot read %s \"%s\": %s", what, path, strerror(errno));
        return -1;
    }
    fclose(f);
    return 0;
}


/* A PNG (texture or cube face) within SCENE_MAX_TEXTURE_SIZE a side; *declared tells whether the
 * header could be read, and then *w and *h hold its size. */
static int check_image_size(const char *what, const char *path, unsigned long *w, unsigned long *h,
                            int *declared, struct error *e)
{
    *declared = png_declared_size(path, w, h) == 0;
    if (*declared && (*w > SCENE_MAX_TEXTURE_SIZE || *h > SCENE_MAX_TEXTURE_SIZE)) {
        error_set(e, ERROR_INPUT, NULL, "%s \"%s\" is %lux%lu pixels; at most %d pixels a side are allowed", what, path,
                 *w, *h, SCENE_MAX_TEXTURE_SIZE);
        return -1;
    }
    return 0;
}

/* ---- setters for what a field copy cannot do ---------------------------------------------- */

/* The image's pixel count bounds every per-pixel allocation: checked whenever a side changes. */
static int check_pixels(long width, long height, struct error *e)
{
    if (width * height > SCENE_MAX_PIXELS) {
        error_set(e, ERROR_INPUT, NULL, "the image would be %ldx%ld = %ld pixels; at most %ld pixels (width x height) are allowed",
                 width, height, width * height, SCENE_MAX_PIXELS);
        return -1;
    }
    return 0;
}

static int set_width(void *owner, void *t, const union conf_parsed *v, struct error *e)
{
    struct scene *s = owner;
    (void)t;
    if (check_pixels(v->integer, s->render.height, e) != 0)
        return -1;
    s->render.width = v->integer;
    return 0;
}

static int set_height(void *owner, void *t, const union conf_parsed *v, struct error *e)
{
    struct scene *s = owner;
    (void)t;
    if (check_pixels(s->render.width, v->integer, e) != 0)
        return -1;
    s->render.height = v->integer;
    return 0;
}

static int set_method(void *owner, void *t, const union conf_parsed *v, struct error *e)
{
    struct scene *s = owner;
    (void)t, (void)e;
    s->render.method = (enum integration_method)v->integer;
    s->render.method_named = 1;
    return 0;
}

static int set_frame_origin(void *owner, void *t, const union conf_parsed *v, struct error *e)
{
    (void)owner, (void)e;
    struct object *o = t;
    o->frame_origin = v3(v->v[0], v->v[1], v->v[2]);
    o->frame_origin_given = 1;
    return 0;
}

/* Several objects often wear the same image: each file is kept once so it is uploaded once. */
/* [sky] catalogue and catalogue_colours: files of the real sky (physics/bright_stars.h), read when
 * the scene is checked (scene_validate.c) */
static int set_star_file(struct scene *s, const char *what, char field[SCENE_PATH_LEN], const char *value,
                         struct error *e)
{
    char path[SCENE_PATH_LEN];
    if (scene_resolve_path(s, value, path, sizeof path) != 0) {
        error_set(e, ERROR_INPUT, NULL, "the path is longer than %d characters", SCENE_PATH_LEN - 1);
        return -1;
    }
    if (check_readable(what, path, e) != 0)
        return -1;
    /* read once here, so that a malformed line is refused with the scene, before any work; its
     * place (the catalogue's FILE:LINE) goes into the message, the scene's own line around it */
    struct error why;
    int n;
    int is_catalogue = field == s->sky.catalogue;
    if (bright_stars_read(is_catalogue ? path : NULL, is_catalogue ? NULL : path, v3(0.0, 0.0, 1.0), v3(1.0, 0.0, 0.0),
                          NULL, &n, &why) != 0) {
        char message[sizeof why.message];
        error_format(&why, message, sizeof message);
        error_set(e, why.status, NULL, "%s", message);
        return -1;
    }
    if (is_catalogue && n == 0) {
        error_set(e, ERROR_INPUT, NULL, "the star catalogue \"%s\" lists no star", path);
        return -1;
    }
    memcpy(field, path, SCENE_PATH_LEN);
    return 0;
}

static int set_catalogue(void *owner, void *t, const union conf_parsed *v, struct error *e)
{
    struct scene *s = owner;
    (void)t;
    return set_star_file(s, "star catalogue", s->sky.catalogue, v->text, e);
}

static int set_catalogue_colours(void *owner, void *t, const union conf_parsed *v, struct error *e)
{
    struct scene *s = owner;
    (void)t;
    return set_star_file(s, "star colour file", s->sky.catalogue_colours, v->text, e);
}

static int set_texture(void *owner, void *t, const union conf_parsed *v, struct error *e)
{
    struct scene *s = owner;
    struct object *o = t;
    char path[SCENE_PATH_LEN];
    if (scene_resolve_path(s, v->text, path, sizeof path) != 0) {
        error_set(e, ERROR_INPUT, NULL, "the path is longer than %d characters", SCENE_PATH_LEN - 1);
        return -1;
    }
    unsigned long w, h;
    int declared;
    if (check_readable("texture", path, e) != 0 || check_image_size("texture", path, &w, &h, &declared, e) != 0)
        return -1;
    for (int i = 0; i < s->n_textures; i++) {
        if (strcmp(s->textures[i], path) == 0) {
            o->material.texture = i;
            return 0;
        }
    }
    if (s->n_textures >= SCENE_MAX_TEXTURES) {
        error_set(e, ERROR_INPUT, NULL, "too many textures: a scene may use at most %d different files",
                 SCENE_MAX_TEXTURES);
        return -1;
    }
    memcpy(s->textures[s->n_textures], path, sizeof path);
    o->material.texture = s->n_textures++;
    return 0;
}

const char *const scene_cubemap_faces[SCENE_CUBEMAP_FACES] = {"px", "nx", "py", "ny", "pz", "nz"};

void scene_cubemap_face_path(const char *prefix, int face, char *out, size_t len)
{
    snprintf(out, len, "%s_%s.png", prefix, scene_cubemap_faces[face]);
}

static int set_cubemap(void *owner, void *t, const union conf_parsed *v, struct error *e)
{
    struct scene *s = owner;
    const char *const *faces = scene_cubemap_faces;
    char prefix[SCENE_PATH_LEN];
    (void)t;
    /* room for the longest face suffix, so every face path fits where the prefix fits */
    if (scene_resolve_path(s, v->text, prefix, sizeof prefix - sizeof "_px.png" + 1) != 0) {
        error_set(e, ERROR_INPUT, NULL, "the path is longer than %d characters",
                 (int)(SCENE_PATH_LEN - sizeof "_px.png"));
        return -1;
    }
    /* the faces of a cube map are squares of one size: GL refuses a face that is not square, and a
     * cube map whose faces differ is incomplete (it samples black) */
    unsigned long side = 0;
    const char *side_face = NULL;
    for (int i = 0; i < SCENE_CUBEMAP_FACES; i++) {
        char face[SCENE_PATH_LEN + sizeof "_px.png"], what[32];
        unsigned long w, h;
        int declared;
        scene_cubemap_face_path(prefix, i, face, sizeof face);
        snprintf(what, sizeof what, "cubemap face %s", faces[i]);
        if (check_readable(what, face, e) != 0 || check_image_size(what, face, &w, &h, &declared, e) != 0)
            return -1;
        if (!declared)
            continue;
        if (w != h) {
            error_set(e, ERROR_INPUT, NULL, "%s \"%s\" is %lux%lu pixels; cube map faces must be square", what, face, w, h);
            return -1;
        }
        if (side_face && w != side) {
            error_set(e, ERROR_INPUT, NULL, "%s \"%s\" is %lux%lu pixels, face %s %lux%lu; every face must have the same size",
                     what, face, w, h, side_face, side, side);
            return -1;
        }
        if (!side_face) {
            side = w;
            side_face = faces[i];
        }
    }
    memcpy(s->sky.cubemap, prefix, sizeof prefix);
    return 0;
}

/* ---- the table ----------------------------------------------------------------------------- */

#define AT_SCENE(field) offsetof(struct scene, field)
#define AT_OBJECT(field) offsetof(struct object, field)
#define AT_LIGHT(field) offsetof(struct light, field)

#define ANY .lo = -INFINITY, .hi = INFINITY
#define POSITIVE .lo = 0.0, .hi = INFINITY, .flags = CONF_ABOVE_LO
#define NON_NEGATIVE .lo = 0.0, .hi = INFINITY
#define COLOR_RANGE .lo = 0.0, .hi = 1000.0
/* 0 is "not a black body"; hotter than any star's surface is a typo */
#define TEMPERATURE_RANGE .lo = 0.0, .hi = 1e6
#define CHOICE(names, field) .kind = CONF_CHOICE, .choices = names, .offset = field

#define FOR_MODEL(t) (1u << (t))
#define ALL_MODELS_BUT_FLAT (((1u << MODEL_COUNT) - 1u) & ~FOR_MODEL(MODEL_FLAT))
#define FOR_PRIM(t) (1u << (t))

/* In the order of docs/SCENES.md, which documents each entry (a unit test checks every name is there).
 * Entries of one section stay together: --set and the loader search by section and name. */
const struct conf_key scene_keys[] = {
    {SECTION_SCENE, "name", CONF_TEXT, .lo = 1, .hi = SCENE_NAME_LEN - 1, .offset = AT_SCENE(name)},
    {SECTION_SCENE, "description", CONF_TEXT, .lo = 0, .hi = sizeof(((struct scene *)0)->description) - 1,
     .offset = AT_SCENE(description)},

    {SECTION_CAMERA, "position", CONF_VECTOR, ANY, .offset = AT_SCENE(camera.position)},
    {SECTION_CAMERA, "look_at", CONF_VECTOR, ANY, .offset = AT_SCENE(camera.look_at)},
    {SECTION_CAMERA, "up", CONF_VECTOR, ANY, .flags = CONF_NONZERO, .offset = AT_SCENE(camera.up)},
    {SECTION_CAMERA, "fov", CONF_NUMBER, .lo = 0.0, .hi = 180.0, .flags = CONF_ABOVE_LO | CONF_BELOW_HI,
     .offset = AT_SCENE(camera.fov_deg)},

    {SECTION_OBSERVER, "velocity", CONF_VECTOR, ANY, .offset = AT_SCENE(observer.velocity)},
    {SECTION_OBSERVER, "effects", CHOICE(effects_names, AT_SCENE(observer.effects))},
    {SECTION_OBSERVER, "exposure", CHOICE(exposure_names, AT_SCENE(observer.exposure))},
    {SECTION_OBSERVER, "gravitational_shift", CHOICE(switch_names, AT_SCENE(observer.gravitational_shift))},
    {SECTION_OBSERVER, "time", CONF_NUMBER, .lo = -1e9, .hi = 1e9, .offset = AT_SCENE(observer.time)},

    {SECTION_RENDER, "width", CONF_INTEGER, .lo = 1, .hi = SCENE_MAX_SIZE, .set = set_width},
    {SECTION_RENDER, "height", CONF_INTEGER, .lo = 1, .hi = SCENE_MAX_SIZE, .set = set_height},
    {SECTION_RENDER, "method", .kind = CONF_CHOICE, .choices = method_names, .set = set_method},
    {SECTION_RENDER, "step", CONF_NUMBER, .lo = 0.0, .hi = 1e6, .flags = CONF_ABOVE_LO,
     .offset = AT_SCENE(render.step_size)},
    {SECTION_RENDER, "steps_per_segment", CONF_INTEGER, .lo = 1, .hi = SCENE_MAX_STEPS_PER_SEGMENT,
     .offset = AT_SCENE(render.steps_per_segment)},
    {SECTION_RENDER, "segments", CONF_INTEGER, .lo = 0, .hi = SCENE_MAX_SEGMENTS,
     .offset = AT_SCENE(render.segments)},
    {SECTION_RENDER, "far_step", CONF_NUMBER, .lo = 0.0, .hi = 1e6, .offset = AT_SCENE(render.far_step)},
    {SECTION_RENDER, "max_path", CONF_NUMBER, .lo = 0.0, .hi = 1e9, .offset = AT_SCENE(render.max_path)},
    {SECTION_RENDER, "unfinished_color", CONF_COLOR, COLOR_RANGE, .offset = AT_SCENE(render.unfinished_color)},
    {SECTION_RENDER, "steps_per_pass", CONF_INTEGER, .lo = 1, .hi = SCENE_MAX_STEPS_PER_PASS,
     .offset = AT_SCENE(render.steps_per_pass)},
    {SECTION_RENDER, "bound_radius", CONF_NUMBER, POSITIVE, .offset = AT_SCENE(render.bound_radius)},
    {SECTION_RENDER, "bound_center", CONF_VECTOR, ANY, .offset = AT_SCENE(render.bound_center)},
    {SECTION_RENDER, "precision", CHOICE(precision_names, AT_SCENE(render.precision))},
    {SECTION_RENDER, "mrt", CHOICE(mrt_names, AT_SCENE(render.mrt))},
    {SECTION_RENDER, "early_z", CHOICE(switch_names, AT_SCENE(render.early_z))},
    {SECTION_RENDER, "termination_interval", CONF_INTEGER, .lo = 1, .hi = SCENE_MAX_SEGMENTS,
     .offset = AT_SCENE(render.termination_interval)},
    {SECTION_RENDER, "batch", CONF_INTEGER, .lo = 1, .hi = SCENE_MAX_BATCH, .offset = AT_SCENE(render.batch)},
    {SECTION_RENDER, "step_control", CHOICE(step_control_names, AT_SCENE(render.step_control))},
    {SECTION_RENDER, "tolerance", CONF_NUMBER, .lo = 0.0, .hi = 1e6, .flags = CONF_ABOVE_LO,
     .offset = AT_SCENE(render.tolerance)},
    {SECTION_RENDER, "grow_fraction", CONF_NUMBER, .lo = 0.0, .hi = 1.0, .flags = CONF_ABOVE_LO | CONF_BELOW_HI,
     .offset = AT_SCENE(render.grow_fraction)},
    {SECTION_RENDER, "step_min", CONF_NUMBER, .lo = 0.0, .hi = 1e6, .offset = AT_SCENE(render.step_min)},
    {SECTION_RENDER, "step_max", CONF_NUMBER, .lo = 0.0, .hi = 1e6, .offset = AT_SCENE(render.step_max)},
    {SECTION_RENDER, "moving_objects", CHOICE(moving_names, AT_SCENE(render.moving_objects))},
    {SECTION_RENDER, "polygon_subdivision", CONF_INTEGER, .lo = 1, .hi = SCENE_MAX_SUBDIVISION,
     .offset = AT_SCENE(render.polygon_subdivision)},
    {SECTION_RENDER, "chord_tolerance", CONF_NUMBER, .lo = 0.0, .hi = 1e6, .flags = CONF_ABOVE_LO,
     .offset = AT_SCENE(render.chord_tolerance)},
    {SECTION_RENDER, "sky_alpha", CONF_NUMBER, .lo = 0.0, .hi = 1.0, .offset = AT_SCENE(render.sky_alpha)},
    {SECTION_RENDER, "samples", CONF_INTEGER, .lo = 1, .hi = SCENE_MAX_SAMPLES, .offset = AT_SCENE(render.samples)},
    {SECTION_RENDER, "max_chords", CONF_INTEGER, .lo = 1, .hi = SCENE_MAX_CHORDS,
     .offset = AT_SCENE(render.max_chords)},
    {SECTION_RENDER, "orbit_rows", CONF_INTEGER, .lo = 4, .hi = SCENE_MAX_ORBIT_ROWS,
     .offset = AT_SCENE(render.orbit_rows)},
    {SECTION_RENDER, "pipeline", CHOICE(pipeline_names, AT_SCENE(render.pipeline))},
    {SECTION_RENDER, "orbit_walk", CHOICE(orbit_walk_names, AT_SCENE(render.orbit_walk))},
    {SECTION_RENDER, "hit_shading", CHOICE(hit_shading_names, AT_SCENE(render.hit_shading))},
    {SECTION_RENDER, "star_pass", CHOICE(star_pass_names, AT_SCENE(render.star_pass))},
    {SECTION_RENDER, "gain", CONF_NUMBER, .lo = 0.0, .hi = 1e6, .flags = CONF_ABOVE_LO, .offset = AT_SCENE(render.gain)},
    {SECTION_RENDER, "tone_curve", CHOICE(tone_curve_names, AT_SCENE(render.tone_curve))},
    {SECTION_RENDER, "bloom", CONF_NUMBER, .lo = 0.0, .hi = 1.0, .offset = AT_SCENE(render.bloom)},
    {SECTION_RENDER, "bloom_radius", CONF_NUMBER, .lo = 0.0, .hi = 0.25, .flags = CONF_ABOVE_LO,
     .offset = AT_SCENE(render.bloom_radius)},
    {SECTION_RENDER, "orbit_columns", CONF_INTEGER, .lo = 4, .hi = SCENE_MAX_ORBIT_COLUMNS,
     .offset = AT_SCENE(render.orbit_columns)},

    {SECTION_MODEL, "type", CHOICE(model_names, AT_SCENE(model.type))},
    {SECTION_MODEL, "center", CONF_VECTOR, ANY, .applies = ALL_MODELS_BUT_FLAT,
     .offset = AT_SCENE(model.center)},
    {SECTION_MODEL, "sigma", CONF_NUMBER, ANY, .applies = FOR_MODEL(MODEL_LORENZ),
     .offset = AT_SCENE(model.sigma)},
    {SECTION_MODEL, "rho", CONF_NUMBER, ANY, .applies = FOR_MODEL(MODEL_LORENZ),
     .offset = AT_SCENE(model.rho)},
    /* the same name means Lorenz's beta or Roessler's second parameter, as in the papers */
    {SECTION_MODEL, "beta", CONF_NUMBER, ANY, .applies = FOR_MODEL(MODEL_LORENZ),
     .offset = AT_SCENE(model.beta)},
    {SECTION_MODEL, "beta", CONF_NUMBER, ANY, .applies = FOR_MODEL(MODEL_ROSSLER),
     .offset = AT_SCENE(model.ross_b)},
    {SECTION_MODEL, "alpha", CONF_NUMBER, ANY, .applies = FOR_MODEL(MODEL_ROSSLER),
     .offset = AT_SCENE(model.ross_a)},
    {SECTION_MODEL, "gamma", CONF_NUMBER, ANY, .applies = FOR_MODEL(MODEL_ROSSLER),
     .offset = AT_SCENE(model.ross_c)},
    {SECTION_MODEL, "scale", CONF_NUMBER, POSITIVE,
     .applies = FOR_MODEL(MODEL_LORENZ) | FOR_MODEL(MODEL_ROSSLER),
     .offset = AT_SCENE(model.scale)},
    {SECTION_MODEL, "strength", CONF_NUMBER, ANY,
     .applies = FOR_MODEL(MODEL_LORENZ) | FOR_MODEL(MODEL_ROSSLER) | FOR_MODEL(MODEL_POTENTIAL),
     .offset = AT_SCENE(model.strength)},
    {SECTION_MODEL, "profile", CHOICE(profile_names, AT_SCENE(model.profile)), .applies = FOR_MODEL(MODEL_POTENTIAL)},
    {SECTION_MODEL, "zeta", CONF_NUMBER, ANY, .applies = FOR_MODEL(MODEL_POTENTIAL),
     .offset = AT_SCENE(model.zeta)},
    {SECTION_MODEL, "mu", CONF_NUMBER, NON_NEGATIVE, .applies = FOR_MODEL(MODEL_POTENTIAL),
     .offset = AT_SCENE(model.mu)},
    {SECTION_MODEL, "radius", CONF_NUMBER, POSITIVE, .applies = FOR_MODEL(MODEL_POTENTIAL),
     .offset = AT_SCENE(model.radius)},
    {SECTION_MODEL, "amplitude", CONF_NUMBER, ANY, .applies = FOR_MODEL(MODEL_REFRACTION),
     .offset = AT_SCENE(model.amplitude)},
    {SECTION_MODEL, "shell_radius", CONF_NUMBER, NON_NEGATIVE, .applies = FOR_MODEL(MODEL_REFRACTION),
     .offset = AT_SCENE(model.shell_radius)},
    {SECTION_MODEL, "shell_width", CONF_NUMBER, POSITIVE, .applies = FOR_MODEL(MODEL_REFRACTION),
     .offset = AT_SCENE(model.shell_width)},
    {SECTION_MODEL, "noise_amplitude", CONF_NUMBER, ANY, .applies = FOR_MODEL(MODEL_REFRACTION),
     .offset = AT_SCENE(model.noise_amplitude)},
    {SECTION_MODEL, "noise_frequency", CONF_NUMBER, NON_NEGATIVE, .applies = FOR_MODEL(MODEL_REFRACTION),
     .offset = AT_SCENE(model.noise_frequency)},
    {SECTION_MODEL, "mass", CONF_NUMBER, NON_NEGATIVE,
     .applies = FOR_MODEL(MODEL_SCHWARZSCHILD) | FOR_MODEL(MODEL_NEWTONIAN), .offset = AT_SCENE(model.mass)},

    {SECTION_LIGHTING, "ambient", CONF_COLOR, COLOR_RANGE, .offset = AT_SCENE(ambient_light)},

    {SECTION_LIGHT, "position", CONF_VECTOR, ANY, .offset = AT_LIGHT(position)},
    {SECTION_LIGHT, "color", CONF_COLOR, COLOR_RANGE, .offset = AT_LIGHT(color)},
    {SECTION_LIGHT, "temperature", CONF_NUMBER, TEMPERATURE_RANGE, .offset = AT_LIGHT(temperature)},

    {SECTION_SKY, "type", CHOICE(sky_names, AT_SCENE(sky.type))},
    {SECTION_SKY, "color", CONF_COLOR, COLOR_RANGE, .offset = AT_SCENE(sky.color)},
    {SECTION_SKY, "cubemap", CONF_PATH, .set = set_cubemap},
    {SECTION_SKY, "temperature", CONF_NUMBER, TEMPERATURE_RANGE, .offset = AT_SCENE(sky.temperature)},
    {SECTION_SKY, "stars", CONF_INTEGER, .lo = 0, .hi = STAR_CATALOGUE_MAX, .offset = AT_SCENE(sky.stars)},
    {SECTION_SKY, "catalogue", CONF_PATH, .set = set_catalogue},
    {SECTION_SKY, "catalogue_colours", CONF_PATH, .set = set_catalogue_colours},
    {SECTION_SKY, "star_seed", CONF_INTEGER, .lo = 0, .hi = 2147483647, .offset = AT_SCENE(sky.star_seed)},
    {SECTION_SKY, "star_brightness", CONF_NUMBER, .lo = 0.0, .hi = 1e6, .offset = AT_SCENE(sky.star_brightness)},
    {SECTION_SKY, "star_size", CONF_NUMBER, .lo = 0.3, .hi = 8.0, .offset = AT_SCENE(sky.star_size)},
    {SECTION_SKY, "milky_way", CONF_NUMBER, .lo = 0.0, .hi = 100.0, .offset = AT_SCENE(sky.milky_way)},
    {SECTION_SKY, "galactic_pole", CONF_VECTOR, ANY, .flags = CONF_NONZERO, .offset = AT_SCENE(sky.galactic_pole)},
    {SECTION_SKY, "galactic_center", CONF_VECTOR, ANY, .flags = CONF_NONZERO, .offset = AT_SCENE(sky.galactic_center)},

    {SECTION_OBJECT, "type", CHOICE(primitive_names, AT_OBJECT(type)), .flags = CONF_REQUIRED},
    {SECTION_OBJECT, "center", CONF_VECTOR, ANY,
     .applies = FOR_PRIM(PRIM_SPHERE) | FOR_PRIM(PRIM_DISK) | FOR_PRIM(PRIM_RECT),
     .offset = AT_OBJECT(center)},
    {SECTION_OBJECT, "radius", CONF_NUMBER, POSITIVE, .applies = FOR_PRIM(PRIM_SPHERE) | FOR_PRIM(PRIM_DISK),
     .offset = AT_OBJECT(radius)},
    {SECTION_OBJECT, "pole", CONF_VECTOR, ANY, .flags = CONF_NONZERO, .applies = FOR_PRIM(PRIM_SPHERE),
     .offset = AT_OBJECT(pole)},
    {SECTION_OBJECT, "v0", CONF_VECTOR, ANY, .applies = FOR_PRIM(PRIM_TRIANGLE),
     .offset = AT_OBJECT(vertex[0])},
    {SECTION_OBJECT, "v1", CONF_VECTOR, ANY, .applies = FOR_PRIM(PRIM_TRIANGLE),
     .offset = AT_OBJECT(vertex[1])},
    {SECTION_OBJECT, "v2", CONF_VECTOR, ANY, .applies = FOR_PRIM(PRIM_TRIANGLE),
     .offset = AT_OBJECT(vertex[2])},
    {SECTION_OBJECT, "uv0", CONF_TEXCOORD, ANY, .applies = FOR_PRIM(PRIM_TRIANGLE),
     .offset = AT_OBJECT(uv[0])},
    {SECTION_OBJECT, "uv1", CONF_TEXCOORD, ANY, .applies = FOR_PRIM(PRIM_TRIANGLE),
     .offset = AT_OBJECT(uv[1])},
    {SECTION_OBJECT, "uv2", CONF_TEXCOORD, ANY, .applies = FOR_PRIM(PRIM_TRIANGLE),
     .offset = AT_OBJECT(uv[2])},
    {SECTION_OBJECT, "normal", CONF_VECTOR, ANY, .flags = CONF_NONZERO, .applies = FOR_PRIM(PRIM_DISK),
     .offset = AT_OBJECT(normal)},
    {SECTION_OBJECT, "inner_radius", CONF_NUMBER, NON_NEGATIVE, .applies = FOR_PRIM(PRIM_DISK),
     .offset = AT_OBJECT(inner_radius)},
    {SECTION_OBJECT, "axis_u", CONF_VECTOR, ANY, .flags = CONF_NONZERO, .applies = FOR_PRIM(PRIM_RECT),
     .offset = AT_OBJECT(axis_u)},
    {SECTION_OBJECT, "axis_v", CONF_VECTOR, ANY, .flags = CONF_NONZERO, .applies = FOR_PRIM(PRIM_RECT),
     .offset = AT_OBJECT(axis_v)},
    {SECTION_OBJECT, "color", CONF_COLOR, COLOR_RANGE, .offset = AT_OBJECT(material.color)},
    {SECTION_OBJECT, "emission", CONF_COLOR, COLOR_RANGE, .offset = AT_OBJECT(material.emission)},
    {SECTION_OBJECT, "ambient", CONF_NUMBER, .lo = 0.0, .hi = 1000.0, .offset = AT_OBJECT(material.ambient)},
    {SECTION_OBJECT, "diffuse", CONF_NUMBER, .lo = 0.0, .hi = 1000.0, .offset = AT_OBJECT(material.diffuse)},
    {SECTION_OBJECT, "specular", CONF_NUMBER, .lo = 0.0, .hi = 1000.0, .offset = AT_OBJECT(material.specular)},
    {SECTION_OBJECT, "shininess", CONF_NUMBER, .lo = 0.0, .hi = 10000.0,
     .offset = AT_OBJECT(material.shininess)},
    {SECTION_OBJECT, "texture", CONF_PATH, .set = set_texture},
    {SECTION_OBJECT, "checker", CONF_NUMBER, NON_NEGATIVE, .offset = AT_OBJECT(material.checker)},
    {SECTION_OBJECT, "checker_color", CONF_COLOR, COLOR_RANGE, .offset = AT_OBJECT(material.checker_color)},
    {SECTION_OBJECT, "temperature", CONF_NUMBER, TEMPERATURE_RANGE, .offset = AT_OBJECT(material.temperature)},
    {SECTION_OBJECT, "accretion", CHOICE(switch_names, AT_OBJECT(material.accretion)), .applies = FOR_PRIM(PRIM_DISK)},
    {SECTION_OBJECT, "clock_period", CONF_NUMBER, .lo = 0.0, .hi = 1e9, .offset = AT_OBJECT(material.clock_period)},
    {SECTION_OBJECT, "velocity", CONF_VECTOR, ANY, .offset = AT_OBJECT(velocity)},
    {SECTION_OBJECT, "frame_origin", CONF_VECTOR, ANY, .set = set_frame_origin},

    {SECTION_QUALITY, "differing_percent", CONF_NUMBER, .lo = 0.0, .hi = 100.0,
     .offset = AT_SCENE(quality.differing_percent)},
    {SECTION_QUALITY, "exit_p99", CONF_NUMBER, .lo = 0.0, .hi = 3.15, .offset = AT_SCENE(quality.exit_p99)},
    {SECTION_QUALITY, "hit_p99", CONF_NUMBER, .lo = 0.0, .hi = 1000.0, .offset = AT_SCENE(quality.hit_p99)},

    {SECTION_KIOSK, "title", CONF_TEXT, .lo = 1, .hi = SCENE_KIOSK_WORDS_LEN - 1, .offset = AT_SCENE(kiosk.title)},
    {SECTION_KIOSK, "caption", CONF_TEXT, .lo = 1, .hi = SCENE_KIOSK_CAPTION_LEN - 1, .offset = AT_SCENE(kiosk.caption)},
    {SECTION_KIOSK, "speed_label", CONF_TEXT, .lo = 1, .hi = SCENE_KIOSK_WORDS_LEN - 1,
     .offset = AT_SCENE(kiosk.speed.label)},
    {SECTION_KIOSK, "mass_label", CONF_TEXT, .lo = 1, .hi = SCENE_KIOSK_WORDS_LEN - 1,
     .offset = AT_SCENE(kiosk.mass.label)},
    {SECTION_KIOSK, "speed_key", CONF_TEXT, .lo = 1, .hi = SCENE_NAME_LEN - 1, .offset = AT_SCENE(kiosk.speed.key)},
    {SECTION_KIOSK, "speed_min", CONF_NUMBER, ANY, .offset = AT_SCENE(kiosk.speed.min)},
    {SECTION_KIOSK, "speed_max", CONF_NUMBER, ANY, .offset = AT_SCENE(kiosk.speed.max)},
    {SECTION_KIOSK, "speed_steps", CONF_INTEGER, .lo = 1, .hi = SCENE_KIOSK_MAX_STEPS,
     .offset = AT_SCENE(kiosk.speed.steps)},
    {SECTION_KIOSK, "mass_key", CONF_TEXT, .lo = 1, .hi = SCENE_NAME_LEN - 1, .offset = AT_SCENE(kiosk.mass.key)},
    {SECTION_KIOSK, "mass_min", CONF_NUMBER, ANY, .offset = AT_SCENE(kiosk.mass.min)},
    {SECTION_KIOSK, "mass_max", CONF_NUMBER, ANY, .offset = AT_SCENE(kiosk.mass.max)},
    {SECTION_KIOSK, "mass_steps", CONF_INTEGER, .lo = 1, .hi = SCENE_KIOSK_MAX_STEPS,
     .offset = AT_SCENE(kiosk.mass.steps)},
};

const int scene_key_count = (int)(sizeof scene_keys / sizeof scene_keys[0]);
/* choices are stored as int into enum fields */
_Static_assert(sizeof(enum model_type) == sizeof(int) && sizeof(enum primitive_type) == sizeof(int) &&
               sizeof(enum integration_method) == sizeof(int) && sizeof(enum step_control) == sizeof(int) &&
               sizeof(enum precision_choice) == sizeof(int) && sizeof(enum mrt_choice) == sizeof(int) &&
               sizeof(enum potential_profile) == sizeof(int) && sizeof(enum sky_type) == sizeof(int) &&
               sizeof(enum relativity_effects) == sizeof(int) && sizeof(enum searchlight_exposure) == sizeof(int) &&
               sizeof(enum moving_objects_method) == sizeof(int) && sizeof(enum pipeline_choice) == sizeof(int) &&
               sizeof(((struct scene *)0)->render.early_z) == sizeof(int) &&
               sizeof(((struct scene *)0)->observer.gravitational_shift) == sizeof(int), "enums are stored as int");
_Static_assert(sizeof scene_keys / sizeof scene_keys[0] <= SCENE_KEY_TABLE_MAX,
               "raise SCENE_KEY_TABLE_MAX");
_Static_assert(MODEL_COUNT <= 16 && PRIM_COUNT <= 16, "type masks are unsigned bit sets");

/* ---- what only a scene knows about its keys -------------------------------------------------- */

/* A limit's value as written in its #define, for messages that are string constants. */
#define NUMBER_TEXT(x) NUMBER_TEXT_(x)
#define NUMBER_TEXT_(x) #x

static void label(const void *owner, int section, int instance, char *buf, size_t len)
{
    scene_section_label(owner, (enum scene_section_kind)section, instance, buf, len);
}

static void *target(void *owner, int section, int instance)
{
    struct scene *s = owner;
    if (section == SECTION_OBJECT)
        return &s->objects[instance];
    if (section == SECTION_LIGHT)
        return &s->lights[instance];
    return s;
}

static const char *type_word(int section)
{
    return section == SECTION_MODEL ? "model" : section == SECTION_OBJECT ? "object type" : NULL;
}

static int type_of(const void *owner, int section, int instance)
{
    const struct scene *s = owner;
    return section == SECTION_MODEL ? (int)s->model.type : (int)s->objects[instance].type;
}

static const char *type_name(int section, int t)
{
    return section == SECTION_MODEL ? scene_model_type_name((enum model_type)t)
                                    : scene_primitive_name((enum primitive_type)t);
}

static int resolve_path(const void *owner, const char *rel, char *out, size_t len)
{
    return scene_resolve_path(owner, rel, out, len);
}

const struct conf_key_table scene_key_table = {
    .keys = scene_keys,
    .count = sizeof scene_keys / sizeof scene_keys[0],
    .name_len = SCENE_NAME_LEN,
    .path_len = SCENE_PATH_LEN,
    .max_abs = SCENE_MAX_ABS_VALUE,
    .max_abs_reason = "larger in magnitude than " NUMBER_TEXT(SCENE_MAX_ABS_VALUE) ", the most a scene number "
                      "may be: the GPU squares lengths in 32-bit floats",
    .relative_note = "relative paths start at the scene file's directory",
    .label = label,
    .target = target,
    .type_word = type_word,
    .type_of = type_of,
    .type_name = type_name,
    .resolve_path = resolve_path,
};

/* "model.rho" as SECTION_MODEL and "rho"; -1 when KEY names no section without instances. */
static int split_key(const char *key, const char **name)
{
    char section[SCENE_NAME_LEN];
    const char *dot = strchr(key, '.');
    if (!dot || (size_t)(dot - key) >= sizeof section)
        return -1;
    memcpy(section, key, (size_t)(dot - key));
    section[dot - key] = '\0';
    int kind = scene_section_find(section);
    if (kind < 0 || scene_section_named(kind))
        return -1;
    *name = dot + 1;
    return kind;
}

int scene_get_number(const struct scene *s, const char *key, double *out)
{
    const char *name;
    int section = split_key(key, &name);
    const struct conf_key *k = section < 0 ? NULL : conf_key_for(&scene_key_table, s, section, 0, name);
    if (!k || k->kind != CONF_NUMBER || k->set)
        return -1;
    memcpy(out, (const char *)s + k->offset, sizeof *out);
    return 0;
}

int scene_key_find(enum scene_section_kind section, const char *name)
{
    return conf_key_find(&scene_key_table, (int)section, name);
}

int scene_key_apply(struct scene *s, enum scene_section_kind section, int instance,
                    const char *name, const char *value, struct error *e)
{
    return conf_key_apply(&scene_key_table, s, (int)section, instance, name, value, e);
}

int scene_set_number(struct scene *s, const char *key, double value, struct error *err)
{
    memset(err, 0, sizeof *err);
    snprintf(err->where, sizeof err->where, "%.*s=%.17g", (int)sizeof err->where - 40, key, value);
    const char *name = NULL;
    int section = split_key(key, &name);
    const struct conf_key *k = section < 0 ? NULL : conf_key_for(&scene_key_table, s, section, 0, name);
    if (!k || k->kind != CONF_NUMBER) {
        snprintf(err->message, sizeof err->message, "'%s' is not a number of this scene (a key such as model.rho, "
                 "as --set names it)", key);
        err->status = ERROR_INPUT;
        return -1;
    }
    char where[sizeof err->where];
    memcpy(where, err->where, sizeof where);
    if (conf_key_apply_number(&scene_key_table, s, section, 0, name, value, err) != 0) {
        memcpy(err->where, where, sizeof where);
        return -1;
    }
    return 0;
}
