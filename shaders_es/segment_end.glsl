// The termination test of one segment (paper section 4.1) as a function, for the passes that take
// a whole segment or ray at once (stage_frame.glsl, stage_segment.glsl): the termination stage's
// rule (bounds.glsl's termination_code), on the same values.
//
// The end of segment k for a ray that has no hit yet: it left the bounding sphere, fell into the
// horizon or failed (steps < 0), as the termination stage decides; code and end_key are its
// outcome and depth key where it ends. Returns whether the ray ends here (or has its hit).
// found: whether the segment's chord meets an object.
bool segment_end_found(vec3 x, float steps, float k, bool found, inout float code, inout float end_key)
{
    float end_code = termination_code(x, steps);
    bool ends = !found && end_code < 0.0;
    float next_key = k + 1.0;
    code = ends ? end_code : code;
    end_key = ends ? next_key : end_key;
    return found || ends;
}

bool segment_end(vec3 x, float steps, float k, candidate best, inout float code, inout float end_key)
{
    return segment_end_found(x, steps, k, best.slot >= 0.0, code, end_key);
}
