/* The viewport-filling quadrilateral every pass draws. */
#ifndef BT_QUAD_H
#define BT_QUAD_H
#include "gl/gl_api.h"
int quad_init(void);
void quad_release(void);
/* Make the quad's vertex array current again (after a stage that drew meshes). */
void quad_bind(void);
/* Draw the quad with the bound program at constant depth z (NDC, -1..1). */
void quad_draw(GLuint program, float z);
#endif
