// Stage 2, ray integration (paper sections 3.2 and 4.2): STEPS_PER_PASS steps of eq. (1) unrolled
// in one shader, of fixed size or adaptive (the ray's step lives in velocity.w). A ray stops moving once it has a hit, has left the bounding sphere, has been
// captured, or its state stopped being finite; the last finite state is kept.
#ifndef SINGLE_PASS
uniform sampler2D u_ray_position;
uniform sampler2D u_ray_velocity;
uniform sampler2D u_hit;
#endif

const float FINITE_LIMIT2 = 1.0e30;   // |x|^2 and |v|^2 beyond this count as overflow

bool travelling(vec3 x)
{
    return inside_bounds(x) && !captured(x);
}

// Finite and not overflowing; NaN fails every comparison, so it fails this one too.
bool finite_state(vec3 x, vec3 v)
{
    return dot(x, x) < FINITE_LIMIT2 && dot(v, v) < FINITE_LIMIT2;
}

// The same after a step from x0, which must also stay shorter than the bounding sphere's
// diameter: a longer one crosses the whole scene in one step, where the field is far too strong
// for the step (a Yukawa zeta of -1e18), and its chord would meet whatever lies across the scene.
// The CPU reference, whose steps adapt, fails such rays too.
bool finite_step(vec3 x0, vec3 x, vec3 v)
{
    vec3 d = x - x0;
    return finite_state(x, v) && dot(d, d) < 4.0 * u_bound_radius2;
}

// The objects' bounds that steps grow away from (STEP_FAR, below: their count), and where the
// steps do not grow, nothing. As the chord cull's balls (stage_intersect.glsl, chord_cull_prepare):
// a CPU rasteriser, which loads a uniform from memory at each use, takes copies once a pixel
// (FAR_REACH_COPIES; llvmpipe's lorenz frame took 0.33 s with the uniforms read at each step, 0.26 s
// with copies); a GPU's compiler reads the uniforms where they are used.
#ifdef STEP_FAR
#if STEP_FAR > 0
uniform vec4 u_reach_ball[STEP_FAR];    // a bound's centre and radius
uniform vec4 u_reach_normal[STEP_FAR];  // a flat bound's unit normal; 0 for a ball alone
#ifdef FAR_REACH_COPIES
#define FAR_REACH_COPIED 1
vec4 reach_ball[STEP_FAR];
vec4 reach_normal[STEP_FAR];

void far_reach_prepare()
{
    for (int n = 0; n < STEP_FAR; n++) {
        reach_ball[n] = u_reach_ball[n];
        reach_normal[n] = u_reach_normal[n];
    }
}
#else
#define reach_ball u_reach_ball
#define reach_normal u_reach_normal
#endif
#endif
#endif
#ifndef FAR_REACH_COPIED
void far_reach_prepare()
{
}
#endif

#ifndef MODEL_FLAT
#ifdef METHOD_DOPRI5
// Dormand and Prince's RK5(4)7M pair (src/physics/model.c has the same tableau as fractions; the
// decimals are written out because Mesa folds constant expressions such as 7.0/9.0 at 16 bits).
// x1, v1: the fifth-order solution; ex, ev: its difference to the fourth-order one (the last
// stage, at the new point, is evaluated only when the error is wanted).
void dopri5_step(vec3 x, vec3 v, float h, out vec3 x1, out vec3 v1, out vec3 ex, out vec3 ev)
{
    vec3 k1x = v;
    vec3 k1v = model_accel(x, v);
    vec3 k2x = v + h * (0.2 * k1v);
    vec3 k2v = model_accel(x + h * (0.2 * k1x), k2x);
    vec3 k3x = v + h * (0.075 * k1v + 0.225 * k2v);
    vec3 k3v = model_accel(x + h * (0.075 * k1x + 0.225 * k2x), k3x);
    vec3 k4x = v + h * (0.9777777777777777 * k1v - 3.7333333333333334 * k2v + 3.5555555555555554 * k3v);
    vec3 k4v = model_accel(x + h * (0.9777777777777777 * k1x - 3.7333333333333334 * k2x + 3.5555555555555554 * k3x),
                           k4x);
    vec3 k5x = v + h * (2.9525986892242035 * k1v - 11.595793324188385 * k2v + 9.822892851699436 * k3v
                        - 0.2908093278463649 * k4v);
    vec3 k5v = model_accel(x + h * (2.9525986892242035 * k1x - 11.595793324188385 * k2x + 9.822892851699436 * k3x
                                    - 0.2908093278463649 * k4x), k5x);
    vec3 k6x = v + h * (2.8462752525252526 * k1v - 10.757575757575758 * k2v + 8.906422717743473 * k3v
                        + 0.2784090909090909 * k4v - 0.2735313036020583 * k5v);
    vec3 k6v = model_accel(x + h * (2.8462752525252526 * k1x - 10.757575757575758 * k2x + 8.906422717743473 * k3x
                                    + 0.2784090909090909 * k4x - 0.2735313036020583 * k5x), k6x);
    x1 = x + h * (0.09114583333333333 * k1x + 0.44923629829290207 * k3x + 0.6510416666666666 * k4x
                  - 0.322376179245283 * k5x + 0.13095238095238096 * k6x);
    v1 = v + h * (0.09114583333333333 * k1v + 0.44923629829290207 * k3v + 0.6510416666666666 * k4v
                  - 0.322376179245283 * k5v + 0.13095238095238096 * k6v);
#ifdef STEP_EMBEDDED
    vec3 k7x = v1;
    vec3 k7v = model_accel(x1, v1);
    ex = h * (0.0012326388888888888 * k1x - 0.004252770290506139 * k3x + 0.036979166666666664 * k4x
              - 0.05086379716981132 * k5x + 0.0419047619047619 * k6x - 0.025 * k7x);
    ev = h * (0.0012326388888888888 * k1v - 0.004252770290506139 * k3v + 0.036979166666666664 * k4v
              - 0.05086379716981132 * k5v + 0.0419047619047619 * k6v - 0.025 * k7v);
#else
    ex = vec3(0.0);
    ev = vec3(0.0);
#endif
}
#endif

// One step of eq. (1): Euler as the paper's eq. (2), classical RK4, or Dormand-Prince 5.
void model_step(vec3 x, vec3 v, float h, out vec3 x1, out vec3 v1)
{
#if defined(METHOD_DOPRI5)
    vec3 ex, ev;
    dopri5_step(x, v, h, x1, v1, ex, ev);
#elif defined(METHOD_RK4)
    vec3 k1x = v;
    vec3 k1v = model_accel(x, v);
    vec3 k2x = v + 0.5 * h * k1v;
    vec3 k2v = model_accel(x + 0.5 * h * k1x, k2x);
    vec3 k3x = v + 0.5 * h * k2v;
    vec3 k3v = model_accel(x + 0.5 * h * k2x, k3x);
    vec3 k4x = v + h * k3v;
    vec3 k4v = model_accel(x + h * k3x, k4x);
    x1 = x + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
    v1 = v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
#else
    x1 = x + h * v;
    v1 = v + h * model_accel(x, v);
#endif
}

#if defined(STEP_DOUBLING) || defined(STEP_EMBEDDED)
uniform float u_tolerance;            // error estimate above which a step is rejected
uniform float u_grow_below;           // step doubling: error estimate below which the step doubles
uniform float u_step_min;
uniform float u_step_max;
const float ERROR_LIMIT = 1.0e30;     // an estimate beyond this (or NaN) rejects the step
#endif
#if defined(STEP_DOUBLING) || defined(STEP_EMBEDDED) || defined(STEP_FAR)
// An adaptive ray's budget is a path, not a number of steps, and so is that of fixed steps that
// grow away from the objects (STEP_FAR): its state's w holds the affine parameter it has travelled
// (in place of the step count of fixed steps), and no step goes beyond u_path_max. A ray that has
// spent it takes steps of length 0 and ends the frame unfinished.
uniform float u_path_max;
#define PATH_BUDGET 1
#endif

#ifdef STEP_FAR
// Steps that grow where no object is near (render.far_step; src/render/far_reach.h). Light far
// from every object needs its steps only for the field's sake: there the longest step grows with
// the point's distance from the nearest object's bound, from what it is near one (fixed steps: the
// scene's step, the state's h; adaptive steps: u_step_max) to at most u_far_step: that distance
// over FAR_STEP_MARGIN |v|, so that the step's chord (about the step times |v| long) ends a third
// of the distance short of every object, whatever the field bends it by. On lorenz.scene a margin
// of 1 was 6% faster and 2 was 10% slower than 1.5, the errors the same. Every chord is still
// tested as before (a long one that comes near an object too): this changes how closely the curve
// is followed where nothing can be hit, never which objects a ray can meet. The bound is a
// function of the point alone, the same in every pass that takes it: the pipelines stay the same
// rays bit for bit.
uniform float u_far_step;
const float FAR_STEP_MARGIN = 1.5;

// A lower bound of the distance from x to the nearest object: to a bound's ball, and for a flat one
// to its plane, whichever is the larger (a ball alone: the larger of that and 0, since its normal
// is 0; a point inside a ball is at 0 or less, where the step is the scene's).
float far_reach(vec3 x)
{
    float reach = 1.0e30;
#if STEP_FAR > 0
    for (int n = 0; n < STEP_FAR; n++) {
        vec3 from_centre = x - reach_ball[n].xyz;
        float from_ball = length(from_centre) - reach_ball[n].w;
        reach = min(reach, max(from_ball, abs(dot(from_centre, reach_normal[n].xyz))));
    }
#endif
    return reach;
}

// The longest step from (x, v): near_most where an object is near, longer away from them (at most
// u_far_step, never less than near_most).
float far_bound(vec3 x, vec3 v, float near_most)
{
    return max(near_most, min(far_reach(x) / (FAR_STEP_MARGIN * length(v)), u_far_step));
}
#endif

// The step to try from a ray that has travelled `travelled` (its state's w): h, or what is left of
// an adaptive ray's budget.
float step_within_budget(float h, float travelled)
{
#ifdef PATH_BUDGET
    return min(h, u_path_max - travelled);
#else
    return h;
#endif
}

// The ray state's w after an accepted step of length h: the step count, or an adaptive ray's path.
float travelled_after(float travelled, float h)
{
#ifdef PATH_BUDGET
    return travelled + h;
#else
    return travelled + 1.0;
#endif
}

// The step to try from (x, v), whose state's step is h and path `travelled`, and the longest the
// step control may make the next (h_most): fixed steps take h where an object is near, adaptive
// ones at most u_step_max; with far steps both grow away from the objects (far_bound).
void step_to_try(vec3 x, vec3 v, float h, float travelled, out float h_try, out float h_most)
{
#if defined(STEP_DOUBLING) || defined(STEP_EMBEDDED)
#ifdef STEP_FAR
    h_most = far_bound(x, v, u_step_max);
    h_try = step_within_budget(min(h, h_most), travelled);
#else
    h_most = u_step_max;
    h_try = step_within_budget(h, travelled);
#endif
#else
#ifdef STEP_FAR
    h_most = far_bound(x, v, h);
#else
    h_most = h;
#endif
    h_try = step_within_budget(h_most, travelled);
#endif
}

// One adaptive (or fixed) step from (x, v) with step h, the step control's longest h_most: the new
// state, whether it is accepted, and the step to take next (paper section 4.2).
void controlled_step(vec3 x, vec3 v, float h, float h_most, out vec3 x1, out vec3 v1, out bool accept,
                     out float h_next)
{
#if defined(STEP_DOUBLING)
    // one full step against two half steps; the two half steps are kept
    vec3 x_full, v_full, x_mid, v_mid;
    float half_h = 0.5 * h;
    model_step(x, v, h, x_full, v_full);
    model_step(x, v, half_h, x_mid, v_mid);
    model_step(x_mid, v_mid, half_h, x1, v1);
    float error = length(x1 - x_full) + h * length(v1 - v_full);
    float shrunk = max(half_h, u_step_min);
    float grown = min(2.0 * h, h_most);
    bool too_big = (error > u_tolerance || !(error < ERROR_LIMIT)) && h > u_step_min;
    accept = !too_big;
    float kept_or_grown = error < u_grow_below ? grown : h;
    h_next = too_big ? shrunk : kept_or_grown;
#elif defined(STEP_EMBEDDED)
    // the usual controller: h * 0.9 (tolerance / error)^(1/5), changing by a factor 0.2 to 5 at most
    vec3 ex, ev;
    dopri5_step(x, v, h, x1, v1, ex, ev);
    float error = length(ex) + h * length(ev);
    float ratio = u_tolerance / max(error, 1.0e-30);
    float factor = clamp(0.9 * pow(ratio, 0.2), 0.2, 5.0);
    float shrunk = max(0.2 * h, u_step_min);
    float controlled = clamp(h * factor, u_step_min, h_most);
    bool too_big = (error > u_tolerance || !(error < ERROR_LIMIT)) && h > u_step_min;
    accept = !too_big;
    h_next = error < ERROR_LIMIT ? controlled : shrunk;
#else
    model_step(x, v, h, x1, v1);
    accept = true;
    h_next = h;
#endif
}

// One step from (x, v), whose state's step is h and path `travelled`: the step tried (h_try), the
// state at its end, whether the step control accepts it, and the state's next step.
void step_attempt(vec3 x, vec3 v, float h, float travelled, out float h_try, out vec3 x1, out vec3 v1,
                  out bool accept, out float h_next)
{
    float h_most;
    step_to_try(x, v, h, travelled, h_try, h_most);
    controlled_step(x, v, h_try, h_most, x1, v1, accept, h_next);
#if defined(STEP_FAR) && !defined(STEP_DOUBLING) && !defined(STEP_EMBEDDED)
    h_next = h;   // fixed steps: the state keeps the scene's step, which the next point's grows from
#endif
}
#endif

#ifndef MODEL_FLAT
// The velocity where a step of length h from (x0, v0) to x0 + chord (v1 there) crossed the bounding
// sphere: the sky's direction, as the CPU reference takes it (src/ref/reference.c). The step's end
// lies beyond the sphere, and a field that still pulls there (Lorenz's grows with the distance)
// would turn the end's velocity by the pull over the rest of the step: an error in proportion to
// the step, which held the scenes' steps small. The crossing is found on the step's cubic Hermite
// curve (its dense output from both ends' positions and velocities, third order in h for the
// velocity), from the chord's crossing by Newton's steps. Models whose sky lies along the orbit's
// direction at infinity (SKY_AT_INFINITY) take it from the step's end, a point of the same orbit.
const int EXIT_NEWTON_STEPS = 3;

vec3 exit_velocity(vec3 x0, vec3 v0, vec3 chord, vec3 v1, float h)
{
    vec3 o0 = x0 - u_bound_center;
    // the chord's crossing: |o0 + t chord|^2 = R^2 with |o0| < R, the root in [0, 1]
    float a = max(dot(chord, chord), 1.0e-30);
    float b = dot(o0, chord);
    float c = dot(o0, o0) - u_bound_radius2;
    float t = clamp((sqrt(max(b * b - a * c, 0.0)) - b) / a, 0.0, 1.0);
    vec3 hv0 = h * v0;
    vec3 hv1 = h * v1;
    for (int i = 0; i < EXIT_NEWTON_STEPS; i++) {
        float t2 = t * t;
        float t3 = t2 * t;
        vec3 p = (2.0 * t3 - 3.0 * t2 + 1.0) * o0 + (t3 - 2.0 * t2 + t) * hv0 + (3.0 * t2 - 2.0 * t3) * (o0 + chord)
                 + (t3 - t2) * hv1;
        vec3 dp = (6.0 * t2 - 6.0 * t) * (-chord) + (3.0 * t2 - 4.0 * t + 1.0) * hv0 + (3.0 * t2 - 2.0 * t) * hv1;
        float f = dot(p, p) - u_bound_radius2;
        float slope = 2.0 * dot(p, dp);
        t = clamp(t - f / (abs(slope) > 1.0e-30 ? slope : 1.0e-30), 0.0, 1.0);
    }
    float t2 = t * t;
    return (6.0 * t2 - 6.0 * t) * (-chord) / h + (3.0 * t2 - 4.0 * t + 1.0) * v0 + (3.0 * t2 - 2.0 * t) * v1;
}

// The step in which a ray left for the sky: its start (x, v) and length h. The velocity where it
// crossed the bounding sphere (exit_velocity) is found from these and the step's end once the
// checked steps are done (exit_taken), not inside their loop: a ray that left takes no more steps,
// so the step that left is the last one taken, and its end is where the loop leaves the ray. The
// same arithmetic on the same values (the chord x1 - x taken where the step computes x1, as
// exit_velocity took it, so that the compiler simplifies it as it did). Why: Newton's steps on the
// Hermite curve, live beside a light model's step in every turn, made the kiosk's lorenz frame
// spill 19 values on V3D 4.2 (`make shader-stats`); found after the single pass's last tests, 3
// (rossler's 0). The stored step costs the heaviest steps (potential's and refraction's step
// doubling) about ten more.
struct exit_step {
    vec3 x, v;
    vec3 chord;      // from x to the step's end
    float h;
    bool left;
};

exit_step no_exit()
{
    return exit_step(vec3(0.0), vec3(0.0), vec3(0.0), 1.0, false);   // h: no division by 0 in exit_taken
}

// One step as the scheme defines it: a ray stops moving once it left the bounding sphere, fell
// into the horizon or its state stopped being finite (the last finite state is kept, and the
// step count turns negative: failed); the ray state is updated with selects (see the precision
// note in common.glsl). A step that leaves for the sky is kept in `left_at` (the velocity at the
// crossing comes after the steps: exit_taken).
void step_checked(inout vec3 x, inout vec3 v, inout float steps, inout float h, inout bool running,
                  inout exit_step left_at)
{
    vec3 x1, v1;
    bool accept;
    float h_try, h_next;
    step_attempt(x, v, h, steps, h_try, x1, v1, accept, h_next);
    bool ok = finite_step(x, x1, v1) || !accept;
    bool take = running && ok && accept;
    float next_steps = travelled_after(steps, h_try);
    float failed_steps = -1.0 - steps;
#ifndef SKY_AT_INFINITY
    // a ray that left for the sky: its step, for the velocity where it crossed the bounding sphere
    bool left = take && outside_bounds(x1) && !captured(x1);
    left_at.x = left ? x : left_at.x;
    left_at.v = left ? v : left_at.v;
    left_at.chord = left ? x1 - x : left_at.chord;
    left_at.h = left ? h_try : left_at.h;
    left_at.left = left_at.left || left;
#endif
    x = take ? x1 : x;
    v = take ? v1 : v;
    steps = take ? next_steps : (running && !ok ? failed_steps : steps);
    h = running && ok ? h_next : h;
    running = running && ok && travelling(x);
}

// The velocity of a ray that the checked steps left at (x, v): where `left_at` says it left in the
// last of them, the velocity where it crossed the bounding sphere.
vec3 exit_taken(exit_step left_at, vec3 x, vec3 v)
{
#ifdef SKY_AT_INFINITY
    return v;
#else
    vec3 crossing = exit_velocity(left_at.x, left_at.v, left_at.chord, v, left_at.h);
    return left_at.left ? crossing : v;
#endif
}

// The same step for a ray assumed to keep travelling: the same arithmetic without the selects
// that stop a ray; `clean` stays true only while that assumption held (the state finite, inside
// the bounding sphere, outside the horizon), and then the state is exactly step_checked's.
void step_unchecked(inout vec3 x, inout vec3 v, inout float steps, inout float h, inout bool clean)
{
    vec3 x1, v1;
    bool accept;
    float h_try, h_next;
    step_attempt(x, v, h, steps, h_try, x1, v1, accept, h_next);
    float next_steps = travelled_after(steps, h_try);
    vec3 x0 = x;
    x = accept ? x1 : x;
    v = accept ? v1 : v;
    steps = accept ? next_steps : steps;
    h = h_next;
    bool inside = inside_bounds(x);
#ifdef MODEL_HORIZON
    inside = inside && !captured(x);
#endif
    clean = clean && inside && finite_step(x0, x, v);
}

// N unchecked steps from (x, v) (N a constant expression), MODEL_STEPS_A_TURN of them to a loop
// turn. The model file says how many: 2 for a light model whose step is small (Lorenz, Roessler,
// the potential, Schwarzschild), 1 for one whose step is large (refraction's noise). The same
// steps in the same order either way, so the same rays bit for bit. Why: on llvmpipe a loop turn
// costs a good part of a small step, so two small steps a turn run faster than one; two large
// steps a turn, or three or more small ones, ran slower than one (docs/PIPELINE.md). The loop
// breaks after its last turn, not only at the top of the next (docs/PIPELINE.md, "Loops that end
// at a turn's end").
#if MODEL_STEPS_A_TURN == 2
#define STEPS_UNCHECKED(N, x, v, steps, h, clean) \
    for (int turn = 0; turn < (N) / 2; turn++) { \
        step_unchecked(x, v, steps, h, clean); \
        step_unchecked(x, v, steps, h, clean); \
        if (turn == (N) / 2 - 1) \
            break; \
    } \
    if ((N) - 2 * ((N) / 2) == 1) \
        step_unchecked(x, v, steps, h, clean);
#else
#define STEPS_UNCHECKED(N, x, v, steps, h, clean) \
    for (int turn = 0; turn < (N); turn++) { \
        step_unchecked(x, v, steps, h, clean); \
        if (turn == (N) - 1) \
            break; \
    }
#endif
#endif

// One pass's worth of the ray's motion: STEPS_PER_PASS steps from (x, v) with step h, or flat
// space's single straight segment. The integration stage runs it once a pass; the single pass
// (stage_frame.glsl) runs it steps_per_segment / STEPS_PER_PASS times a segment, the same arithmetic.
// The steps are first taken unchecked (step_unchecked), which is exact while the ray keeps
// travelling through all of them, as it does in every pass but its last; only where it did not
// are they taken again from the pass's start, each checked (step_checked). The rays are the same
// bit for bit (tests/unit/test_acceleration.c, and the goldens). Why: the checks and selects
// cost several times the arithmetic of a light model's step. A GPU that runs fragments in groups
// (llvmpipe: 8) runs the checked loop's turns only while one of the group needs them; llvmpipe
// still runs its first turn, so a pass costs about one checked step more than its unchecked ones
// (docs/PIPELINE.md has the measurements).
void integrate_pass(inout vec3 x, inout vec3 v, inout float steps, inout float h, bool running)
{
#ifdef MODEL_FLAT
    // Flat space is not integrated: one straight segment to where the ray leaves the bounding sphere.
    vec3 d = normalize(v);
    vec3 oc = x - u_bound_center;
    float b = dot(oc, d);
    float c = dot(oc, oc) - u_bound_radius2;
    float exit_distance = sqrt(max(b * b - c, 0.0)) - b;
    // 1% beyond the boundary, so that even a 16-bit position lands outside it
    vec3 exit_point = x + d * exit_distance * 1.01;
    float next_steps = steps + 1.0;
    x = running ? exit_point : x;
    steps = running ? next_steps : steps;
#else
    vec3 x_start = x;
    vec3 v_start = v;
    float steps_start = steps;
    float h_start = h;
    bool clean = true;
#ifdef CHECK_EVERY_STEP
    // every step checked, as the scheme states it: what tests/unit/test_acceleration.c compares with
    clean = false;
#else
    STEPS_UNCHECKED(STEPS_PER_PASS, x, v, steps, h, clean)
#endif
    // where the ray stopped within the pass, the pass again from its start, each step checked
    bool again = running && !clean;
    vec3 x_checked = x_start;
    vec3 v_checked = v_start;
    float steps_checked = steps_start;
    float h_checked = h_start;
    bool running_checked = running;
    exit_step left_at = no_exit();
    for (int i = 0; i < STEPS_PER_PASS; i++) {
        if (!again)
            break;
        step_checked(x_checked, v_checked, steps_checked, h_checked, running_checked, left_at);
        // at the turn's end (docs/PIPELINE.md, "Loops that end at a turn's end")
        if (i == STEPS_PER_PASS - 1)
            break;
    }
    v_checked = exit_taken(left_at, x_checked, v_checked);
    // the checked state kept apart until here: selected, not assigned in the loop that may break
    // (see the precision note in common.glsl); a ray that was not travelling keeps its state
    vec3 x_moved = again ? x_checked : x;
    vec3 v_moved = again ? v_checked : v;
    float steps_moved = again ? steps_checked : steps;
    float h_moved = again ? h_checked : h;
    x = running ? x_moved : x_start;
    v = running ? v_moved : v_start;
    steps = running ? steps_moved : steps_start;
    h = running ? h_moved : h_start;
#endif
}

#ifndef MODEL_FLAT
// integrate_pass where its steps are known not to all hold unchecked (the single pass's segment in
// which a ray left, fell in or failed): the checked steps alone, the same state bit for bit, but
// for a ray that left for the sky, whose velocity where it crossed the bounding sphere the caller
// takes from left_at (exit_taken) once the rest of its tests are done: fewer values live beside
// Newton's steps (the kiosk's lorenz frame on V3D 4.2: 19 values spilled with it here, 3 there).
void integrate_pass_checked(inout vec3 x, inout vec3 v, inout float steps, inout float h, bool running,
                            inout exit_step left_at)
{
    vec3 x_checked = x;
    vec3 v_checked = v;
    float steps_checked = steps;
    float h_checked = h;
    bool running_checked = running;
    for (int i = 0; i < STEPS_PER_PASS; i++) {
        if (!running_checked)
            break;
        step_checked(x_checked, v_checked, steps_checked, h_checked, running_checked, left_at);
        // at the turn's end (docs/PIPELINE.md, "Loops that end at a turn's end")
        if (!running_checked || i == STEPS_PER_PASS - 1)
            break;
    }
    // selected, not assigned in the loop that may break (see the precision note in common.glsl)
    x = running ? x_checked : x;
    v = running ? v_checked : v;
    steps = running ? steps_checked : steps;
    h = running ? h_checked : h;
}
#endif

#ifndef SINGLE_PASS
void main()
{
    far_reach_prepare();
    vec4 position = fetch(u_ray_position);
    vec4 velocity = fetch(u_ray_velocity);
    vec3 x = position.xyz;
    vec3 v = velocity.xyz;
    float steps = position.w;
    float h = velocity.w;
    bool running = fetch(u_hit).w >= NO_HIT && steps >= 0.0 && travelling(x);
    integrate_pass(x, v, steps, h, running);
    WRITE_TARGET0(state_rounded(vec4(x, steps)));
    WRITE_TARGET1(state_rounded(vec4(v, h)));
}
#endif
