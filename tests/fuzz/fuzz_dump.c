/* libFuzzer harness: per-pixel dump files (docs/DUMP.md), read by `bentray compare`.
 *
 * The input is a dump file: dump_read(). What it accepts must be what the format allows (sides 1 to
 * DUMP_MAX_SIDE, at most DUMP_MAX_OBJECTS objects, terminated names) and every record must be there
 * to read (the sanitizer sees each one read); it must then survive dump_write() and a second
 * dump_read() unchanged, bit for bit (the writer is what the engines use). A refusal must say why,
 * as the input's fault (ERROR_INPUT), or the machine's where the records do not fit in memory.
 *
 * dump_read() takes a path: the input goes to one temporary file per process, made at start in
 * $BT_FUZZ_TMPDIR (else $TMPDIR, else /tmp), rewritten for every input and removed at exit, and so
 * does the rewritten copy. */
#include <errno.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <unistd.h>
#include "fuzz_input_file.h"
#include "results/dump.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The second file, for the copy dump_write() makes: next to the first, removed at exit. */
static char copy_path[sizeof tmp_path + 8];

static void copy_remove(void)
{
    if (copy_path[0] != '\0')
        unlink(copy_path);
}

/* ---- the harness ------------------------------------------------------------------------------ */

static void check_refusal(const struct error *e, int rc)
{
    if (memchr(e->message, '\0', sizeof e->message) == NULL || e->message[0] == '\0')
        __builtin_trap();
    if (e->status != (rc == DUMP_READ_NO_MEMORY ? ERROR_RUNTIME : ERROR_INPUT))
        __builtin_trap();
}

/* Reads every field of every record, so that a record short of the allocation shows. */
static uint32_t touch(const struct dump *d)
{
    uint32_t sum = 0;
    size_t n = (size_t)d->width * (size_t)d->height;
    for (size_t i = 0; i < n; i++) {
        uint32_t words[13];
        memcpy(words, &d->records[i], sizeof words);
        for (int k = 0; k < 13; k++)
            sum ^= words[k];
        if (dump_outcome_name(d->records[i].outcome) == NULL)
            __builtin_trap();
    }
    return sum;
}

static int same_dump(const struct dump *a, const struct dump *b)
{
    size_t n = (size_t)a->width * (size_t)a->height;
    if (a->width != b->width || a->height != b->height || a->n_objects != b->n_objects ||
        strcmp(a->engine, b->engine) != 0 || strcmp(a->scene, b->scene) != 0)
        return 0;
    if (memcmp(a->object_size, b->object_size, (size_t)a->n_objects * sizeof a->object_size[0]) != 0)
        return 0;
    for (size_t i = 0; i < n; i++) {
        const struct dump_record *x = &a->records[i], *y = &b->records[i];
        if (x->outcome != y->outcome || memcmp(x->hit, y->hit, sizeof x->hit) != 0 ||
            memcmp(x->position, y->position, sizeof x->position) != 0 ||
            memcmp(x->direction, y->direction, sizeof x->direction) != 0 ||
            memcmp(&x->depth, &y->depth, sizeof x->depth) != 0 || x->steps != y->steps ||
            memcmp(x->rgba, y->rgba, sizeof x->rgba) != 0)
            return 0;
    }
    return 1;
}

/* where touch() leaves its sum, so that the reads are not optimised away */
volatile uint32_t fuzz_dump_sink;

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    tmp_create("dump");
    /* made now so that it is ours; dump_write() replaces its contents */
    snprintf(copy_path, sizeof copy_path, "%s.copy", tmp_path);
    FILE *f = fopen(copy_path, "wb");
    if (f == NULL) {
        fprintf(stderr, "fuzz: cannot create %s: %s\n", copy_path, strerror(errno));
        exit(2);
    }
    fclose(f);
    atexit(copy_remove);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct dump d, again;
    static struct error err;

    tmp_write(data, size);
    int rc = dump_read(tmp_path, &d, &err);
    if (rc != 0) {
        check_refusal(&err, rc);
        if (d.records != NULL)      /* refused: nothing left to free */
            __builtin_trap();
        return 0;
    }
    if (d.width < 1 || d.height < 1 || d.width > DUMP_MAX_SIDE || d.height > DUMP_MAX_SIDE ||
        d.n_objects < 0 || d.n_objects > DUMP_MAX_OBJECTS || d.records == NULL ||
        memchr(d.engine, '\0', sizeof d.engine) == NULL || memchr(d.scene, '\0', sizeof d.scene) == NULL)
        __builtin_trap();
    /* the whole file was read: header, object table, records, nothing after */
    if (size != DUMP_HEADER_SIZE + 4u * (size_t)d.n_objects +
                (size_t)d.width * (size_t)d.height * DUMP_RECORD_SIZE)
        __builtin_trap();
    fuzz_dump_sink = touch(&d);

    if (dump_write(copy_path, &d, 1, &err) != 0) {
        fprintf(stderr, "fuzz: dump_write: %s\n", err.message);
        abort();
    }
    if (dump_read(copy_path, &again, &err) != 0 || !same_dump(&d, &again))
        __builtin_trap();
    dump_free(&again);
    dump_free(&d);
    if (d.records != NULL)
        __builtin_trap();
    return 0;
}
