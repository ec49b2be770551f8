/* The GL entry points bentray uses, loaded at run time from the current context's back-end.
 * EGL/GLES and OSMesa both export gl* symbols; calling through one table that the active
 * back-end filled keeps them apart in one binary. Rendering code calls the usual gl* names. */
#ifndef BT_GL_API_H
#define BT_GL_API_H
#include <stddef.h>
#include <GLES3/gl3.h>
#include <GLES2/gl2ext.h>
#include "io/error.h"

#ifndef GL_HALF_FLOAT_OES
#define GL_HALF_FLOAT_OES 0x8D61
#endif

/* X(return type, name without "gl", parameter list) */
#define BT_GL_FUNCTIONS(X) \
    X(void, ActiveTexture, (GLenum texture)) \
    X(void, AttachShader, (GLuint program, GLuint shader)) \
    X(void, BindAttribLocation, (GLuint program, GLuint index, const GLchar *name)) \
    X(void, BindBuffer, (GLenum target, GLuint buffer)) \
    X(void, BindFramebuffer, (GLenum target, GLuint framebuffer)) \
    X(void, BindRenderbuffer, (GLenum target, GLuint renderbuffer)) \
    X(void, BindTexture, (GLenum target, GLuint texture)) \
    X(void, BlendFunc, (GLenum sfactor, GLenum dfactor)) \
    X(void, BufferData, (GLenum target, GLsizeiptr size, const void *data, GLenum usage)) \
    X(GLenum, CheckFramebufferStatus, (GLenum target)) \
    X(void, Clear, (GLbitfield mask)) \
    X(void, ClearColor, (GLfloat r, GLfloat g, GLfloat b, GLfloat a)) \
    X(void, ClearDepthf, (GLfloat d)) \
    X(void, CompileShader, (GLuint shader)) \
    X(GLuint, CreateProgram, (void)) \
    X(GLuint, CreateShader, (GLenum type)) \
    X(void, DeleteBuffers, (GLsizei n, const GLuint *buffers)) \
    X(void, DeleteFramebuffers, (GLsizei n, const GLuint *framebuffers)) \
    X(void, DeleteProgram, (GLuint program)) \
    X(void, DeleteRenderbuffers, (GLsizei n, const GLuint *renderbuffers)) \
    X(void, DeleteShader, (GLuint shader)) \
    X(void, DeleteTextures, (GLsizei n, const GLuint *textures)) \
    X(void, DepthFunc, (GLenum func)) \
    X(void, DepthMask, (GLboolean flag)) \
    X(void, Disable, (GLenum cap)) \
    X(void, DrawArrays, (GLenum mode, GLint first, GLsizei count)) \
    X(void, Enable, (GLenum cap)) \
    X(void, EnableVertexAttribArray, (GLuint index)) \
    X(void, Finish, (void)) \
    X(void, FramebufferRenderbuffer, (GLenum target, GLenum attachment, GLenum rbtarget, GLuint rb)) \
    X(void, FramebufferTexture2D, (GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level)) \
    X(void, GenBuffers, (GLsizei n, GLuint *buffers)) \
    X(void, GenFramebuffers, (GLsizei n, GLuint *framebuffers)) \
    X(void, GenRenderbuffers, (GLsizei n, GLuint *renderbuffers)) \
    X(void, GenTextures, (GLsizei n, GLuint *textures)) \
    X(void, GetActiveUniform, (GLuint program, GLuint index, GLsizei bufSize, GLsizei *length, GLint *size, \
                               GLenum *type, GLchar *name)) \
    X(GLenum, GetError, (void)) \
    X(void, GetIntegerv, (GLenum pname, GLint *data)) \
    X(void, GetProgramInfoLog, (GLuint program, GLsizei bufSize, GLsizei *length, GLchar *infoLog)) \
    X(void, GetProgramiv, (GLuint program, GLenum pname, GLint *params)) \
    X(void, GetShaderInfoLog, (GLuint shader, GLsizei bufSize, GLsizei *length, GLchar *infoLog)) \
    X(void, GetShaderiv, (GLuint shader, GLenum pname, GLint *params)) \
    X(void, GetShaderPrecisionFormat, (GLenum shadertype, GLenum precisiontype, GLint *range, GLint *precision)) \
    X(const GLubyte *, GetString, (GLenum name)) \
    X(GLint, GetUniformLocation, (GLuint program, const GLchar *name)) \
    X(void, LinkProgram, (GLuint program)) \
    X(void, PixelStorei, (GLenum pname, GLint param)) \
    X(void, ReadPixels, (GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type, void *pixels)) \
    X(void, RenderbufferStorage, (GLenum target, GLenum internalformat, GLsizei width, GLsizei height)) \
    X(void, ShaderSource, (GLuint shader, GLsizei count, const GLchar *const *string, const GLint *length)) \
    X(void, TexImage2D, (GLenum target, GLint level, GLint internalformat, GLsizei width, GLsizei height, GLint border, GLenum format, GLenum type, const void *pixels)) \
    X(void, TexParameteri, (GLenum target, GLenum pname, GLint param)) \
    X(void, TexSubImage2D, (GLenum target, GLint level, GLint xoffset, GLint yoffset, GLsizei width, GLsizei height, GLenum format, GLenum type, const void *pixels)) \
    X(void, Uniform1f, (GLint location, GLfloat v0)) \
    X(void, Uniform1i, (GLint location, GLint v0)) \
    X(void, Uniform2f, (GLint location, GLfloat v0, GLfloat v1)) \
    X(void, Uniform3f, (GLint location, GLfloat v0, GLfloat v1, GLfloat v2)) \
    X(void, Uniform4f, (GLint location, GLfloat v0, GLfloat v1, GLfloat v2, GLfloat v3)) \
    X(void, UseProgram, (GLuint program)) \
    X(void, VertexAttribPointer, (GLuint index, GLint size, GLenum type, GLboolean normalized, GLsizei stride, const void *pointer)) \
    X(void, Viewport, (GLint x, GLint y, GLsizei width, GLsizei height))

/* Entry points of OpenGL ES 3 and desktop GL that a GLES2 context may offer as an extension:
 * glNAME, else glNAMEEXT (EXT_draw_buffers, EXT_occlusion_query_boolean); NULL if neither.
 * glBlitFramebuffer (OpenGL ES 3) copies the kiosk's canvas to its screen. A loader may hand out a pointer for a function the context lacks: gl/caps.c proves each by
 * rendering before it is used. */
#define BT_GL_OPTIONAL_FUNCTIONS(X) \
    X(void, DrawBuffers, (GLsizei n, const GLenum *bufs)) \
    X(void, GenQueries, (GLsizei n, GLuint *ids)) \
    X(void, DeleteQueries, (GLsizei n, const GLuint *ids)) \
    X(void, BeginQuery, (GLenum target, GLuint id)) \
    X(void, EndQuery, (GLenum target)) \
    X(void, GetQueryObjectuiv, (GLuint id, GLenum pname, GLuint *params)) \
    X(void, BlitFramebuffer, (GLint srcX0, GLint srcY0, GLint srcX1, GLint srcY1, GLint dstX0, GLint dstY0, \
                              GLint dstX1, GLint dstY1, GLbitfield mask, GLenum filter))

struct gl_api {
#define BT_GL_MEMBER(ret, name, args) ret (GL_APIENTRY *name) args;
    BT_GL_FUNCTIONS(BT_GL_MEMBER)
    BT_GL_OPTIONAL_FUNCTIONS(BT_GL_MEMBER)
#undef BT_GL_MEMBER
};

extern struct gl_api bt_gl;

/* Fill bt_gl with get_proc; returns NULL on success or the name of the first missing function. */
const char *gl_api_load(void *(*get_proc)(const char *name));

#define glActiveTexture bt_gl.ActiveTexture
#define glAttachShader bt_gl.AttachShader
#define glBindAttribLocation bt_gl.BindAttribLocation
#define glBindBuffer bt_gl.BindBuffer
#define glBindFramebuffer bt_gl.BindFramebuffer
#define glBindRenderbuffer bt_gl.BindRenderbuffer
#define glBindTexture bt_gl.BindTexture
#define glBlendFunc bt_gl.BlendFunc
#define glBufferData bt_gl.BufferData
#define glCheckFramebufferStatus bt_gl.CheckFramebufferStatus
#define glClear bt_gl.Clear
#define glClearColor bt_gl.ClearColor
#define glClearDepthf bt_gl.ClearDepthf
#define glCompileShader bt_gl.CompileShader
#define glCreateProgram bt_gl.CreateProgram
#define glCreateShader bt_gl.CreateShader
#define glDeleteBuffers bt_gl.DeleteBuffers
#define glDeleteFramebuffers bt_gl.DeleteFramebuffers
#define glDeleteProgram bt_gl.DeleteProgram
#define glDeleteRenderbuffers bt_gl.DeleteRenderbuffers
#define glDeleteShader bt_gl.DeleteShader
#define glDeleteTextures bt_gl.DeleteTextures
#define glDepthFunc bt_gl.DepthFunc
#define glDepthMask bt_gl.DepthMask
#define glDisable bt_gl.Disable
#define glDrawArrays bt_gl.DrawArrays
#define glDrawBuffers bt_gl.DrawBuffers
#define glGenQueries bt_gl.GenQueries
#define glDeleteQueries bt_gl.DeleteQueries
#define glBeginQuery bt_gl.BeginQuery
#define glEndQuery bt_gl.EndQuery
#define glGetQueryObjectuiv bt_gl.GetQueryObjectuiv
#define glBlitFramebuffer bt_gl.BlitFramebuffer
#define glEnable bt_gl.Enable
#define glEnableVertexAttribArray bt_gl.EnableVertexAttribArray
#define glFinish bt_gl.Finish
#define glFramebufferRenderbuffer bt_gl.FramebufferRenderbuffer
#define glFramebufferTexture2D bt_gl.FramebufferTexture2D
#define glGenBuffers bt_gl.GenBuffers
#define glGenFramebuffers bt_gl.GenFramebuffers
#define glGenRenderbuffers bt_gl.GenRenderbuffers
#define glGenTextures bt_gl.GenTextures
#define glGetActiveUniform bt_gl.GetActiveUniform
#define glGetError bt_gl.GetError
#define glGetIntegerv bt_gl.GetIntegerv
#define glGetProgramInfoLog bt_gl.GetProgramInfoLog
#define glGetProgramiv bt_gl.GetProgramiv
#define glGetShaderInfoLog bt_gl.GetShaderInfoLog
#define glGetShaderiv bt_gl.GetShaderiv
#define glGetShaderPrecisionFormat bt_gl.GetShaderPrecisionFormat
#define glGetString bt_gl.GetString
#define glGetUniformLocation bt_gl.GetUniformLocation
#define glLinkProgram bt_gl.LinkProgram
#define glPixelStorei bt_gl.PixelStorei
#define glReadPixels bt_gl.ReadPixels
#define glRenderbufferStorage bt_gl.RenderbufferStorage
#define glShaderSource bt_gl.ShaderSource
#define glTexImage2D bt_gl.TexImage2D
#define glTexSubImage2D bt_gl.TexSubImage2D
#define glTexParameteri bt_gl.TexParameteri
#define glUniform1f bt_gl.Uniform1f
#define glUniform1i bt_gl.Uniform1i
#define glUniform2f bt_gl.Uniform2f
#define glUniform3f bt_gl.Uniform3f
#define glUniform4f bt_gl.Uniform4f
#define glUseProgram bt_gl.UseProgram
#define glVertexAttribPointer bt_gl.VertexAttribPointer
#define glViewport bt_gl.Viewport

/* Name of a GL error code, for messages. */
const char *gl_error_name(GLenum e);
/* Check glGetError at a stage boundary; on error fill e with "STAGE: GL_xxx" (ERROR_RUNTIME) and
 * return -1. */
int gl_check(const char *stage, struct error *e);

#endif
