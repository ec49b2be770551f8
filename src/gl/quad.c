#include "gl/quad.h"

static GLuint quad_buffer;
/* renderers sharing the current context share the quad: the last one to go deletes it */
static int quad_users;

int quad_init(void)
{
    static const GLfloat corners[] = {-1, -1, 1, -1, -1, 1, 1, 1};
    if (quad_users++ > 0) {
        quad_bind();
        return glGetError() == GL_NO_ERROR ? 0 : -1;
    }
    glGenBuffers(1, &quad_buffer);
    glBindBuffer(GL_ARRAY_BUFFER, quad_buffer);
    glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, 0);
    glEnableVertexAttribArray(0);
    return glGetError() == GL_NO_ERROR ? 0 : -1;
}

void quad_release(void)
{
    if (quad_users > 0 && --quad_users > 0)
        return;
    if (quad_buffer)
        glDeleteBuffers(1, &quad_buffer);
    quad_buffer = 0;
}

void quad_bind(void)
{
    glBindBuffer(GL_ARRAY_BUFFER, quad_buffer);
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
