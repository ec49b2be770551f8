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
/* An RGBA8 target of width x height for a probe or a check: its texture (nearest, no data, left
 * bound to the active unit) and a framebuffer on it, bound. Whether that framebuffer is complete;
 * both are made either way, for texture_rgba8_target_release. */
int texture_rgba8_target(int width, int height, GLuint *tex, GLuint *fbo);
/* Deletes them, the default framebuffer bound. */
void texture_rgba8_target_release(GLuint tex, GLuint fbo);
#endif
