#include "gl/texture.h"

static GLuint texture_name(GLint filter)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return tex;
}

void texture_define(GLuint tex, GLint internal_format, GLenum format, GLenum type, int width, int height)
{
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, internal_format, width, height, 0, format, type, NULL);
}

GLuint texture_create(GLint internal_format, GLenum format, GLenum type, int width, int height, GLint filter)
{
    GLuint tex = texture_name(filter);
    texture_define(tex, internal_format, format, type, width, height);
    return tex;
}

GLuint texture_name_nearest(void)
{
    return texture_name(GL_NEAREST);
}

GLuint texture_create_nearest(GLint internal_format, GLenum format, GLenum type, int width, int height)
{
    return texture_create(internal_format, format, type, width, height, GL_NEAREST);
}

int texture_rgba8_target(int width, int height, GLuint *tex, GLuint *fbo)
{
    *tex = texture_create_nearest(GL_RGBA, GL_RGBA, GL_UNSIGNED_BYTE, width, height);
    glGenFramebuffers(1, fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, *fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, *tex, 0);
    return glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

void texture_rgba8_target_release(GLuint tex, GLuint fbo)
{
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(1, &tex);
}
