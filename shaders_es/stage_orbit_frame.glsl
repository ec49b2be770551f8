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
    WRITE_TARGET0(sky_final_colour(image, direction));
#else
    WRITE_TARGET0(image);
    WRITE_TARGET1(vec4(direction, 1.0));
#endif
}
#else
// Chords taken together, ORBIT_GROUP at a time: a group whose chords can meet nothing is passed
// over in one step, its end point computed as its last chord would compute it, so the rays, hits
// and images stay those of the chord-by-chord walk (tests/unit/test_orbit_render.c).
const float ORBIT_GROUP = 4.0;
// How far, relative to the radius, the interpolated orbit might stray from the radii of its ends
// between them (float roundings, and the interpolant's wiggle where the orbit is nearly circular)
const float GROUP_RADIUS_MARGIN = 1e-3;
// How many times a ray goes on after a hit its orbit misses (the last hit found is kept)
const int ORBIT_HIT_TRIES = 3;

// Whether the chords between fractions s_a and s_b of the orbit (where it has u, du/ds = q_a and
// q_b) can meet no object, end inside the capture sphere or leave the bounding sphere. Without a
// turning point between them (du/ds keeps its sign) all their ends lie between the radii of the
// two ends; a group with one is followed chord by chord.
bool group_clear(orbit_ray ray, float s_a, vec2 q_a, vec2 cs_a, float s_b, vec2 q_b, vec2 cs_b)
{
    bool turns = q_a.y * q_b.y <= 0.0;
    float r_a = 1.0 / q_a.x;
    float r_b = 1.0 / q_b.x;
    float r_lo = min(r_a, r_b) * (1.0 - GROUP_RADIUS_MARGIN);
    float r_hi = max(r_a, r_b) * (1.0 + GROUP_RADIUS_MARGIN);
    float capture_offset = length(u_capture_center - u_model_center);
    float nearest_capture = r_lo - capture_offset;
    bool may_fall = u_capture_radius2 > 0.0 &&
                    (nearest_capture <= 0.0 || nearest_capture * nearest_capture <= u_capture_radius2);
    float farthest_bound = length(u_model_center - u_bound_center) + r_hi;
    bool may_leave = farthest_bound * farthest_bound >= u_bound_radius2 * (1.0 - GROUP_RADIUS_MARGIN);
    cull_phi_a = s_a * ray.phi_end;
    cull_phi_b = s_b * ray.phi_end;
    vec4 ends = vec4(cs_a, cs_b);
    return !turns && !may_fall && !may_leave && cull_group_clear(ray, ends, r_lo, r_hi);
}

void main()
{
    orbit_ray ray = orbit_ray_of();
    cull_prepare(ray);
    // What the loops carry from turn to turn is kept to what they cannot compute again: every value
    // live across their turns takes a register for the whole loop, and an exhibit's GPU has few
    // (`make shader-stats`). The chord a walk ends on is found again after it from where the ray
    // stands (k, s and a), and a walk that goes on after a hit the orbit misses starts again from
    // its chord k alone, with the same arithmetic, so that their values are the walk's own.
    float k = 0.0;                       // the chord where the ray stands (a walk starts)
    vec3 a = u_camera_position;          // where the ray stands: the start of chord k
    vec3 b = a;                          // the end of the chord the walk ended on
    float s = 0.0;                       // the orbit's fraction where the ray moved last
    vec2 q = vec2(1.0, 0.0);             // u, du/ds at s
    bool leaves = false;
    float steps = 0.0;
    float code = CODE_UNFINISHED;
    float end_key = NO_HIT;
    // The chord that leaves the bounding sphere ends where the orbit crosses it, found by Newton's
    // steps on the orbit (orbit_chord_from): once per ray, after the loop, rather than in a branch
    // of it that a group of pixels would take as often as any one of them leaves.
    bool leaving = false;
    candidate best = candidate(NO_HIT, 0.0, -1.0, vec3(0.0), vec3(0.0));
    // A hit is found again on the orbit (orbit_refine_hit) after the walk; where the orbit misses
    // what the chord met, the ray goes on from that chord's end (as the multipass scheme, whose
    // intersection stage keeps no such hit), up to ORBIT_HIT_TRIES walks.
    for (int attempt = 0; attempt < ORBIT_HIT_TRIES; attempt++) {
        // the walk starts at chord k: at the camera, or at the end of the chord before it
        bool at_camera = k <= 0.0;
        s = orbit_chord_end(ray, k);
        q = orbit_at(ray, s);
        float phi = s * ray.phi_end;
        vec2 cs_group = at_camera ? vec2(1.0, 0.0) : vec2(cos(phi), sin(phi));  // cos, sin of phi at s
        vec3 on_orbit = orbit_point(ray, q, s);
        a = at_camera ? u_camera_position : on_orbit;
        leaving = false;
        best = candidate(NO_HIT, 0.0, -1.0, vec3(0.0), vec3(0.0));
        // Chords are taken ORBIT_GROUP at a time. At a group's start a turn looks at the group's
        // last end only: where the group can meet nothing, fall in or leave (group_clear), the ray
        // moves there at once, to the point its last chord would have reached; otherwise the next
        // turns follow the group chord by chord. Every turn evaluates the orbit once and tests one
        // chord, whichever it does, so that a group of pixels where some rays pass a group over
        // and others follow its chords pays for one turn, not for both.
        float k_end = k;                 // end of the group being followed chord by chord
        bool done = false;               // a hit found, or the chord ends inside the capture sphere
        for (int i = 0; i < 2 * MAX_SEGMENTS + 2; i++) {
            if (k >= ray.segments || leaving || done)
                break;
            bool probe = k >= k_end;
            float group_end = min(k + ORBIT_GROUP, ray.segments);
            float k1 = probe ? group_end : k + 1.0;
            float s1 = orbit_chord_end(ray, k1);
            vec2 q1 = orbit_at(ray, s1);
            vec3 p1 = orbit_point(ray, q1, s1);
            float phi1 = s1 * ray.phi_end;
            vec2 cs1 = vec2(cos(phi1), sin(phi1));
            bool clear = group_clear(ray, s, q, cs_group, s1, q1, cs1);
            bool passes = probe && clear;
            bool chord = !probe;
            k_end = probe ? group_end : k_end;
            // a leaving chord moves nothing: the ray stands at its start (a, s, k)
            leaving = chord && outside_bounds(p1);
            bool tested = chord && !leaving;
            bool moves = passes || tested;
            q = moves ? q1 : q;
            s = moves ? s1 : s;
            cs_group = moves ? cs1 : cs_group;
            candidate trial = best;
            intersect_chord(a, p1, k, trial);
            best.key = tested ? trial.key : best.key;
            best.t = tested ? trial.t : best.t;
            best.slot = tested ? trial.slot : best.slot;
            done = best.slot >= 0.0 || (tested && captured(p1));
            // a chord with a hit (or that falls in) keeps its start: the ray stands at a, chord k
            a = moves && !done ? p1 : a;
            k = moves && !done ? k1 : k;
            // at the turn's end (docs/PIPELINE.md, "Loops that end at a turn's end")
            if (k >= ray.segments || leaving || done)
                break;
        }
        // The chord the walk ended on starts at a, at fraction s_a of the orbit (chord k; as the
        // intersection stage of the multipass scheme finds it). Where it found a hit or fell in
        // (done), it ends at s, where the ray moved last; otherwise the ray stands at its end.
        float s_a = orbit_chord_end(ray, k);
        vec3 chord_end = orbit_point(ray, q, s);
        b = done ? chord_end : a;
        bool falls = done && captured(b);
        bool found = best.slot >= 0.0;
        steps = done ? k + 1.0 : k;
        code = done && !found ? CODE_CAPTURED : CODE_UNFINISHED;
        end_key = done && !found ? steps : NO_HIT;
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
            intersect_chord(a, b, k, best);
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
        if (best.slot >= 0.0)
            orbit_refine_hit(ray, s_a, s, k, hit_a, hit_b, best, lost);
        lost = lost && attempt < ORBIT_HIT_TRIES - 1;
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
        // at the turn's end (docs/PIPELINE.md, "Loops that end at a turn's end")
        if (!goes_on)
            break;
    }
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
    // only the image is read: the sky stage's final colour, here (stage_frame.c)
    WRITE_TARGET0(sky_final_colour(found ? new_image : end_image, tangent));
#else
    float reached = leaves ? 1.0 : s;
    WRITE_TARGET0(found ? new_image : end_image);
    WRITE_TARGET1(vec4(tangent, reached));
#endif
}
#endif
