/* Segment-primitive intersections; see intersect.h for the contract. */
#include "physics/intersect.h"

#include <math.h>

/* Sine of the angle between segment and plane below which the segment counts as parallel: the
 * crossing parameter would be a ratio of two rounding errors. Dimensionless. */
#define PARALLEL_SINE_LIMIT 1e-12
/* Sine of a triangle's smallest corner angle below which it has no usable area. Dimensionless. */
#define DEGENERATE_SINE_LIMIT 1e-12

static int in_unit_interval(double t) { return t >= 0.0 && t <= 1.0; }

int intersect_sphere(vec3d a, vec3d b, vec3d c, double radius, double *t)
{
    vec3d d = v3_sub(b, a);
    vec3d oc = v3_sub(a, c);
    double dd = v3_dot(d, d);
    if (!(dd > 0.0))
        return 0;
    double half_b = v3_dot(oc, d);
    /* The discriminant over dd is radius^2 minus the squared distance of the line from c; forming
     * it from that distance avoids the cancellation in half_b^2 - dd*C for distant spheres. */
    vec3d closest = v3_axpy(-half_b / dd, d, oc);
    double disc = radius * radius - v3_dot(closest, closest);
    if (disc < 0.0)
        return 0;
    double root = sqrt(dd * disc);
    double q = -(half_b + copysign(root, half_b));
    double c_term = v3_dot(oc, oc) - radius * radius;
    double t_near, t_far;
    if (q == 0.0) {
        t_near = t_far = 0.0;     /* grazing exactly at a */
    } else {
        /* Vieta's product c/q keeps the smaller root accurate where -b + sqrt would cancel. */
        double t1 = q / dd, t2 = c_term / q;
        t_near = fmin(t1, t2);
        t_far = fmax(t1, t2);
    }
    if (in_unit_interval(t_near)) {
        *t = t_near;
        return 1;
    }
    if (in_unit_interval(t_far)) {
        *t = t_far;
        return 1;
    }
    return 0;
}

int intersect_triangle(vec3d a, vec3d b, vec3d p0, vec3d p1, vec3d p2,
                       double *t, double *bary_u, double *bary_v)
{
    vec3d d = v3_sub(b, a);
    vec3d e1 = v3_sub(p1, p0);
    vec3d e2 = v3_sub(p2, p0);
    double area2 = v3_len(v3_cross(e1, e2));
    if (!(area2 > DEGENERATE_SINE_LIMIT * v3_len(e1) * v3_len(e2)))
        return 0;
    vec3d pvec = v3_cross(d, e2);
    double det = v3_dot(e1, pvec);   /* = -d . (e1 x e2) */
    if (!(fabs(det) > PARALLEL_SINE_LIMIT * v3_len(d) * area2))
        return 0;
    double inv_det = 1.0 / det;
    vec3d tvec = v3_sub(a, p0);
    double u = v3_dot(tvec, pvec) * inv_det;
    if (u < 0.0 || u > 1.0)
        return 0;
    vec3d qvec = v3_cross(tvec, e1);
    double v = v3_dot(d, qvec) * inv_det;
    if (v < 0.0 || u + v > 1.0)
        return 0;
    double t_hit = v3_dot(e2, qvec) * inv_det;
    if (!in_unit_interval(t_hit))
        return 0;
    *t = t_hit;
    *bary_u = u;
    *bary_v = v;
    return 1;
}

/* Crossing of the segment with the plane through c with normal n, or 0 when parallel or outside. */
static int plane_crossing(vec3d a, vec3d d, vec3d c, vec3d n, double *t)
{
    double denom = v3_dot(n, d);
    if (!(fabs(denom) > PARALLEL_SINE_LIMIT * v3_len(n) * v3_len(d)))
        return 0;
    double t_hit = v3_dot(n, v3_sub(c, a)) / denom;
    if (!in_unit_interval(t_hit))
        return 0;
    *t = t_hit;
    return 1;
}

int intersect_disk(vec3d a, vec3d b, vec3d c, vec3d normal, double inner_radius, double outer_radius,
                   double *t)
{
    vec3d d = v3_sub(b, a);
    double t_hit;
    if (!plane_crossing(a, d, c, normal, &t_hit))
        return 0;
    double dist = v3_len(v3_sub(v3_axpy(t_hit, d, a), c));
    if (dist < inner_radius || dist > outer_radius)
        return 0;
    *t = t_hit;
    return 1;
}

int intersect_rect(vec3d a, vec3d b, vec3d c, vec3d axis_u, vec3d axis_v,
                   double *t, double *s_u, double *s_v)
{
    vec3d d = v3_sub(b, a);
    double t_hit;
    if (!plane_crossing(a, d, c, v3_cross(axis_u, axis_v), &t_hit))
        return 0;
    vec3d w = v3_sub(v3_axpy(t_hit, d, a), c);
    double su = v3_dot(w, axis_u) / v3_dot(axis_u, axis_u);
    double sv = v3_dot(w, axis_v) / v3_dot(axis_v, axis_v);
    if (fabs(su) > 1.0 || fabs(sv) > 1.0)
        return 0;
    *t = t_hit;
    *s_u = su;
    *s_v = sv;
    return 1;
}
