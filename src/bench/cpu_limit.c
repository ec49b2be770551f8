/* The CPU's limit for ray integration: the float arithmetic of shaders_es/stage_integrate.glsl and
 * shaders_es/model_*.glsl, operation for operation where C allows, over rays stored as structs of arrays.
 *
 * Vectorisation, checked with gcc 12.2 on x86-64 with AVX2, `-std=c11 -O3 -march=native -fno-math-errno`
 * and -fopt-info-vec-optimized / -fdump-tree-vect-details: the inner loop over rays of advance_block()
 * is vectorised with 32-byte vectors (8 rays) in the 8 kernels whose force needs no libm call
 * (Schwarzschild, Lorenz, Roessler, polynomial potential; Euler and RK4), sweep_schwarzschild_rk4
 * included: vsqrtps, vdivps, and vpblendvb for the selects. Yukawa (expf) and refraction (sinf, cosf,
 * expf) stay scalar: glibc declares its vector maths (libmvec) to the compiler only under -ffast-math.
 * -O3 is needed (gcc 12's -O2 cost model leaves the loop scalar) and so is -fno-math-errno (otherwise
 * sqrtf keeps a path that sets errno, and only Lorenz and Roessler vectorise). The library's plain -O2
 * build compiles this file too, scalar, and its rays end bit for bit where the vectorised ones do:
 * -std=c11 never fuses a*b+c, and the selects are exact.
 *
 * Known differences from the GPU's work, all small: h is a constant here where the shader reads it per
 * ray from the velocity texture (0.5 h and h / 6 are hoisted out of the loop), and no a*b+c is fused
 * where a GPU compiler fuses freely. The shaders' products with the zero components of the refraction
 * noise directions are left out, as GPU compilers fold them. */
#include "io/clock.h"
#include "io/parallel.h"
#include "bench/cpu_limit.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define MAX_THREADS 256
/* Rays advanced together through all the steps of a sweep: 256 rays' state (7 floats) and running
 * flags take 8 KiB, so the step loop works out of the L1 data cache, as an unrolled pass of the
 * shader works out of registers. */
#define BLOCK_RAYS 256
/* Slices and arrays start on 64-byte cache lines (16 floats): no two threads write the same line. */
#define CACHE_LINE_BYTES 64
#define RAYS_PER_LINE 16

/* The shaders' constants. */
#define GUARD_RADIUS 1e-9f       /* MODEL_GUARD_RADIUS: below it the direction to the centre is lost (scene units) */
#define FINITE_LIMIT2 1.0e30f    /* FINITE_LIMIT2: |x|^2 and |v|^2 beyond this count as overflow */
/* Rays farther than this from the centre stop changing, as rays that leave a scene's bounding sphere
 * do; far larger than any scene so that almost every ray keeps moving (scene units). */
#define BOUND_RADIUS 1.0e4
/* The cost of a step does not depend on h; a small step keeps rays for the whole run in the region
 * around the centre where the scenes' forces act (scene units). */
#define STEP_SIZE 0.01f
/* Rays start this far from the centre, the distance of a scene's camera (scene units). */
#define START_RADIUS_MIN 10.0
#define START_RADIUS_SPAN 10.0
/* Largest tangent of the angle between a starting ray and the direction to the centre: 45 degrees,
 * so the rays cover impact parameters from 0 to past the Schwarzschild shadow's edge. */
#define MAX_TILT 1.0

typedef struct { float x, y, z; } vec3f;

/* Forces with distinct arithmetic; the two potential profiles are separate shaders too. */
enum force_law { LAW_LORENZ, LAW_ROSSLER, LAW_YUKAWA, LAW_POLYNOMIAL, LAW_REFRACTION, LAW_SCHWARZSCHILD, LAW_COUNT };

/* The model as the shaders receive it (uniforms in float, src/render/model_uniforms.c), with the
 * uniform-only subexpressions evaluated once in float (the same bits as the shader's own). */
struct float_model {
    vec3f center;
    float scale, strength;
    vec3f lorenz;              /* sigma, rho, beta */
    vec3f rossler;             /* alpha, beta, gamma */
    float zeta, mu, neg_mu;    /* Yukawa */
    float poly_radius, neg_strength;
    float amplitude, shell_radius, shell_width, noise_amplitude, noise_frequency;
    float wave_slope_scale;    /* noise_frequency / 3 */
    float neg_three_mass;      /* -3 M */
    vec3f bound_center, capture_center;
    float bound_radius2, capture_radius2;
};

struct ray_state {
    vec3f x, v;
};

/* Rays as structs of arrays, so that consecutive rays fill the lanes of a vector. */
struct ray_arrays {
    float *pos[3], *vel[3];
    float *steps;              /* steps taken; negative once the ray failed, as the shader's position.w */
    size_t n;
    float *memory;
};

/* ---- GLSL's vec3 arithmetic in float ---- */

static inline vec3f f3(float x, float y, float z) { vec3f r = {x, y, z}; return r; }
static inline vec3f f3_add(vec3f a, vec3f b) { return f3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec3f f3_sub(vec3f a, vec3f b) { return f3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec3f f3_scale(vec3f a, float s) { return f3(a.x * s, a.y * s, a.z * s); }
static inline vec3f f3_div(vec3f a, float s) { return f3(a.x / s, a.y / s, a.z / s); }
static inline float f3_dot(vec3f a, vec3f b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline float f3_length(vec3f a) { return sqrtf(f3_dot(a, a)); }
static inline vec3f f3_cross(vec3f a, vec3f b)
{
    return f3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
/* GLSL's c ? a : b on floats, as a bit mask rather than C's ?:. With ?: the compiler moves the
 * arithmetic that only one arm uses into that arm, and (floating point may trap without
 * -ffast-math) then refuses to turn the branch back into a vector blend, so the loop over rays
 * would not be vectorised. The mask keeps both values computed, as the shader's select does. */
static inline float f_select(int c, float a, float b)
{
    uint32_t a_bits, b_bits, mask = 0u - (uint32_t)(c != 0), out_bits;
    float out;
    memcpy(&a_bits, &a, sizeof a_bits);
    memcpy(&b_bits, &b, sizeof b_bits);
    out_bits = (a_bits & mask) | (b_bits & ~mask);
    memcpy(&out, &out_bits, sizeof out);
    return out;
}
static inline vec3f f3_select(int c, vec3f a, vec3f b)
{
    return f3(f_select(c, a.x, b.x), f_select(c, a.y, b.y), f_select(c, a.z, b.z));
}
/* GLSL's max and min through the mask too: from ?: the compiler would carry 1 / max(r, guard) into
 * both arms, a division under a branch, with the same result for the loop. */
static inline float f_max(float a, float b) { return f_select(a > b, a, b); }
static inline float f_min(float a, float b) { return f_select(a < b, a, b); }

/* ---- model_accel of each shaders_es/model_*.glsl ---- */

static inline vec3f lorenz_accel(const struct float_model *fm, vec3f x)
{
    vec3f u = f3_div(f3_sub(x, fm->center), fm->scale);
    vec3f flow = f3(fm->lorenz.x * (u.y - u.x), u.x * (fm->lorenz.y - u.z) - u.y, u.x * u.y - fm->lorenz.z * u.z);
    return f3_scale(flow, fm->strength);
}

static inline vec3f rossler_accel(const struct float_model *fm, vec3f x)
{
    vec3f u = f3_div(f3_sub(x, fm->center), fm->scale);
    vec3f flow = f3(-(u.y + u.z), u.x + fm->rossler.x * u.y, fm->rossler.y + u.z * (u.x - fm->rossler.z));
    return f3_scale(flow, fm->strength);
}

static inline vec3f yukawa_accel(const struct float_model *fm, vec3f x)
{
    vec3f y = f3_sub(x, fm->center);
    float r = f3_length(y);
    float safe_r = f_max(r, GUARD_RADIUS);
    vec3f outward = f3_div(y, safe_r);
    float radial = fm->zeta * expf(fm->neg_mu * safe_r) / safe_r * (1.0f / safe_r + fm->mu);
    return f3_select(r <= GUARD_RADIUS, f3(0.0f, 0.0f, 0.0f), f3_scale(outward, radial));
}

static inline vec3f polynomial_accel(const struct float_model *fm, vec3f x)
{
    vec3f y = f3_sub(x, fm->center);
    float r = f3_length(y);
    float safe_r = f_max(r, GUARD_RADIUS);
    vec3f outward = f3_div(y, safe_r);
    float q = f_min(safe_r / fm->poly_radius, 1.0f);
    float xi = (2.0f * q - 3.0f) * q * q + 1.0f;
    return f3_select(r <= GUARD_RADIUS, f3(0.0f, 0.0f, 0.0f), f3_scale(outward, fm->neg_strength * xi));
}

/* n grad n of the explosion model. The noise directions are (0.8, 0.6, 0), (0, 0.8, 0.6), (0.6, 0, 0.8)
 * and the phases 0, 1.7, 4.1, as in model_refraction.glsl. */
static inline vec3f refraction_accel(const struct float_model *fm, vec3f x)
{
    vec3f y = f3_sub(x, fm->center);
    float r = f3_length(y);
    vec3f phase = f3(fm->noise_frequency * (0.8f * y.x + 0.6f * y.y),
                     fm->noise_frequency * (0.8f * y.y + 0.6f * y.z) + 1.7f,
                     fm->noise_frequency * (0.6f * y.x + 0.8f * y.z) + 4.1f);
    vec3f wave_slope = f3(cosf(phase.x) * fm->wave_slope_scale, cosf(phase.y) * fm->wave_slope_scale,
                          cosf(phase.z) * fm->wave_slope_scale);
    float noise = (sinf(phase.x) + sinf(phase.y) + sinf(phase.z)) / 3.0f;
    vec3f noise_grad = f3(wave_slope.x * 0.8f + wave_slope.z * 0.6f, wave_slope.x * 0.6f + wave_slope.y * 0.8f,
                          wave_slope.y * 0.6f + wave_slope.z * 0.8f);
    float q = (r - fm->shell_radius) / fm->shell_width;
    float shell = expf(-q * q);
    float modulation = 1.0f + fm->noise_amplitude * noise;
    vec3f grad_n = f3_scale(noise_grad, fm->amplitude * shell * fm->noise_amplitude);
    /* The shader's `if (r > MODEL_GUARD_RADIUS)` as a select: the radial term is computed for every ray. */
    float dshell_dr = -2.0f * q / fm->shell_width * shell;
    vec3f radial = f3_scale(f3_div(y, r), fm->amplitude * dshell_dr * modulation);
    grad_n = f3_select(r > GUARD_RADIUS, f3_add(grad_n, radial), grad_n);
    float n = 1.0f + fm->amplitude * shell * modulation;
    return f3_scale(grad_n, n);
}

static inline vec3f schwarzschild_accel(const struct float_model *fm, vec3f x, vec3f v)
{
    vec3f y = f3_sub(x, fm->center);
    float r = f3_length(y);
    float inv_r = 1.0f / f_max(r, GUARD_RADIUS);
    vec3f outward = f3_scale(y, inv_r);
    vec3f transverse = f3_cross(outward, v);
    float pull = fm->neg_three_mass * f3_dot(transverse, transverse) * inv_r * inv_r;
    return f3_select(r <= GUARD_RADIUS, f3(0.0f, 0.0f, 0.0f), f3_scale(outward, pull));
}

/* Always inlined, so that each kernel below is specialised to one law and the loop over rays
 * holds no call and no switch. */
static inline __attribute__((always_inline)) vec3f model_accel_f(const struct float_model *fm,
                                                                 enum force_law law, vec3f x, vec3f v)
{
    switch (law) {
    case LAW_LORENZ: return lorenz_accel(fm, x);
    case LAW_ROSSLER: return rossler_accel(fm, x);
    case LAW_YUKAWA: return yukawa_accel(fm, x);
    case LAW_POLYNOMIAL: return polynomial_accel(fm, x);
    case LAW_REFRACTION: return refraction_accel(fm, x);
    case LAW_SCHWARZSCHILD: return schwarzschild_accel(fm, x, v);
    case LAW_COUNT: break;
    }
    return f3(0.0f, 0.0f, 0.0f);
}

/* ---- model_step and the ray's bookkeeping of stage_integrate.glsl ---- */

static inline __attribute__((always_inline)) struct ray_state
ray_step(const struct float_model *fm, enum force_law law, enum integration_method method, float h, vec3f x, vec3f v)
{
    struct ray_state next;
    if (method == METHOD_EULER) {
        next.x = f3_add(x, f3_scale(v, h));
        next.v = f3_add(v, f3_scale(model_accel_f(fm, law, x, v), h));
        return next;
    }
    float half_h = 0.5f * h, sixth_h = h / 6.0f;
    vec3f k1x = v;
    vec3f k1v = model_accel_f(fm, law, x, v);
    vec3f k2x = f3_add(v, f3_scale(k1v, half_h));
    vec3f k2v = model_accel_f(fm, law, f3_add(x, f3_scale(k1x, half_h)), k2x);
    vec3f k3x = f3_add(v, f3_scale(k2v, half_h));
    vec3f k3v = model_accel_f(fm, law, f3_add(x, f3_scale(k2x, half_h)), k3x);
    vec3f k4x = f3_add(v, f3_scale(k3v, h));
    vec3f k4v = model_accel_f(fm, law, f3_add(x, f3_scale(k3x, h)), k4x);
    vec3f dx = f3_add(f3_add(f3_add(k1x, f3_scale(k2x, 2.0f)), f3_scale(k3x, 2.0f)), k4x);
    vec3f dv = f3_add(f3_add(f3_add(k1v, f3_scale(k2v, 2.0f)), f3_scale(k3v, 2.0f)), k4v);
    next.x = f3_add(x, f3_scale(dx, sixth_h));
    next.v = f3_add(v, f3_scale(dv, sixth_h));
    return next;
}

/* Inside the bounding sphere and not captured; a model without a horizon captures nothing. */
static inline int travelling(const struct float_model *fm, vec3f x)
{
    vec3f from_bound = f3_sub(x, fm->bound_center);
    vec3f from_mass = f3_sub(x, fm->capture_center);
    int has_horizon = fm->capture_radius2 > 0.0f;
    int inside_horizon = f3_dot(from_mass, from_mass) <= fm->capture_radius2;
    int inside_bound = f3_dot(from_bound, from_bound) < fm->bound_radius2;
    return inside_bound & !(has_horizon & inside_horizon);
}

/* NaN fails every comparison, so it fails this one too. */
static inline int finite_state(vec3f x, vec3f v)
{
    int x_finite = f3_dot(x, x) < FINITE_LIMIT2;
    int v_finite = f3_dot(v, v) < FINITE_LIMIT2;
    return x_finite & v_finite;
}

/* One sweep of steps_per_call steps over count <= BLOCK_RAYS rays: the shader's main() with
 * STEPS_PER_PASS = steps_per_call, every ray doing every step's arithmetic and a stopped ray keeping
 * its state through selects. The arrays are restrict parameters, so that the compiler knows no store
 * to one ray's state changes another array or the model, and vectorises without run-time checks. */
static inline __attribute__((always_inline)) void
advance_block(const struct float_model *restrict model, enum force_law law, enum integration_method method,
              float h, int steps_per_call, size_t count, float *restrict pos_x, float *restrict pos_y,
              float *restrict pos_z, float *restrict vel_x, float *restrict vel_y, float *restrict vel_z,
              float *restrict steps)
{
    const struct float_model fm = *model;
    int running[BLOCK_RAYS];
    for (size_t i = 0; i < count; i++)
        running[i] = (int)(steps[i] >= 0.0f) & travelling(&fm, f3(pos_x[i], pos_y[i], pos_z[i]));
    for (int s = 0; s < steps_per_call; s++) {
        for (size_t i = 0; i < count; i++) {
            vec3f x = f3(pos_x[i], pos_y[i], pos_z[i]);
            vec3f v = f3(vel_x[i], vel_y[i], vel_z[i]);
            struct ray_state next = ray_step(&fm, law, method, h, x, v);
            int take = running[i] & finite_state(next.x, next.v);
            float next_steps = steps[i] + 1.0f;
            float failed_steps = -1.0f - steps[i];
            x = f3_select(take, next.x, x);
            v = f3_select(take, next.v, v);
            steps[i] = f_select(take, next_steps, f_select(running[i], failed_steps, steps[i]));
            running[i] = take & travelling(&fm, x);
            pos_x[i] = x.x;
            pos_y[i] = x.y;
            pos_z[i] = x.z;
            vel_x[i] = v.x;
            vel_y[i] = v.y;
            vel_z[i] = v.z;
        }
    }
}

typedef void (*sweep_kernel)(const struct float_model *fm, float h, int steps_per_call,
                             const struct ray_arrays *rays, size_t begin, size_t end);

static inline __attribute__((always_inline)) void
sweep_slice(const struct float_model *fm, enum force_law law, enum integration_method method, float h,
            int steps_per_call, const struct ray_arrays *rays, size_t begin, size_t end)
{
    for (size_t b = begin; b < end; b += BLOCK_RAYS) {
        size_t count = end - b < BLOCK_RAYS ? end - b : BLOCK_RAYS;
        advance_block(fm, law, method, h, steps_per_call, count, rays->pos[0] + b, rays->pos[1] + b,
                      rays->pos[2] + b, rays->vel[0] + b, rays->vel[1] + b, rays->vel[2] + b, rays->steps + b);
    }
}

/* One kernel per law and method, each with its own loop over rays (the vectoriser's dump names them). */
#define SWEEP_KERNEL(name, law, method)                                                                   \
    static void name(const struct float_model *fm, float h, int steps_per_call, const struct ray_arrays *rays, \
                     size_t begin, size_t end)                                                             \
    {                                                                                                      \
        sweep_slice(fm, law, method, h, steps_per_call, rays, begin, end);                                 \
    }
SWEEP_KERNEL(sweep_lorenz_euler, LAW_LORENZ, METHOD_EULER)
SWEEP_KERNEL(sweep_lorenz_rk4, LAW_LORENZ, METHOD_RK4)
SWEEP_KERNEL(sweep_rossler_euler, LAW_ROSSLER, METHOD_EULER)
SWEEP_KERNEL(sweep_rossler_rk4, LAW_ROSSLER, METHOD_RK4)
SWEEP_KERNEL(sweep_yukawa_euler, LAW_YUKAWA, METHOD_EULER)
SWEEP_KERNEL(sweep_yukawa_rk4, LAW_YUKAWA, METHOD_RK4)
SWEEP_KERNEL(sweep_polynomial_euler, LAW_POLYNOMIAL, METHOD_EULER)
SWEEP_KERNEL(sweep_polynomial_rk4, LAW_POLYNOMIAL, METHOD_RK4)
SWEEP_KERNEL(sweep_refraction_euler, LAW_REFRACTION, METHOD_EULER)
SWEEP_KERNEL(sweep_refraction_rk4, LAW_REFRACTION, METHOD_RK4)
SWEEP_KERNEL(sweep_schwarzschild_euler, LAW_SCHWARZSCHILD, METHOD_EULER)
SWEEP_KERNEL(sweep_schwarzschild_rk4, LAW_SCHWARZSCHILD, METHOD_RK4)
#undef SWEEP_KERNEL

static const sweep_kernel sweep_kernels[LAW_COUNT][2] = {
    [LAW_LORENZ] = {[METHOD_EULER] = sweep_lorenz_euler, [METHOD_RK4] = sweep_lorenz_rk4},
    [LAW_ROSSLER] = {[METHOD_EULER] = sweep_rossler_euler, [METHOD_RK4] = sweep_rossler_rk4},
    [LAW_YUKAWA] = {[METHOD_EULER] = sweep_yukawa_euler, [METHOD_RK4] = sweep_yukawa_rk4},
    [LAW_POLYNOMIAL] = {[METHOD_EULER] = sweep_polynomial_euler, [METHOD_RK4] = sweep_polynomial_rk4},
    [LAW_REFRACTION] = {[METHOD_EULER] = sweep_refraction_euler, [METHOD_RK4] = sweep_refraction_rk4},
    [LAW_SCHWARZSCHILD] = {[METHOD_EULER] = sweep_schwarzschild_euler, [METHOD_RK4] = sweep_schwarzschild_rk4},
};

/* ---- the model in float ---- */

static vec3f to_f3(vec3d a) { return f3((float)a.x, (float)a.y, (float)a.z); }

/* The law of model m; -1 for a model that integrates nothing (flat) or is unknown. */
static int force_law_of(const struct model *m)
{
    switch (m->type) {
    case MODEL_LORENZ: return LAW_LORENZ;
    case MODEL_ROSSLER: return LAW_ROSSLER;
    case MODEL_POTENTIAL: return m->profile == PROFILE_POLYNOMIAL ? LAW_POLYNOMIAL : LAW_YUKAWA;
    case MODEL_REFRACTION: return LAW_REFRACTION;
    case MODEL_SCHWARZSCHILD: return LAW_SCHWARZSCHILD;
    default: break;    /* flat space, or a model this kernel has no float law of */
    }
    return -1;
}

static void float_model_init(const struct model *m, struct float_model *fm)
{
    memset(fm, 0, sizeof *fm);
    fm->center = to_f3(m->center);
    fm->scale = (float)m->scale;
    fm->strength = (float)m->strength;
    fm->lorenz = f3((float)m->sigma, (float)m->rho, (float)m->beta);
    fm->rossler = f3((float)m->ross_a, (float)m->ross_b, (float)m->ross_c);
    fm->zeta = (float)m->zeta;
    fm->mu = (float)m->mu;
    fm->neg_mu = -fm->mu;
    fm->poly_radius = (float)m->radius;
    fm->neg_strength = -fm->strength;
    fm->amplitude = (float)m->amplitude;
    fm->shell_radius = (float)m->shell_radius;
    fm->shell_width = (float)m->shell_width;
    fm->noise_amplitude = (float)m->noise_amplitude;
    fm->noise_frequency = (float)m->noise_frequency;
    fm->wave_slope_scale = fm->noise_frequency / 3.0f;
    fm->neg_three_mass = -3.0f * (float)m->mass;
    double capture = model_capture_radius(m);
    fm->bound_center = fm->center;
    fm->bound_radius2 = (float)(BOUND_RADIUS * BOUND_RADIUS);
    fm->capture_center = fm->center;
    fm->capture_radius2 = (float)(capture * capture);
}

void cpu_limit_step(const struct model *m, enum integration_method method, float h, float x[3], float v[3])
{
    int law = force_law_of(m);
    if (law < 0)
        return;
    struct float_model fm;
    float_model_init(m, &fm);
    struct ray_state next = ray_step(&fm, (enum force_law)law, method, h, f3(x[0], x[1], x[2]), f3(v[0], v[1], v[2]));
    x[0] = next.x.x;
    x[1] = next.x.y;
    x[2] = next.x.z;
    v[0] = next.v.x;
    v[1] = next.v.y;
    v[2] = next.v.z;
}

/* ---- the rays ---- */

static double fraction(double a) { return a - floor(a); }

/* Ray i of n: directions from the centre on a Fibonacci sphere, distances and tilts from additive
 * recurrences with irrational steps, so the rays spread evenly and the same way on every run. */
static void starting_ray(const struct model *m, size_t i, size_t n, vec3d *x, vec3d *v)
{
    const double golden_angle = PI_D * (3.0 - sqrt(5.0));
    double z = 1.0 - (2.0 * (double)i + 1.0) / (double)n;
    double ring = sqrt(1.0 - z * z), azimuth = golden_angle * (double)i;
    vec3d outward = v3(ring * cos(azimuth), ring * sin(azimuth), z);
    double r = START_RADIUS_MIN + START_RADIUS_SPAN * fraction(0.5 + 0.7548776662466927 * (double)i);
    double tilt = MAX_TILT * fraction(0.5 + 0.5698402909980532 * (double)i);
    double turn = 2.0 * PI_D * fraction(0.4142135623730950 * (double)i);
    vec3d t1 = v3_perpendicular(outward), t2 = v3_cross(outward, t1);
    vec3d tangent = v3_add(v3_scale(t1, cos(turn)), v3_scale(t2, sin(turn)));
    vec3d dir = v3_normalize(v3_axpy(tilt, tangent, v3_scale(outward, -1.0)));
    *x = v3_axpy(r, outward, m->center);
    *v = model_initial_velocity(m, *x, dir);
}

static size_t round_up(size_t a, size_t to) { return (a + to - 1) / to * to; }

static int rays_alloc(struct ray_arrays *rays, size_t n)
{
    size_t stride = round_up(n, RAYS_PER_LINE);
    memset(rays, 0, sizeof *rays);
    rays->memory = aligned_alloc(CACHE_LINE_BYTES, 7 * stride * sizeof(float));
    if (!rays->memory)
        return -1;
    for (int k = 0; k < 3; k++) {
        rays->pos[k] = rays->memory + (size_t)k * stride;
        rays->vel[k] = rays->memory + (size_t)(3 + k) * stride;
    }
    rays->steps = rays->memory + 6 * stride;
    rays->n = n;
    return 0;
}

static void rays_start(struct ray_arrays *rays, const struct model *m)
{
    for (size_t i = 0; i < rays->n; i++) {
        vec3d x, v;
        starting_ray(m, i, rays->n, &x, &v);
        rays->pos[0][i] = (float)x.x;
        rays->pos[1][i] = (float)x.y;
        rays->pos[2][i] = (float)x.z;
        rays->vel[0][i] = (float)v.x;
        rays->vel[1][i] = (float)v.y;
        rays->vel[2][i] = (float)v.z;
        rays->steps[i] = 0.0f;
    }
}

static double rays_checksum(const struct ray_arrays *rays)
{
    double sum = 0.0;
    for (size_t i = 0; i < rays->n; i++) {
        double x = rays->pos[0][i], y = rays->pos[1][i], z = rays->pos[2][i];
        sum += sqrt(x * x + y * y + z * z);
    }
    return sum;
}

/* ---- threads ---- */

/* One thread's share: a contiguous slice of rays, swept `sweeps` times. */
struct slice_job {
    sweep_kernel kernel;
    const struct float_model *fm;
    const struct ray_arrays *rays;
    float h;
    int steps_per_call;
    size_t begin, end;
    long long sweeps;
};

/* Slice `part` of the jobs, swept its times. */
static void run_slice(void *arg, int part, int parts)
{
    (void)parts;
    const struct slice_job *job = (const struct slice_job *)arg + part;
    for (long long k = 0; k < job->sweeps; k++)
        job->kernel(job->fm, job->h, job->steps_per_call, job->rays, job->begin, job->end);
}

/* Every slice swept `sweeps` times, slice 0 on the calling thread (io/parallel.h: a slice whose
 * thread cannot start is swept there afterwards, so the work is always complete). Returns the
 * wall time. */
static double run_round(struct slice_job *jobs, int n_jobs, long long sweeps)
{
    double start = clock_seconds();
    for (int t = 0; t < n_jobs; t++)
        jobs[t].sweeps = sweeps;
    parallel_run(n_jobs, run_slice, jobs);
    return clock_seconds() - start;
}

/* Slices of whole cache lines of rays, as even as that allows; returns how many are non-empty. */
static int split_slices(struct slice_job *jobs, int threads, size_t n_rays)
{
    size_t lines = round_up(n_rays, RAYS_PER_LINE) / RAYS_PER_LINE;
    size_t lines_per_slice = round_up(lines, (size_t)threads) / (size_t)threads;
    size_t rays_per_slice = lines_per_slice * RAYS_PER_LINE;
    int n = 0;
    for (size_t begin = 0; begin < n_rays; begin += rays_per_slice, n++) {
        jobs[n].begin = begin;
        jobs[n].end = n_rays - begin < rays_per_slice ? n_rays : begin + rays_per_slice;
    }
    return n;
}

static int thread_count(int threads)
{
    long n = threads > 0 ? threads : sysconf(_SC_NPROCESSORS_ONLN);
    return n < 1 ? 1 : n > MAX_THREADS ? MAX_THREADS : (int)n;
}

/* Sweeps in rounds sized from the time per sweep seen so far, until min_seconds have been measured. */
static void measure_sweeps(struct slice_job *jobs, int n_jobs, double min_seconds, double *seconds,
                           long long *sweeps)
{
    double per_sweep = run_round(jobs, n_jobs, 1);      /* warm-up: caches, clock speed; not counted */
    *seconds = 0.0;
    *sweeps = 0;
    do {
        double wanted = ceil((min_seconds - *seconds) / (per_sweep > 0.0 ? per_sweep : 1e-9));
        long long round = wanted < 1.0 ? 1 : wanted > 1e9 ? 1000000000LL : (long long)wanted;
        *seconds += run_round(jobs, n_jobs, round);
        *sweeps += round;
        per_sweep = *seconds / (double)*sweeps;
    } while (*seconds < min_seconds);
}

static int check_arguments(const struct model *m, enum integration_method method, int n_rays, int steps_per_call,
                           double min_seconds, struct error *e)
{
    /* no command takes these from its user: a wrong one is the program's, ERROR_RUNTIME */
    if (!model_ops_of(m->type)->integrates)
        return error_set(e, ERROR_RUNTIME, NULL, "the flat model integrates nothing (its rays are single straight "
                         "segments): measure the CPU limit with a curved model");
    if (force_law_of(m) < 0)
        return error_set(e, ERROR_RUNTIME, NULL, "unknown model type %d", (int)m->type);
    if (method != METHOD_EULER && method != METHOD_RK4)
        return error_set(e, ERROR_RUNTIME, NULL, "unknown integration method %d: use euler or rk4", (int)method);
    if (n_rays < 1 || steps_per_call < 1)
        return error_set(e, ERROR_RUNTIME, NULL, "%d rays and %d steps per sweep: both must be at least 1", n_rays,
                         steps_per_call);
    if (!(min_seconds >= 0.0 && isfinite(min_seconds)))
        return error_set(e, ERROR_RUNTIME, NULL, "measuring time %g s: give a finite time of 0 s or more",
                         min_seconds);
    return 0;
}

int cpu_limit_measure(const struct model *m, enum integration_method method, int n_rays, int steps_per_call,
                      int threads, double min_seconds, struct cpu_limit_result *out, struct error *e)
{
    memset(out, 0, sizeof *out);
    if (check_arguments(m, method, n_rays, steps_per_call, min_seconds, e) != 0)
        return -1;
    struct ray_arrays rays;
    if (rays_alloc(&rays, (size_t)n_rays) != 0)
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory for %d rays: measure with fewer", n_rays);
    rays_start(&rays, m);
    struct float_model fm;
    float_model_init(m, &fm);
    struct slice_job jobs[MAX_THREADS];
    int n_jobs = split_slices(jobs, thread_count(threads), rays.n);
    for (int t = 0; t < n_jobs; t++) {
        jobs[t].kernel = sweep_kernels[force_law_of(m)][method];
        jobs[t].fm = &fm;
        jobs[t].rays = &rays;
        jobs[t].h = STEP_SIZE;
        jobs[t].steps_per_call = steps_per_call;
    }
    measure_sweeps(jobs, n_jobs, min_seconds, &out->seconds, &out->sweeps);
    out->threads = n_jobs;
    out->steps = out->sweeps * (long long)n_rays * steps_per_call;
    out->steps_per_second = out->seconds > 0.0 ? (double)out->steps / out->seconds : 0.0;
    out->checksum = rays_checksum(&rays);
    free(rays.memory);
    return 0;
}
