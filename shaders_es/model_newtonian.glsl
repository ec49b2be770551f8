// Newtonian gravity for light (Soldner 1801; src/physics/model.c): corpuscles of light pulled by a
// point mass, a = -M y / r^3, launched at the speed that is c far away. They run on hyperbolas,
// deflected by 2 atan(M / b), half of general relativity's bending far from the mass.
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
    // M / r^2 along -y / r: no r^3 to underflow
    vec3 pull = (-u_mass * inv_r * inv_r) * (y * inv_r);
    return r <= MODEL_GUARD_RADIUS ? vec3(0.0) : pull;
}

// The speed that is c far away: sqrt(1 + 2M/r) where the corpuscle starts.
vec3 model_initial_velocity(vec3 x, vec3 d)
{
    float r = max(length(x - u_model_center), MODEL_GUARD_RADIUS);
    return d * sqrt(1.0 + 2.0 * u_mass / r);
}

// Where a ray that left the bounding sphere at x moving along v goes at infinity: the asymptote of
// its hyperbola. With h = y x v and the eccentricity vector e = v x h / M - y / r, it leaves at the
// true anomaly nu with cos nu = -1 / |e|, along cos nu e/|e| + sin nu (h/|h| x e/|e|). Computed for
// every ray, then selected (see the precision note in common.glsl): a radial ray keeps v.
vec3 model_exit_direction(vec3 x, vec3 v)
{
    vec3 y = x - u_model_center;
    float r = max(length(y), MODEL_GUARD_RADIUS);
    vec3 h = cross(y, v);
    float h_length = length(h);
    vec3 e = cross(v, h) / max(u_mass, 1e-30) - y / r;
    float ecc = max(length(e), 1.0);
    vec3 e_hat = e / max(length(e), 1e-30);
    vec3 ahead = cross(h / max(h_length, 1e-30), e_hat);
    float inv_ecc = 1.0 / ecc;
    vec3 at_infinity = -inv_ecc * e_hat + sqrt(max(1.0 - inv_ecc * inv_ecc, 0.0)) * ahead;
    bool hyperbola = u_mass > 0.0 && h_length > 0.0 && length(e) > 1.0;
    return hyperbola ? at_infinity : normalize(v);
}
