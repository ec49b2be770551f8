// Continuous refraction in a procedural explosion (paper section 5.3):
// n = 1 + amplitude s(r) (1 + noise_amplitude N(y)), s a Gaussian shell, N three plane waves.
// With ds = n dsigma the ray equation becomes d2x/dsigma2 = n grad n and |dx/dsigma| = n.
// The step is large (three waves' sines and cosines, a Gaussian): one step to a loop turn
// (STEPS_UNCHECKED, stage_integrate.glsl).
#define MODEL_STEPS_A_TURN 1
uniform vec3 u_model_center;
uniform vec4 u_refraction;      // amplitude, shell_radius, shell_width, noise_amplitude
uniform float u_noise_frequency; // 1 / scene length

// Below this distance the direction to the centre is lost to rounding (scene units). Compared with
// <= so that a precision which flushes it to zero still guards r == 0.
const float MODEL_GUARD_RADIUS = 1e-9;
// Fixed wave directions and phases; the same numbers as src/physics/model.c.
const vec3 NOISE_DIR_1 = vec3(0.8, 0.6, 0.0);
const vec3 NOISE_DIR_2 = vec3(0.0, 0.8, 0.6);
const vec3 NOISE_DIR_3 = vec3(0.6, 0.0, 0.8);
const vec3 NOISE_PHASE = vec3(0.0, 1.7, 4.1);

// n at x; grad_n receives its analytic gradient.
float model_refraction_index(vec3 x, out vec3 grad_n)
{
    vec3 y = x - u_model_center;
    float r = length(y);
    vec3 phase = u_noise_frequency * vec3(dot(NOISE_DIR_1, y), dot(NOISE_DIR_2, y), dot(NOISE_DIR_3, y))
               + NOISE_PHASE;
    vec3 wave_slope = cos(phase) * (u_noise_frequency / 3.0);
    float noise = (sin(phase.x) + sin(phase.y) + sin(phase.z)) / 3.0;
    vec3 noise_grad = wave_slope.x * NOISE_DIR_1 + wave_slope.y * NOISE_DIR_2 + wave_slope.z * NOISE_DIR_3;

    float q = (r - u_refraction.y) / u_refraction.z;
    float shell = exp(-q * q);
    float modulation = 1.0 + u_refraction.w * noise;
    grad_n = (u_refraction.x * shell * u_refraction.w) * noise_grad;
    // The shell is a cone at r = 0 with no defined slope: its radial term is dropped there.
    // (selected, not branched: a branch in the step costs llvmpipe more than the term)
    float dshell_dr = -2.0 * q / u_refraction.z * shell;
    vec3 with_radial = grad_n + (u_refraction.x * dshell_dr * modulation) * (y / r);
    grad_n = r > MODEL_GUARD_RADIUS ? with_radial : grad_n;
    return 1.0 + u_refraction.x * shell * modulation;
}

vec3 model_accel(vec3 x, vec3 v)
{
    vec3 grad_n;
    float n = model_refraction_index(x, grad_n);
    return n * grad_n;
}

vec3 model_initial_velocity(vec3 x, vec3 d)
{
    vec3 grad_n;
    return model_refraction_index(x, grad_n) * d;
}
