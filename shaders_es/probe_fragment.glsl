// Capability probe: proves that a float format renders, samples and keeps its precision,
// and that several draw buffers are really written. See src/gl/caps.c.
uniform sampler2D u_source;
uniform vec4 u_value;
uniform float u_use_source;

void main()
{
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
