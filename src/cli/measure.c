#include "cli/measure.h"
#include "render/frame.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ", N samples a pixel" for the render line, or nothing for one. */
static void samples_text(const struct scene *s, char *out, size_t len)
{
    out[0] = '\0';
    if (s->render.samples > 1)
        snprintf(out, len, ", %d samples a pixel", s->render.samples);
}

static long count_nonfinite(const struct render_result *res)
{
    long nonfinite = 0;
    size_t n = (size_t)res->width * res->height;
    const float *arrays[4] = {res->position, res->velocity, res->hit, res->image};
    if (res->outcome)
        nonfinite += res->outcome_nonfinite;   /* the image's, counted on the GPU */
    for (int a = 0; a < 4; a++)
        for (size_t k = 0; arrays[a] && k < 4 * n; k++)
            nonfinite += !isfinite(arrays[a][k]);
    return nonfinite;
}

/* One ray's outcome and its pixel, counted. */
static void count_one(struct outcome_counts *c, int32_t outcome, const unsigned char rgba[4])
{
    c->objects += outcome >= 0;
    c->sky += outcome == DUMP_SKY;
    c->captured += outcome == DUMP_CAPTURED;
    c->unfinished += outcome == DUMP_UNFINISHED;
    c->failed += outcome == DUMP_FAILED;
    c->dark += rgba[0] <= OUTCOME_DARK_CHANNEL && rgba[1] <= OUTCOME_DARK_CHANNEL && rgba[2] <= OUTCOME_DARK_CHANNEL;
}

/* The outcome of every ray of a frame read with RENDER_READ_OUTCOMES (or more), as the dump's records
 * hold it (result_to_dump), counted; with the black pixels of its image. */
static void count_outcomes(const struct render_result *res, struct outcome_counts *c)
{
    memset(c, 0, sizeof *c);
    size_t n = (size_t)res->width * res->height;
    for (size_t i = 0; i < n; i++) {
        int32_t o = render_result_outcome(res, i);
        count_one(c, res->position && res->position[4 * i + 3] < 0.0f ? DUMP_FAILED : o, res->rgba + 4 * i);
    }
}

/* The same from a dump's records. */
static void count_records(const struct dump *d, struct outcome_counts *c)
{
    memset(c, 0, sizeof *c);
    size_t n = (size_t)d->width * d->height;
    for (size_t i = 0; i < n; i++)
        count_one(c, d->records[i].outcome, d->records[i].rgba);
}

int measure_gpu(const struct scene *s, const char *backend, int need_state, enum progress_mode progress, int hdr,
                struct measured *m, struct error *e)
{
    memset(m, 0, sizeof *m);
    struct render_result res;
    struct frame_info info;
    if (render_frame(s, &(struct frame_request){backend, need_state ? RENDER_READ_STATE : RENDER_READ_OUTCOMES, progress, hdr}, &res, &info, e) != 0)
        return -1;
    snprintf(m->engine, sizeof m->engine, "gpu %s", info.path_name);
    snprintf(m->device, sizeof m->device, "%.120s on %s", info.renderer, info.backend);
    count_outcomes(&res, &m->counts);
    if (need_state && result_to_dump(&res, s, m->engine, &m->dump) != 0) {
        render_result_free(&res);
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory");
    }
    if (!need_state)
        result_dump_header(&res, s, m->engine, &m->dump);   /* a summary needs the counts, not records */
    m->rgba = res.rgba;
    m->color = res.color;
    res.rgba = NULL;                /* kept; the ray state is not */
    res.color = NULL;
    m->seconds = res.seconds;
    m->compile_seconds = res.compile_seconds;
    m->work = res.passes;
    m->nonfinite = count_nonfinite(&res);
    char samples[48];
    samples_text(s, samples, sizeof samples);
    char stars[112] = "";
    if (res.sky_seconds > 0.0)
        snprintf(stars, sizeof stars, ", the stars of the sky %.3f s on the CPU", res.sky_seconds);
    if (res.bloom_seconds > 0.0)
        snprintf(stars + strlen(stars), sizeof stars - strlen(stars), ", the bloom %.3f s on the CPU", res.bloom_seconds);
    snprintf(m->how, sizeof m->how, "%s on %s (%s), %.3f s%s%s, %ld pass%s (%s: %s)", info.path_description,
             info.backend, info.renderer, res.seconds, samples, stars, res.passes, res.passes == 1 ? "" : "es",
             info.pipeline, info.pipeline_why);
    render_result_free(&res);
    return 0;
}

int measure_cpu(const struct scene *s, const struct cpu_render_options *o, struct measured *m, struct error *e)
{
    memset(m, 0, sizeof *m);
    error_clear(e);
    struct cpu_image img;
    if (cpu_render(s, o, &img, e) != 0)
        return -1;                  /* its status stands: a texture it cannot read is the user's */
    m->dump = img.dump;
    count_records(&m->dump, &m->counts);
    m->rgba = img.rgba;
    m->color = img.color;
    m->seconds = img.seconds;
    m->work = img.steps;
    snprintf(m->engine, sizeof m->engine, "%s", img.dump.engine);
    snprintf(m->device, sizeof m->device, "%d CPU threads", img.threads);
    char samples[48];
    samples_text(s, samples, sizeof samples);
    snprintf(m->how, sizeof m->how, "CPU reference (Dormand-Prince 5(4), rtol %.0e), %.3f s%s, %ld steps, %ld rejected",
             o->ref.rtol, img.seconds, samples, img.steps, img.rejected);
    return 0;
}

void measured_free(struct measured *m)
{
    dump_free(&m->dump);
    free(m->rgba);
    free(m->color);
    m->rgba = NULL;
    m->color = NULL;
}
