// Segment a -> b against triangle p0 p1 p2 (Moller-Trumbore); bary weighs p1 and p2.
// Same contract as intersect_triangle() in src/physics/intersect.c.

// Sines of the segment-plane angle and of the triangle's corner angle below which float rounding
// decides the answer; such cases are misses. Dimensionless.
const float TRI_PARALLEL_SINE_LIMIT = 1e-6;
const float TRI_DEGENERATE_SINE_LIMIT = 1e-6;

bool hit_triangle(vec3 a, vec3 b, vec3 p0, vec3 p1, vec3 p2, out float t, out vec2 bary)
{
    t = 0.0;
    bary = vec2(0.0);
    vec3 d = b - a;
    vec3 e1 = p1 - p0;
    vec3 e2 = p2 - p0;
    float area2 = length(cross(e1, e2));
    if (!(area2 > TRI_DEGENERATE_SINE_LIMIT * length(e1) * length(e2)))
        return false;
    vec3 pvec = cross(d, e2);
    float det = dot(e1, pvec);
    if (!(abs(det) > TRI_PARALLEL_SINE_LIMIT * length(d) * area2))
        return false;
    float inv_det = 1.0 / det;
    vec3 tvec = a - p0;
    float u = dot(tvec, pvec) * inv_det;
    vec3 qvec = cross(tvec, e1);
    float v = dot(d, qvec) * inv_det;
    float t_hit = dot(e2, qvec) * inv_det;
    if (u < 0.0 || v < 0.0 || u + v > 1.0 || !(t_hit >= 0.0 && t_hit <= 1.0))   // a NaN t too
        return false;
    t = t_hit;
    bary = vec2(u, v);
    return true;
}
