// Stage 2 for Schwarzschild without integration (render.method = orbit_table): segment
// u_segment_index of each ray is the chord between two exact points of its orbit, read from the
// orbit table (orbit_table.glsl). A ray's orbit is split into `segments` chords of about equal
// sag, as few as keep the chords within render.chord_tolerance of the orbit. Where the chord's
// end lies outside the bounding sphere, the end moves back to where the orbit itself crosses it
// (safeguarded Newton on |p(s) - centre|^2 - R^2), and the velocity is the orbit's tangent there:
// the exit direction is that of the orbit, as the CPU reference takes it. The ray state keeps the
// layout of common.glsl: position.w counts segments, velocity.w holds the fraction s reached.
uniform sampler2D u_ray_position;
uniform sampler2D u_ray_velocity;
uniform sampler2D u_hit;
uniform float u_segment_index;
uniform vec3 u_bound_center;
uniform float u_bound_radius2;
uniform float u_bound_outside;        // bounding radius (1 + a margin): where an exit point is put

const int ORBIT_CROSSING_ITERATIONS = 8;

void main()
{
    vec4 position = fetch(u_ray_position);
    vec4 velocity = fetch(u_ray_velocity);
    bool running = fetch(u_hit).w >= NO_HIT && position.w >= 0.0;
    orbit_ray ray = orbit_ray_of();
    float k = u_segment_index;
    float s0 = orbit_chord_end(ray, k);
    float s1 = orbit_chord_end(ray, k + 1.0);
    vec2 q = orbit_at(ray, s1);
    vec3 p = orbit_point(ray, q, s1);
    float s = s1;
    vec3 from_bound = p - u_bound_center;
    if (dot(from_bound, from_bound) >= u_bound_radius2) {
        float inside = s0;
        float outside = s1;
        float half_sum = 0.5;
        for (int i = 0; i < ORBIT_CROSSING_ITERATIONS; i++) {
            vec2 qi = orbit_at(ray, s);
            vec3 pi = orbit_point(ray, qi, s) - u_bound_center;
            float g = dot(pi, pi) - u_bound_radius2;
            float slope = 2.0 * dot(pi, orbit_velocity(ray, qi, s));
            inside = g < 0.0 ? s : inside;
            outside = g < 0.0 ? outside : s;
            float newton = s - g / slope;
            float middle = half_sum * (inside + outside);
            s = newton >= inside && newton <= outside ? newton : middle;
        }
        q = orbit_at(ray, s);
        vec3 crossing = orbit_point(ray, q, s) - u_bound_center;
        // on the sphere to the last rounding; put just outside it, so that termination sees it
        p = u_bound_center + crossing * (u_bound_outside / length(crossing));
    }
    vec3 tangent = normalize(orbit_velocity(ray, q, s));
    bool moves = running && k < ray.segments;
    float next_steps = k + 1.0;
    vec4 new_position = vec4(p, next_steps);
    vec4 new_velocity = vec4(tangent, s);
    WRITE_TARGET0(moves ? new_position : position);
    WRITE_TARGET1(moves ? new_velocity : velocity);
}
