/* The machine's limit for the benchmark: the CPU doing exactly the float arithmetic of one step of
 * shaders_es/stage_integrate.glsl (model_accel, Euler or RK4, the finite and travelling checks with
 * selects) for many rays at once, vectorised across rays and on every core, so that the GPU path's
 * integration steps per second can be reported as a fraction of what this machine can do. */
#ifndef BT_CPU_LIMIT_H
#define BT_CPU_LIMIT_H
#include <stddef.h>
#include "io/error.h"
#include "physics/model.h"

struct cpu_limit_result {
    double steps_per_second;  /* ray integration steps (one whole Euler or RK4 step of one ray) per second */
    double seconds;           /* wall time measured */
    long long steps;          /* steps done: rays * steps_per_call * sweeps */
    long long sweeps;         /* sweeps over every ray, each of steps_per_call steps */
    int threads;
    double checksum;          /* sum of final |x| over rays, so the work cannot be optimised away */
};

/* Integrate n_rays rays (struct-of-arrays floats, starting 10 to 20 scene units from the model's centre
 * and heading inward at up to 45 degrees off the centre) with the model's float arithmetic,
 * steps_per_call steps per ray per sweep, repeating sweeps until min_seconds have elapsed (one warm-up
 * sweep first is not counted). threads <= 0: one per online core. Every model of enum model_type but
 * MODEL_FLAT, which integrates nothing. 0 ok, or -1 with e (no place; ERROR_RUNTIME: arguments
 * outside those ranges, which no command takes from its user, or no memory for the rays). */
int cpu_limit_measure(const struct model *m, enum integration_method method, int n_rays, int steps_per_call,
                      int threads, double min_seconds, struct cpu_limit_result *out, struct error *e);

/* One step of size h for one ray in float, the arithmetic of the measured kernel (for tests); the
 * kernel's freeze of rays that left the bounding sphere or stopped being finite is not applied.
 * MODEL_FLAT, which is not integrated, leaves x and v as they are. */
void cpu_limit_step(const struct model *m, enum integration_method method, float h, float x[3], float v[3]);

#endif
