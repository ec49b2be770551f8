#include "ref/surface.h"
#include "scene/object_bound.h"

void surface_init(struct surface *sf, const struct object *o)
{
    struct object_bound b;
    object_bound(o, &b);
    *sf = (struct surface){.object = o, .center = b.centre, .radius = o->radius, .bound_radius = b.radius,
                           .normal = b.normal, .is_sphere = !b.flat};
    /* never hit: a sphere without radius, a flat object without a plane (object_bound's normal 0) */
    sf->degenerate = b.flat ? v3_len(b.normal) == 0.0 : !(o->radius > 0.0);
}

double surface_value(const struct surface *sf, vec3d x)
{
    vec3d d = v3_sub(x, sf->center);
    if (sf->is_sphere)
        return v3_dot(d, d) - sf->radius * sf->radius;
    return v3_dot(d, sf->normal);
}

/* Barycentric weights of p1 and p2 for a point p in the triangle's plane. */
static void barycentric(const struct object *o, vec3d p, double *u, double *v)
{
    vec3d e1 = v3_sub(o->vertex[1], o->vertex[0]), e2 = v3_sub(o->vertex[2], o->vertex[0]);
    vec3d q = v3_sub(p, o->vertex[0]);
    double d11 = v3_dot(e1, e1), d12 = v3_dot(e1, e2), d22 = v3_dot(e2, e2);
    double q1 = v3_dot(q, e1), q2 = v3_dot(q, e2);
    double det = d11 * d22 - d12 * d12;
    *u = (d22 * q1 - d12 * q2) / det;
    *v = (d11 * q2 - d12 * q1) / det;
}

int surface_contains(const struct surface *sf, vec3d p)
{
    const struct object *o = sf->object;
    if (sf->degenerate)
        return 0;
    switch (o->type) {
    case PRIM_SPHERE:
        return 1;
    case PRIM_DISK: {
        double r = v3_len(v3_sub(p, o->center));
        return r >= o->inner_radius && r <= o->radius;
    }
    case PRIM_RECT: {
        vec3d d = v3_sub(p, o->center);
        double su = v3_dot(d, o->axis_u) / v3_dot(o->axis_u, o->axis_u);
        double sv = v3_dot(d, o->axis_v) / v3_dot(o->axis_v, o->axis_v);
        return fabs(su) <= 1.0 && fabs(sv) <= 1.0;
    }
    case PRIM_TRIANGLE:
    default: {
        double u, v;
        barycentric(o, p, &u, &v);
        return u >= 0.0 && v >= 0.0 && u + v <= 1.0;
    }
    }
}

void surface_shading(const struct surface *sf, vec3d p, vec3d *normal, double uv[2])
{
    const struct object *o = sf->object;
    switch (o->type) {
    case PRIM_SPHERE: {
        vec3d n = v3_scale(v3_sub(p, o->center), 1.0 / o->radius);
        vec3d pole = v3_normalize(o->pole), ref = v3_perpendicular(pole), third = v3_cross(pole, ref);
        double c = v3_dot(n, pole);
        uv[0] = atan2(v3_dot(n, third), v3_dot(n, ref)) / (2.0 * PI_D) + 0.5;
        uv[1] = acos(c < -1.0 ? -1.0 : c > 1.0 ? 1.0 : c) / PI_D;
        *normal = n;
        break;
    }
    case PRIM_DISK: {
        vec3d d = v3_sub(p, o->center), ref = v3_perpendicular(sf->normal), third = v3_cross(sf->normal, ref);
        double width = o->radius - o->inner_radius;
        uv[0] = (v3_len(d) - o->inner_radius) / (width > 1e-6 ? width : 1e-6);
        uv[1] = atan2(v3_dot(d, third), v3_dot(d, ref)) / (2.0 * PI_D) + 0.5;
        *normal = sf->normal;
        break;
    }
    case PRIM_RECT: {
        vec3d d = v3_sub(p, o->center);
        uv[0] = 0.5 * (v3_dot(d, o->axis_u) / v3_dot(o->axis_u, o->axis_u) + 1.0);
        uv[1] = 0.5 * (v3_dot(d, o->axis_v) / v3_dot(o->axis_v, o->axis_v) + 1.0);
        *normal = sf->normal;
        break;
    }
    case PRIM_TRIANGLE:
    default: {
        double u, v;
        barycentric(o, p, &u, &v);
        for (int k = 0; k < 2; k++)
            uv[k] = (1.0 - u - v) * o->uv[0][k] + u * o->uv[1][k] + v * o->uv[2][k];
        *normal = sf->normal;
        break;
    }
    }
}
