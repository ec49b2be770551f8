// The camera and its motion (Müller, Grottel and Weiskopf 2010, section 3.1): the direction a pixel
// looks in, in the observer's frame and in the scene's frame, and the frequency ratio of the light
// it receives (docs/RELATIVITY.md).
uniform vec3 u_camera_position;
uniform vec3 u_camera_forward;        // unit view direction
uniform vec3 u_camera_right;          // scaled by tan(fov / 2) * aspect
uniform vec3 u_camera_up;             // scaled by tan(fov / 2)
uniform vec2 u_pixel_origin;          // image pixel of ray-state texel (0, 0); (0, 0) for a full frame
uniform vec2 u_image_size;
uniform float u_observer_time;        // scene time of the picture (c = 1)
#ifdef OBSERVER_MOVING
uniform vec3 u_observer_beta;         // velocity / c in the scene's (or the static observer's) frame
uniform float u_observer_gamma;
#endif

// Pixel centres at (i + 0.5) / W (paper 004's eye rays): the view direction of the ray at `ray`
// (from (0, 0)), and of the fragment's own.
vec3 observer_view_direction_at(vec2 ray)
{
    vec2 pixel_centre = u_pixel_origin + ray + 0.5;
    vec2 ndc = pixel_centre / u_image_size * 2.0 - 1.0;
    return normalize(u_camera_forward + ndc.x * u_camera_right + ndc.y * u_camera_up);
}

vec3 observer_view_direction()
{
    return observer_view_direction_at(ray_pixel());
}

// Aberration, Eq. 3-4: the photon's four-momentum boosted from the observer's frame to the scene's.
// The factor 1 / (gamma (1 - beta.d)) of the exact formula only scales, so normalize() is exact.
vec3 observer_scene_direction(vec3 d)
{
#ifdef OBSERVER_MOVING
    float g = u_observer_gamma;
    float along = dot(u_observer_beta, d);
    float boost = g * g / (g + 1.0) * along - g;
    return normalize(d + boost * u_observer_beta);
#else
    return d;
#endif
}

#if defined(GPU_STARS) || defined(TONE_MAP) || defined(BLACKBODY_LINEAR)
// the sRGB transfer function and its inverse (io/sample_average.c), for values beyond 1 too
float srgb_decode(float x)
{
    return x <= 0.04045 ? x / 12.92 : pow((x + 0.055) / 1.055, 2.4);
}

float srgb_encode(float x)
{
    return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}
#endif

#ifdef BLACKBODY_LINEAR
const float BLACKBODY_LOG2_SPAN = 24.0;   // physics/blackbody.h
#endif

#ifdef DOPPLER_COLOUR
uniform sampler2D u_blackbody;        // sRGB of black bodies, temperatures log-spaced
uniform float u_blackbody_log_min;    // ln(T) of the first texel
uniform float u_blackbody_texels;     // texels per unit of ln(T)
uniform float u_blackbody_size;       // texels
uniform vec3 u_gravity_center;
uniform float u_gravity_mass;         // Schwarzschild M; 0 without gravity
uniform float u_observer_lapse;       // sqrt(1 - 2M/r) at the camera; 1 without gravity or its shift
uniform float u_gravity_shown;        // 1: colours shifted by gravity too; 0: by motion alone
                                      // (observer.gravitational_shift = off)

// nu_observer / nu_scene of light arriving along the view direction d: 1 / (gamma (1 - beta.d)).
float observer_doppler(vec3 d)
{
#ifdef OBSERVER_MOVING
    float approach = 1.0 - dot(u_observer_beta, d);
    return 1.0 / (u_observer_gamma * approach);
#else
    return 1.0;
#endif
}

// sqrt(1 - 2M/r) of a static emitter at p; the frequency ratio between static observers is the
// ratio of their lapses.
float static_lapse(vec3 p)
{
    float r = max(length(p - u_gravity_center), 1e-9);
    return sqrt(max(1.0 - 2.0 * u_gravity_mass / r, 0.0));
}

// scene/camera.h's static_lapse_shown and emitted_ratio_shown: the lapse at p as the image shows
// it, and a ratio of which it is a factor with it taken out where gravity's shift is not shown
float static_lapse_shown(vec3 p)
{
    return u_gravity_shown > 0.5 ? static_lapse(p) : 1.0;
}

float emitted_ratio_shown(vec3 p, float ratio)
{
    float lapse = static_lapse(p);
    return u_gravity_shown > 0.5 || lapse <= 0.0 ? ratio : ratio / lapse;
}

#ifdef ACCRETION
// physics/accretion.c's keplerian_emitter_shift: 1 / (u^t (1 - Omega lambda_z)) of matter on a
// circular orbit at p about the mass, in the plane with unit normal axis (counterclockwise about
// it), for light reaching the camera along the traced direction d (the photon travels along -d).
// The static emitter's factor is static_lapse(p); that of a static observer at the camera is
// applied by the caller.
float keplerian_shift(vec3 p, vec3 d, vec3 axis)
{
    vec3 y = p - u_gravity_center;
    float r = max(length(y), 1e-9);
    vec3 radial = y / r;
    vec3 dir = normalize(d);
    float along = dot(dir, radial);
    float across_length = length(dir - along * radial);
    float safe_across = max(across_length, 1e-30);
    // Binet's first integral: (du/dphi)^2 + u^2 (1 - 2 M u) = 1 / b^2
    float u = 1.0 / r;
    float w = -u * along / safe_across;
    float b = inversesqrt(max(w * w + u * u * (1.0 - 2.0 * u_gravity_mass * u), 1e-30));
    // the photon's angular momentum over its energy, about the axis
    float lambda_z = b * dot(cross(radial, -dir), axis) / safe_across;
    float omega = sqrt(u_gravity_mass * u * u * u);
    float inverse_ut = sqrt(max(1.0 - 3.0 * u_gravity_mass * u, 0.0));
    return inverse_ut / (1.0 - omega * lambda_z);
}

// physics/accretion.c's thin_disk_temperature: peak at r = 49/36 r_in, 0 inside r_in.
float thin_disk_temperature(float peak, float r_in, float r)
{
    float r_peak = 1.3611111111111112 * r_in;
    float ratio = r_in / max(r, 1e-30);
    float profile = pow(r_peak / max(r, 1e-30), 0.75) * pow(max(7.0 * (1.0 - sqrt(ratio)), 0.0), 0.25);
    return r > r_in ? peak * profile : 0.0;
}
#endif

// The display colour of a black body at its apparent temperature: texel centres at
// (0.5 + u_blackbody_texels * (ln T - ln T_min)) / size, clamped to the table's ends. With the
// image's filmic curve (BLACKBODY_LINEAR, physics/blackbody.h TONE_SCENE_LINEAR) the table holds
// the chromaticity and log2 of the brightness: the colour may pass white, for the curve to bring
// it to the screen.
vec3 blackbody_colour(float temperature)
{
    float texel = u_blackbody_texels * (log(max(temperature, 1.0)) - u_blackbody_log_min);
    float s = (clamp(texel, 0.0, u_blackbody_size - 1.0) + 0.5) / u_blackbody_size;
#ifdef BLACKBODY_LINEAR
    vec4 t = texture2D(u_blackbody, vec2(s, 0.5));
    vec3 lin = vec3(srgb_decode(t.r), srgb_decode(t.g), srgb_decode(t.b)) * exp2((t.a - 0.5) * BLACKBODY_LOG2_SPAN);
    return vec3(srgb_encode(lin.r), srgb_encode(lin.g), srgb_encode(lin.b));
#else
    return texture2D(u_blackbody, vec2(s, 0.5)).rgb;
#endif
}

// 0.2126 R + 0.7152 G + 0.0722 B: the luminance an RGB texel lends a black-body emitter.
float rgb_luminance(vec3 c)
{
    return dot(c, vec3(0.2126, 0.7152, 0.0722));
}
#endif
