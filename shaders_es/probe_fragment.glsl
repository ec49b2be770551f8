// Capability probe: proves that a float format renders, samples and keeps its precision,
// and that several draw buffers are really written. See src/gl/caps.c.
uniform sampler2D u_source;
uniform vec4 u_value;
uniform float u_use_source;

void main()
{
#ifdef PROBE_LOOPS
    // How many turns a loop really runs when u_value.x of them are asked for: llvmpipe ends every
    // loop after 65535 turns, whatever its condition. Counted in a float (exact to 2^24) and
    // written as three bytes, each turn's work depending on the last so that no compiler folds it.
    float asked = u_value.x;
    float turns = 0.0;
    float x = u_value.y;
    for (highp int i = 0; i < PROBE_LOOP_TURNS; i++) {
        if (turns >= asked)
            break;
        turns += 1.0;
        x = fract(x * 1.5 + 0.25);
    }
    float high = floor(turns / 65536.0);
    float middle = floor((turns - high * 65536.0) / 256.0);
    float low = turns - high * 65536.0 - middle * 256.0;
    gl_FragColor = vec4(low, middle, high, 255.0 * step(-1.0, x)) / 255.0;
    return;
#endif
#ifdef PROBE_PACKING
    // A float's four bytes (common.glsl, pack_float) unpacked, times u_value.x, and packed again: exact only
    // where the fragment shader computes in 32-bit floats (src/gl/packing.c). u_value.y: the size
    // of a texel of the source in texture coordinates.
    float x = unpack_float(texture2D(u_source, gl_FragCoord.xy * u_value.y));
    gl_FragColor = pack_float(x * u_value.x);
    return;
#endif
#ifdef PROBE_ARITHMETIC
    // What the fragment shader really computes in: u_value.x = u_value.y = 1 + 2^-12, which 32-bit
    // floats hold and 16-bit ones round to 1; their product less 1, times u_value.z = 1024, is
    // 0.5005 in fp32 and 0 in fp16 (a product, not (a + b) - a, which a compiler may rewrite).
    gl_FragColor = vec4((u_value.x * u_value.y - 1.0) * u_value.z, 0.0, 0.0, 1.0);
    return;
#endif
    vec4 v = u_value;
    if (u_use_source > 0.5)
        v += texture2D(u_source, vec2(0.5));
#ifdef PROBE_MRT
    gl_FragData[0] = v;
    gl_FragData[1] = v * 2.0;
#else
    gl_FragColor = v;
#endif
}
