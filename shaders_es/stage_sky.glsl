// Stage 5, sky and final colour (paper section 4.3): rays without a hit look the sky up by
// their direction, asymptotically flat at the bounding sphere. Captured rays are black.
uniform sampler2D u_image;
uniform sampler2D u_ray_velocity;
#ifdef SKY_CUBEMAP
uniform samplerCube u_sky;
#else
uniform vec3 u_sky_color;
#endif

vec3 sky(vec3 direction)
{
#ifdef SKY_CUBEMAP
    return textureCube(u_sky, direction).rgb;
#else
    return u_sky_color;
#endif
}

void main()
{
    vec4 image = fetch(u_image);
    vec3 color = image.rgb;
    if (image.a == CODE_SKY || image.a == CODE_UNFINISHED)
        color = sky(normalize(fetch(u_ray_velocity).xyz));
    else if (image.a < -0.5)
        color = vec3(0.0);
    gl_FragColor = vec4(clamp(color, 0.0, 1.0), 1.0);
}
