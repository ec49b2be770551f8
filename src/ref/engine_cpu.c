#include "ref/engine_cpu.h"
#include "results/dump_scene.h"
#include "ref/shade_cpu.h"
#include "ref/straight.h"
#include "io/sample_average.h"
#include "scene/pixel_samples.h"
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>


struct job {
    const struct scene *scene;
    const struct cpu_render_options *opt;
    const struct cpu_materials *materials;
    const struct pixel_samples *pattern;
    struct cpu_image *out;
    atomic_int next_row;
    atomic_int rows_done;
    atomic_long steps, rejected;
};

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

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
        if (pattern->n > 1) {
            /* every sample, averaged in linear light as the GPU's frames are (io/sample_average.h) */
            struct pixel_average sum = {{0.0, 0.0, 0.0}, 0.0, {0.0, 0.0, 0.0}};
            int first = pattern->centre_included;
            if (first)
                add_sample(&sum, color, hdr);
            for (int n = first; n < pattern->n; n++) {
                double other[4];
                trace_at(job, i, j, pattern->dx[n], pattern->dy[n], &ray, other);
                add_sample(&sum, other, hdr);
                steps += ray.steps;
                rejected += ray.rejected;
            }
            pixel_average_mean(&sum, pattern->n, color, &color[3]);
        }
        for (int c = 0; c < 4; c++) {
            rgba[c] = unorm8(color[c]);
            if (hdr)
                img->color[4 * k + c] = (float)color[c];
        }
        ref_ray_to_record(&centre, rgba, &img->dump.records[k]);
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

/* Wait for the workers, showing their progress while a long render runs. */
static void wait_with_progress(struct job *job)
{
    int rows = job->scene->render.height;
    struct progress p;
    progress_begin(&p, job->opt->progress);
    for (int done = 0; done < rows;) {
        struct timespec pause = {0, 50 * 1000 * 1000};
        nanosleep(&pause, NULL);
        done = atomic_load(&job->rows_done);
        char label[64];
        snprintf(label, sizeof label, "cpu reference: %d/%d rows", done, rows);
        progress_report(&p, label, (double)done / rows, done == rows);
    }
    progress_end(&p);
}

int cpu_render(const struct scene *s, const struct cpu_render_options *o, struct cpu_image *out, char *err,
               size_t errlen)
{
    memset(out, 0, sizeof *out);
    int w = s->render.width, h = s->render.height;
    struct cpu_materials materials;
    if (cpu_materials_load(&materials, s, err, errlen) != 0) {
        cpu_materials_free(&materials);
        return -1;
    }
    out->width = w;
    out->height = h;
    out->rgba = malloc((size_t)w * h * 4);
    out->dump.records = calloc((size_t)w * h, sizeof *out->dump.records);
    if (o->hdr)
        out->color = malloc((size_t)w * h * 4 * sizeof(float));
    if (!out->rgba || !out->dump.records || (o->hdr && !out->color)) {
        cpu_materials_free(&materials);
        cpu_image_free(out);
        snprintf(err, errlen, "out of memory for a %dx%d image", w, h);
        return -1;
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
    int n = thread_count(o, h), started = 0;
    pthread_t threads[CPU_MAX_THREADS];
    double start = now_s();
    for (int i = 0; i < n; i++)
        started += pthread_create(&threads[started], NULL, worker, &job) == 0;
    if (started == 0)
        worker(&job);               /* no thread could start: do the work here */
    else
        wait_with_progress(&job);
    for (int i = 0; i < started; i++)
        pthread_join(threads[i], NULL);
    out->seconds = now_s() - start;
    out->threads = started > 0 ? started : 1;
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
