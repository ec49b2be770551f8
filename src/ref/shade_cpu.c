#include "ref/shade_cpu.h"
#include "scene/texture_wrap.h"
#include "scene/camera.h"
#include "io/png_io.h"
#include "io/sample_average.h"
#include "physics/accretion.h"
#include "physics/blackbody.h"
#include "physics/relativity.h"
#include "results/dump.h"
#include <stdio.h>
#include <stdlib.h>

int cpu_materials_load(struct cpu_materials *mat, const struct scene *s, struct error *e)
{
    *mat = (struct cpu_materials){.scene = s};
    for (int i = 0; i < s->n_textures; i++) {
        struct cpu_texture *t = &mat->textures[i];
        if (png_read_rgba8(s->textures[i], SCENE_MAX_TEXTURE_SIZE, &t->width, &t->height, &t->rgba, e) != 0)
            return -1;
    }
    if (s->sky.type == SKY_CUBEMAP) {
        mat->has_sky_cubemap = 1;
        for (int f = 0; f < SCENE_CUBEMAP_FACES; f++) {
            char path[SCENE_PATH_LEN + 16];
            scene_cubemap_face_path(s->sky.cubemap, f, path, sizeof path);
            struct cpu_texture *t = &mat->sky[f];
            if (png_read_rgba8(path, SCENE_MAX_TEXTURE_SIZE, &t->width, &t->height, &t->rgba, e) != 0)
                return -1;
        }
    }
    if (doppler_colour(s)) {
        struct cpu_texture *t = &mat->blackbody;
        t->width = BLACKBODY_LUT_SIZE;
        t->height = 1;
        t->rgba = malloc(4 * BLACKBODY_LUT_SIZE);
        if (!t->rgba)
            return error_set(e, ERROR_RUNTIME, NULL, "out of memory");
        blackbody_lut_fill_exposed((enum blackbody_tone)scene_blackbody_tone(s), scene_reference_temperature(s), t->rgba);
        mat->blackbody_linear = scene_blackbody_tone(s) == TONE_SCENE_LINEAR;
    }
    return 0;
}

void cpu_materials_free(struct cpu_materials *mat)
{
    for (int i = 0; i < SCENE_MAX_TEXTURES; i++)
        free(mat->textures[i].rgba);
    for (int f = 0; f < 6; f++)
        free(mat->sky[f].rgba);
    free(mat->blackbody.rgba);
}

static vec3d texel(const struct cpu_texture *t, int x, int y)
{
    x = x < 0 ? 0 : x >= t->width ? t->width - 1 : x;
    y = y < 0 ? 0 : y >= t->height ? t->height - 1 : y;
    const unsigned char *p = t->rgba + 4 * ((size_t)y * t->width + x);
    return v3(p[0] / 255.0, p[1] / 255.0, p[2] / 255.0);
}

/* Texel index i of n along an axis that goes round (wraps) or stops at its edges. */
static int texel_index(int i, int n, int wraps)
{
    return wraps ? ((i % n) + n) % n : i;
}

/* GL_LINEAR with GL_CLAMP_TO_EDGE: texel centres at (i + 0.5) / size; along an axis that goes
 * round (wrap_s, wrap_t: scene/texture_wrap.h), the texels at its two ends are neighbours, as the
 * shaders filter them (texture_wrapped in shade.glsl). */
static vec3d sample_bilinear_wrapped(const struct cpu_texture *t, double s, double tc, int wrap_s, int wrap_t)
{
    s = s < 0.0 ? 0.0 : s > 1.0 ? 1.0 : s;
    tc = tc < 0.0 ? 0.0 : tc > 1.0 ? 1.0 : tc;
    double u = s * t->width - 0.5, v = tc * t->height - 0.5;
    int x0 = (int)floor(u), y0 = (int)floor(v);
    double fx = u - x0, fy = v - y0;
    int xa = texel_index(x0, t->width, wrap_s), xb = texel_index(x0 + 1, t->width, wrap_s);
    int ya = texel_index(y0, t->height, wrap_t), yb = texel_index(y0 + 1, t->height, wrap_t);
    vec3d bottom = v3_add(v3_scale(texel(t, xa, ya), 1.0 - fx), v3_scale(texel(t, xb, ya), fx));
    vec3d top = v3_add(v3_scale(texel(t, xa, yb), 1.0 - fx), v3_scale(texel(t, xb, yb), fx));
    return v3_add(v3_scale(bottom, 1.0 - fy), v3_scale(top, fy));
}

static vec3d sample_bilinear(const struct cpu_texture *t, double s, double tc)
{
    return sample_bilinear_wrapped(t, s, tc, 0, 0);
}

/* Face and (s, t) of a direction: table 3.21 of the OpenGL ES 3.2 specification. */
static vec3d sample_cube(const struct cpu_materials *mat, vec3d d)
{
    double ax = fabs(d.x), ay = fabs(d.y), az = fabs(d.z), sc, tc, ma;
    int face;
    if (ax >= ay && ax >= az) {
        face = d.x > 0.0 ? 0 : 1;
        sc = d.x > 0.0 ? -d.z : d.z;
        tc = -d.y;
        ma = ax;
    } else if (ay >= az) {
        face = d.y > 0.0 ? 2 : 3;
        sc = d.x;
        tc = d.y > 0.0 ? d.z : -d.z;
        ma = ay;
    } else {
        face = d.z > 0.0 ? 4 : 5;
        sc = d.z > 0.0 ? d.x : -d.x;
        tc = -d.y;
        ma = az;
    }
    if (!(ma > 0.0))
        return v3(0.0, 0.0, 0.0);
    return sample_bilinear(&mat->sky[face], 0.5 * (sc / ma + 1.0), 0.5 * (tc / ma + 1.0));
}

static vec3d vmul(vec3d a, vec3d b) { return v3(a.x * b.x, a.y * b.y, a.z * b.z); }

/* blackbody_colour() of shaders_es/observer.glsl: the table at its texel centres, ends clamped */
static vec3d blackbody_colour(const struct cpu_materials *mat, double temperature)
{
    double texel = (BLACKBODY_LUT_SIZE - 1) / log(BLACKBODY_T_MAX_K / BLACKBODY_T_MIN_K) *
                   (log(fmax(temperature, 1.0)) - log(BLACKBODY_T_MIN_K));
    texel = texel < 0.0 ? 0.0 : texel > BLACKBODY_LUT_SIZE - 1 ? BLACKBODY_LUT_SIZE - 1 : texel;
    if (!mat->blackbody_linear)
        return sample_bilinear(&mat->blackbody, (texel + 0.5) / BLACKBODY_LUT_SIZE, 0.5);
    /* the linear table: its four bytes interpolated as GL_LINEAR does, then decoded */
    int i = (int)floor(texel), j = i + 1 < BLACKBODY_LUT_SIZE ? i + 1 : i;
    double f = texel - i, rgba[4], lin[3];
    for (int c = 0; c < 4; c++)
        rgba[c] = ((1.0 - f) * mat->blackbody.rgba[4 * i + c] + f * mat->blackbody.rgba[4 * j + c]) / 255.0;
    blackbody_lut_decode(rgba, lin);
    return v3(linear_to_srgb_unclamped(lin[0]), linear_to_srgb_unclamped(lin[1]), linear_to_srgb_unclamped(lin[2]));
}

/* The frequency ratio at the camera of observer.glsl (scene/camera.h; a name of its own beside
 * shade_surface's variable) */
static double doppler_at_camera(const struct scene *s, vec3d view) { return camera_doppler(s, view); }

static double rgb_luminance(vec3d c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

static double pow4(double x) { return x * x * x * x; }

/* shade() of shaders_es/shade.glsl */
static vec3d shade_surface(const struct cpu_materials *mat, const struct ref_ray *ray, vec3d view)
{
    const struct scene *s = mat->scene;
    const struct material *m = &s->objects[ray->outcome].material;
    vec3d base = m->color;
    if (m->texture >= 0) {
        int wraps[2];
        texture_wraps(s->objects[ray->outcome].type, wraps);
        base = vmul(base, sample_bilinear_wrapped(&mat->textures[m->texture], ray->uv[0], ray->uv[1], wraps[0],
                                                  wraps[1]));
    }
    if (m->checker > 0.0) {
        double sx = floor(ray->uv[0] * m->checker), sy = floor(ray->uv[1] * m->checker);
        if (fmod(sx + sy, 2.0) != 0.0)
            base = m->checker_color;
    }
    if (m->clock_period > 0.0) {
        /* proper time when the light left the clock (straight rays: flat space only) */
        struct object_motion clock = {{0.0, 0.0, 0.0}, 1.0, {0.0, 0.0, 0.0}};
        object_motion(&s->objects[ray->outcome], &clock);
        double emitted = s->observer.time - v3_len(v3_sub(ray->hit, s->camera.position));
        if (clock_face_mark(ray->uv[0], ray->uv[1], proper_time(&clock, emitted, ray->hit) / m->clock_period))
            base = v3(0.05, 0.05, 0.05);
    }
    vec3d color = v3_add(m->emission, v3_scale(vmul(s->ambient_light, base), m->ambient));
    /* a moving surface is lit in its rest frame (Eq. 17): the directions of the light arriving and
     * leaving are aberrated into it, and its normal is a rest-frame normal */
    struct object_motion motion;
    int moving = object_motion(&s->objects[ray->outcome], &motion);
    vec3d v_out = v3_scale(v3_normalize(ray->velocity), -1.0);
    vec3d to_viewer = moving ? propagation_in_frame(motion.beta, v_out) : v_out;
    vec3d n = v3_dot(ray->normal, to_viewer) < 0.0 ? v3_scale(ray->normal, -1.0) : ray->normal;
    int doppler = doppler_colour(s);
    double camera_doppler = doppler ? doppler_at_camera(s, view) : 1.0;
    double reflectance = 0.5 * (0.3 * base.x + 0.59 * base.y + 0.11 * base.z + 1.0);   /* Eq. 18 */
    vec3d black_bodies = v3(0.0, 0.0, 0.0);
    /* the light the surface sends itself */
    double emitted = camera_doppler * (moving ? emission_doppler(motion.beta, v_out) : static_lapse_shown(s, ray->hit));
    double temperature = m->temperature;
    if (m->accretion) {
        /* matter on its orbit about the mass, at its place's temperature (physics/accretion.h) */
        const struct object *o = &s->objects[ray->outcome];
        vec3d from_mass = v3_sub(ray->hit, s->model.center);
        double lambda_z = photon_lambda_z(model_gravity_mass(&s->model), from_mass, ray->velocity, v3_normalize(o->normal));
        emitted = camera_doppler * emitted_ratio_shown(s, ray->hit, keplerian_emitter_shift(model_gravity_mass(&s->model),
                                                                                           v3_len(from_mass), lambda_z));
        temperature = thin_disk_temperature(m->temperature, o->inner_radius, v3_len(v3_sub(ray->hit, o->center)));
    }
    if (doppler && m->temperature > 0.0) {
        color = v3_sub(color, m->emission);
        black_bodies = v3_scale(blackbody_colour(mat, temperature * emitted), rgb_luminance(m->emission));
    }
    for (int i = 0; i < s->n_lights; i++) {
        vec3d to_light = v3_normalize(v3_sub(s->lights[i].position, ray->hit));
        vec3d v_in = v3_scale(to_light, -1.0);
        if (moving)
            to_light = v3_scale(propagation_in_frame(motion.beta, v_in), -1.0);
        double lambert = fmax(v3_dot(n, to_light), 0.0);
        vec3d halfway = v3_normalize(v3_add(to_light, to_viewer));
        double specular = lambert > 0.0 ? pow(fmax(v3_dot(n, halfway), 0.0), m->shininess) : 0.0;
        vec3d lit = v3_add(v3_scale(base, m->diffuse * lambert), v3(m->specular * specular, m->specular * specular,
                                                                     m->specular * specular));
        if (doppler && s->lights[i].temperature > 0.0) {
            double d = camera_doppler * (moving ? reflection_doppler(motion.beta, v_in, v_out)
                                                : static_lapse_shown(s, s->lights[i].position));
            double f = reflectance * (m->diffuse * lambert + m->specular * specular);
            vec3d c = blackbody_colour(mat, s->lights[i].temperature * d);
            black_bodies = v3_add(black_bodies, v3_scale(vmul(s->lights[i].color, c), f));
        } else {
            color = v3_add(color, vmul(s->lights[i].color, lit));
        }
    }
    if (s->observer.effects == EFFECTS_SEARCHLIGHT)
        color = v3_scale(color, pow4(emitted));
    return v3_add(color, black_bodies);
}

/* sky_colour.glsl: an RGB sky, or black bodies at infinity lent their luminance by the sky's texels */
static vec3d shade_sky(const struct cpu_materials *mat, const struct ref_ray *ray, vec3d view)
{
    const struct scene *s = mat->scene;
    vec3d c = mat->has_sky_cubemap ? sample_cube(mat, v3_normalize(ray->velocity)) : s->sky.color;
    if (!doppler_colour(s))
        return c;
    double d = doppler_at_camera(s, view);
    if (s->sky.temperature > 0.0)
        return v3_scale(blackbody_colour(mat, s->sky.temperature * d), rgb_luminance(c));
    return s->observer.effects == EFFECTS_SEARCHLIGHT ? v3_scale(c, pow4(d)) : c;
}

void cpu_shade_color(const struct cpu_materials *mat, const struct ref_ray *ray, vec3d view, double rgba[4])
{
    vec3d c = v3(0.0, 0.0, 0.0);
    if (ray->outcome >= 0)
        c = shade_surface(mat, ray, view);
    else if (ray->outcome == DUMP_SKY)
        c = shade_sky(mat, ray, view);
    else if (ray->outcome == DUMP_UNFINISHED)
        c = mat->scene->render.unfinished_color;
    /* as the sky stage writes its float target: negative parts cut, brighter than white kept */
    rgba[0] = fmax(c.x, 0.0);
    rgba[1] = fmax(c.y, 0.0);
    rgba[2] = fmax(c.z, 0.0);
    rgba[3] = ray->outcome == DUMP_SKY ? mat->scene->render.sky_alpha : 1.0;
}

