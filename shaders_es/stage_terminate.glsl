// Stage 4, test for ray termination (paper section 4.1): after the objects of a segment,
// a ray without a hit that left the bounding sphere, fell into the horizon or failed gets its
// outcome; its depth key ends the ray at the end of this segment.
uniform sampler2D u_segment_end;
uniform sampler2D u_hit;
uniform sampler2D u_image;
uniform float u_segment_index;

void main()
{
    vec4 hit = fetch(u_hit);
    vec4 image = fetch(u_image);
    vec4 end = fetch(u_segment_end);
    float code = termination_code(end.xyz, end.w);
    // computed before the select: see the precision note in common.glsl
    vec4 end_hit = vec4(end.xyz, u_segment_index + 1.0);
    vec4 end_image = vec4(0.0, 0.0, 0.0, code);
    bool ends = hit.w >= NO_HIT && code < 0.0;
    hit = ends ? end_hit : hit;
    image = ends ? end_image : image;
    WRITE_TARGET0(hit);
    WRITE_TARGET1(image);
}
