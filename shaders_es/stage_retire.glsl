// Test for ray termination (paper section 4.1), the cheap pass: a ray that has found its hit or
// its outcome is retired: its final state is copied into the result textures and the depth
// buffer marks it, so that the early-z test skips it in every heavy pass after this one. Rays
// still travelling are discarded here (this pass may discard: it is not one of the heavy passes,
// and it draws at depth 0, in front of them). u_retire_all retires every ray (the end of a frame).
// Pair 0 copies position and velocity, pair 1 hit and image.
uniform sampler2D u_state0;
uniform sampler2D u_state1;
uniform sampler2D u_hit;
uniform float u_retire_all;
#ifdef SKY_AT_INFINITY
// Integrated rays around a mass: a ray that left (its image's code) looks the sky up along its
// direction at infinity (model_exit_direction), as the single pass does. Pair 0 only.
uniform sampler2D u_image;
uniform float u_exit_pair;
#endif

void main()
{
    bool finished = fetch(u_hit).w < NO_HIT;
    if (!finished && u_retire_all < 0.5)
        discard;
    vec4 state0 = fetch(u_state0);
    vec4 state1 = fetch(u_state1);
#ifdef SKY_AT_INFINITY
    vec3 escape = model_exit_direction(state0.xyz, state1.xyz) * length(state1.xyz);
    bool left = u_exit_pair > 0.5 && fetch(u_image).a == CODE_SKY;
    state1.xyz = left ? escape : state1.xyz;
#endif
    WRITE_TARGET0(state0);
    WRITE_TARGET1(state1);
}
