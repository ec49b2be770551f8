/* One scene on the kiosk: preview, then refinement band by band. */
#include "kiosk/kiosk_view.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

int kiosk_view_init(struct kiosk_view *v, const struct kiosk_config *cfg, const struct gl_context *gl, char *err,
                    size_t errlen)
{
    memset(v, 0, sizeof *v);
    v->cfg = cfg;
    v->gl = gl;
    v->scene_index = -1;
    const struct kiosk_main *k = &cfg->kiosk;
    long preview_rays = (long)k->preview_width * k->preview_height;
    int by_cost = (int)(preview_rays / ((long)PREVIEW_STEP_FACTOR * k->width));
    /* rounded down: at least refine_frames bands, as the configuration promises */
    int by_frames = k->height / k->refine_frames > 0 ? k->height / k->refine_frames : 1;
    v->band_rows = by_cost < 1 ? 1 : by_cost < by_frames ? by_cost : by_frames;
    v->refined_rows = k->height;
    return compositor_init(&v->comp, gl, k->width, k->height, err, errlen);
}

void kiosk_view_release(struct kiosk_view *v)
{
    renderer_destroy(v->renderer);
    v->renderer = NULL;
    compositor_release(&v->comp);
}

int kiosk_view_load(struct kiosk_view *v, int scene_index, const struct scene *base, char *err, size_t errlen)
{
    if (v->scene_index == scene_index && v->renderer)
        return 0;
    renderer_destroy(v->renderer);
    v->renderer = NULL;
    v->scene_index = -1;
    struct scene_error serr;
    if (base) {
        v->base = *base;
    } else if (scene_load(&v->base, v->cfg->kiosk.scenes[scene_index], &serr) != 0) {
        snprintf(err, errlen, "%s: %s", serr.where, serr.message);
        return -1;
    }
    v->base.render.width = v->cfg->kiosk.width;
    v->base.render.height = v->cfg->kiosk.height;
    v->live = v->base;
    int bad = 0;
    v->renderer = renderer_create(v->gl, &v->live, err, errlen, &bad);
    if (!v->renderer)
        return -1;
    v->scene_index = scene_index;
    return 0;
}

void kiosk_preview_scene(const struct scene *full, const struct kiosk_main *k, struct scene *out)
{
    *out = *full;
    out->render.width = k->preview_width;
    out->render.height = k->preview_height;
    const int fewer = PREVIEW_STEP_FACTOR * PREVIEW_SEGMENT_FACTOR;
    int segments = render_segments(&full->render);
    if (full->render.step_control == STEP_FIXED && segments >= fewer &&
        full->render.steps_per_segment * PREVIEW_SEGMENT_FACTOR <= SCENE_MAX_STEPS_PER_SEGMENT) {
        out->render.step_size = full->render.step_size * PREVIEW_STEP_FACTOR;
        out->render.steps_per_segment = full->render.steps_per_segment * PREVIEW_SEGMENT_FACTOR;
        out->render.segments = (segments + fewer - 1) / fewer;
        out->render.max_path = 0.0;      /* the segments are the budget now */
    }
    if (full->render.method == METHOD_ORBIT_TABLE) {
        /* exact orbits need no steps: the preview takes a coarse table, cheap to build again at
         * every turn of the mass knob, and chords PREVIEW_CHORD_FACTOR times as far from the orbit */
        out->render.orbit_rows = full->render.orbit_rows < PREVIEW_ORBIT_ROWS ? full->render.orbit_rows : PREVIEW_ORBIT_ROWS;
        out->render.orbit_columns =
            full->render.orbit_columns < PREVIEW_ORBIT_COLUMNS ? full->render.orbit_columns : PREVIEW_ORBIT_COLUMNS;
        out->render.chord_tolerance = full->render.chord_tolerance * PREVIEW_CHORD_FACTOR;
    }
}

int kiosk_view_preview(struct kiosk_view *v, const struct kiosk_state *st, char *err, size_t errlen)
{
    struct scene_error serr;
    if (kiosk_state_apply(st, &v->base, &v->full, &serr) != 0) {
        snprintf(err, errlen, "%s: %s", serr.where, serr.message);
        return -1;
    }
    kiosk_preview_scene(&v->full, &v->cfg->kiosk, &v->live);
    v->pipeline_view = st->pipeline_view;
    const struct kiosk_main *k = &v->cfg->kiosk;
    if (renderer_run(v->renderer, 0, 0, k->preview_width, k->preview_height, NULL, NULL, err, errlen) != 0)
        return -1;
    struct renderer_textures t;
    /* the pipeline view shows every ray's final state, which a single-pass frame writes on demand */
    if (v->pipeline_view && renderer_complete_state(v->renderer, err, errlen) != 0)
        return -1;
    renderer_textures(v->renderer, &t);
    int rc = v->pipeline_view ? compositor_put_pipeline(&v->comp, &t, v->live.render.bound_radius,
                                                        render_segments(&v->live.render), v->live.render.step_size, err,
                                                        errlen)
                              : compositor_put_preview(&v->comp, t.image, err, errlen);
    /* the pipeline view shows the preview's own state: it is not refined */
    v->refined_rows = v->pipeline_view ? k->height : 0;
    return rc;
}

int kiosk_view_refine(struct kiosk_view *v, char *err, size_t errlen)
{
    const struct kiosk_main *k = &v->cfg->kiosk;
    if (v->refined_rows >= k->height || !v->renderer)
        return 0;
    v->live = v->full;
    /* every band has the same size, so the ray state is made once per refinement; the last one
     * may trace rows above the frame, which are not shown */
    int y0 = v->refined_rows;
    if (renderer_run(v->renderer, 0, y0, k->width, v->band_rows, NULL, NULL, err, errlen) != 0)
        return -1;
    struct renderer_textures t;
    renderer_textures(v->renderer, &t);
    int rows = k->height - y0 < v->band_rows ? k->height - y0 : v->band_rows;
    if (compositor_put_band(&v->comp, t.image, v->band_rows, y0, rows, err, errlen) != 0)
        return -1;
    v->refined_rows += rows;
    return 0;
}

int kiosk_view_refined(const struct kiosk_view *v)
{
    return v->refined_rows >= v->cfg->kiosk.height;
}
