#include "physics/bright_stars.h"
#include "io/text_file.h"
#include <errno.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The IAU's galactic frame in J2000 equatorial coordinates (degrees): its north pole and its centre
 * (l = 0, b = 0). */
#define NGP_RA_DEG 192.85948
#define NGP_DEC_DEG 27.12825
#define CENTRE_RA_DEG 266.40499
#define CENTRE_DEC_DEG -28.93617

/* Marble's colour classes: the B-V each stands for (its converter's reference stars) */
static const double class_bv[] = {-0.23, 0.00, 0.09, 0.80, 1.23, 1.85, 2.35};
#define CLASSES ((int)(sizeof class_bv / sizeof class_bv[0]))
/* the highest HR number a colour file may list (the catalogue's is 9110) */
#define HR_MAX 100000

double star_temperature_of_bv(double bv)
{
    return 4600.0 * (1.0 / (0.92 * bv + 1.7) + 1.0 / (0.92 * bv + 0.62));
}

static vec3d equatorial(double ra_rad, double dec_rad)
{
    return v3(cos(dec_rad) * cos(ra_rad), cos(dec_rad) * sin(ra_rad), sin(dec_rad));
}

/* J2000 equatorial unit vector -> the scene's direction, through galactic coordinates */
struct sky_frame {
    vec3d pole, centre, ninety;   /* galactic z, x, y in equatorial coordinates */
    struct star_catalogue scene;  /* the scene's galactic frame (only its axes) */
};

static void sky_frame_make(struct sky_frame *f, vec3d pole, vec3d centre)
{
    const double deg = PI_D / 180.0;
    f->pole = equatorial(NGP_RA_DEG * deg, NGP_DEC_DEG * deg);
    vec3d c = equatorial(CENTRE_RA_DEG * deg, CENTRE_DEC_DEG * deg);
    f->centre = v3_normalize(v3_sub(c, v3_scale(f->pole, v3_dot(c, f->pole))));
    f->ninety = v3_cross(f->pole, f->centre);
    memset(&f->scene, 0, sizeof f->scene);
    star_catalogue_frame(&f->scene, pole, centre);
}

static vec3d sky_direction(const struct sky_frame *f, vec3d eq)
{
    double x = v3_dot(eq, f->centre), y = v3_dot(eq, f->ninety), z = v3_dot(eq, f->pole);
    return v3_normalize(v3_add(v3_add(v3_scale(f->scene.x_axis, x), v3_scale(f->scene.y_axis, y)),
                               v3_scale(f->scene.pole, z)));
}

__attribute__((format(printf, 4, 5)))
static int refuse(struct error *e, const char *path, int line, const char *fmt, ...)
{
    char where[sizeof e->where], message[sizeof e->message];
    snprintf(where, sizeof where, "%s:%d", path, line);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(message, sizeof message, fmt, ap);
    va_end(ap);
    return error_set(e, ERROR_INPUT, where, "%s", message);
}

/* A decimal number at *p (digits, sign, point, exponent: no hexadecimal, inf or nan), p moved past
 * it. 0, or -1 where there is none. */
static int decimal(const char **p, double *v)
{
    const char *s = *p + strspn(*p, " \t");
    size_t len = strspn(s, "0123456789+-.eE");
    if (len == 0 || len > 40 || !strpbrk(s, "0123456789") || strpbrk(s, "0123456789") >= s + len)
        return -1;
    char buf[48];
    memcpy(buf, s, len);
    buf[len] = '\0';
    char *end;
    errno = 0;
    *v = strtod(buf, &end);
    if (*end != '\0' || errno == ERANGE || !isfinite(*v))
        return -1;
    *p = s + len;
    return 0;
}

/* The colour classes by HR number (-1: none) from Marble's file; *classes NULL where path is. */
static int read_colours(const char *path, signed char **classes, struct error *e)
{
    *classes = NULL;
    if (!path)
        return 0;
    size_t size;
    unsigned char *bytes = (unsigned char *)text_file_read(path, BRIGHT_STARS_MAX_BYTES, "star colour file", &size, e);
    if (!bytes)
        return -1;
    uint32_t magic = size >= 8 ? (uint32_t)bytes[0] << 24 | bytes[1] << 16 | bytes[2] << 8 | bytes[3] : 0;
    int32_t version = size >= 8 ? (int32_t)((uint32_t)bytes[4] << 24 | bytes[5] << 16 | bytes[6] << 8 | bytes[7]) : 0;
    int record = version >= 2 ? 32 : 28;
    int rc = 0;
    if (magic != 0x73746172u)
        rc = error_set(e, ERROR_INPUT, path, "not a star file of Marble's (stars.dat): it does not begin with \"star\"");
    else if (version < 1 || version > 4)
        rc = error_set(e, ERROR_INPUT, path, "version %d of Marble's star file: versions 1 to 4 are read", (int)version);
    else if ((size - 8) % (size_t)record != 0)
        rc = error_set(e, ERROR_INPUT, path, "%zu bytes after the header: not whole records of %d bytes (version %d)",
                       size - 8, record, (int)version);
    else if (!(*classes = malloc(HR_MAX + 1)))
        rc = error_set(e, ERROR_RUNTIME, path, "out of memory for the star colours");
    if (rc == 0) {
        memset(*classes, -1, HR_MAX + 1);
        for (size_t at = 8; at < size && version >= 2; at += (size_t)record) {
            const unsigned char *r = bytes + at;
            int32_t hr = (int32_t)((uint32_t)r[0] << 24 | r[1] << 16 | r[2] << 8 | r[3]);
            int32_t colour = (int32_t)((uint32_t)r[28] << 24 | r[29] << 16 | r[30] << 8 | r[31]);
            long index = (long)((at - 8) / (size_t)record) + 1;
            if (hr < 1 || hr > HR_MAX) {
                rc = error_set(e, ERROR_INPUT, path, "record %ld (byte %zu): star number %d is not one of 1..%d",
                               index, at, (int)hr, HR_MAX);
                break;
            }
            if (colour < 0 || colour >= CLASSES) {
                rc = error_set(e, ERROR_INPUT, path, "record %ld (byte %zu): colour class %d is not one of 0..%d",
                               index, at, (int)colour, CLASSES - 1);
                break;
            }
            (*classes)[hr] = (signed char)colour;
        }
    }
    free(bytes);
    if (rc != 0) {
        free(*classes);
        *classes = NULL;
    }
    return rc;
}

/* One line of the catalogue into *star: 1, 0 for a comment, -1 with e */
static int parse_star(const char *text, const char *path, int line, const signed char *classes,
                      const struct sky_frame *f, struct star *star, struct error *e)
{
    const char *p = text + strspn(text, " \t");
    if (*p == '\0' || *p == '#')
        return 0;
    double dec, ra, mag;
    if (decimal(&p, &dec) != 0 || decimal(&p, &ra) != 0 || decimal(&p, &mag) != 0)
        return refuse(e, path, line, "expected a star's declination (degrees), right ascension (hours) and "
                      "visual magnitude: \"%.60s\"", text);
    if (dec < -90.0 || dec > 90.0)
        return refuse(e, path, line, "declination %g is outside -90..90 degrees", dec);
    if (ra < 0.0 || ra > 24.0)
        return refuse(e, path, line, "right ascension %g is outside 0..24 hours", ra);
    if (mag < -30.0 || mag > 30.0)
        return refuse(e, path, line, "visual magnitude %g is outside -30..30", mag);
    if (*p != '\0' && *p != ' ' && *p != '\t')
        return refuse(e, path, line, "\"%.20s\" after the magnitude: expected a space, a quoted name or the line's end", p);
    p += strspn(p, " \t");
    long hr = 0;
    if (*p == '"') {
        const char *close = strchr(p + 1, '"');
        if (!close)
            return refuse(e, path, line, "the star's name has no closing quote");
        p = close + 1;
        p += strspn(p, " \t");
        if (*p >= '0' && *p <= '9') {
            char *end;
            errno = 0;
            hr = strtol(p, &end, 10);
            if (errno == ERANGE || hr < 1 || hr > HR_MAX || (*end != '\0' && *end != ' ' && *end != '\t'))
                return refuse(e, path, line, "the star's number in the catalogue (HR) \"%.20s\" is not one of 1..%d",
                              p, HR_MAX);
        }
    }
    const double deg = PI_D / 180.0;
    star->direction = sky_direction(f, equatorial(ra * 15.0 * deg, dec * deg));
    star->magnitude = mag;
    int colour = classes && hr > 0 ? classes[hr] : -1;
    star->temperature = colour >= 0 ? star_temperature_of_bv(class_bv[colour]) : BRIGHT_STAR_WHITE_K;
    return 1;
}

int bright_stars_read(const char *path, const char *colours_path, vec3d pole, vec3d centre, struct star **stars,
                      int *n, struct error *e)
{
    if (stars)
        *stars = NULL;
    *n = 0;
    signed char *classes;
    if (read_colours(colours_path, &classes, e) != 0)
        return -1;
    if (!path) {
        free(classes);
        return 0;
    }
    size_t size;
    char *text = text_file_read(path, BRIGHT_STARS_MAX_BYTES, "star catalogue", &size, e);
    if (!text) {
        free(classes);
        return -1;
    }
    struct sky_frame f;
    sky_frame_make(&f, pole, centre);
    struct text_lines lines = {.text = text, .len = size};
    struct star *list = NULL, one;
    int count = 0, capacity = 0, rc = 0, more;
    const char *start;
    size_t len;
    struct error why;
    while (rc == 0 && (more = text_lines_next(&lines, &start, &len, &why)) != 0) {
        char buf[BRIGHT_STARS_MAX_LINE + 1];
        if (more < 0) {
            rc = refuse(e, path, lines.line, "%s", why.message);
        } else if (len > BRIGHT_STARS_MAX_LINE) {
            rc = refuse(e, path, lines.line, "line longer than %d characters", BRIGHT_STARS_MAX_LINE);
        } else {
            memcpy(buf, start, len);
            buf[len] = '\0';
            int got = memchr(buf, '\r', len) ? refuse(e, path, lines.line, "a carriage return inside the line")
                                              : parse_star(buf, path, lines.line, classes, &f, &one, e);
            rc = got < 0 ? -1 : 0;
            if (got > 0 && count == STAR_CATALOGUE_MAX)
                rc = refuse(e, path, lines.line, "more than %d stars", STAR_CATALOGUE_MAX);
            if (rc == 0 && got > 0 && stars && count == capacity) {
                capacity = capacity ? 2 * capacity : 1024;
                struct star *grown = realloc(list, (size_t)capacity * sizeof *list);
                if (!grown)
                    rc = error_set(e, ERROR_RUNTIME, path, "out of memory for the star catalogue");
                else
                    list = grown;
            }
            if (rc == 0 && got > 0) {
                if (stars)
                    list[count] = one;
                count++;
            }
        }
    }
    free(text);
    free(classes);
    if (rc != 0) {
        free(list);
        return -1;
    }
    if (stars)
        *stars = list;
    *n = count;
    return 0;
}
