/* The force laws f(x, v) of eq. (1) and their integrators, in double precision.
 * shaders_es/model_*.glsl must compute the same functions; change both together. */
#include "physics/model.h"
#include "physics/dormand_prince.h"
#include "physics/escape.h"

#include <math.h>
#include <stddef.h>

/* Below this distance from a force centre the direction to it is meaningless (scene length units);
 * the force is taken as zero there rather than letting 0/0 poison the ray state. */
#define CENTER_GUARD_RADIUS 1e-9

/* Fixed noise directions and phases of the procedural explosion model: incommensurate enough
 * that the sum of three plane waves does not look periodic on screen. */
static const double noise_dir[3][3] = {{0.8, 0.6, 0.0}, {0.0, 0.8, 0.6}, {0.6, 0.0, 0.8}};
static const double noise_phase[3] = {0.0, 1.7, 4.1};

static double schwarzschild_gravity_mass(const struct model *m) { return m->mass; }

static int schwarzschild_at_infinity(const struct model *m, vec3d x, vec3d v, vec3d *out)
{
    return escape_direction(m->mass, m->center, x, v, out);
}

static const char *potential_defines(const struct model *m)
{
    return m->profile == PROFILE_POLYNOMIAL ? "#define PROFILE_POLYNOMIAL 1\n" : "";
}

/* Newtonian gravity for light (Soldner 1801): corpuscles of light pulled by a point mass M,
 * a = -M y / r^3 (G = c = 1), launched at the speed that is c far away, sqrt(1 + 2M/r) where they
 * start. They run on hyperbolas, deflected by 2 atan(M / b): 2M/b far from the mass, half of
 * general relativity's 4M/b (Schwarzschild), which is what the 1919 eclipse measured. The mass
 * is a dark star of radius 2M (Michell 1784), where the escape speed is c: light that reaches it is
 * absorbed, which a ray does below b = 2 sqrt(2) M (its shadow; Schwarzschild's is 3 sqrt(3) M). */
static vec3d newtonian_accel(const struct model *m, vec3d y)
{
    double r = v3_len(y);
    if (r < CENTER_GUARD_RADIUS)
        return v3(0.0, 0.0, 0.0);
    double inv_r = 1.0 / r;
    return v3_scale(y, -m->mass * inv_r * inv_r * inv_r);
}

static vec3d newtonian_initial_velocity(const struct model *m, vec3d x, vec3d dir)
{
    double r = fmax(v3_len(v3_sub(x, m->center)), CENTER_GUARD_RADIUS);
    return v3_scale(dir, sqrt(1.0 + 2.0 * m->mass / r));
}

/* The asymptote of the hyperbola through x with velocity v: with h = y x v and the eccentricity
 * vector e = v x h / M - y / r, the orbit reaches infinity at the true anomaly nu with
 * cos nu = -1 / |e|, going along cos nu e/|e| + sin nu (h/|h| x e/|e|). */
static int newtonian_at_infinity(const struct model *m, vec3d x, vec3d v, vec3d *out)
{
    vec3d y = v3_sub(x, m->center);
    double r = v3_len(y);
    vec3d h = v3_cross(y, v);
    double h_len = v3_len(h);
    if (!(m->mass > 0.0) || !(r > 0.0) || !(h_len > 0.0) || !(0.5 * v3_dot(v, v) > m->mass / r))
        return 0;
    vec3d e = v3_sub(v3_scale(v3_cross(v, h), 1.0 / m->mass), v3_scale(y, 1.0 / r));
    double ecc = v3_len(e);
    if (!(ecc > 1.0))
        return 0;
    vec3d e_hat = v3_scale(e, 1.0 / ecc);
    vec3d ahead = v3_cross(v3_scale(h, 1.0 / h_len), e_hat);
    *out = v3_add(v3_scale(e_hat, -1.0 / ecc), v3_scale(ahead, sqrt(1.0 - 1.0 / (ecc * ecc))));
    return 1;
}

static const struct model_ops model_table[MODEL_COUNT] = {
    [MODEL_FLAT] = {.name = "flat"},
    [MODEL_LORENZ] = {.name = "lorenz", .integrates = 1},
    [MODEL_ROSSLER] = {.name = "rossler", .integrates = 1},
    [MODEL_POTENTIAL] = {.name = "potential", .integrates = 1, .shader_defines = potential_defines},
    [MODEL_REFRACTION] = {.name = "refraction", .integrates = 1},
    [MODEL_SCHWARZSCHILD] = {.name = "schwarzschild", .integrates = 1, .has_mass = 1, .exact_orbits = 1,
                             .gravity_mass = schwarzschild_gravity_mass,
                             .direction_at_infinity = schwarzschild_at_infinity},
    [MODEL_NEWTONIAN] = {.name = "newtonian", .integrates = 1, .has_mass = 1,
                         .direction_at_infinity = newtonian_at_infinity},
};

const struct model_ops *model_ops_of(enum model_type t)
{
    static const struct model_ops unknown = {.name = "unknown"};
    return (unsigned)t < MODEL_COUNT ? &model_table[t] : &unknown;
}

double model_gravity_mass(const struct model *m)
{
    const struct model_ops *ops = model_ops_of(m->type);
    return ops->gravity_mass ? ops->gravity_mass(m) : 0.0;
}

const char *model_name(enum model_type t) { return model_ops_of(t)->name; }

const char *method_name(enum integration_method m)
{
    switch (m) {
    case METHOD_EULER: return "euler";
    case METHOD_RK4: return "rk4";
    case METHOD_DOPRI5: return "dopri5";
    case METHOD_ORBIT_TABLE: return "orbit_table";
    }
    return "unknown";
}

int model_is_straight(const struct model *m)
{
    switch (m->type) {
    case MODEL_FLAT: return 1;
    case MODEL_LORENZ:
    case MODEL_ROSSLER: return m->strength == 0.0;
    case MODEL_POTENTIAL: return m->profile == PROFILE_YUKAWA ? m->zeta == 0.0 : m->strength == 0.0;
    case MODEL_REFRACTION: return m->amplitude == 0.0;
    case MODEL_SCHWARZSCHILD:
    case MODEL_NEWTONIAN: return m->mass == 0.0;
    case MODEL_COUNT: break;
    }
    return 0;
}

static vec3d lorenz_accel(const struct model *m, vec3d y)
{
    vec3d u = v3_scale(y, 1.0 / m->scale);
    vec3d flow = v3(m->sigma * (u.y - u.x), u.x * (m->rho - u.z) - u.y, u.x * u.y - m->beta * u.z);
    return v3_scale(flow, m->strength);
}

static vec3d rossler_accel(const struct model *m, vec3d y)
{
    vec3d u = v3_scale(y, 1.0 / m->scale);
    vec3d flow = v3(-(u.y + u.z), u.x + m->ross_a * u.y, m->ross_b + u.z * (u.x - m->ross_c));
    return v3_scale(flow, m->strength);
}

static vec3d potential_accel(const struct model *m, vec3d y)
{
    double r = v3_len(y);
    if (r < CENTER_GUARD_RADIUS)
        return v3(0.0, 0.0, 0.0);
    vec3d outward = v3_scale(y, 1.0 / r);
    if (m->profile == PROFILE_POLYNOMIAL) {
        if (r > m->radius)
            return v3(0.0, 0.0, 0.0);
        double q = r / m->radius;
        double xi = (2.0 * q - 3.0) * q * q + 1.0;
        return v3_scale(outward, -m->strength * xi);
    }
    /* -dV/dr of V = zeta exp(-mu r) / r, pointing outward for zeta > 0 (repulsion). */
    double radial = m->zeta * exp(-m->mu * r) * (1.0 / (r * r) + m->mu / r);
    return v3_scale(outward, radial);
}

/* Gaussian shell profile s(r) of the explosion front. */
static double shell_profile(const struct model *m, double r)
{
    double q = (r - m->shell_radius) / m->shell_width;
    return exp(-q * q);
}

/* N(y) and its gradient; the sum of three plane waves is divided by three so |N| <= 1. */
static double noise_field(const struct model *m, vec3d y, vec3d *grad)
{
    double sum = 0.0;
    vec3d g = v3(0.0, 0.0, 0.0);
    for (int i = 0; i < 3; i++) {
        vec3d e = v3(noise_dir[i][0], noise_dir[i][1], noise_dir[i][2]);
        double phase = m->noise_frequency * v3_dot(e, y) + noise_phase[i];
        sum += sin(phase);
        g = v3_axpy(m->noise_frequency * cos(phase), e, g);
    }
    *grad = v3_scale(g, 1.0 / 3.0);
    return sum / 3.0;
}

/* n(x) and, when grad is not NULL, its analytic gradient. */
static double refraction_index(const struct model *m, vec3d x, vec3d *grad)
{
    vec3d y = v3_sub(x, m->center);
    double r = v3_len(y);
    vec3d noise_grad;
    double noise = noise_field(m, y, &noise_grad);
    double shell = shell_profile(m, r);
    double modulation = 1.0 + m->noise_amplitude * noise;
    if (grad) {
        /* The shell is a cone at r = 0 with no defined slope; its radial term is dropped there. */
        vec3d g = v3_scale(noise_grad, m->amplitude * shell * m->noise_amplitude);
        if (r >= CENTER_GUARD_RADIUS) {
            double dshell_dr = -2.0 * (r - m->shell_radius) / (m->shell_width * m->shell_width) * shell;
            g = v3_axpy(m->amplitude * dshell_dr * modulation / r, y, g);
        }
        *grad = g;
    }
    return 1.0 + m->amplitude * shell * modulation;
}

double model_refraction_index(const struct model *m, vec3d x)
{
    if (m->type != MODEL_REFRACTION)
        return 1.0;
    return refraction_index(m, x, NULL);
}

/* Binet's u'' + u = 3 M u^2 as a central force: with h = |y x v| conserved,
 * f = -3 M h^2 y / r^5 = -3 M |yhat x v|^2 yhat / r^2 (the second form never forms h^2 or r^5). */
static vec3d schwarzschild_accel(const struct model *m, vec3d y, vec3d v)
{
    double r = v3_len(y);
    if (r < CENTER_GUARD_RADIUS)
        return v3(0.0, 0.0, 0.0);
    vec3d outward = v3_scale(y, 1.0 / r);
    vec3d transverse = v3_cross(outward, v);
    double pull = 3.0 * m->mass * v3_dot(transverse, transverse) / (r * r);
    return v3_scale(outward, -pull);
}

vec3d model_accel(const struct model *m, vec3d x, vec3d v)
{
    vec3d y = v3_sub(x, m->center);
    switch (m->type) {
    case MODEL_LORENZ: return lorenz_accel(m, y);
    case MODEL_ROSSLER: return rossler_accel(m, y);
    case MODEL_POTENTIAL: return potential_accel(m, y);
    case MODEL_REFRACTION: {
        /* With ds = n dsigma the ray equation d/ds(n dx/ds) = grad n becomes
         * d2x/dsigma2 = n grad n, and |dx/dsigma| = n. */
        vec3d grad;
        double n = refraction_index(m, x, &grad);
        return v3_scale(grad, n);
    }
    case MODEL_SCHWARZSCHILD: return schwarzschild_accel(m, y, v);
    case MODEL_NEWTONIAN: return newtonian_accel(m, y);
    case MODEL_FLAT:
    case MODEL_COUNT: break;
    }
    return v3(0.0, 0.0, 0.0);
}

/* A static observer measures radial lengths stretched by 1/sqrt(1 - 2M/r) against the Schwarzschild
 * coordinate, so the coordinate direction of a ray has its radial part scaled by sqrt(1 - 2M/r).
 * This makes the Binet invariant 1/b^2 = u'^2 + u^2 - 2 M u^3 equal (sin psi / r)^2 / (1 - 2M/r). */
static vec3d schwarzschild_initial_velocity(const struct model *m, vec3d x, vec3d dir)
{
    vec3d y = v3_sub(x, m->center);
    double r = v3_len(y);
    if (m->mass == 0.0 || r < CENTER_GUARD_RADIUS || r <= 2.0 * m->mass)
        return dir;
    vec3d outward = v3_scale(y, 1.0 / r);
    double radial_shrink = 1.0 - sqrt(1.0 - 2.0 * m->mass / r);
    vec3d d = v3_axpy(-radial_shrink * v3_dot(dir, outward), outward, dir);
    return v3_normalize(d);
}

vec3d model_initial_velocity(const struct model *m, vec3d x, vec3d dir)
{
    switch (m->type) {
    case MODEL_REFRACTION: return v3_scale(dir, refraction_index(m, x, NULL));
    case MODEL_SCHWARZSCHILD: return schwarzschild_initial_velocity(m, x, dir);
    case MODEL_NEWTONIAN: return newtonian_initial_velocity(m, x, dir);
    case MODEL_FLAT:
    case MODEL_LORENZ:
    case MODEL_ROSSLER:
    case MODEL_POTENTIAL:
    case MODEL_COUNT: break;
    }
    return dir;
}

/* Schwarzschild: the critical launch angle (b = 3 sqrt(3) M) seen by the static observer at r_o,
 * measured from the nearer radial direction (src/physics/orbit_table.h tabulates the orbits around
 * it; the kiosk bounds the shadow's size with it). */
double orbit_critical_from_axis(double mass, double r_observer, int *inward)
{
    double s = 3.0 * sqrt(3.0) * mass * sqrt(1.0 - 2.0 * mass / r_observer) / r_observer;
    if (s > 1.0)
        s = 1.0;                      /* r_o = 3M: rounding only */
    if (inward)
        *inward = r_observer > 3.0 * mass;
    return asin(s);
}

double orbit_critical_angle(double mass, double r_observer)
{
    const double pi = 3.14159265358979323846;
    int inward;
    double a = orbit_critical_from_axis(mass, r_observer, &inward);
    return inward ? pi - a : a;
}

double model_capture_radius(const struct model *m)
{
    /* Schwarzschild's horizon; the Newtonian dark star's surface (Michell 1784), where the escape
     * speed is c: light that reaches it is absorbed */
    if ((m->type == MODEL_SCHWARZSCHILD || m->type == MODEL_NEWTONIAN) && m->mass > 0.0)
        return 2.0 * m->mass;
    return 0.0;
}

static void dopri5_fixed_step(const struct model *m, double h, vec3d *x, vec3d *v)
{
    vec3d kx[6], kv[6];
    for (int s = 0; s < 6; s++) {
        vec3d xs = *x, vs = *v;
        for (int j = 0; j < s; j++) {
            xs = v3_axpy(h * dormand_prince_a[s - 1][j], kx[j], xs);
            vs = v3_axpy(h * dormand_prince_a[s - 1][j], kv[j], vs);
        }
        kx[s] = vs;
        kv[s] = model_accel(m, xs, vs);
    }
    vec3d x1 = *x, v1 = *v;
    for (int j = 0; j < 6; j++) {
        x1 = v3_axpy(h * dormand_prince_a[5][j], kx[j], x1);
        v1 = v3_axpy(h * dormand_prince_a[5][j], kv[j], v1);
    }
    *x = x1;
    *v = v1;
}

void model_step(const struct model *m, enum integration_method method, double h, vec3d *x, vec3d *v)
{
    if (method == METHOD_DOPRI5) {
        dopri5_fixed_step(m, h, x, v);
        return;
    }
    vec3d x0 = *x, v0 = *v;
    if (method == METHOD_EULER) {
        /* Eq. (2): both updates read the old state. */
        vec3d f0 = model_accel(m, x0, v0);
        *x = v3_axpy(h, v0, x0);
        *v = v3_axpy(h, f0, v0);
        return;
    }
    vec3d k1x = v0;
    vec3d k1v = model_accel(m, x0, v0);
    vec3d k2x = v3_axpy(0.5 * h, k1v, v0);
    vec3d k2v = model_accel(m, v3_axpy(0.5 * h, k1x, x0), k2x);
    vec3d k3x = v3_axpy(0.5 * h, k2v, v0);
    vec3d k3v = model_accel(m, v3_axpy(0.5 * h, k2x, x0), k3x);
    vec3d k4x = v3_axpy(h, k3v, v0);
    vec3d k4v = model_accel(m, v3_axpy(h, k3x, x0), k4x);
    vec3d dx = v3_add(v3_add(k1x, k4x), v3_scale(v3_add(k2x, k3x), 2.0));
    vec3d dv = v3_add(v3_add(k1v, k4v), v3_scale(v3_add(k2v, k3v), 2.0));
    *x = v3_axpy(h / 6.0, dx, x0);
    *v = v3_axpy(h / 6.0, dv, v0);
}
