#include "io/clock.h"
#include "render/frame.h"
#include "render/frame_bands.h"
#include "render/orbit_store.h"
#include "io/sample_average.h"
#include "results/bloom.h"
#include "results/dump_scene.h"
#include "results/star_light.h"
#include "results/tone.h"
#include "scene/pixel_samples.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The stars and Milky Way of [sky] on one image of the frame, from its rays' exit directions. */
static int add_star_light(const struct star_sky *k, struct render_result *img, double dx, double dy,
                          struct error *e)
{
    size_t n = (size_t)img->width * img->height;
    unsigned char *sky = malloc(n ? n : 1);
    if (!sky)
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory for the stars of a %dx%d image", img->width,
                         img->height);
    for (size_t i = 0; i < n; i++)
        sky[i] = render_result_outcome(img, i) == DUMP_SKY;
    /* the renderer's subpixel offsets run up the image, as the camera's do (scene/camera.h) */
    struct star_view v = {img->width, img->height, dx, dy, img->velocity, 4, sky};
    star_sky_add(k, &v, img->rgba, img->color, NULL);
    free(sky);
    return 0;
}

/* One image of the frame, its rays started (dx, dy) off the pixels' centres, with the stars when
 * stars is not NULL. */
static int run_image(struct renderer *r, const struct scene *s, const struct star_sky *stars, double dx, double dy,
                     struct render_result *out, enum render_read reads, struct frame_progress *p, struct error *e)
{
    if (!stars)
        return frame_run_image(r, s, dx, dy, out, reads, p, e);
    if (frame_run_image(r, s, dx, dy, out, render_read_with_sky(reads), p, e) != 0)
        return -1;
    double t0 = clock_seconds();
    if (add_star_light(stars, out, dx, dy, e) != 0) {
        render_result_free(out);
        return -1;
    }
    out->sky_seconds += clock_seconds() - t0;
    return 0;
}

/* The most steps (or chords) a ray of s may take: its budget. */
static double ray_steps_bound(const struct scene *s)
{
    if (model_is_straight(&s->model))
        return 1.0;
    if (s->render.method == METHOD_ORBIT_TABLE)
        return s->render.max_chords;
    return (double)render_segments(&s->render) * s->render.steps_per_segment;
}

int frame_bands_wanted(const struct scene *s, long pixel_samples)
{
    /* a small frame whose rays may take long (a budget of many steps) shows progress too */
    return pixel_samples >= FRAME_BAND_MIN_PIXELS ||
           (double)pixel_samples * ray_steps_bound(s) >= FRAME_BAND_MIN_RAY_STEPS;
}

static int run_samples(struct renderer *r, const struct scene *s, const struct star_sky *stars,
                       struct render_result *out, enum render_read reads, enum progress_mode progress, struct error *e)
{
    struct pixel_samples pattern;
    pixel_samples_make(s->render.samples, &pattern);
    /* the dump's rays are the pixels' centres; a summary's outcomes (RENDER_READ_OUTCOMES) may come
     * from the first sample */
    int extra_centre = pattern.n > 1 && reads == RENDER_READ_STATE && !pattern.centre_included;
    struct frame_progress p = {.runs = pattern.n + extra_centre, .samples = pattern.n};
    progress_begin(&p.line, progress);
    long pixel_samples = (long)s->render.width * s->render.height * p.runs;
    p.banded = progress == PROGRESS_ALWAYS || (progress == PROGRESS_AUTO && frame_bands_wanted(s, pixel_samples));
    if (pattern.n == 1) {
        int rc = run_image(r, s, stars, 0.0, 0.0, out, reads, &p, e);
        progress_end(&p.line);
        return rc;
    }
    struct sample_average sum;
    if (sample_average_init(&sum, (size_t)s->render.width * s->render.height) != 0)
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory for the samples of a %dx%d image", s->render.width,
                         s->render.height);
    int first = 0, rc = 0;
    if (extra_centre) {
        /* the centres' state only, not a sample of the image */
        p.sample = -1;
        rc = frame_run_image(r, s, 0.0, 0.0, out, RENDER_READ_STATE, &p, e);
        p.run++;
    } else {
        rc = run_image(r, s, stars, pattern.dx[0], pattern.dy[0], out, reads, &p, e);
        if (rc == 0)
            sample_average_add(&sum, out->rgba, out->color);
        first = 1;
        p.run++;
    }
    for (int k = first; k < pattern.n && rc == 0; k++) {
        struct render_result sample;
        p.sample = k;
        rc = run_image(r, s, stars, pattern.dx[k], pattern.dy[k], &sample, RENDER_READ_IMAGE, &p, e);
        p.run++;
        if (rc == 0) {
            sample_average_add(&sum, sample.rgba, sample.color);
            out->seconds += sample.seconds;
            out->compile_seconds += sample.compile_seconds;
            out->sky_seconds += sample.sky_seconds;
            out->passes += sample.passes;
        }
        render_result_free(&sample);
    }
    if (rc == 0)
        sample_average_write(&sum, out->rgba, out->color);
    else
        render_result_free(out);
    sample_average_free(&sum);
    progress_end(&p.line);
    return rc;
}

/* Whether the frame's 8-bit image is made on the CPU from its colour read as floats: for its bloom,
 * and for a gain or tone curve that must come after the stars the CPU's pass adds (results/tone.h). */
static int light_on_cpu(const struct renderer *r, const struct scene *s)
{
    return bloom_active(&s->render) || (tone_active(&s->render) && star_sky_wanted(s) && !renderer_gpu_stars(r));
}

/* The 8-bit image of a frame read as floats, with its bloom, gain and curve (results/bloom.h); the
 * float colour kept only where the caller asked for it. 0, or -1 with e (out is then freed). */
static int frame_bloom(const struct scene *s, struct render_result *out, int keep_color, struct error *e)
{
    double t0 = clock_seconds();
    if (bloom_image(&s->render, out->width, out->height, out->color, out->rgba) != 0) {
        render_result_free(out);
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory for the bloom of a %dx%d image", out->width,
                         out->height);
    }
    out->bloom_seconds = bloom_active(&s->render) ? clock_seconds() - t0 : 0.0;
    if (!keep_color) {
        free(out->color);
        out->color = NULL;
    }
    return 0;
}

/* The samples of the frame, with the CPU's stars where they are drawn there. */
static int run_with_stars(struct renderer *r, const struct scene *s, struct render_result *out, enum render_read reads,
                          enum progress_mode progress, struct error *e)
{
    /* the GPU's star pass draws them in the frame's own pass (render.star_pass = gpu, or auto) */
    if (!star_sky_wanted(s) || renderer_gpu_stars(r))
        return run_samples(r, s, NULL, out, reads, progress, e);
    struct star_sky *stars = malloc(sizeof *stars);
    if (!stars)
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory for the stars of the sky");
    int rc = star_sky_init(stars, s, e) == 0 ? run_samples(r, s, stars, out, reads, progress, e) : -1;
    star_sky_free(stars);
    free(stars);
    return rc;
}

int frame_run_samples(struct renderer *r, const struct scene *s, struct render_result *out, enum render_read reads,
                      enum progress_mode progress, struct error *e)
{
    int on_cpu = light_on_cpu(r, s);
    const char *asked = renderer_hdr_why(r);   /* the caller's own float image, if any */
    /* the frame's colour read back as floats, for the CPU to finish it */
    if (on_cpu && !asked)
        renderer_set_hdr(r, bloom_active(&s->render) ? "render.bloom (the frame's colour read back as floats)"
                                                     : "the gain and tone curve after the CPU's stars (the frame's "
                                                       "colour read back as floats; render.star_pass = gpu draws "
                                                       "the stars in the frame's pass)");
    int rc = run_with_stars(r, s, out, reads, progress, e);
    renderer_set_hdr(r, asked);
    if (rc == 0 && on_cpu)
        rc = frame_bloom(s, out, asked != NULL, e);
    return rc;
}

int render_frame(const struct scene *s, const struct frame_request *req, struct render_result *out,
                 struct frame_info *info, struct error *e)
{
    error_clear(e);
    /* the orbit table is built on the CPU while the context is made, the GPU probed and the scene's
     * textures loaded, which take about as long here (docs/BENCH.md, "The time a user waits") */
    struct orbit_store *ahead = renderer_orbit_ahead(s);
    struct gl_context *ctx = gl_context_create(req->backend, e);
    if (!ctx) {
        orbit_store_destroy(ahead);
        return -1;
    }
    int rc = -1;
    struct renderer *r = renderer_create(ctx, s, e);
    if (!r)
        orbit_store_destroy(ahead);
    if (r) {
        renderer_orbit_store_give(r, ahead);
        if (info) {
            snprintf(info->backend, sizeof info->backend, "%s", ctx->backend);
            snprintf(info->path_name, sizeof info->path_name, "%s", renderer_path(r)->name);
            snprintf(info->path_description, sizeof info->path_description, "%s", renderer_path(r)->description);
            snprintf(info->renderer, sizeof info->renderer, "%s", renderer_caps(r)->renderer);
        }
        renderer_set_hdr(r, req->hdr ? "writing a float image (a 16-bit PNG or PFM)" : NULL);
        renderer_time_first_draws(r, 1);
        rc = frame_run_samples(r, s, out, req->reads, req->progress, e);
        if (info) {
            snprintf(info->pipeline, sizeof info->pipeline, "%s", renderer_pipeline(r));
            snprintf(info->pipeline_why, sizeof info->pipeline_why, "%s", renderer_pipeline_why(r));
        }
        renderer_destroy(r);
    }
    gl_context_destroy(ctx);
    return rc;
}

void result_dump_header(const struct render_result *res, const struct scene *s, const char *engine, struct dump *d)
{
    memset(d, 0, sizeof *d);
    dump_describe_scene(d, s);
    d->width = res->width;
    d->height = res->height;
    snprintf(d->engine, sizeof d->engine, "%s", engine);
}

int result_to_dump(const struct render_result *res, const struct scene *s, const char *engine, struct dump *d)
{
    result_dump_header(res, s, engine, d);
    size_t n = (size_t)res->width * res->height;
    d->records = calloc(n, sizeof *d->records);
    if (!d->records)
        return -1;
    /* read with RENDER_READ_OUTCOMES: outcome and colour, every other field 0 */
    static const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    int state = res->position && res->velocity && res->hit;
    for (size_t i = 0; i < n; i++) {
        struct dump_record *rec = &d->records[i];
        const float *pos = state ? res->position + 4 * i : none, *vel = state ? res->velocity + 4 * i : none;
        const float *hit = state ? res->hit + 4 * i : none;
        float code = res->image[4 * i + 3];
        rec->outcome = (int32_t)lrintf(code);
        if (pos[3] < 0.0f)
            rec->outcome = DUMP_FAILED;
        float len = sqrtf(vel[0] * vel[0] + vel[1] * vel[1] + vel[2] * vel[2]);
        for (int k = 0; k < 3; k++) {
            rec->hit[k] = rec->outcome >= 0 ? hit[k] : 0.0f;
            rec->position[k] = pos[k];
            rec->direction[k] = len > 0.0f ? vel[k] / len : 0.0f;
        }
        rec->depth = hit[3];
        /* fixed steps: the state's w counts them; an adaptive ray's w is the path it travelled
         * (its budget), and its steps are not counted; nor are fixed steps that grow (far_step) */
        float steps = pos[3] < 0.0f ? -1.0f - pos[3] : pos[3];
        rec->steps = s->render.step_control == STEP_FIXED && !scene_far_steps(s) ? (uint32_t)lrintf(steps) : 0;
        memcpy(rec->rgba, res->rgba + 4 * i, 4);
    }
    return 0;
}
