// Radial force field around a centre (paper section 5.2): Yukawa, or the polynomial xi(r) when the
// preamble defines PROFILE_POLYNOMIAL.
// The step is small: two steps to a loop turn (STEPS_UNCHECKED, stage_integrate.glsl).
#define MODEL_STEPS_A_TURN 2
uniform vec3 u_model_center;
#ifdef PROFILE_POLYNOMIAL
uniform float u_model_strength;
uniform float u_poly_inv_radius; // 1 / range R (scene length units), rounded once from double
#else
uniform vec2 u_yukawa;          // zeta, mu (1 / scene length)
#endif

// Below this distance the direction to the centre is lost to rounding (scene units). Compared with
// <= so that a precision which flushes it to zero still guards r == 0.
const float MODEL_GUARD_RADIUS = 1e-9;

// Computed for every ray, then selected: see the precision note in common.glsl.
vec3 model_accel(vec3 x, vec3 v)
{
    vec3 y = x - u_model_center;
    float r = length(y);
    float safe_r = max(r, MODEL_GUARD_RADIUS);
    // one quotient, then products: a division costs several multiplications
    float inv_r = 1.0 / safe_r;
    vec3 outward = y * inv_r;
#ifdef PROFILE_POLYNOMIAL
    float q = min(safe_r * u_poly_inv_radius, 1.0);   // xi(R) = 0, so clamping gives zero force beyond R
    float xi = (2.0 * q - 3.0) * q * q + 1.0;
    vec3 force = -u_model_strength * xi * outward;
#else
    // zeta exp(-mu r) (1/r^2 + mu/r) written as (zeta exp(-mu r) / r) (1/r + mu): no r^2 to underflow.
    float radial = u_yukawa.x * exp(-u_yukawa.y * safe_r) * inv_r * (inv_r + u_yukawa.y);
    vec3 force = radial * outward;
#endif
    return r <= MODEL_GUARD_RADIUS ? vec3(0.0) : force;
}

vec3 model_initial_velocity(vec3 x, vec3 d)
{
    return d;
}
