/* A thin accretion disk about a non-rotating mass (`accretion = on` on a disk object): matter on
 * circular Keplerian orbits in the disk's plane, glowing as a black body whose temperature falls
 * outwards as a thin disk's does. The GLSL ES versions are in shaders_es/observer.glsl. */
#ifndef BT_ACCRETION_H
#define BT_ACCRETION_H
#include "physics/vec3.h"

/* The temperature of a thin disk (Shakura and Sunyaev 1973) with inner edge r_in at radius r:
 * T(r) proportional to r^(-3/4) (1 - sqrt(r_in / r))^(1/4), scaled so that its peak, at
 * r = 49/36 r_in, is peak_k. 0 inside r_in (and for r_in <= 0). */
double thin_disk_temperature(double peak_k, double r_in, double r);

/* Matter on a circular orbit at y (from a mass M, in the plane with unit normal `axis`, moving
 * counterclockwise about it: angular velocity Omega = sqrt(M / r^3), u^t = 1 / sqrt(1 - 3M/r)),
 * sending light that reaches the camera along the traced ray's direction d (from the camera: the
 * photon travels along -d; d is the orbit's direction in the coordinates the rays are traced in,
 * r and phi taken as plane polar coordinates). The ratio of the frequency a static observer far
 * away receives to the emitted one: 1 / (u^t (1 - Omega lambda_z)), where lambda_z = L_z / E is
 * the photon's angular momentum about the axis over its energy, b = L / E from Binet's first
 * integral at y. A static observer at r_o receives it divided by sqrt(1 - 2M/r_o). M = 0: matter
 * at rest, 1. 0 where no circular orbit exists (r <= 3M). */
double keplerian_emitter_shift(double mass, vec3d y, vec3d d, vec3d axis);

#endif
