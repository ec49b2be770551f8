/* One scene on the kiosk: preview, then refinement band by band. */
#include "kiosk/kiosk_view.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

/* Previews of width x height from now on, and bands that integrate as many steps as one. */
static void use_preview_size(struct kiosk_view *v, int width, int height)
{
    const struct kiosk_main *k = &v->cfg->kiosk;
    v->preview_width = width;
    v->preview_height = height;
    long preview_rays = (long)width * height;
    int by_cost = (int)(preview_rays / ((long)PREVIEW_STEP_FACTOR * k->width));
    /* at most KIOSK_MAX_BANDS bands: each costs a turn of the loop and a composited frame besides
     * its rays, which a preview tuned small on a slow GPU would otherwise multiply */
    int fewest = k->height / KIOSK_MAX_BANDS;
    by_cost = by_cost < fewest ? fewest : by_cost;
    /* rounded down: at least refine_frames bands, as the configuration promises */
    int by_frames = k->height / k->refine_frames > 0 ? k->height / k->refine_frames : 1;
    v->band_rows = by_cost < 1 ? 1 : by_cost < by_frames ? by_cost : by_frames;
}

int kiosk_view_init(struct kiosk_view *v, const struct kiosk_config *cfg, const struct gl_context *gl, struct error *e)
{
    memset(v, 0, sizeof *v);
    v->cfg = cfg;
    v->gl = gl;
    v->scene_index = -1;
    const struct kiosk_main *k = &cfg->kiosk;
    for (int i = 0; i < KIOSK_MAX_SCENES; i++) {
        v->preview_sizes[i][0] = k->preview_width;
        v->preview_sizes[i][1] = k->preview_height;
    }
    use_preview_size(v, k->preview_width, k->preview_height);
    v->refined_rows = k->height;
    pixel_samples_make(k->refine_samples, &v->samples);
    v->sample = v->samples.n;
    return compositor_init(&v->comp, gl, k->width, k->height, e);
}

void kiosk_view_set_preview_size(struct kiosk_view *v, int scene_index, int width, int height)
{
    v->preview_sizes[scene_index][0] = width;
    v->preview_sizes[scene_index][1] = height;
    if (scene_index == v->scene_index)
        use_preview_size(v, width, height);
}

void kiosk_view_release(struct kiosk_view *v)
{
    renderer_destroy(v->renderer);
    v->renderer = NULL;
    if (v->programs_ready)
        program_cache_release(&v->programs);
    v->programs_ready = 0;
    compositor_release(&v->comp);
}

void kiosk_view_forget_programs(struct kiosk_view *v)
{
    kiosk_view_unload(v);
    if (v->programs_ready)
        program_cache_release(&v->programs);
    v->programs_ready = 0;
}

void kiosk_view_unload(struct kiosk_view *v)
{
    renderer_destroy(v->renderer);
    v->renderer = NULL;
    v->scene_index = -1;
    v->prefetched = 0;
}

int kiosk_view_load(struct kiosk_view *v, int scene_index, const struct scene *base, struct error *e)
{
    if (v->scene_index == scene_index && v->renderer)
        return 0;
    renderer_destroy(v->renderer);
    v->renderer = NULL;
    v->scene_index = -1;
    v->prefetched = 0;
    if (base)
        v->base = *base;
    else if (scene_load(&v->base, v->cfg->kiosk.scenes[scene_index], e) != 0)
        return -1;
    v->base.render.width = v->cfg->kiosk.width;
    v->base.render.height = v->cfg->kiosk.height;
    /* the kiosk's frames never leave the GPU: its stars are drawn in the frame's own pass */
    v->base.render.star_pass = STAR_PASS_GPU;
    v->live = v->base;
    v->live_is_full = 0;
    v->renderer = renderer_create(v->gl, &v->live, e);
    if (!v->renderer)
        return -1;
    /* the first renderer's shader target and MRT choice make the cache; a scene that needs other
     * programs (another MRT choice) keeps its own and compiles them on each switch */
    const struct program_cache *own = renderer_programs(v->renderer);
    if (!v->programs_ready)
        program_cache_init(&v->programs, &own->target, own->mrt);
    v->programs_ready = 1;
    renderer_share_programs(v->renderer, &v->programs);
    v->scene_index = scene_index;
    use_preview_size(v, v->preview_sizes[scene_index][0], v->preview_sizes[scene_index][1]);
    return 0;
}

void kiosk_preview_scene(const struct scene *full, int width, int height, struct scene *out)
{
    *out = *full;
    out->render.width = width;
    out->render.height = height;
    /* the stars as the screen shows them once the preview is scaled up to it: a star's light,
     * summed over the preview's pixels, is spread over scale^2 times as many of the screen's, so
     * it is that much fainter here; its Gaussian as narrow on screen as the preview's pixels can
     * sample it (PREVIEW_STAR_SIZE_MIN pixels of the preview at least) */
    double scale = width > 0 ? (double)full->render.width / width : 1.0;
    if (scale > 1.0) {
        out->sky.star_brightness = full->sky.star_brightness / (scale * scale);
        out->sky.star_size = fmax(full->sky.star_size / scale, PREVIEW_STAR_SIZE_MIN);
    }
    const int fewer = PREVIEW_STEP_FACTOR * PREVIEW_SEGMENT_FACTOR;
    int segments = render_segments(&full->render);
    if (full->render.step_control == STEP_FIXED && segments >= fewer &&
        full->render.steps_per_segment * PREVIEW_SEGMENT_FACTOR <= SCENE_MAX_STEPS_PER_SEGMENT) {
        out->render.step_size = full->render.step_size * PREVIEW_STEP_FACTOR;
        /* steps that grow away from the objects grow from the longer step, as far again */
        out->render.far_step = full->render.far_step > 0.0 ? full->render.far_step * PREVIEW_STEP_FACTOR : 0.0;
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

void kiosk_tiles_plan(struct kiosk_tiles *t, int width, int height, int max_rows, long steps_per_ray)
{
    memset(t, 0, sizeof *t);
    t->width = width;
    t->height = height;
    long rays = steps_per_ray > 0 ? KIOSK_TURN_RAY_STEPS / steps_per_ray : (long)width * max_rows;
    rays = rays < 1 ? 1 : rays;
    if (rays >= (long)width * max_rows) {
        t->tile_width = width;
        t->tile_height = max_rows;
    } else if (rays >= width) {
        t->tile_width = width;
        t->tile_height = (int)(rays / width);
    } else {
        t->tile_width = (int)rays;
        t->tile_height = 1;
    }
    /* Tiles start on even rows and columns, so that the GPU's 2x2 groups of fragments, whose
     * differences the star pass takes (dFdx, dFdy; sky_colour.glsl), are the whole frame's: sizes
     * rounded down to even, one-row tiles made two rows of half the width (no more rays a tile);
     * tiles of fewer than 4 rays (a budget of millions of steps a ray) stay as they are. */
    if (t->tile_height == 1 && t->tile_width < width && t->tile_width >= 4) {
        t->tile_width /= 2;
        t->tile_height = 2;
    }
    if (t->tile_height < height && t->tile_height >= 2)
        t->tile_height &= ~1;
    if (t->tile_width < width && t->tile_width >= 2)
        t->tile_width &= ~1;
    t->columns = (width + t->tile_width - 1) / t->tile_width;
    t->count = t->columns * ((height + t->tile_height - 1) / t->tile_height);
    t->next = 0;
}

/* The most integration steps a ray of s takes: 0 for straight rays and exact orbits (not tiled). */
static long steps_per_ray(const struct scene *s)
{
    if (model_is_straight(&s->model) || s->render.method == METHOD_ORBIT_TABLE)
        return 0;
    return (long)render_segments(&s->render) * s->render.steps_per_segment;
}

double kiosk_state_budget(const struct scene *s)
{
    if (s->render.step_control != STEP_FIXED || steps_per_ray(s) == 0)
        return 0.0;
    return scene_far_steps(s) ? render_path_budget(&s->render) : (double)steps_per_ray(s);
}

/* Tile k of t: its lower-left pixel and the part of it inside the frame. */
static void tile_at(const struct kiosk_tiles *t, int k, int *x0, int *y0, int *w, int *h)
{
    *x0 = (k % t->columns) * t->tile_width;
    *y0 = (k / t->columns) * t->tile_height;
    *w = t->width - *x0 < t->tile_width ? t->width - *x0 : t->tile_width;
    *h = t->height - *y0 < t->tile_height ? t->height - *y0 : t->tile_height;
}

/* Tile t->next drawn by the renderer: where it goes and its image. 0, or -1 with e. */
static int run_tile(struct kiosk_view *v, const struct kiosk_tiles *t, int *x0, int *y0, int *w, int *h,
                    GLuint *image, struct error *e)
{
    tile_at(t, t->next, x0, y0, w, h);
    if (renderer_run(v->renderer, &v->live, *x0, *y0, t->tile_width, t->tile_height, NULL, NULL, e) != 0)
        return -1;
    struct renderer_textures tex;
    renderer_textures(v->renderer, &tex);
    *image = tex.image;
    return 0;
}

/* The next tile of the preview, offscreen; the preview shown once whole. */
static int preview_tile(struct kiosk_view *v, struct error *e)
{
    struct kiosk_tiles *t = &v->preview;
    int x0, y0, w, h;
    GLuint image;
    if (run_tile(v, t, &x0, &y0, &w, &h, &image, e) != 0 ||
        compositor_put_preview_tile(&v->comp, image, t->tile_width, t->tile_height, x0, y0, w, h, t->width,
                                    t->height, e) != 0)
        return -1;
    if (++t->next == t->count && compositor_show_preview(&v->comp, e) != 0)
        return -1;
    return 0;
}

int kiosk_view_preview(struct kiosk_view *v, const struct kiosk_state *st, struct error *e)
{
    if (kiosk_state_apply(st, &v->base, &v->full, e) != 0)
        return -1;
    kiosk_preview_scene(&v->full, v->preview_width, v->preview_height, &v->live);
    v->live_is_full = 0;
    v->pipeline_view = st->pipeline_view;
    const struct kiosk_main *k = &v->cfg->kiosk;
    /* refinement starts over whatever the preview is, and the anti-aliasing after it: with the
     * centre among its points, the one-ray frame is its first sample */
    v->refined_rows = 0;
    v->sample = v->samples.centre_included ? 1 : 0;
    v->sample_rows = 0;
    kiosk_tiles_plan(&v->refine, k->width, k->height, v->band_rows, steps_per_ray(&v->full));
    kiosk_tiles_plan(&v->preview, v->preview_width, v->preview_height, v->preview_height,
                     v->pipeline_view ? 0 : steps_per_ray(&v->live));
    /* the screen shows the image alone, which a single pass then draws in one pass; the pipeline
     * view shows every ray's final state too */
    renderer_set_reads(v->renderer, v->pipeline_view ? RENDER_READ_STATE : RENDER_READ_IMAGE);
    if (v->preview.count > 1)
        return preview_tile(v, e) != 0 || kiosk_view_prefetch(v, st, e) != 0 ? -1 : 0;
    v->preview.next = v->preview.count;
    /* the pipeline view shows every ray's final state, which a single-pass frame writes on demand */
    if (renderer_run(v->renderer, &v->live, 0, 0, v->preview_width, v->preview_height, NULL, NULL, e) != 0 ||
        (v->pipeline_view && renderer_complete_state(v->renderer, e) != 0))
        return -1;
    struct renderer_textures t;
    renderer_textures(v->renderer, &t);
    int rc = v->pipeline_view ? compositor_put_pipeline(&v->comp, &t, v->live.render.bound_radius,
                                                        render_segments(&v->live.render), v->live.render.step_size,
                                                        kiosk_state_budget(&v->live), e)
                              : compositor_put_preview(&v->comp, t.image, e);
    /* the pipeline view shows the preview's own state: it is not refined */
    v->refined_rows = v->pipeline_view ? k->height : 0;
    if (v->pipeline_view)
        v->sample = v->samples.n;
    return rc != 0 ? rc : kiosk_view_prefetch(v, st, e);
}

int kiosk_view_preview_pending(const struct kiosk_view *v)
{
    return v->preview.next < v->preview.count;
}

/* The next band (or tile) of a frame at full size and quality, its rays started (dx, dy) pixels off
 * the pixels' centres, into the canvas with weight (compositor_put_band); *rows: the frame's rows
 * done, from the bottom. */
static int frame_step(struct kiosk_view *v, int *rows, double dx, double dy, float weight, struct error *e)
{
    const struct kiosk_main *k = &v->cfg->kiosk;
    struct kiosk_tiles *t = &v->refine;
    renderer_set_subpixel(v->renderer, dx, dy);
    int rc;
    if (t->tile_width == k->width) {
        /* whole bands: every band has the same size, so the ray state is made once per refinement;
         * the last one may trace rows above the frame, which are not shown */
        int y0 = *rows;
        rc = renderer_run(v->renderer, &v->live, 0, y0, k->width, t->tile_height, NULL, NULL, e);
        if (rc == 0) {
            struct renderer_textures tex;
            renderer_textures(v->renderer, &tex);
            int n = k->height - y0 < t->tile_height ? k->height - y0 : t->tile_height;
            rc = compositor_put_band(&v->comp, tex.image, t->tile_height, y0, n, weight, e);
            *rows += rc == 0 ? n : 0;
        }
    } else {
        /* tiles narrower than the frame: a row of tiles at a time, the rows counted once it is done */
        int x0, y0, w, h;
        GLuint image;
        rc = run_tile(v, t, &x0, &y0, &w, &h, &image, e) != 0 ||
             compositor_put_tile(&v->comp, image, t->tile_width, t->tile_height, x0, y0, w, h, weight, e) != 0 ? -1 : 0;
        if (rc == 0) {
            t->next++;
            if (t->next % t->columns == 0 || t->next == t->count)
                *rows = y0 + h;
        }
    }
    renderer_set_subpixel(v->renderer, 0.0, 0.0);
    return rc;
}

int kiosk_view_refine(struct kiosk_view *v, struct error *e)
{
    const struct kiosk_main *k = &v->cfg->kiosk;
    if (!v->renderer)
        return 0;
    if (kiosk_view_preview_pending(v))
        return preview_tile(v, e);
    if ((v->refined_rows < k->height || v->sample < v->samples.n) && !v->live_is_full) {
        renderer_set_reads(v->renderer, RENDER_READ_IMAGE);
        v->live = v->full;
        v->live_is_full = 1;
    }
    if (v->refined_rows < k->height)
        return frame_step(v, &v->refined_rows, 0.0, 0.0, 1.0f, e);
    if (v->sample >= v->samples.n)
        return 0;
    /* sample k of the anti-aliasing, the mean of those before it on the canvas: weight 1 / (k + 1)
     * keeps it the mean (the first replaces the one-ray frame, unless that is the first) */
    if (v->refine.next >= v->refine.count)
        v->refine.next = 0;              /* tiles: the refinement or the sample before used them all */
    if (frame_step(v, &v->sample_rows, v->samples.dx[v->sample], v->samples.dy[v->sample],
                   1.0f / (float)(v->sample + 1), e) != 0)
        return -1;
    if (v->sample_rows >= k->height) {
        v->sample++;
        v->sample_rows = 0;
    }
    return 0;
}

int kiosk_view_refined(const struct kiosk_view *v)
{
    return !kiosk_view_preview_pending(v) && v->refined_rows >= v->cfg->kiosk.height;
}

int kiosk_view_done(const struct kiosk_view *v)
{
    return kiosk_view_refined(v) && v->sample >= v->samples.n;
}

int kiosk_view_samples_drawn(const struct kiosk_view *v)
{
    if (!kiosk_view_refined(v))
        return 0;
    return v->sample < v->samples.n ? v->sample : v->samples.n;
}
