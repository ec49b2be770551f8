// One viewport-filling quadrilateral per pass (paper section 3): the fragments are the rays.
// u_quad_depth is the constant z of the quad; passes over terminated rays can be culled by
// the depth test against it.
attribute vec2 a_corner;
uniform float u_quad_depth;

void main()
{
    gl_Position = vec4(a_corner, u_quad_depth, 1.0);
}
