/* The camera's rays: the direction each pixel looks in, in the observer's frame and in the scene's,
 * and the frequency ratio of light arriving from infinity along a view direction. */
#ifndef BT_CAMERA_H
#define BT_CAMERA_H
#include "scene/scene.h"

/* Direction the observer looks in through pixel (i, j), in the observer's own frame; j counted from
 * the top row; pixel centres at (i + 0.5) / W. */
vec3d camera_view_direction(const struct scene *s, int i, int j);
/* The same viewing ray in the scene's frame (aberrated when the observer moves): where rays start. */
vec3d camera_ray(const struct scene *s, int i, int j);
/* The same for a ray (dx, dy) pixels off the centre, dy up (render.samples: scene/pixel_samples.h). */
vec3d camera_view_direction_at(const struct scene *s, int i, int j, double dx, double dy);
vec3d camera_ray_at(const struct scene *s, int i, int j, double dx, double dy);
/* The camera's axes, worked out once for many pixels: camera_frame_view and camera_frame_ray give
 * the same bits as camera_view_direction_at and camera_ray_at. */
struct camera_frame {
    const struct scene *scene;
    vec3d forward, right, up;
    double tan_half;
    int moving;
};
void camera_frame_make(const struct scene *s, struct camera_frame *f);
vec3d camera_frame_view(const struct camera_frame *f, int i, int j, double dx, double dy);
vec3d camera_frame_ray(const struct camera_frame *f, int i, int j, double dx, double dy);
/* The lapse sqrt(1 - 2M/r) of a static observer at p (1 off Schwarzschild): the frequency ratio of
 * light sent by a static emitter at p and received by a static observer at infinity. */
double static_lapse(const struct scene *s, vec3d p);
/* The same as the image shows it: 1 where observer.gravitational_shift is off (motion's shift alone). */
double static_lapse_shown(const struct scene *s, vec3d p);
/* A frequency ratio `ratio` of light sent at p and received by a static observer at infinity, of
 * which the static observer's lapse at p is a factor (an orbiting emitter's: physics/accretion.h), as
 * the image shows it: with observer.gravitational_shift off, that lapse taken out. */
double emitted_ratio_shown(const struct scene *s, vec3d p, double ratio);
/* Frequency ratio D of light from a source at rest at infinity, seen along view direction `view`
 * (observer's frame): the motion's Doppler factor times the gravitational blueshift at the camera
 * (where observer.gravitational_shift is on). */
double camera_doppler(const struct scene *s, vec3d view);

#endif
