// A 32-bit float in the four bytes of an RGBA8 texel, for a GPU that has no float textures
// (VC4: the Raspberry Pi 0 to 3): the bytes IEEE 754 gives the float, high byte first (r: the
// sign and the exponent's high seven bits; g: the exponent's low bit and the mantissa's high
// seven; b and a: the rest of the mantissa), written and read with float arithmetic alone, as
// GLSL ES 1.00 has no bit operations. Every normal float comes back bit for bit; zero comes back
// as zero of either sign, a subnormal as zero (GPUs flush them), an infinity or NaN as infinity.
// Exact only where the fragment shader computes in 32-bit floats: src/gl/caps.c probes it.

// 2^e for a whole e from -126 to 127, exactly: 2^-126 times the powers 2^(2^i) that e + 126 is
// made of, each a literal. exp2 would do where it is exact at whole numbers, which GLSL ES 1.00
// leaves to the GPU.
float pow2_whole(float e)
{
    float k = e + 126.0;
    float p = 1.1754943508222875e-38;
    float b = step(128.0, k);
    k -= 128.0 * b;
    p *= mix(1.0, 1.8446744073709552e19, b);
    p *= mix(1.0, 1.8446744073709552e19, b);
    b = step(64.0, k);
    k -= 64.0 * b;
    p *= mix(1.0, 1.8446744073709552e19, b);
    b = step(32.0, k);
    k -= 32.0 * b;
    p *= mix(1.0, 4294967296.0, b);
    b = step(16.0, k);
    k -= 16.0 * b;
    p *= mix(1.0, 65536.0, b);
    b = step(8.0, k);
    k -= 8.0 * b;
    p *= mix(1.0, 256.0, b);
    b = step(4.0, k);
    k -= 4.0 * b;
    p *= mix(1.0, 16.0, b);
    b = step(2.0, k);
    k -= 2.0 * b;
    p *= mix(1.0, 4.0, b);
    b = step(1.0, k);
    p *= mix(1.0, 2.0, b);
    return p;
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
