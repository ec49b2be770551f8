/* A 2D texture with no initial data, clamped at its edges: nearest filtering for one texel per
 * pixel, linear where a texture is drawn at another size. */
#ifndef BT_TEXTURE_H
#define BT_TEXTURE_H
#include "gl/gl_api.h"
/* filter: GL_NEAREST or GL_LINEAR, for minification and magnification alike. */
GLuint texture_create(GLint internal_format, GLenum format, GLenum type, int width, int height, GLint filter);
GLuint texture_create_nearest(GLint internal_format, GLenum format, GLenum type, int width, int height);
/* The same in two steps: a texture name with nearest filtering and clamped edges but no storage
 * (no memory yet), and its storage, given once it is needed. */
GLuint texture_name_nearest(void);
void texture_define(GLuint tex, GLint internal_format, GLenum format, GLenum type, int width, int height);
#endif
