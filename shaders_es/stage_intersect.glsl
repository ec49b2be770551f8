// Stage 3, ray-object intersection and local illumination (paper sections 3.3, 3.4): one
// object against the current segment of every ray. The depth key (segment index + fraction)
// orders hits along the curved ray; a closer hit replaces the stored one.
uniform sampler2D u_segment_start;
uniform sampler2D u_segment_end;
uniform sampler2D u_hit;
uniform sampler2D u_image;
uniform float u_segment_index;
uniform float u_object_id;
// Geometry of this object (which fields are used depends on the primitive)
uniform vec3 u_center;
uniform float u_radius;
uniform float u_inner_radius;
uniform vec3 u_normal;
uniform vec3 u_axis_u;                // rect: half edge; sphere, disk: texture reference axis
uniform vec3 u_axis_v;                // rect: half edge; sphere: pole
uniform vec3 u_vertex0;
uniform vec3 u_vertex1;
uniform vec3 u_vertex2;
uniform vec2 u_uv0;
uniform vec2 u_uv1;
uniform vec2 u_uv2;

const float PI = 3.14159265358979;

// Hit of the segment a -> b: fraction t, surface normal and texture coordinates.
bool hit_object(vec3 a, vec3 b, out float t, out vec3 normal, out vec2 uv)
{
    bool found;
    vec3 p;
#if defined(PRIM_SPHERE)
    found = hit_sphere(a, b, u_center, u_radius, t);
    p = mix(a, b, t);
    normal = (p - u_center) / u_radius;
    vec3 third = cross(u_axis_v, u_axis_u);
    uv = vec2(atan(dot(normal, third), dot(normal, u_axis_u)) / (2.0 * PI) + 0.5,
              acos(clamp(dot(normal, u_axis_v), -1.0, 1.0)) / PI);
#elif defined(PRIM_TRIANGLE)
    vec2 bary;
    found = hit_triangle(a, b, u_vertex0, u_vertex1, u_vertex2, t, bary);
    normal = normalize(cross(u_vertex1 - u_vertex0, u_vertex2 - u_vertex0));
    uv = (1.0 - bary.x - bary.y) * u_uv0 + bary.x * u_uv1 + bary.y * u_uv2;
#elif defined(PRIM_DISK)
    found = hit_disk(a, b, u_center, u_normal, u_inner_radius, u_radius, t);
    p = mix(a, b, t) - u_center;
    normal = u_normal;
    vec3 third = cross(u_normal, u_axis_u);
    uv = vec2((length(p) - u_inner_radius) / max(u_radius - u_inner_radius, 1e-6),
              atan(dot(p, third), dot(p, u_axis_u)) / (2.0 * PI) + 0.5);
#else
    vec2 s;
    found = hit_rect(a, b, u_center, u_axis_u, u_axis_v, t, s);
    normal = normalize(cross(u_axis_u, u_axis_v));
    uv = 0.5 * (s + 1.0);
#endif
    return found;
}

void main()
{
    vec4 hit = fetch(u_hit);
    vec4 image = fetch(u_image);
    vec3 a = fetch(u_segment_start).xyz;
    vec3 b = fetch(u_segment_end).xyz;
    float t;
    vec3 normal;
    vec2 uv;
    bool found = hit_object(a, b, t, normal, uv);
    // computed before the select: see the precision note in common.glsl
    float key = u_segment_index + t;
    vec3 p = mix(a, b, t);
    vec4 new_hit = vec4(p, key);
    vec4 new_image = vec4(shade(p, normal, uv, normalize(b - a)), u_object_id);
    bool closer = found && key < hit.w;
    hit = closer ? new_hit : hit;
    image = closer ? new_image : image;
    WRITE_TARGET0(hit);
    WRITE_TARGET1(image);
}
