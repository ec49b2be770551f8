#include "results/star_map.h"
#include "physics/blackbody.h"
#include "results/star_light.h"
#include <stdlib.h>
#include <string.h>

static double sign_not_zero(double x) { return x >= 0.0 ? 1.0 : -1.0; }

void octahedral_encode(vec3d d, double *u, double *v)
{
    double l1 = fabs(d.x) + fabs(d.y) + fabs(d.z);
    double x = d.x / l1, y = d.y / l1;
    if (d.z < 0.0) {
        double fx = (1.0 - fabs(y)) * sign_not_zero(x), fy = (1.0 - fabs(x)) * sign_not_zero(y);
        x = fx;
        y = fy;
    }
    *u = 0.5 * x + 0.5;
    *v = 0.5 * y + 0.5;
}

vec3d octahedral_decode(double u, double v)
{
    double x = 2.0 * u - 1.0, y = 2.0 * v - 1.0, z = 1.0 - fabs(x) - fabs(y);
    if (z < 0.0) {
        double fx = (1.0 - fabs(y)) * sign_not_zero(x), fy = (1.0 - fabs(x)) * sign_not_zero(y);
        x = fx;
        y = fy;
    }
    return v3_normalize(v3(x, y, z));
}

static int quantize(double x, int top)
{
    long q = lrint(x);
    return q < 0 ? 0 : q > top ? top : (int)q;
}

static void put_star(struct star_map *m, int level, const struct star *s, int *occupants)
{
    int n = m->cells >> level;
    double u, v;
    octahedral_encode(s->direction, &u, &v);
    int i = (int)(u * n), j = (int)(v * n);
    i = i < 0 ? 0 : i >= n ? n - 1 : i;
    j = j < 0 ? 0 : j >= n ? n - 1 : j;
    int *held = &occupants[(size_t)j * n + i];
    if (*held >= STAR_MAP_SLOTS) {
        if (level == 0)
            m->dropped++;
        return;   /* the stars come brightest first: the cell keeps its brightest */
    }
    int slot = (*held)++;
    if (level == 0)
        m->stars++;
    unsigned char *p = m->texels + 4 * ((size_t)(m->level_y[level] + j) * m->width + m->level_x[level] +
                                        2 * (STAR_MAP_SLOTS * i + slot));
    int qu = quantize((u * n - i) * 65536.0 - 0.5, 65535), qv = quantize((v * n - j) * 65536.0 - 0.5, 65535);
    double span = m->faintest - m->brightest;
    int qm = span > 0.0 ? quantize((m->faintest - s->magnitude) / span * 65535.0, 65535) : 65535;
    double t = s->temperature < BLACKBODY_T_MIN_K ? BLACKBODY_T_MIN_K
               : s->temperature > BLACKBODY_T_MAX_K ? BLACKBODY_T_MAX_K : s->temperature;
    int qt = quantize(log(t / BLACKBODY_T_MIN_K) / log(BLACKBODY_T_MAX_K / BLACKBODY_T_MIN_K) * (STAR_CHROMA_TEXELS - 1),
                      STAR_CHROMA_TEXELS - 1);
    const unsigned char place[8] = {(unsigned char)(qu >> 8), (unsigned char)(qu & 255), (unsigned char)(qv >> 8),
                                    (unsigned char)(qv & 255), (unsigned char)(qm >> 8), (unsigned char)(qm & 255),
                                    (unsigned char)qt, 255};
    memcpy(p, place, sizeof place);
}

/* The cell the GPU's pass reads as cell (i, j) of a level of n cells a side: across the square's
 * border the map folds back onto itself mirrored (sky_colour.glsl's fold, in the same order). */
static void fold_cell(int n, int *i, int *j)
{
    if (*i < 0 || *i > n - 1) {
        *j = n - 1 - *j;
        *i = *i < 0 ? 0 : n - 1;
    }
    if (*j < 0 || *j > n - 1) {
        *i = n - 1 - *i;
        *j = *j < 0 ? 0 : n - 1;
    }
}

/* Each cell's mask of the 3x3 cells about it that hold a star (star_map.h), from the level's
 * occupants. */
static void put_masks(struct star_map *m, int level, const int *occupants)
{
    int n = m->cells >> level;
    for (int cj = 0; cj < n; cj++)
        for (int ci = 0; ci < n; ci++) {
            int mask = 0;
            for (int k = 0; k < 9; k++) {
                int i = ci - 1 + k % 3, j = cj - 1 + k / 3;
                fold_cell(n, &i, &j);
                if (occupants[(size_t)j * n + i] > 0)
                    mask |= 1 << (8 - k);
            }
            unsigned char *p = m->texels + 4 * ((size_t)(m->mask_y + cj) * m->width + m->mask_x[level] + ci);
            p[0] = (unsigned char)(mask & 255);
            p[1] = (unsigned char)(mask >> 8);
            p[3] = 255;
        }
}

static int brighter_first(const void *a, const void *b)
{
    const struct star *const *x = a, *const *y = b;
    return (*x)->magnitude < (*y)->magnitude ? -1 : (*x)->magnitude > (*y)->magnitude ? 1 : (*x < *y ? -1 : *x > *y);
}

int star_map_build(struct star_map *m, const struct star_catalogue *c, int cells)
{
    memset(m, 0, sizeof *m);
    m->cells = cells;
    m->width = 2 * STAR_MAP_SLOTS * cells;
    int x = 0;
    for (int n = cells; n >= STAR_MAP_MIN_CELLS && m->levels < STAR_MAP_LEVELS_MAX; n >>= 1) {
        m->level_x[m->levels] = m->levels == 0 ? 0 : x;
        m->level_y[m->levels] = m->levels == 0 ? 0 : cells;
        m->mask_x[m->levels] = m->levels == 0 ? 0 : 2 * cells - 2 * n;
        x += m->levels == 0 ? 0 : 2 * STAR_MAP_SLOTS * n;
        m->levels++;
    }
    m->chroma_y = cells + cells / 2;
    m->mask_y = m->chroma_y + 1;
    m->height = m->mask_y + cells;
    m->faintest = -INFINITY;
    m->brightest = INFINITY;
    for (int i = 0; i < c->n; i++) {
        m->faintest = fmax(m->faintest, c->stars[i].magnitude);
        m->brightest = fmin(m->brightest, c->stars[i].magnitude);
    }
    if (c->n == 0)
        m->faintest = m->brightest = 0.0;
    m->texels = calloc((size_t)m->width * m->height, 4);   /* every slot empty */
    const struct star **order = malloc((c->n > 0 ? c->n : 1) * sizeof *order);
    int *occupants = malloc((size_t)cells * cells * sizeof *occupants);
    if (!m->texels || !order || !occupants) {
        free(order);
        free(occupants);
        star_map_free(m);
        return -1;
    }
    for (int i = 0; i < c->n; i++)
        order[i] = &c->stars[i];
    qsort(order, c->n, sizeof *order, brighter_first);
    for (int level = 0; level < m->levels; level++) {
        int n = cells >> level;
        memset(occupants, 0, (size_t)n * n * sizeof *occupants);
        for (int i = 0; i < c->n; i++)
            put_star(m, level, order[i], occupants);
        put_masks(m, level, occupants);
    }
    free(order);
    free(occupants);
    /* the colours per unit luminance over ln T, each over its largest component */
    for (int k = 0; k < STAR_CHROMA_TEXELS; k++) {
        double t = BLACKBODY_T_MIN_K * pow(BLACKBODY_T_MAX_K / BLACKBODY_T_MIN_K, (double)k / (STAR_CHROMA_TEXELS - 1));
        double rgb[3];
        star_chromaticity(t, rgb);
        double top = fmax(rgb[0], fmax(rgb[1], rgb[2]));
        unsigned char *p = m->texels + 4 * ((size_t)m->chroma_y * m->width + k);
        for (int n = 0; n < 3; n++)
            p[n] = (unsigned char)quantize(top > 0.0 ? rgb[n] / top * 255.0 : 0.0, 255);
        p[3] = 255;
    }
    return 0;
}

void star_map_free(struct star_map *m)
{
    free(m->texels);
    m->texels = NULL;
}
