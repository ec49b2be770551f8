/* Double-precision 3-vectors for the physics and the CPU reference. */
#ifndef BT_VEC3_H
#define BT_VEC3_H
#include <math.h>

typedef struct { double x, y, z; } vec3d;

#define PI_D 3.14159265358979323846

static inline vec3d v3(double x, double y, double z) { vec3d r = {x, y, z}; return r; }
static inline vec3d v3_add(vec3d a, vec3d b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec3d v3_sub(vec3d a, vec3d b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec3d v3_scale(vec3d a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static inline vec3d v3_axpy(double s, vec3d a, vec3d b) { return v3(s * a.x + b.x, s * a.y + b.y, s * a.z + b.z); }
static inline double v3_dot(vec3d a, vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline vec3d v3_cross(vec3d a, vec3d b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double v3_len(vec3d a) { return sqrt(v3_dot(a, a)); }
/* Between these the squared length of a vector neither underflows nor overflows. */
#define V3_LEN_SAFE_MIN 1e-150
#define V3_LEN_SAFE_MAX 1e150
static inline vec3d v3_normalize(vec3d a)
{
    double l = v3_len(a);
    if (l > V3_LEN_SAFE_MIN && l < V3_LEN_SAFE_MAX)
        return v3_scale(a, 1.0 / l);
    /* a direction of 1e-200 or 1e200: scaled by its largest component first */
    double m = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
    if (!(m > 0.0) || !isfinite(m))
        return a;
    a = v3_scale(a, 1.0 / m);
    return v3_scale(a, 1.0 / v3_len(a));
}
/* A unit vector perpendicular to n: the reference direction of angular texture coordinates
 * (the GPU's uniforms and the CPU shading take it from here, so both agree). */
static inline vec3d v3_perpendicular(vec3d n)
{
    vec3d helper = fabs(n.x) < 0.9 ? v3(1, 0, 0) : v3(0, 1, 0);
    return v3_normalize(v3_cross(helper, n));
}
static inline int v3_isfinite(vec3d a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }

#endif
