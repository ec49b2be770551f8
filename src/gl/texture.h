/* A 2D texture for one texel per pixel: nearest filtering, clamped, no initial data. */
#ifndef BT_TEXTURE_H
#define BT_TEXTURE_H
#include "gl/gl_api.h"
GLuint texture_create_nearest(GLint internal_format, GLenum format, GLenum type, int width, int height);
#endif
