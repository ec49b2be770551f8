/* Aberration and Doppler factor of a moving observer; gravitational shift between static observers.
 * The one formula behind both (docs/RELATIVITY.md): nu_observer / nu_emitter = (k·u_observer) /
 * (k·u_emitter) for the photon's four-momentum k and the four-velocities u; these are its closed
 * forms for the frames the renderer uses. */
#include "physics/relativity.h"

double lorentz_gamma(vec3d beta)
{
    return 1.0 / sqrt(1.0 - v3_dot(beta, beta));
}

/* The Lorentz boost of a photon direction: d' seen from a frame moving with +beta maps to d. */
static vec3d boost_direction(vec3d beta, vec3d d)
{
    double gamma = lorentz_gamma(beta);
    double bd = v3_dot(beta, d);
    vec3d n = v3_axpy(gamma * gamma / (gamma + 1.0) * bd, beta, v3_axpy(-gamma, beta, d));
    return v3_scale(n, 1.0 / (gamma * (1.0 - bd)));
}

vec3d aberrate_to_scene(vec3d beta, vec3d d_observer)
{
    return boost_direction(beta, d_observer);
}

vec3d aberrate_to_observer(vec3d beta, vec3d d_scene)
{
    return boost_direction(v3_scale(beta, -1.0), d_scene);
}

double doppler_observer(vec3d beta, vec3d d_observer)
{
    return 1.0 / (lorentz_gamma(beta) * (1.0 - v3_dot(beta, d_observer)));
}

vec3d rest_position(const struct object_motion *m, double t, vec3d x)
{
    vec3d r = v3_sub(x, m->origin);
    double g = m->gamma;
    return v3_axpy(g * g / (g + 1.0) * v3_dot(m->beta, r) - g * t, m->beta, r);
}

double proper_time(const struct object_motion *m, double t, vec3d x)
{
    return m->gamma * (t - v3_dot(m->beta, v3_sub(x, m->origin)));
}

int clock_face_mark(double u, double v, double turns)
{
    double qx = u - 0.5, qy = v - 0.5;
    double angle = 2.0 * PI_D * (turns - floor(turns));
    double hx = sin(angle), hy = cos(angle);
    double along = qx * hx + qy * hy, across = fabs(qx * hy - qy * hx);
    int on_hand = along >= 0.0 && along <= CLOCK_HAND_LENGTH && across <= CLOCK_HAND_HALF_WIDTH;
    int on_ring = fabs(sqrt(qx * qx + qy * qy) - CLOCK_RING_RADIUS) <= CLOCK_RING_HALF_WIDTH;
    return on_hand || on_ring;
}

vec3d propagation_in_frame(vec3d beta, vec3d k)
{
    return v3_normalize(boost_direction(beta, k));
}

double reflection_doppler(vec3d beta, vec3d v_in, vec3d v_out)
{
    return (1.0 - v3_dot(beta, v_in)) / (1.0 - v3_dot(beta, v_out));
}

double emission_doppler(vec3d beta, vec3d v_out)
{
    return 1.0 / (lorentz_gamma(beta) * (1.0 - v3_dot(beta, v_out)));
}

/* the lapse sqrt(1 - 2M/r) of a static observer; 1 at infinity and without mass (also at r = 0) */
static double lapse(double mass, double r)
{
    return isinf(r) || mass == 0.0 ? 1.0 : sqrt(1.0 - 2.0 * mass / r);
}

double gravitational_shift(double mass, double r_from, double r_to)
{
    return lapse(mass, r_from) / lapse(mass, r_to);
}
