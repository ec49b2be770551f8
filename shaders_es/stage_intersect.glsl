// Stage 3, ray-object intersection and local illumination (paper sections 3.3, 3.4): a batch of
// BATCH_SIZE objects against the current segment of every ray (batch 1 is the paper's crossbar of
// one pass per object). The C side lists the batch as BATCH_TESTS, one TEST_<PRIMITIVE>(slot) per
// object in scene order, and defines HAS_PRIM_<TYPE> for the types present, so the shader holds
// only the primitives of this batch. The depth key (segment index + fraction) orders hits along the
// curved ray; a closer hit replaces the stored one, in scene order, exactly as one pass per object
// would; the closest is shaded once.
#ifndef SINGLE_PASS
uniform sampler2D u_segment_start;
uniform sampler2D u_segment_end;
uniform sampler2D u_hit;
uniform sampler2D u_image;
uniform float u_segment_index;
#endif
// Per slot, five geometry vectors (which depends on the primitive, see src/render/stage_intersect.c)
// and five material vectors.
uniform vec4 u_geometry[5 * BATCH_SIZE];
uniform vec4 u_materials[5 * BATCH_SIZE];
#ifdef TEXTURED
uniform sampler2D u_textures[BATCH_SIZE];
// BATCH_TEXTURES lists SAMPLE_TEXTURE(slot) for the textured objects of the batch
// (the chosen slot's material is selected first: its emitter.zw are the sizes texture_wrapped takes)
#define SAMPLE_TEXTURE(n) { vec3 sampled = texture_wrapped(u_textures[n], uv, emitter.zw); \
                            texel = best.slot == float(n) ? sampled : texel; }
#endif

const float PI = 3.14159265358979;

#ifdef MOVING_OBJECTS
// Objects moving near light speed in flat space (docs/RELATIVITY.md): per slot beta, gamma and the
// rest frame's origin; zero velocity for the slots at rest. The C side wraps the test of a moving
// slot as MOVING_TEST(slot, TEST_<PRIMITIVE>(slot)): the segment's end events, Poincaré
// transformed into the object's rest frame, are tested against its rest-frame geometry; the
// fraction of a hit is the same in both frames (the transformation is affine along the photon).
uniform vec4 u_motion[2 * BATCH_SIZE];
#define MOTION(slot, k) u_motion[2 * (slot) + (k)]

// The event where the photon passed x on its straight path from the camera (scene time
// t_obs - |x - camera|), in the rest frame, relative to the frame origin.
vec3 rest_position(vec3 x, vec4 beta_gamma, vec4 origin)
{
    float t = u_observer_time - length(x - u_camera_position);
    vec3 r = x - origin.xyz;
    float g = beta_gamma.w;
    return r + (g * g / (g + 1.0) * dot(beta_gamma.xyz, r) - g * t) * beta_gamma.xyz;
}
#define MOVING_TEST_FULL(slot, test) { vec3 a_scene = a; vec3 b_scene = b; \
    { vec3 a = rest_position(a_scene, MOTION(slot, 0), MOTION(slot, 1)); \
      vec3 b = rest_position(b_scene, MOTION(slot, 0), MOTION(slot, 1)); test } }
#define MOVING_TEST(slot, test) MOVING_TEST_FULL(slot, test)
#endif

#define GEOMETRY(slot, k) u_geometry[5 * (slot) + (k)]
#define MATERIAL(slot, k) u_materials[5 * (slot) + (k)]

#ifdef HAS_PRIM_SPHERE
// g0 = centre, radius; g1 = texture reference axis; g2 = pole
// surface = the normal, from which sphere_uv finds the texture coordinates of the hit that is kept
bool object_sphere(vec3 a, vec3 b, vec4 g0, out float t, out vec3 normal, out vec3 surface)
{
    bool found = hit_sphere(a, b, g0.xyz, g0.w, t);
    vec3 p = mix(a, b, t);
    normal = (p - g0.xyz) / g0.w;
    surface = normal;
    return found;
}
#define TEST_SPHERE_FULL(slot) consider(object_sphere(a, b, GEOMETRY(slot, 0), t, normal, surface), \
                                        t, normal, surface, float(slot), best);
#define TEST_SPHERE(slot) TEST_SPHERE_FULL(slot)
#endif

#ifdef HAS_PRIM_TRIANGLE
// g0, g1, g2 = vertices; g3 = uv0, uv1; g4.xy = uv2
// surface.xy = the texture coordinates
bool object_triangle(vec3 a, vec3 b, vec4 g0, vec4 g1, vec4 g2, vec4 g3, vec4 g4, out float t, out vec3 normal,
                     out vec3 surface)
{
    vec2 bary;
    bool found = hit_triangle(a, b, g0.xyz, g1.xyz, g2.xyz, t, bary);
    normal = normalize(cross(g1.xyz - g0.xyz, g2.xyz - g0.xyz));
    vec2 uv = (1.0 - bary.x - bary.y) * g3.xy + bary.x * g3.zw + bary.y * g4.xy;
    surface = vec3(uv, 0.0);
    return found;
}
#define TEST_TRIANGLE_FULL(slot) consider(object_triangle(a, b, GEOMETRY(slot, 0), GEOMETRY(slot, 1), \
                                                          GEOMETRY(slot, 2), GEOMETRY(slot, 3), GEOMETRY(slot, 4), \
                                                          t, normal, surface), t, normal, surface, float(slot), best);
#define TEST_TRIANGLE(slot) TEST_TRIANGLE_FULL(slot)
#endif

#ifdef HAS_PRIM_DISK
// g0 = centre, outer radius; g1 = normal, inner radius; g2 = texture reference axis
// surface = the hit relative to the centre, from which disk_uv finds the texture coordinates
bool object_disk(vec3 a, vec3 b, vec4 g0, vec4 g1, out float t, out vec3 normal, out vec3 surface)
{
    bool found = hit_disk(a, b, g0.xyz, g1.xyz, g1.w, g0.w, t);
    surface = mix(a, b, t) - g0.xyz;
    normal = g1.xyz;
    return found;
}
#define TEST_DISK_FULL(slot) consider(object_disk(a, b, GEOMETRY(slot, 0), GEOMETRY(slot, 1), t, normal, surface), \
                                      t, normal, surface, float(slot), best);
#define TEST_DISK(slot) TEST_DISK_FULL(slot)
#endif

#ifdef HAS_PRIM_RECT
// g0 = centre; g1, g2 = half edges
// surface.xy = the texture coordinates
bool object_rect(vec3 a, vec3 b, vec4 g0, vec4 g1, vec4 g2, out float t, out vec3 normal, out vec3 surface)
{
    vec2 s;
    bool found = hit_rect(a, b, g0.xyz, g1.xyz, g2.xyz, t, s);
    normal = normalize(cross(g1.xyz, g2.xyz));
    vec2 uv = 0.5 * (s + 1.0);
    surface = vec3(uv, 0.0);
    return found;
}
#define TEST_RECT_FULL(slot) consider(object_rect(a, b, GEOMETRY(slot, 0), GEOMETRY(slot, 1), GEOMETRY(slot, 2), \
                                              t, normal, surface), t, normal, surface, float(slot), best);
#define TEST_RECT(slot) TEST_RECT_FULL(slot)
#endif

// The closest hit of the batch so far: fraction t, normal, surface (what its texture coordinates
// come from: candidate_surface); key = depth key; slot < 0: none. The coordinates of a sphere or
// a disk take an arctangent: found once for the hit that is kept, not for every test.
struct candidate {
    float key, t, slot;
    vec3 normal;
    vec3 surface;
};

// the segment index of the chord being tested (u_segment_index, or the single pass's loop)
float intersect_segment_index;

// Whether any test since chord_meets was last cleared found a hit (intersect_chord_meets).
bool chord_meets;

// Computed for every object, then selected: see the precision note in common.glsl. A test keeps
// the hit's depth key, fraction and object only; its normal and surface are found once, for the
// hit that is shaded (candidate_surface), not carried through every chord's tests.
void consider(bool found, float t, vec3 normal, vec3 surface, float slot, inout candidate best)
{
    chord_meets = chord_meets || found;
    float key = intersect_segment_index + t;
    bool closer = found && key < best.key;
    best.key = closer ? key : best.key;
    best.t = closer ? t : best.t;
    best.slot = closer ? slot : best.slot;
}

// The texture coordinates of a hit, as the reference's intersect_* functions give them
// (src/physics/intersect.c): on a sphere (g1: its texture's reference axis, g2: its pole) from the
// unit normal; on a disk (g0.w: outer radius; g1: normal, inner radius; g2: reference axis) from
// the hit relative to its centre, p; a flat object's are its test's own (surface.xy).
vec2 sphere_uv(vec3 normal, vec4 g1, vec4 g2)
{
    vec3 third = cross(g2.xyz, g1.xyz);
    return vec2(atan(dot(normal, third), dot(normal, g1.xyz)) / (2.0 * PI) + 0.5,
                acos(clamp(dot(normal, g2.xyz), -1.0, 1.0)) / PI);
}

vec2 disk_uv(vec3 p, vec4 g0, vec4 g1, vec4 g2)
{
    vec3 third = cross(g1.xyz, g2.xyz);
    return vec2((length(p) - g1.w) / max(g0.w - g1.w, 1e-6),
                atan(dot(p, third), dot(p, g2.xyz)) / (2.0 * PI) + 0.5);
}

// best's normal and surface: the chosen object's test again on chord a -> b, the chord on which
// best was found, on its geometry (and, for an object that moves, its motion), selected first as
// its material is: one test of each kind of primitive in the batch, each on the geometry selected
// among the slots of its kind (BATCH_SLOTS_<KIND>, src/render/stage_intersect.c), not one test for
// every object (a GPU's registers: cube_approach's frame on V3D 4.2 spilled 23 values with six
// tests here, none with one). The same arithmetic on the same values as the test that found it,
// so they are the ones that test computed. uv: its texture coordinates, from that test's surface
// and the geometry selected for it (sphere_uv, disk_uv): arctangents found once, for the hit shaded.
#define SELECT_SLOT(n) { bool chosen = best.slot == float(n); \
                         g0 = chosen ? GEOMETRY(n, 0) : g0; g1 = chosen ? GEOMETRY(n, 1) : g1; \
                         g2 = chosen ? GEOMETRY(n, 2) : g2; g3 = chosen ? GEOMETRY(n, 3) : g3; \
                         g4 = chosen ? GEOMETRY(n, 4) : g4; chosen_kind = chosen_kind || chosen; }
#define SELECT_MOVING(n) { bool chosen = best.slot == float(n); \
                           motion = chosen ? MOTION(n, 0) : motion; origin = chosen ? MOTION(n, 1) : origin; \
                           moves = moves || chosen; }
#define SURFACE_OF(kind_slots, test, kind_uv) g0 = g1 = g2 = g3 = g4 = vec4(0.0); chosen_kind = false; kind_slots \
    test; best.normal = chosen_kind ? normal : best.normal; best.surface = chosen_kind ? surface : best.surface; \
    { vec2 uv_of_kind = kind_uv; uv = chosen_kind ? uv_of_kind : uv; }

void candidate_surface(vec3 a, vec3 b, inout candidate best, out vec2 uv)
{
    uv = vec2(0.0);
    vec3 from = a;
    vec3 to = b;
#ifdef MOVING_OBJECTS
    // as MOVING_TEST_FULL: the chord's ends in the moving object's rest frame
    vec4 motion = vec4(0.0);
    vec4 origin = vec4(0.0);
    bool moves = false;
    BATCH_SLOTS_MOVING
    vec3 rest_from = rest_position(a, motion, origin);
    vec3 rest_to = rest_position(b, motion, origin);
    from = moves ? rest_from : a;
    to = moves ? rest_to : b;
#endif
    float t;
    vec3 normal;
    vec3 surface;
    vec4 g0, g1, g2, g3, g4;
    bool chosen_kind;
#ifdef HAS_PRIM_SPHERE
    SURFACE_OF(BATCH_SLOTS_SPHERE, object_sphere(from, to, g0, t, normal, surface), sphere_uv(surface, g1, g2))
#endif
#ifdef HAS_PRIM_DISK
    SURFACE_OF(BATCH_SLOTS_DISK, object_disk(from, to, g0, g1, t, normal, surface), disk_uv(surface, g0, g1, g2))
#endif
#ifdef HAS_PRIM_RECT
    SURFACE_OF(BATCH_SLOTS_RECT, object_rect(from, to, g0, g1, g2, t, normal, surface), surface.xy)
#endif
#ifdef HAS_PRIM_TRIANGLE
    SURFACE_OF(BATCH_SLOTS_TRIANGLE, object_triangle(from, to, g0, g1, g2, g3, g4, t, normal, surface), surface.xy)
#endif
}

#if defined(CHORD_CULL) || (defined(SINGLE_PASS) && defined(ORBIT_HITS))
// Each object's bounding ball and, for a flat one, its plane (object_bound.h): the same for every
// pixel, computed once a frame on the CPU in double (object_batch_set_uniforms), for the single
// passes' culls below.
uniform vec4 u_object_ball[BATCH_SIZE];   // centre, radius
uniform vec4 u_object_plane[BATCH_SIZE];  // a flat object's unit normal, 1; 0 for the others
#endif

#if defined(SINGLE_PASS) && defined(ORBIT_HITS)
// Where the chords of the single pass on exact orbits can meet an object (the single pass passes
// over a group of chords that can meet none: group_clear in stage_orbit_walk.glsl). Every chord
// of a ray joins two points of its orbit, which lies in the plane of e1 and e2 through the mass,
// at angles phi_a < phi_b about the mass (phi from e1 towards e2) less than half a turn apart:
// the chord stays in that plane, inside the wedge between the two angles. An object's bounding
// ball cuts the plane in a disc; where the ball misses the plane, or the disc lies outside the
// wedge, no chord of that wedge can meet the object. The balls are taken a little larger
// (ORBIT_CULL_MARGIN of their distance from the mass, src/render/stage_intersect.c) than the
// objects, and the discs wider (CULL_ANGLE_MARGIN of their distance: that angle seen from the
// mass) than a float rounding of the chords' points could move them. Each chord's own tests are
// not guarded by it: llvmpipe runs the body of an `if` for every pixel group whatever its
// condition, so such a guard only added its own arithmetic there (docs/PIPELINE.md).
// The disc is found at each test from the ray's e2 and two vectors an object, the same for every
// pixel (computed once a frame on the CPU in double): kept per ray, four floats an object stayed
// live through the whole walk, and made an exhibit's GPU spill (`make shader-stats`).
const float CULL_TURN = 6.28318530717959;
const float CULL_ANGLE_MARGIN = 1e-4;
const float CULL_MARGIN = 1e-4;          // of a plane's distances (ORBIT_CULL_MARGIN's for the balls)
uniform vec4 u_cull_ball[BATCH_SIZE];     // the ball's centre less the mass's centre (c), its radius
uniform vec4 u_cull_across[BATCH_SIZE];   // c x e1 (e1: from the mass to the camera), and e1 . c

// The disc object `slot`'s ball cuts from the ray's orbit plane: its centre (x, y), x along e1 and y
// along e2, its radius (< 0 where the ball misses the plane) and the centre's distance from the mass.
vec4 cull_disc_of(orbit_ray ray, int slot)
{
    vec4 ball = u_cull_ball[slot];
    vec4 across = u_cull_across[slot];
    float x = across.w;
    float y = dot(ray.e2, ball.xyz);
    float off_plane = dot(ray.e2, across.xyz);   // along e1 x e2
    float in_plane = sqrt(max(ball.w * ball.w - off_plane * off_plane, 0.0));
    float rho = sqrt(x * x + y * y);
    float none = -1.0;
    return vec4(x, y, abs(off_plane) <= ball.w ? in_plane : none, rho);
}

#ifdef ORBIT_WALK_PASS
// The walk's own pass (an exhibit's GPU): each disc found where it is tested, and met against the
// wedge and the ring in vector form, without an angle, so the loop keeps nothing per object.
void cull_prepare(orbit_ray ray)
{
}

// Whether the disc of object `slot` meets the wedge of the group (from phi_a, whose cosine and
// sine are ends.xy, to phi_b, ends.zw) and the ring r_in .. r_hi.
bool cull_disc_meets(orbit_ray ray, int slot, vec4 ends, float phi_a, float span, float r_in, float r_hi)
{
    vec4 disc = cull_disc_of(ray, slot);
    float x = disc.x;
    float y = disc.y;
    float in_plane = disc.z;
    float rho = disc.w;
    bool ring = rho + in_plane >= r_in && rho - in_plane <= r_hi;
    // the wedge is convex (less than half a turn): the disc meets it where its centre lies inside,
    // or within reach of either edge, the rays from the mass along the two ends
    float reach = in_plane + CULL_ANGLE_MARGIN * rho;
    float from_a = ends.x * y - ends.y * x;
    float to_b = x * ends.w - y * ends.z;
    float along_a = ends.x * x + ends.y * y;
    float along_b = ends.z * x + ends.w * y;
    bool inside = from_a >= 0.0 && to_b >= 0.0;
    float edge_a = along_a >= 0.0 ? abs(from_a) : rho;
    float edge_b = along_b >= 0.0 ? abs(to_b) : rho;
    bool wedge = span >= 0.5 * CULL_TURN || inside || edge_a <= reach || edge_b <= reach;
    return in_plane >= 0.0 && wedge && ring;
}
#else
// In the frame's pass (render.orbit_walk = inline, a CPU rasteriser's): each disc found once a ray,
// from the objects' own geometry, and kept as the angles its wedge spans and the radii its ring
// spans, which llvmpipe holds in its registers: a test is then a few comparisons (the discs of the
// walk's own pass, found at each test, made llvmpipe's frames slower).
const float CULL_MARGIN_BALL = 1e-4;      // ORBIT_CULL_MARGIN
float cull_start[BATCH_SIZE];   // per object: where its wedge starts, in [0, 2 pi)
float cull_width[BATCH_SIZE];   // its width (beyond a turn: every angle); < 0: misses the plane
float cull_rho_lo[BATCH_SIZE];  // its ring
float cull_rho_hi[BATCH_SIZE];
float cull_wedge_start;
float cull_wedge_width;
float cull_wedge_rho_lo;
float cull_wedge_rho_hi;

// The wedge and ring of the ball (centre, radius) about the mass in the orbit's plane.
void cull_wedge(orbit_ray ray, vec3 centre, float radius)
{
    vec3 from_mass = centre - u_model_center;
    float distance = length(from_mass);
    float r = radius + CULL_MARGIN_BALL * (distance + radius);
    vec3 normal = cross(ray.e1, ray.e2);
    float off_plane = dot(normal, from_mass);
    float x = dot(ray.e1, from_mass);
    float y = dot(ray.e2, from_mass);
    float in_plane = sqrt(max(r * r - off_plane * off_plane, 0.0));
    float rho = sqrt(x * x + y * y);
    float half_width = asin(min(in_plane / max(rho, 1e-30), 1.0)) + CULL_ANGLE_MARGIN;
    cull_wedge_start = mod(atan(y, x) - half_width, CULL_TURN);
    cull_wedge_width = abs(off_plane) > r ? -1.0 : rho <= in_plane ? 2.0 * CULL_TURN : 2.0 * half_width;
    cull_wedge_rho_lo = rho - in_plane;
    cull_wedge_rho_hi = rho + in_plane;
}

// Each object's wedge for this ray: its bounding ball's, found from its geometry by its kind of
// primitive (as object_bound.h bounds it). BATCH_WEDGES lists WEDGE_OF_<PRIMITIVE>(slot) for every
// object of the batch (stage_intersect.c).
#define CULL_KEEP(n) cull_start[n] = cull_wedge_start; cull_width[n] = cull_wedge_width; \
                     cull_rho_lo[n] = cull_wedge_rho_lo; cull_rho_hi[n] = cull_wedge_rho_hi;
#define WEDGE_OF_SPHERE(n) { vec4 g0 = GEOMETRY(n, 0); cull_wedge(ray, g0.xyz, g0.w); CULL_KEEP(n) }
#define WEDGE_OF_DISK(n) WEDGE_OF_SPHERE(n)
#define WEDGE_OF_RECT(n) { vec4 g0 = GEOMETRY(n, 0); vec3 g1 = GEOMETRY(n, 1).xyz, g2 = GEOMETRY(n, 2).xyz; \
                           cull_wedge(ray, g0.xyz, max(length(g1 + g2), length(g1 - g2))); CULL_KEEP(n) }
#define WEDGE_OF_TRIANGLE(n) { vec3 v0 = GEOMETRY(n, 0).xyz, v1 = GEOMETRY(n, 1).xyz, v2 = GEOMETRY(n, 2).xyz; \
                               vec3 c = (v0 + v1 + v2) / 3.0; \
                               cull_wedge(ray, c, max(length(v0 - c), max(length(v1 - c), length(v2 - c)))); \
                               CULL_KEEP(n) }
void cull_prepare(orbit_ray ray)
{
    BATCH_WEDGES
}

bool cull_disc_meets(orbit_ray ray, int slot, vec4 ends, float phi_a, float span, float r_in, float r_hi)
{
    float from_start = mod(phi_a - cull_start[slot], CULL_TURN);
    bool overlaps = from_start <= cull_width[slot] || from_start + span >= CULL_TURN;
    bool wedge = span >= 0.5 * CULL_TURN || (cull_width[slot] >= 0.0 && overlaps);
    bool ring = cull_rho_hi[slot] >= r_in && cull_rho_lo[slot] <= r_hi;
    return wedge && ring;
}
#endif

// A group of chords, whose ends all lie at angles phi_a .. phi_b (span = phi_b - phi_a) and at
// radii r_lo .. r_hi from the mass, where (cos, sin) of phi_a and phi_b are ends.xy and .zw: can
// any of its chords meet object `slot`? Each chord joins two such ends, so it stays inside the
// wedge, at radii of at least r_in = r_lo cos((phi_b - phi_a) / 2), and on the side of a plane that
// holds every point of the region: the object is out of reach where its disc misses the wedge or
// that ring, or where a flat object's plane leaves the whole region on one side (the signed
// distance, linear in the point, is extreme at a corner of the region or where the outer arc
// faces the plane's normal (A, B): where that direction lies between the two ends, by the signs of
// their cross products with it; a group of half a turn or more may face it anywhere).
bool cull_group_meets(orbit_ray ray, int slot, bool flat_object, vec4 ends, float phi_a, float span, float r_lo,
                      float r_in, float r_hi)
{
    // a flat object's plane against the region
    vec3 n = flat_object ? u_object_plane[slot].xyz : vec3(0.0);
    float along_e1 = dot(n, ray.e1);
    float along_e2 = dot(n, ray.e2);
    vec4 plane = vec4(dot(n, u_model_center - u_object_ball[slot].xyz), along_e1, along_e2,
                      sqrt(along_e1 * along_e1 + along_e2 * along_e2));
    float across_a = ends.x * along_e2 - ends.y * along_e1;
    float across_b = along_e1 * ends.w - along_e2 * ends.z;
    bool narrow = span < 0.5 * CULL_TURN;
    bool faces = !narrow || (across_a >= 0.0 && across_b >= 0.0);
    bool turns_away = !narrow || (across_a <= 0.0 && across_b <= 0.0);
    float f_a = plane.y * ends.x + plane.z * ends.y;
    float f_b = plane.y * ends.z + plane.z * ends.w;
    float f_max = faces ? plane.w : max(f_a, f_b);
    float f_min = turns_away ? -plane.w : min(f_a, f_b);
    float d_lo = plane.x + min(r_lo * f_min, r_hi * f_min);
    float d_hi = plane.x + max(r_lo * f_max, r_hi * f_max);
    float margin = CULL_MARGIN * (abs(plane.x) + r_hi * plane.w);
    bool crosses = d_lo <= margin && d_hi >= -margin;
    return cull_disc_meets(ray, slot, ends, phi_a, span, r_in, r_hi) && crosses;
}

// Whether a group of chords with ends as cull_group_meets takes them can meet no object of the
// batch.
// BATCH_GROUP_CULLS lists GROUP_MEETS(slot, flat) for every object of the batch (stage_intersect.c).
#define GROUP_MEETS(n, flat_object) meets = meets || cull_group_meets(ray, n, flat_object, ends, phi_a, span, r_lo, \
                                                                      r_in, r_hi);
bool cull_group_clear(orbit_ray ray, vec4 ends, float phi_a, float span, float r_lo, float r_hi)
{
    bool meets = false;
    // the nearest a chord of the group comes to the mass: the same for every object
    float r_in = span < 0.5 * CULL_TURN ? r_lo * cos(0.5 * span) : 0.0;
    BATCH_GROUP_CULLS
    return !meets;
}
#endif

#ifdef CHORD_CULL
// Which chords of the integrated single pass (stage_frame.glsl) may meet an object: each object
// lies inside a ball (a sphere or disk: its own; a rectangle: around its centre, to its corners; a
// triangle: around its centroid, to its farthest corner), and a flat one within its plane. A chord
// a -> b lies inside the ball of radius |b - a| / 2 about its midpoint, so it can meet the object
// only where that ball meets the object's ball and, for a flat object, its plane. The exact tests
// report a hit only at a point of the chord inside the object, to float roundings (a grazing
// sphere's square root can move it by about |a - c|^2 / r times a rounding): the balls are taken
// CHORD_CULL_MARGIN of their reach (relative to the object's radius) and CHORD_CULL_POSITION_MARGIN
// of the points' coordinates larger, hundreds of times what those roundings can move a point. An
// object that moves comes near every chord: a batch with one (MOVING_OBJECTS) culls none.
// The balls and planes are the frame's, the same for every pixel: computed once on the CPU
// (chord_cull_pack, src/render/stage_intersect.c), not in every pixel. Why: computed in the shader,
// ten floats an object stayed live across the whole loop, more than the register file of an
// exhibit's GPU holds; as uniforms, V3D's and Bifrost's compilers read them where they are used
// (`make shader-stats`: the kiosk's lorenz frame went from 82 to 46 spills on V3D 4.2, from 24 to 7
// on Mali-G52). On a CPU rasteriser they are copied once a pixel (chord_cull_prepare) and used from
// the copies: llvmpipe, which loads a uniform from memory at each use, keeps the copies in its
// registers (read at each use, its frame took twice as long). A GPU's compiler reads the uniforms
// themselves (CHORD_CULL_UNIFORMS): Bifrost keeps the copies in memory, which cost the kiosk's lorenz
// frame on Mali-G52 a third of its load/store cycles (150 -> 105); V3D sees through either.
const float CHORD_CULL_MARGIN = 1e-3;
const float CHORD_CULL_POSITION_MARGIN = 1e-5;
uniform vec2 u_chord_scale[BATCH_SIZE];   // 1 / radius, the centre's position margin
#ifdef CHORD_CULL_UNIFORMS
#define chord_ball u_object_ball
#define chord_plane u_object_plane
#define chord_scale u_chord_scale

void chord_cull_prepare()
{
}
#else
vec4 chord_ball[BATCH_SIZE];
vec4 chord_plane[BATCH_SIZE];
vec2 chord_scale[BATCH_SIZE];

void chord_cull_prepare()
{
    for (int n = 0; n < BATCH_SIZE; n++) {
        chord_ball[n] = u_object_ball[n];
        chord_plane[n] = u_object_plane[n];
        chord_scale[n] = u_chord_scale[n];
    }
}
#endif

// Whether a chord about mid, of half length half_length, comes near the object of this ball, plane
// and scales.
bool chord_near_object(vec4 ball_of, vec4 plane_of, vec2 scale, vec3 mid, float half_length, float mid_margin)
{
    vec3 from_centre = mid - ball_of.xyz;
    float reach = ball_of.w + half_length;
    float margin = CHORD_CULL_MARGIN * reach * (1.0 + reach * scale.x) + mid_margin + scale.y;
    float within = reach + margin;
    bool ball = dot(from_centre, from_centre) <= within * within;
    bool plane = plane_of.w == 0.0 || abs(dot(from_centre, plane_of.xyz)) <= half_length + margin;
    return ball && plane;
}

// Whether chord a -> b comes near an object of the batch: where it does not, it can meet none.
bool chord_near(vec3 a, vec3 b)
{
    vec3 mid = 0.5 * (a + b);
    float half_length = 0.5 * length(b - a);
    float mid_margin = CHORD_CULL_POSITION_MARGIN * (abs(mid.x) + abs(mid.y) + abs(mid.z));
    bool near = false;
#ifdef MOVING_OBJECTS
    near = true;
#else
    for (int n = 0; n < BATCH_SIZE; n++)
        near = near || chord_near_object(chord_ball[n], chord_plane[n], chord_scale[n], mid, half_length, mid_margin);
#endif
    return near;
}
#else
void chord_cull_prepare()
{
}

// Every chord may meet an object.
bool chord_near(vec3 a, vec3 b)
{
    return true;
}
#endif

// Every object of the batch against chord a -> b of segment `segment`: best keeps the closest hit
// (a closer one replaces it, in scene order, exactly as one pass per object would).
void intersect_chord(vec3 a, vec3 b, float segment, inout candidate best)
{
    intersect_segment_index = segment;
    float t;
    vec3 normal;
    vec3 surface;
    BATCH_TESTS
}

#if defined(ORBIT_HITS) || defined(SINGLE_PASS)
// Whether any object of the batch meets chord a -> b: what intersect_chord's best.slot >= 0 would
// say (consider() notes it in chord_meets), the closest hit's depth, fraction and object left unread
// for the compiler to drop (the orbit walk and the integrated single pass's loop need only whether
// to stop; the hit is found after the loop). The same tests: each finds a hit only at a fraction t
// in [0, 1] (prim_*.glsl), whose depth key consider() always takes over NO_HIT. Carrying less, the
// loops spill less on V3D and Bifrost (`make shader-stats`).
bool intersect_chord_meets(vec3 a, vec3 b)
{
    candidate best = candidate(NO_HIT, 0.0, -1.0, vec3(0.0), vec3(0.0));
    float t;
    vec3 normal;
    vec3 surface;
    chord_meets = false;
    BATCH_TESTS
    return chord_meets;
}
#endif

// The hit record and the shaded colour (object id in alpha) of candidate best on chord a -> b.
void intersect_shade(candidate best, vec3 a, vec3 b, out vec4 new_hit, out vec4 new_image)
{
    vec2 uv;
    candidate_surface(a, b, best, uv);
    // the chosen object's material
    vec4 color_checker = MATERIAL(0, 0), emission_id = MATERIAL(0, 1), factors = MATERIAL(0, 2),
         checker_color = MATERIAL(0, 3), emitter = MATERIAL(0, 4);
#ifdef MOVING_OBJECTS
    surface_motion = MOTION(0, 0);
    vec4 surface_origin = MOTION(0, 1);
#endif
    for (int i = 1; i < BATCH_SIZE; i++) {
        bool chosen = best.slot == float(i);
#ifdef MOVING_OBJECTS
        surface_motion = chosen ? MOTION(i, 0) : surface_motion;
        surface_origin = chosen ? MOTION(i, 1) : surface_origin;
#endif
        color_checker = chosen ? MATERIAL(i, 0) : color_checker;
        emission_id = chosen ? MATERIAL(i, 1) : emission_id;
        factors = chosen ? MATERIAL(i, 2) : factors;
        checker_color = chosen ? MATERIAL(i, 3) : checker_color;
        emitter = chosen ? MATERIAL(i, 4) : emitter;
    }
    vec3 texel = vec3(1.0);
#ifdef TEXTURED
    BATCH_TEXTURES
#endif
    vec3 p = mix(a, b, best.t);
#ifdef DOPPLER_COLOUR
    surface_emission_temperature = emitter.x;
#ifdef ACCRETION
    surface_accretion_inner = emitter.y;
    // a disk's surface is the hit relative to its centre (object_disk)
    surface_accretion_radius = length(best.surface);
#endif
#endif
#ifdef CLOCKS
    // the clock shows its proper time when the light left it: scene time t_obs - |p - camera| on
    // the straight ray, gamma (t - beta.(p - origin)) in its rest frame
    float emitted = u_observer_time - length(p - u_camera_position);
#ifdef MOVING_OBJECTS
    float proper = surface_motion.w * (emitted - dot(surface_motion.xyz, p - surface_origin.xyz));
#else
    float proper = emitted;
#endif
    float period = checker_color.w;
    surface_clock_turns = period > 0.0 ? proper / period : -1.0;
#endif
    surface_material m = surface_material(color_checker.rgb * texel, color_checker.w, emission_id.rgb, factors,
                                        checker_color.rgb);
    new_hit = vec4(p, best.key);
    new_image = vec4(shade(p, best.normal, uv, normalize(b - a), m), emission_id.w);
}

#ifdef ORBIT_HITS
// Hits on the orbit, not on its chord (render.method = orbit_table; orbit_table.glsl comes first):
// a hit found on chord a -> b, which runs from fraction s_a to s_b of the ray's orbit, is found
// again on the two halves of that stretch of orbit, split in its middle, ORBIT_HIT_LEVELS times:
// the chord that carries the hit halves at every level and its distance from the orbit falls
// fourfold. Every object is tested again on the first half, so a hit that the orbit reaches first
// is the one kept; where the first half meets nothing, the hit lies on the second, which the next
// level splits in turn, untested: one half tested a level, not two. A level asks only whether the
// half meets anything (intersect_chord_meets), carrying no depth, fraction or object through the
// loop; the closest hit is found once, on the last chord, after the last level: the hit a level's
// full test would have kept there (V3D 4.2 spilled 29 values with a full test a level, 14 with
// this). Where the last chord meets nothing (a chord that crossed an object, or an edge of one,
// that the orbit passes by), the hit is lost: its caller keeps no hit there and the ray goes on
// from the chord's end. The split is never at the hit itself: the orbit there lies within the
// chord's error of the object's surface, often closer than a float rounding, where both halves
// could miss a surface that the orbit does cross. Used by the intersection stage and by the single
// pass alike, with the same arithmetic, so both find the same hits.
const int ORBIT_HIT_LEVELS = 4;

// best: the hit on chord a -> b (segment `segment`); a and b become the ends of the short chord
// that carries the hit, and best its fraction, normal and uv there (its depth key is kept); lost:
// whether the orbit misses what the chord met; halves: which half each level kept, 2^level for a
// second half (orbit_hit_chord finds the short chord again from them).
void orbit_refine_hit(orbit_ray ray, float s_a, float s_b, float segment, inout vec3 a, inout vec3 b,
                      inout candidate best, out bool lost, out float halves)
{
    float lo = s_a;
    float hi = s_b;
    float key = best.key;
    float level_bit = 1.0;
    halves = 0.0;
    for (int level = 0; level < ORBIT_HIT_LEVELS; level++) {
        float s_m = lo + 0.5 * (hi - lo);
        vec2 q = orbit_at(ray, s_m);
        vec3 m = orbit_point(ray, q, s_m);
        bool first_half = intersect_chord_meets(a, m);
        halves += first_half ? 0.0 : level_bit;
        level_bit *= 2.0;
        float new_lo = first_half ? lo : s_m;
        float new_hi = first_half ? s_m : hi;
        vec3 new_a = first_half ? a : m;
        vec3 new_b = first_half ? m : b;
        lo = new_lo;
        hi = new_hi;
        a = new_a;
        b = new_b;
        // at the turn's end (docs/PIPELINE.md, "Loops that end at a turn's end")
        if (level == ORBIT_HIT_LEVELS - 1)
            break;
    }
    // the closest hit on the last chord: where it meets nothing, the hit is lost
    candidate last = candidate(NO_HIT, 0.0, -1.0, vec3(0.0), vec3(0.0));
    intersect_chord(a, b, segment, last);
    lost = last.slot < 0.0;
    best = last;
    best.key = key;
}

#ifdef HIT_ENDS
// The short chord a -> b that orbit_refine_hit ended on, from the halves it kept: the same
// fractions of the orbit, and its points there found by the same arithmetic (an end that no level
// moved is the segment's own, as there).
void orbit_hit_chord(orbit_ray ray, float s_a, float s_b, float halves, inout vec3 a, inout vec3 b)
{
    float lo = s_a;
    float hi = s_b;
    bool moved_a = false;
    bool moved_b = false;
    float rest = halves;
    for (int level = 0; level < ORBIT_HIT_LEVELS; level++) {
        float s_m = lo + 0.5 * (hi - lo);
        bool second_half = rest - 2.0 * floor(0.5 * rest) >= 0.5;
        rest = floor(0.5 * rest);
        lo = second_half ? s_m : lo;
        hi = second_half ? hi : s_m;
        moved_a = moved_a || second_half;
        moved_b = moved_b || !second_half;
    }
    vec3 at_lo = orbit_point(ray, orbit_at(ray, lo), lo);
    vec3 at_hi = orbit_point(ray, orbit_at(ray, hi), hi);
    a = moved_a ? at_lo : a;
    b = moved_b ? at_hi : b;
}
#endif
#endif

#ifndef SINGLE_PASS
// The segment's chord runs from fraction s_a of the orbit to s_b (the orbit stage's own arithmetic,
// again).
#ifdef ORBIT_HITS
void orbit_segment(orbit_ray ray, out float s_a, out float s_b)
{
    s_a = orbit_chord_end(ray, u_segment_index);
    vec2 q_b;
    bool leaves;
    orbit_chord_from(ray, s_a, u_segment_index, q_b, s_b, leaves);
}
#endif

#if defined(HIT_CHORD)
// The hit shaded in a pass of its own (render.hit_shading = separate, src/render/stage_intersect.c),
// first: the closest hit on the segment's chord, nearer than the ray's hit so far: its depth key,
// fraction and object (< 0: none) in u_hit_found's layout. On exact orbits the next pass finds it
// again on the orbit; elsewhere this is the hit.
void main()
{
    vec4 hit = fetch(u_hit);
    vec3 a = fetch(u_segment_start).xyz;
    vec3 b = fetch(u_segment_end).xyz;
    candidate best = candidate(hit.w, 0.0, -1.0, vec3(0.0), vec3(0.0));
    intersect_chord(a, b, u_segment_index, best);
    WRITE_TARGET0(vec4(best.key, best.t, best.slot, 0.0));
}
#elif defined(HIT_ORBIT) || defined(HIT_ENDS)
uniform sampler2D u_hit_found;

// What the pass before found on the segment, the segment's chord a -> b, the ray's orbit and the
// fractions of it the chord runs between.
void found_on_segment(out vec4 found, out vec3 a, out vec3 b, out orbit_ray ray, out float s_a, out float s_b)
{
    found = fetch(u_hit_found);
    a = fetch(u_segment_start).xyz;
    b = fetch(u_segment_end).xyz;
    ray = orbit_ray_of();
    orbit_segment(ray, s_a, s_b);
}

#ifdef HIT_ORBIT
// Second, on exact orbits: the chord's hit found again on the orbit (orbit_refine_hit), with the
// halves that lead to its short chord; object < 0 where the chord met nothing or the orbit misses it.
void main()
{
    vec4 found_on_chord;
    vec3 a, b;
    orbit_ray ray;
    float s_a, s_b;
    found_on_segment(found_on_chord, a, b, ray, s_a, s_b);
    candidate best = candidate(found_on_chord.x, found_on_chord.y, found_on_chord.z, vec3(0.0), vec3(0.0));
    bool lost;
    float halves;
    orbit_refine_hit(ray, s_a, s_b, u_segment_index, a, b, best, lost, halves);
    bool found = found_on_chord.z >= 0.0 && !lost;
    WRITE_TARGET0(found ? vec4(best.key, best.t, best.slot, halves) : vec4(0.0, 0.0, -1.0, 0.0));
}
#else
// Third, on exact orbits: the short chord that carries the hit (orbit_hit_chord), its start in one
// target and its end in the other. The finding and the shading in one pass were too large for VC4's
// register allocator; each of these passes fits (`make shader-stats`).
void main()
{
    vec4 found_here;
    vec3 a, b;
    orbit_ray ray;
    float s_a, s_b;
    found_on_segment(found_here, a, b, ray, s_a, s_b);
    orbit_hit_chord(ray, s_a, s_b, found_here.w, a, b);
    WRITE_TARGET0(vec4(a, 0.0));
    WRITE_TARGET1(vec4(b, 0.0));
}
#endif
#elif defined(HIT_SHADE)
// Last: the hit found shaded, as the stage in one pass shades it below, on the chord that carries it
// (the segment's, or on exact orbits the short chord of the pass before).
uniform sampler2D u_hit_found;
uniform sampler2D u_hit_chord_start;
uniform sampler2D u_hit_chord_end;
void main()
{
    vec4 hit = fetch(u_hit);
    vec4 image = fetch(u_image);
    vec4 found_here = fetch(u_hit_found);
    vec3 a = fetch(u_hit_chord_start).xyz;
    vec3 b = fetch(u_hit_chord_end).xyz;
    candidate best = candidate(found_here.x, found_here.y, found_here.z, vec3(0.0), vec3(0.0));
    vec4 new_hit, new_image;
    intersect_shade(best, a, b, new_hit, new_image);
    bool found = best.slot >= 0.0;
    WRITE_TARGET0(found ? new_hit : hit);
    WRITE_TARGET1(found ? new_image : image);
}
#else
// The intersection stage in one pass: find the closest hit of the batch, and shade it.
void main()
{
    vec4 hit = fetch(u_hit);
    vec4 image = fetch(u_image);
    vec3 a = fetch(u_segment_start).xyz;
    vec3 b = fetch(u_segment_end).xyz;
    candidate best = candidate(hit.w, 0.0, -1.0, vec3(0.0), vec3(0.0));
    intersect_chord(a, b, u_segment_index, best);
    bool found = best.slot >= 0.0;
#ifdef ORBIT_HITS
    // the hit is found again on the orbit
    orbit_ray ray = orbit_ray_of();
    float s_a, s_b;
    orbit_segment(ray, s_a, s_b);
    bool lost;
    float halves;
    orbit_refine_hit(ray, s_a, s_b, u_segment_index, a, b, best, lost, halves);
    // a hit the orbit misses is not kept: the ray goes on (or ends at the chord's end)
    found = found && !lost;
#endif
    // computed before the select: see the precision note in common.glsl
    vec4 new_hit, new_image;
    intersect_shade(best, a, b, new_hit, new_image);
    hit = found ? new_hit : hit;
    image = found ? new_image : image;
    WRITE_TARGET0(hit);
    WRITE_TARGET1(image);
}
#endif
#endif
