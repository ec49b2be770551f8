/* Special relativity of light seen by a moving observer (Müller, Grottel and Weiskopf 2010, section
 * 3.1) and the frequency shift between static observers in Schwarzschild space-time. Units c = 1,
 * G = 1; beta is the observer's velocity relative to the frame the scene is described in (the
 * scene's rest frame in flat space, the static observer at the camera in Schwarzschild). */
#ifndef BT_RELATIVITY_H
#define BT_RELATIVITY_H
#include "physics/vec3.h"

/* Speeds are refused at and above this (gamma about 22): a typo must not ask for a singular
 * Lorentz matrix, and fp32 shaders keep 1 - beta·d resolvable. */
#define BETA_MAX 0.999

double lorentz_gamma(vec3d beta);

/* A viewing ray: d_observer is where the moving observer looks (a unit vector from the eye, against
 * the photon's motion). Returns the same ray's direction in the scene frame, the Lorentz
 * transformation of the photon's four-momentum (Eq. 3-4):
 *   d = (d' - gamma beta + gamma^2/(gamma+1) (beta·d') beta) / (gamma (1 - beta·d')),
 * so that along beta cos(theta) = (cos(theta') - |beta|) / (1 - |beta| cos(theta')). */
vec3d aberrate_to_scene(vec3d beta, vec3d d_observer);

/* The inverse: where the observer sees a ray that travels along -d_scene in the scene frame. */
vec3d aberrate_to_observer(vec3d beta, vec3d d_scene);

/* Frequency ratio nu_observer / nu_scene of light seen in direction d_observer, the kinematic
 * Doppler factor 1 / (gamma (1 - beta·d')): above 1 (blue) looking forward. */
double doppler_observer(vec3d beta, vec3d d_observer);

/* An object moving with constant velocity beta: its rest frame S' has its origin at `origin` at
 * scene time t = t' = 0 (Müller, Grottel and Weiskopf 2010, Eq. 1 with a = (0, origin)). */
struct object_motion {
    vec3d beta;
    double gamma;
    vec3d origin;
};

/* The rest-frame position (relative to the origin) of the event (t, x) of the scene frame: the
 * spatial part of the Poincaré transformation x' = Lambda(-beta) (x - a). */
vec3d rest_position(const struct object_motion *m, double t, vec3d x);

/* The clock face, in units of texture coordinates (shaders_es/shade.glsl has the same numbers). */
#define CLOCK_RING_RADIUS 0.45
#define CLOCK_RING_HALF_WIDTH 0.02
#define CLOCK_HAND_LENGTH 0.38
#define CLOCK_HAND_HALF_WIDTH 0.025

/* The proper time of a body with this motion at the event (t, x) on its worldline, counted from the
 * event (0, origin): t' = gamma (t - beta·(x - origin)). */
double proper_time(const struct object_motion *m, double t, vec3d x);

/* Where the hand of a clock face in texture space points: 1 on the dial or the hand, else 0. The
 * dial is a ring of radius 0.45 about uv (0.5, 0.5); the hand, 0.38 long, turns clockwise from +v
 * once per unit of `turns`. shaders_es/shade.glsl draws the same. */
int clock_face_mark(double u, double v, double turns);

/* A photon travelling along unit vector k in the scene frame travels along the returned unit vector
 * in the frame that moves with beta (the aberration of Eq. 4, the other way round). */
vec3d propagation_in_frame(vec3d beta, vec3d k);

/* Frequency ratio nu_out / nu_in, both measured in the scene frame, of light reflected by a surface
 * moving with beta: arriving along v_in, leaving along v_out (propagation directions). The
 * reflection keeps the frequency in the surface's rest frame, so this is
 * (1 - beta·v_in) / (1 - beta·v_out): above 1 when the surface approaches the receiver (Eq. 17). */
double reflection_doppler(vec3d beta, vec3d v_in, vec3d v_out);

/* Frequency ratio nu_scene / nu_rest of light emitted along v_out by a source moving with beta:
 * 1 / (gamma (1 - beta·v_out)). */
double emission_doppler(vec3d beta, vec3d v_out);

/* Frequency ratio nu_to / nu_from of light travelling from a static emitter at Schwarzschild radius
 * r_from to a static receiver at r_to: sqrt((1 - 2M/r_from) / (1 - 2M/r_to)). Either radius may be
 * INFINITY (1 there). Both must lie outside the horizon. */
double gravitational_shift(double mass, double r_from, double r_to);

#endif
