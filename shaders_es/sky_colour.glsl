// The final colour of a ray (paper section 4.3), from what the earlier stages left in its image
// texel (a shaded colour, or an outcome code in alpha) and its final direction (the velocity): rays
// without a hit look the sky up by their final direction, at the bounding sphere or around a
// Schwarzschild mass at infinity. Captured and failed rays are black; a ray still travelling when
// its budget ran out shows render.unfinished_color, so that no one takes it for the sky. The sky
// stage (stage_sky.glsl) calls it on the result textures; a single-pass frame that only the image
// is read from calls it on its own results, in the same pass (FRAME_COLOUR, stage_frame.c).
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

// image: colour and outcome code (common.glsl); velocity: the final direction, any length.
vec4 sky_final_colour(vec4 image, vec3 velocity)
{
    vec3 color = image.rgb;
    float alpha = image.a == CODE_SKY ? u_sky_alpha : 1.0;
    if (image.a == CODE_SKY) {
        color = sky(normalize(velocity));
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
    return vec4(max(color, 0.0), alpha);
#else
    return vec4(clamp(color, 0.0, 1.0), alpha);
#endif
}

#ifdef FRAME_CODES
// Beside the final colour, for a summary of the frame (FRAME_WRITES_COLOUR_CODES, stage_frame.c),
// in an 8-bit target: in r the ray's outcome code (its image texel's alpha: an object's id, 0 to
// 63, or a code of common.glsl down to CODE_FAILED) plus 4, in g how many of the texel's four
// values the 32-bit float image texture would carry as not finite (beyond its largest finite
// value; NaN fails the test too). Each count is written a quarter above its byte, so that a
// driver that rounds and one that truncates store the same byte. On 32-bit paths only
// (renderer.c, run_single_pass).
float not_held(float x)
{
    return abs(x) <= 3.4028235e38 ? 0.0 : 1.0;
}

vec4 outcome_code_bytes(vec4 image)
{
    float bad = not_held(image.r) + not_held(image.g) + not_held(image.b) + not_held(image.a);
    return vec4((image.a + 4.25) / 255.0, (bad + 0.25) / 255.0, 0.0, 1.0);
}
#define WRITE_FRAME_COLOUR(image, direction) WRITE_TARGET0(sky_final_colour(image, direction)); WRITE_TARGET1(outcome_code_bytes(image))
#else
#define WRITE_FRAME_COLOUR(image, direction) WRITE_TARGET0(sky_final_colour(image, direction))
#endif
