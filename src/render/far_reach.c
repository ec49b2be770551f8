/* The objects' bounds that fixed steps grow away from (far_reach.h). */
#include "render/far_reach.h"
#include "scene/object_bound.h"
#include <math.h>

/* The smallest ball holding balls a and b. */
static struct object_bound ball_union(const struct object_bound *a, const struct object_bound *b)
{
    struct object_bound u = {.centre = a->centre, .radius = a->radius, .normal = v3(0.0, 0.0, 0.0), .flat = 0};
    vec3d ab = v3_sub(b->centre, a->centre);
    double d = v3_len(ab);
    if (d + b->radius <= a->radius)
        return u;
    if (d + a->radius <= b->radius) {
        u.centre = b->centre;
        u.radius = b->radius;
        return u;
    }
    u.radius = 0.5 * (d + a->radius + b->radius);
    u.centre = v3_add(a->centre, v3_scale(ab, (u.radius - a->radius) / d));
    return u;
}

int far_reach_pack(const struct scene *s, int most, float ball[][4], float normal[][4])
{
    struct object_bound b[SCENE_MAX_OBJECTS];
    int n = s->n_objects;
    for (int i = 0; i < n; i++) {
        object_bound(&s->objects[i], &b[i]);
        /* a degenerate flat object (no normal) is bounded by its ball alone */
        b[i].flat = b[i].flat && v3_dot(b[i].normal, b[i].normal) > 0.0;
    }
    most = most < 1 ? 1 : most > FAR_REACH_MAX ? FAR_REACH_MAX : most;
    while (n > most) {
        int best_i = 0, best_j = 1;
        double best = INFINITY;
        for (int i = 0; i < n; i++)
            for (int j = i + 1; j < n; j++) {
                double r = ball_union(&b[i], &b[j]).radius;
                if (r < best) {
                    best = r;
                    best_i = i;
                    best_j = j;
                }
            }
        b[best_i] = ball_union(&b[best_i], &b[best_j]);
        b[best_j] = b[--n];
    }
    for (int k = 0; k < n; k++) {
        ball[k][0] = (float)b[k].centre.x;
        ball[k][1] = (float)b[k].centre.y;
        ball[k][2] = (float)b[k].centre.z;
        ball[k][3] = (float)b[k].radius;
        normal[k][0] = b[k].flat ? (float)b[k].normal.x : 0.0f;
        normal[k][1] = b[k].flat ? (float)b[k].normal.y : 0.0f;
        normal[k][2] = b[k].flat ? (float)b[k].normal.z : 0.0f;
        normal[k][3] = 0.0f;
    }
    return n;
}
