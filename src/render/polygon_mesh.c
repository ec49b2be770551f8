/* Tessellation of the primitives with the ray tracer's normals and texture coordinates
 * (shaders_es/stage_intersect.glsl, src/ref/surface.c). */
#include "render/polygon_mesh.h"
#include <math.h>
#include <stdlib.h>

static void put(struct mesh_vertex *v, vec3d p, vec3d n, double u, double w)
{
    v->rest[0] = (float)p.x, v->rest[1] = (float)p.y, v->rest[2] = (float)p.z;
    v->normal[0] = (float)n.x, v->normal[1] = (float)n.y, v->normal[2] = (float)n.z;
    v->uv[0] = (float)u, v->uv[1] = (float)w;
}

/* Two triangles per cell of a (columns + 1) x (rows + 1) vertex grid. */
static void grid_indices(struct polygon_mesh *m, int columns, int rows)
{
    for (int j = 0; j < rows; j++)
        for (int i = 0; i < columns; i++) {
            uint16_t a = (uint16_t)(j * (columns + 1) + i), b = (uint16_t)(a + 1);
            uint16_t c = (uint16_t)(a + columns + 1), d = (uint16_t)(c + 1);
            uint16_t tri[6] = {a, b, d, a, d, c};
            for (int k = 0; k < 6; k++)
                m->indices[m->n_indices++] = tri[k];
        }
}

static int alloc(struct polygon_mesh *m, int vertices, int indices)
{
    m->vertices = malloc(sizeof *m->vertices * (size_t)vertices);
    m->indices = malloc(sizeof *m->indices * (size_t)indices);
    m->n_vertices = m->n_indices = 0;
    return m->vertices && m->indices ? 0 : -1;
}

/* uv = (longitude / 2 pi + 1/2, colatitude / pi) about the pole, from the reference axis */
static void sphere(const struct object *o, int n, struct polygon_mesh *m)
{
    vec3d pole = v3_normalize(o->pole), ref = v3_perpendicular(pole), third = v3_cross(pole, ref);
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= 2 * n; i++) {
            double v = (double)j / n, u = (double)i / (2 * n);
            double theta = PI_D * v, phi = 2.0 * PI_D * (u - 0.5);
            vec3d across = v3_add(v3_scale(ref, cos(phi)), v3_scale(third, sin(phi)));
            vec3d normal = v3_add(v3_scale(pole, cos(theta)), v3_scale(across, sin(theta)));
            put(&m->vertices[m->n_vertices++], v3_axpy(o->radius, normal, o->center), normal, u, v);
        }
    grid_indices(m, 2 * n, n);
}

/* uv = ((s + 1) / 2, (t + 1) / 2) for the point centre + s axis_u + t axis_v */
static void rect(const struct object *o, int n, struct polygon_mesh *m)
{
    vec3d normal = v3_normalize(v3_cross(o->axis_u, o->axis_v));
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++) {
            double s = -1.0 + 2.0 * i / n, t = -1.0 + 2.0 * j / n;
            vec3d p = v3_add(o->center, v3_add(v3_scale(o->axis_u, s), v3_scale(o->axis_v, t)));
            put(&m->vertices[m->n_vertices++], p, normal, 0.5 * (s + 1.0), 0.5 * (t + 1.0));
        }
    grid_indices(m, n, n);
}

/* uv = ((r - inner) / (outer - inner), angle / 2 pi + 1/2) */
static void disk(const struct object *o, int n, struct polygon_mesh *m)
{
    vec3d normal = v3_normalize(o->normal), ref = v3_perpendicular(normal), third = v3_cross(normal, ref);
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= 2 * n; i++) {
            double u = (double)j / n, w = (double)i / (2 * n);
            double r = o->inner_radius + u * (o->radius - o->inner_radius), phi = 2.0 * PI_D * (w - 0.5);
            vec3d p = v3_add(o->center, v3_scale(v3_add(v3_scale(ref, cos(phi)), v3_scale(third, sin(phi))), r));
            put(&m->vertices[m->n_vertices++], p, normal, u, w);
        }
    grid_indices(m, 2 * n, n);
}

/* barycentric grid: point v0 + a (v1 - v0) + b (v2 - v0), uv interpolated the same way */
static void triangle(const struct object *o, int n, struct polygon_mesh *m)
{
    vec3d e1 = v3_sub(o->vertex[1], o->vertex[0]), e2 = v3_sub(o->vertex[2], o->vertex[0]);
    vec3d normal = v3_normalize(v3_cross(e1, e2));
    int row_start[SCENE_MAX_SUBDIVISION + 2];
    for (int j = 0; j <= n; j++) {
        row_start[j] = m->n_vertices;
        for (int i = 0; i <= n - j; i++) {
            double a = (double)i / n, b = (double)j / n, c = 1.0 - a - b;
            vec3d p = v3_add(o->vertex[0], v3_add(v3_scale(e1, a), v3_scale(e2, b)));
            put(&m->vertices[m->n_vertices++], p, normal, c * o->uv[0][0] + a * o->uv[1][0] + b * o->uv[2][0],
                c * o->uv[0][1] + a * o->uv[1][1] + b * o->uv[2][1]);
        }
    }
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n - j; i++) {
            uint16_t p = (uint16_t)(row_start[j] + i), q = (uint16_t)(p + 1), r = (uint16_t)(row_start[j + 1] + i);
            m->indices[m->n_indices++] = p, m->indices[m->n_indices++] = q, m->indices[m->n_indices++] = r;
            if (i + 1 < n - j) {
                uint16_t s = (uint16_t)(r + 1);
                m->indices[m->n_indices++] = q, m->indices[m->n_indices++] = s, m->indices[m->n_indices++] = r;
            }
        }
}

int polygon_mesh_build(const struct object *rest, int n, struct polygon_mesh *m)
{
    n = n < 1 ? 1 : n > SCENE_MAX_SUBDIVISION ? SCENE_MAX_SUBDIVISION : n;
    int columns = rest->type == PRIM_SPHERE || rest->type == PRIM_DISK ? 2 * n : n;
    if (alloc(m, (columns + 1) * (n + 1), 6 * columns * n) != 0) {
        polygon_mesh_free(m);
        return -1;
    }
    switch (rest->type) {
    case PRIM_SPHERE: sphere(rest, n, m); break;
    case PRIM_RECT: rect(rest, n, m); break;
    case PRIM_DISK: disk(rest, n, m); break;
    case PRIM_TRIANGLE: triangle(rest, n, m); break;
    default: break;
    }
    return 0;
}

void polygon_mesh_free(struct polygon_mesh *m)
{
    free(m->vertices);
    free(m->indices);
    m->vertices = NULL;
    m->indices = NULL;
    m->n_vertices = m->n_indices = 0;
}
