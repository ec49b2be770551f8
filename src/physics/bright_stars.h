/* The real naked-eye sky ([sky] catalogue): the Yale Bright Star Catalogue (5th revised edition,
 * Hoffleit and Warren 1991) as Debian's xplanet package ships it, stars/BSC, 9102 stars with
 * their J2000 positions and visual magnitudes; and their colours, where a second file has them, from
 * the same catalogue's B-V colour index as Debian's Marble ships it (stars/stars.dat).
 *
 * - The catalogue, a text file: a line per star, "DEC RA MAG", then optionally a quoted name and the
 *   star's number in the catalogue (HR), and anything after it (xplanet's file goes on with the HD
 *   and SAO numbers). DEC in degrees (-90..90), RA in hours (0..24), MAG a visual magnitude
 *   (-30..30). Blank lines and lines from '#' are comments. A line that is none of these is
 *   refused, with FILE:LINE.
 * - The colours, a binary file (Qt's QDataStream, big-endian): "star", a version (1..4), then a
 *   record per star: HR number (int32), RA and Dec (radians) and magnitude (doubles), and from
 *   version 2 a colour class (int32, 0..6): the nearest of B-V = -0.23, 0.00, 0.09, 0.80, 1.23, 1.85
 *   and 2.35 (Spica, Rigel, Deneb, Capella, Arcturus, Betelgeuse, mu Cephei), which Marble's own
 *   converter takes the star's B-V to. A star of the catalogue takes the temperature of its class's
 *   B-V (star_temperature_of_bv); a star that the colours do not list (most stars fainter than
 *   magnitude 6), or every star where no colours are given, is white: BRIGHT_STAR_WHITE_K.
 * - Directions: equatorial J2000 to galactic (the IAU's north galactic pole and centre), then into
 *   the scene by its galactic frame ([sky] galactic_pole and galactic_center), the one the Milky Way
 *   is drawn in: the real stars stand where they are in the real band. */
#ifndef BT_BRIGHT_STARS_H
#define BT_BRIGHT_STARS_H
#include "io/error.h"
#include "physics/star_catalogue.h"

/* Where Debian installs them (packages xplanet and marble-qt-data) */
#define BRIGHT_STARS_XPLANET_PATH "/usr/share/xplanet/stars/BSC"
#define BRIGHT_STARS_MARBLE_PATH "/usr/share/marble/data/stars/stars.dat"

/* The temperature of a star of no known colour: the sRGB white point (D65), white on screen. */
#define BRIGHT_STAR_WHITE_K 6504.0
/* Files larger than these are refused (the Bright Star Catalogue is 9110 lines, Marble's colours
 * 160 KB). */
#define BRIGHT_STARS_MAX_BYTES (16L << 20)
#define BRIGHT_STARS_MAX_LINE 512

/* The effective temperature of a star of colour index B-V (Ballesteros 2012, EPL 97 34008: a black
 * body's B-V), K. */
double star_temperature_of_bv(double bv);

/* The stars of the catalogue at path, their temperatures from the colours at colours_path (NULL:
 * none), their directions in the galactic frame of pole and centre (star_catalogue_frame). 0 with
 * *stars (malloc'd, *n of them; NULL where stars is NULL: the files only checked; path NULL: the
 * colours alone checked, no star); -1 with e: the
 * user's error, at FILE:LINE for a line of the catalogue or FILE for the colours, or the machine's
 * (no memory, a read that failed). */
int bright_stars_read(const char *path, const char *colours_path, vec3d pole, vec3d centre, struct star **stars,
                      int *n, struct error *e);

#endif
