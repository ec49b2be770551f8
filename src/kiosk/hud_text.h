/* Text for the kiosk's head-up display, drawn with FreeType into an RGBA8 image that the
 * compositor lays over the frame. */
#ifndef BT_KIOSK_HUD_TEXT_H
#define BT_KIOSK_HUD_TEXT_H
#include <stddef.h>
#include "io/error.h"

struct hud_font;

/* NULL with e (where: the font file; the message: why) when the font cannot be read: the user's
 * (ERROR_INPUT) for a path that is refused or a file that is no usable font, the machine's for no
 * memory, a failed read or FreeType that cannot start. */
struct hud_font *hud_font_open(const char *path, struct error *e);
void hud_font_close(struct hud_font *f);

/* Width in pixels of UTF-8 text at pixel_height. */
int hud_text_width(struct hud_font *f, int pixel_height, const char *utf8);
/* Draws UTF-8 text into rgba (w x h, top row first, straight alpha) with its baseline at row y
 * and its pen starting at column x, blending colour (RGBA) over what is there; clipped to the
 * image. Returns the pen's advance. */
int hud_text_draw(struct hud_font *f, unsigned char *rgba, int w, int h, int x, int y, int pixel_height,
                  const char *utf8, const unsigned char color[4]);

#endif
