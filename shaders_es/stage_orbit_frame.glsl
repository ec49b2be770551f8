// render.method = orbit_table in one pass (render.pipeline = single): each pixel follows its orbit
// chord by chord (orbit_chord, as the orbit stage), tests every object of the scene against each
// chord (intersect_chord, as the intersection stage) and ends at the first hit, at the horizon or
// where it leaves the bounding sphere (as the termination stage). It writes what the multipass
// scheme leaves in the result textures: image and velocity, all the sky stage needs
// (FRAME_STATE undefined), or hit and position (FRAME_STATE 1), only when they are
// read, or where only the image is read the final colour itself (FRAME_COLOUR: the sky stage's
// sky_colour.glsl, in this pass). MAX_SEGMENTS is the scene's render.max_chords.
uniform vec3 u_capture_center;
uniform float u_capture_radius2;

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
void main()
{
    orbit_ray ray = orbit_ray_of();
    cull_prepare(ray);
    vec3 a = u_camera_position;
    vec3 hit_a = a;
    vec3 hit_b = a;
    vec3 b = a;
    vec2 q = vec2(1.0, 0.0);
    float s = 0.0;
    bool leaves = false;
    float hit_s_a = 0.0;
    float hit_s_b = 0.0;
    float hit_segment = 0.0;
    float steps = 0.0;
    float code = CODE_UNFINISHED;
    float end_key = NO_HIT;
    // The chord that leaves the bounding sphere ends where the orbit crosses it, found by Newton's
    // steps on the orbit (orbit_chord_from): once per ray, after the loop, rather than in a branch
    // of it that a group of pixels would take as often as any one of them leaves.
    bool leaving = false;
    vec3 leave_a = a;
    float leave_s = 0.0;
    float leave_k = 0.0;
    float leave_s1 = 0.0;
    vec2 leave_q1 = q;
    vec3 leave_from_bound = vec3(0.0);
    candidate best = candidate(NO_HIT, 0.0, -1.0, vec3(0.0), vec3(0.0));
    for (int i = 0; i < MAX_SEGMENTS; i++) {
        float k = float(i);
        if (k >= ray.segments || leaving)
            break;
        float s_a = s;
        float s1 = orbit_chord_end(ray, k + 1.0);
        vec2 q1 = orbit_at(ray, s1);
        vec3 p1 = orbit_point(ray, q1, s1);
        vec3 from_bound = p1 - u_bound_center;
        leaving = dot(from_bound, from_bound) >= u_bound_radius2;
        leave_a = a;
        leave_s = s_a;
        leave_k = k;
        leave_s1 = s1;
        leave_q1 = q1;
        leave_from_bound = from_bound;
        if (leaving)
            continue;
        q = q1;
        s = s1;
        b = p1;
        steps = k + 1.0;
        cull_phi_a = s_a * ray.phi_end;
        cull_phi_b = s * ray.phi_end;
        intersect_chord(a, b, k, best);
        hit_a = a;
        hit_b = b;
        hit_s_a = s_a;
        hit_s_b = s;
        hit_segment = k;
        vec3 from_mass = b - u_capture_center;
        bool captured = u_capture_radius2 > 0.0 && dot(from_mass, from_mass) <= u_capture_radius2;
        bool found = best.slot >= 0.0;
        bool ends = !found && captured;
        code = ends ? CODE_CAPTURED : code;
        end_key = ends ? steps : end_key;
        if (found || ends)
            break;
        a = b;
    }
    if (leaving) {
        // the leaving chord as the orbit stage makes it (orbit_chord_from): from its end outside
        // the sphere back to where the orbit crosses it, on the same values
        q = leave_q1;
        orbit_crossing(ray, leave_s, leave_s1, leave_from_bound, q, s);
        leaves = true;
        b = orbit_chord_point(ray, q, s, leaves);
        steps = leave_k + 1.0;
        cull_phi_a = leave_s * ray.phi_end;
        cull_phi_b = s * ray.phi_end;
        intersect_chord(leave_a, b, leave_k, best);
        hit_a = leave_a;
        hit_b = b;
        hit_s_a = leave_s;
        hit_s_b = s;
        hit_segment = leave_k;
        bool found = best.slot >= 0.0;
        code = found ? code : CODE_SKY;
        end_key = found ? end_key : steps;
    }
    // the final state again from (q, s), outside the loop: see the precision note in common.glsl
    vec3 end = orbit_chord_point(ray, q, s, leaves);
    // a ray that leaves looks the sky up along its direction at infinity (as the orbit stage)
    vec3 along_orbit = orbit_tangent(ray, q, s);
    vec3 escape = orbit_direction_at_infinity(ray);
    vec3 tangent = leaves ? escape : along_orbit;
    // a hit is found again on the orbit itself; a ray without one skips that (no pixel group of
    // the sky-only frame runs it)
    if (best.slot >= 0.0)
        orbit_refine_hit(ray, hit_s_a, hit_s_b, hit_segment, hit_a, hit_b, best);
    vec4 new_hit, new_image;
    intersect_shade(best, hit_a, hit_b, new_hit, new_image);
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
