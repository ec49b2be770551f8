// Straight rays: no force, the camera direction is the velocity.
vec3 model_accel(vec3 x, vec3 v)
{
    return vec3(0.0);
}

vec3 model_initial_velocity(vec3 x, vec3 d)
{
    return d;
}
