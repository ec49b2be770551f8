// The fused segment pass (render.pipeline = fused; stage_segment.c): the integration, intersection
// and termination stages of one segment in one pass, for GPUs that write four targets at once but
// need not run long loops (OpenGL ES 2 with EXT_draw_buffers). Each ray's segment is integrated
// pass by pass as the integration stage does (integrate_pass, PASSES_PER_SEGMENT times), its chord
// is tested against every object of the scene (intersect_chord, as the intersection stage with all
// objects in one batch), and it ends as the termination stage decides (segment_end): the same
// functions on the same 32-bit values, so the rays are the multipass scheme's bit for bit
// (tests/unit/test_acceleration.c). It writes position, velocity, hit and image at once; the
// retirement stage stays as it is. A ray that already has its hit or outcome (not yet retired,
// with render.termination_interval > 1) keeps its state, as the three stages leave it.
uniform sampler2D u_ray_position;
uniform sampler2D u_ray_velocity;
uniform sampler2D u_hit;
uniform sampler2D u_image;
uniform float u_segment_index;

// segment_end: segment_end.glsl

void main()
{
    far_reach_prepare();
    vec4 position = fetch(u_ray_position);
    vec4 velocity = fetch(u_ray_velocity);
    vec4 hit = fetch(u_hit);
    vec4 image = fetch(u_image);
    vec3 a = position.xyz;
    vec3 x = a;
    vec3 v = velocity.xyz;
    float steps = position.w;
    float h = velocity.w;
    bool waiting = hit.w >= NO_HIT;
    for (int p = 0; p < PASSES_PER_SEGMENT; p++) {
        bool running = waiting && steps >= 0.0 && travelling(x);
        integrate_pass(x, v, steps, h, running);
        // at the turn's end (docs/PIPELINE.md, "Loops that end at a turn's end")
        if (p == PASSES_PER_SEGMENT - 1)
            break;
    }
    float k = u_segment_index;
    candidate best = candidate(hit.w, 0.0, -1.0, vec3(0.0), vec3(0.0));
    intersect_chord(a, x, k, best);
    // computed before the selects: see the precision note in common.glsl
    vec4 new_hit, new_image;
    intersect_shade(best, a, x, new_hit, new_image);
    bool found = best.slot >= 0.0;
    float code = CODE_UNFINISHED;
    float end_key = NO_HIT;
    segment_end(x, steps, k, best, code, end_key);
    bool ends = end_key < NO_HIT;
    vec4 end_hit = vec4(x, end_key);
    vec4 end_image = vec4(0.0, 0.0, 0.0, code);
    vec4 ended_hit = ends ? end_hit : hit;
    vec4 ended_image = ends ? end_image : image;
    vec4 hit_out = found ? new_hit : ended_hit;
    vec4 image_out = found ? new_image : ended_image;
    // a ray that was not waiting: its state as it came (integrate_pass kept x, v, steps and h)
    WRITE_TARGET0(state_rounded(vec4(x, steps)));
    WRITE_TARGET1(state_rounded(vec4(v, h)));
    WRITE_TARGET2(waiting ? hit_out : hit);
    WRITE_TARGET3(waiting ? image_out : image);
}
