// Stage 5, sky and final colour (paper section 4.3): rays without a hit look the sky up by
// their final direction: at the bounding sphere, or around a Schwarzschild mass at infinity (the
// earlier stages put it in the velocity). It writes the 8-bit image, and
// with HDR_OUTPUT the same colours unclamped into a float target (renderer_set_hdr). Captured and failed rays are black;
// a ray still travelling when its budget ran out shows render.unfinished_color, so that no one takes
// it for the sky.
uniform sampler2D u_image;
uniform sampler2D u_ray_velocity;
uniform vec3 u_unfinished_color;
uniform float u_sky_alpha;            // render.sky_alpha: the image's alpha where rays reached the sky
#ifdef SKY_CUBEMAP
uniform samplerCube u_sky;
#else
uniform vec3 u_sky_color;
#endif
#ifdef DOPPLER_COLOUR
uniform float u_sky_temperature;      // K; 0: an RGB sky
#endif

vec3 sky(vec3 direction)
{
#ifdef SKY_CUBEMAP
    return textureCube(u_sky, direction).rgb;
#else
    return u_sky_color;
#endif
}

void main()
{
    vec4 image = fetch(u_image);
    vec3 color = image.rgb;
    float alpha = image.a == CODE_SKY ? u_sky_alpha : 1.0;
    if (image.a == CODE_SKY) {
        color = sky(normalize(fetch(u_ray_velocity).xyz));
#ifdef DOPPLER_COLOUR
        // the sky rests at infinity (lapse 1)
        float doppler = observer_doppler(observer_view_direction()) / u_observer_lapse;
        vec3 black_body = rgb_luminance(color) * blackbody_colour(u_sky_temperature * doppler);
#ifdef SEARCHLIGHT
        vec3 rgb = color * (doppler * doppler * doppler * doppler);
#else
        vec3 rgb = color;
#endif
        color = u_sky_temperature > 0.0 ? black_body : rgb;
#endif
    }
    else if (image.a == CODE_UNFINISHED)
        color = u_unfinished_color;
    else if (image.a < -0.5)
        color = vec3(0.0);
#ifdef HDR_OUTPUT
    // a float target (16-bit PNG, PFM): the colour as shaded, brighter than white where it is
    gl_FragColor = vec4(max(color, 0.0), alpha);
#else
    gl_FragColor = vec4(clamp(color, 0.0, 1.0), alpha);
#endif
}
