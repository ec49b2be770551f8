// render.method = orbit_table in one pass, where every object is flat and lies in a plane through
// the mass (an accretion disk about the hole; chosen by orbit_crossings_apply in
// src/render/orbit_crossings.c). A photon orbit runs in a plane through the mass, so it meets
// such a plane only on the line the two planes share: at the angles phi_0 + j pi about the mass,
// phi_0 where cos(phi) e1 + sin(phi) e2 is across the plane's normal. There the orbit's point comes
// from the table exactly, and the object's own test, on a short chord across the crossing, says
// whether the orbit passes through the object. The first crossing inside an object is the hit: a
// few table lookups a pixel, where stage_orbit_frame.glsl follows the orbit chord by chord. Nothing
// else can end the ray first: the C side checked that the bounding sphere is about the mass and
// holds the camera and every object (so every point of the orbit up to a hit lies inside it), and
// a crossing inside the capture sphere is none. It writes the targets stage_orbit_frame.glsl writes,
// with the hit's own point where the walk writes the end of the chord that carries it (position,
// and for --dump the final position), its depth the orbit's fraction there in chords, and w of the
// velocity target the fraction of the orbit reached (1 for a ray without a hit, as the walk's
// ORBIT_NOTHING_TO_MEET).
uniform vec3 u_crossing_normal[BATCH_SIZE];   // each object's unit normal

// Half the length of the chord across a crossing, relative to its distance from the mass: long
// enough to cross the object's plane where a float rounding puts the orbit's point beside it,
// short enough that it strays from the orbit by about CROSSING_CHORD^2 / 2 of that distance.
const float CROSSING_CHORD = 1e-3;
// Half-turns of the longest orbit: one that winds next to the critical angle sweeps about
// ln(1 / 1e-7) + 2 pi radians, under 8 half-turns (test_orbit_crossings checks the table's).
const int MAX_PLANE_CROSSINGS = 16;
const float HALF_TURN = 3.14159265358979;

// The first angle in [0, pi] where the orbit's plane meets the plane through the mass with this
// normal; beyond any orbit's end where the two planes are one (no crossing to speak of, as a
// chord inside a disk's plane meets nothing).
float first_crossing(orbit_ray ray, vec3 normal)
{
    float across_e1 = dot(normal, ray.e1);
    float across_e2 = dot(normal, ray.e2);
    // the angle of (across_e2, -across_e1), or of its opposite, whichever lies in the upper half
    // plane (accurate_angle, common.glsl: Mesa's atan is off by up to 3.3e-6 rad)
    float up = abs(across_e1);
    float right = across_e1 <= 0.0 ? across_e2 : -across_e2;
    float phi = accurate_angle(up, right);
    bool same_plane = across_e1 == 0.0 && across_e2 == 0.0;
    float never = 1e30;
    return same_plane ? never : phi;
}

void main()
{
    orbit_ray ray = orbit_ray_of();
    float first[BATCH_SIZE];
    float never = 1e30;
    float earliest = never;
    for (int n = 0; n < BATCH_SIZE; n++) {
        first[n] = first_crossing(ray, u_crossing_normal[n]);
        earliest = min(earliest, first[n]);
    }
    candidate best = candidate(NO_HIT, 0.0, -1.0, vec3(0.0), vec3(0.0));
    vec3 hit_a = u_camera_position;
    vec3 hit_b = hit_a;
    float hit_s = 0.0;
    // Crossing j of every object, then crossing j + 1: the next lie a half-turn further on, so a
    // hit found among crossings j ends the search. The depth key of a hit is its angle (plus the
    // fraction on its short chord), so the nearest along the orbit is kept, in scene order on a tie.
    for (int j = 0; j < MAX_PLANE_CROSSINGS; j++) {
        float turn = float(j) * HALF_TURN;
        for (int n = 0; n < BATCH_SIZE; n++) {
            float phi = first[n] + turn;
            bool on_orbit = phi <= ray.phi_end;
            float s = clamp(phi / max(ray.phi_end, 1e-30), 0.0, 1.0);
            vec2 q = orbit_at(ray, s);
            vec3 p = orbit_point(ray, q, s);
            vec3 along = orbit_tangent(ray, q, s);
            float half_chord = CROSSING_CHORD / q.x;
            vec3 a = p - half_chord * along;
            vec3 b = p + half_chord * along;
            candidate trial = best;
            intersect_chord(a, b, phi, trial);
            bool closer = on_orbit && !captured(p) && trial.slot >= 0.0 && trial.key < best.key;
            best = closer ? trial : best;
            hit_a = closer ? a : hit_a;
            hit_b = closer ? b : hit_b;
            hit_s = closer ? s : hit_s;
        }
        // at the turn's end (docs/PIPELINE.md, "Loops that end at a turn's end")
        if (best.slot >= 0.0 || earliest + turn + HALF_TURN > ray.phi_end)
            break;
    }
    bool found = best.slot >= 0.0;
    // without a hit, each ray's outcome is its side of the critical angle, its sky along its
    // direction at infinity (as stage_orbit_frame.glsl's ORBIT_NOTHING_TO_MEET)
    bool escapes = ray.side_first < 0.5;
    vec3 escape = orbit_direction_at_infinity(ray);
#ifdef FRAME_COLOUR
    // a captured ray is black whatever its direction
    vec3 direction = escape;
#else
    vec2 q_end = orbit_at(ray, 1.0);
    vec3 fallen = orbit_tangent(ray, q_end, 1.0);
    vec3 direction = escapes ? escape : fallen;
#endif
    vec4 end_image = vec4(0.0, 0.0, 0.0, escapes ? CODE_SKY : CODE_CAPTURED);
    // computed for every ray, then selected: see the precision note in common.glsl (shaded inside
    // an `if`, llvmpipe's sky directions came out a hundred times less precise)
    vec4 new_hit, new_image;
    intersect_shade(best, hit_a, hit_b, new_hit, new_image);
    // the depth of a hit: the orbit's fraction there, in its chords (docs/DUMP.md)
    float depth = hit_s * ray.segments;
#ifdef FRAME_STATE
    // a ray without a hit ends where the chord walk ends it: at the first of its chords' ends
    // inside the capture sphere, or where the orbit crosses the bounding sphere
    float s_end = 0.0;
    vec3 end = u_camera_position;
    float steps = 0.0;
    for (int k = 0; k < MAX_SEGMENTS; k++) {
        if (found || float(k) >= ray.segments)
            break;
        vec2 q;
        float s;
        bool leaves;
        orbit_chord_from(ray, s_end, float(k), q, s, leaves);
        end = orbit_chord_point(ray, q, s, leaves);
        s_end = s;
        steps = float(k) + 1.0;
        // at the turn's end (docs/PIPELINE.md, "Loops that end at a turn's end")
        if (leaves || captured(end))
            break;
    }
    WRITE_TARGET0(found ? vec4(new_hit.xyz, depth) : vec4(end, steps));
    WRITE_TARGET1(found ? vec4(new_hit.xyz, depth) : vec4(end, steps));
#elif defined(FRAME_COLOUR)
    // only the image is read: the sky stage's final colour, here (stage_frame.c)
    WRITE_FRAME_COLOUR(found ? new_image : end_image, direction);
#else
    WRITE_TARGET0(found ? new_image : end_image);
    WRITE_TARGET1(vec4(found ? normalize(hit_b - hit_a) : direction, found ? hit_s : 1.0));
#endif
}
