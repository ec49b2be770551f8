// The whole frame in one pass (render.pipeline = single) for integrated rays: each pixel sets its
// ray up (as the setup stage), integrates it segment by segment (integrate_pass, as the
// integration stage, PASSES_PER_SEGMENT times a segment), tests every object of the scene against
// each segment's chord that comes near one (intersect_chord, as the intersection stage; a chord
// that comes near none can meet none) and ends at the first hit or where the segment's end left
// the bounding sphere, fell into the horizon or stopped being finite (as the termination stage).
// The same functions, in the same order, on the same 32-bit values, so the rays are the
// multipass scheme's bit for bit (tests/unit/test_acceleration.c). It writes
// what that scheme leaves in the result textures: image and velocity, all the sky stage needs
// (FRAME_STATE undefined), or hit and position (FRAME_STATE 1), only when they are read.
uniform float u_step_size;
uniform float u_segments;             // render.segments (1 for straight rays)

// the loop's constant bound, SCENE_MAX_SEGMENTS; the scene's own count stops it (u_segments). Its
// counter is highp: GLSL ES's default int is mediump, which Mesa keeps in 16 bits, and a bound
// beyond 32767 wrapped there would end the loop before its first turn.
const highp int FRAME_MAX_SEGMENTS = 100000;

// segment_end: segment_end.glsl

void main()
{
    far_reach_prepare();
    vec3 view = observer_scene_direction(observer_view_direction());
    vec3 x = u_camera_position;
    vec3 v = model_initial_velocity(u_camera_position, view);
    float steps = 0.0;
    float h = u_step_size;
    vec3 a = x;
    float code = CODE_UNFINISHED;
    float end_key = NO_HIT;
    candidate best = candidate(NO_HIT, 0.0, -1.0, vec3(0.0), vec3(0.0));
#ifdef MODEL_FLAT
    // Flat space: the ray is one straight chord, from the camera to where it leaves the bounding
    // sphere (integrate_pass), tested against the objects once if it comes near one, and ended.
    // What the loops below do with one segment of one pass, with no loop to carry values through
    // (a GPU's registers hold far less): the same rays bit for bit (tests/unit/test_acceleration.c).
    bool running = steps >= 0.0 && travelling(x);
    integrate_pass(x, v, steps, h, running);
    chord_cull_prepare();
    if (chord_near(a, x))
        intersect_chord(a, x, 0.0, best);
    segment_end(x, steps, 0.0, best, code, end_key);
#else
    bool stop = false;
    vec3 v_a = v;
    float steps_a = steps;
    float h_a = h;
    float k_last = 0.0;
    bool again = false;
    // Segments are taken in an inner loop that integrates them and asks of each chord only whether
    // it comes near an object (chord_near, stage_intersect.glsl: a few multiplications an object);
    // a chord that does not cannot meet one, and its end is decided at once. A chord that does ends
    // the inner loop, and the outer loop's turn tests it against every object and decides its end
    // with that: whether it meets one (intersect_chord_meets), the closest hit found once, after
    // the loops (intersect_chord; V3D 4.2 spilled 14 values of the kiosk's lorenz frame with the
    // hit carried through the loop, none without). The same tests on the same chords as the
    // multipass scheme where it matters, in the same order: the same rays bit for bit
    // (tests/unit/test_acceleration.c). Why: a GPU that runs fragments in groups (llvmpipe: 8) pays
    // for an object's test on every chord whatever the test's `if`s say; a loop's turns it pays
    // only while one of the group needs them. The inner loop's turns cost a segment's steps, the
    // outer's the objects' tests.
    float next_segment = 0.0;
    bool pending = false;   // chord a -> x, segment k_last, comes near an object: its tests are due
    bool hit_chord = false; // chord a -> x, segment k_last, meets an object: the ray stopped on it
    chord_cull_prepare();
    for (highp int i = 0; i < FRAME_MAX_SEGMENTS; i++) {
        if (stop || next_segment >= u_segments)
            break;
        for (highp int j = 0; j < FRAME_MAX_SEGMENTS; j++) {
            float k = next_segment;
            if (k >= u_segments || stop || pending)
                break;
            a = x;
            v_a = v;
            steps_a = steps;
            h_a = h;
            k_last = k;
            bool clean = true;
#ifdef CHECK_EVERY_STEP
            for (int p = 0; p < PASSES_PER_SEGMENT; p++) {
                bool running = steps >= 0.0 && travelling(x);
                integrate_pass(x, v, steps, h, running);
                // at the turn's end (docs/PIPELINE.md, "Loops that end at a turn's end")
                if (p == PASSES_PER_SEGMENT - 1)
                    break;
            }
#else
            // the segment's steps unchecked (stage_integrate.glsl); a ray that left, fell in or
            // failed within them takes the segment again after the segments' loops, from its
            // start, each step checked
            STEPS_UNCHECKED(PASSES_PER_SEGMENT * STEPS_PER_PASS, x, v, steps, h, clean)
#endif
            bool near = chord_near(a, x);
            float new_code = code;
            float new_end_key = end_key;
            bool ended = segment_end(x, steps, k, best, new_code, new_end_key);
            bool decided = clean && !near;
            code = decided ? new_code : code;
            end_key = decided ? new_end_key : end_key;
            again = !clean;
            // A segment that changed nothing (an adaptive ray that has spent its path takes steps
            // of length 0) leaves every later one the same: the ray stops there, the same bit for bit.
            bool still = x == a && v == v_a && steps == steps_a && h == h_a;
            // a ray that left, fell in or failed within the segment's unchecked steps stands at
            // the segment's start again, which it takes again after the loops, each step checked:
            // restored here, the segment's start need not be kept through the rest of the walk
            // (a GPU's registers: `make shader-stats`)
            x = again ? a : x;
            v = again ? v_a : v;
            steps = again ? steps_a : steps;
            h = again ? h_a : h;
            pending = clean && near;
            stop = again || (decided && ended) || still;
            next_segment = k + 1.0;
            // at the turn's end (docs/PIPELINE.md, "Loops that end at a turn's end")
            if (next_segment >= u_segments || stop || pending)
                break;
        }
        // whether the chord meets an object: the ray stops on it, and its closest hit is found
        // after the loops, where the checked segment's is (the loop carries no hit)
        bool meets = intersect_chord_meets(a, x);
        float new_code = code;
        float new_end_key = end_key;
        bool ended = segment_end_found(x, steps, k_last, meets, new_code, new_end_key);
        code = pending ? new_code : code;
        end_key = pending ? new_end_key : end_key;
        hit_chord = pending && meets;
        stop = stop || (pending && ended);
        pending = false;
        // at the turn's end, as every loop here (docs/PIPELINE.md, "Loops that end at a turn's end")
        if (stop || next_segment >= u_segments)
            break;
    }
    // The segment in which a ray left, fell into the horizon or failed, from its start (where the
    // loop left it), as the multipass scheme integrates, intersects and ends it: the same rays bit
    // for bit (tests/unit/test_acceleration.c). Once per ray, not once per segment.
    vec3 x_checked = x;
    vec3 v_checked = v;
    float steps_checked = steps;
    float h_checked = h;
    exit_step left_at = no_exit();
    for (int p = 0; p < PASSES_PER_SEGMENT; p++) {
        if (!again)
            break;
        bool running = steps_checked >= 0.0 && travelling(x_checked);
        integrate_pass_checked(x_checked, v_checked, steps_checked, h_checked, running, left_at);
        // at the turn's end (docs/PIPELINE.md, "Loops that end at a turn's end")
        if (p == PASSES_PER_SEGMENT - 1)
            break;
    }
    // selected, not assigned in the loop that may break (see the precision note in common.glsl)
    x = again ? x_checked : x;
    v = again ? v_checked : v;
    steps = again ? steps_checked : steps;
    h = again ? h_checked : h;
    // the closest hit on the last chord: the one the ray stopped on, or the checked segment's
    candidate tested = best;
    intersect_chord(a, x, k_last, tested);
    best = again || hit_chord ? tested : best;
    float new_code = code;
    float new_end_key = end_key;
    segment_end(x, steps, k_last, best, new_code, new_end_key);
    code = again ? new_code : code;
    end_key = again ? new_end_key : end_key;
    // a ray that left for the sky in that segment: its velocity where it crossed the bounding
    // sphere (stage_integrate.glsl), found here, where the segment's tests no longer hold registers
    v = exit_taken(left_at, x, v);
#endif
    vec4 new_hit, new_image;
    intersect_shade(best, a, x, new_hit, new_image);
    bool found = best.slot >= 0.0;
    // a ray still travelling keeps the "no hit yet" of the setup stage's fill
    vec4 ended_hit = vec4(x, end_key);
    vec4 no_hit = vec4(0.0, 0.0, 0.0, NO_HIT);
    vec4 end_hit = end_key < NO_HIT ? ended_hit : no_hit;
    vec4 end_image = vec4(0.0, 0.0, 0.0, code);
#ifdef FRAME_STATE
    WRITE_TARGET0(found ? new_hit : end_hit);
    WRITE_TARGET1(vec4(x, steps));
#else
#ifdef SKY_AT_INFINITY
    // a ray that left looks the sky up along its direction at infinity (as the retire stage)
    vec3 escape = model_exit_direction(x, v) * length(v);
    v = !found && code == CODE_SKY ? escape : v;
#endif
#ifdef FRAME_COLOUR
    // only the image is read: the sky stage's final colour, here (stage_frame.c)
    WRITE_FRAME_COLOUR(found ? new_image : end_image, v);
#else
    WRITE_TARGET0(found ? new_image : end_image);
    WRITE_TARGET1(vec4(v, h));
#endif
#endif
}
