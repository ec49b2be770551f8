// Stage 2 for Schwarzschild without integration (render.method = orbit_table): segment
// u_segment_index of each ray is the chord between two exact points of its orbit, read from the
// orbit table (orbit_table.glsl). A ray's orbit is split into `segments` chords of about equal
// sag, as few as keep the chords within render.chord_tolerance of the orbit; where a chord leaves
// the bounding sphere it ends where the orbit does (orbit_chord). The ray state keeps the layout of
// common.glsl: position.w counts segments, velocity.w holds the fraction s reached.
uniform sampler2D u_ray_position;
uniform sampler2D u_ray_velocity;
uniform sampler2D u_hit;
uniform float u_segment_index;

void main()
{
    vec4 position = fetch(u_ray_position);
    vec4 velocity = fetch(u_ray_velocity);
    bool running = fetch(u_hit).w >= NO_HIT && position.w >= 0.0;
    orbit_ray ray = orbit_ray_of();
    float k = u_segment_index;
    vec2 q;
    float s;
    bool leaves;
    orbit_chord(ray, k, q, s, leaves);
    vec3 b = orbit_chord_point(ray, q, s, leaves);
    // a ray that leaves looks the sky up along its direction at infinity
    vec3 tangent = orbit_tangent(ray, q, s);
    vec3 escape = orbit_direction_at_infinity(ray);
    vec3 direction = leaves ? escape : tangent;
    bool moves = running && k < ray.segments;
    float next_steps = k + 1.0;
    vec4 new_position = vec4(b, next_steps);
    // velocity.w: the fraction of the orbit reached, 1 for a ray that left (it goes to infinity)
    float reached = leaves ? 1.0 : s;
    vec4 new_velocity = vec4(direction, reached);
    WRITE_TARGET0(moves ? new_position : position);
    WRITE_TARGET1(moves ? new_velocity : velocity);
}
