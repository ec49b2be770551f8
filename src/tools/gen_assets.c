/* Build tool: writes the generated textures and sky cube maps. Usage: gen_assets DIR
 *
 *   DIR/textures/checker_{blue,yellow}.png  256x128 equirectangular checkerboards (16 x 8 squares)
 *   DIR/textures/checker_grey.png           256x256 checkerboard (8 x 8 squares)
 *   DIR/sky/stars_FACE.png                  256x256 star field cube map
 *   DIR/sky/grid_FACE.png                   128x128 latitude/longitude test pattern cube map
 *
 * The output is a pure function of this file: a fixed-seed generator and no clock, so that the
 * files are byte-identical on every run and regenerating them never shows up as a change.
 *
 * Cube-map convention: the OpenGL one (major-axis table of the GL specification). For a
 * direction d, the face is that of its largest component ma, and
 *     face  sc   tc        face  sc   tc        face  sc   tc
 *     +X    -z   -y        +Y    +x   +z        +Z    +x   -y
 *     -X    +z   -y        -Y    +x   -z        -Z    -x   -y
 *     s = (sc/|ma| + 1) / 2,   t = (tc/|ma| + 1) / 2
 * Row 0 of every PNG holds t = 0 and column 0 holds s = 0: the renderer uploads the rows
 * top-down as increasing t, so the files can be handed to glTexImage2D as they are.
 * FACE is px, nx, py, ny, pz, nz for +X, -X, +Y, -Y, +Z, -Z.
 *
 * Sky coordinates used by the grid: +Y is north (latitude +90), longitude 0 looks along -Z (the
 * default view direction of a GL camera) and longitude +90 along +X. */
#include "io/png_io.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define PI 3.14159265358979323846

enum { FACE_PX, FACE_NX, FACE_PY, FACE_NY, FACE_PZ, FACE_NZ, FACE_COUNT };
static const char *const face_name[FACE_COUNT] = {"px", "nx", "py", "ny", "pz", "nz"};

/* ---- deterministic random numbers (splitmix64) ---- */

static uint64_t rng_state = 0x62656e7472617931ULL;

static uint64_t rng_u64(void)
{
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

/* Uniform in [0, 1). */
static double rng_uniform(void)
{
    return (double)(rng_u64() >> 11) * (1.0 / 9007199254740992.0);
}

/* Uniform in (0, 1], for logarithms and negative powers. */
static double rng_uniform_pos(void)
{
    return 1.0 - rng_uniform();
}

static void random_direction(double d[3])
{
    double z = 2.0 * rng_uniform() - 1.0;
    double phi = 2.0 * PI * rng_uniform();
    double r = sqrt(fmax(0.0, 1.0 - z * z));
    d[0] = r * cos(phi);
    d[1] = r * sin(phi);
    d[2] = z;
}

/* ---- small vector helpers ---- */

static void normalize3(double v[3])
{
    double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    v[0] /= n;
    v[1] /= n;
    v[2] /= n;
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* ---- cube-map geometry (see the table at the top) ---- */

/* Unit direction through the point (sc, tc) in [-1, 1]^2 of FACE. */
static void face_direction(int face, double sc, double tc, double d[3])
{
    switch (face) {
    case FACE_PX: d[0] = 1;   d[1] = -tc; d[2] = -sc; break;
    case FACE_NX: d[0] = -1;  d[1] = -tc; d[2] = sc;  break;
    case FACE_PY: d[0] = sc;  d[1] = 1;   d[2] = tc;  break;
    case FACE_NY: d[0] = sc;  d[1] = -1;  d[2] = -tc; break;
    case FACE_PZ: d[0] = sc;  d[1] = -tc; d[2] = 1;   break;
    default:      d[0] = -sc; d[1] = -tc; d[2] = -1;  break;
    }
    normalize3(d);
}

/* Projects D onto the plane of FACE. Unlike a texture lookup it also answers for directions
 * whose major axis is another face (then |sc| or |tc| > 1), which is what lets a star near an
 * edge spill onto the neighbouring face. Returns 0 when D points away from FACE. */
static int face_project(int face, const double d[3], double *sc, double *tc)
{
    double ma, s, t;
    switch (face) {
    case FACE_PX: ma = d[0];  s = -d[2]; t = -d[1]; break;
    case FACE_NX: ma = -d[0]; s = d[2];  t = -d[1]; break;
    case FACE_PY: ma = d[1];  s = d[0];  t = d[2];  break;
    case FACE_NY: ma = -d[1]; s = d[0];  t = -d[2]; break;
    case FACE_PZ: ma = d[2];  s = d[0];  t = -d[1]; break;
    default:      ma = -d[2]; s = -d[0]; t = -d[1]; break;
    }
    if (ma <= 1e-6)
        return 0;
    *sc = s / ma;
    *tc = t / ma;
    return 1;
}

/* Direction through the centre of texel (i, j) of an N x N face; j is the PNG row, i.e. t. */
static void texel_direction(int face, int n, int i, int j, double d[3])
{
    face_direction(face, 2.0 * (i + 0.5) / n - 1.0, 2.0 * (j + 0.5) / n - 1.0, d);
}

/* ---- output ---- */

static int ensure_dir(const char *path)
{
    if (mkdir(path, 0777) == 0 || errno == EEXIST)
        return 0;
    fprintf(stderr, "gen_assets: cannot create directory %s: %s\n", path, strerror(errno));
    return -1;
}

static int save(const char *dir, const char *name, int w, int h, const unsigned char *px)
{
    char path[4096];
    struct error err;
    int n = snprintf(path, sizeof path, "%s/%s", dir, name);
    if (n < 0 || (size_t)n >= sizeof path) {
        fprintf(stderr, "gen_assets: path too long: %s/%s\n", dir, name);
        return -1;
    }
    if (png_write_rgba8(path, w, h, px, 1, PNG_COMPRESSION_SMALL, &err) != 0) {
        fprintf(stderr, "gen_assets: %s\n", err.message);
        return -1;
    }
    printf("%s\n", path);
    return 0;
}

static unsigned char to_byte(double v)
{
    if (!(v > 0.0))
        return 0;
    if (v >= 1.0)
        return 255;
    return (unsigned char)(v * 255.0 + 0.5);
}

static void put_rgb(unsigned char *p, double r, double g, double b)
{
    p[0] = to_byte(r);
    p[1] = to_byte(g);
    p[2] = to_byte(b);
    p[3] = 255;
}

/* ---- checkerboards ---- */

static int write_checker(const char *dir, const char *name, int w, int h, int nx, int ny,
                         const unsigned char a[3], const unsigned char b[3])
{
    unsigned char *px = malloc((size_t)w * h * 4);
    if (!px) {
        fprintf(stderr, "gen_assets: out of memory\n");
        return -1;
    }
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            const unsigned char *c = ((x * nx / w + y * ny / h) & 1) ? b : a;
            unsigned char *p = px + ((size_t)y * w + x) * 4;
            p[0] = c[0];
            p[1] = c[1];
            p[2] = c[2];
            p[3] = 255;
        }
    int rc = save(dir, name, w, h, px);
    free(px);
    return rc;
}

/* ---- star field ---- */

#define STAR_FACE 256
#define STARS_UNIFORM 5000
#define STARS_BAND 4000
#define STAR_FLUX_MIN 0.03
#define STAR_FLUX_MAX 8.0
/* Footprint of a star in radians: a little over half a texel at the centre of a face. */
#define STAR_SIGMA (0.6 * 2.0 / STAR_FACE)
/* Width of the Milky-Way-like band in radians (about 9 degrees). */
#define BAND_WIDTH 0.16

/* Linear-light radiance being built, one RGB float triple a texel. */
static float sky_accum[FACE_COUNT][STAR_FACE * STAR_FACE * 3];

/* Orthonormal frame of the band: pole[] is normal to its great circle, e1/e2 span it. */
static double band_pole[3], band_e1[3], band_e2[3];

/* Plane waves of a fixed random set give a smooth, seamless mottling over the sphere. */
#define MOTTLE_WAVES 16
static double mottle_dir[MOTTLE_WAVES][3], mottle_freq[MOTTLE_WAVES], mottle_phase[MOTTLE_WAVES];

static void init_band(void)
{
    band_pole[0] = 0.32;
    band_pole[1] = 0.88;
    band_pole[2] = -0.35;
    normalize3(band_pole);
    double helper[3] = {1, 0, 0};
    cross3(band_pole, helper, band_e1);
    normalize3(band_e1);
    cross3(band_pole, band_e1, band_e2);
    for (int k = 0; k < MOTTLE_WAVES; k++) {
        random_direction(mottle_dir[k]);
        mottle_freq[k] = 3.0 + 14.0 * rng_uniform();
        mottle_phase[k] = 2.0 * PI * rng_uniform();
    }
}

/* In [0, 1], roughly centred on 0.5. */
static double mottle(const double d[3])
{
    double s = 0;
    for (int k = 0; k < MOTTLE_WAVES; k++)
        s += sin(mottle_freq[k] * dot3(d, mottle_dir[k]) + mottle_phase[k]);
    return fmin(1.0, fmax(0.0, 0.5 + 0.5 * s / sqrt((double)MOTTLE_WAVES) * 1.2));
}

/* Power-law brightness, as star counts go: N(>f) proportional to f^-1.5, so most are faint. */
static double star_flux(double f_min)
{
    return fmin(STAR_FLUX_MAX, f_min * pow(rng_uniform_pos(), -1.0 / 1.5));
}

/* A slight colour-temperature tint, from orange-white through white to blue-white. */
static void star_tint(double rgb[3])
{
    static const double warm[3] = {1.0, 0.78, 0.58}, white[3] = {1.0, 0.97, 0.92},
                        cool[3] = {0.74, 0.84, 1.0};
    double u = rng_uniform();
    const double *a = u < 0.5 ? warm : white, *b = u < 0.5 ? white : cool;
    double f = u < 0.5 ? u * 2.0 : u * 2.0 - 1.0;
    for (int c = 0; c < 3; c++)
        rgb[c] = a[c] + (b[c] - a[c]) * f;
}

/* Adds a Gaussian of angular width STAR_SIGMA around S to every face that sees it. The
 * weight of a texel depends only on the angle between its direction and S, so a star
 * straddling an edge is cut into pieces that join without a seam. */
static void splat_star(const double s[3], double flux, const double rgb[3])
{
    const double two_sigma2 = 2.0 * STAR_SIGMA * STAR_SIGMA;
    /* Beyond this angle the star adds less than 1/4096, well under one 8-bit step. */
    double r_cut = STAR_SIGMA * sqrt(2.0 * log(fmax(2.0, flux * 4096.0)));
    /* Texels are smallest (in angle) at face corners: 1/3 of the centre's size radially. */
    int half = (int)ceil(r_cut / (2.0 / STAR_FACE / 3.0)) + 1;
    double margin = (half + 1) * 2.0 / STAR_FACE;

    for (int f = 0; f < FACE_COUNT; f++) {
        double sc, tc;
        if (!face_project(f, s, &sc, &tc))
            continue;
        if (sc < -1.0 - margin || sc > 1.0 + margin || tc < -1.0 - margin || tc > 1.0 + margin)
            continue;
        int ci = (int)floor((sc + 1.0) * 0.5 * STAR_FACE);
        int cj = (int)floor((tc + 1.0) * 0.5 * STAR_FACE);
        for (int j = cj - half; j <= cj + half; j++) {
            if (j < 0 || j >= STAR_FACE)
                continue;
            for (int i = ci - half; i <= ci + half; i++) {
                if (i < 0 || i >= STAR_FACE)
                    continue;
                double d[3];
                texel_direction(f, STAR_FACE, i, j, d);
                double dx = d[0] - s[0], dy = d[1] - s[1], dz = d[2] - s[2];
                double chord2 = dx * dx + dy * dy + dz * dz;
                if (chord2 > r_cut * r_cut)
                    continue;
                double w = flux * exp(-chord2 / two_sigma2);
                float *p = &sky_accum[f][((size_t)j * STAR_FACE + i) * 3];
                p[0] += (float)(w * rgb[0]);
                p[1] += (float)(w * rgb[1]);
                p[2] += (float)(w * rgb[2]);
            }
        }
    }
}

/* Diffuse light of the band, evaluated per texel direction so it is seamless too. */
static void add_band_glow(void)
{
    for (int f = 0; f < FACE_COUNT; f++)
        for (int j = 0; j < STAR_FACE; j++)
            for (int i = 0; i < STAR_FACE; i++) {
                double d[3];
                texel_direction(f, STAR_FACE, i, j, d);
                double b = dot3(d, band_pole); /* sine of the band latitude */
                double core = exp(-b * b / (2.0 * BAND_WIDTH * BAND_WIDTH));
                double m = mottle(d);
                /* A darker lane along the middle, as dust does in the real one. */
                double lane = 1.0 - 0.45 * exp(-(b - 0.02) * (b - 0.02) / (2.0 * 0.03 * 0.03)) * m;
                double g = 0.045 * core * (0.35 + 0.65 * m) * lane;
                float *p = &sky_accum[f][((size_t)j * STAR_FACE + i) * 3];
                p[0] += (float)(g * 0.95);
                p[1] += (float)(g * 0.93);
                p[2] += (float)(g * 1.00);
            }
}

static int write_stars(const char *dir)
{
    init_band();
    add_band_glow();

    /* All stars are placed once in direction space; faces only sample them. */
    for (int k = 0; k < STARS_UNIFORM; k++) {
        double s[3], rgb[3];
        random_direction(s);
        double flux = star_flux(STAR_FLUX_MIN);
        star_tint(rgb);
        splat_star(s, flux, rgb);
    }
    /* Extra faint stars crowding the band. */
    for (int k = 0; k < STARS_BAND; k++) {
        double lon = 2.0 * PI * rng_uniform();
        /* Box-Muller: a Gaussian spread in latitude about the band's great circle. */
        double lat = BAND_WIDTH * 0.8 * sqrt(-2.0 * log(rng_uniform_pos())) *
                     cos(2.0 * PI * rng_uniform());
        double s[3], rgb[3];
        for (int c = 0; c < 3; c++)
            s[c] = cos(lat) * (cos(lon) * band_e1[c] + sin(lon) * band_e2[c]) +
                   sin(lat) * band_pole[c];
        normalize3(s);
        double flux = star_flux(STAR_FLUX_MIN * 0.6) * 0.5;
        star_tint(rgb);
        splat_star(s, flux, rgb);
    }

    unsigned char *px = malloc((size_t)STAR_FACE * STAR_FACE * 4);
    if (!px) {
        fprintf(stderr, "gen_assets: out of memory\n");
        return -1;
    }
    int rc = 0;
    for (int f = 0; f < FACE_COUNT && rc == 0; f++) {
        for (int k = 0; k < STAR_FACE * STAR_FACE; k++) {
            double v[3];
            for (int c = 0; c < 3; c++) {
                /* Soft shoulder so bright stars saturate gracefully, then display gamma. */
                double x = 1.0 - exp(-(double)sky_accum[f][k * 3 + c]);
                v[c] = pow(x, 1.0 / 2.2);
            }
            put_rgb(px + (size_t)k * 4, v[0], v[1], v[2]);
        }
        char name[64];
        snprintf(name, sizeof name, "sky/stars_%s.png", face_name[f]);
        rc = save(dir, name, STAR_FACE, STAR_FACE, px);
    }
    free(px);
    return rc;
}

/* ---- latitude/longitude test pattern ---- */

#define GRID_FACE 128
#define GRID_STEP 15.0

static void lat_lon(const double d[3], double *lat, double *lon)
{
    *lat = asin(fmax(-1.0, fmin(1.0, d[1]))) * (180.0 / PI);
    *lon = atan2(d[0], -d[2]) * (180.0 / PI);
}

static double wrap180(double a)
{
    while (a > 180.0)
        a -= 360.0;
    while (a < -180.0)
        a += 360.0;
    return a;
}

/* Fraction of a texel covered by a line HALF texels wide at DIST texels from its centre. */
static double coverage(double dist, double half)
{
    return fmax(0.0, fmin(1.0, half + 0.5 - dist));
}

static int write_grid(const char *dir)
{
    /* Muted, one per face, so that which face is where can be read off a render. */
    static const double base[FACE_COUNT][3] = {
        {0.55, 0.30, 0.30}, /* +X red */
        {0.24, 0.45, 0.45}, /* -X teal */
        {0.34, 0.50, 0.30}, /* +Y green */
        {0.45, 0.34, 0.55}, /* -Y purple */
        {0.30, 0.35, 0.56}, /* +Z blue */
        {0.55, 0.47, 0.27}, /* -Z ochre */
    };
    static const double minor[3] = {0.86, 0.86, 0.86}, major[3] = {1.0, 0.97, 0.55};
    const double step = 2.0 / GRID_FACE;

    unsigned char *px = malloc((size_t)GRID_FACE * GRID_FACE * 4);
    if (!px) {
        fprintf(stderr, "gen_assets: out of memory\n");
        return -1;
    }
    int rc = 0;
    for (int f = 0; f < FACE_COUNT && rc == 0; f++) {
        for (int j = 0; j < GRID_FACE; j++)
            for (int i = 0; i < GRID_FACE; i++) {
                double sc = 2.0 * (i + 0.5) / GRID_FACE - 1.0;
                double tc = 2.0 * (j + 0.5) / GRID_FACE - 1.0;
                double d[3], ds[3], dt[3];
                face_direction(f, sc, tc, d);
                face_direction(f, sc + step, tc, ds);
                face_direction(f, sc, tc + step, dt);
                double lat, lon, lat_s, lon_s, lat_t, lon_t;
                lat_lon(d, &lat, &lon);
                lat_lon(ds, &lat_s, &lon_s);
                lat_lon(dt, &lat_t, &lon_t);
                /* Degrees per texel: distances to a line are then measured in texels, which
                 * keeps the lines equally thin everywhere on every face. */
                double g_lat = hypot(lat_s - lat, lat_t - lat) + 1e-9;
                double g_lon = hypot(wrap180(lon_s - lon), wrap180(lon_t - lon)) + 1e-9;

                double k_lat = round(lat / GRID_STEP), k_lon = round(lon / GRID_STEP);
                double d_lat = fabs(lat - k_lat * GRID_STEP) / g_lat;
                double d_lon = fabs(wrap180(lon - k_lon * GRID_STEP)) / g_lon;
                int is_equator = k_lat == 0.0, is_prime = k_lon == 0.0;
                /* Only the quarter meridians run into the poles, where 24 lines would merge. */
                int meridian_here = fabs(lat) <= 90.0 - GRID_STEP || fmod(fabs(k_lon), 6.0) == 0.0;

                double c_minor = 0.0, c_major = 0.0;
                if (fabs(k_lat) * GRID_STEP < 90.0) {
                    double c = coverage(d_lat, is_equator ? 1.0 : 0.6);
                    if (is_equator)
                        c_major = fmax(c_major, c);
                    else
                        c_minor = fmax(c_minor, c);
                }
                if (meridian_here) {
                    double c = coverage(d_lon, is_prime ? 1.0 : 0.6);
                    if (is_prime)
                        c_major = fmax(c_major, c);
                    else
                        c_minor = fmax(c_minor, c);
                }
                double v[3];
                for (int c = 0; c < 3; c++) {
                    v[c] = base[f][c] + (minor[c] - base[f][c]) * c_minor;
                    v[c] += (major[c] - v[c]) * c_major;
                }
                put_rgb(px + ((size_t)j * GRID_FACE + i) * 4, v[0], v[1], v[2]);
            }
        char name[64];
        snprintf(name, sizeof name, "sky/grid_%s.png", face_name[f]);
        rc = save(dir, name, GRID_FACE, GRID_FACE, px);
    }
    free(px);
    return rc;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: gen_assets DIR\n"
                        "writes DIR/textures/checker_*.png and DIR/sky/{stars,grid}_*.png\n");
        return 2;
    }
    const char *dir = argv[1];
    char sub[4096];
    if (ensure_dir(dir) != 0)
        return 1;
    snprintf(sub, sizeof sub, "%s/textures", dir);
    if (ensure_dir(sub) != 0)
        return 1;
    snprintf(sub, sizeof sub, "%s/sky", dir);
    if (ensure_dir(sub) != 0)
        return 1;

    static const unsigned char white[3] = {236, 240, 255}, blue[3] = {38, 84, 214},
                               yellow[3] = {255, 222, 70}, orange[3] = {232, 118, 28},
                               light[3] = {200, 200, 200}, dark[3] = {92, 92, 92};
    if (write_checker(dir, "textures/checker_blue.png", 256, 128, 16, 8, white, blue) != 0 ||
        write_checker(dir, "textures/checker_yellow.png", 256, 128, 16, 8, yellow, orange) != 0 ||
        write_checker(dir, "textures/checker_grey.png", 256, 256, 8, 8, light, dark) != 0 ||
        write_stars(dir) != 0 || write_grid(dir) != 0)
        return 1;
    return 0;
}
