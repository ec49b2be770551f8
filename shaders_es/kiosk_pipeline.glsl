// The pipeline view: the renderer's own ray state after the last pass, one panel per quantity
// (layout of the textures: common.glsl).
//   u_panel 0  ray positions: xyz / bound radius mapped to colour
//   u_panel 1  ray directions: the unit velocity mapped to colour
//   u_panel 2  depth: the segment index of the hit, blue (first) to red (last); grey: no hit (a
//              ray that reached the sky or fell in has a depth too: where it ended)
//   u_panel 3  step size: log2 of h against the scene's step, blue (shorter) to red (longer); with
//              steps of fixed size (u_steps_budget > 0, h the same everywhere) the steps each ray
//              took instead, blue (none) to red (the whole budget), black where the ray failed
//              (steps that grow away from the objects: the path each ray took, its state's w);
//              with exact orbits (u_orbit_rows > 0) the orbit table instead: one orbit per row,
//              from the observer (left) to where it ends (right), coloured by u = 1/r against the
//              horizon's, blue (far) to red (at the horizon), the photon sphere at 2/3; escaping
//              orbits in the upper half, captured ones in the lower, the critical launch angle
//              (the shadow's edge) on the middle line, launch angles outwards from it as the
//              table spaces them (logarithmically next to it)
//   u_panel 4  outcome: objects green, sky blue, captured black, unfinished red, failed magenta
//   u_panel 5  a colour scale below a panel: ramp() from its left end (0) to its right (1)
//   u_panel 6  the outcome panel's legend: its five colours side by side on grey
uniform sampler2D u_position;
uniform sampler2D u_velocity;
uniform sampler2D u_hit;
uniform sampler2D u_outcome;
uniform float u_panel;
uniform float u_bound_radius;
uniform float u_segments;
uniform float u_step;
uniform float u_steps_budget;       // the steps (or with far steps the path) every ray has, where they are fixed; else 0
uniform sampler2D u_orbit_table;
uniform vec2 u_orbit_size;          // the table texture's width and height in texels
uniform float u_orbit_columns;
uniform float u_orbit_rows;         // rows each side; 0: no table
uniform float u_orbit_u_capture;
varying vec2 v_uv;

const float PIPELINE_NO_HIT = 60000.0;

vec3 ramp(float t)
{
    t = clamp(t, 0.0, 1.0);
    return vec3(smoothstep(0.4, 0.9, t), sin(3.14159265 * t), 1.0 - smoothstep(0.1, 0.6, t));
}

vec3 outcome_colour(float code)
{
    return code > -0.5 ? vec3(0.2, 0.8, 0.3)
         : code > -1.5 ? vec3(0.3, 0.5, 1.0)
         : code > -2.5 ? vec3(0.0)
         : code > -3.5 ? vec3(0.9, 0.1, 0.1) : vec3(0.9, 0.1, 0.9);
}

vec3 orbit_table_panel(vec2 uv)
{
    float escaping = step(0.5, uv.y);
    float row = min(floor(abs(uv.y - 0.5) * 2.0 * u_orbit_rows), u_orbit_rows - 1.0) + (1.0 - escaping) * u_orbit_rows;
    float column = min(floor(uv.x * u_orbit_columns), u_orbit_columns - 1.0);
    float u = texture2D(u_orbit_table, (vec2(column, row) + 0.5) / u_orbit_size).x;
    return ramp(u / u_orbit_u_capture);
}

void main()
{
    vec3 c;
    if (u_panel < 0.5) {
        c = 0.5 + 0.5 * texture2D(u_position, v_uv).xyz / u_bound_radius;
    } else if (u_panel < 1.5) {
        vec3 v = texture2D(u_velocity, v_uv).xyz;
        float len = length(v);
        c = len > 0.0 ? 0.5 + 0.5 * v / len : vec3(0.0);
    } else if (u_panel < 2.5) {
        float depth = texture2D(u_hit, v_uv).w;
        bool hit = texture2D(u_outcome, v_uv).a > -0.5 && depth < PIPELINE_NO_HIT;
        c = hit ? ramp(depth / u_segments) : vec3(0.25);
    } else if (u_panel < 3.5 && u_orbit_rows > 0.0) {
        c = orbit_table_panel(v_uv);
    } else if (u_panel < 3.5 && u_steps_budget > 0.0) {
        float steps = texture2D(u_position, v_uv).w;
        c = steps >= 0.0 ? ramp(steps / u_steps_budget) : vec3(0.0);
    } else if (u_panel < 3.5) {
        float h = abs(texture2D(u_velocity, v_uv).w);
        c = h > 0.0 ? ramp(0.5 + 0.125 * log2(h / u_step)) : vec3(0.0);
    } else if (u_panel < 4.5) {
        c = outcome_colour(texture2D(u_outcome, v_uv).a);
    } else if (u_panel < 5.5) {
        c = ramp(v_uv.x);
    } else {
        // five swatches, each the middle 60% of its fifth of the strip
        float slot = min(floor(v_uv.x * 5.0), 4.0);
        float within = v_uv.x * 5.0 - slot;
        c = within > 0.2 && within < 0.8 ? outcome_colour(-slot) : vec3(0.5);
    }
    gl_FragColor = vec4(c, 1.0);
}
