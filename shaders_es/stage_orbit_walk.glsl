// The walk of render.method = orbit_table's single pass (stage_orbit_frame.glsl): a ray follows its
// orbit chord by chord (orbit_chord, as the orbit stage), tests every object of the scene against
// each chord (intersect_chord, as the intersection stage), and stops at the first chord that meets
// one, that ends inside the capture sphere or that leaves the bounding sphere (as the termination
// stage), or after its last chord. What happens there (the crossing of the bounding sphere, the
// hit found again on the orbit, the shading, the sky) is the frame's finish.
//
// Where the ray state holds 32-bit floats, the walk is a pass of its own (ORBIT_WALK_PASS) that
// writes where each ray stopped, and the finish a second pass that reads it (ORBIT_WALKED): the
// walk's loop then holds none of the finish's values, and an exhibit's GPU runs it without
// spilling most of its registers (`make shader-stats`). Elsewhere the frame calls orbit_walk
// itself, in one pass.

// Where a walk stopped, in one RGBA8 texel (4 bytes a ray, a tile-based GPU's bandwidth): its
// chord k (two bytes: render.max_chords is at most 10000), how it stopped (1 at a hit or in the
// capture sphere: done; 2 where the chord leaves the bounding sphere; 3 where the ray left it in a
// group of chords that meets nothing (ORBIT_SKY_UNPLACED: escaped); 0 where the orbit's chords ran
// out) and whether it met an object (1) or not (0). Whole numbers only: the finish finds every other
// value of the walk again from them, with the walk's own arithmetic (the orbit's fraction where
// the ray moved last is the end of chord k where done, its start otherwise; the hit is chord k's,
// intersect_chord again), so the rays stay bit for bit those of one pass. A fraction written as the
// loop left it could come out of the loop at 16-bit precision (the precision note in common.glsl).
uniform sampler2D u_orbit_walk;

vec4 orbit_walk_state(float k, bool done, bool leaving, bool escaped, bool found)
{
    float k_high = floor(k / 256.0);
    float k_low = k - 256.0 * k_high;
    float how = done ? 1.0 : leaving ? 2.0 : escaped ? 3.0 : 0.0;
    vec4 bytes = vec4(k_low, k_high, how, found ? 1.0 : 0.0);
    return bytes / 255.0;
}

// k, done, leaving, escaped and whether the walk found a hit (orbit_walk_found finds it again)
void orbit_walk_read(out float k, out bool done, out bool leaving, out bool escaped, out bool found)
{
    vec4 bytes = floor(fetch(u_orbit_walk) * 255.0 + 0.5);
    k = bytes.x + 256.0 * bytes.y;
    done = bytes.z == 1.0;
    leaving = bytes.z == 2.0;
    escaped = bytes.z == 3.0;
    found = bytes.w > 0.0;
}

// Where a walk from chord k starts: the chord's start (the camera for chord 0), the orbit's
// fraction s there and u, du/ds = q.
vec3 orbit_walk_start(orbit_ray ray, float k, out float s, out vec2 q)
{
    s = orbit_chord_end(ray, k);
    q = orbit_at(ray, s);
    vec3 on_orbit = orbit_point(ray, q, s);
    return k <= 0.0 ? u_camera_position : on_orbit;
}

// What a walk that stopped at chord k found, again from k with the walk's own arithmetic: the
// chord's start a, the orbit's fraction s where the ray moved last (the end of chord k where done,
// its start otherwise) and u, du/ds = q there, and the hit best on chord k where found.
void orbit_walk_found(orbit_ray ray, float k, bool done, bool found, out vec3 a, out float s, out vec2 q,
                      out candidate best)
{
    float s_start;
    vec2 q_start;
    a = orbit_walk_start(ray, k, s_start, q_start);
    float k_moved = done ? k + 1.0 : k;
    s = orbit_chord_end(ray, k_moved);
    q = orbit_at(ray, s);
    best = candidate(NO_HIT, 0.0, -1.0, vec3(0.0), vec3(0.0));
#ifdef FRAME_STATE
    // the hit's depth key, which the ray's state keeps
    if (found)
        intersect_chord(a, orbit_point(ray, q, s), k, best);
#else
    // only that the chord meets an object: orbit_refine_hit finds the hit itself on the orbit, and
    // nothing read here keeps the chord's own hit (the walk's test, on the same chord, said so)
    best.slot = found ? 0.0 : -1.0;
#endif
}

#ifndef ORBIT_WALKED
// Chords taken together in groups: a group whose chords can meet nothing is passed over in one
// step, its end point computed as its last chord would compute it, so the rays, hits and images
// stay those of the chord-by-chord walk (tests/unit/test_orbit_render.c). A walk's first group
// is ORBIT_GROUP_FIRST chords; a group passed over doubles the next one, up to ORBIT_GROUP_MOST,
// and a group that cannot be passed over is halved and looked at again, down to one chord, which
// is tested: the walk closes in on the first chord that can meet something in about log2 of the
// chords before it, and moves on as fast again behind it.
const float ORBIT_GROUP_FIRST = 4.0;
const float ORBIT_GROUP_MOST = 256.0;
// How far, relative to the radius, the interpolated orbit might stray from the radii of its ends
// between them (float roundings, and the interpolant's wiggle where the orbit is nearly circular)
const float GROUP_RADIUS_MARGIN = 1e-3;

// Whether the chords between fractions s_a and s_b of the orbit (where it has u, du/ds = q_a and
// q_b) can meet no object, end inside the capture sphere or leave the bounding sphere. Without a
// turning point between them (du/ds keeps its sign) all their ends lie between the radii of the
// two ends; with the orbit's periapsis (u rises, then falls), between that of the periapsis (r_turn)
// and the larger of the ends'; a group with another turn (an apoapsis: seen from inside the photon
// sphere) is followed chord by chord. meets_nothing: whether the group's chords meet nothing and
// fall into nothing, whether or not they leave (a group that does and ends outside the bounding
// sphere: the chord-by-chord walk would leave on one of them, with no hit).
bool group_clear(orbit_ray ray, float s_a, vec2 q_a, vec2 cs_a, float s_b, vec2 q_b, vec2 cs_b,
                 out bool meets_nothing)
{
    bool periapsis = q_a.y >= 0.0 && q_b.y <= 0.0;
    bool turns = q_a.y * q_b.y <= 0.0 && !periapsis;
    float r_a = 1.0 / q_a.x;
    float r_b = 1.0 / q_b.x;
    float r_lo = (periapsis ? min(ray.r_turn, min(r_a, r_b)) : min(r_a, r_b)) * (1.0 - GROUP_RADIUS_MARGIN);
    float r_hi = max(r_a, r_b) * (1.0 + GROUP_RADIUS_MARGIN);
    float capture_offset = length(u_capture_center - u_model_center);
    float nearest_capture = r_lo - capture_offset;
    bool may_fall = u_capture_radius2 > 0.0 &&
                    (nearest_capture <= 0.0 || nearest_capture * nearest_capture <= u_capture_radius2);
    float farthest_bound = length(u_model_center - u_bound_center) + r_hi;
    bool may_leave = farthest_bound * farthest_bound >= u_bound_radius2 * (1.0 - GROUP_RADIUS_MARGIN);
    float phi_a = s_a * ray.phi_end;
    float span = s_b * ray.phi_end - phi_a;
    vec4 ends = vec4(cs_a, cs_b);
    meets_nothing = !turns && !may_fall && cull_group_clear(ray, ends, phi_a, span, r_lo, r_hi);
    return meets_nothing && !may_leave;
}

// The walk from chord k: where it stops, k is the chord it stopped on; done: the
// chord meets an object (found) or ends inside the capture sphere; leaving: it leaves the bounding
// sphere (untested: the finish tests it up to the crossing); escaped: it left the bounding sphere
// on a chord of a group from chord k that meets nothing (group_clear); none of them: the orbit's
// chords are all walked. Nothing else comes out: the finish finds the rest again from k
// (orbit_walk_found).
void orbit_walk(orbit_ray ray, inout float k, out bool done, out bool leaving, out bool escaped, out bool found)
{
    // What the loop carries from turn to turn is kept to what it cannot compute again: every value
    // live across its turns takes a register for the whole loop, and an exhibit's GPU has few
    // (`make shader-stats`). The ray stands at the start of chord k: the camera, or the point of
    // the orbit at s (q = u, du/ds there; cs_group = cos, sin of its angle), found from those at
    // each turn rather than kept; the hit is found again after the walk.
    bool at_camera = k <= 0.0;
    float s;
    vec2 q;
    s = orbit_chord_end(ray, k);
    q = orbit_at(ray, s);
    float phi = s * ray.phi_end;
    vec2 cs_group = at_camera ? vec2(1.0, 0.0) : vec2(cos(phi), sin(phi));
    leaving = false;
    escaped = false;
    done = false;
    found = false;
    // Each turn looks at the end of the group from chord k: where no chord of the group can meet
    // an object, fall in or leave (group_clear), the ray moves there at once, to the point its last
    // chord would have reached, and the next group is twice as long; otherwise a group of more than
    // one chord is halved (the ray stays), and a single chord is tested as the chord-by-chord walk
    // tests it. Every turn evaluates the orbit once and tests one chord, whichever it does, so that
    // a group of pixels where some rays pass a group over and others test a chord pays for one
    // turn, not for both.
    // (at most two turns a chord: a chord passed over alone doubles the group, whose first chord
    // the next turn but one passes over or tests; and the first group's halvings)
    float group = ORBIT_GROUP_FIRST;
    for (int i = 0; i < 2 * MAX_SEGMENTS + 8; i++) {
        if (k >= ray.segments || leaving || escaped || done)
            break;
        vec3 on_orbit = orbit_point_at(ray, q, cs_group);
        vec3 a = k <= 0.0 ? u_camera_position : on_orbit;
        float k1 = min(k + group, ray.segments);
        float s1 = orbit_chord_end(ray, k1);
        vec2 q1 = orbit_at(ray, s1);
        float phi1 = s1 * ray.phi_end;
        vec2 cs1 = vec2(cos(phi1), sin(phi1));
        vec3 p1 = orbit_point_at(ray, q1, cs1);
        bool meets_nothing;
        bool passes = group_clear(ray, s, q, cs_group, s1, q1, cs1, meets_nothing);
        bool outside = outside_bounds(p1);
#ifdef ORBIT_SKY_UNPLACED
        // where the frame reads of a leaving ray only that it leaves: a group that meets nothing
        // and ends outside the bounding sphere ends the walk
        escaped = meets_nothing && outside;
#endif
        float chords = k1 - k;
        bool chord = !passes && !escaped && chords <= 1.0;
        // a leaving chord moves nothing: the ray stands at its start (k)
        leaving = chord && outside;
        bool tested = chord && !leaving;
        bool moves = passes || tested;
        // the orbit's values at the new end are taken before the chord's test, so that the old
        // ones are not live through it: where the chord meets an object (or falls in) the walk
        // ends here, and only k, which stays, says where (its values are found again from k)
        q = moves ? q1 : q;
        s = moves ? s1 : s;
        cs_group = moves ? cs1 : cs_group;
        found = tested && intersect_chord_meets(a, p1);
        done = found || (tested && captured(p1));
        // a chord with a hit (or that falls in) keeps its start: the ray stands at chord k
        k = moves && !done ? k1 : k;
        group = passes ? min(2.0 * chords, ORBIT_GROUP_MOST) : max(floor(0.5 * chords), 1.0);
        // at the turn's end (docs/PIPELINE.md, "Loops that end at a turn's end")
        if (k >= ray.segments || leaving || escaped || done)
            break;
    }
}
#endif

#ifdef ORBIT_WALK_PASS
// The walk pass: from the camera (u_orbit_resume = 0), or, where the finish lost the hit a walk
// stopped at (the orbit misses what the chord met), from that walk's chord's end.
uniform float u_orbit_resume;

void main()
{
    orbit_ray ray = orbit_ray_of();
    cull_prepare(ray);
    float k = 0.0;
    if (u_orbit_resume > 0.0) {
        bool done_before, leaving_before, escaped_before, found_before;
        orbit_walk_read(k, done_before, leaving_before, escaped_before, found_before);
        k = done_before ? k + 1.0 : k;
    }
    bool done, leaving, escaped, found;
    orbit_walk(ray, k, done, leaving, escaped, found);
    WRITE_TARGET0(orbit_walk_state(k, done, leaving, escaped, found));
}
#endif
