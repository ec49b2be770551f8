/* The double-precision CPU reference: one ray through a scene, integrated with the adaptive
 * Dormand-Prince 5(4) pair, with every crossing (object surface, bounding sphere, horizon)
 * located on the dense output so that the step size never decides what is hit.
 *
 * Same semantics as the GPU path: the ray obeys dx/dlambda = v, dv/dlambda = f(x, v) of the
 * scene's model; it ends at its first object hit, where it leaves the bounding sphere (sky), where
 * it enters the capture radius (captured), or when lambda reaches segments * steps_per_segment *
 * step (unfinished; with method orbit_table, which has no budget, never). In flat space the ray is
 * one straight segment, as on the GPU. */
#ifndef BT_REFERENCE_H
#define BT_REFERENCE_H
#include "scene/scene.h"
#include <stdint.h>

#define REF_DEFAULT_RTOL 1e-10

struct ref_options {
    double rtol;          /* relative tolerance per step (default REF_DEFAULT_RTOL) */
    double atol;          /* absolute tolerance of positions, scene length units (default rtol * bound
                           * radius); velocities use rtol * |v0| */
    long max_steps;       /* accepted + rejected steps before the ray counts as failed */
    double min_step;      /* smallest step size; a ray that needs less fails (no stall) */
};

/* Defaults for scene s (tolerances scale with the bounding radius). */
void ref_options_default(struct ref_options *o, const struct scene *s);

struct ref_ray {
    int32_t outcome;      /* object index >= 0 or DUMP_SKY / DUMP_CAPTURED / DUMP_UNFINISHED / DUMP_FAILED */
    vec3d hit;            /* hit point (outcome >= 0) */
    vec3d normal;         /* unit surface normal at the hit, as the shader computes it */
    double uv[2];         /* texture coordinates at the hit */
    vec3d position;       /* where the ray ended (hit, boundary or capture crossing, or last state) */
    vec3d velocity;       /* dx/dlambda there */
    double lambda;        /* curve parameter where it ended */
    double depth;         /* segment index + fraction: lambda / (steps_per_segment * step) */
    long steps;           /* accepted steps */
    long rejected;        /* rejected steps */
    double winding;       /* angle swept around the model centre, radians (orbits near the photon sphere) */
    double min_radius;    /* closest approach to the model centre */
};

/* Called at lambda = k * interval (k = 1, 2, ...) while the ray travels, and once at its end. */
typedef void (*ref_sample_fn)(void *arg, double lambda, vec3d x, vec3d v);

/* Trace one ray from x0 with initial velocity v0 (as model_initial_velocity gives it).
 * sample may be NULL. Never returns a non-finite state: such a ray is DUMP_FAILED at its last
 * finite state. */
void ref_trace(const struct scene *s, const struct ref_options *o, vec3d x0, vec3d v0, struct ref_ray *out,
               double sample_interval, ref_sample_fn sample, void *arg);

/* Integrate the bare model (no objects, no boundary) from lambda = 0 to length with the same
 * adaptive pair; for tests against closed forms and independent integrators. Returns the number of
 * accepted steps, or -1 when the state stopped being finite or max_steps ran out. */
long ref_integrate(const struct model *m, const struct ref_options *o, double length, vec3d *x, vec3d *v);

#endif
