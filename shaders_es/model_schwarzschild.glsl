// Light near a non-rotating black hole (paper section 5.4): the spatial photon orbit obeys Binet's
// u'' + u = 3 M u^2, which is the central force f = -3 M h^2 y / r^5 with h = |y x v| conserved.
uniform vec3 u_model_center;
uniform float u_mass;           // M in scene length units (G = c = 1)

// Below this distance the direction to the centre is lost to rounding; no force there (scene units).
// Compared with <= so that a precision which flushes it to zero still guards r == 0.
const float MODEL_GUARD_RADIUS = 1e-9;

vec3 model_accel(vec3 x, vec3 v)
{
    vec3 y = x - u_model_center;
    float r = length(y);
    if (r <= MODEL_GUARD_RADIUS)
        return vec3(0.0);
    vec3 outward = y / r;
    // h^2 y / r^5 = |yhat x v|^2 yhat / r^2: neither h^2 nor r^5 is formed, so distant rays do not
    // overflow and the force keeps full relative precision at every radius.
    vec3 transverse = cross(outward, v);
    float inv_r = 1.0 / r;
    return (-3.0 * u_mass * dot(transverse, transverse) * inv_r * inv_r) * outward;
}

// A static observer's radial lengths are stretched by 1/sqrt(1 - 2M/r), so the coordinate direction
// has its radial part scaled by sqrt(1 - 2M/r).
vec3 model_initial_velocity(vec3 x, vec3 d)
{
    vec3 y = x - u_model_center;
    float r = length(y);
    if (u_mass == 0.0 || r <= MODEL_GUARD_RADIUS || r <= 2.0 * u_mass)
        return d;
    vec3 outward = y / r;
    float radial_scale = sqrt(1.0 - 2.0 * u_mass / r);
    vec3 radial = dot(d, outward) * outward;
    return normalize(d - radial + radial_scale * radial);
}
