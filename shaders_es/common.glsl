// Conventions every stage shares; the C side is src/render/raystate.h.
//   ray position  texture: xyz = x,  w = integration steps taken (negative: the ray failed)
//   ray velocity  texture: xyz = v,  w = step size h
//   hit           texture: xyz = hit point, w = depth key = segment index + fraction in the segment
//   image         texture: rgb = shaded colour, a = object id, or an outcome code below
// One texel per pixel (a 2x2 block of them on the packed path, below); gl_FragCoord.xy is the texel
// centre, so no filtering ever happens.

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

#if defined(STATE_PACKED) || defined(PROBE_PACKING)
// A 32-bit float in the four bytes of an RGBA8 texel, for a GPU that has no float textures
// (VC4: the Raspberry Pi 0 to 3): the bytes IEEE 754 gives the float, high byte first (r: the
// sign and the exponent's high seven bits; g: the exponent's low bit and the mantissa's high
// seven; b and a: the rest of the mantissa), written and read with float arithmetic alone, as
// GLSL ES 1.00 has no bit operations. Every normal float comes back bit for bit; zero comes back
// as zero of either sign, a subnormal as zero (GPUs flush them), an infinity or NaN as infinity.
// Exact only where the fragment shader computes in 32-bit floats: src/gl/packing.c probes it.

// p times 2^bit (factor) where k holds that bit (k >= bit), the bit then taken off k
float times_bit(float p, inout float k, float bit, float factor)
{
    float b = step(bit, k);
    k -= bit * b;
    return p * mix(1.0, factor, b);
}

// 2^e for a whole e from -126 to 127, exactly: 2^-126 times the powers 2^(2^i) that e + 126 is
// made of, each a literal. exp2 would do where it is exact at whole numbers, which GLSL ES 1.00
// leaves to the GPU.
float pow2_whole(float e)
{
    float k = e + 126.0;
    float p = 1.1754943508222875e-38;          // 2^-126
    // 2^128 is no float: twice 2^64
    float top = step(128.0, k);
    k -= 128.0 * top;
    p *= mix(1.0, 1.8446744073709552e19, top);
    p *= mix(1.0, 1.8446744073709552e19, top);
    p = times_bit(p, k, 64.0, 1.8446744073709552e19);
    p = times_bit(p, k, 32.0, 4294967296.0);
    p = times_bit(p, k, 16.0, 65536.0);
    p = times_bit(p, k, 8.0, 256.0);
    p = times_bit(p, k, 4.0, 16.0);
    p = times_bit(p, k, 2.0, 4.0);
    return times_bit(p, k, 1.0, 2.0);
}

// The colour that writes x's four bytes into an RGBA8 target: each byte a quarter above its
// level, so that a GPU that rounds and one that truncates as it converts store the same byte.
vec4 pack_float(float x)
{
    float a = abs(x);
    float sign_byte = 128.0 * (1.0 - step(0.0, x));
    // the exponent e, 2^e <= a < 2^(e + 1): log2's estimate, its rounding next to a power of two
    // put right
    float e = clamp(floor(log2(a)), -126.0, 127.0);
    float p = pow2_whole(e);
    float down = (1.0 - step(p, a)) * step(-125.5, e);
    float up = step(p + p, a) * (1.0 - step(126.5, e));
    e += up - down;
    // the mantissa's 23 bits as a whole number: a / 2^e - 1 in [0, 1), times 2^23; 2^-e from
    // pow2_whole's range (2^-127 as 2^-126 / 2)
    float top = step(126.5, e);
    float m = a * pow2_whole(top - e) * (1.0 - 0.5 * top);
    float f = (m - 1.0) * 8388608.0;
    float f_high = floor(f * 1.52587890625e-05);
    float f_rest = f - 65536.0 * f_high;
    float f_middle = floor(f_rest * 0.00390625);
    float f_low = f_rest - 256.0 * f_middle;
    float biased = e + 127.0;
    float e_high = floor(biased * 0.5);
    float e_low = biased - 2.0 * e_high;
    vec4 normal = vec4(sign_byte + e_high, 128.0 * e_low + f_high, f_middle, f_low);
    vec4 zero = vec4(sign_byte, 0.0, 0.0, 0.0);
    vec4 infinity = vec4(sign_byte + 127.0, 128.0, 0.0, 0.0);
    bool tiny = a < 1.1754943508222875e-38;
    bool finite = a <= 3.4028234663852886e38;
    vec4 bytes = tiny ? zero : normal;
    bytes = finite ? bytes : infinity;
    return (bytes + 0.25) / 255.0;
}

// The float whose four bytes an RGBA8 texel holds (pack_float's).
float unpack_float(vec4 texel)
{
    vec4 b = floor(texel * 255.0 + 0.5);
    float negative = step(128.0, b.x);
    float e_low = step(128.0, b.y);
    float biased = 2.0 * (b.x - 128.0 * negative) + e_low;
    float f = 65536.0 * (b.y - 128.0 * e_low) + 256.0 * b.z + b.w;
    float m = 1.0 + f * 1.1920928955078125e-07;
    float v = m * pow2_whole(clamp(biased - 127.0, -126.0, 127.0));
    float zero = 0.0;
    float infinity = 2.0 * pow2_whole(127.0);
    v = biased < 0.5 ? zero : v;
    v = biased > 254.5 ? infinity : v;
    float minus_v = -v;
    return negative > 0.5 ? minus_v : v;
}
#endif

#ifdef STATE_PACKED
// The packed path (a GPU without float textures): each texel of a float texture is a 2x2 block of
// RGBA8 texels, its x, y, z, w at (0, 0), (1, 0), (0, 1), (1, 1) of the block, each one float
// (pack_float above), in textures twice as wide and high (u_inv_size: 1 / their size). A pass that
// writes the ray state draws all four texels of each ray's block, each fragment the whole stage
// and the one float its texel holds (u_pixel_scale 0.5); a pass that writes a colour (the sky
// stage) draws one fragment a ray (1).
uniform float u_pixel_scale;

// the ray's pixel, from (0, 0)
vec2 ray_pixel()
{
    return floor(gl_FragCoord.xy * u_pixel_scale);
}

// The four floats of the 2x2 block of RGBA8 texels whose first texel is `corner` (in texels, from
// (0, 0)) of a packed texture whose texels are texel_size across (1 / its size). A function: an
// RGBA8 texture's texels are bytes, which any sampler precision holds.
vec4 unpack_block(sampler2D texels, vec2 corner, vec2 texel_size)
{
    vec2 at = corner + 0.5;
    return vec4(unpack_float(texture2D(texels, at * texel_size)),
                unpack_float(texture2D(texels, (at + vec2(1.0, 0.0)) * texel_size)),
                unpack_float(texture2D(texels, (at + vec2(0.0, 1.0)) * texel_size)),
                unpack_float(texture2D(texels, (at + vec2(1.0, 1.0)) * texel_size)));
}

// A texel of a float texture: its four floats from the ray's block.
vec4 fetch_packed(sampler2D state)
{
    return unpack_block(state, 2.0 * ray_pixel(), u_inv_size);
}
#define fetch(state) fetch_packed(state)
// the texel of the ray at `ray` (from (0, 0)), another ray's than the fragment's
#define fetch_at(state, ray) unpack_block(state, 2.0 * (ray), u_inv_size)

// What a pass writes for value: in a ray's block, the float of the fragment's texel, packed; a
// colour (u_pixel_scale 1) as it is.
vec4 state_written(vec4 value)
{
    vec2 within = gl_FragCoord.xy - 2.0 * floor(gl_FragCoord.xy * 0.5) - 0.5;
    float low = within.x < 0.5 ? value.x : value.y;
    float high = within.x < 0.5 ? value.z : value.w;
    float component = within.y < 0.5 ? low : high;
    vec4 bytes = pack_float(component);
    return u_pixel_scale < 0.75 ? bytes : value;
}
#else
// the ray's pixel, from (0, 0)
vec2 ray_pixel()
{
    return floor(gl_FragCoord.xy);
}

// A macro, not a function: a sampler passed as a function parameter can lose its highp
// precision in GLSL ES 1.00 (Mesa then returns 16-bit floats from a 32-bit texture).
#define fetch(state) texture2D(state, gl_FragCoord.xy * u_inv_size)
// the texel of the ray at `ray` (from (0, 0)), another ray's than the fragment's
#define fetch_at(state, ray) texture2D(state, ((ray) + 0.5) * u_inv_size)
#define state_written(value) (value)
#endif

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
#define WRITE_TARGET0(value) gl_FragColor = state_written(value)
#define WRITE_TARGET1(value)
#else
#define WRITE_TARGET0(value)
#define WRITE_TARGET1(value) gl_FragColor = state_written(value)
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
