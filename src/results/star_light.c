#include "results/star_light.h"
#include "io/parallel.h"
#include "io/sample_average.h"
#include "physics/blackbody.h"
#include "physics/bright_stars.h"
#include "scene/camera.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MILKY_WAY_TEMPERATURE_K 4300.0

void star_chromaticity(double temperature_k, double rgb[3])
{
    double xyz[3];
    blackbody_xyz(temperature_k, xyz);
    double y = xyz[1] > 0.0 ? xyz[1] : 1.0;
    for (int c = 0; c < 3; c++)
        xyz[c] /= y;
    xyz_to_linear_bt709(xyz, rgb);
    for (int c = 0; c < 3; c++)
        rgb[c] = rgb[c] > 0.0 ? rgb[c] : 0.0;
}

static double chroma_position(double temperature_k)
{
    double t = temperature_k < BLACKBODY_T_MIN_K ? BLACKBODY_T_MIN_K
               : temperature_k > BLACKBODY_T_MAX_K ? BLACKBODY_T_MAX_K : temperature_k;
    return (STAR_CHROMA_SIZE - 1) * log(t / BLACKBODY_T_MIN_K) / log(BLACKBODY_T_MAX_K / BLACKBODY_T_MIN_K);
}

/* the table, linear in log T between its entries */
static void chroma(const struct star_sky *k, double temperature_k, double rgb[3])
{
    double x = chroma_position(temperature_k);
    int i = (int)x;
    i = i >= STAR_CHROMA_SIZE - 1 ? STAR_CHROMA_SIZE - 2 : i;
    double f = x - i;
    for (int c = 0; c < 3; c++)
        rgb[c] = k->chroma[i][c] + f * (k->chroma[i + 1][c] - k->chroma[i][c]);
}

int star_sky_wanted(const struct scene *s)
{
    return s->sky.stars > 0 || s->sky.catalogue[0] || s->sky.milky_way > 0.0;
}

static double star_flux(const struct scene *s, double magnitude)
{
    return s->sky.star_brightness * pow(10.0, -0.4 * (magnitude - STAR_MAGNITUDE_LIMIT));
}

int star_sky_init(struct star_sky *k, const struct scene *s, struct error *e)
{
    memset(k, 0, sizeof *k);
    k->scene = s;
    k->milky_way_temperature = MILKY_WAY_TEMPERATURE_K;
    camera_frame_make(s, &k->camera);
    for (int i = 0; i < STAR_CHROMA_SIZE; i++) {
        double t = BLACKBODY_T_MIN_K * pow(BLACKBODY_T_MAX_K / BLACKBODY_T_MIN_K, (double)i / (STAR_CHROMA_SIZE - 1));
        star_chromaticity(t, k->chroma[i]);
    }
    if (s->sky.catalogue[0]) {
        /* the real sky's stars (the files were read once when the scene was loaded) */
        struct star *stars;
        int n;
        if (bright_stars_read(s->sky.catalogue, s->sky.catalogue_colours[0] ? s->sky.catalogue_colours : NULL,
                              s->sky.galactic_pole, s->sky.galactic_center, &stars, &n, e) != 0)
            return -1;
        if (star_catalogue_index(&k->catalogue, stars, n, s->sky.galactic_pole, s->sky.galactic_center) != 0)
            return error_set(e, ERROR_RUNTIME, NULL, "out of memory for the star catalogue %s", s->sky.catalogue);
    } else if (s->sky.stars > 0 &&
        star_catalogue_make(&k->catalogue, s->sky.stars, (uint64_t)s->sky.star_seed, s->sky.galactic_pole,
                            s->sky.galactic_center) != 0)
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory for a catalogue of %d stars ([sky] stars)",
                         s->sky.stars);
    double brightest = INFINITY;
    for (int i = 0; i < k->catalogue.n; i++)
        brightest = fmin(brightest, k->catalogue.stars[i].magnitude);
    k->brightest_flux = k->catalogue.n > 0 ? star_flux(s, brightest) : 0.0;
    if (k->catalogue.n == 0)
        star_catalogue_frame(&k->catalogue, s->sky.galactic_pole, s->sky.galactic_center);   /* the band's */
    return 0;
}

void star_sky_free(struct star_sky *k) { star_catalogue_free(&k->catalogue); }

/* Radiance of the galactic band along d, relative to its brightest: a disk brighter toward the
 * centre (longitude 0), a bulge about the centre, a dark dust lane along the plane, and a slow
 * ripple in longitude for its clouds. Smooth: it holds up at any resolution. */
static double milky_way_shape(const struct star_catalogue *c, vec3d d)
{
    /* beyond 0.95 rad of the plane both the disk and the bulge are below 1e-6 of their peak */
    if (fabs(v3_dot(d, c->pole)) > 0.8134)
        return 0.0;
    double b, l;
    star_catalogue_galactic(c, d, &b, &l);
    double towards_centre = 0.5 + 0.5 * cos(l);
    double disk = exp(-0.5 * (b / 0.10) * (b / 0.10)) * (0.35 + 0.65 * towards_centre * towards_centre);
    double bulge = 0.8 * exp(-0.5 * ((b / 0.18) * (b / 0.18) + (l / 0.35) * (l / 0.35)));
    double dust = 1.0 - 0.55 * exp(-0.5 * (b / 0.025) * (b / 0.025)) * towards_centre;
    double clouds = 1.0 + 0.2 * cos(5.0 * l + 0.7) + 0.15 * cos(11.0 * l + 2.1);
    return (disk + bulge) * dust * clouds / 1.8;
}

static vec3d direction_at(const struct star_view *v, int i, int j)
{
    const float *p = v->direction + (size_t)v->stride * ((size_t)j * v->width + i);
    return v3_normalize(v3(p[0], p[1], p[2]));
}

static int sky_at(const struct star_view *v, int i, int j)
{
    return i >= 0 && j >= 0 && i < v->width && j < v->height && v->sky[(size_t)j * v->width + i];
}

/* The Jacobian column along one image axis (di, dj): central where both neighbours reached the
 * sky, one-sided where one did, and the camera's straight rays' column with the same stencil.
 * 0 when neither neighbour reached the sky. */
static int jacobian_column(const struct star_view *v, const struct camera_frame *camera, int i, int j, int di,
                           int dj, vec3d *col, vec3d *flat)
{
    int ahead = sky_at(v, i + di, j + dj), behind = sky_at(v, i - di, j - dj);
    if (!ahead && !behind)
        return 0;
    int ia = ahead ? i + di : i, ja = ahead ? j + dj : j, ib = behind ? i - di : i, jb = behind ? j - dj : j;
    double span = ahead && behind ? 0.5 : 1.0;
    *col = v3_scale(v3_sub(direction_at(v, ia, ja), direction_at(v, ib, jb)), span);
    *flat = v3_scale(v3_sub(camera_frame_ray(camera, ia, ja, v->dx, v->dy), camera_frame_ray(camera, ib, jb, v->dx, v->dy)),
                     span);
    return 1;
}

struct pixel_stars {
    const struct star_sky *k;
    vec3d d, jx, jy;
    double inverse[3];        /* (J^T J)^-1: xx, xy, yy */
    double gain;              /* flux factor: magnification, and D^2 under the searchlight */
    double reach_cos;         /* cosine of the angle the brightest star's light reaches from d */
    double doppler;           /* temperature factor */
    double rgb[3];
};

static void add_star(const struct star *star, void *arg)
{
    struct pixel_stars *p = arg;
    const struct scene *s = p->k->scene;
    double along = v3_dot(star->direction, p->d);
    if (along < p->reach_cos || along <= 0.0)   /* most of the stars of the cells visited */
        return;
    vec3d t = v3_sub(v3_scale(star->direction, 1.0 / along), p->d);   /* on the tangent plane at d */
    double rx = v3_dot(p->jx, t), ry = v3_dot(p->jy, t);
    double px = p->inverse[0] * rx + p->inverse[1] * ry, py = p->inverse[1] * rx + p->inverse[2] * ry;
    double sigma = s->sky.star_size;
    double value = star_flux(s, star->magnitude) * p->gain * exp(-(px * px + py * py) / (2.0 * sigma * sigma)) /
                   (2.0 * PI_D * sigma * sigma);
    if (!(value >= STAR_LIGHT_EPSILON))
        return;
    double c[3];
    chroma(p->k, star->temperature * p->doppler, c);
    for (int k = 0; k < 3; k++)
        p->rgb[k] += value * c[k];
}

void star_sky_light(const struct star_sky *k, const struct star_view *v, int i, int j, double rgb[3])
{
    const struct scene *s = k->scene;
    rgb[0] = rgb[1] = rgb[2] = 0.0;
    if (!sky_at(v, i, j))
        return;
    vec3d d = direction_at(v, i, j);
    int doppler_on = s->observer.effects != EFFECTS_GEOMETRY;
    int searchlight = s->observer.effects == EFFECTS_SEARCHLIGHT;
    double doppler = doppler_on ? camera_doppler(s, camera_frame_view(&k->camera, i, j, v->dx, v->dy)) : 1.0;
    double band = s->sky.milky_way > 0.0 ? milky_way_shape(&k->catalogue, d) : 0.0;
    if (band > 0.0) {
        double c[3], radiance = s->sky.milky_way * band;
        radiance *= searchlight ? doppler * doppler * doppler * doppler : 1.0;
        chroma(k, k->milky_way_temperature * doppler, c);
        for (int n = 0; n < 3; n++)
            rgb[n] += radiance * c[n];
    }
    if (k->catalogue.n == 0)
        return;
    struct pixel_stars p = {.k = k, .d = d, .doppler = doppler};
    vec3d flat_x, flat_y;
    if (!jacobian_column(v, &k->camera, i, j, 1, 0, &p.jx, &flat_x) ||
        !jacobian_column(v, &k->camera, i, j, 0, 1, &p.jy, &flat_y))
        return;
    double xx = v3_dot(p.jx, p.jx), xy = v3_dot(p.jx, p.jy), yy = v3_dot(p.jy, p.jy);
    double det = xx * yy - xy * xy;
    if (!(det > 0.0))
        return;
    double magnification = fmin(v3_len(v3_cross(flat_x, flat_y)) / sqrt(det), STAR_MAGNIFICATION_MAX);
    p.gain = magnification * (searchlight ? doppler * doppler : 1.0);
    p.inverse[0] = yy / det;
    p.inverse[1] = -xy / det;
    p.inverse[2] = xx / det;
    /* how far the brightest star's light reaches here, in pixels, then in angle */
    double sigma = s->sky.star_size, peak = k->brightest_flux * p.gain / (2.0 * PI_D * sigma * sigma);
    if (!(peak >= STAR_LIGHT_EPSILON))
        return;
    double reach_px = fmin(sigma * sqrt(2.0 * log(peak / STAR_LIGHT_EPSILON)), STAR_RADIUS_MAX_PX);
    double trace = xx + yy, widest = sqrt(0.5 * (trace + sqrt(fmax(trace * trace - 4.0 * det, 0.0))));
    double reach = fmin(reach_px * widest, STAR_FOOTPRINT_MAX_RAD);
    if (!(reach > 0.0))
        return;
    p.reach_cos = cos(reach);
    star_catalogue_near(&k->catalogue, d, reach, add_star, &p);
    for (int n = 0; n < 3; n++)
        rgb[n] += p.rgb[n];
}

struct add_job {
    const struct star_sky *k;
    const struct star_view *v;
    unsigned char *rgba;
    float *color;
    double *color_d;
};

/* Rows part, part + parts, ... of the view. */
static void add_rows(void *arg, int part, int parts)
{
    const struct add_job *job = arg;
    const struct star_view *v = job->v;
    double decoded[256];
    for (int code = 0; code < 256; code++)
        decoded[code] = srgb_to_linear(code / 255.0);
    for (int j = part; j < v->height; j += parts)
        for (int i = 0; i < v->width; i++) {
            double light[3];
            star_sky_light(job->k, v, i, j, light);
            if (light[0] == 0.0 && light[1] == 0.0 && light[2] == 0.0)
                continue;
            size_t at = 4 * ((size_t)j * v->width + i);
            for (int c = 0; c < 3; c++) {
                if (job->rgba)
                    job->rgba[at + c] = unorm8(linear_to_srgb(decoded[job->rgba[at + c]] + light[c]));
                if (job->color)
                    job->color[at + c] = (float)linear_to_srgb_unclamped(srgb_to_linear(job->color[at + c]) + light[c]);
                if (job->color_d)
                    job->color_d[at + c] = linear_to_srgb_unclamped(srgb_to_linear(job->color_d[at + c]) + light[c]);
            }
        }
}

void star_sky_add(const struct star_sky *k, const struct star_view *v, unsigned char *rgba, float *color,
                  double *color_d)
{
    /* each pixel apart from the others: rows interleaved over the cores */
    struct add_job job = {k, v, rgba, color, color_d};
    parallel_run(parallel_parts(v->height, 64), add_rows, &job);
}
