// Conventions every stage shares; the C side is src/render/raystate.h.
//   ray position  texture: xyz = x,  w = integration steps taken (negative: the ray failed)
//   ray velocity  texture: xyz = v,  w = step size h
//   hit           texture: xyz = hit point, w = depth key = segment index + fraction in the segment
//   image         texture: rgb = shaded colour, a = object id, or an outcome code below
// One texel per pixel; gl_FragCoord.xy is the texel centre, so no filtering ever happens.

const float NO_HIT = 60000.0;          // depth key of a ray still travelling (fits in fp16)
const float CODE_SKY = -1.0;           // left the bounding sphere: sky by exit direction
const float CODE_CAPTURED = -2.0;      // fell through the horizon: black
const float CODE_UNFINISHED = -3.0;    // still travelling after the last segment
const float CODE_FAILED = -4.0;        // the integration produced a non-finite number

// Precision traps of GLSL ES on Mesa 22.3 (checked on llvmpipe; the fp32 render tests catch them):
// - an expression with a literal constant written inside a branch of ?: or if is evaluated
//   at 16-bit precision: compute it into a named local first, then select;
// - constant expressions such as 7.0 / 9.0 fold at 16-bit precision: write the literal;
// - a value assigned in the turn of a loop that breaks in that same turn can come out of it at
//   16-bit precision: break at the top of the next turn instead (stage_frame.glsl), or keep the
//   loop's inputs and compute the outputs again after it (stage_orbit_frame.glsl; the walk's pass,
//   stage_orbit_walk.glsl, writes only whole numbers, from which the finish computes them again);
// - int is mediump by default, kept in 16 bits: a loop counter bound beyond 32767 is highp;
// - Mesa's atan is off by up to 3.3e-6 rad on llvmpipe: accurate_angle below is not.

uniform vec2 u_inv_size;               // 1 / ray-state texture size

// A macro, not a function: a sampler passed as a function parameter can lose its highp
// precision in GLSL ES 1.00 (Mesa then returns 16-bit floats from a 32-bit texture).
#define fetch(state) texture2D(state, gl_FragCoord.xy * u_inv_size)

#ifdef STATE_HALF
// The ray state in 16-bit floats (a GPU without 32-bit float targets, or render.precision = fp16):
// each value is rounded to the nearest 16-bit float before it is written, so that a GPU that
// truncates when it converts to a 16-bit target (llvmpipe does) writes it unchanged. Truncated, a
// position lost about a unit in its last place at every pass, always towards zero: schwarzschild's
// sky rays fell short of the bounding sphere by 2.5% of their path, 3273 of 76800 left unfinished
// where 32-bit floats leave 3. Rounded, the errors are no longer all of one sign.
float half_rounded(float x)
{
    float a = abs(x);
    // the exponent of a as a 16-bit float (at least -14, where the subnormals' spacing begins),
    // log2's rounding next to a power of two put right
    float e = floor(log2(max(a, 6.103515625e-05)));
    float e_up = e + 1.0;
    float e_down = e - 1.0;
    e = a >= exp2(e_up) ? e_up : e;
    e = a < exp2(e) && e > -14.0 ? e_down : e;
    float unit = exp2(e - 10.0);
    float r = floor(a / unit + 0.5) * unit;
    return x < 0.0 ? -r : r;
}

vec4 state_rounded(vec4 v)
{
    return vec4(half_rounded(v.x), half_rounded(v.y), half_rounded(v.z), half_rounded(v.w));
}
#else
#define state_rounded(v) (v)
#endif

// A stage writes up to two targets: in one pass with MRT, or one per pass (BT_TARGET). The fused
// segment pass (stage_segment.glsl) writes four, with MRT only.
#ifdef BT_MRT
#define WRITE_TARGET0(value) gl_FragData[0] = (value)
#define WRITE_TARGET1(value) gl_FragData[1] = (value)
#define WRITE_TARGET2(value) gl_FragData[2] = (value)
#define WRITE_TARGET3(value) gl_FragData[3] = (value)
#elif BT_TARGET == 0
#define WRITE_TARGET0(value) gl_FragColor = (value)
#define WRITE_TARGET1(value)
#else
#define WRITE_TARGET0(value)
#define WRITE_TARGET1(value) gl_FragColor = (value)
#endif

// The angle of (x, y), y >= 0, in [0, pi], to a float rounding or two (Cephes' atanf: octant
// reduction and its minimax polynomial). Mesa 22.3's built-in atan is off by up to 3.3e-6 rad on
// llvmpipe (measured), which next to the shadow's edge the orbit magnifies a thousandfold.
float accurate_angle(float y, float x)
{
    float ax = abs(x);
    float big = max(ax, y);
    float small = min(ax, y);
    float t = small / max(big, 1e-30);
    bool upper = t > 0.41421356237309503;
    float z_upper = (t - 1.0) / (t + 1.0);
    float z = upper ? z_upper : t;
    float z2 = z * z;
    float p = (((0.0805374449538 * z2 - 0.138776856032) * z2 + 0.199777106478) * z2 - 0.333329491539) * z2 * z + z;
    float quarter_pi = 0.78539816339744831;
    float half_pi = 1.5707963267948966;
    float pi = 3.1415926535897931;
    float zero = 0.0;
    float base = upper ? quarter_pi : zero;
    float octant = base + p;
    float steep = half_pi - octant;
    float first = y > ax ? steep : octant;
    float behind = pi - first;
    return x < 0.0 ? behind : first;
}
