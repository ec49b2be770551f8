/* render.pipeline: which of the three schedules draws a frame, chosen here and nowhere else.
 *
 *   single pass     the whole ray in one fragment-shader loop (stage_frame.c): where the GPU runs
 *                   long loops and every object fits one intersection batch;
 *   fused segment   integration, intersection and termination of one segment in one pass with four
 *                   draw buffers (stage_segment.c);
 *   multipass       the paper's scheme (Figure 1): integrate, intersect per batch, terminate, retire,
 *                   one pass each per segment.
 *
 * All three give the same rays bit for bit (tests/unit/test_acceleration.c). */
#include "render/stages.h"
#include <stdio.h>
#include <string.h>

static const char *const pipeline_names[] = {"single pass", "fused segment", "multipass"};

const char *pipeline_name(enum pipeline_kind kind) { return pipeline_names[kind]; }

static void objects_why(const struct renderer *r, char *why, size_t whylen)
{
    snprintf(why, whylen, "the scene's objects do not fit one pass (at most %d here%s)", frame_object_limit(r),
             r->scene->render.moving_objects == MOVING_POLYGONS ? ", or are drawn as polygons" : "");
}

/* The most turns one loop of the single-pass frame takes: a turn a segment (stage_frame.glsl), or
 * two a chord and two more (stage_orbit_frame.glsl). */
static long frame_loop_turns(const struct renderer *r)
{
    const struct scene *s = r->scene;
    return r->exact_orbits ? 2L * s->render.max_chords + 2 : (long)render_segments(&s->render);
}

/* Whether the whole ray runs in one pass, with why in words. */
static int single_pass_fits(const struct renderer *r, int per_segment_hook, char *why, size_t whylen,
                            struct error *e)
{
    const struct scene *s = r->scene;
    struct object_batch b;
    if (s->render.pipeline == PIPELINE_MULTIPASS || s->render.pipeline == PIPELINE_FUSED) {
        snprintf(why, whylen, "render.pipeline = %s", s->render.pipeline == PIPELINE_FUSED ? "fused" : "multipass");
        return 0;
    }
    if (per_segment_hook) {
        snprintf(why, whylen, "the rays are read back after every segment");
        return 0;
    }
    /* the packed path is the multipass scheme's: its passes write one float a fragment */
    if (r->path.packed) {
        if (s->render.pipeline == PIPELINE_SINGLE)
            return error_set(e, ERROR_INPUT, NULL, "render.pipeline = single: the packed path (render path packed "
                             "8-bit) runs the multipass scheme; use render.pipeline = multipass or auto");
        snprintf(why, whylen, "the packed path writes one float a fragment");
        return 0;
    }
    /* a loop that the GPU ends early would leave rays short of their budget, unnoticed: refused
     * even where the scene asks for the single pass (a GLES2 device that may cut loops is not
     * probed, loop_turns 0, and the scene's choice is taken there, as documented) */
    long turns = frame_loop_turns(r);
    if (s->render.pipeline == PIPELINE_SINGLE) {
        if (r->caps.long_loops && turns > r->caps.loop_turns)
            return error_set(e, ERROR_INPUT, NULL, "render.pipeline = single: this GPU ends a fragment-shader loop "
                             "after %ld turns (probed), and one ray may take %ld %s; use render.pipeline = auto or "
                             "multipass", r->caps.loop_turns, r->exact_orbits ? (long)s->render.max_chords : turns,
                             r->exact_orbits ? "chords" : "segments");
        if (frame_batch(r, &b, e) != 0)
            return -1;
        snprintf(why, whylen, "render.pipeline = single");
        return 1;
    }
    if (!r->caps.long_loops) {
        snprintf(why, whylen, "%s", r->caps.long_loops_why);
        return 0;
    }
    if (turns > r->caps.loop_turns) {
        snprintf(why, whylen, "this GPU ends a fragment-shader loop after %ld turns (probed), and one ray may take "
                 "%ld %s", r->caps.loop_turns, r->exact_orbits ? (long)s->render.max_chords : turns,
                 r->exact_orbits ? "chords" : "segments");
        return 0;
    }
    if (object_batch_all(r, &b) != 0) {
        objects_why(r, why, whylen);
        return 0;
    }
    snprintf(why, whylen, "%s", r->caps.long_loops_why);
    return 1;
}

/* Why this frame's segments cannot each run as one fused pass (NULL: they can). */
static const char *fused_missing(const struct renderer *r, char *buf, size_t n)
{
    struct object_batch b;
    if (r->exact_orbits)
        return "render.method = orbit_table runs its own orbit stage";
    if (!r->path.mrt)
        return r->caps.mrt_works ? "the render path writes one target a pass (mrt = off)" : "MRT does not work here";
    if (!render_path_can_fuse(&r->caps, r->path.mrt)) {
        snprintf(buf, n, "GL_MAX_DRAW_BUFFERS is %d, the fused pass writes %d", r->caps.max_draw_buffers,
                 SEGMENT_FUSED_TARGETS);
        return buf;
    }
    if (object_batch_all(r, &b) != 0) {
        objects_why(r, buf, n);
        return buf;
    }
    return NULL;
}

/* Whether the segments run fused, with why in words. */
static int fused_fits(const struct renderer *r, char *why, size_t whylen, struct error *e)
{
    enum pipeline_choice choice = r->scene->render.pipeline;
    char buf[160];
    if (choice == PIPELINE_MULTIPASS) {
        snprintf(why, whylen, "render.pipeline = multipass");
        return 0;
    }
    const char *missing = fused_missing(r, buf, sizeof buf);
    if (choice == PIPELINE_FUSED && missing)
        return error_set(e, ERROR_INPUT, NULL, "render.pipeline = fused: %s; use render.pipeline = multipass or auto",
                         missing);
    if (missing) {
        snprintf(why, whylen, "%s", missing);
        return 0;
    }
    snprintf(why, whylen, choice == PIPELINE_FUSED ? "render.pipeline = fused"
                                                   : "%d draw buffers: one pass a segment", r->caps.max_draw_buffers);
    return 1;
}

/* Says in the reason where the scene names a choice for a pipeline this frame does not run
 * (render.hit_shading, render.orbit_walk): a setting that changes nothing is said, not ignored. */
static void unused_choices(const struct renderer *r, struct pipeline_choice_made *out)
{
    const struct render_settings *rs = &r->scene->render;
    size_t used = strlen(out->why);
    if (rs->hit_shading != HIT_SHADING_AUTO && out->kind != PIPELINE_RUN_MULTIPASS)
        used += (size_t)snprintf(out->why + used, sizeof out->why - used, "; render.hit_shading is for the multipass "
                                 "scheme's intersection stage, which this frame does not run");
    if (used < sizeof out->why && rs->orbit_walk != ORBIT_WALK_AUTO &&
        (out->kind != PIPELINE_RUN_SINGLE || !r->exact_orbits))
        snprintf(out->why + used, sizeof out->why - used, "; render.orbit_walk is for the single pass on exact "
                 "orbits, which this frame does not run");
}

int pipeline_choose(const struct renderer *r, int per_segment_hook, struct pipeline_choice_made *out,
                    struct error *e)
{
    int single = single_pass_fits(r, per_segment_hook, out->why, sizeof out->why, e);
    if (single < 0)
        return -1;
    if (single) {
        out->kind = PIPELINE_RUN_SINGLE;
        if (orbit_crossings_apply(r)) {
            size_t used = strlen(out->why);
            snprintf(out->why + used, sizeof out->why - used, "; the objects' planes pass through the mass: "
                     "each met where the orbits cross it");
        }
        unused_choices(r, out);
        return 0;
    }
    /* the render paths whose ray state the other pipelines cannot keep */
    if (r->exact_orbits && !r->path.fp32)
        return error_set(e, ERROR_RUNTIME, NULL, "render.method = orbit_table on a 16-bit ray state (render path %s) "
                         "runs in the single pass only, and this frame cannot (%s): use render.method = rk4",
                         r->path.name, out->why);
    if (r->path.image_only)
        return error_set(e, ERROR_RUNTIME, NULL, "render path image only (no float format renders on this GPU): "
                         "the frame cannot run in the single pass (%s), and the other pipelines keep the ray state "
                         "in float textures", out->why);
    char fused_why[200];
    int fused = fused_fits(r, fused_why, sizeof fused_why, e);
    if (fused < 0)
        return -1;
    if (r->scene->render.pipeline == PIPELINE_AUTO) {
        /* why not the single pass, then why (not) fused */
        size_t used = strlen(out->why);
        snprintf(out->why + used, sizeof out->why - used, "; %s%s", fused ? "" : "not fused: ", fused_why);
    }
    out->kind = fused ? PIPELINE_RUN_FUSED : PIPELINE_RUN_MULTIPASS;
    unused_choices(r, out);
    return 0;
}
