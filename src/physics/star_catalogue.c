#include "physics/star_catalogue.h"
#include <stdlib.h>
#include <string.h>

/* splitmix64: the same sequence on every machine */
static uint64_t next_u64(uint64_t *state)
{
    uint64_t z = (*state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/* uniform in (0, 1]: 53 random bits */
static double uniform(uint64_t *state) { return ((next_u64(state) >> 11) + 1.0) * 0x1.0p-53; }

/* Spectral classes of naked-eye stars: share of the stars, and the range of temperatures. */
static const struct {
    double share, t_lo, t_hi;
} classes[] = {
    {0.005, 30000.0, 45000.0},  /* O */
    {0.150, 10000.0, 30000.0},  /* B */
    {0.200, 7500.0, 10000.0},   /* A */
    {0.150, 6000.0, 7500.0},    /* F */
    {0.150, 5200.0, 6000.0},    /* G */
    {0.250, 3700.0, 5200.0},    /* K */
    {0.095, 2400.0, 3700.0},    /* M */
};

static double draw_temperature(uint64_t *state)
{
    double u = uniform(state), v = uniform(state);
    int n = (int)(sizeof classes / sizeof classes[0]), k = 0;
    for (double sum = classes[0].share; k < n - 1 && u > sum; sum += classes[++k].share)
        ;
    return classes[k].t_lo * pow(classes[k].t_hi / classes[k].t_lo, v);
}

static vec3d from_galactic(const struct star_catalogue *c, double latitude, double longitude)
{
    vec3d in_plane = v3_add(v3_scale(c->x_axis, cos(longitude)), v3_scale(c->y_axis, sin(longitude)));
    return v3_normalize(v3_add(v3_scale(in_plane, cos(latitude)), v3_scale(c->pole, sin(latitude))));
}

static vec3d draw_direction(const struct star_catalogue *c, uint64_t *state)
{
    double kind = uniform(state), a = uniform(state), b = uniform(state);
    if (kind <= 0.5) {
        /* uniform over the sphere: sin(latitude) uniform in [-1, 1] */
        return from_galactic(c, asin(2.0 * a - 1.0), 2.0 * PI_D * b);
    }
    /* the disk: |latitude| exponential, folded back within the pole */
    double latitude = fmin(-STAR_DISK_LATITUDE_RAD * log(a), 0.5 * PI_D);
    double sign = uniform(state) <= 0.5 ? -1.0 : 1.0;
    return from_galactic(c, sign * latitude, 2.0 * PI_D * b);
}

double star_faintest_magnitude(int n)
{
    return STAR_MAGNITUDE_LIMIT + 2.0 * log10((n > 0 ? n : 1) / STAR_COUNT_AT_LIMIT);
}

void star_catalogue_galactic(const struct star_catalogue *c, vec3d d, double *latitude, double *longitude)
{
    double z = v3_dot(d, c->pole);
    *latitude = asin(z < -1.0 ? -1.0 : z > 1.0 ? 1.0 : z);
    *longitude = atan2(v3_dot(d, c->y_axis), v3_dot(d, c->x_axis));
}

static int cell_of(const struct star_catalogue *c, vec3d d)
{
    double latitude, longitude;
    star_catalogue_galactic(c, d, &latitude, &longitude);
    int row = (int)floor((latitude + 0.5 * PI_D) / c->row_step);
    int column = (int)floor((longitude + PI_D) / c->column_step);
    row = row < 0 ? 0 : row >= c->rows ? c->rows - 1 : row;
    column = column < 0 ? 0 : column >= c->columns ? c->columns - 1 : column;
    return row * c->columns + column;
}

void star_catalogue_frame(struct star_catalogue *c, vec3d pole, vec3d centre)
{
    c->pole = v3_normalize(pole);
    vec3d in_plane = v3_sub(centre, v3_scale(c->pole, v3_dot(centre, c->pole)));
    c->x_axis = v3_len(in_plane) > 1e-9 * v3_len(centre) && v3_len(in_plane) > 0.0 ? v3_normalize(in_plane)
                                                                                   : v3_perpendicular(c->pole);
    c->y_axis = v3_cross(c->pole, c->x_axis);
}

int star_catalogue_index(struct star_catalogue *c, struct star *stars, int n, vec3d pole, vec3d centre)
{
    memset(c, 0, sizeof *c);
    n = n < 0 ? 0 : n;
    star_catalogue_frame(c, pole, centre);
    /* about one star a cell: a pixel's reach is far smaller than a cell, so that most lookups visit
     * one cell, and the fewer stars it holds the fewer are tested */
    int rows = (int)lrint(sqrt(n / 2.0));
    c->rows = rows < 1 ? 1 : rows > 2048 ? 2048 : rows;
    c->columns = 2 * c->rows;
    c->row_step = PI_D / c->rows;
    c->column_step = 2.0 * PI_D / c->columns;
    size_t cells = (size_t)c->rows * c->columns;
    int *cell = malloc((n > 0 ? n : 1) * sizeof *cell);
    c->stars = malloc((n > 0 ? n : 1) * sizeof *c->stars);
    c->cell_start = calloc(cells + 1, sizeof *c->cell_start);
    int32_t *fill = malloc(cells * sizeof *fill);
    if (!cell || !c->stars || !c->cell_start || !fill) {
        free(cell);
        free(fill);
        free(stars);
        star_catalogue_free(c);
        return -1;
    }
    for (int i = 0; i < n; i++) {
        cell[i] = cell_of(c, stars[i].direction);
        c->cell_start[cell[i] + 1]++;
    }
    /* counting sort by cell, stable: the order within a cell is the order given */
    for (size_t k = 0; k < cells; k++)
        c->cell_start[k + 1] += c->cell_start[k];
    memcpy(fill, c->cell_start, cells * sizeof *fill);
    for (int i = 0; i < n; i++)
        c->stars[fill[cell[i]]++] = stars[i];
    free(fill);
    free(cell);
    free(stars);
    c->n = n;
    return 0;
}

int star_catalogue_make(struct star_catalogue *c, int n, uint64_t seed, vec3d pole, vec3d centre)
{
    memset(c, 0, sizeof *c);
    n = n < 0 ? 0 : n > STAR_CATALOGUE_MAX ? STAR_CATALOGUE_MAX : n;
    star_catalogue_frame(c, pole, centre);   /* the directions are drawn in it */
    struct star *drawn = malloc((n > 0 ? n : 1) * sizeof *drawn);
    if (!drawn)
        return -1;
    uint64_t state = seed;
    double faintest = star_faintest_magnitude(n);
    for (int i = 0; i < n; i++) {
        drawn[i].direction = draw_direction(c, &state);
        drawn[i].magnitude = faintest + 2.0 * log10(uniform(&state));
        drawn[i].temperature = draw_temperature(&state);
    }
    return star_catalogue_index(c, drawn, n, pole, centre);
}

void star_catalogue_free(struct star_catalogue *c)
{
    free(c->stars);
    free(c->cell_start);
    c->stars = NULL;
    c->cell_start = NULL;
    c->n = 0;
}

void star_catalogue_near(const struct star_catalogue *c, vec3d d, double radius, star_visit visit, void *arg)
{
    if (c->n == 0)
        return;
    double latitude, longitude;
    star_catalogue_galactic(c, d, &latitude, &longitude);
    radius += 1e-9;   /* rounding of the angles above */
    int row0 = (int)floor((latitude - radius + 0.5 * PI_D) / c->row_step);
    int row1 = (int)floor((latitude + radius + 0.5 * PI_D) / c->row_step);
    row0 = row0 < 0 ? 0 : row0;
    row1 = row1 >= c->rows ? c->rows - 1 : row1;
    /* the longitudes of a cap of that radius about d, when it holds neither pole */
    int all = fabs(latitude) + radius >= 0.5 * PI_D || radius >= 0.5 * PI_D;
    double half_width = all ? PI_D : asin(fmin(sin(radius) / cos(latitude), 1.0));
    int col0 = (int)floor((longitude - half_width + PI_D) / c->column_step);
    int col1 = (int)floor((longitude + half_width + PI_D) / c->column_step);
    if (all || col1 - col0 + 1 >= c->columns) {
        col0 = 0;
        col1 = c->columns - 1;
    }
    for (int row = row0; row <= row1; row++)
        for (int col = col0; col <= col1; col++) {
            int wrapped = ((col % c->columns) + c->columns) % c->columns;
            int cell = row * c->columns + wrapped;
            for (int32_t k = c->cell_start[cell]; k < c->cell_start[cell + 1]; k++)
                visit(&c->stars[k], arg);
        }
}
