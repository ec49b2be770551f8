/* Stage 5, sky and final colour (paper section 4.3), from the retired state of every ray. The
 * colour itself is shaders_es/sky_colour.glsl, which a single-pass frame also calls in its own pass
 * (stage_frame.c) when only the image is read. */
#include "render/stages.h"
#include <math.h>
#include <stdio.h>
#include "results/tone.h"

void sky_colour_set_uniforms(const struct program_uniforms *p, const struct renderer *r, int sky_unit)
{
    /* the camera's rays: the Doppler factor of a view direction, and the GPU's stars' straight
     * footprint */
    if (doppler_colour(r->scene) || r->star_map)
        observer_set_uniforms(p, r);
    if (doppler_colour(r->scene))
        uniform_float(p, "u_sky_temperature", r->scene->sky.temperature);
    if (r->sky_cubemap) {
        glActiveTexture(GL_TEXTURE0 + sky_unit);
        glBindTexture(GL_TEXTURE_CUBE_MAP, r->sky_cubemap);
        glUniform1i(program_uniform(p, "u_sky"), sky_unit);
    } else {
        uniform_vec3(p, "u_sky_color", r->scene->sky.color);
    }
    if (r->star_map) {
        const struct star_map *m = &r->star_layout;
        const struct sky *sky = &r->scene->sky;
        glActiveTexture(GL_TEXTURE0 + UNIT_STARS);
        glBindTexture(GL_TEXTURE_2D, r->star_map);
        glUniform1i(program_uniform(p, "u_star_map"), UNIT_STARS);
        glUniform2f(program_uniform(p, "u_star_map_size"), (float)m->width, (float)m->height);
        uniform_float(p, "u_star_map_cells", m->cells);
        uniform_float(p, "u_star_map_levels", m->levels);
        uniform_float(p, "u_star_map_chroma_row", m->chroma_y);
        uniform_float(p, "u_star_map_mask_row", m->mask_y);
        glUniform2f(program_uniform(p, "u_star_magnitudes"), (float)m->faintest, (float)(m->brightest - m->faintest));
        uniform_float(p, "u_star_brightness", sky->star_brightness);
        /* the brightest star's flux at rest (star_light.c's), from this run's brightness */
        double brightest = m->stars > 0 ? sky->star_brightness * pow(10.0, -0.4 * (m->brightest - 6.0)) : 0.0;
        uniform_float(p, "u_star_brightest_flux", brightest);
        uniform_float(p, "u_star_sigma", sky->star_size);
        uniform_float(p, "u_milky_way", sky->milky_way);
        uniform_vec3(p, "u_galactic_pole", r->galactic_pole);
        uniform_vec3(p, "u_galactic_x", r->galactic_x);
        uniform_vec3(p, "u_galactic_y", r->galactic_y);
    }
    if (tone_active(&r->scene->render))
        uniform_float(p, "u_gain", r->scene->render.gain);
    uniform_vec3(p, "u_unfinished_color", r->scene->render.unfinished_color);
    uniform_float(p, "u_sky_alpha", r->scene->render.sky_alpha);
}

#define STAR_DEFINES_(n) "#define GPU_STARS 1\n#define STAR_MAP_SLOTS_N " #n "\n"
#define STAR_DEFINES(n) STAR_DEFINES_(n)

void sky_colour_defines(const struct renderer *r, char *out, size_t len)
{
    const struct render_settings *rs = &r->scene->render;
    snprintf(out, len, "%s%s%s%s%s", r->sky_cubemap ? "#define SKY_CUBEMAP 1\n" : "",
             r->star_map ? STAR_DEFINES(STAR_MAP_SLOTS) : "",
             stars_from_neighbours(r) ? "#define STAR_FOOTPRINT_NEIGHBOURS 1\n" : "",
             tone_active(rs) ? "#define TONE_MAP 1\n" : "",
             tone_active(rs) && rs->tone_curve == TONE_CURVE_FILMIC ? "#define TONE_FILMIC 1\n" : "");
}

int stars_from_neighbours(const struct renderer *r)
{
    return r->star_map && !r->caps.derivatives;
}

static void set_sky(const struct program_uniforms *p, const void *arg)
{
    const struct renderer *r = arg;
    sky_colour_set_uniforms(p, r, UNIT_SKY);
    if (stars_from_neighbours(r))
        glUniform2f(program_uniform(p, "u_run_rays"), (float)r->rs.width, (float)r->rs.height);
}

int stage_sky(struct renderer *r, struct error *e)
{
    static const char *const files[] = {"common.glsl", "observer.glsl", "sky_colour.glsl", "stage_sky.glsl", NULL};
    struct raystate *rs = &r->rs;
    char sky_defines[SKY_COLOUR_DEFINES_LEN], defines[sizeof r->observer_defines + SKY_COLOUR_DEFINES_LEN];
    sky_colour_defines(r, sky_defines, sizeof sky_defines);
    snprintf(defines, sizeof defines, "%s%s", sky_defines, r->observer_defines);
    const struct stage_program *sp = program_cache_get(r->programs, files, defines, 0, e);
    if (!sp)
        return -1;
    struct pass_input in[] = {
        {"u_image", rs->result_image},
        {"u_ray_velocity", rs->result_velocity},
    };
    if (pass_run(r, sp, rs->final_color, 0, in, 2, set_sky, r, e) != 0)
        return -1;
    if (r->hdr_why) {
        /* the float colour into a ping-pong texture of the ray state, free once the rays are done */
        char hdr_defines[sizeof defines + 32];
        snprintf(hdr_defines, sizeof hdr_defines, "#define HDR_OUTPUT 1\n%s", defines);
        const struct stage_program *hp = program_cache_get(r->programs, files, hdr_defines, 0, e);
        if (!hp || pass_run(r, hp, raystate_hdr_color(rs), 0, in, 2, set_sky, r, e) != 0)
            return -1;
    }
    return gl_check("sky and final colour", e);
}
