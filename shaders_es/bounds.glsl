// The scene's bounds: the bounding sphere that rays leave for the sky, the horizon they fall through,
// and the paper's termination rule (section 4.1) on them, written once for every stage that tests
// them (integrate, the orbit's chords, terminate, and the fused and single passes).
uniform vec3 u_bound_center;
uniform float u_bound_radius2;        // squared radius of the bounding sphere
uniform vec3 u_capture_center;
uniform float u_capture_radius2;      // squared horizon radius; 0 when nothing captures

// Strictly inside the bounding sphere (a NaN position is not).
bool inside_bounds(vec3 x)
{
    vec3 from_bound = x - u_bound_center;
    return dot(from_bound, from_bound) < u_bound_radius2;
}

// On or beyond the bounding sphere: the ray has left the scene (a NaN position has not).
bool outside_bounds(vec3 x)
{
    vec3 from_bound = x - u_bound_center;
    return dot(from_bound, from_bound) >= u_bound_radius2;
}

// In the horizon; a model without one (capture radius 0) captures nothing, not even a ray at its
// centre.
bool captured(vec3 x)
{
    vec3 from_mass = x - u_capture_center;
    return u_capture_radius2 > 0.0 && dot(from_mass, from_mass) <= u_capture_radius2;
}

// The termination rule: the outcome of a ray without a hit whose segment ends at x having taken
// `steps` (< 0: its state stopped being finite): failed, captured, the sky once outside the bounding
// sphere, else 0 (still travelling).
float termination_code(vec3 x, float steps)
{
    return steps < 0.0 ? CODE_FAILED : captured(x) ? CODE_CAPTURED : outside_bounds(x) ? CODE_SKY : 0.0;
}
