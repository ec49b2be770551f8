/* What the visitor has set: the scene shown, the two knobs' values, the effects, the pipeline view;
 * and how knob counts, button actions and a scene file combine into the scene that is drawn. Pure:
 * the loop, the inputs and the display live elsewhere. */
#ifndef BT_KIOSK_STATE_H
#define BT_KIOSK_STATE_H
#include "kiosk_config/kiosk_config.h"
#include "scene/scene.h"

struct kiosk_state {
    int scene;                       /* index into the configuration's scenes */
    double speed;                    /* observer speed, fraction of c */
    double mass;                     /* central mass, the scene's unit */
    /* the value of the scene key a knob is mapped to ([kiosk] of the scene file), NAN while it is the
     * scene's own; unused for a knob that keeps its own meaning */
    double speed_param, mass_param;
    enum relativity_effects effects;
    int gravitational_shift;         /* 1: colours shifted by gravity as well as motion */
    /* 1: the scene's own observer.effects and gravitational_shift, as its file sets them (at start,
     * after reset and a scene change: a scene whose description names Doppler colour shows it); 0:
     * `effects` and `gravitational_shift`, as the effects button chose them */
    int effects_from_scene;
    int pipeline_view;               /* 1: show the renderer's stages instead of the image */
    /* 1: staff mode: the HUD adds the scene's file name, keys, symbols and frame rate, and the log
     * the frame times. Not part of what is drawn (kiosk_state_same leaves it out); reset ends it. */
    int staff;
};

/* The effects the state shows in its scene `base` (the scene's own, or those chosen), and whether
 * gravity's shift is among them. */
enum relativity_effects kiosk_state_effects(const struct kiosk_state *st, const struct scene *base);
int kiosk_state_gravitational_shift(const struct kiosk_state *st, const struct scene *base);

/* The value a knob reaches after `counts` detents from `value`, along its curve (linear in the
 * value, in rapidity atanh(v) for speed, in ln(mass) for log), clamped to [min, max]. A log knob
 * leaving 0 starts at min, or at exp(step) times its smallest positive value. */
double knob_turn(const struct kiosk_knob *k, double value, long counts);

/* The value of an absolute knob at position p (0: one end, 1: the other), evenly along its curve. */
double knob_position(const struct kiosk_knob *k, double p);

/* A knob mapped to a scene key (the scene's [kiosk]) after counts detents from param (NAN: the
 * scene's own value), clamped to the mapping's range. */
double knob_turn_mapped(const struct knob_mapping *m, const struct scene *scene, double param, long counts);

/* Whether two states are the same, field by field (a NAN parameter equals itself). */
int kiosk_state_same(const struct kiosk_state *a, const struct kiosk_state *b);

/* The start: the configured start scene and knob starts, geometry only, no pipeline view. */
void kiosk_state_reset(struct kiosk_state *st, const struct kiosk_config *c);

/* A button's action. Cycling effects adds one layer of the light's shift at a time on a scene
 * that has a black body: geometry -> Doppler colour (motion alone) -> + searchlight (beaming) ->
 * + gravity's shift (on a scene with a mass) -> geometry; from a scene's own Doppler colour with
 * gravity's shift it goes on to the searchlight with it. It leaves geometry alone on a scene that has
 * no black body (scene: the scene being shown). */
void kiosk_state_action(struct kiosk_state *st, const struct kiosk_config *c, const struct scene *scene,
                        enum kiosk_action action);

/* The scene to draw: base (the scene file as loaded) with the observer moving at st->speed along
 * the camera's view direction, the black hole's mass set to st->mass (0: flat space, the camera
 * stays where it is, so the shadow grows with the mass), and the effects. A scene without a black
 * hole keeps its model. A knob the scene maps to one of its keys ([kiosk]) sets that key instead.
 * 0, or -1 with the reason (the mass puts the camera inside the horizon). */
int kiosk_state_apply(const struct kiosk_state *st, const struct scene *base, struct scene *out,
                      struct error *err);

#endif
