/* Stage 5, sky and final colour (paper section 4.3), from the retired state of every ray. The
 * colour itself is shaders_es/sky_colour.glsl, which a single-pass frame also calls in its own pass
 * (stage_frame.c) when only the image is read. */
#include "render/stages.h"
#include <stdio.h>

void sky_colour_set_uniforms(const struct program_uniforms *p, const struct renderer *r, int sky_unit)
{
    if (doppler_colour(r->scene)) {
        observer_set_uniforms(p, r);
        uniform_float(p, "u_sky_temperature", r->scene->sky.temperature);
    }
    if (r->sky_cubemap) {
        glActiveTexture(GL_TEXTURE0 + sky_unit);
        glBindTexture(GL_TEXTURE_CUBE_MAP, r->sky_cubemap);
        glUniform1i(program_uniform(p, "u_sky"), sky_unit);
    } else {
        uniform_vec3(p, "u_sky_color", r->scene->sky.color);
    }
    uniform_vec3(p, "u_unfinished_color", r->scene->render.unfinished_color);
    uniform_float(p, "u_sky_alpha", r->scene->render.sky_alpha);
}

const char *sky_colour_defines(const struct renderer *r)
{
    return r->sky_cubemap ? "#define SKY_CUBEMAP 1\n" : "";
}

static void set_sky(const struct program_uniforms *p, const void *arg)
{
    sky_colour_set_uniforms(p, arg, UNIT_SKY);
}

int stage_sky(struct renderer *r, struct error *e)
{
    static const char *const files[] = {"common.glsl", "observer.glsl", "sky_colour.glsl", "stage_sky.glsl", NULL};
    struct raystate *rs = &r->rs;
    char defines[sizeof r->observer_defines + 32];
    snprintf(defines, sizeof defines, "%s%s", sky_colour_defines(r), r->observer_defines);
    const struct stage_program *sp = program_cache_get(r->programs, files, defines, 0, e);
    if (!sp)
        return -1;
    struct pass_input in[] = {
        {"u_image", rs->result_image},
        {"u_ray_velocity", rs->result_velocity},
    };
    if (pass_run(r, sp, rs->final_color, 0, in, 2, set_sky, r, e) != 0)
        return -1;
    if (r->hdr) {
        /* the float colour into a ping-pong texture of the ray state, free once the rays are done */
        char hdr_defines[sizeof defines + 32];
        snprintf(hdr_defines, sizeof hdr_defines, "#define HDR_OUTPUT 1\n%s", defines);
        const struct stage_program *hp = program_cache_get(r->programs, files, hdr_defines, 0, e);
        if (!hp || pass_run(r, hp, raystate_hdr_color(rs), 0, in, 2, set_sky, r, e) != 0)
            return -1;
    }
    return gl_check("sky and final colour", e);
}
