#include "results/dump.h"
#include "io/output_file.h"
#include "io/text_file.h"
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

const char *dump_outcome_name(int32_t outcome)
{
    switch (outcome) {
    case DUMP_SKY: return "sky";
    case DUMP_CAPTURED: return "captured";
    case DUMP_UNFINISHED: return "unfinished";
    case DUMP_FAILED: return "failed";
    default: return outcome >= 0 ? "object" : "invalid";
    }
}

static void put_u32(unsigned char *p, uint32_t v)
{
    for (int i = 0; i < 4; i++)
        p[i] = (unsigned char)(v >> (8 * i));
}

static uint32_t get_u32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static void put_f32(unsigned char *p, float f)
{
    uint32_t v;
    memcpy(&v, &f, 4);
    put_u32(p, v);
}

static float get_f32(const unsigned char *p)
{
    uint32_t v = get_u32(p);
    float f;
    memcpy(&f, &v, 4);
    return f;
}

static void encode(unsigned char *p, const struct dump_record *r)
{
    put_u32(p, (uint32_t)r->outcome);
    for (int i = 0; i < 3; i++) {
        put_f32(p + 4 + 4 * i, r->hit[i]);
        put_f32(p + 16 + 4 * i, r->position[i]);
        put_f32(p + 28 + 4 * i, r->direction[i]);
    }
    put_f32(p + 40, r->depth);
    put_u32(p + 44, r->steps);
    memcpy(p + 48, r->rgba, 4);
}

static void decode(const unsigned char *p, struct dump_record *r)
{
    r->outcome = (int32_t)get_u32(p);
    for (int i = 0; i < 3; i++) {
        r->hit[i] = get_f32(p + 4 + 4 * i);
        r->position[i] = get_f32(p + 16 + 4 * i);
        r->direction[i] = get_f32(p + 28 + 4 * i);
    }
    r->depth = get_f32(p + 40);
    r->steps = get_u32(p + 44);
    memcpy(r->rgba, p + 48, 4);
}

int dump_write(const char *path, const struct dump *d, int overwrite, struct error *e)
{
    struct output_file o;
    if (output_open(&o, path, overwrite, e) != 0)
        return -1;
    FILE *f = o.fp;
    unsigned char header[DUMP_HEADER_SIZE] = {0}, rec[DUMP_RECORD_SIZE];
    memcpy(header, DUMP_MAGIC, 8);
    put_u32(header + 8, DUMP_VERSION);
    put_u32(header + 12, (uint32_t)d->width);
    put_u32(header + 16, (uint32_t)d->height);
    put_u32(header + 20, DUMP_RECORD_SIZE);
    snprintf((char *)header + 24, 32, "%s", d->engine);
    put_u32(header + 56, (uint32_t)d->n_objects);
    snprintf((char *)header + 64, 32, "%s", d->scene);
    int ok = fwrite(header, sizeof header, 1, f) == 1;
    for (int i = 0; ok && i < d->n_objects; i++) {
        unsigned char size[4];
        put_f32(size, d->object_size[i]);
        ok = fwrite(size, sizeof size, 1, f) == 1;
    }
    size_t n = (size_t)d->width * d->height;
    for (size_t i = 0; ok && i < n; i++) {
        encode(rec, &d->records[i]);
        ok = fwrite(rec, sizeof rec, 1, f) == 1;
    }
    if (!ok) {
        /* the old file, if any, is untouched: only the temporary goes */
        error_set(e, ERROR_RUNTIME, NULL, "cannot write %s: %s", path, strerror(errno));
        output_abort(&o);
        return -1;
    }
    return output_commit(&o, e);
}

int dump_read(const char *path, struct dump *d, struct error *e)
{
    memset(d, 0, sizeof *d);
    struct error why;
    FILE *f = regular_file_open(path, "dump", &why);
    if (!f)
        return error_set(e, why.status, NULL, "%s: %s", path, why.message);
    unsigned char header[DUMP_HEADER_SIZE], rec[DUMP_RECORD_SIZE];
    if (fread(header, sizeof header, 1, f) != 1 || memcmp(header, DUMP_MAGIC, 8) != 0) {
        fclose(f);
        return error_set(e, ERROR_INPUT, NULL, "%s is not a bentray dump (bad header)", path);
    }
    uint32_t version = get_u32(header + 8), w = get_u32(header + 12), h = get_u32(header + 16);
    uint32_t rsize = get_u32(header + 20), n_objects = get_u32(header + 56);
    if (version != DUMP_VERSION || rsize != DUMP_RECORD_SIZE || w < 1 || h < 1 || w > DUMP_MAX_SIDE ||
        h > DUMP_MAX_SIDE || (unsigned long)w * h > (unsigned long)DUMP_MAX_PIXELS || n_objects > DUMP_MAX_OBJECTS) {
        fclose(f);
        return error_set(e, ERROR_INPUT, NULL,
                         "%s: unsupported dump (version %u, %ux%u, record %u bytes, %u objects; expected "
                         "version %d, sides 1..%d and at most %ld pixels, record %d bytes, at most %d objects)",
                         path, version, w, h, rsize, n_objects, DUMP_VERSION, DUMP_MAX_SIDE, DUMP_MAX_PIXELS,
                         DUMP_RECORD_SIZE, DUMP_MAX_OBJECTS);
    }
    d->width = (int)w;
    d->height = (int)h;
    memcpy(d->engine, header + 24, 31);
    d->engine[31] = '\0';
    memcpy(d->scene, header + 64, 31);
    d->scene[31] = '\0';
    d->n_objects = (int)n_objects;
    for (int i = 0; i < d->n_objects; i++) {
        unsigned char size[4];
        if (fread(size, sizeof size, 1, f) != 1) {
            fclose(f);
            return error_set(e, ERROR_INPUT, NULL, "%s is truncated in its object table", path);
        }
        d->object_size[i] = get_f32(size);
    }
    size_t n = (size_t)w * h;
    /* the records the header promises must be in the file before memory is asked for them: a
     * damaged header must not cost gigabytes */
    long here = ftell(f);
    if (here < 0 || fseek(f, 0, SEEK_END) != 0) {
        fclose(f);
        return error_set(e, ERROR_RUNTIME, NULL, "cannot seek in %s: %s", path, strerror(errno));
    }
    long size = ftell(f);
    if (size < here || (unsigned long)(size - here) / DUMP_RECORD_SIZE < n || fseek(f, here, SEEK_SET) != 0) {
        fclose(f);
        return error_set(e, ERROR_INPUT, NULL, "%s is truncated: %ld of %zu records", path,
                         size < here ? 0L : (size - here) / DUMP_RECORD_SIZE, n);
    }
    d->records = malloc(n * sizeof *d->records);
    if (!d->records) {
        fclose(f);
        error_set(e, ERROR_RUNTIME, NULL, "out of memory reading %s (%zu records)", path, n);
        return DUMP_READ_NO_MEMORY;
    }
    for (size_t i = 0; i < n; i++) {
        if (fread(rec, sizeof rec, 1, f) != 1) {
            fclose(f);
            dump_free(d);
            return error_set(e, ERROR_INPUT, NULL, "%s is truncated: %zu of %zu records", path, i, n);
        }
        decode(rec, &d->records[i]);
    }
    int extra = fgetc(f) != EOF;
    fclose(f);
    if (extra) {
        dump_free(d);
        return error_set(e, ERROR_INPUT, NULL, "%s has data after its last record", path);
    }
    return 0;
}

void dump_free(struct dump *d)
{
    free(d->records);
    d->records = NULL;
}
