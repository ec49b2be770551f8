// The polygon method's fragments: the rest-frame normal and texture coordinates interpolated across
// the straight triangle, lit by the same shade() as the traced rays; hidden where a traced ray hit
// something closer. Writes the same result as the rays: hit point and depth key, colour and id.
uniform sampler2D u_hit;              // the traced rays' hits (objects at rest)
uniform sampler2D u_segment_end;      // where each straight ray ends: the depth key's scale
uniform vec4 u_material[5];           // as u_materials of one slot in stage_intersect.glsl
uniform vec4 u_body_motion;
uniform float u_object_id;
#ifdef TEXTURED
uniform sampler2D u_texture;
#endif
varying vec3 v_apparent;
varying vec3 v_normal;
varying vec2 v_uv;
varying float v_proper_time;

void main()
{
    vec4 ray_hit = fetch(u_hit);
    float distance = length(v_apparent - u_camera_position);
    if (ray_hit.w < NO_HIT && length(ray_hit.xyz - u_camera_position) <= distance)
        discard;
    vec3 texel = vec3(1.0);
#ifdef TEXTURED
    texel = texture_wrapped(u_texture, v_uv, u_material[4].zw);
#endif
    surface_motion = u_body_motion;
#ifdef CLOCKS
    surface_clock_turns = u_material[3].w > 0.0 ? v_proper_time / u_material[3].w : -1.0;
#endif
#ifdef DOPPLER_COLOUR
    surface_emission_temperature = u_material[4].x;
#endif
    surface_material m = surface_material(u_material[0].rgb * texel, u_material[0].w, u_material[1].rgb, u_material[2],
                                          u_material[3].rgb);
    vec3 color = shade(v_apparent, normalize(v_normal), v_uv, normalize(v_apparent - u_camera_position), m);
    float key = distance / length(fetch(u_segment_end).xyz - u_camera_position);
    WRITE_TARGET0(vec4(v_apparent, key));
    WRITE_TARGET1(vec4(color, u_object_id));
}
