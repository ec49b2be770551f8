// Stage 1, ray setup (paper section 3.1): a pinhole camera; pixel centres at (i + 0.5) / W.
// The model turns the viewing direction into the initial velocity of the ray.
uniform vec3 u_camera_position;
uniform vec3 u_camera_forward;        // unit view direction
uniform vec3 u_camera_right;          // scaled by tan(fov / 2) * aspect
uniform vec3 u_camera_up;             // scaled by tan(fov / 2)
uniform vec2 u_pixel_origin;          // image pixel of ray-state texel (0, 0); (0, 0) for a full frame
uniform vec2 u_image_size;
uniform float u_step_size;

void main()
{
    vec2 pixel_centre = u_pixel_origin + gl_FragCoord.xy;
    vec2 ndc = pixel_centre / u_image_size * 2.0 - 1.0;
    vec3 view = normalize(u_camera_forward + ndc.x * u_camera_right + ndc.y * u_camera_up);
    WRITE_TARGET0(vec4(u_camera_position, 0.0));
    WRITE_TARGET1(vec4(model_initial_velocity(u_camera_position, view), u_step_size));
}
