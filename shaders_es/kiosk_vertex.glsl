// The kiosk compositor's quadrilateral: it fills the viewport, and v_uv runs across the part of the
// source image given by u_uv_rect (lower-left corner xy, extent zw; a negative extent flips).
attribute vec2 a_corner;
uniform vec4 u_uv_rect;
varying vec2 v_uv;

void main()
{
    v_uv = u_uv_rect.xy + (a_corner * 0.5 + 0.5) * u_uv_rect.zw;
    gl_Position = vec4(a_corner, 0.0, 1.0);
}
