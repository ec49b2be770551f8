// The polygon method (Müller, Grottel and Weiskopf 2010, section 3.2), kept for comparison with the
// per-pixel ray tracing of moving objects: each vertex of the object's tessellated rest-frame
// surface is moved to where it is seen, the event where its worldline meets the observer's backward
// light cone (Eq. 5-8), and the triangles between are rasterised straight.
attribute vec3 a_rest_position;     // relative to the frame origin
attribute vec3 a_rest_normal;
attribute vec2 a_uv;
uniform vec3 u_camera_position;
uniform vec3 u_camera_forward;
uniform vec3 u_camera_right;        // scaled by tan(fov / 2) * aspect
uniform vec3 u_camera_up;           // scaled by tan(fov / 2)
uniform vec4 u_body_motion;         // beta, gamma
uniform vec3 u_body_origin;
uniform vec3 u_observer_rest;       // the observation event in the rest frame (Eq. 5), relative to the origin
uniform float u_observer_rest_time;
uniform float u_far;                // distances map to depth 0..1 up to here
uniform vec2 u_subpixel_ndc;        // where in its pixel the ray of this sample starts (render.samples)
uniform vec4 u_band_ndc;            // the part of the image drawn (a band of rows): scale xy, centre zw
#ifdef OBSERVER_MOVING
uniform vec3 u_observer_beta;
uniform float u_observer_gamma;
#endif
varying vec3 v_apparent;
varying vec3 v_normal;
varying vec2 v_uv;
varying float v_proper_time;

void main()
{
    vec3 p = a_rest_position;
    // Eq. 7: emitted when the light reaching the eye at t'_obs had to leave
    float emitted = u_observer_rest_time - length(p - u_observer_rest);
    // Eq. 8: that event back in the scene frame
    float g = u_body_motion.w;
    vec3 x = p + (g * g / (g + 1.0) * dot(u_body_motion.xyz, p) + g * emitted) * u_body_motion.xyz + u_body_origin;
    v_apparent = x;
    v_normal = a_rest_normal;
    v_uv = a_uv;
    v_proper_time = emitted;
    vec3 d = x - u_camera_position;
    float distance = length(d);
#ifdef OBSERVER_MOVING
    // where the moving observer sees that direction (the inverse of the setup stage's aberration)
    vec3 beta = -u_observer_beta;
    float og = u_observer_gamma;
    float along = dot(beta, d / distance);
    d = distance * normalize(d / distance + (og * og / (og + 1.0) * along - og) * beta);
#endif
    float w = dot(d, u_camera_forward);
    // a sample off the pixel's centre sees what lies that far off: the image moves the other way
    vec2 ndc_w = vec2(dot(d, u_camera_right) / dot(u_camera_right, u_camera_right),
                      dot(d, u_camera_up) / dot(u_camera_up, u_camera_up)) - u_subpixel_ndc * w;
    // a band of the image fills the viewport: its centre to the origin, its size to 2
    vec2 band_w = (ndc_w - u_band_ndc.zw * w) * u_band_ndc.xy;
    gl_Position = vec4(band_w, (2.0 * distance / u_far - 1.0) * w, w);
}
