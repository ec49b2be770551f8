// Stage 0: clear the hit and image state to "no hit yet" (a clear colour would be clamped
// to [0,1] on some GLES2 devices, so a pass writes the values).
uniform vec4 u_fill0;
uniform vec4 u_fill1;

void main()
{
    WRITE_TARGET0(u_fill0);
    WRITE_TARGET1(u_fill1);
}
