#include "gl/quad.h"
#include "gl/context.h"

/* The quad belongs to the current context (struct gl_context): a buffer name of one context means
 * nothing in the next. Without a registered context, one of its own. */
static struct gl_context orphan;

static struct gl_context *owner(void)
{
    struct gl_context *ctx = gl_context_current();
    return ctx ? ctx : &orphan;
}

int quad_init(void)
{
    static const GLfloat corners[] = {-1, -1, 1, -1, -1, 1, 1, 1};
    struct gl_context *ctx = owner();
    if (ctx->quad_users++ > 0) {
        quad_bind();
        return glGetError() == GL_NO_ERROR ? 0 : -1;
    }
    GLuint buffer = 0;
    glGenBuffers(1, &buffer);
    ctx->quad_buffer = buffer;
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, 0);
    glEnableVertexAttribArray(0);
    return glGetError() == GL_NO_ERROR ? 0 : -1;
}

void quad_release(void)
{
    struct gl_context *ctx = owner();
    if (ctx->quad_users > 0 && --ctx->quad_users > 0)
        return;
    if (ctx->quad_buffer) {
        GLuint buffer = ctx->quad_buffer;
        glDeleteBuffers(1, &buffer);
    }
    ctx->quad_buffer = 0;
}

void quad_bind(void)
{
    glBindBuffer(GL_ARRAY_BUFFER, owner()->quad_buffer);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, 0);
    glEnableVertexAttribArray(0);
    for (GLuint a = 1; a < 8; a++)     /* GLES2 guarantees 8 attributes; meshes used 1 and 2 */
        glDisableVertexAttribArray(a);
}

void quad_draw(GLuint program, float z)
{
    GLint loc = glGetUniformLocation(program, "u_quad_depth");
    if (loc >= 0)
        glUniform1f(loc, z);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}
