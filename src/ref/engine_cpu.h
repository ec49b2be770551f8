/* The CPU reference engine for a whole image: every pixel's ray through ref_trace(), shaded as the
 * GPU shades it, on all cores (pthreads), with progress on stderr for long renders. */
#ifndef BT_ENGINE_CPU_H
#define BT_ENGINE_CPU_H
#include "io/progress.h"
#include "results/dump.h"
#include "ref/reference.h"

/* Worker threads of one CPU render (--threads): their handles live in a fixed array. */
#define CPU_MAX_THREADS 256

struct cpu_render_options {
    struct ref_options ref;
    int threads;          /* 0: one per online core */
    enum progress_mode progress;   /* rows done on stderr (io/progress.h) */
    int hdr;              /* also the unclamped colour (cpu_image.color) */
};

struct cpu_image {
    int width, height;
    unsigned char *rgba;  /* RGBA8, top row first, as written to the PNG */
    float *color;         /* the same unclamped, RGBA floats (cpu_render_options.hdr); else NULL */
    struct dump dump;     /* per-pixel records (rgba included), engine "cpu dopri5 rtol R" */
    double seconds;       /* wall time */
    long steps, rejected; /* summed over all rays */
    int threads;          /* worker threads that ran */
};

/* Render scene s (its render.width x render.height). 0 ok, or -1 with e: a texture that cannot be read
 * (cpu_materials_load's error, its status with it), or out of memory (the machine's). */
int cpu_render(const struct scene *s, const struct cpu_render_options *o, struct cpu_image *out, struct error *e);
void cpu_image_free(struct cpu_image *img);
/* The dump record of one traced ray with its colour. */
void ref_ray_to_record(const struct ref_ray *ray, const unsigned char rgba[4], struct dump_record *rec);
/* The 8-bit colour of pixel (i, j) for a ray traced through its centre, as the CPU image writes it
 * with one sample and before the point stars of [sky] stars are added (results/star_light.h needs
 * the whole image). 0, or -1 with e (a texture that cannot be read). */
int ref_pixel_colour(const struct scene *s, const struct ref_ray *ray, int i, int j, unsigned char rgba[4],
                     struct error *e);

#endif
