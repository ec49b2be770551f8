/* The kiosk's compositor: a canvas of the refined frame's size that previews (upscaled) and
 * refined bands are drawn into, and the step that puts the canvas on the screen, letterboxed,
 * with the HUD blended over it. The renderer never draws to the screen itself, so a frame on
 * screen is always whole: the last preview with the bands refined so far over it. */
#ifndef BT_KIOSK_COMPOSITOR_H
#define BT_KIOSK_COMPOSITOR_H
#include <stddef.h>
#include "display/screen.h"
#include "io/error.h"
#include "render/renderer.h"
#include "kiosk/pipeline_layout.h"

struct compositor {
    int width, height;               /* the canvas: the refined frame */
    GLuint canvas, canvas_fbo;
    GLuint hud;                      /* RGBA8 texture of the screen's size, top row first */
    int hud_width, hud_height, hud_valid;
    int hud_top, hud_rows;           /* the HUD's rows that are not wholly transparent (top row first) */
    int framebuffer_blit;            /* the probe's: the canvas is copied to a screen of its size */
    GLuint blit, pipeline;           /* programs */
    int has_quad;                    /* holds a share of the pass quadrilateral */
    GLuint preview, preview_fbo;     /* a preview drawn tile by tile, shown once whole; 0 until then */
    int preview_width, preview_height;
};

/* The functions below that return int give 0, or -1 with e filled: a GL failure or no memory is the
 * machine's (ERROR_RUNTIME); compositor_init keeps the status of the probe and of the shaders'
 * build (a shader file missing under --shader-dir is the user's). */
int compositor_init(struct compositor *c, const struct gl_context *gl, int width, int height, struct error *e);
void compositor_release(struct compositor *c);

/* A whole frame rendered at lower resolution, upscaled over the whole canvas. */
int compositor_put_preview(struct compositor *c, GLuint image, struct error *e);
/* Rows [0, rows) of a band rendered at full width, into canvas rows [y0, y0 + rows) (GL order,
 * bottom-up); band_height: the height of the band's texture. weight: 1 replaces what the canvas
 * holds there, w < 1 blends the band in as w x band + (1 - w) x canvas (the anti-aliasing's mean). */
int compositor_put_band(struct compositor *c, GLuint image, int band_height, int y0, int rows, float weight,
                        struct error *e);
/* Rows [0, h) and columns [0, w) of a tile whose texture is tex_w x tex_h, into canvas pixels
 * [x0, x0 + w) x [y0, y0 + h) (GL order), with weight as compositor_put_band's. */
int compositor_put_tile(struct compositor *c, GLuint image, int tex_w, int tex_h, int x0, int y0, int w, int h,
                        float weight, struct error *e);
/* The same into an offscreen preview of pw x ph (made or resized here), and that preview, once
 * whole, upscaled over the canvas as compositor_put_preview draws a preview of one run. */
int compositor_put_preview_tile(struct compositor *c, GLuint image, int tex_w, int tex_h, int x0, int y0, int w,
                                int h, int pw, int ph, struct error *e);
int compositor_show_preview(struct compositor *c, struct error *e);
/* The pipeline view of a run's ray state: five panels (positions, directions, segment index of
 * the hit, step size, outcome) and the image, in a 3 x 2 grid over the canvas. With exact orbits
 * (t->orbit_table) the step-size panel shows the orbit table the run followed; with steps of fixed
 * size (steps_budget > 0: the steps every ray has) the steps each ray took. Each panel keeps the
 * frame's aspect ratio (round things stay round), centred in its cell (kiosk/pipeline_layout.h);
 * the bands above and below it are black but for the colour scales and the outcome's legend. */
int compositor_put_pipeline(struct compositor *c, const struct renderer_textures *t, double bound_radius,
                            int segments, double step, double steps_budget, struct error *e);
/* The HUD image (screen-sized, top row first, straight alpha), or NULL for none. */
int compositor_set_hud(struct compositor *c, const unsigned char *rgba, int width, int height, struct error *e);
/* Where compositor_draw puts the canvas on a screen of sw x sh: keeping its aspect ratio, centred;
 * x, y from the top-left corner. */
void compositor_letterbox(const struct compositor *c, int sw, int sh, int *x, int *y, int *w, int *h);
/* Canvas, letterboxed into the screen, then the HUD; the screen's present() is left to the caller. */
int compositor_draw(struct compositor *c, const struct screen *s, struct error *e);
/* The screen's framebuffer as RGBA8, top row first (w x h x 4 bytes), for PNG files. */
int compositor_read_screen(const struct screen *s, unsigned char *rgba, struct error *e);

#endif
