/* The pipeline view's layout, shared by the compositor that draws its panels and the HUD that
 * labels them: six panels in a 3 x 2 grid of cells over the canvas, each with the frame's aspect
 * ratio (round things stay round), centred in its cell; the band above a panel holds its label,
 * the band below its colour scale or legend. Rectangles in pixels, x and y from the canvas's
 * top-left corner. */
#ifndef BT_KIOSK_PIPELINE_LAYOUT_H
#define BT_KIOSK_PIPELINE_LAYOUT_H

#define PIPELINE_COLUMNS 3
#define PIPELINE_ROWS 2
/* Panel k of a canvas of w x h: 0 the image, then positions, directions (top row), segment index
 * of the hit, step size, outcome (bottom row). */
void pipeline_panel_rect(int w, int h, int k, int *x, int *y, int *pw, int *ph);
/* The strip below panel k where its colour scale (segment of the hit, step size or orbit table)
 * or legend (outcome) is drawn, and the HUD's words under it (or on it, for positions and
 * directions, which have no strip): 0, or -1 where the band is too thin. */
int pipeline_legend_rect(int w, int h, int k, int *x, int *y, int *lw, int *lh);

#endif
