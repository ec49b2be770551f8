// Local illumination (paper section 3.4): ambient, emissive, texture-modulated material and
// the paper's "fake" Blinn-Phong, lit along straight connections to the light sources.
uniform vec3 u_color;
uniform vec3 u_emission;
uniform vec4 u_material;              // ambient, diffuse, specular factors, shininess
uniform float u_checker;              // squares per unit texture coordinate; 0: none
uniform vec3 u_checker_color;
uniform vec3 u_ambient_light;
#ifdef TEXTURED
uniform sampler2D u_texture;
#endif
#if LIGHT_COUNT > 0
uniform vec3 u_light_position[LIGHT_COUNT];
uniform vec3 u_light_color[LIGHT_COUNT];
#endif

vec3 shade(vec3 p, vec3 normal, vec2 uv, vec3 ray_direction)
{
    vec3 base = u_color;
#ifdef TEXTURED
    base *= texture2D(u_texture, uv).rgb;
#endif
    if (u_checker > 0.0) {
        vec2 square = floor(uv * u_checker);
        if (mod(square.x + square.y, 2.0) >= 1.0)
            base = u_checker_color;
    }
    vec3 color = u_emission + u_material.x * u_ambient_light * base;
#if LIGHT_COUNT > 0
    vec3 to_viewer = -ray_direction;
    vec3 n = dot(normal, to_viewer) < 0.0 ? -normal : normal;    // surfaces are two-sided
    for (int i = 0; i < LIGHT_COUNT; i++) {
        vec3 to_light = normalize(u_light_position[i] - p);
        float lambert = max(dot(n, to_light), 0.0);
        vec3 halfway = normalize(to_light + to_viewer);
        float specular = lambert > 0.0 ? pow(max(dot(n, halfway), 0.0), u_material.w) : 0.0;
        color += u_light_color[i] * (u_material.y * lambert * base + u_material.z * specular);
    }
#endif
    return color;
}
