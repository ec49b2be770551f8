// Local illumination (paper section 3.4): ambient, emissive, texture-modulated material and
// the paper's "fake" Blinn-Phong, lit along straight connections to the light sources.
uniform vec3 u_ambient_light;
#if LIGHT_COUNT > 0
uniform vec3 u_light_position[LIGHT_COUNT];
uniform vec3 u_light_color[LIGHT_COUNT];
#ifdef DOPPLER_COLOUR
uniform float u_light_temperature[LIGHT_COUNT];   // K; 0: an RGB light
#endif
#endif

#ifdef TEXTURED
// An object's texture at uv. Along a coordinate that goes round (the sphere's longitude, the
// disk's angle: src/scene/texture_wrap.h) the texels at its two ends are neighbours, and filtering
// blends them across the seam as GL_REPEAT would, which ES 2.0 allows only for power-of-two sizes:
// there, two lookups at the texel centres on either side (where GL_LINEAR gives the texel itself
// along that coordinate), mixed. wrap_size: the texture's size along each coordinate that goes
// round, 0 along one that does not (then both lookups are the plain one). ref/shade_cpu.c filters
// the same way.
vec3 texture_wrapped(sampler2D t, vec2 uv, vec2 wrap_size)
{
    vec2 wraps = vec2(greaterThan(wrap_size, vec2(0.0)));
    vec2 size = max(wrap_size, vec2(1.0));
    vec2 x = uv * size - 0.5;
    vec2 below = floor(x);
    vec2 f = x - below;
    vec2 centre_below = (mod(below, size) + 0.5) / size;
    vec2 centre_above = (mod(below + 1.0, size) + 0.5) / size;
    vec3 a = texture2D(t, mix(uv, centre_below, wraps)).rgb;
    vec3 b = texture2D(t, mix(uv, centre_above, wraps)).rgb;
    return mix(a, b, dot(f, wraps));
}
#endif

#ifdef MOVING_OBJECTS
// beta, gamma of the surface being shaded (beta 0 for one at rest): it is lit in its rest frame
vec4 surface_motion;

// A photon travelling along unit k in the scene frame travels along this in the frame moving with
// beta (Eq. 4 the other way round).
vec3 propagation_in_frame(vec3 k, vec4 beta_gamma)
{
    float g = beta_gamma.w;
    float along = dot(beta_gamma.xyz, k);
    return normalize(k + (g * g / (g + 1.0) * along - g) * beta_gamma.xyz);
}
#endif

#ifdef CLOCKS
// turns of the clock hand of the surface being shaded; negative: it has no clock
float surface_clock_turns;

// The clock face of relativity.c's clock_face_mark(): a ring and one hand in texture space.
bool clock_face_mark(vec2 uv, float turns)
{
    vec2 q = uv - 0.5;
    float angle = 6.28318530718 * fract(turns);
    vec2 hand = vec2(sin(angle), cos(angle));
    float along = dot(q, hand);
    float across = abs(q.x * hand.y - q.y * hand.x);
    bool on_hand = along >= 0.0 && along <= 0.38 && across <= 0.025;
    bool on_ring = abs(length(q) - 0.45) <= 0.02;
    return on_hand || on_ring;
}
#endif

#ifdef DOPPLER_COLOUR
// K; above 0 the surface's emission is a black body whose luminance the RGB emission gives
float surface_emission_temperature;
#ifdef ACCRETION
// above 0: the surface is an accretion disk with this inner radius (physics/accretion.h), its
// temperature the peak of a thin disk's profile, its matter on Keplerian orbits about its normal
float surface_accretion_inner;
float surface_accretion_radius;  // the hit's distance from the disk's own centre: its temperature's radius
#endif
#endif

struct surface_material {
    vec3 base;                 // colour, already modulated by the texture
    float checker;             // squares per unit texture coordinate; 0: none
    vec3 emission;
    vec4 factors;              // ambient, diffuse, specular factors, shininess
    vec3 checker_color;
};

vec3 shade(vec3 p, vec3 normal, vec2 uv, vec3 ray_direction, surface_material m)
{
    vec3 base = m.base;
    if (m.checker > 0.0) {
        vec2 square = floor(uv * m.checker);
        if (mod(square.x + square.y, 2.0) >= 1.0)
            base = m.checker_color;
    }
#ifdef CLOCKS
    if (surface_clock_turns >= 0.0 && clock_face_mark(uv, surface_clock_turns))
        base = vec3(0.05);
#endif
    vec3 color = m.emission + m.factors.x * u_ambient_light * base;
    vec3 v_out = -ray_direction;                                 // the photon's way to the eye
#ifdef DOPPLER_COLOUR
    // light reaching the observer from a static emitter at e: D = D_kinematic * lapse(e) / lapse(camera)
    float doppler_at_camera = observer_doppler(observer_view_direction()) / u_observer_lapse;
    // the paper's reflectance factor f_ar (Eq. 18) takes the grey value of the RGB material
    float reflectance = 0.5 * (dot(base, vec3(0.3, 0.59, 0.11)) + 1.0);
    vec3 black_bodies = vec3(0.0);
    // light the surface sends itself: D = D_kinematic * lapse(p) / lapse(camera), or its motion's
#ifdef MOVING_OBJECTS
    float emitted_doppler = doppler_at_camera / (surface_motion.w * (1.0 - dot(surface_motion.xyz, v_out)));
#else
    float emitted_doppler = doppler_at_camera * static_lapse_shown(p);
#endif
    float emitted_temperature = surface_emission_temperature;
#ifdef ACCRETION
    // matter on its orbit, at its place's temperature (computed for every surface, then selected:
    // see the precision note in common.glsl)
    bool accretes = surface_accretion_inner > 0.0;
    float orbiting_doppler = doppler_at_camera * emitted_ratio_shown(p, keplerian_shift(p, ray_direction, normal));
    float disk_temperature = thin_disk_temperature(surface_emission_temperature, surface_accretion_inner,
                                                   surface_accretion_radius);
    emitted_doppler = accretes ? orbiting_doppler : emitted_doppler;
    emitted_temperature = accretes ? disk_temperature : emitted_temperature;
#endif
    vec3 glow = rgb_luminance(m.emission) * blackbody_colour(emitted_temperature * emitted_doppler);
    bool glows = surface_emission_temperature > 0.0;
    black_bodies += glows ? glow : vec3(0.0);
    color -= glows ? m.emission : vec3(0.0);
#endif
#if LIGHT_COUNT > 0
#ifdef MOVING_OBJECTS
    vec3 to_viewer = propagation_in_frame(v_out, surface_motion);
#else
    vec3 to_viewer = v_out;
#endif
    vec3 n = dot(normal, to_viewer) < 0.0 ? -normal : normal;    // surfaces are two-sided
    for (int i = 0; i < LIGHT_COUNT; i++) {
        vec3 to_light = normalize(u_light_position[i] - p);
#ifdef MOVING_OBJECTS
        vec3 v_in = -to_light;
        to_light = -propagation_in_frame(v_in, surface_motion);
#endif
        float lambert = max(dot(n, to_light), 0.0);
        vec3 halfway = normalize(to_light + to_viewer);
        float specular = lambert > 0.0 ? pow(max(dot(n, halfway), 0.0), m.factors.w) : 0.0;
        vec3 rgb_lit = u_light_color[i] * (m.factors.y * lambert * base + m.factors.z * specular);
#ifdef DOPPLER_COLOUR
#ifdef MOVING_OBJECTS
        // Eq. 17: reflected by a moving surface, nu_out / nu_in = (1 - beta.v_in) / (1 - beta.v_out)
        float reflected = (1.0 - dot(surface_motion.xyz, v_in)) / (1.0 - dot(surface_motion.xyz, v_out));
        float light_doppler = doppler_at_camera * reflected;
#else
        float light_doppler = doppler_at_camera * static_lapse_shown(u_light_position[i]);
#endif
        vec3 black_body = u_light_color[i] * reflectance * (m.factors.y * lambert + m.factors.z * specular) *
                          blackbody_colour(u_light_temperature[i] * light_doppler);
        bool is_black_body = u_light_temperature[i] > 0.0;
        black_bodies += is_black_body ? black_body : vec3(0.0);
        rgb_lit = is_black_body ? vec3(0.0) : rgb_lit;
#endif
        color += rgb_lit;
    }
#endif
#ifdef SEARCHLIGHT
    // RGB light has no spectrum to shift: its bolometric radiance scales with D^4
    color *= emitted_doppler * emitted_doppler * emitted_doppler * emitted_doppler;
#endif
#ifdef DOPPLER_COLOUR
    color += black_bodies;
#endif
    return color;
}
