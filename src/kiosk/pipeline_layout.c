/* Where the pipeline view's panels lie on the canvas (pipeline_layout.h). */
#include "kiosk/pipeline_layout.h"

void pipeline_panel_rect(int w, int h, int k, int *x, int *y, int *pw, int *ph)
{
    int cell_w = w / PIPELINE_COLUMNS, cell_h = h / PIPELINE_ROWS;
    /* the frame's aspect w / h in a cell: as wide as the cell, or as high where that is narrower */
    int fit_w = cell_w, fit_h = (int)((double)cell_w * h / w + 0.5);
    if (fit_h > cell_h) {
        fit_h = cell_h;
        fit_w = (int)((double)cell_h * w / h + 0.5);
    }
    *pw = fit_w;
    *ph = fit_h;
    *x = (k % PIPELINE_COLUMNS) * cell_w + (cell_w - fit_w) / 2;
    *y = (k / PIPELINE_COLUMNS) * cell_h + (cell_h - fit_h) / 2;
}

int pipeline_legend_rect(int w, int h, int k, int *x, int *y, int *lw, int *lh)
{
    int px, py, pw, ph;
    pipeline_panel_rect(w, h, k, &px, &py, &pw, &ph);
    int band = (h / PIPELINE_ROWS - ph) / 2;
    /* a twentieth of the panel in from each side, so that the words at the ends of two scales side
     * by side stay apart */
    *x = px + pw / 20;
    *y = py + ph + band / 6;
    *lw = pw - 2 * (pw / 20);
    *lh = band / 3;
    return *lh >= 2 ? 0 : -1;
}
