// Segment a -> b against the rectangle c + s.x eu + s.y ev, s in [-1, 1]^2, with orthogonal
// half-edges eu, ev. Same contract as intersect_rect() in src/physics/intersect.c.

// Sine of the segment-plane angle below which the crossing is a ratio of rounding errors. Dimensionless.
const float RECT_PARALLEL_SINE_LIMIT = 1e-6;

bool hit_rect(vec3 a, vec3 b, vec3 c, vec3 eu, vec3 ev, out float t, out vec2 s)
{
    t = 0.0;
    s = vec2(0.0);
    vec3 d = b - a;
    vec3 n = cross(eu, ev);
    float denom = dot(n, d);
    if (!(abs(denom) > RECT_PARALLEL_SINE_LIMIT * length(n) * length(d)))
        return false;
    float t_hit = dot(n, c - a) / denom;
    if (!(t_hit >= 0.0 && t_hit <= 1.0))      // a NaN too: a hit lies at t in [0, 1]
        return false;
    vec3 w = a + t_hit * d - c;
    vec2 s_hit = vec2(dot(w, eu) / dot(eu, eu), dot(w, ev) / dot(ev, ev));
    if (abs(s_hit.x) > 1.0 || abs(s_hit.y) > 1.0)
        return false;
    t = t_hit;
    s = s_hit;
    return true;
}
