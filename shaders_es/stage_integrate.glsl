// Stage 2, ray integration (paper section 3.2): STEPS_PER_PASS steps of eq. (1) unrolled in
// one shader. A ray stops moving once it has a hit, has left the bounding sphere, has been
// captured, or its state stopped being finite; the last finite state is kept.
uniform sampler2D u_ray_position;
uniform sampler2D u_ray_velocity;
uniform sampler2D u_hit;
uniform vec3 u_bound_center;
uniform float u_bound_radius2;        // squared radius of the bounding sphere
uniform vec3 u_capture_center;
uniform float u_capture_radius2;      // squared horizon radius; 0 when nothing captures

const float FINITE_LIMIT2 = 1.0e30;   // |x|^2 and |v|^2 beyond this count as overflow

bool travelling(vec3 x)
{
    vec3 from_bound = x - u_bound_center;
    vec3 from_mass = x - u_capture_center;
    // a model without a horizon (capture radius 0) captures nothing, not even a ray at its centre
    bool captured = u_capture_radius2 > 0.0 && dot(from_mass, from_mass) <= u_capture_radius2;
    return dot(from_bound, from_bound) < u_bound_radius2 && !captured;
}

// Finite and not overflowing; NaN fails every comparison, so it fails this one too.
bool finite_state(vec3 x, vec3 v)
{
    return dot(x, x) < FINITE_LIMIT2 && dot(v, v) < FINITE_LIMIT2;
}

#ifndef MODEL_FLAT
// One step of eq. (1): Euler as the paper's eq. (2), or classical RK4.
void model_step(vec3 x, vec3 v, float h, out vec3 x1, out vec3 v1)
{
#ifdef METHOD_RK4
    vec3 k1x = v;
    vec3 k1v = model_accel(x, v);
    vec3 k2x = v + 0.5 * h * k1v;
    vec3 k2v = model_accel(x + 0.5 * h * k1x, k2x);
    vec3 k3x = v + 0.5 * h * k2v;
    vec3 k3v = model_accel(x + 0.5 * h * k2x, k3x);
    vec3 k4x = v + h * k3v;
    vec3 k4v = model_accel(x + h * k3x, k4x);
    x1 = x + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
    v1 = v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
#else
    x1 = x + h * v;
    v1 = v + h * model_accel(x, v);
#endif
}
#endif

// The ray state is updated here, in main, with selects: see the precision note in common.glsl.
void main()
{
    vec4 position = fetch(u_ray_position);
    vec4 velocity = fetch(u_ray_velocity);
    vec3 x = position.xyz;
    vec3 v = velocity.xyz;
    float steps = position.w;
    bool running = fetch(u_hit).w >= NO_HIT && steps >= 0.0 && travelling(x);
#ifdef MODEL_FLAT
    // Flat space is not integrated: one straight segment to where the ray leaves the bounding sphere.
    vec3 d = normalize(v);
    vec3 oc = x - u_bound_center;
    float b = dot(oc, d);
    float c = dot(oc, oc) - u_bound_radius2;
    float exit_distance = sqrt(max(b * b - c, 0.0)) - b;
    // 1% beyond the boundary, so that even a 16-bit position lands outside it
    vec3 exit_point = x + d * exit_distance * 1.01;
    float next_steps = steps + 1.0;
    x = running ? exit_point : x;
    steps = running ? next_steps : steps;
#else
    float h = velocity.w;
    for (int i = 0; i < STEPS_PER_PASS; i++) {
        vec3 x1, v1;
        model_step(x, v, h, x1, v1);
        bool ok = finite_state(x1, v1);
        bool take = running && ok;
        float next_steps = steps + 1.0;
        float failed_steps = -1.0 - steps;
        x = take ? x1 : x;
        v = take ? v1 : v;
        steps = take ? next_steps : (running ? failed_steps : steps);
        running = take && travelling(x);
    }
#endif
    WRITE_TARGET0(vec4(x, steps));
    WRITE_TARGET1(vec4(v, velocity.w));
}
