/* Point stars and the Milky Way on the sky at infinity ([sky] stars, milky_way), added to an image
 * that either engine made, from its rays' exit directions.
 *
 * A star is a point: its light is spread over the pixels by a Gaussian of render-independent size
 * ([sky] star_size, pixels), centred where the star's direction falls between the pixels' exit
 * directions. The footprint of a pixel, the Jacobian J of exit direction per pixel step, comes from
 * the neighbouring rays of the same image (central differences, one-sided beside a pixel that did
 * not reach the sky). A star's offset from a pixel in pixels is J's least-squares inverse applied to
 * its angular offset, and its flux is multiplied by the lensing magnification
 * mu = |det J_flat| / |det J|, where J_flat is the same Jacobian of the camera's straight, aberrated
 * rays: a lensed star stays a sharp point and grows brighter, not larger, as a point source does.
 *
 * Colours are black bodies in linear light (CIE 1931 -> BT.709, per unit luminance), added to the
 * decoded sRGB values of the image. observer.effects: geometry keeps each star's rest colour and
 * flux; doppler shows it at T D; searchlight also scales its flux by D^2 (a point source: the
 * intensity's D^4 times the solid angle's D^-2), and the Milky Way's radiance by D^4. D is the
 * Doppler factor of the camera's view direction, the gravitational blueshift at the camera included,
 * as for the rest of the sky. */
#ifndef BT_STAR_LIGHT_H
#define BT_STAR_LIGHT_H
#include "io/error.h"
#include "physics/star_catalogue.h"
#include "scene/camera.h"

/* Light below this (linear) is not drawn: a 16th of an 8-bit sRGB step at black. */
#define STAR_LIGHT_EPSILON 2e-5
/* A star's light reaches no farther than this many pixels from its centre. */
#define STAR_RADIUS_MAX_PX 24.0
/* A pixel looks for stars no farther than this (radians) from its direction. A coarse image's
 * pixels ahead of a fast observer, whose sky the aberration gathers, or next to a black hole's
 * shadow reach farther; there the nearest 0.2 rad are taken (a bright star's glow cut where it
 * would reach past them), not no star at all: an 80x60 flight at 0.6 c showed a black disk ahead. */
#define STAR_FOOTPRINT_MAX_RAD 0.2
/* The magnification of a star next to a critical curve is capped here. */
#define STAR_MAGNIFICATION_MAX 1e4

/* Entries of the table of black-body colours over log T that stars are coloured from. */
#define STAR_CHROMA_SIZE 512

struct star_sky {
    const struct scene *scene;
    struct camera_frame camera;
    struct star_catalogue catalogue;
    double brightest_flux;             /* flux of the catalogue's brightest star at rest */
    double milky_way_temperature;      /* K */
    double chroma[STAR_CHROMA_SIZE][3];  /* star_chromaticity over log T, BLACKBODY_T_MIN_K..MAX_K */
};

/* One image's rays: exit directions (stride floats a pixel, xyz used, need not be unit length) and
 * whether each reached the sky, top row first, their rays started (dx, dy) pixels off the centres. */
struct star_view {
    int width, height;
    double dx, dy;
    const float *direction;
    int stride;
    const unsigned char *sky;
};

/* 0, or -1 with e (out of memory: the machine's). With no stars and no Milky Way in s it holds nothing. */
int star_sky_init(struct star_sky *k, const struct scene *s, struct error *e);
void star_sky_free(struct star_sky *k);
/* 1 when the scene has stars or a Milky Way to draw. */
int star_sky_wanted(const struct scene *s);

/* Linear RGB of the stars and the Milky Way at pixel (i, j) of v (0 where it shows none). */
void star_sky_light(const struct star_sky *k, const struct star_view *v, int i, int j, double rgb[3]);

/* Add that light to an image of v's size: RGBA8 codes (may be NULL), RGBA floats (sRGB-encoded,
 * unclamped; may be NULL) and RGBA doubles (may be NULL), sky pixels only. */
void star_sky_add(const struct star_sky *k, const struct star_view *v, unsigned char *rgba, float *color,
                  double *color_d);

/* The linear RGB of a black body at temperature T per unit luminance (Y = 1), negative parts cut. */
void star_chromaticity(double temperature_k, double rgb[3]);

#endif
