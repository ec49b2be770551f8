/* The camera and its motion on the GPU: the uniforms of shaders_es/observer.glsl, its variant
 * defines, and the black-body lookup table of the Doppler colour effects. */
#include "physics/blackbody.h"
#include "physics/relativity.h"
#include "render/stages.h"
#include "scene/camera.h"
#include <math.h>
#include <stdio.h>

int observer_defines(const struct scene *s, char *out, size_t len)
{
    int n = snprintf(out, len, "%s%s%s%s", observer_moving(s) ? "#define OBSERVER_MOVING 1\n" : "",
                     doppler_colour(s) ? "#define DOPPLER_COLOUR 1\n" : "",
                     s->observer.effects == EFFECTS_SEARCHLIGHT ? "#define SEARCHLIGHT 1\n" : "",
                     doppler_colour(s) && scene_blackbody_tone(s) == TONE_SCENE_LINEAR ? "#define BLACKBODY_LINEAR 1\n" : "");
    return n < 0 || (size_t)n >= len ? -1 : 0;
}

void observer_set_uniforms(const struct program_uniforms *p, const struct renderer *r)
{
    const struct scene *s = r->scene;
    vec3d forward = v3_normalize(v3_sub(s->camera.look_at, s->camera.position));
    vec3d right = v3_normalize(v3_cross(forward, s->camera.up));
    vec3d up = v3_cross(right, forward);
    double tan_half = tan(s->camera.fov_deg * PI_D / 360.0);
    double aspect = (double)s->render.width / (double)s->render.height;
    uniform_vec3(p, "u_camera_position", s->camera.position);
    uniform_vec3(p, "u_camera_forward", forward);
    uniform_vec3(p, "u_camera_right", v3_scale(right, tan_half * aspect));
    uniform_vec3(p, "u_camera_up", v3_scale(up, tan_half));
    /* the sample's offset is a multiple of 1/1024 (scene/pixel_samples.h): exact in the sum */
    glUniform2f(program_uniform(p, "u_pixel_origin"), (float)(r->origin_x + r->subpixel_x),
                (float)(r->origin_y + r->subpixel_y));
    glUniform2f(program_uniform(p, "u_subpixel_ndc"), (float)(2.0 * r->subpixel_x / s->render.width),
                (float)(2.0 * r->subpixel_y / s->render.height));
    /* a band of the image (rows or a tile) as the whole viewport: its centre and scale in the
     * image's normalised device coordinates */
    double band_w = r->have_state ? r->rs.width : s->render.width, band_h = r->have_state ? r->rs.height : s->render.height;
    glUniform4f(program_uniform(p, "u_band_ndc"), (float)(s->render.width / band_w), (float)(s->render.height / band_h),
                (float)((2.0 * r->origin_x + band_w) / s->render.width - 1.0),
                (float)((2.0 * r->origin_y + band_h) / s->render.height - 1.0));
    glUniform2f(program_uniform(p, "u_image_size"), (float)s->render.width, (float)s->render.height);
    uniform_float(p, "u_observer_time", s->observer.time);
    if (observer_moving(s)) {
        uniform_vec3(p, "u_observer_beta", s->observer.velocity);
        uniform_float(p, "u_observer_gamma", lorentz_gamma(s->observer.velocity));
    }
    if (!doppler_colour(s))
        return;
    glActiveTexture(GL_TEXTURE0 + UNIT_BLACKBODY(r));
    glBindTexture(GL_TEXTURE_2D, r->blackbody_lut);
    glUniform1i(program_uniform(p, "u_blackbody"), UNIT_BLACKBODY(r));
    uniform_float(p, "u_blackbody_log_min", log(BLACKBODY_T_MIN_K));
    uniform_float(p, "u_blackbody_texels", (BLACKBODY_LUT_SIZE - 1) / log(BLACKBODY_T_MAX_K / BLACKBODY_T_MIN_K));
    uniform_float(p, "u_blackbody_size", BLACKBODY_LUT_SIZE);
    double mass = model_gravity_mass(&s->model);
    uniform_vec3(p, "u_gravity_center", s->model.center);
    uniform_float(p, "u_gravity_mass", mass);
    uniform_float(p, "u_observer_lapse", static_lapse_shown(s, s->camera.position));
    uniform_float(p, "u_gravity_shown", s->observer.gravitational_shift ? 1.0 : 0.0);
}

int observer_lut_load(struct renderer *r, struct error *e)
{
    if (!doppler_colour(r->scene))
        return 0;
    int tone = scene_blackbody_tone(r->scene);
    double reference = scene_reference_temperature(r->scene);
    if (r->blackbody_lut && r->blackbody_tone == tone && r->blackbody_reference == reference)
        return 0;
    observer_lut_release(r);
    r->blackbody_tone = tone;
    r->blackbody_reference = reference;
    unsigned char rgba[4 * BLACKBODY_LUT_SIZE];
    blackbody_lut_fill_exposed((enum blackbody_tone)tone, reference, rgba);
    glGenTextures(1, &r->blackbody_lut);
    glBindTexture(GL_TEXTURE_2D, r->blackbody_lut);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, BLACKBODY_LUT_SIZE, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    return gl_check("uploading the black-body table", e);
}

void observer_lut_release(struct renderer *r)
{
    if (r->blackbody_lut)
        glDeleteTextures(1, &r->blackbody_lut);
    r->blackbody_lut = 0;
}
