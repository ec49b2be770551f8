/* Exact photon orbits around a non-rotating mass, tabulated for one static observer.
 *
 * Every Schwarzschild photon orbit lies in a plane through the centre; u = 1/r obeys Binet's
 * u'' + u = 3 M u^2 in the polar angle phi. A static observer at r_o who sees a ray leave at angle
 * psi from the outward radial direction starts it at u_o = 1/r_o with
 * du/dphi = -u_o sqrt(1 - 2 M u_o) cot psi (impact parameter b = r_o sin psi / sqrt(1 - 2M/r_o)).
 * So for one (M, r_o) the whole family of orbits is one-parameter, in psi:
 *   - rays with psi < psi_c escape, rays with psi > psi_c fall through the horizon, where psi_c is
 *     the launch angle of the critical impact parameter b_c = 3 sqrt(3) M;
 *   - each orbit runs from the observer (phi = 0) to phi_end, where it reaches r_far (escaping)
 *     or just inside the horizon (captured).
 * The table holds, per launch angle, phi_end and u at evenly spaced fractions s = phi / phi_end,
 * with du/ds, integrated in double precision (Dormand-Prince 5(4), tolerance 1e-12; the end located
 * by integrating in u over the last step). Rows are spaced as ln|psi - psi_c| next to the critical
 * angle, where phi_end diverges logarithmically, and the two sides of psi_c are separate blocks of
 * rows, never interpolated across. shaders_es/orbit_table.glsl reads the same numbers as a float
 * texture and interpolates exactly as orbit_table_eval() does here. */
#ifndef BT_ORBIT_TABLE_H
#define BT_ORBIT_TABLE_H
#include <stddef.h>
#include "io/error.h"
#include "physics/model.h"

enum orbit_side { ORBIT_ESCAPES, ORBIT_CAPTURED };

/* Rows are at psi_c -+ d, evenly spaced in the coordinate ln(d / epsilon) + d / even_scale:
 * logarithmic next to psi_c, even beyond even_scale (rad). The float launch angle of a camera ray
 * is good to about 1e-7 rad, so rows closer than epsilon to psi_c would tell nothing; a side
 * narrower than 1000 epsilon (the capture cone of a tiny mass) takes a thousandth of its width. */
#define ORBIT_CRITICAL_EPSILON 1e-7
#define ORBIT_EVEN_SCALE 0.25
/* The outermost rows, rad from the radial directions, where cot psi stays finite; phi_end is
 * stored divided by sin psi, which has a finite limit there, so rays closer still are exact. */
#define ORBIT_RADIAL_GAP 1e-6
/* A captured orbit ends this fraction inside the horizon, so that a float position is inside. */
#define ORBIT_HORIZON_MARGIN 1e-5
/* Samples of each orbit's chord schedule (see orbit_table.c: chords of equal sag). */
#define ORBIT_WARP_SAMPLES 32
/* Binet integration: relative and absolute (of u_o) tolerance per step. */
#define ORBIT_RTOL 1e-12

struct orbit_table_params {
    double mass;               /* M > 0 (scene length units, G = c = 1) */
    double r_observer;         /* r_o > 2M: distance of the camera from the centre */
    double r_far;              /* escaping orbits are tabulated out to here (> r_o) */
    int rows_per_side;         /* launch angles on each side of psi_c (>= 4) */
    int columns;               /* samples along each orbit (>= 4) */
    /* segments per orbit: the fewest chords of about equal sag that stray at most this far from
     * the orbit (scene units), at most max_segments; INFINITY: one segment */
    double chord_tolerance;
    int max_segments;
    /* no object lies closer to the centre than this (scene units): a chord between two points
     * inside this radius stays inside it and can meet nothing, so its sag does not count */
    double clear_radius;
};

struct orbit_table {
    struct orbit_table_params p;
    double psi_c;              /* critical launch angle */
    /* the same measured from the nearer radial direction: from the inward one (towards the mass)
     * when r_o > 3M, where psi_c = pi - critical_from_axis, else from the outward one */
    double critical_from_axis;
    int critical_inward;
    double psi_min, psi_max;   /* the outermost rows */
    double log_span[2];        /* each side's extent in the row coordinate */
    double epsilon[2];         /* each side's epsilon: ORBIT_CRITICAL_EPSILON, or less for a narrow side */
    double u_observer, u_far, u_capture;
    /* texture layout: width columns + 1 + ORBIT_WARP_SAMPLES, height 2 rows_per_side (escaping
     * rows first, from psi_c outwards); texel (j, row) = (u(s_j), du/ds(s_j), u(s_j+1), du/ds(s_j+1))
     * with s_j = j / (columns - 1) (the last column's next pair is 0); texel (columns, row) =
     * (phi_end / sin psi, segments, phi_infinity / sin psi, psi); texel (columns + 1 + m, row) = (s where chord
     * schedule sample m lies, the same for sample m + 1 (or m, the last), and these two of the next
     * row of the same side (the last row: its own)): chord k of n ends at the warp interpolated
     * linearly at k / n. The orbit's interpolation reads one texel per row, the chord schedule one
     * texel for both of its rows. */
    int width, height;
    float *texels;             /* RGBA, width x height, row-major */
    double *u, *du_ds;         /* the same in double: height x columns */
    double *phi_over_sin;      /* height */
    /* the angle swept to infinity (escaping rows; captured rows: phi_end), over sin psi: where the
     * sky is seen (physics/escape.h) */
    double *phi_infinity_over_sin;
    double *psi;               /* launch angle of each row */
    int *segments;             /* height */
    int max_segments;          /* over all rows */
    double build_seconds;
};

/* Build the table; 0, or -1 with e (no place; ERROR_RUNTIME: bad parameters, out of memory, an
 * orbit that does not end, all of which a validated scene never gives). */
int orbit_table_build(struct orbit_table *t, const struct orbit_table_params *p, struct error *e);
/* Whether a table can be built for (mass, r_observer): 0 where one side of psi_c is too narrow for
 * rows of their own in double precision, the capture cone of a mass below about 4e-14 r_o. Such a
 * mass bends a camera ray by at most about 2e-13 / theta rad (theta: the ray's angle from the
 * mass), under a float direction's rounding except within about 3e-6 rad of the mass, and the
 * renderer takes its rays as straight (render/renderer.c). */
int orbit_table_resolves(double mass, double r_observer);
void orbit_table_free(struct orbit_table *t);
/* The double arrays freed, the texels and the scalars kept: what the GPU reads of a table. */
void orbit_table_free_cpu_arrays(struct orbit_table *t);

/* orbit_critical_angle and orbit_critical_from_axis: physics/model.h */
/* Side and fractional row (0 .. rows_per_side - 1) of launch angle psi. */
double orbit_table_row(const struct orbit_table *t, double psi, enum orbit_side *side);

/* The orbit of launch angle psi at fraction s in [0, 1] as the shader interpolates it: u, du/dphi,
 * phi; and phi_end and the segment count of the ray. orbit_table_chord_end: the fraction s where
 * chord k of the ray's n ends. */
struct orbit_point {
    double u, du_dphi, phi;
};
void orbit_table_eval(const struct orbit_table *t, double psi, double s, struct orbit_point *out, double *phi_end,
                      int *segments);
double orbit_table_chord_end(const struct orbit_table *t, double psi, int k, int n);

/* One orbit traced directly (no table): phi_end and whether it is captured, and u, du/dphi at
 * n_at angles phi_at[] (ascending, <= phi_end; NULL for none). 0, or -1 when it does not end. */
int orbit_trace(double mass, double r_observer, double psi, double u_far, double u_capture, const double *phi_at,
                int n_at, double *u_at, double *du_at, double *phi_end, int *captured);

#endif
