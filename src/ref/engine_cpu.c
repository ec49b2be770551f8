#include "io/clock.h"
#include "ref/engine_cpu.h"
#include "results/dump_scene.h"
#include "ref/shade_cpu.h"
#include "ref/straight.h"
#include "io/sample_average.h"
#include "scene/pixel_samples.h"
#include "results/star_light.h"
#include "results/bloom.h"
#include "results/tone.h"
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

/* One whole image of rays started (dx, dy) off the pixels' centres, before the stars of the sky are
 * added to it (results/star_light.h needs every pixel's neighbours): colours, exit directions,
 * which rays reached the sky, and the dump records when these are the centres' rays. */
struct sample_image {
    double dx, dy;
    double *color;             /* 4 a pixel, cpu_shade_color's */
    float *direction;          /* 3 a pixel */
    unsigned char *sky;
    struct dump_record *records;   /* the centres' run only; else NULL */
};

struct job {
    const struct scene *scene;
    const struct cpu_render_options *opt;
    const struct cpu_materials *materials;
    const struct pixel_samples *pattern;
    struct cpu_image *out;
    /* with stars in the sky: one image of rays at a time, all pixels at (dx, dy) */
    struct sample_image *image;
    atomic_int next_row;
    atomic_int rows_done;
    atomic_long steps, rejected;
    int threads_started;
};

void ref_ray_to_record(const struct ref_ray *ray, const unsigned char rgba[4], struct dump_record *rec)
{
    vec3d dir = v3_normalize(ray->velocity);
    rec->outcome = ray->outcome;
    float hit[3] = {(float)ray->hit.x, (float)ray->hit.y, (float)ray->hit.z};
    float pos[3] = {(float)ray->position.x, (float)ray->position.y, (float)ray->position.z};
    float d[3] = {(float)dir.x, (float)dir.y, (float)dir.z};
    memcpy(rec->hit, hit, sizeof hit);
    memcpy(rec->position, pos, sizeof pos);
    memcpy(rec->direction, d, sizeof d);
    rec->depth = (float)ray->depth;
    rec->steps = (uint32_t)ray->steps;
    memcpy(rec->rgba, rgba, 4);
}

/* The colour of the ray started (dx, dy) pixels off the centre of pixel (i, j) (cpu_shade_color:
 * unclamped, with alpha); the traced ray in *ray. */
static void trace_at(struct job *job, int i, int j, double dx, double dy, struct ref_ray *ray, double color[4])
{
    const struct scene *s = job->scene;
    vec3d x0 = s->camera.position;
    vec3d v0 = model_initial_velocity(&s->model, x0, camera_ray_at(s, i, j, dx, dy));
    ref_trace(s, &job->opt->ref, x0, v0, ray, 0.0, NULL, NULL);
    cpu_shade_color(job->materials, ray, camera_view_direction_at(s, i, j, dx, dy), color);
}

int ref_pixel_colour(const struct scene *s, const struct ref_ray *ray, int i, int j, unsigned char rgba[4],
                     struct error *e)
{
    struct cpu_materials materials;
    if (cpu_materials_load(&materials, s, e) != 0)
        return -1;
    double color[4];
    cpu_shade_color(&materials, ray, camera_view_direction_at(s, i, j, 0.0, 0.0), color);
    if (tone_active(&s->render))
        tone_map(&s->render, color);
    for (int c = 0; c < 4; c++)
        rgba[c] = unorm8(color[c]);
    cpu_materials_free(&materials);
    return 0;
}

/* A sample into the pixel's average as the GPU's images are summed (io/sample_average.c): its 8-bit
 * codes, or with a float image its colour itself. */
static void add_sample(struct pixel_average *p, const double color[4], int hdr)
{
    double encoded[3];
    for (int c = 0; c < 3; c++)
        encoded[c] = hdr ? color[c] : unorm8(color[c]) / 255.0;
    pixel_average_add(p, encoded, hdr ? color[3] : unorm8(color[3]) / 255.0);
}

static void render_row(struct job *job, int j)
{
    const struct scene *s = job->scene;
    const struct pixel_samples *pattern = job->pattern;
    struct cpu_image *img = job->out;
    int hdr = img->color != NULL;
    long steps = 0, rejected = 0;
    for (int i = 0; i < s->render.width; i++) {
        size_t k = (size_t)j * s->render.width + i;
        unsigned char *rgba = img->rgba + 4 * k;
        struct ref_ray ray;
        double color[4];
        /* the pixel's centre: the ray of the dump record, and sample 0 where the pattern holds it */
        trace_at(job, i, j, 0.0, 0.0, &ray, color);
        steps += ray.steps;
        rejected += ray.rejected;
        struct ref_ray centre = ray;
        /* the gain and the tone curve on each sample's colour before its 8-bit code, as the
         * GPU's shader does (results/tone.h); a float image keeps the light as traced */
        int tone = tone_active(&s->render);
        if (tone && !hdr)
            tone_map(&s->render, color);
        if (pattern->n > 1) {
            /* every sample, averaged in linear light as the GPU's frames are (io/sample_average.h) */
            struct pixel_average sum = {{0.0, 0.0, 0.0}, 0.0, {0.0, 0.0, 0.0}};
            int first = pattern->centre_included;
            if (first)
                add_sample(&sum, color, hdr);
            for (int n = first; n < pattern->n; n++) {
                double other[4];
                trace_at(job, i, j, pattern->dx[n], pattern->dy[n], &ray, other);
                if (tone && !hdr)
                    tone_map(&s->render, other);
                add_sample(&sum, other, hdr);
                steps += ray.steps;
                rejected += ray.rejected;
            }
            pixel_average_mean(&sum, pattern->n, color, &color[3]);
        }
        double display[4] = {color[0], color[1], color[2], color[3]};
        if (tone && hdr)
            tone_map(&s->render, display);
        for (int c = 0; c < 4; c++) {
            rgba[c] = unorm8(display[c]);
            if (hdr)
                img->color[4 * k + c] = (float)color[c];
        }
        ref_ray_to_record(&centre, rgba, &img->dump.records[k]);
    }
    atomic_fetch_add(&job->steps, steps);
    atomic_fetch_add(&job->rejected, rejected);
}

/* Row j of a sample image: every pixel's ray at the image's offset, shaded, without stars. */
static void sample_row(struct job *job, int j)
{
    const struct scene *s = job->scene;
    struct sample_image *img = job->image;
    long steps = 0, rejected = 0;
    for (int i = 0; i < s->render.width; i++) {
        size_t k = (size_t)j * s->render.width + i;
        struct ref_ray ray;
        trace_at(job, i, j, img->dx, img->dy, &ray, img->color + 4 * k);
        steps += ray.steps;
        rejected += ray.rejected;
        vec3d d = v3_normalize(ray.velocity);
        img->direction[3 * k] = (float)d.x;
        img->direction[3 * k + 1] = (float)d.y;
        img->direction[3 * k + 2] = (float)d.z;
        img->sky[k] = ray.outcome == DUMP_SKY;
        if (img->records) {
            static const unsigned char none[4] = {0, 0, 0, 0};
            ref_ray_to_record(&ray, none, &img->records[k]);
        }
    }
    atomic_fetch_add(&job->steps, steps);
    atomic_fetch_add(&job->rejected, rejected);
}

static void *worker(void *arg)
{
    struct job *job = arg;
    for (;;) {
        int j = atomic_fetch_add(&job->next_row, 1);
        if (j >= job->scene->render.height)
            return NULL;
        if (job->image)
            sample_row(job, j);
        else
            render_row(job, j);
        atomic_fetch_add(&job->rows_done, 1);
    }
}

static int thread_count(const struct cpu_render_options *o, int rows)
{
    long n = o->threads > 0 ? o->threads : sysconf(_SC_NPROCESSORS_ONLN);
    n = n < 1 ? 1 : n > CPU_MAX_THREADS ? CPU_MAX_THREADS : n;
    return n > rows ? rows : (int)n;
}

/* Wait for the workers, showing their progress while a long render runs: run `run` of `runs`. */
static void wait_with_progress(struct job *job, struct progress *p, int run, int runs)
{
    int rows = job->scene->render.height;
    for (int done = 0; done < rows;) {
        struct timespec pause = {0, 50 * 1000 * 1000};
        nanosleep(&pause, NULL);
        done = atomic_load(&job->rows_done);
        char label[80];
        if (runs > 1)
            snprintf(label, sizeof label, "cpu reference: image %d/%d, %d/%d rows", run + 1, runs, done, rows);
        else
            snprintf(label, sizeof label, "cpu reference: %d/%d rows", done, rows);
        progress_report(p, label, (run + (double)done / rows) / runs, run + 1 == runs && done == rows);
    }
}

/* Every row of the job on the workers (or here, when none could start). */
static void run_rows(struct job *job, int threads, struct progress *p, int run, int runs)
{
    atomic_store(&job->next_row, 0);
    atomic_store(&job->rows_done, 0);
    pthread_t handles[CPU_MAX_THREADS];
    int started = 0;
    for (int i = 0; i < threads; i++)
        started += pthread_create(&handles[started], NULL, worker, job) == 0;
    if (started == 0)
        worker(job);               /* no thread could start: do the work here */
    else
        wait_with_progress(job, p, run, runs);
    for (int i = 0; i < started; i++)
        pthread_join(handles[i], NULL);
    job->threads_started = started > 0 ? started : 1;
}

/* With stars in the sky: each sample a whole image, its stars added from its neighbouring rays,
 * then averaged in linear light as the GPU's images are (the same order of samples as render_row). */
static int render_with_stars(struct job *job, int threads, struct progress *p, struct error *e)
{
    const struct scene *s = job->scene;
    const struct pixel_samples *pattern = job->pattern;
    struct cpu_image *out = job->out;
    int hdr = out->color != NULL;
    size_t n = (size_t)s->render.width * s->render.height;
    struct sample_image img = {0};
    img.color = malloc(n * 4 * sizeof *img.color);
    img.direction = malloc(n * 3 * sizeof *img.direction);
    img.sky = malloc(n);
    struct pixel_average *sum = pattern->n > 1 ? calloc(n, sizeof *sum) : NULL;
    struct star_sky *stars = malloc(sizeof *stars);
    int rc = -1;
    if (!img.color || !img.direction || !img.sky || (pattern->n > 1 && !sum) || !stars) {
        error_set(e, ERROR_RUNTIME, NULL, "out of memory for the samples of a %dx%d image", s->render.width,
                  s->render.height);
        free(stars);
        stars = NULL;
        goto done;
    }
    if (star_sky_init(stars, s, e) != 0)
        goto done;
    job->image = &img;
    int centre_run = pattern->n > 1 && !pattern->centre_included;   /* the records' rays only */
    int runs = pattern->n + centre_run;
    for (int run = 0; run < runs; run++) {
        int k = run - centre_run;                  /* the sample, -1: the centres' run */
        img.dx = k < 0 ? 0.0 : pattern->dx[k];
        img.dy = k < 0 ? 0.0 : pattern->dy[k];
        img.records = k < 0 || (k == 0 && pattern->centre_included) || pattern->n == 1 ? out->dump.records : NULL;
        run_rows(job, threads, p, run, runs);
        if (k < 0)
            continue;
        struct star_view v = {s->render.width, s->render.height, img.dx, img.dy, img.direction, 3, img.sky};
        star_sky_add(stars, &v, NULL, NULL, img.color);
        for (size_t i = 0; i < n && !hdr && tone_active(&s->render); i++)
            tone_map(&s->render, img.color + 4 * i);   /* after the stars, as the GPU's pass */
        for (size_t i = 0; i < n && sum; i++)
            add_sample(&sum[i], img.color + 4 * i, hdr);
    }
    for (size_t i = 0; i < n; i++) {
        double color[4];
        if (sum)
            pixel_average_mean(&sum[i], pattern->n, color, &color[3]);
        else
            memcpy(color, img.color + 4 * i, sizeof color);
        double display[4] = {color[0], color[1], color[2], color[3]};
        if (hdr && tone_active(&s->render))
            tone_map(&s->render, display);
        for (int c = 0; c < 4; c++) {
            out->rgba[4 * i + c] = unorm8(display[c]);
            if (hdr)
                out->color[4 * i + c] = (float)color[c];
        }
        memcpy(out->dump.records[i].rgba, out->rgba + 4 * i, 4);
    }
    rc = 0;
done:
    job->image = NULL;
    if (stars)
        star_sky_free(stars);
    free(stars);
    free(sum);
    free(img.color);
    free(img.direction);
    free(img.sky);
    return rc;
}

/* The 8-bit image with its bloom (results/bloom.h), from the float colour, as the GPU's frame
 * (render/frame.c), and the records' colours with it; the colour kept where a float image was
 * asked for. 0, or -1 when out of memory. */
static int apply_bloom(const struct scene *s, struct cpu_image *out, int keep_color)
{
    if (bloom_image(&s->render, out->width, out->height, out->color, out->rgba) != 0)
        return -1;
    for (size_t i = 0; i < (size_t)out->width * out->height; i++)
        memcpy(out->dump.records[i].rgba, out->rgba + 4 * i, 4);
    if (!keep_color) {
        free(out->color);
        out->color = NULL;
    }
    return 0;
}

int cpu_render(const struct scene *s, const struct cpu_render_options *o, struct cpu_image *out, struct error *e)
{
    memset(out, 0, sizeof *out);
    int w = s->render.width, h = s->render.height;
    struct cpu_materials materials;
    if (cpu_materials_load(&materials, s, e) != 0) {
        cpu_materials_free(&materials);
        return -1;
    }
    out->width = w;
    out->height = h;
    out->rgba = malloc((size_t)w * h * 4);
    out->dump.records = calloc((size_t)w * h, sizeof *out->dump.records);
    /* bloom spreads the light beyond white: the colour is kept as floats for it, as the GPU's */
    int bloom = bloom_active(&s->render), hdr = o->hdr || bloom;
    if (hdr)
        out->color = malloc((size_t)w * h * 4 * sizeof(float));
    if (!out->rgba || !out->dump.records || (hdr && !out->color)) {
        cpu_materials_free(&materials);
        cpu_image_free(out);
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory for a %dx%d image", w, h);
    }
    out->dump.width = w;
    out->dump.height = h;
    dump_describe_scene(&out->dump, s);
    snprintf(out->dump.engine, sizeof out->dump.engine, "cpu dopri5 rtol %.0e", o->ref.rtol);

    struct pixel_samples pattern;
    pixel_samples_make(s->render.samples, &pattern);
    struct job job = {.scene = s, .opt = o, .materials = &materials, .pattern = &pattern, .out = out};
    atomic_init(&job.next_row, 0);
    atomic_init(&job.rows_done, 0);
    atomic_init(&job.steps, 0);
    atomic_init(&job.rejected, 0);
    int n = thread_count(o, h), rc = 0;
    double start = clock_seconds();
    struct progress p;
    progress_begin(&p, o->progress);
    if (star_sky_wanted(s))
        rc = render_with_stars(&job, n, &p, e);
    else
        run_rows(&job, n, &p, 0, 1);
    progress_end(&p);
    if (rc != 0) {
        cpu_materials_free(&materials);
        cpu_image_free(out);
        return -1;
    }
    if (bloom && apply_bloom(s, out, o->hdr) != 0) {
        cpu_materials_free(&materials);
        cpu_image_free(out);
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory for the bloom of a %dx%d image", w, h);
    }
    out->seconds = clock_seconds() - start;
    out->threads = job.threads_started;
    out->steps = atomic_load(&job.steps);
    out->rejected = atomic_load(&job.rejected);
    cpu_materials_free(&materials);
    return 0;
}

void cpu_image_free(struct cpu_image *img)
{
    free(img->rgba);
    free(img->color);
    img->color = NULL;
    img->rgba = NULL;
    dump_free(&img->dump);
}
