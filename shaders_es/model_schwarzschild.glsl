// Light near a non-rotating black hole (paper section 5.4): the spatial photon orbit obeys Binet's
// u'' + u = 3 M u^2, which is the central force f = -3 M h^2 y / r^5 with h = |y x v| conserved.
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
