// Exact Schwarzschild photon orbits from the orbit table (src/physics/orbit_table.h): a ray seen
// by the static observer at the camera at angle psi from the outward radial direction runs in
// the plane of e1 (outward radial) and e2 (its own direction across it), at u = 1/r(phi). The
// table is sampled at texel centres only (NEAREST), and interpolated here exactly as
// orbit_table_eval() does in C: Catmull-Rom across rows, cubic Hermite along the orbit.
uniform sampler2D u_orbit_table;
uniform vec2 u_orbit_texel;           // 1 / (texture width, height)
uniform float u_orbit_rows;           // rows per side of the critical angle
uniform float u_orbit_columns;        // samples along each orbit; column u_orbit_columns holds
                                      // (phi_end / sin psi, segments, phi_infinity / sin psi, psi), the columns
                                      // after it the chord schedule's u_orbit_warps samples
uniform float u_orbit_warps;
uniform vec2 u_orbit_span;            // row coordinate of each side's outermost row
uniform vec2 u_orbit_epsilon;         // the row coordinate ln(d / epsilon) + d / even_scale of a ray
uniform float u_orbit_even_scale;     // at d from psi_c, epsilon per side (uniforms: a literal 1e-7
                                      // could fold to 0)

struct orbit_ray {
    vec3 e1, e2;
    float side_first, side_last;      // texel rows of the ray's side of the critical angle
    float row0;                       // first of the four rows, as a texel row
    float row_fraction;               // the ray's place between rows row0 + 1 and row0 + 2
    vec4 weights;                     // Catmull-Rom weights of rows row0 .. row0 + 3
    float phi_end;                    // angle swept to the orbit's end
    float phi_infinity;               // escaping: angle swept to infinity, where the sky is
    float segments;                   // chords along the orbit
    float r_turn;                     // at most the radius of the orbit's periapsis, where it has one
};

// How much lower than the periapsis of the exact orbit r_turn is taken: more than the float
// roundings of the closed form below next to the critical angle (its acos at -1 has an infinite
// slope: 4e-4 of the radius for a rounding of its argument) and than the orbit that the table's
// interpolation gives differs from the exact one.
const float ORBIT_TURN_MARGIN = 1e-2;

#ifdef STATE_PACKED
// the packed path: a texel's four floats from its 2x2 block of RGBA8 texels, as the ray state is
// packed (common.glsl); u_orbit_texel is 1 / the packed texture's size
#define ORBIT_TEXEL(col, row) unpack_block(u_orbit_table, 2.0 * vec2(col, row), u_orbit_texel)
#else
#define ORBIT_TEXEL(col, row) texture2D(u_orbit_table, (vec2(col, row) + 0.5) * u_orbit_texel)
#endif

// The launch angle is measured from the radial axis nearer the critical cone (towards the mass
// when r_o > 3M), as chi, so that chi - chi_c keeps its relative precision next to the shadow's
// edge, where the orbit's swept angle diverges as -ln|chi - chi_c|. A camera at rest takes chi
// from the pixel itself: the unnormalised view direction F + x R + y U is split along the axis
// and across it with coefficients the CPU computed in double, and x, y are taken relative to the
// pixel where the axis itself is seen (a hi + lo pair), so no O(1) terms cancel. A moving camera
// aberrates the direction first and takes chi from the float direction.
uniform vec3 u_orbit_axis;            // unit radial axis at the camera: -e1 or +e1
uniform vec2 u_orbit_critical_chi;    // chi_c as hi + lo
uniform float u_orbit_axis_sign;      // psi_c - psi = sign (chi - chi_c)
#ifndef OBSERVER_MOVING
uniform vec2 u_orbit_axis_pixel_hi;   // image pixel where the axis is seen (or the image centre)
uniform vec2 u_orbit_axis_pixel_lo;
uniform vec2 u_orbit_pixel_scale;     // 2 / image size: ndc per pixel
uniform vec3 u_orbit_across0;         // across-axis part of the view direction at that pixel
uniform vec3 u_orbit_across_x;        // ... per ndc unit of x and of y
uniform vec3 u_orbit_across_y;
uniform vec3 u_orbit_along;           // along-axis part: at that pixel, per ndc unit of x and y
#endif

orbit_ray orbit_ray_of()
{
    orbit_ray ray;
    ray.e1 = normalize(u_camera_position - u_model_center);
#ifdef OBSERVER_MOVING
    vec3 d = observer_scene_direction(observer_view_direction());
    float along = dot(d, u_orbit_axis);
    vec3 across = d - along * u_orbit_axis;
#else
    vec2 pixel = u_pixel_origin + ray_pixel() + 0.5;
    vec2 offset = ((pixel - u_orbit_axis_pixel_hi) - u_orbit_axis_pixel_lo) * u_orbit_pixel_scale;
    vec3 across = u_orbit_across0 + offset.x * u_orbit_across_x + offset.y * u_orbit_across_y;
    float along = u_orbit_along.x + offset.x * u_orbit_along.y + offset.y * u_orbit_along.z;
#endif
    float across_length = length(across);
    float chi = accurate_angle(across_length, along);
    float sin_psi = across_length / sqrt(along * along + across_length * across_length);
    // a radial ray has no plane of its own: any plane through it holds it (phi_end is 0)
    vec3 axis_x = vec3(1.0, 0.0, 0.0);
    vec3 axis_y = vec3(0.0, 1.0, 0.0);
    vec3 any_axis = abs(ray.e1.x) < 0.9 ? axis_x : axis_y;
    vec3 any_across = normalize(cross(ray.e1, any_axis));
    vec3 own_across = across / max(across_length, 1e-30);
    ray.e2 = across_length > 0.0 ? own_across : any_across;
    float from_critical = (chi - u_orbit_critical_chi.x) - u_orbit_critical_chi.y;
    bool escapes = u_orbit_axis_sign * from_critical > 0.0;
    float epsilon = escapes ? u_orbit_epsilon.x : u_orbit_epsilon.y;
    float distance = max(abs(from_critical), epsilon);
    float coordinate = log(distance / epsilon) + distance / u_orbit_even_scale;
    float span = escapes ? u_orbit_span.x : u_orbit_span.y;
    float last_row = u_orbit_rows - 1.0;
    float row = clamp(coordinate / span, 0.0, 1.0) * last_row;
    float i = min(floor(row), last_row - 1.0);
    float f = row - i;
    float f2 = f * f;
    float f3 = f2 * f;
    ray.row_fraction = f;
    ray.weights = 0.5 * vec4(-f3 + 2.0 * f2 - f, 3.0 * f3 - 5.0 * f2 + 2.0, -3.0 * f3 + 4.0 * f2 + f, f3 - f2);
    float side_base = escapes ? 0.0 : u_orbit_rows;
    ray.row0 = i - 1.0;
    float phi_over_sin = 0.0;
    float infinity_over_sin = 0.0;
    vec4 ends[4];
    for (int m = 0; m < 4; m++) {
        float r = clamp(ray.row0 + float(m), 0.0, last_row) + side_base;
        ends[m] = ORBIT_TEXEL(u_orbit_columns, r);
        phi_over_sin += ray.weights[m] * ends[m].x;
        infinity_over_sin += ray.weights[m] * ends[m].z;
    }
    ray.row0 += side_base;
    ray.side_first = side_base;
    ray.side_last = side_base + last_row;
    ray.phi_end = phi_over_sin * sin_psi;
    ray.phi_infinity = infinity_over_sin * sin_psi;
    // rows i and i + 1 are the stencil's middle two (0 <= i <= last_row - 1: no clamp)
    ray.segments = max(ends[1].y, ends[2].y);
    // the periapsis of light with impact parameter b = r_o sin psi / sqrt(1 - 2M / r_o) past the
    // critical one (b > 3 sqrt 3 M): the largest root of r^3 - b^2 r + 2 M b^2 = 0, in the cubic's
    // trigonometric form, (2 b / sqrt 3) cos(acos(-3 sqrt 3 M / b) / 3); b itself in flat space
    float r_o = length(u_camera_position - u_model_center);
    float b = r_o * sin_psi / sqrt(max(1.0 - 2.0 * u_mass / r_o, 1e-30));
    float critical = clamp(-5.196152422706632 * u_mass / max(b, 1e-30), -1.0, 0.0);
    ray.r_turn = 1.1547005383792515 * b * cos(acos(critical) / 3.0) * (1.0 - ORBIT_TURN_MARGIN);
    return ray;
}

// u and du/ds at fraction s of the orbit.
vec2 orbit_at(orbit_ray ray, float s)
{
    float last_column = u_orbit_columns - 1.0;
    float c = clamp(s, 0.0, 1.0) * last_column;
    float j = min(floor(c), last_column - 1.0);
    float g = c - j;
    float g2 = g * g;
    float g3 = g2 * g;
    float dj = 1.0 / last_column;
    vec4 value = vec4(2.0 * g3 - 3.0 * g2 + 1.0, (g3 - 2.0 * g2 + g) * dj, -2.0 * g3 + 3.0 * g2, (g3 - g2) * dj);
    vec4 slope = vec4((6.0 * g2 - 6.0 * g) / dj, 3.0 * g2 - 4.0 * g + 1.0, (-6.0 * g2 + 6.0 * g) / dj,
                      3.0 * g2 - 2.0 * g);
    vec2 sum = vec2(0.0);
    for (int m = 0; m < 4; m++) {
        float r = clamp(ray.row0 + float(m), ray.side_first, ray.side_last);
        // u, du/ds at samples j and j + 1, in one texel
        vec4 samples = ORBIT_TEXEL(j, r);
        sum += ray.weights[m] * vec2(dot(value, samples), dot(slope, samples));
    }
    return sum;
}

// The fraction s where chord k of the ray's ends: the chord schedule (equal sag, see
// src/physics/orbit_table.c) interpolated linearly, along it and between the two nearest rows,
// so that it stays increasing in k.
float orbit_chord_end(orbit_ray ray, float k)
{
    float last = u_orbit_warps - 1.0;
    float x = clamp(k / ray.segments, 0.0, 1.0) * last;
    float m = min(floor(x), last - 1.0);
    float g = x - m;
    float column = u_orbit_columns + 1.0 + m;
    float row = ray.row0 + 1.0;
    // the first and the last end are the orbit's own ends: no fetch (the selects below keep the
    // arithmetic outside the branch, see the precision note in common.glsl)
    float end = k <= 0.0 ? 0.0 : 1.0;
    if (k > 0.0 && k < ray.segments) {
        // samples m and m + 1 of this row (xy) and of the next (zw), in one texel
        vec4 rows = ORBIT_TEXEL(column, row);
        end = mix(mix(rows.x, rows.y, g), mix(rows.z, rows.w, g), ray.row_fraction);
    }
    return end;
}

// The point of the orbit where it has u, du/ds = q and its angle phi has cosine and sine cs.
vec3 orbit_point_at(orbit_ray ray, vec2 q, vec2 cs)
{
    return u_model_center + (cs.x * ray.e1 + cs.y * ray.e2) / q.x;
}

// The point of the orbit at fraction s, where it has u, du/ds = q.
vec3 orbit_point(orbit_ray ray, vec2 q, float s)
{
    float phi = s * ray.phi_end;
    return orbit_point_at(ray, q, vec2(cos(phi), sin(phi)));
}

// d(point)/ds there.
vec3 orbit_velocity(orbit_ray ray, vec2 q, float s)
{
    float phi = s * ray.phi_end;
    vec3 radial = cos(phi) * ray.e1 + sin(phi) * ray.e2;
    vec3 around = cos(phi) * ray.e2 - sin(phi) * ray.e1;
    return (-q.y / (q.x * q.x)) * radial + (ray.phi_end / q.x) * around;
}

// Chord k of the ray: the fraction s of the orbit where it ends and u, du/ds there (q), and
// whether it leaves the bounding sphere; orbit_chord_point gives its end point, orbit_tangent the
// direction there.
// Where the chord's end lies outside the bounding sphere, the end moves back to where the orbit
// itself crosses it (safeguarded Newton on |p(s) - centre|^2 - R^2) and is put just outside it,
// so that the termination test sees it; the tangent there is the exit direction, as the CPU
// reference takes it.
uniform float u_bound_outside;        // bounding radius (1 + a margin): where an exit point is put

const int ORBIT_CROSSING_ITERATIONS = 2;

// Where the orbit crosses the bounding sphere between s0 (inside) and s1 (outside, where it has
// u, du/ds = q and lies at from_bound from the sphere's centre): s and q there.
void orbit_crossing(orbit_ray ray, float s0, float s1, vec3 from_bound, inout vec2 q, out float s)
{
    s = s1;
    // first guess: where the tangent line at s1 meets the sphere (far out the orbit is nearly
    // straight), then Newton's steps on the orbit itself, kept inside the bracket [s0, s1]
    vec3 velocity = orbit_velocity(ray, q, s1);
    float a2 = dot(velocity, velocity);
    float half_b = dot(from_bound, velocity);
    float c = dot(from_bound, from_bound) - u_bound_radius2;
    float root = sqrt(max(half_b * half_b - a2 * c, 0.0));
    float back = (-half_b - root) / a2;
    float back_other = (-half_b + root) / a2;
    float step_back = back_other <= 0.0 ? back_other : back;
    float inside = s0;
    float outside = s1;
    s = clamp(s1 + step_back, s0, s1);
    float half_sum = 0.5;
    for (int i = 0; i < ORBIT_CROSSING_ITERATIONS; i++) {
        vec2 qi = orbit_at(ray, s);
        vec3 pi = orbit_point(ray, qi, s) - u_bound_center;
        float g = dot(pi, pi) - u_bound_radius2;
        float slope = 2.0 * dot(pi, orbit_velocity(ray, qi, s));
        inside = g < 0.0 ? s : inside;
        outside = g < 0.0 ? outside : s;
        float newton = s - g / slope;
        float middle = half_sum * (inside + outside);
        s = newton >= inside && newton <= outside ? newton : middle;
        // at the turn's end (docs/PIPELINE.md, "Loops that end at a turn's end")
        if (i == ORBIT_CROSSING_ITERATIONS - 1)
            break;
    }
    q = orbit_at(ray, s);
}

void orbit_chord_from(orbit_ray ray, float s0, float k, out vec2 q, out float s, out bool leaves)
{
    float s1 = orbit_chord_end(ray, k + 1.0);
    q = orbit_at(ray, s1);
    vec3 p = orbit_point(ray, q, s1);
    s = s1;
    vec3 from_bound = p - u_bound_center;
    leaves = outside_bounds(p);
    if (leaves)
        orbit_crossing(ray, s0, s1, from_bound, q, s);
}

// The same from the chord's start: the previous chord's end, or orbit_chord_end(ray, k).
void orbit_chord(orbit_ray ray, float k, out vec2 q, out float s, out bool leaves)
{
    orbit_chord_from(ray, orbit_chord_end(ray, k), k, q, s, leaves);
}

// The end point of a chord that orbit_chord found: on the orbit, or where the orbit leaves the
// bounding sphere, put just outside it.
vec3 orbit_chord_point(orbit_ray ray, vec2 q, float s, bool leaves)
{
    vec3 p = orbit_point(ray, q, s);
    vec3 crossing = p - u_bound_center;
    vec3 outside = u_bound_center + crossing * (u_bound_outside / length(crossing));
    return leaves ? outside : p;
}

// The direction at infinity of an escaping ray, where the sky rests (physics/escape.h): its
// orbit's asymptote.
vec3 orbit_direction_at_infinity(orbit_ray ray)
{
    return cos(ray.phi_infinity) * ray.e1 + sin(ray.phi_infinity) * ray.e2;
}

// The orbit's unit tangent at fraction s, where it has u, du/ds = q.
vec3 orbit_tangent(orbit_ray ray, vec2 q, float s)
{
    return normalize(orbit_velocity(ray, q, s));
}
