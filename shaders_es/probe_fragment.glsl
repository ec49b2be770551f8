// Capability probe: proves that a float format renders, samples and keeps its precision,
// and that several draw buffers are really written. See src/gl/caps.c.
uniform sampler2D u_source;
uniform vec4 u_value;
uniform float u_use_source;

void main()
{
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
