/* A thin accretion disk about a non-rotating mass (`accretion = on` on a disk object): matter on
 * circular Keplerian orbits in the disk's plane, glowing as a black body whose temperature falls
 * outwards as a thin disk's does. The GLSL ES versions are in shaders_es/observer.glsl. */
#ifndef BT_ACCRETION_H
#define BT_ACCRETION_H
#include "physics/vec3.h"

/* The temperature of a thin disk (Shakura and Sunyaev 1973) with inner edge r_in at radius r (from
 * the disk's centre):
 * T(r) proportional to r^(-3/4) (1 - sqrt(r_in / r))^(1/4), scaled so that its peak, at
 * r = 49/36 r_in, is peak_k. 0 inside r_in (and for r_in <= 0). */
double thin_disk_temperature(double peak_k, double r_in, double r);

/* The photon's angular momentum about `axis` (unit) over its energy, L_z / E, from any point y of its
 * orbit (relative to a mass M) and the traced ray's direction d there (from the camera: the photon
 * travels along -d; d is the orbit's direction in the coordinates the rays are traced in, r and phi
 * taken as plane polar coordinates): L / E is the impact parameter b of Binet's first integral
 * (du/dphi)^2 + u^2 (1 - 2 M u) = 1 / b^2, along the normal of the orbit's plane. Conserved along
 * the orbit, so any of its points gives the same. */
double photon_lambda_z(double mass, vec3d y, vec3d d, vec3d axis);

/* Matter on the circular orbit at radius r about a mass M (angular velocity Omega = sqrt(M / r^3),
 * u^t = 1 / sqrt(1 - 3M/r)), moving counterclockwise about the axis that lambda_z = L_z / E of its
 * light is taken about: the ratio of the frequency a static observer far away receives to the
 * emitted one, 1 / (u^t (1 - Omega lambda_z)). A static observer at r_o receives it divided by
 * sqrt(1 - 2M/r_o). M = 0: matter at rest, 1. 0 where no circular orbit exists (r <= 3M). */
double keplerian_emitter_shift(double mass, double r, double lambda_z);

#endif
