/* What the kiosk shows of one scene: the scene file, the renderer drawing it as the visitor's
 * state says, and the progression from a quick preview to the refined frame.
 *
 * A change of state draws a preview at once: the preview size, with steps PREVIEW_STEP_FACTOR
 * times longer, PREVIEW_SEGMENT_FACTOR times more of them per segment and as many times fewer
 * segments (the same path length in fewer passes), upscaled over the canvas. When nothing
 * changes, each frame refines one band of rows at full size and quality, bottom to top, until the
 * canvas is whole. A band integrates as many steps as a preview (at most preview pixels x
 * PREVIEW_STEP_FACTOR rays), so input waits about one preview frame; and there are at least
 * refine_frames bands. The bands follow from sizes alone, never from timing, so a run is the
 * same on any machine.
 * Work per turn of the loop is bounded the same way: a frame whose rays may take more than
 * KIOSK_TURN_RAY_STEPS integration steps in all (rays x segments x steps per segment, the
 * most they can take) is drawn in tiles of at most that many ray-steps, one tile a turn, down
 * to one pixel, so that signals, input and the watchdog are served between them whatever the
 * scene. A preview in tiles is drawn offscreen and shown once whole. Straight rays and exact
 * orbits (at most max_chords chords each) are not tiled, and neither is the pipeline view. Scenes with adaptive steps keep their own step control in the preview.
 * A scene on exact orbits (render.method = orbit_table) previews with a coarse table of at most
 * PREVIEW_ORBIT_ROWS x PREVIEW_ORBIT_COLUMNS and chords PREVIEW_CHORD_FACTOR times as far from the
 * orbit; the renderer keeps that table and the refined one side by side. */
#ifndef BT_KIOSK_VIEW_H
#define BT_KIOSK_VIEW_H
#include "kiosk/compositor.h"
#include "kiosk/kiosk_state.h"
#include "render/programs.h"
#include "render/renderer.h"
#include "physics/orbit_table.h"
#include "scene/pixel_samples.h"

#define PREVIEW_STEP_FACTOR 2
#define PREVIEW_SEGMENT_FACTOR 2
#define PREVIEW_ORBIT_ROWS 128
#define PREVIEW_ORBIT_COLUMNS 32
#define PREVIEW_CHORD_FACTOR 4.0
/* the narrowest Gaussian of a star in a preview, its pixels: a narrower one sampled at the pixels'
 * centres loses its light between them */
#define PREVIEW_STAR_SIZE_MIN 0.5
/* The most bands a refinement takes (where the preview is small, bands of more rays than one
 * preview; src/kiosk/kiosk_tune.h) */
#define KIOSK_MAX_BANDS 64
/* Integration steps of all the rays of one tile: about 50 ms of llvmpipe on two cores (a
 * lorenz preview, 57600 rays x 270 steps, fits in one). */
#define KIOSK_TURN_RAY_STEPS (1L << 24)

/* A frame cut into tiles of one size (the ray state's), drawn one a turn from the bottom row of
 * tiles up, left to right; the last of a row or a column may reach beyond the frame, and what lies
 * beyond is not shown. */
struct kiosk_tiles {
    int width, height;               /* the frame */
    int tile_width, tile_height;
    int columns, count, next;        /* tiles across; in all; the next to draw */
};

/* Tiles of at most max_rows full-width rows, narrower where a tile of rays taking steps_per_ray
 * steps each would exceed KIOSK_TURN_RAY_STEPS (steps_per_ray 0: no bound). */
void kiosk_tiles_plan(struct kiosk_tiles *t, int width, int height, int max_rows, long steps_per_ray);

struct kiosk_view {
    const struct kiosk_config *cfg;
    const struct gl_context *gl;
    int scene_index;                 /* the scene file loaded in base, -1 for none */
    struct scene base;               /* as loaded */
    struct scene full;               /* base with the visitor's state, at the refined frame's size */
    struct scene live;               /* what the renderer draws now: full, or its preview */
    int live_is_full;                /* live is full, set for the bands of the refinement and the
                                        anti-aliasing (copied once, not at each band) */
    struct renderer *renderer;
    struct compositor comp;
    int pipeline_view;
    /* each scene's preview size: the configuration's, or smaller where previews at that size cost
     * more than the kiosk's preview_rate allows here (kiosk_tune.h) */
    int preview_sizes[KIOSK_MAX_SCENES][2];
    int preview_width, preview_height;   /* the loaded scene's */
    int band_rows;                   /* rows of one band: as many steps as one preview */
    int refined_rows;                /* rows of the canvas at full quality, from the bottom */
    struct kiosk_tiles preview;      /* the preview being drawn; next == count: shown */
    struct kiosk_tiles refine;       /* the refinement's tiles */
    /* anti-aliasing, once refined: the points of pixel_samples(refine_samples) in turn, each a frame
     * traced band by band with its rays started there and blended into the canvas with weight
     * 1 / (k + 1), so that the canvas holds the mean of the samples drawn so far (the one-ray frame
     * is the first where the points include the centre, odd counts) */
    struct pixel_samples samples;
    int sample;                      /* the next of samples to draw; samples.n: none left */
    int sample_rows;                 /* its rows drawn, from the bottom */
    /* the programs of every scene, compiled once (kiosk_warm.c compiles them all before the first
     * frame): a renderer made for a scene takes them from here */
    struct program_cache programs;
    int programs_ready;
    int prefetch_off;                /* no orbit tables built ahead (while warming) */
    int prefetched;                  /* the orbit tables around prefetched_for were asked for */
    struct orbit_table_params prefetched_for;   /* the refined table of the state they were asked for */
};

/* 0, or -1 with e (compositor_init's). */
int kiosk_view_init(struct kiosk_view *v, const struct kiosk_config *cfg, const struct gl_context *gl, struct error *e);
void kiosk_view_release(struct kiosk_view *v);
/* Scene index i: base, the scene as read at start, or NULL to read its file now (once per switch).
 * 0, or -1 with e: the scene file's error (where: the file) or the renderer's. */
int kiosk_view_load(struct kiosk_view *v, int scene_index, const struct scene *base, struct error *e);
/* No scene loaded (its renderer destroyed); the programs stay. */
void kiosk_view_unload(struct kiosk_view *v);
/* The view's program cache emptied (no scene loaded): the next scene loaded starts a new one. */
void kiosk_view_forget_programs(struct kiosk_view *v);
/* Draw the preview of a state into the canvas (the scene must be loaded); refinement starts
 * over. 0, or -1 with e: a state the scene cannot take (where: the scene or the key), or the
 * renderer's or the compositor's failure. */
int kiosk_view_preview(struct kiosk_view *v, const struct kiosk_state *st, struct error *e);
/* The next tile of a preview drawn in tiles, else the next band (or tile) of refinement, else of
 * the anti-aliasing's next sample; 0, or -1 with e. Nothing to do once done. */
int kiosk_view_refine(struct kiosk_view *v, struct error *e);
/* A preview is still being drawn, tile by tile (not yet shown). */
int kiosk_view_preview_pending(const struct kiosk_view *v);
/* The frame is refined: one ray a pixel at full size and quality on the canvas. */
int kiosk_view_refined(const struct kiosk_view *v);
/* Refined and anti-aliased: nothing left to draw until the state changes. */
int kiosk_view_done(const struct kiosk_view *v);
/* Samples of the anti-aliasing drawn into the canvas so far, the one-ray frame counted where it is
 * one of them (0 while refining). */
int kiosk_view_samples_drawn(const struct kiosk_view *v);
/* Detents of each knob, on each side, whose orbit tables are built ahead (kiosk_view_prefetch). */
#define KIOSK_PREFETCH_DETENTS 16
/* The orbit tables the knobs' next KIOSK_PREFETCH_DETENTS detents on either side will ask for
 * (previews first, nearest first, then the refined tables of the detents beside st), built by the
 * renderer's worker while the exhibit shows st; nothing for a scene without a table. kiosk_view_preview
 * calls it. 0, or -1 with e (no memory). */
int kiosk_view_prefetch(struct kiosk_view *v, const struct kiosk_state *st, struct error *e);
/* The preview of a full scene: width x height, and longer steps over the same path length. */
void kiosk_preview_scene(const struct scene *full, int width, int height, struct scene *out);
/* Scene scene_index previews at width x height from now on (at most the configuration's size). */
void kiosk_view_set_preview_size(struct kiosk_view *v, int scene_index, int width, int height);

/* The budget each ray of s has where its steps are fixed, against which the pipeline view shows
 * how much of it a ray took (the state's w): the steps, or the path where they grow away from the
 * objects (render.far_step, scene_far_steps). 0 for adaptive steps (the view shows their step
 * sizes), straight rays and exact orbits. */
double kiosk_state_budget(const struct scene *s);

#endif
