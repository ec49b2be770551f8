/* Per-pixel results in a documented binary file (docs/DUMP.md): what each pixel's ray hit,
 * where, where it ended, in which direction, after how many steps. Written by both engines. */
#ifndef BT_DUMP_H
#define BT_DUMP_H
#include <stddef.h>
#include <stdint.h>

#include "io/error.h"

#define DUMP_MAGIC "BTDUMP\0\0"
#define DUMP_VERSION 2
#define DUMP_HEADER_SIZE 96
#define DUMP_RECORD_SIZE 52
/* What a reader accepts from a header, checked before any record is allocated (and the records
 * the header promises must be in the file): at least what a render can write (SCENE_MAX_SIZE,
 * SCENE_MAX_PIXELS, SCENE_MAX_OBJECTS; src/results/dump_scene.c checks it at compile time). */
#define DUMP_MAX_SIDE 8192          /* pixels along either side */
#define DUMP_MAX_PIXELS (1L << 23)  /* records, width x height: 436 MB of records in memory */
#define DUMP_MAX_OBJECTS 64         /* entries of the object-size table */

/* Outcome of a ray: object index >= 0, or one of these; both engines write them, the GPU in the alpha
 * of its image texture. */
enum dump_outcome { DUMP_SKY = -1, DUMP_CAPTURED = -2, DUMP_UNFINISHED = -3, DUMP_FAILED = -4 };

struct dump_record {
    int32_t outcome;
    float hit[3];          /* hit point (outcome >= 0) */
    float position[3];     /* final position of the ray */
    float direction[3];    /* final direction, unit length */
    float depth;           /* segment index + fraction where the ray ended */
    uint32_t steps;        /* integration steps taken */
    uint8_t rgba[4];       /* the pixel's colour in the PNG, sRGB 8 bit */
};

struct dump {
    int width, height;
    char engine[32];       /* "gpu fp32+mrt", "cpu", ... */
    char scene[32];        /* scene name: compare refuses dumps of different scenes */
    int n_objects;
    float object_size[DUMP_MAX_OBJECTS]; /* length scale of each object, for relative hit errors */
    struct dump_record *records;  /* width * height, top row first */
};

const char *dump_outcome_name(int32_t outcome);   /* "sky", "captured", ..., "object" */
/* 0, or -1 with the message in *e: ERROR_INPUT for a refused path (output_check's rules),
 * ERROR_RUNTIME for a write that failed. */
int dump_write(const char *path, const struct dump *d, int overwrite, struct error *e);
/* DUMP_READ_NO_MEMORY: the dump is well formed, but its records do not fit in memory (a failure
 * of this machine, not of the input; ERROR_RUNTIME in *e) */
#define DUMP_READ_NO_MEMORY (-2)
/* 0, DUMP_READ_NO_MEMORY, or -1 with the message in *e: ERROR_INPUT for a file that is missing,
 * unreadable, not a dump, unsupported, truncated or followed by more data, ERROR_RUNTIME for a
 * failure of the machine. */
int dump_read(const char *path, struct dump *d, struct error *e);
void dump_free(struct dump *d);

#endif
