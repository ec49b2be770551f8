// Stage 5, sky and final colour (paper section 4.3): every ray's final colour from its retired
// state (sky_colour.glsl). It writes the 8-bit image, and with HDR_OUTPUT the same colours
// unclamped into a float target (renderer_set_hdr).
uniform sampler2D u_image;
uniform sampler2D u_ray_velocity;

#ifdef STAR_FOOTPRINT_NEIGHBOURS
// The stars' footprints on a GPU that takes no derivatives (GL_OES_standard_derivatives): from the
// neighbouring rays of this run, as the CPU's star pass takes them from the image's
// (src/results/star_light.c, jacobian_column): along each axis the difference of the exit
// directions of the two neighbours, halved, where both reached the sky; one-sided where one did;
// none where neither did (then no star is drawn here). The camera's straight rays take the same
// stencil. A neighbour beyond this run's rays (the image's edge, or a band's) is not one.
uniform vec2 u_run_rays;    // the rays of this run, across and up

bool sky_ray(vec2 ray)
{
    bool inside = ray.x >= 0.0 && ray.y >= 0.0 && ray.x < u_run_rays.x && ray.y < u_run_rays.y;
    return inside && fetch_at(u_image, ray).a == CODE_SKY;
}

void footprint_column(vec2 ray, vec2 along, out vec3 column, out vec3 straight)
{
    bool ahead = sky_ray(ray + along);
    bool behind = sky_ray(ray - along);
    vec2 a = ahead ? ray + along : ray;
    vec2 b = behind ? ray - along : ray;
    float span = ahead && behind ? 0.5 : 1.0;
    vec3 exit_a = normalize(fetch_at(u_ray_velocity, a).xyz);
    vec3 exit_b = normalize(fetch_at(u_ray_velocity, b).xyz);
    column = ahead || behind ? span * (exit_a - exit_b) : vec3(0.0);
    straight = span * (observer_scene_direction(observer_view_direction_at(a)) -
                       observer_scene_direction(observer_view_direction_at(b)));
}

void star_footprints(out vec3 jx, out vec3 jy, out vec3 fx, out vec3 fy)
{
    vec2 ray = ray_pixel();
    footprint_column(ray, vec2(1.0, 0.0), jx, fx);
    footprint_column(ray, vec2(0.0, 1.0), jy, fy);
}
#endif

void main()
{
    // the colour as it is, or on the packed path a float colour (HDR_OUTPUT) packed (common.glsl)
    gl_FragColor = state_written(sky_final_colour(fetch(u_image), fetch(u_ray_velocity).xyz));
}
