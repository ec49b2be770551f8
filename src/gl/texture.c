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
