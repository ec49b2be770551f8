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

/* Frequency ratio nu_to / nu_from of light travelling from a static emitter at Schwarzschild radius
 * r_from to a static receiver at r_to: sqrt((1 - 2M/r_from) / (1 - 2M/r_to)). Either radius may be
 * INFINITY (1 there). Both must lie outside the horizon. */
double gravitational_shift(double mass, double r_from, double r_to);

#endif
