/* A generated star catalogue for the sky at infinity: point stars with directions, visual
 * magnitudes and black-body temperatures drawn from the distributions of the real naked-eye sky,
 * the same for the same seed on every machine, and indexed by direction for lookup per ray.
 *
 * - Counts: the real sky holds about STAR_COUNT_AT_LIMIT stars brighter than magnitude
 *   STAR_MAGNITUDE_LIMIT, and their number grows by about 10^0.5 per magnitude
 *   (N(<m) = 5000 * 10^(0.5 (m - 6))). A catalogue of n stars is the n brightest of such a sky:
 *   its faintest star has magnitude 6 + 2 log10(n / 5000), and each star's magnitude is
 *   m_faint + 2 log10(u), u uniform in (0, 1].
 * - Directions: half of the stars uniform over the sphere, half concentrated toward the galactic
 *   plane (latitude exponentially distributed, scale STAR_DISK_LATITUDE_RAD), as the faint stars
 *   of the Milky Way are.
 * - Temperatures: the spectral classes of naked-eye stars in their observed proportions (O 0.5%,
 *   B 15%, A 20%, F 15%, G 15%, K 25%, M 9.5%), log-uniform within each class's range.
 * - Lookup: cells of equal latitude and longitude steps around the galactic pole; each cell lists
 *   its stars (compressed rows), so that the stars within an angle of a direction are found by
 *   visiting the few cells that angle touches. */
#ifndef BT_STAR_CATALOGUE_H
#define BT_STAR_CATALOGUE_H
#include "physics/vec3.h"
#include <stdint.h>

#define STAR_MAGNITUDE_LIMIT 6.0
#define STAR_COUNT_AT_LIMIT 5000.0
#define STAR_DISK_LATITUDE_RAD 0.2
#define STAR_CATALOGUE_MAX 1000000

struct star {
    vec3d direction;       /* unit vector toward the star */
    double magnitude;      /* visual magnitude */
    double temperature;    /* K, black body */
};

struct star_catalogue {
    int n;
    struct star *stars;    /* sorted by cell */
    vec3d pole, x_axis, y_axis; /* the galactic frame: pole, and longitude 0 along x_axis */
    int rows, columns;     /* cells in latitude and longitude */
    double row_step, column_step;  /* their angular steps, radians */
    int32_t *cell_start;   /* rows * columns + 1: stars of cell c are [cell_start[c], cell_start[c + 1]) */
};

/* Generate n stars (0..STAR_CATALOGUE_MAX) from seed in the galactic frame of pole and centre
 * (star_catalogue_frame). 0, or -1 when out of memory (the catalogue is then empty). */
int star_catalogue_make(struct star_catalogue *c, int n, uint64_t seed, vec3d pole, vec3d centre);
/* A catalogue of the n stars given (taken over: freed here, also on failure), indexed by cell in the
 * galactic frame of pole and centre. 0, or -1 when out of memory (the catalogue is then empty). */
int star_catalogue_index(struct star_catalogue *c, struct star *stars, int n, vec3d pole, vec3d centre);
/* The galactic frame alone: pole (need not be unit; not zero), and longitude 0 toward centre's part
 * in the galactic plane (a direction of the plane's own choosing when centre lies along the pole). */
void star_catalogue_frame(struct star_catalogue *c, vec3d pole, vec3d centre);
void star_catalogue_free(struct star_catalogue *c);

/* Calls visit(star, arg) for every star whose direction lies within `radius` radians of the unit
 * vector d, and possibly a few more close by (the caller tests the distance it needs). */
typedef void (*star_visit)(const struct star *star, void *arg);
void star_catalogue_near(const struct star_catalogue *c, vec3d d, double radius, star_visit visit, void *arg);

/* Galactic latitude and longitude of unit vector d, radians. */
void star_catalogue_galactic(const struct star_catalogue *c, vec3d d, double *latitude, double *longitude);

/* The magnitude of the faintest star of a catalogue of n stars. */
double star_faintest_magnitude(int n);

#endif
