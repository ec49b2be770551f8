/* The table of scene keys and the parsing of their values. A key is described once here (section,
 * name, type, range, the model or primitive types it belongs to, where it is stored), so the file
 * loader, --set and the tests cannot disagree about what a scene may say. */
#include <ctype.h>
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "scene/scene_keys.h"
#include "io/png_header.h"
#include "io/text_file.h"
#include "physics/star_catalogue.h"

/* ---- names of enumerations, in enum order ------------------------------------------------- */

static const char *const model_names[] = {
    "flat", "lorenz", "rossler", "potential", "refraction", "schwarzschild", NULL
};
static const char *const primitive_names[] = {"sphere", "triangle", "disk", "rect", NULL};
static const char *const method_names[] = {"euler", "rk4", "dopri5", "orbit_table", NULL};
static const char *const step_control_names[] = {"fixed", "doubling", "embedded", NULL};
static const char *const switch_names[] = {"off", "on", NULL};
static const char *const precision_names[] = {"auto", "fp32", "fp16", NULL};
static const char *const mrt_names[] = {"auto", "on", "off", NULL};
static const char *const profile_names[] = {"yukawa", "polynomial", NULL};
static const char *const sky_names[] = {"color", "cubemap", NULL};
static const char *const effects_names[] = {"geometry", "doppler", "searchlight", NULL};
static const char *const exposure_names[] = {"scene", "paper", NULL};
static const char *const moving_names[] = {"rays", "polygons", NULL};
static const char *const pipeline_names[] = {"auto", "multipass", "single", "fused", NULL};

_Static_assert(sizeof model_names / sizeof model_names[0] == MODEL_COUNT + 1,
               "one name per model type");
_Static_assert(sizeof primitive_names / sizeof primitive_names[0] == PRIM_COUNT + 1,
               "one name per primitive type");

const char *scene_model_type_name(enum model_type type)
{
    return (unsigned)type < MODEL_COUNT ? model_names[type] : "?";
}

const char *scene_primitive_name(enum primitive_type type)
{
    return (unsigned)type < PRIM_COUNT ? primitive_names[type] : "?";
}

/* ---- sections ---------------------------------------------------------------------------- */

static const struct {
    const char *name;
    int named;
    int type_first;
} sections[SECTION_COUNT] = {
    [SECTION_SCENE] = {"scene", 0, 0},
    [SECTION_CAMERA] = {"camera", 0, 0},
    [SECTION_OBSERVER] = {"observer", 0, 0},
    [SECTION_RENDER] = {"render", 0, 0},
    [SECTION_MODEL] = {"model", 0, 1},
    [SECTION_LIGHTING] = {"lighting", 0, 0},
    [SECTION_LIGHT] = {"light", 1, 0},
    [SECTION_SKY] = {"sky", 0, 0},
    [SECTION_OBJECT] = {"object", 1, 1},
    [SECTION_QUALITY] = {"quality", 0, 0},
    [SECTION_KIOSK] = {"kiosk", 0, 0},
};

const char *scene_section_name(enum scene_section_kind section) { return sections[section].name; }
int scene_section_named(enum scene_section_kind section) { return sections[section].named; }
int scene_section_type_first(enum scene_section_kind section) { return sections[section].type_first; }

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
    int n;
    if (rel[0] == '/' || s->dir[0] == '\0' || strcmp(s->dir, ".") == 0)
        n = snprintf(out, out_len, "%s", rel);
    else
        n = snprintf(out, out_len, "%s/%s", s->dir, rel);
    return n < 0 || (size_t)n >= out_len ? -1 : 0;
}

/* A directory opens fine with fopen on Linux, so regular files are asked for explicitly. */
static int check_readable(const char *what, const char *path, char *reason, size_t len)
{
    struct stat st;
    FILE *f;
    if (stat(path, &st) != 0) {
        snprintf(reason, len, "cannot read %s \"%s\": %s (relative paths start at the scene "
                 "file's directory)", what, path, strerror(errno));
        return -1;
    }
    if (!S_ISREG(st.st_mode)) {
        snprintf(reason, len, "%s \"%s\" is not a regular file", what, path);
        return -1;
    }
    f = fopen(path, "rb");
    if (!f) {
        snprintf(reason, len, "cannot read %s \"%s\": %s", what, path, strerror(errno));
        return -1;
    }
    fclose(f);
    return 0;
}


/* A PNG (texture or cube face) within SCENE_MAX_TEXTURE_SIZE a side; *declared tells whether the
 * header could be read, and then *w and *h hold its size. */
static int check_image_size(const char *what, const char *path, unsigned long *w, unsigned long *h,
                            int *declared, char *reason, size_t len)
{
    *declared = png_declared_size(path, w, h) == 0;
    if (*declared && (*w > SCENE_MAX_TEXTURE_SIZE || *h > SCENE_MAX_TEXTURE_SIZE)) {
        snprintf(reason, len, "%s \"%s\" is %lux%lu pixels; at most %d pixels a side are allowed", what, path,
                 *w, *h, SCENE_MAX_TEXTURE_SIZE);
        return -1;
    }
    return 0;
}

/* ---- setters for what a field copy cannot do ---------------------------------------------- */

/* The image's pixel count bounds every per-pixel allocation: checked whenever a side changes. */
static int check_pixels(long width, long height, char *r, size_t n)
{
    if (width * height > SCENE_MAX_PIXELS) {
        snprintf(r, n, "the image would be %ldx%ld = %ld pixels; at most %ld pixels (width x height) are allowed",
                 width, height, width * height, SCENE_MAX_PIXELS);
        return -1;
    }
    return 0;
}

static int set_width(struct scene *s, void *t, const union scene_key_value *v, char *r, size_t n)
{
    (void)t;
    if (check_pixels(v->integer, s->render.height, r, n) != 0)
        return -1;
    s->render.width = v->integer;
    return 0;
}

static int set_height(struct scene *s, void *t, const union scene_key_value *v, char *r, size_t n)
{
    (void)t;
    if (check_pixels(s->render.width, v->integer, r, n) != 0)
        return -1;
    s->render.height = v->integer;
    return 0;
}

static int set_model_type(struct scene *s, void *t, const union scene_key_value *v, char *r, size_t n)
{
    (void)t, (void)r, (void)n;
    s->model.type = (enum model_type)v->choice;
    return 0;
}

static int set_profile(struct scene *s, void *t, const union scene_key_value *v, char *r, size_t n)
{
    (void)t, (void)r, (void)n;
    s->model.profile = (enum potential_profile)v->choice;
    return 0;
}

static int set_method(struct scene *s, void *t, const union scene_key_value *v, char *r, size_t n)
{
    (void)t, (void)r, (void)n;
    s->render.method = (enum integration_method)v->choice;
    return 0;
}

static int set_step_control(struct scene *s, void *t, const union scene_key_value *v, char *r, size_t n)
{
    (void)t, (void)r, (void)n;
    s->render.step_control = (enum step_control)v->choice;
    return 0;
}

static int set_early_z(struct scene *s, void *t, const union scene_key_value *v, char *r, size_t n)
{
    (void)t, (void)r, (void)n;
    s->render.early_z = v->choice;
    return 0;
}

static int set_precision(struct scene *s, void *t, const union scene_key_value *v, char *r, size_t n)
{
    (void)t, (void)r, (void)n;
    s->render.precision = (enum precision_choice)v->choice;
    return 0;
}

static int set_mrt(struct scene *s, void *t, const union scene_key_value *v, char *r, size_t n)
{
    (void)t, (void)r, (void)n;
    s->render.mrt = (enum mrt_choice)v->choice;
    return 0;
}

static int set_effects(struct scene *s, void *t, const union scene_key_value *v, char *r, size_t n)
{
    (void)t, (void)r, (void)n;
    s->observer.effects = (enum relativity_effects)v->choice;
    return 0;
}

static int set_exposure(struct scene *s, void *t, const union scene_key_value *v, char *r, size_t n)
{
    (void)t, (void)r, (void)n;
    s->observer.exposure = (enum searchlight_exposure)v->choice;
    return 0;
}

static int set_pipeline(struct scene *s, void *t, const union scene_key_value *v, char *r, size_t n)
{
    (void)t, (void)r, (void)n;
    s->render.pipeline = (enum pipeline_choice)v->choice;
    return 0;
}

static int set_moving_objects(struct scene *s, void *t, const union scene_key_value *v, char *r, size_t n)
{
    (void)t, (void)r, (void)n;
    s->render.moving_objects = (enum moving_objects_method)v->choice;
    return 0;
}

static int set_frame_origin(struct scene *s, void *t, const union scene_key_value *v, char *r, size_t n)
{
    (void)s, (void)r, (void)n;
    struct object *o = t;
    o->frame_origin = v->vector;
    o->frame_origin_given = 1;
    return 0;
}

static int set_sky_type(struct scene *s, void *t, const union scene_key_value *v, char *r, size_t n)
{
    (void)t, (void)r, (void)n;
    s->sky.type = (enum sky_type)v->choice;
    return 0;
}

static int set_object_type(struct scene *s, void *t, const union scene_key_value *v, char *r, size_t n)
{
    (void)s, (void)r, (void)n;
    ((struct object *)t)->type = (enum primitive_type)v->choice;
    return 0;
}

/* Several objects often wear the same image: each file is kept once so it is uploaded once. */
static int set_texture(struct scene *s, void *t, const union scene_key_value *v, char *r, size_t n)
{
    struct object *o = t;
    char path[SCENE_PATH_LEN];
    if (scene_resolve_path(s, v->text, path, sizeof path) != 0) {
        snprintf(r, n, "the path is longer than %d characters", SCENE_PATH_LEN - 1);
        return -1;
    }
    unsigned long w, h;
    int declared;
    if (check_readable("texture", path, r, n) != 0 || check_image_size("texture", path, &w, &h, &declared, r, n) != 0)
        return -1;
    for (int i = 0; i < s->n_textures; i++) {
        if (strcmp(s->textures[i], path) == 0) {
            o->material.texture = i;
            return 0;
        }
    }
    if (s->n_textures >= SCENE_MAX_TEXTURES) {
        snprintf(r, n, "too many textures: a scene may use at most %d different files",
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

static int set_cubemap(struct scene *s, void *t, const union scene_key_value *v, char *r, size_t n)
{
    const char *const *faces = scene_cubemap_faces;
    char prefix[SCENE_PATH_LEN];
    (void)t;
    /* room for the longest face suffix, so every face path fits where the prefix fits */
    if (scene_resolve_path(s, v->text, prefix, sizeof prefix - sizeof "_px.png" + 1) != 0) {
        snprintf(r, n, "the path is longer than %d characters",
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
        if (check_readable(what, face, r, n) != 0 || check_image_size(what, face, &w, &h, &declared, r, n) != 0)
            return -1;
        if (!declared)
            continue;
        if (w != h) {
            snprintf(r, n, "%s \"%s\" is %lux%lu pixels; cube map faces must be square", what, face, w, h);
            return -1;
        }
        if (side_face && w != side) {
            snprintf(r, n, "%s \"%s\" is %lux%lu pixels, face %s %lux%lu; every face must have the same size",
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
#define CHOICE(names, setter) .kind = KEY_CHOICE, .choices = names, .set = setter

#define FOR_MODEL(t) (1u << (t))
#define ALL_MODELS_BUT_FLAT (((1u << MODEL_COUNT) - 1u) & ~FOR_MODEL(MODEL_FLAT))
#define FOR_PRIM(t) (1u << (t))

/* In the order of docs/SCENES.md, which documents each entry (a unit test checks every name is there).
 * Entries of one section stay together: --set and the loader search by section and name. */
const struct scene_key scene_keys[] = {
    {SECTION_SCENE, "name", KEY_TEXT, .lo = 1, .hi = SCENE_NAME_LEN - 1, .offset = AT_SCENE(name)},
    {SECTION_SCENE, "description", KEY_TEXT, .lo = 0, .hi = sizeof(((struct scene *)0)->description) - 1,
     .offset = AT_SCENE(description)},

    {SECTION_CAMERA, "position", KEY_VECTOR, ANY, .offset = AT_SCENE(camera.position)},
    {SECTION_CAMERA, "look_at", KEY_VECTOR, ANY, .offset = AT_SCENE(camera.look_at)},
    {SECTION_CAMERA, "up", KEY_VECTOR, ANY, .flags = KEY_NONZERO, .offset = AT_SCENE(camera.up)},
    {SECTION_CAMERA, "fov", KEY_NUMBER, .lo = 0.0, .hi = 180.0, .flags = CONF_ABOVE_LO | CONF_BELOW_HI,
     .offset = AT_SCENE(camera.fov_deg)},

    {SECTION_OBSERVER, "velocity", KEY_VECTOR, ANY, .offset = AT_SCENE(observer.velocity)},
    {SECTION_OBSERVER, "effects", CHOICE(effects_names, set_effects)},
    {SECTION_OBSERVER, "exposure", CHOICE(exposure_names, set_exposure)},
    {SECTION_OBSERVER, "time", KEY_NUMBER, .lo = -1e9, .hi = 1e9, .offset = AT_SCENE(observer.time)},

    {SECTION_RENDER, "width", KEY_INTEGER, .lo = 1, .hi = SCENE_MAX_SIZE, .set = set_width},
    {SECTION_RENDER, "height", KEY_INTEGER, .lo = 1, .hi = SCENE_MAX_SIZE, .set = set_height},
    {SECTION_RENDER, "method", CHOICE(method_names, set_method)},
    {SECTION_RENDER, "step", KEY_NUMBER, .lo = 0.0, .hi = 1e6, .flags = CONF_ABOVE_LO,
     .offset = AT_SCENE(render.step_size)},
    {SECTION_RENDER, "steps_per_segment", KEY_INTEGER, .lo = 1, .hi = SCENE_MAX_STEPS_PER_SEGMENT,
     .offset = AT_SCENE(render.steps_per_segment)},
    {SECTION_RENDER, "segments", KEY_INTEGER, .lo = 0, .hi = SCENE_MAX_SEGMENTS,
     .offset = AT_SCENE(render.segments)},
    {SECTION_RENDER, "max_path", KEY_NUMBER, .lo = 0.0, .hi = 1e9, .offset = AT_SCENE(render.max_path)},
    {SECTION_RENDER, "unfinished_color", KEY_COLOR, COLOR_RANGE, .offset = AT_SCENE(render.unfinished_color)},
    {SECTION_RENDER, "steps_per_pass", KEY_INTEGER, .lo = 1, .hi = SCENE_MAX_STEPS_PER_PASS,
     .offset = AT_SCENE(render.steps_per_pass)},
    {SECTION_RENDER, "bound_radius", KEY_NUMBER, POSITIVE, .offset = AT_SCENE(render.bound_radius)},
    {SECTION_RENDER, "bound_center", KEY_VECTOR, ANY, .offset = AT_SCENE(render.bound_center)},
    {SECTION_RENDER, "precision", CHOICE(precision_names, set_precision)},
    {SECTION_RENDER, "mrt", CHOICE(mrt_names, set_mrt)},
    {SECTION_RENDER, "early_z", CHOICE(switch_names, set_early_z)},
    {SECTION_RENDER, "termination_interval", KEY_INTEGER, .lo = 1, .hi = SCENE_MAX_SEGMENTS,
     .offset = AT_SCENE(render.termination_interval)},
    {SECTION_RENDER, "batch", KEY_INTEGER, .lo = 1, .hi = SCENE_MAX_BATCH, .offset = AT_SCENE(render.batch)},
    {SECTION_RENDER, "step_control", CHOICE(step_control_names, set_step_control)},
    {SECTION_RENDER, "tolerance", KEY_NUMBER, .lo = 0.0, .hi = 1e6, .flags = CONF_ABOVE_LO,
     .offset = AT_SCENE(render.tolerance)},
    {SECTION_RENDER, "grow_fraction", KEY_NUMBER, .lo = 0.0, .hi = 1.0, .flags = CONF_ABOVE_LO | CONF_BELOW_HI,
     .offset = AT_SCENE(render.grow_fraction)},
    {SECTION_RENDER, "step_min", KEY_NUMBER, .lo = 0.0, .hi = 1e6, .offset = AT_SCENE(render.step_min)},
    {SECTION_RENDER, "step_max", KEY_NUMBER, .lo = 0.0, .hi = 1e6, .offset = AT_SCENE(render.step_max)},
    {SECTION_RENDER, "moving_objects", CHOICE(moving_names, set_moving_objects)},
    {SECTION_RENDER, "polygon_subdivision", KEY_INTEGER, .lo = 1, .hi = SCENE_MAX_SUBDIVISION,
     .offset = AT_SCENE(render.polygon_subdivision)},
    {SECTION_RENDER, "chord_tolerance", KEY_NUMBER, .lo = 0.0, .hi = 1e6, .flags = CONF_ABOVE_LO,
     .offset = AT_SCENE(render.chord_tolerance)},
    {SECTION_RENDER, "sky_alpha", KEY_NUMBER, .lo = 0.0, .hi = 1.0, .offset = AT_SCENE(render.sky_alpha)},
    {SECTION_RENDER, "samples", KEY_INTEGER, .lo = 1, .hi = SCENE_MAX_SAMPLES, .offset = AT_SCENE(render.samples)},
    {SECTION_RENDER, "max_chords", KEY_INTEGER, .lo = 1, .hi = SCENE_MAX_CHORDS,
     .offset = AT_SCENE(render.max_chords)},
    {SECTION_RENDER, "orbit_rows", KEY_INTEGER, .lo = 4, .hi = SCENE_MAX_ORBIT_ROWS,
     .offset = AT_SCENE(render.orbit_rows)},
    {SECTION_RENDER, "pipeline", CHOICE(pipeline_names, set_pipeline)},
    {SECTION_RENDER, "orbit_columns", KEY_INTEGER, .lo = 4, .hi = SCENE_MAX_ORBIT_COLUMNS,
     .offset = AT_SCENE(render.orbit_columns)},

    {SECTION_MODEL, "type", CHOICE(model_names, set_model_type)},
    {SECTION_MODEL, "center", KEY_VECTOR, ANY, .applies = ALL_MODELS_BUT_FLAT,
     .offset = AT_SCENE(model.center)},
    {SECTION_MODEL, "sigma", KEY_NUMBER, ANY, .applies = FOR_MODEL(MODEL_LORENZ),
     .offset = AT_SCENE(model.sigma)},
    {SECTION_MODEL, "rho", KEY_NUMBER, ANY, .applies = FOR_MODEL(MODEL_LORENZ),
     .offset = AT_SCENE(model.rho)},
    /* the same name means Lorenz's beta or Roessler's second parameter, as in the papers */
    {SECTION_MODEL, "beta", KEY_NUMBER, ANY, .applies = FOR_MODEL(MODEL_LORENZ),
     .offset = AT_SCENE(model.beta)},
    {SECTION_MODEL, "beta", KEY_NUMBER, ANY, .applies = FOR_MODEL(MODEL_ROSSLER),
     .offset = AT_SCENE(model.ross_b)},
    {SECTION_MODEL, "alpha", KEY_NUMBER, ANY, .applies = FOR_MODEL(MODEL_ROSSLER),
     .offset = AT_SCENE(model.ross_a)},
    {SECTION_MODEL, "gamma", KEY_NUMBER, ANY, .applies = FOR_MODEL(MODEL_ROSSLER),
     .offset = AT_SCENE(model.ross_c)},
    {SECTION_MODEL, "scale", KEY_NUMBER, POSITIVE,
     .applies = FOR_MODEL(MODEL_LORENZ) | FOR_MODEL(MODEL_ROSSLER),
     .offset = AT_SCENE(model.scale)},
    {SECTION_MODEL, "strength", KEY_NUMBER, ANY,
     .applies = FOR_MODEL(MODEL_LORENZ) | FOR_MODEL(MODEL_ROSSLER) | FOR_MODEL(MODEL_POTENTIAL),
     .offset = AT_SCENE(model.strength)},
    {SECTION_MODEL, "profile", CHOICE(profile_names, set_profile), .applies = FOR_MODEL(MODEL_POTENTIAL)},
    {SECTION_MODEL, "zeta", KEY_NUMBER, ANY, .applies = FOR_MODEL(MODEL_POTENTIAL),
     .offset = AT_SCENE(model.zeta)},
    {SECTION_MODEL, "mu", KEY_NUMBER, NON_NEGATIVE, .applies = FOR_MODEL(MODEL_POTENTIAL),
     .offset = AT_SCENE(model.mu)},
    {SECTION_MODEL, "radius", KEY_NUMBER, POSITIVE, .applies = FOR_MODEL(MODEL_POTENTIAL),
     .offset = AT_SCENE(model.radius)},
    {SECTION_MODEL, "amplitude", KEY_NUMBER, ANY, .applies = FOR_MODEL(MODEL_REFRACTION),
     .offset = AT_SCENE(model.amplitude)},
    {SECTION_MODEL, "shell_radius", KEY_NUMBER, NON_NEGATIVE, .applies = FOR_MODEL(MODEL_REFRACTION),
     .offset = AT_SCENE(model.shell_radius)},
    {SECTION_MODEL, "shell_width", KEY_NUMBER, POSITIVE, .applies = FOR_MODEL(MODEL_REFRACTION),
     .offset = AT_SCENE(model.shell_width)},
    {SECTION_MODEL, "noise_amplitude", KEY_NUMBER, ANY, .applies = FOR_MODEL(MODEL_REFRACTION),
     .offset = AT_SCENE(model.noise_amplitude)},
    {SECTION_MODEL, "noise_frequency", KEY_NUMBER, NON_NEGATIVE, .applies = FOR_MODEL(MODEL_REFRACTION),
     .offset = AT_SCENE(model.noise_frequency)},
    {SECTION_MODEL, "mass", KEY_NUMBER, NON_NEGATIVE, .applies = FOR_MODEL(MODEL_SCHWARZSCHILD),
     .offset = AT_SCENE(model.mass)},

    {SECTION_LIGHTING, "ambient", KEY_COLOR, COLOR_RANGE, .offset = AT_SCENE(ambient_light)},

    {SECTION_LIGHT, "position", KEY_VECTOR, ANY, .offset = AT_LIGHT(position)},
    {SECTION_LIGHT, "color", KEY_COLOR, COLOR_RANGE, .offset = AT_LIGHT(color)},
    {SECTION_LIGHT, "temperature", KEY_NUMBER, TEMPERATURE_RANGE, .offset = AT_LIGHT(temperature)},

    {SECTION_SKY, "type", CHOICE(sky_names, set_sky_type)},
    {SECTION_SKY, "color", KEY_COLOR, COLOR_RANGE, .offset = AT_SCENE(sky.color)},
    {SECTION_SKY, "cubemap", KEY_PATH, .set = set_cubemap},
    {SECTION_SKY, "temperature", KEY_NUMBER, TEMPERATURE_RANGE, .offset = AT_SCENE(sky.temperature)},
    {SECTION_SKY, "stars", KEY_INTEGER, .lo = 0, .hi = STAR_CATALOGUE_MAX, .offset = AT_SCENE(sky.stars)},
    {SECTION_SKY, "star_seed", KEY_INTEGER, .lo = 0, .hi = 2147483647, .offset = AT_SCENE(sky.star_seed)},
    {SECTION_SKY, "star_brightness", KEY_NUMBER, .lo = 0.0, .hi = 1e6, .offset = AT_SCENE(sky.star_brightness)},
    {SECTION_SKY, "star_size", KEY_NUMBER, .lo = 0.3, .hi = 8.0, .offset = AT_SCENE(sky.star_size)},
    {SECTION_SKY, "milky_way", KEY_NUMBER, .lo = 0.0, .hi = 100.0, .offset = AT_SCENE(sky.milky_way)},
    {SECTION_SKY, "galactic_pole", KEY_VECTOR, ANY, .flags = KEY_NONZERO, .offset = AT_SCENE(sky.galactic_pole)},
    {SECTION_SKY, "galactic_center", KEY_VECTOR, ANY, .flags = KEY_NONZERO, .offset = AT_SCENE(sky.galactic_center)},

    {SECTION_OBJECT, "type", CHOICE(primitive_names, set_object_type)},
    {SECTION_OBJECT, "center", KEY_VECTOR, ANY,
     .applies = FOR_PRIM(PRIM_SPHERE) | FOR_PRIM(PRIM_DISK) | FOR_PRIM(PRIM_RECT),
     .offset = AT_OBJECT(center)},
    {SECTION_OBJECT, "radius", KEY_NUMBER, POSITIVE, .applies = FOR_PRIM(PRIM_SPHERE) | FOR_PRIM(PRIM_DISK),
     .offset = AT_OBJECT(radius)},
    {SECTION_OBJECT, "pole", KEY_VECTOR, ANY, .flags = KEY_NONZERO, .applies = FOR_PRIM(PRIM_SPHERE),
     .offset = AT_OBJECT(pole)},
    {SECTION_OBJECT, "v0", KEY_VECTOR, ANY, .applies = FOR_PRIM(PRIM_TRIANGLE),
     .offset = AT_OBJECT(vertex[0])},
    {SECTION_OBJECT, "v1", KEY_VECTOR, ANY, .applies = FOR_PRIM(PRIM_TRIANGLE),
     .offset = AT_OBJECT(vertex[1])},
    {SECTION_OBJECT, "v2", KEY_VECTOR, ANY, .applies = FOR_PRIM(PRIM_TRIANGLE),
     .offset = AT_OBJECT(vertex[2])},
    {SECTION_OBJECT, "uv0", KEY_TEXCOORD, ANY, .applies = FOR_PRIM(PRIM_TRIANGLE),
     .offset = AT_OBJECT(uv[0])},
    {SECTION_OBJECT, "uv1", KEY_TEXCOORD, ANY, .applies = FOR_PRIM(PRIM_TRIANGLE),
     .offset = AT_OBJECT(uv[1])},
    {SECTION_OBJECT, "uv2", KEY_TEXCOORD, ANY, .applies = FOR_PRIM(PRIM_TRIANGLE),
     .offset = AT_OBJECT(uv[2])},
    {SECTION_OBJECT, "normal", KEY_VECTOR, ANY, .flags = KEY_NONZERO, .applies = FOR_PRIM(PRIM_DISK),
     .offset = AT_OBJECT(normal)},
    {SECTION_OBJECT, "inner_radius", KEY_NUMBER, NON_NEGATIVE, .applies = FOR_PRIM(PRIM_DISK),
     .offset = AT_OBJECT(inner_radius)},
    {SECTION_OBJECT, "axis_u", KEY_VECTOR, ANY, .flags = KEY_NONZERO, .applies = FOR_PRIM(PRIM_RECT),
     .offset = AT_OBJECT(axis_u)},
    {SECTION_OBJECT, "axis_v", KEY_VECTOR, ANY, .flags = KEY_NONZERO, .applies = FOR_PRIM(PRIM_RECT),
     .offset = AT_OBJECT(axis_v)},
    {SECTION_OBJECT, "color", KEY_COLOR, COLOR_RANGE, .offset = AT_OBJECT(material.color)},
    {SECTION_OBJECT, "emission", KEY_COLOR, COLOR_RANGE, .offset = AT_OBJECT(material.emission)},
    {SECTION_OBJECT, "ambient", KEY_NUMBER, .lo = 0.0, .hi = 1000.0, .offset = AT_OBJECT(material.ambient)},
    {SECTION_OBJECT, "diffuse", KEY_NUMBER, .lo = 0.0, .hi = 1000.0, .offset = AT_OBJECT(material.diffuse)},
    {SECTION_OBJECT, "specular", KEY_NUMBER, .lo = 0.0, .hi = 1000.0, .offset = AT_OBJECT(material.specular)},
    {SECTION_OBJECT, "shininess", KEY_NUMBER, .lo = 0.0, .hi = 10000.0,
     .offset = AT_OBJECT(material.shininess)},
    {SECTION_OBJECT, "texture", KEY_PATH, .set = set_texture},
    {SECTION_OBJECT, "checker", KEY_NUMBER, NON_NEGATIVE, .offset = AT_OBJECT(material.checker)},
    {SECTION_OBJECT, "checker_color", KEY_COLOR, COLOR_RANGE, .offset = AT_OBJECT(material.checker_color)},
    {SECTION_OBJECT, "temperature", KEY_NUMBER, TEMPERATURE_RANGE, .offset = AT_OBJECT(material.temperature)},
    {SECTION_OBJECT, "clock_period", KEY_NUMBER, .lo = 0.0, .hi = 1e9, .offset = AT_OBJECT(material.clock_period)},
    {SECTION_OBJECT, "velocity", KEY_VECTOR, ANY, .offset = AT_OBJECT(velocity)},
    {SECTION_OBJECT, "frame_origin", KEY_VECTOR, ANY, .set = set_frame_origin},

    {SECTION_QUALITY, "differing_percent", KEY_NUMBER, .lo = 0.0, .hi = 100.0,
     .offset = AT_SCENE(quality.differing_percent)},
    {SECTION_QUALITY, "exit_p99", KEY_NUMBER, .lo = 0.0, .hi = 3.15, .offset = AT_SCENE(quality.exit_p99)},
    {SECTION_QUALITY, "hit_p99", KEY_NUMBER, .lo = 0.0, .hi = 1000.0, .offset = AT_SCENE(quality.hit_p99)},

    {SECTION_KIOSK, "speed_key", KEY_TEXT, .lo = 1, .hi = SCENE_NAME_LEN - 1, .offset = AT_SCENE(kiosk.speed.key)},
    {SECTION_KIOSK, "speed_min", KEY_NUMBER, ANY, .offset = AT_SCENE(kiosk.speed.min)},
    {SECTION_KIOSK, "speed_max", KEY_NUMBER, ANY, .offset = AT_SCENE(kiosk.speed.max)},
    {SECTION_KIOSK, "speed_steps", KEY_INTEGER, .lo = 1, .hi = SCENE_KIOSK_MAX_STEPS,
     .offset = AT_SCENE(kiosk.speed.steps)},
    {SECTION_KIOSK, "mass_key", KEY_TEXT, .lo = 1, .hi = SCENE_NAME_LEN - 1, .offset = AT_SCENE(kiosk.mass.key)},
    {SECTION_KIOSK, "mass_min", KEY_NUMBER, ANY, .offset = AT_SCENE(kiosk.mass.min)},
    {SECTION_KIOSK, "mass_max", KEY_NUMBER, ANY, .offset = AT_SCENE(kiosk.mass.max)},
    {SECTION_KIOSK, "mass_steps", KEY_INTEGER, .lo = 1, .hi = SCENE_KIOSK_MAX_STEPS,
     .offset = AT_SCENE(kiosk.mass.steps)},
};

const int scene_key_count = (int)(sizeof scene_keys / sizeof scene_keys[0]);
_Static_assert(sizeof scene_keys / sizeof scene_keys[0] <= SCENE_KEY_TABLE_MAX,
               "raise SCENE_KEY_TABLE_MAX");
_Static_assert(MODEL_COUNT <= 16 && PRIM_COUNT <= 16, "type masks are unsigned bit sets");

int scene_get_number(const struct scene *s, const char *key, double *out)
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
    for (int i = 0; i < scene_key_count; i++) {
        const struct scene_key *k = &scene_keys[i];
        if ((int)k->section == kind && strcmp(k->name, dot + 1) == 0 && k->kind == KEY_NUMBER && !k->set &&
            (k->applies == 0 || kind != SECTION_MODEL || (k->applies & (1u << s->model.type)))) {
            memcpy(out, (const char *)s + k->offset, sizeof *out);
            return 0;
        }
    }
    return -1;
}

int scene_key_find(enum scene_section_kind section, const char *name)
{
    for (int i = 0; i < scene_key_count; i++)
        if (scene_keys[i].section == section && strcmp(scene_keys[i].name, name) == 0)
            return i;
    return -1;
}

/* ---- parsing values ------------------------------------------------------------------------ */

/* A limit's value as written in its #define, for messages that are string constants. */
#define NUMBER_TEXT(x) NUMBER_TEXT_(x)
#define NUMBER_TEXT_(x) #x

#define TOO_LARGE_REASON                                                                                        \
    "larger in magnitude than " NUMBER_TEXT(SCENE_MAX_ABS_VALUE) ", the most a scene number may be: the GPU "  \
    "squares lengths in 32-bit floats"

/* COUNT numbers as every configuration reads them (conf/conf_value.h), each within the most a
 * scene number may be. */
static int parse_numbers(const char *text, double *out, int count, const char **reason)
{
    if (conf_parse_numbers(text, out, count, reason) != 0)
        return -1;
    for (int i = 0; i < count; i++)
        if (fabs(out[i]) > SCENE_MAX_ABS_VALUE) {
            *reason = TOO_LARGE_REASON;
            return -1;
        }
    return 0;
}

static int in_range(const struct scene_key *k, double x)
{
    return conf_in_range(x, k->lo, k->hi, k->flags);
}

static int parse_integer(const char *text, int *out)
{
    long long x;
    if (conf_parse_integer(text, &x) != 0 || x < -2147483647LL || x > 2147483647LL)
        return -1;
    *out = (int)x;
    return 0;
}

static int parse_value(const struct scene_key *k, const char *text, union scene_key_value *v,
                       const char **reason)
{
    double x[3];
    switch (k->kind) {
    case KEY_NUMBER:
        if (parse_numbers(text, x, 1, reason) != 0 || !in_range(k, x[0]))
            return -1;
        v->number = x[0];
        return 0;
    case KEY_INTEGER:
        if (parse_integer(text, &v->integer) != 0 || !in_range(k, v->integer))
            return -1;
        return 0;
    case KEY_VECTOR:
        if (parse_numbers(text, x, 3, reason) != 0)
            return -1;
        if ((k->flags & KEY_NONZERO) && x[0] == 0.0 && x[1] == 0.0 && x[2] == 0.0)
            return -1;
        v->vector = v3(x[0], x[1], x[2]);
        return 0;
    case KEY_COLOR:
        if (parse_numbers(text, x, 3, reason) != 0)
            return -1;
        for (int i = 0; i < 3; i++)
            if (!in_range(k, x[i]))
                return -1;
        v->vector = v3(x[0], x[1], x[2]);
        return 0;
    case KEY_TEXCOORD:
        if (parse_numbers(text, v->texcoord, 2, reason) != 0)
            return -1;
        return 0;
    case KEY_CHOICE:
        v->choice = conf_choice_find(k->choices, text);
        return v->choice >= 0 ? 0 : -1;
    case KEY_TEXT:
        if (strlen(text) < (size_t)k->lo || strlen(text) > (size_t)k->hi)
            return -1;
        v->text = text;
        return 0;
    case KEY_PATH:
        if (text[0] == '\0' || strlen(text) >= SCENE_PATH_LEN)
            return -1;
        v->text = text;
        return 0;
    }
    return -1;
}

static void store_value(const struct scene_key *k, void *target, const union scene_key_value *v)
{
    char *field = (char *)target + k->offset;
    switch (k->kind) {
    case KEY_NUMBER:
        memcpy(field, &v->number, sizeof v->number);
        break;
    case KEY_INTEGER:
        memcpy(field, &v->integer, sizeof v->integer);
        break;
    case KEY_VECTOR:
    case KEY_COLOR:
        memcpy(field, &v->vector, sizeof v->vector);
        break;
    case KEY_TEXCOORD:
        memcpy(field, v->texcoord, sizeof v->texcoord);
        break;
    case KEY_TEXT:
        memcpy(field, v->text, strlen(v->text) + 1);
        break;
    case KEY_CHOICE:
    case KEY_PATH:
        break;  /* these always have a setter */
    }
}

/* ---- messages ------------------------------------------------------------------------------ */

static void describe_range(const struct scene_key *k, char *buf, size_t len)
{
    conf_describe_range(k->lo, k->hi, k->flags, buf, len);
}

static void describe_expected(const struct scene_key *k, char *buf, size_t len)
{
    char range[64];
    describe_range(k, range, sizeof range);
    switch (k->kind) {
    case KEY_NUMBER:
        snprintf(buf, len, "a number%s", range);
        break;
    case KEY_INTEGER:
        snprintf(buf, len, "an integer%s", range);
        break;
    case KEY_VECTOR:
        snprintf(buf, len, "3 numbers \"x y z\"%s", k->flags & KEY_NONZERO ? ", not all zero" : "");
        break;
    case KEY_COLOR:
        snprintf(buf, len, "3 numbers \"r g b\", each%s", range);
        break;
    case KEY_TEXCOORD:
        snprintf(buf, len, "2 numbers \"u v\"");
        break;
    case KEY_CHOICE:
        conf_describe_choices(k->choices, buf, len);
        break;
    case KEY_TEXT:
        if (k->lo > 0)
            snprintf(buf, len, "text of %g to %g characters", k->lo, k->hi);
        else
            snprintf(buf, len, "text of at most %g characters", k->hi);
        break;
    case KEY_PATH:
        snprintf(buf, len, "a file path of 1 to %d characters", SCENE_PATH_LEN - 1);
        break;
    }
}

/* A near miss of a real key is nearly always a typo; naming the key saves a trip to the docs. */
static const char *closest_key(enum scene_section_kind section, const char *name)
{
    const char *best = NULL;
    int best_d = 3;
    for (int i = 0; i < scene_key_count; i++) {
        if (scene_keys[i].section != section)
            continue;
        int d = edit_distance(name, scene_keys[i].name, SCENE_NAME_LEN);
        if (d < best_d && (size_t)d < strlen(name)) {
            best_d = d;
            best = scene_keys[i].name;
        }
    }
    return best;
}

/* "lorenz, rossler": the types that have key NAME, for a key used with the wrong type. */
static void list_owners(enum scene_section_kind section, const char *name, char *buf, size_t len)
{
    unsigned mask = 0;
    size_t used = 0;
    int count = section == SECTION_MODEL ? MODEL_COUNT : PRIM_COUNT;
    buf[0] = '\0';
    for (int i = 0; i < scene_key_count; i++)
        if (scene_keys[i].section == section && strcmp(scene_keys[i].name, name) == 0)
            mask |= scene_keys[i].applies;
    for (int t = 0; t < count && used < len; t++) {
        if (!(mask & (1u << t)))
            continue;
        const char *type_name = section == SECTION_MODEL ? model_names[t] : primitive_names[t];
        used += (size_t)snprintf(buf + used, len - used, "%s%s", used ? ", " : "", type_name);
    }
}

/* The entry of NAME that fits the current model or primitive type, NULL if none does. */
static const struct scene_key *applicable_key(const struct scene *s, enum scene_section_kind section,
                                              int instance, int first)
{
    unsigned type_bit = 0;
    if (section == SECTION_MODEL)
        type_bit = 1u << s->model.type;
    else if (section == SECTION_OBJECT)
        type_bit = 1u << s->objects[instance].type;
    for (int i = first; i < scene_key_count; i++) {
        const struct scene_key *k = &scene_keys[i];
        if (k->section != section || strcmp(k->name, scene_keys[first].name) != 0)
            continue;
        if (k->applies == 0 || (k->applies & type_bit))
            return k;
    }
    return NULL;
}

int scene_key_apply(struct scene *s, enum scene_section_kind section, int instance,
                    const char *name, const char *value, char *msg, size_t msg_len)
{
    char label[SCENE_NAME_LEN + 16];
    char expected[160];
    char reason[SCENE_PATH_LEN + 160];
    const char *why = NULL;
    union scene_key_value v;
    const struct scene_key *k;
    void *target = s;
    int first;

    scene_section_label(s, section, instance, label, sizeof label);
    first = scene_key_find(section, name);
    if (first < 0) {
        const char *guess = closest_key(section, name);
        if (guess)
            snprintf(msg, msg_len, "unknown key '%s' in %s (did you mean '%s'?)", name, label, guess);
        else
            snprintf(msg, msg_len, "unknown key '%s' in %s", name, label);
        return -1;
    }
    k = applicable_key(s, section, instance, first);
    if (!k) {
        char owners[128];
        list_owners(section, name, owners, sizeof owners);
        if (section == SECTION_MODEL)
            snprintf(msg, msg_len, "key '%s' does not apply to model '%s' (only to %s)", name,
                     model_names[s->model.type], owners);
        else
            snprintf(msg, msg_len, "key '%s' in %s does not apply to object type '%s' (only to %s)",
                     name, label, primitive_names[s->objects[instance].type], owners);
        return -1;
    }
    if (parse_value(k, value, &v, &why) != 0) {
        char quoted[CONF_QUOTE_MAX + 8];
        describe_expected(k, expected, sizeof expected);
        conf_quote(value, quoted, sizeof quoted);
        snprintf(msg, msg_len, "key '%s' in %s: expected %s, got %s%s%s%s", name, label, expected, quoted,
                 why ? " (" : "", why ? why : "", why ? ")" : "");
        return -1;
    }
    if (section == SECTION_OBJECT)
        target = &s->objects[instance];
    else if (section == SECTION_LIGHT)
        target = &s->lights[instance];
    if (k->set) {
        if (k->set(s, target, &v, reason, sizeof reason) != 0) {
            snprintf(msg, msg_len, "key '%s' in %s: %s", name, label, reason);
            return -1;
        }
        return 0;
    }
    store_value(k, target, &v);
    return 0;
}

int scene_set_number(struct scene *s, const char *key, double value, struct conf_error *err)
{
    memset(err, 0, sizeof *err);
    snprintf(err->where, sizeof err->where, "%.*s=%.17g", (int)sizeof err->where - 40, key, value);
    char section[SCENE_NAME_LEN];
    const char *dot = strchr(key, '.');
    int kind = -1;
    if (dot && (size_t)(dot - key) < sizeof section) {
        memcpy(section, key, (size_t)(dot - key));
        section[dot - key] = '\0';
        kind = scene_section_find(section);
    }
    int first = kind >= 0 && !scene_section_named(kind) ? scene_key_find(kind, dot + 1) : -1;
    const struct scene_key *k = first >= 0 ? applicable_key(s, kind, 0, first) : NULL;
    if (!k || k->kind != KEY_NUMBER) {
        snprintf(err->message, sizeof err->message, "'%s' is not a number of this scene (a key such as model.rho, "
                 "as --set names it)", key);
        return -1;
    }
    char label[SCENE_NAME_LEN + 16];
    scene_section_label(s, kind, 0, label, sizeof label);
    /* what parse_value checks of a number written in a file: finite, a normal double, within the
     * most a scene number may be, within the key's range */
    const char *why = !isfinite(value)                          ? "not a finite number"
                      : fabs(value) > SCENE_MAX_ABS_VALUE          ? TOO_LARGE_REASON
                      : value != 0.0 && fabs(value) < DBL_MIN      ? "too large or too small for a double"
                                                                   : NULL;
    if (why || !in_range(k, value)) {
        char expected[160];
        describe_expected(k, expected, sizeof expected);
        snprintf(err->message, sizeof err->message, "key '%s' in %s: expected %s, got %.17g%s%s%s", dot + 1, label,
                 expected, value, why ? " (" : "", why ? why : "", why ? ")" : "");
        return -1;
    }
    union scene_key_value v = {.number = value};
    char reason[SCENE_PATH_LEN + 160];
    if (k->set) {
        if (k->set(s, s, &v, reason, sizeof reason) != 0) {
            snprintf(err->message, sizeof err->message, "key '%.64s' in %s: %.300s", dot + 1, label, reason);
            return -1;
        }
        return 0;
    }
    store_value(k, s, &v);
    return 0;
}
