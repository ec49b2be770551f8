// Segment a -> b against the annulus r_in <= |p - c| <= r_out in the plane through c with normal n
// (any length). Same contract as intersect_disk() in src/physics/intersect.c.

// Sine of the segment-plane angle below which the crossing is a ratio of rounding errors. Dimensionless.
const float DISK_PARALLEL_SINE_LIMIT = 1e-6;

bool hit_disk(vec3 a, vec3 b, vec3 c, vec3 n, float r_in, float r_out, out float t)
{
    t = 0.0;
    vec3 d = b - a;
    float denom = dot(n, d);
    if (!(abs(denom) > DISK_PARALLEL_SINE_LIMIT * length(n) * length(d)))
        return false;
    float t_hit = dot(n, c - a) / denom;
    if (!(t_hit >= 0.0 && t_hit <= 1.0))      // a NaN too: a hit lies at t in [0, 1]
        return false;
    float dist = length(a + t_hit * d - c);
    if (dist < r_in || dist > r_out)
        return false;
    t = t_hit;
    return true;
}
