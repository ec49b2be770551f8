// Rays following the Roessler flow (paper section 5.1), scaled about a centre: f = strength * F((x - c) / scale).
// The step is small: two steps to a loop turn (STEPS_UNCHECKED, stage_integrate.glsl).
#define MODEL_STEPS_A_TURN 2
uniform vec3 u_model_center;
uniform float u_model_inv_scale;     // 1 / scale, rounded once from double (a product is cheaper than a quotient)
uniform float u_model_strength;
uniform vec3 u_rossler;         // alpha, beta, gamma

vec3 model_accel(vec3 x, vec3 v)
{
    vec3 u = (x - u_model_center) * u_model_inv_scale;
    vec3 flow = vec3(-(u.y + u.z),
                     u.x + u_rossler.x * u.y,
                     u_rossler.y + u.z * (u.x - u_rossler.z));
    return u_model_strength * flow;
}

vec3 model_initial_velocity(vec3 x, vec3 d)
{
    return d;
}
