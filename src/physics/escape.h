/* Where light goes once it has left the scene. Around a non-rotating mass, light that leaves the
 * bounding sphere is still bent on its way out: the sky, which rests at infinity, is seen along the
 * asymptote of its orbit, not along its direction where it crossed the sphere (for M = 0.12 at 30
 * units the two differ by up to 2M/r = 8e-3 rad, several pixels). Both engines look the sky up in
 * this direction: the CPU reference with escape_direction, the GPU's integrated rays with the
 * same quadrature in float (shaders_es/model_schwarzschild.glsl), exact orbits with the orbit
 * table's angle swept to infinity (physics/orbit_table.h).
 *
 * In the orbit's plane, u = 1/r obeys Binet's first integral (du/dphi)^2 = 1/b^2 - u^2 + 2 M u^3.
 * Light at u moving outwards sweeps Phi(u) = int_0^u du / sqrt(...) more on its way to u = 0;
 * moving inwards past a periapsis u_t, 2 Phi(u_t) - Phi(u). With a periapsis the substitution
 * u = u_t sin(theta) leaves the smooth integrand 1 / sqrt(1 - 2 M u_t (1 + s + s^2) / (1 + s)),
 * s = sin(theta); without one (b <= b_c) the integrand in u has no root and is integrated as it is.
 * Light that falls into the horizon instead (inwards with b <= b_c, or outwards inside the photon
 * sphere's barrier) has no direction at infinity: it keeps its own. */
#ifndef BT_PHYSICS_ESCAPE_H
#define BT_PHYSICS_ESCAPE_H
#include "physics/vec3.h"

/* The angle light at u = 1/r with du/dphi = w sweeps until infinity, or -1 when it falls in. */
double escape_sweep(double mass, double u, double w);

/* The direction at infinity of light at x moving along v around mass at centre; 1 when continued,
 * 0 (out = v normalised) in flat space, for radial light and where the light falls in. */
int escape_direction(double mass, vec3d centre, vec3d x, vec3d v, vec3d *out);

#endif
