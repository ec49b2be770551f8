/* Models of curved light: dx/dtau = v, dv/dtau = f(x, v) (paper eq. 1), in double precision.
 * The GLSL ES versions in shaders_es/model_*.glsl compute the same functions in float. */
#ifndef BT_MODEL_H
#define BT_MODEL_H
#include "physics/vec3.h"

enum model_type {
    MODEL_FLAT,           /* straight rays; nothing is integrated */
    MODEL_LORENZ,
    MODEL_ROSSLER,
    MODEL_POTENTIAL,      /* radial force field around a centre */
    MODEL_REFRACTION,     /* medium with varying index of refraction */
    MODEL_SCHWARZSCHILD,
    MODEL_NEWTONIAN,      /* corpuscles of light pulled by a point mass (Soldner 1801) */
    MODEL_COUNT
};

enum potential_profile {
    PROFILE_YUKAWA,       /* V = zeta exp(-mu r) / r, f = -grad V */
    PROFILE_POLYNOMIAL    /* f = -strength (x-c)/r xi(r), xi = 2r^3/R^3 - 3r^2/R^2 + 1 for r <= R */
};

struct model {
    enum model_type type;
    vec3d center;         /* origin of the flow, the force centre, the explosion centre, the mass */
    /* Lorenz and Roessler: f(x) = strength * F((x - center) / scale) */
    double scale;
    double strength;
    double sigma, rho, beta;                 /* Lorenz */
    double ross_a, ross_b, ross_c;           /* Roessler alpha, beta, gamma */
    /* Potential field */
    enum potential_profile profile;
    double zeta, mu;                         /* Yukawa */
    double radius;                           /* polynomial xi(r): range R (strength reused) */
    /* Varying index of refraction: n(x) = 1 + amplitude * shell(r) * (1 + noise_amplitude * N(x)) */
    double amplitude, shell_radius, shell_width, noise_amplitude, noise_frequency;
    /* Schwarzschild, Newtonian */
    double mass;                             /* M in scene length units (G = c = 1) */
};

const char *model_name(enum model_type t);

/* What the rest of the program asks of a model, so that no file outside src/physics tests a model's
 * type (docs/ARCHITECTURE.md, "A new model"; `make check-layers` checks it): one row per model in
 * model.c, beside its force law. */
struct model_ops {
    const char *name;            /* model.type in a scene file; its shader is shaders_es/model_NAME.glsl */
    int integrates;              /* 0: its rays are straight lines whatever its keys (flat space) */
    int has_mass;                /* model.mass is its parameter: the kiosk's mass knob sets it */
    int exact_orbits;            /* render.method = orbit_table follows its rays (physics/orbit_table.h) */
    /* the mass whose static observers' clocks run slow, which shifts the frequency of light
     * between them (docs/RELATIVITY.md); NULL: none */
    double (*gravity_mass)(const struct model *m);
    /* where a ray that left the bounding sphere at x moving along v is seen: the unit direction it
     * goes in at infinity (*out), 1; 0 where it keeps its own (light that falls in); NULL: the
     * model's field is left behind at the sphere, which sees the sky along the ray's direction there */
    int (*direction_at_infinity)(const struct model *m, vec3d x, vec3d v, vec3d *out);
    /* the variant of its shader (#define lines, or ""); NULL: one shader for every value */
    const char *(*shader_defines)(const struct model *m);
};
const struct model_ops *model_ops_of(enum model_type t);
/* ops->gravity_mass of m, 0 without one */
double model_gravity_mass(const struct model *m);
/* Are the rays of this model straight lines: flat space, or a model with every field off (no
 * strength, no mass, no index change)? Such rays are not integrated but cast in one segment. */
int model_is_straight(const struct model *m);
/* f(x, v) of eq. (1). */
vec3d model_accel(const struct model *m, vec3d x, vec3d v);
/* Initial ray velocity for a unit viewing direction dir seen by a camera at x. */
vec3d model_initial_velocity(const struct model *m, vec3d x, vec3d dir);
/* Radius (around center) inside which rays are captured; 0 when the model has none. */
double model_capture_radius(const struct model *m);
/* Schwarzschild: the critical launch angle (impact parameter b_c = 3 sqrt(3) M) for the static
 * observer at r_o > 2M, from the outward radial direction; orbit_critical_from_axis gives it from
 * the nearer radial direction (*inward: from the inward one, r_o > 3M; may be NULL), without the
 * rounding of pi - angle. The shadow's angular radius is pi - orbit_critical_angle. */
double orbit_critical_angle(double mass, double r_observer);
double orbit_critical_from_axis(double mass, double r_observer, int *inward);
/* Index of refraction n(x) for MODEL_REFRACTION (1 elsewhere). */
double model_refraction_index(const struct model *m, vec3d x);

/* Euler (paper eq. 2), classical RK4, and the fifth-order solution of Dormand and Prince's 5(4) pair;
 * and no integration at all: the GPU follows exact Schwarzschild orbits from a table
 * (physics/orbit_table.h), which model_step, a stepping function, takes as RK4. */
enum integration_method { METHOD_EULER, METHOD_RK4, METHOD_DOPRI5, METHOD_ORBIT_TABLE };
const char *method_name(enum integration_method m);
/* One step of size h of eq. (1), in place (Euler as eq. (2), classical RK4, or Dormand-Prince 5). */
void model_step(const struct model *m, enum integration_method method, double h, vec3d *x, vec3d *v);

#endif
