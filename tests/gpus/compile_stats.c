/* compile_stats: compiles and draws shader programs, as bentray wrote them (BT_SHADER_DUMP), on
 * whatever GLES driver EGL's surfaceless platform opens: under tests/gpus/shader_stats.sh that is
 * one of Mesa's drivers for the exhibit's GPUs over its noop drm-shim, which compiles real code for
 * that GPU and draws nothing. Each program is linked, then drawn once into RGBA8 targets (one per
 * gl_FragData it writes), so that the driver compiles the variant a draw needs as well as the one
 * it may compile at link time. A driver compiles that variant for the textures bound: V3D, for one,
 * returns an 8-bit texture's texels as packed 16-bit pairs and a 32-bit float texture's as four
 * registers. So each sampler gets a texture of the format bentray binds to it (sampler_format):
 * the ray state and the orbit table in the best float format the GPU samples (bentray's own path
 * ladder takes 32-bit floats first, docs/HARDWARE.md), everything else RGBA8.
 *
 *   compile_stats STEM...      (STEM.vert and STEM.frag; none: the driver's capabilities only)
 *
 * Everything goes to stderr, in order with the driver's own statistics lines (written there or
 * through KHR_debug, whose messages are printed as "KHR: ..."):
 *   == program STEM
 *   == result STEM ok|compile|link|draw cpu_ms=N [first line of the log, or the draw's GL error]
 *   == end STEM
 * Exit 0 where every program was handled (a program that does not compile is a result, not a
 * failure), 1 where no context could be made or a file not read. */
#define _GNU_SOURCE
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES2/gl2.h>
#include <GLES2/gl2ext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif

static PFNGLDRAWBUFFERSEXTPROC draw_buffers;

static void GL_APIENTRY on_message(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                                   const GLchar *message, const void *arg)
{
    (void)source, (void)type, (void)id, (void)severity, (void)arg;
    fprintf(stderr, "KHR: %.*s\n", length > 0 ? (int)length : (int)strlen(message), message);
}

static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap);
    for (size_t got; buf && (got = fread(buf + n, 1, cap - n - 1, f)) > 0;) {
        n += got;
        if (n + 1 == cap) {
            char *bigger = realloc(buf, cap *= 2);
            if (!bigger)
                free(buf);
            buf = bigger;
        }
    }
    fclose(f);
    if (buf)
        buf[n] = '\0';
    return buf;
}

static double cpu_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

/* The first line of a shader's or program's log that says "error" (else its first line), into out. */
static void first_line(GLuint object, int is_program, char *out, size_t n)
{
    char log[8192] = "";
    if (is_program)
        glGetProgramInfoLog(object, sizeof log, NULL, log);
    else
        glGetShaderInfoLog(object, sizeof log, NULL, log);
    const char *line = log;
    for (const char *p = log; *p; p += strcspn(p, "\n") + (p[strcspn(p, "\n")] != '\0'))
        if (strstr(p, "error") && strstr(p, "error") < p + strcspn(p, "\n")) {
            line = p;
            break;
        }
    size_t len = strcspn(line, "\n");
    snprintf(out, n, "%.*s", (int)(len < 300 ? len : 300), line);
}

static GLuint compile(GLenum stage, const char *text, char *why, size_t n)
{
    GLuint sh = glCreateShader(stage);
    glShaderSource(sh, 1, &text, NULL);
    glCompileShader(sh);
    GLint ok = 0;
    glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        first_line(sh, 0, why, n);
        glDeleteShader(sh);
        return 0;
    }
    return sh;
}

/* How many colour targets the fragment shader writes: 1 + the highest gl_FragData index. */
static int targets_written(const char *fragment)
{
    int most = 1;
    for (const char *p = fragment; (p = strstr(p, "gl_FragData[")) != NULL; p += 12) {
        int i = atoi(p + 12);
        if (i + 1 > most && i < 8)
            most = i + 1;
    }
    return most;
}

/* The texture bentray binds to sampler NAME of a program: 1 for float data (the ray state's
 * textures, src/render/raystate.c, and the orbit table, src/render/orbit_store.c), 0 for 8-bit
 * colour (objects' textures, the sky, the black-body table, the orbit walk's bytes, the kiosk's
 * canvas). u_image is the ray state's image everywhere but in the kiosk's blit, which copies its
 * 8-bit canvas. On the packed path every texture holds bytes. */
static int sampler_holds_floats(const char *name, const char *fragment)
{
    static const char *const floats[] = {"u_orbit_table", "u_hit", "u_image", "u_position", "u_velocity",
                                         "u_ray_position", "u_ray_velocity", "u_segment_start", "u_segment_end",
                                         "u_state0", "u_state1", "u_outcome", NULL};
    if (strcmp(name, "u_image") == 0 && strstr(fragment, "// shaders_es/kiosk_blit.glsl"))
        return 0;
    /* the packed path's ray state and orbit table: bytes (render/path.h) */
    if (strstr(fragment, "#define STATE_PACKED 1"))
        return 0;
    for (int i = 0; floats[i]; i++)
        if (strcmp(name, floats[i]) == 0)
            return 1;
    return 0;
}

/* The best float format this GPU samples, as bentray's probe would find it: 32-bit floats in
 * OpenGL ES 3 or with OES_texture_float, else 16-bit with OES_texture_half_float, else none
 * (0: RGBA8 then, the draw compiles whatever it can). */
static GLenum float_texel_type(void)
{
    const char *version = (const char *)glGetString(GL_VERSION);
    const char *ext = (const char *)glGetString(GL_EXTENSIONS);
    int es3 = version && strstr(version, "OpenGL ES 3") != NULL;
    if (es3 || (ext && strstr(ext, "GL_OES_texture_float")))
        return GL_FLOAT;
    if (ext && strstr(ext, "GL_OES_texture_half_float"))
        return 0x8D61; /* GL_HALF_FLOAT_OES */
    return 0;
}

/* A complete 1x1 texture of the sampler's type on the active unit (floats: see sampler_holds_floats):
 * an incomplete one would make the GL build a fallback texture, and wait for the GPU there, which a
 * noop shim never answers. */
static GLuint bind_texture(GLenum type, int floats)
{
    static const unsigned char texel[4] = {128, 128, 128, 255};
    static const float float_texel[4] = {0.5f, 0.5f, 0.5f, 1.0f};
    static const unsigned short half_texel[4] = {0x3800, 0x3800, 0x3800, 0x3c00};
    GLenum target = type == GL_SAMPLER_CUBE ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
    GLenum float_type = floats && target == GL_TEXTURE_2D ? float_texel_type() : 0;
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(target, tex);
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    const char *version = (const char *)glGetString(GL_VERSION);
    int es3 = version && strstr(version, "OpenGL ES 3") != NULL;
    if (float_type == GL_FLOAT)
        /* ES 3: the sized RGBA32F, as bentray allocates it; ES 2: the unsized OES form */
        glTexImage2D(GL_TEXTURE_2D, 0, es3 ? 0x8814 /* GL_RGBA32F */ : GL_RGBA, 1, 1, 0, GL_RGBA, GL_FLOAT, float_texel);
    else if (float_type)
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, float_type, half_texel);
    else if (target == GL_TEXTURE_2D)
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    else
        for (int face = 0; face < 6; face++)
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    return tex;
}

/* Each sampler its own texture unit (samplers of two types on one unit, both on unit 0 as they
 * start, make the draw an error, and the driver then compiles nothing for it), with a texture. */
static void spread_samplers(GLuint prog, const char *fragment)
{
    GLint count = 0, unit = 0, units = 8;
    glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &units);
    glGetProgramiv(prog, GL_ACTIVE_UNIFORMS, &count);
    glUseProgram(prog);
    for (GLint i = 0; i < count; i++) {
        char name[256];
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(prog, (GLuint)i, sizeof name, NULL, &size, &type, name);
        if (type != GL_SAMPLER_2D && type != GL_SAMPLER_CUBE)
            continue;
        GLint location = glGetUniformLocation(prog, name);
        for (GLint k = 0; k < size && unit < units; k++) {
            glActiveTexture(GL_TEXTURE0 + unit);
            bind_texture(type, sampler_holds_floats(name, fragment));
            glUniform1i(location + k, unit++);
        }
    }
    glActiveTexture(GL_TEXTURE0);
}

/* Draws the program once; returns the first GL error of the draw (GL_NO_ERROR where it drew). */
static GLenum draw_once(GLuint prog, int targets, const char *fragment)
{
    GLint most = 1;
    if (targets > 1)
        glGetIntegerv(GL_MAX_DRAW_BUFFERS_EXT, &most);
    if (targets > most || (targets > 1 && !draw_buffers))
        targets = 1;
    GLuint tex[8], fbo;
    GLenum bufs[8];
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glGenTextures(targets, tex);
    for (int i = 0; i < targets; i++) {
        glBindTexture(GL_TEXTURE_2D, tex[i]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + i, GL_TEXTURE_2D, tex[i], 0);
        bufs[i] = GL_COLOR_ATTACHMENT0 + i;
    }
    if (targets > 1)
        draw_buffers(targets, bufs);
    static const float corners[] = {-1, -1, 1, -1, -1, 1, 1, 1};
    GLuint vbo;
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, NULL);
    glEnableVertexAttribArray(0);
    glViewport(0, 0, 8, 8);
    spread_samplers(prog, fragment);
    while (glGetError() != GL_NO_ERROR) {
    }
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    GLenum error = glGetError();
    /* the compile is done within the draw; glFinish would wait for a GPU that a noop shim never runs */
    glFlush();
    glDeleteBuffers(1, &vbo);
    glDeleteTextures(targets, tex);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    return error;
}

static int one_program(const char *stem)
{
    char path[4096];
    snprintf(path, sizeof path, "%s.vert", stem);
    char *vertex = read_text(path);
    snprintf(path, sizeof path, "%s.frag", stem);
    char *fragment = read_text(path);
    if (!vertex || !fragment) {
        fprintf(stderr, "compile_stats: cannot read %s.vert and .frag\n", stem);
        free(vertex);
        free(fragment);
        return 1;
    }
    fprintf(stderr, "== program %s\n", stem);
    char why[400] = "";
    const char *result = "ok";
    double t0 = cpu_ms();
    GLuint vs = compile(GL_VERTEX_SHADER, vertex, why, sizeof why);
    GLuint fs = vs ? compile(GL_FRAGMENT_SHADER, fragment, why, sizeof why) : 0;
    GLuint prog = 0;
    if (!vs || !fs) {
        result = "compile";
    } else {
        prog = glCreateProgram();
        glAttachShader(prog, vs);
        glAttachShader(prog, fs);
        glBindAttribLocation(prog, 0, "a_corner");
        glBindAttribLocation(prog, 0, "a_rest_position");
        glLinkProgram(prog);
        GLint ok = 0;
        glGetProgramiv(prog, GL_LINK_STATUS, &ok);
        if (!ok) {
            first_line(prog, 1, why, sizeof why);
            result = "link";
        } else {
            GLenum error = draw_once(prog, targets_written(fragment), fragment);
            if (error != GL_NO_ERROR) {
                snprintf(why, sizeof why, "GL error 0x%04x at the draw", error);
                result = "draw";
            }
        }
    }
    double t1 = cpu_ms();
    fprintf(stderr, "== result %s %s cpu_ms=%.0f %s\n", stem, result, t1 - t0, why);
    if (prog)
        glDeleteProgram(prog);
    if (vs)
        glDeleteShader(vs);
    if (fs)
        glDeleteShader(fs);
    while (glGetError() != GL_NO_ERROR) {
    }
    fprintf(stderr, "== end %s\n", stem);
    free(vertex);
    free(fragment);
    return 0;
}

/* What the driver offers of what bentray's paths need (docs/HARDWARE.md):
 *   == caps gles=MAJOR.MINOR float_textures=yes|no half_float_textures=yes|no
 *      float_targets=yes|no|untested half_float_targets=yes|no draw_buffers=N highp_bits=N
 * ES 3 samples 32- and 16-bit float textures in core (NEAREST); rendering to them takes
 * EXT_color_buffer_float (ES 3) or EXT_color_buffer_half_float (ES 2 and 3). */
static void print_caps(void)
{
    const char *version = (const char *)glGetString(GL_VERSION);
    int major = 2, minor = 0;
    if (version)
        sscanf(version, "OpenGL ES %d.%d", &major, &minor);
    const char *ext = (const char *)glGetString(GL_EXTENSIONS);
    ext = ext ? ext : "";
#define HAS(name) (strstr(ext, name " ") != NULL || (strlen(ext) >= strlen(name) && \
                   strcmp(ext + strlen(ext) - strlen(name), name) == 0))
    int float_tex = major >= 3 || HAS("GL_OES_texture_float");
    int half_tex = major >= 3 || HAS("GL_OES_texture_half_float");
    /* ES 2 names no extension for 32-bit float targets: only a draw and a read-back tell (bentray's
     * probe does that; a noop shim cannot), so "untested" */
    const char *float_target = major >= 3 ? (HAS("GL_EXT_color_buffer_float") ? "yes" : "no")
                                          : HAS("GL_OES_texture_float") ? "untested" : "no";
    int half_target = HAS("GL_EXT_color_buffer_half_float") || (major >= 3 && HAS("GL_EXT_color_buffer_float"));
    GLint buffers = 1;
    if (major >= 3 || HAS("GL_EXT_draw_buffers"))
        glGetIntegerv(GL_MAX_DRAW_BUFFERS_EXT, &buffers);
#undef HAS
    GLint range[2] = {0, 0}, precision = 0;
    glGetShaderPrecisionFormat(GL_FRAGMENT_SHADER, GL_HIGH_FLOAT, range, &precision);
    while (glGetError() != GL_NO_ERROR) {
    }
    fprintf(stderr, "== caps gles=%d.%d float_textures=%s half_float_textures=%s float_targets=%s "
            "half_float_targets=%s draw_buffers=%d highp_bits=%d\n", major, minor, float_tex ? "yes" : "no",
            half_tex ? "yes" : "no", float_target, half_target ? "yes" : "no", buffers, precision);
}

int main(int argc, char **argv)
{
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    EGLDisplay dpy = get_display ? get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL)
                                 : EGL_NO_DISPLAY;
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, NULL, NULL) || !eglBindAPI(EGL_OPENGL_ES_API)) {
        fprintf(stderr, "compile_stats: no surfaceless EGL display\n");
        return 1;
    }
    EGLContext ctx = EGL_NO_CONTEXT;
    for (int major = 3; major >= 2 && ctx == EGL_NO_CONTEXT; major--) {
        const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, major, EGL_NONE};
        ctx = eglCreateContext(dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    }
    if (ctx == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
        fprintf(stderr, "compile_stats: no GLES context\n");
        return 1;
    }
    fprintf(stderr, "== renderer %s | %s\n", (const char *)glGetString(GL_RENDERER),
            (const char *)glGetString(GL_VERSION));
    print_caps();
    draw_buffers = (PFNGLDRAWBUFFERSEXTPROC)eglGetProcAddress("glDrawBuffersEXT");
    PFNGLDEBUGMESSAGECALLBACKKHRPROC callback =
        (PFNGLDEBUGMESSAGECALLBACKKHRPROC)eglGetProcAddress("glDebugMessageCallbackKHR");
    if (callback) {
        glEnable(GL_DEBUG_OUTPUT_KHR);
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR);
        callback(on_message, NULL);
    }
    int failed = 0;
    for (int i = 1; i < argc; i++)
        failed |= one_program(argv[i]);
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(dpy, ctx);
    eglTerminate(dpy);
    return failed;
}
