// The termination test of one segment (paper section 4.1) as a function, for the passes that take
// a whole segment or ray at once (stage_frame.glsl, stage_segment.glsl): the same decision as the
// termination stage (stage_terminate.glsl), on the same values.
//
// The end of segment k for a ray that has no hit yet: it left the bounding sphere, fell into the
// horizon or failed (steps < 0), as the termination stage decides; code and end_key are its
// outcome and depth key where it ends. Returns whether the ray ends here (or has its hit).
bool segment_end(vec3 x, float steps, float k, candidate best, inout float code, inout float end_key)
{
    vec3 from_bound = x - u_bound_center;
    vec3 from_mass = x - u_capture_center;
    bool captured = u_capture_radius2 > 0.0 && dot(from_mass, from_mass) <= u_capture_radius2;
    bool outside = dot(from_bound, from_bound) >= u_bound_radius2;
    float end_code = steps < 0.0 ? CODE_FAILED : captured ? CODE_CAPTURED : CODE_SKY;
    bool found = best.slot >= 0.0;
    bool ends = !found && (steps < 0.0 || captured || outside);
    float next_key = k + 1.0;
    code = ends ? end_code : code;
    end_key = ends ? next_key : end_key;
    return found || ends;
}
