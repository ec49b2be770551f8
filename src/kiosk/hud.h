/* The kiosk's head-up display: what the visitor has set, in words and units, drawn over the frame.
 * Pure: it draws into an RGBA8 image (top row first, transparent where there is no HUD) that the
 * compositor blends over the picture; it never touches GL. */
#ifndef BT_KIOSK_HUD_H
#define BT_KIOSK_HUD_H
#include "kiosk/hud_text.h"

#define HUD_LINE_LEN 160
#define HUD_MAX_LINES 8

enum hud_knob { HUD_KNOB_NONE, HUD_KNOB_SPEED, HUD_KNOB_MASS };

struct hud_view {
    /* Visitors read a title, a caption and the knobs in plain words; staff mode (the kiosk's
     * staff_mode action) adds the scene file's name and description, the keys with their values,
     * the symbols and the frame rate. */
    int staff;
    const char *title;               /* the scene's title for visitors ([kiosk] title, else its name) */
    const char *caption;             /* one line for visitors ([kiosk] caption), or NULL */
    const char *name;                /* staff: the scene's name */
    const char *explanation;         /* staff: the scene file's description */
    int has_speed;                   /* the scene lets the observer move */
    double speed;                    /* v/c; the HUD shows gamma too */
    int has_mass;                    /* the scene has a central mass (Schwarzschild) */
    double mass;                     /* M in the scene's unit; the HUD shows r_s = 2M */
    double camera_distance;          /* from the mass, the scene's unit: fixed while M changes */
    double shadow_share;             /* the black hole's shadow: its diameter over the view's height */
    /* a knob the scene maps to one of its keys ([kiosk] of the scene file): the key ("model.rho")
     * and its value; NULL where the knob keeps its meaning */
    const char *speed_key, *mass_key;
    double speed_param, mass_param;
    /* what each knob changes in a visitor's words ([kiosk] speed_label, mass_label), or NULL; a
     * mapped knob's range (its key's values at the knob's two ends): visitors read how far along it is */
    const char *speed_label, *mass_label;
    double speed_range[2], mass_range[2];
    int effects;                     /* the effects shown (enum relativity_effects); < 0 where the
                                        scene has no black body to shift */
    int gravitational_shift;         /* 1: gravity's shift among them (a scene with a mass) */
    double fps;                      /* staff: frames shown per second, measured; <= 0: not shown */
    int refining;                    /* 1 while the picture is still being refined */
    /* The knob turned in the last moments: a short indicator of its value within its range. */
    enum hud_knob indicator;
    double indicator_value, indicator_min, indicator_max;
    const char *notice;              /* one line of warning (a limit reached), or NULL */
    /* The pipeline view (compositor_put_pipeline's 3 x 2 panels over the canvas): each panel gets
     * its label in its top-left corner, and the block of lines gives way to the scene's name in
     * the image panel's label. canvas_*: where the canvas lies on the screen (top-down pixels). */
    int pipeline_view;
    int orbit_table;                 /* exact orbits: the step-size panel shows the orbit table */
    int fixed_steps;                 /* steps of fixed size: that panel shows the steps each ray took */
    int far_steps;                   /* ... that grow away from the objects: the path each ray took */
    int canvas_x, canvas_y, canvas_w, canvas_h;
};

/* The pipeline view's panels, left to right, top row first. */
#define HUD_PIPELINE_PANELS 6
extern const char *const hud_pipeline_labels[HUD_PIPELINE_PANELS];
/* The step-size panel's label where it shows the orbit table, and that panel's index. */
#define HUD_PIPELINE_TABLE_PANEL 4
extern const char *const hud_pipeline_table_label;
/* Its label where it shows the steps each ray took, and where it shows the path (far steps). */
extern const char *const hud_pipeline_steps_label;
extern const char *const hud_pipeline_path_label;

/* The HUD's text, one line per entry (title, caption, knobs in words, colours, notice; in staff
 * mode the name, description, knobs with symbols and keys, effects, fps), for the log and for
 * tests; returns the number of lines. */
int hud_lines(const struct hud_view *v, char lines[][HUD_LINE_LEN], int max);
/* Draws the HUD into rgba (w x h), clearing it first. Text height scales with h so that it reads
 * the same at 720p and 1080p; a translucent band behind the text keeps it legible over any
 * picture. font NULL: clears only. */
void hud_draw(struct hud_font *font, unsigned char *rgba, int w, int h, const struct hud_view *v);

#endif
