/* A draw the driver skipped, caught (draw_check.h). */
#include "gl/draw_check.h"
#include "gl/quad.h"
#include "gl/texture.h"
#include <stdio.h>
#include <string.h>

#define CHECK_SAMPLERS 64

/* The program's samplers, each element of an array its own: their locations and units as the
 * stages left them. */
struct samplers {
    GLint location[CHECK_SAMPLERS], unit[CHECK_SAMPLERS];
    GLenum type[CHECK_SAMPLERS];
    int n;
};

static void samplers_read(GLuint program, struct samplers *s)
{
    GLint count = 0;
    glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
    s->n = 0;
    for (GLint i = 0; i < count; i++) {
        char name[128];
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(program, (GLuint)i, sizeof name, NULL, &size, &type, name);
        if (type != GL_SAMPLER_2D && type != GL_SAMPLER_CUBE)
            continue;
        char *bracket = strchr(name, '[');
        if (bracket)
            *bracket = '\0';
        for (GLint k = 0; k < size && s->n < CHECK_SAMPLERS; k++) {
            char element[160];
            snprintf(element, sizeof element, size > 1 ? "%s[%d]" : "%s", name, (int)k);
            GLint location = glGetUniformLocation(program, element);
            if (location < 0)
                continue;
            s->location[s->n] = location;
            s->type[s->n] = type;
            glGetUniformiv(program, location, &s->unit[s->n]);
            s->n++;
        }
    }
}

int draw_check_program(GLuint program, int skip)
{
    GLint framebuffer = 0, viewport[4], current = 0, texture = 0;
    GLfloat clear[4];
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &framebuffer);
    glGetIntegerv(GL_VIEWPORT, viewport);
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
    const GLenum tests[3] = {GL_DEPTH_TEST, GL_SCISSOR_TEST, GL_BLEND};
    GLboolean enabled[3];
    for (int i = 0; i < 3; i++) {
        enabled[i] = glIsEnabled(tests[i]);
        glDisable(tests[i]);
    }
    while (glGetError() != GL_NO_ERROR) {
    }
    GLuint target, fbo;
    int complete = texture_rgba8_target(1, 1, &target, &fbo);
    /* the program may sample the active unit: not the target it draws into */
    glBindTexture(GL_TEXTURE_2D, (GLuint)texture);
    int drawn = -1;
    if (complete) {
        static const GLfloat colours[2][4] = {{0.2f, 0.4f, 0.6f, 0.8f}, {0.8f, 0.6f, 0.4f, 0.2f}};
        unsigned char got[2][4];
        glViewport(0, 0, 1, 1);
        glUseProgram(program);
        quad_bind();
        /* samplers of two types on one unit are a GL error at the draw: the 2D ones on unit 0, the
         * cube maps on unit 1, for the check; put back after it */
        struct samplers s;
        samplers_read(program, &s);
        for (int i = 0; i < s.n; i++)
            glUniform1i(s.location[i], s.type[i] == GL_SAMPLER_CUBE ? 1 : 0);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        for (int k = 0; k < 2; k++) {
            glClearColor(colours[k][0], colours[k][1], colours[k][2], colours[k][3]);
            glClear(GL_COLOR_BUFFER_BIT);
            if (!skip)
                quad_draw(program, 0.0f);
            glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, got[k]);
        }
        for (int i = 0; i < s.n; i++)
            glUniform1i(s.location[i], s.unit[i]);
        /* a GL error: the check itself could not draw, and tells nothing */
        drawn = glGetError() != GL_NO_ERROR ? -1 : memcmp(got[0], got[1], 4) == 0;
    }
    texture_rgba8_target_release(target, fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, (GLuint)framebuffer);
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    /* the program in use may have been deleted since (a probe's): then none */
    glUseProgram(glIsProgram((GLuint)current) ? (GLuint)current : 0);
    glClearColor(clear[0], clear[1], clear[2], clear[3]);
    for (int i = 0; i < 3; i++)
        if (enabled[i])
            glEnable(tests[i]);
    return drawn;
}
