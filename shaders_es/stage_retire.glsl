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

void main()
{
    bool finished = fetch(u_hit).w < NO_HIT;
    if (!finished && u_retire_all < 0.5)
        discard;
    WRITE_TARGET0(fetch(u_state0));
    WRITE_TARGET1(fetch(u_state1));
}
