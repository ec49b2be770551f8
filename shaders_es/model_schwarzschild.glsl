// Light near a non-rotating black hole (paper section 5.4): the spatial photon orbit obeys Binet's
// u'' + u = 3 M u^2, which is the central force f = -3 M h^2 y / r^5 with h = |y x v| conserved.
// The step is small: two steps to a loop turn (STEPS_UNCHECKED, stage_integrate.glsl).
#define MODEL_STEPS_A_TURN 2
uniform vec3 u_model_center;
uniform float u_mass;           // M in scene length units (G = c = 1)

// Below this distance the direction to the centre is lost to rounding; no force there (scene units).
// Compared with <= so that a precision which flushes it to zero still guards r == 0.
const float MODEL_GUARD_RADIUS = 1e-9;

// Computed for every ray, then selected: see the precision note in common.glsl.
vec3 model_accel(vec3 x, vec3 v)
{
    vec3 y = x - u_model_center;
    float r = length(y);
    float inv_r = 1.0 / max(r, MODEL_GUARD_RADIUS);
    vec3 outward = y * inv_r;
    // h^2 y / r^5 = |yhat x v|^2 yhat / r^2: neither h^2 nor r^5 is formed, so distant rays do not
    // overflow and the force keeps full relative precision at every radius.
    vec3 transverse = cross(outward, v);
    vec3 pull = (-3.0 * u_mass * dot(transverse, transverse) * inv_r * inv_r) * outward;
    return r <= MODEL_GUARD_RADIUS ? vec3(0.0) : pull;
}

// A static observer's radial lengths are stretched by 1/sqrt(1 - 2M/r), so the coordinate direction
// has its radial part scaled by sqrt(1 - 2M/r).
// An early return here made Mesa 22.3 evaluate the whole function at 16 bits in ES contexts (camera
// rays 3e-4 rad off): the bent direction is computed for every ray, then selected.
vec3 model_initial_velocity(vec3 x, vec3 d)
{
    vec3 y = x - u_model_center;
    float r = length(y);
    float safe_r = max(r, MODEL_GUARD_RADIUS);
    vec3 outward = y / safe_r;
    float radial_scale = sqrt(max(1.0 - 2.0 * u_mass / safe_r, 0.0));
    vec3 radial = dot(d, outward) * outward;
    vec3 bent = normalize(d - radial + radial_scale * radial);
    bool static_frame_exists = u_mass > 0.0 && r > MODEL_GUARD_RADIUS && r > 2.0 * u_mass;
    return static_frame_exists ? bent : d;
}

// Where light that left the bounding sphere at x along v goes at infinity, where the sky rests
// (src/physics/escape.h has the derivation): the angle Phi it sweeps on its way out, by 8-node
// Gauss-Legendre quadrature of Binet's first integral, in theta = asin(u / u_t) past a periapsis
// u_t, in u itself without one. Light falling in instead keeps v. Computed for every ray, then
// selected (see the precision note in common.glsl).
float escape_integrand(float t, float u_t, float p2, bool in_theta)
{
    float s = sin(t);
    float around = 1.0 - 2.0 * u_mass * u_t * (1.0 + s + s * s) / (1.0 + s);
    float radial = p2 - t * t + 2.0 * u_mass * t * t * t;
    return inversesqrt(max(in_theta ? around : radial, 1e-30));
}

// int_0^b of the integrand
float escape_integral(float b, float u_t, float p2, bool in_theta)
{
    float h = 0.5 * b;
    float sum = 0.10122853629037618 * (escape_integrand(h - h * 0.96028985649753629, u_t, p2, in_theta) +
                                       escape_integrand(h + h * 0.96028985649753629, u_t, p2, in_theta));
    sum += 0.22238103445337445 * (escape_integrand(h - h * 0.79666647741362684, u_t, p2, in_theta) +
                                  escape_integrand(h + h * 0.79666647741362684, u_t, p2, in_theta));
    sum += 0.31370664587788738 * (escape_integrand(h - h * 0.52553240991632899, u_t, p2, in_theta) +
                                  escape_integrand(h + h * 0.52553240991632899, u_t, p2, in_theta));
    sum += 0.36268378337836199 * (escape_integrand(h - h * 0.18343464249564981, u_t, p2, in_theta) +
                                  escape_integrand(h + h * 0.18343464249564981, u_t, p2, in_theta));
    return h * sum;
}

vec3 model_exit_direction(vec3 x, vec3 v)
{
    vec3 y = x - u_model_center;
    float r = length(y);
    vec3 radial = y / max(r, MODEL_GUARD_RADIUS);
    vec3 d = normalize(v);
    float along = dot(d, radial);
    vec3 across = d - along * radial;
    float across_length = length(across);
    vec3 around = across / max(across_length, 1e-30);
    float u = 1.0 / max(r, MODEL_GUARD_RADIUS);
    // du/dphi, and p^2 = 1 / b^2 = (du/dphi)^2 + u^2 (1 - 2 M u)
    float w = -u * along / max(across_length, 1e-30);
    float p2 = w * w + u * u * (1.0 - 2.0 * u_mass * u);
    float p = sqrt(max(p2, 0.0));
    float third = 1.0 / (3.0 * max(u_mass, 1e-30));
    bool periapsis = p * p < third * third / 3.0;           // b > b_c: 1/b^2 < 1/(27 M^2)
    // the periapsis u_t = u + delta, from delta (2u + delta) - 2 M delta (3u^2 + 3u delta + delta^2)
    // = w^2 by Newton's steps from flat space's root: no cancellation for tangential light, and
    // theta = asin(u / u_t) taken as an atan of well-conditioned sides
    float delta = w * w / (u + sqrt(u * u + w * w));
    for (int i = 0; i < 8; i++) {
        float at = u + delta;
        float f = delta * (2.0 * u + delta) - 2.0 * u_mass * delta * (3.0 * u * u + 3.0 * u * delta + delta * delta) - w * w;
        float slope = 2.0 * at * (1.0 - 3.0 * u_mass * at);
        delta = clamp(delta - f / max(slope, 1e-30), 0.0, max(third - u, 0.0));
    }
    float u_t = u + delta;
    bool outwards = w <= 0.0;
    float theta = accurate_angle(u, sqrt(delta * (u_t + u)));
    float here = escape_integral(periapsis ? theta : u, u_t, p2, periapsis);
    float half_way = escape_integral(1.5707963267948966, u_t, p2, true);
    float past_periapsis = 2.0 * half_way - here;
    float sweep = outwards ? here : past_periapsis;
    // falling in: inwards without a periapsis, or behind the photon sphere's barrier
    bool escapes = u_mass > 0.0 && across_length > 0.0 && (periapsis ? u < third : outwards);
    vec3 at_infinity = cos(sweep) * radial + sin(sweep) * around;
    return escapes ? at_infinity : d;
}
