// Stage 1, ray setup (paper section 3.1): a pinhole camera, moving with the observer's velocity;
// the model turns the viewing direction into the initial velocity of the ray.
uniform float u_step_size;

void main()
{
    vec3 view = observer_scene_direction(observer_view_direction());
    WRITE_TARGET0(state_rounded(vec4(u_camera_position, 0.0)));
    WRITE_TARGET1(state_rounded(vec4(model_initial_velocity(u_camera_position, view), u_step_size)));
}
