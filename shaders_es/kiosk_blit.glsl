// The kiosk compositor: one image, filtered, into the viewport (previews are upscaled here, the
// refined bands copied, the HUD blended over the frame).
uniform sampler2D u_image;
varying vec2 v_uv;

void main()
{
    gl_FragColor = texture2D(u_image, v_uv);
}
