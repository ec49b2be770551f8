/* Every shader program the kiosk's scenes can ask for, compiled before the first frame.
 *
 * A program is compiled the first time a scene, a knob's value or a button needs its variant
 * (render/programs.h). On an exhibit's GPU that can take a minute (V3D's compiler spills these
 * shaders heavily), far longer than the service's watchdog interval, and a compile cut short is
 * never cached: the kiosk would restart forever. So before it tells the service manager it is
 * ready (while only the start timeout runs, which it extends), the kiosk draws each scene once
 * in every state whose programs may differ, into the view's shared program cache: each knob at
 * rest, at its lower and at its upper end, and the nine pairs of these; each effect; the pipeline
 * view. Each state draws its preview and the first band of its refinement, so both qualities'
 * programs (and a scene's orbit tables at the knobs' ends) are built, in a view of its own at
 * KIOSK_WARM_SIZE pixels: the programs depend on the scenes and states, never on the sizes, so
 * that the drawing costs little beside the compiles. A scene change or a knob turned later takes
 * its programs from the cache and compiles nothing. */
#ifndef BT_KIOSK_WARM_H
#define BT_KIOSK_WARM_H
#include "kiosk/kiosk_view.h"

/* Width and height of the frames and previews drawn while warming, pixels (the smallest a
 * configuration allows). */
#define KIOSK_WARM_SIZE 16
/* Detents turned to reach a knob's end from anywhere (values are clamped to the knob's range). */
#define KIOSK_WARM_DETENTS 1000000L
/* The longest reason kept for a scene that cannot be drawn, bytes. */
#define KIOSK_REFUSAL_LEN 600

struct kiosk_warm_report {
    int scenes;                      /* scenes drawn */
    int states;                      /* states drawn, over all scenes */
    int refused;                     /* states a scene refuses (a mass that puts the camera inside
                                        its horizon): not drawn, as the kiosk never draws them */
    long programs;                   /* programs compiled */
    double seconds;
    /* scenes whose drawing failed (this GPU cannot draw them: a program it does not compile, a
     * path it lacks), each with why; the others are drawn all the same */
    int failed[KIOSK_MAX_SCENES];
    char why[KIOSK_MAX_SCENES][KIOSK_REFUSAL_LEN];
};

/* Draws every scene of c (scenes: each scene file as read at start) as above and leaves their
 * programs in v's cache (v: the screen's view, which has compiled none yet; it is left with no
 * scene loaded). `between` is called before each state with arg, and a nonzero answer stops the
 * warm-up there (a signal). A scene that fails to draw is marked in out->failed with why, and
 * the next is drawn. 0, or -1 with e where no view could be made for it. */
int kiosk_warm(struct kiosk_view *v, const struct kiosk_config *c, const struct scene *scenes,
               int (*between)(void *arg), void *arg, struct kiosk_warm_report *out, struct error *e);

#endif
