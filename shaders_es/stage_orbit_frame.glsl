// render.method = orbit_table in one pass (render.pipeline = single): each pixel follows its orbit
// chord by chord (orbit_chord, as the orbit stage), tests every object of the scene against each
// chord (intersect_chord, as the intersection stage) and ends at the first hit, at the horizon or
// where it leaves the bounding sphere (as the termination stage). It writes what the multipass
// scheme leaves in the result textures: image and velocity, all the sky stage needs
// (FRAME_STATE undefined), or hit and position (FRAME_STATE 1), only when they are
// read, or where only the image is read the final colour itself (FRAME_COLOUR: the sky stage's
// sky_colour.glsl, in this pass). MAX_SEGMENTS is the scene's render.max_chords.

#if defined(ORBIT_NOTHING_TO_MEET) && !defined(FRAME_STATE)
// A scene without objects, for the image: each ray's outcome is its side of the critical angle, and
// an escaping ray's sky is along its direction at infinity, both from the table. No chord is
// followed (the multipass scheme's one chord per orbit ends the same: it leaves or falls in at the
// orbit's end), no crossing of the bounding sphere is found: the state pass finds it for --dump.
void main()
{
    orbit_ray ray = orbit_ray_of();
    bool escapes = ray.side_first < 0.5;
    vec2 q = orbit_at(ray, 1.0);
    vec3 fallen = orbit_tangent(ray, q, 1.0);
    vec3 escape = orbit_direction_at_infinity(ray);
    vec4 image = vec4(0.0, 0.0, 0.0, escapes ? CODE_SKY : CODE_CAPTURED);
    vec3 direction = escapes ? escape : fallen;
#ifdef FRAME_COLOUR
    // only the image is read: the sky stage's final colour, here (stage_frame.c)
    WRITE_FRAME_COLOUR(image, direction);
#else
    WRITE_TARGET0(image);
    WRITE_TARGET1(vec4(direction, 1.0));
#endif
}
#else
// ORBIT_HIT_TRIES (stage_frame.c): how many walks a ray takes at most, in one pass or in as many
// pairs of passes; after a hit its orbit misses it goes on (the last hit found is kept).
#ifdef ORBIT_WALKED
uniform float u_orbit_last_try;       // 1 in the last pair of passes
#endif

void main()
{
    orbit_ray ray = orbit_ray_of();
    float k = 0.0;                       // the chord where the walk stopped
    vec3 a = u_camera_position;          // its start
    vec3 b = a;                          // the end of the chord the walk ended on
    float s = 0.0;                       // the orbit's fraction where the ray moved last
    vec2 q = vec2(1.0, 0.0);             // u, du/ds at s
    bool leaves = false;
    float steps = 0.0;
    float code = CODE_UNFINISHED;
    float end_key = NO_HIT;
    bool done = false;
    bool leaving = false;
    bool escaped = false;
    candidate best = candidate(NO_HIT, 0.0, -1.0, vec3(0.0), vec3(0.0));
    bool found_walking;
#ifdef ORBIT_WALKED
    // where the walk pass stopped
    orbit_walk_read(k, done, leaving, escaped, found_walking);
    bool last_try = u_orbit_last_try > 0.0;
    {
#else
    cull_prepare(ray);
    // A hit is found again on the orbit (orbit_refine_hit) after the walk; where the orbit misses
    // what the chord met, the ray goes on from that chord's end (as the multipass scheme, whose
    // intersection stage keeps no such hit), up to ORBIT_HIT_TRIES walks.
    for (int attempt = 0; attempt < ORBIT_HIT_TRIES; attempt++) {
        orbit_walk(ray, k, done, leaving, escaped, found_walking);
        bool last_try = attempt == ORBIT_HIT_TRIES - 1;
#endif
        // every value of the walk where it stopped, found again from it
        orbit_walk_found(ray, k, done, found_walking, a, s, q, best);
        // The chord the walk ended on starts at a, at fraction s_a of the orbit (chord k; as the
        // intersection stage of the multipass scheme finds it). Where it found a hit or fell in
        // (done), it ends at s, where the ray moved last; otherwise the ray stands at its end.
        // The chord that leaves the bounding sphere ends where the orbit crosses it, found by
        // Newton's steps on the orbit (orbit_chord_from): once per ray, here, rather than in a
        // branch of the walk that a group of pixels would take as often as any one of them leaves.
        float s_a = orbit_chord_end(ray, k);
        vec3 chord_end = orbit_point(ray, q, s);
        b = done ? chord_end : a;
        bool falls = done && captured(b);
        bool found = best.slot >= 0.0;
        steps = done ? k + 1.0 : k;
        code = done && !found ? CODE_CAPTURED : CODE_UNFINISHED;
        end_key = done && !found ? steps : NO_HIT;
        // a ray that left the bounding sphere in a group of chords that meets nothing
        // (ORBIT_SKY_UNPLACED): the sky, along its direction at infinity; where it crossed the
        // sphere is not read
        code = escaped ? CODE_SKY : code;
        end_key = escaped ? steps : end_key;
        leaves = escaped;
        if (leaving) {
            // the leaving chord as the orbit stage makes it (orbit_chord_from): from its end outside
            // the sphere back to where the orbit crosses it, on the same values
            float s1 = orbit_chord_end(ray, k + 1.0);
            q = orbit_at(ray, s1);
            vec3 from_bound = orbit_point(ray, q, s1) - u_bound_center;
            orbit_crossing(ray, s_a, s1, from_bound, q, s);
            leaves = true;
            b = orbit_chord_point(ray, q, s, leaves);
            steps = k + 1.0;
#ifdef FRAME_STATE
            intersect_chord(a, b, k, best);
#else
            // whether it meets an object: the hit itself is found on the orbit below
            best.slot = intersect_chord_meets(a, b) ? 0.0 : -1.0;
#endif
            found = best.slot >= 0.0;
            code = found ? code : CODE_SKY;
            end_key = found ? end_key : steps;
        }
        // the hit found again on the orbit itself, on the chord from a (s_a) to b (s); where the
        // orbit misses (lost), the chord's end decides as it would have without the hit: the ray
        // leaves, falls in or goes on from there
        bool lost = false;
        vec3 hit_a = a;
        vec3 hit_b = b;
        float halves = 0.0;
        if (best.slot >= 0.0)
            orbit_refine_hit(ray, s_a, s, k, hit_a, hit_b, best, lost, halves);
        lost = lost && !last_try;
        bool goes_on = lost && !leaving && !falls;
        bool stops = lost && !goes_on;
        code = stops ? (leaving ? CODE_SKY : CODE_CAPTURED) : code;
        end_key = stops ? steps : end_key;
        best.slot = lost ? -1.0 : best.slot;
        best.key = lost ? NO_HIT : best.key;
        // a hit kept: a and b become the short chord that carries it (for the shading below)
        a = hit_a;
        b = hit_b;
        k = goes_on ? steps : k;
#ifdef ORBIT_WALKED
        // the next pair of passes walks on from the chord's end (this pixel left as it is)
        if (goes_on)
            discard;
    }
#else
        // at the turn's end (docs/PIPELINE.md, "Loops that end at a turn's end")
        if (!goes_on)
            break;
    }
#endif
    // the final state again from (q, s), outside the loop: see the precision note in common.glsl
    vec3 end = orbit_chord_point(ray, q, s, leaves);
    // a ray that leaves looks the sky up along its direction at infinity (as the orbit stage)
    vec3 along_orbit = orbit_tangent(ray, q, s);
    vec3 escape = orbit_direction_at_infinity(ray);
    vec3 tangent = leaves ? escape : along_orbit;
    vec4 new_hit, new_image;
    intersect_shade(best, a, b, new_hit, new_image);
    bool found = best.slot >= 0.0;
    vec4 end_hit = vec4(end, end_key);
    vec4 end_image = vec4(0.0, 0.0, 0.0, code);
#ifdef FRAME_STATE
    WRITE_TARGET0(found ? new_hit : end_hit);
    WRITE_TARGET1(vec4(end, steps));
#elif defined(FRAME_COLOUR)
    // only the image is read: the sky stage's final colour, here (stage_frame.c); the direction
    // matters only for the sky, where the ray leaves along its direction at infinity, so the orbit
    // where the walk stopped need not stay live through the hit's refinement for it
    WRITE_FRAME_COLOUR(found ? new_image : end_image, escape);
#else
    float reached = leaves ? 1.0 : s;
    WRITE_TARGET0(found ? new_image : end_image);
    WRITE_TARGET1(vec4(tangent, reached));
#endif
}
#endif
