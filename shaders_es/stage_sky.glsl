// Stage 5, sky and final colour (paper section 4.3): every ray's final colour from its retired
// state (sky_colour.glsl). It writes the 8-bit image, and with HDR_OUTPUT the same colours
// unclamped into a float target (renderer_set_hdr).
uniform sampler2D u_image;
uniform sampler2D u_ray_velocity;

void main()
{
    // the colour as it is, or on the packed path a float colour (HDR_OUTPUT) packed (common.glsl)
    gl_FragColor = state_written(sky_final_colour(fetch(u_image), fetch(u_ray_velocity).xyz));
}
