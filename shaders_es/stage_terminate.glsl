// Stage 4, test for ray termination (paper section 4.1): after the objects of a segment,
// a ray without a hit that left the bounding sphere, fell into the horizon or failed gets its
// outcome; its depth key ends the ray at the end of this segment.
uniform sampler2D u_segment_end;
uniform sampler2D u_hit;
uniform sampler2D u_image;
uniform float u_segment_index;
uniform vec3 u_bound_center;
uniform float u_bound_radius2;
uniform vec3 u_capture_center;
uniform float u_capture_radius2;

void main()
{
    vec4 hit = fetch(u_hit);
    vec4 image = fetch(u_image);
    vec4 end = fetch(u_segment_end);
    vec3 from_bound = end.xyz - u_bound_center;
    vec3 from_mass = end.xyz - u_capture_center;
    float code = end.w < 0.0 ? CODE_FAILED
               : u_capture_radius2 > 0.0 && dot(from_mass, from_mass) <= u_capture_radius2 ? CODE_CAPTURED
               : dot(from_bound, from_bound) >= u_bound_radius2 ? CODE_SKY : 0.0;
    // computed before the select: see the precision note in common.glsl
    vec4 end_hit = vec4(end.xyz, u_segment_index + 1.0);
    vec4 end_image = vec4(0.0, 0.0, 0.0, code);
    bool ends = hit.w >= NO_HIT && code < 0.0;
    hit = ends ? end_hit : hit;
    image = ends ? end_image : image;
    WRITE_TARGET0(hit);
    WRITE_TARGET1(image);
}
