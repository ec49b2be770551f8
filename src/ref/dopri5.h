/* The embedded Runge-Kutta pair of Dormand and Prince (1980), order 5 with an order-4 error
 * estimate, first-same-as-last, with the order-4 dense output of Hairer, Norsett and Wanner
 * (Solving ODEs I, section II.6, routine CONTD5). State: ray position x and velocity v. */
#ifndef BT_DOPRI5_H
#define BT_DOPRI5_H
#include "physics/model.h"

struct dopri5 {
    const struct model *model;
    double rtol;
    double atol[6];        /* absolute tolerance of each component: position, then velocity */
    double y[6];           /* x, v at lambda */
    double dy[6];          /* derivative at lambda (first same as last) */
    double lambda;
    double h;              /* next step size to try */
    long steps, rejected;
    /* dense output of the last accepted step [lambda_old, lambda_old + h_old] */
    double lambda_old, h_old;
    double cont[5][6];
};

/* Start at lambda 0 from x, v; h is the first step to try. Absolute tolerances: atol_x for the
 * position (a length), atol_v for the velocity (whose scale is |v|, about 1). */
void dopri5_init(struct dopri5 *d, const struct model *m, double rtol, double atol_x, double atol_v, vec3d x, vec3d v,
                 double h);
/* Take one accepted step of at most h_max. Returns 0, or -1 when the step size fell below
 * h_min or the state stopped being finite (d is left at its last good state). */
int dopri5_step(struct dopri5 *d, double h_max, double h_min, long max_tries);
/* Position and velocity at theta in [0, 1] of the last accepted step. */
void dopri5_dense(const struct dopri5 *d, double theta, vec3d *x, vec3d *v);
vec3d dopri5_dense_x(const struct dopri5 *d, double theta);

#endif
