/* Whether the driver really draws with a program. A driver may link a program and then skip every
 * draw with it, without a GL error: Mesa's VC4 does so when its register allocator cannot hold the
 * program ("Failed to register allocate", on stderr at most). A picture drawn with such a program
 * would be wrong without a word, so each program is drawn once here before a pass uses it. */
#ifndef BT_DRAW_CHECK_H
#define BT_DRAW_CHECK_H
#include "gl/gl_api.h"

/* The pass quad drawn with PROGRAM into a 1x1 RGBA8 target cleared first to one colour, then to
 * another: a program that ran writes the same texel both times, which cannot match both colours;
 * a draw the driver skipped leaves each colour as it was. The state a pass sets (framebuffer,
 * viewport, program, depth, scissor and blend tests, clear colour, the active unit's texture) is
 * put back; the pass quad is left bound, as every pass draws it. skip: draw nothing, as such a driver would (BT_FAULT=draw_skipped).
 * 1: drawn; 0: skipped; -1: no RGBA8 target to check with (nothing known). */
int draw_check_program(GLuint program, int skip);

#endif
