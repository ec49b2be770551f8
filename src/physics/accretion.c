/* Thin accretion disks: temperature profile and the frequency shift of orbiting matter. */
#include "physics/accretion.h"
#include <math.h>

double thin_disk_temperature(double peak_k, double r_in, double r)
{
    if (!(r_in > 0.0) || !(r > r_in))
        return 0.0;
    /* f(r) / f(r_peak) with f(r) = r^-3/4 (1 - sqrt(r_in / r))^1/4, f(r_peak) = r_peak^-3/4 (1/7)^1/4 */
    double r_peak = 49.0 / 36.0 * r_in;
    return peak_k * pow(r_peak / r, 0.75) * pow(7.0 * (1.0 - sqrt(r_in / r)), 0.25);
}

double photon_lambda_z(double mass, vec3d y, vec3d d, vec3d axis)
{
    double r = v3_len(y);
    vec3d dir = v3_normalize(d);
    if (!(r > 0.0))
        return 0.0;
    vec3d radial = v3_scale(y, 1.0 / r);
    double along = v3_dot(dir, radial);
    double across_length = v3_len(v3_sub(dir, v3_scale(radial, along)));
    if (!(across_length > 0.0))
        return 0.0;    /* a radial photon carries no angular momentum */
    double u = 1.0 / r;
    double w = -u * along / across_length;
    double b = 1.0 / sqrt(w * w + u * u * (1.0 - 2.0 * mass * u));
    /* y x (-d) has length r |d| sin(angle): its unit vector is the orbit plane's normal, the way
     * the photon turns about the mass */
    vec3d spin = v3_cross(radial, v3_scale(dir, -1.0));
    return b * v3_dot(spin, axis) / across_length;
}

double keplerian_emitter_shift(double mass, double r, double lambda_z)
{
    if (!(r > 3.0 * mass) || !(r > 0.0))
        return 0.0;
    double omega = sqrt(mass / (r * r * r));
    return sqrt(1.0 - 3.0 * mass / r) / (1.0 - omega * lambda_z);
}
