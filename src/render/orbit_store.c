/* The orbit tables a renderer has built or will need (orbit_store.h). One lock guards the list; the
 * worker builds outside it. Entries are allocated one by one, so that a table handed to a caller
 * stays where it is while the worker adds to the list; only the caller's thread frees entries. */
#include "render/orbit_store.h"
#include "io/clock.h"
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

enum entry_state { ENTRY_QUEUED, ENTRY_BUILDING, ENTRY_READY, ENTRY_FAILED };

struct entry {
    struct orbit_table_params p;
    struct orbit_table table;     /* ENTRY_READY: its texels and scalars */
    enum entry_state state;
    int order;                    /* ENTRY_QUEUED: built lowest first */
    unsigned long used;           /* ENTRY_READY: when last asked for or prefetched (least recent goes first) */
};

struct orbit_store {
    pthread_mutex_t lock;
    pthread_cond_t changed;       /* an entry was built, or there is work or an end */
    struct entry **entries;
    int n, cap;
    size_t budget, ready_bytes;
    unsigned long tick;
    int refs;                     /* the owner, and the worker once started */
    int worker_started, quit;
    double caller_seconds;
    int caller_builds;
};

int orbit_params_same(const struct orbit_table_params *a, const struct orbit_table_params *b)
{
    return a->mass == b->mass && a->r_observer == b->r_observer && a->r_far == b->r_far &&
           a->rows_per_side == b->rows_per_side && a->columns == b->columns &&
           a->chord_tolerance == b->chord_tolerance && a->max_segments == b->max_segments &&
           a->clear_radius == b->clear_radius;
}

size_t orbit_store_table_bytes(const struct orbit_table_params *p)
{
    return (size_t)(p->columns + 1 + ORBIT_WARP_SAMPLES) * 2 * (size_t)p->rows_per_side * 4 * sizeof(float);
}

static int find(const struct orbit_store *s, const struct orbit_table_params *p)
{
    for (int i = 0; i < s->n; i++)
        if (s->entries[i]->state != ENTRY_FAILED && orbit_params_same(&s->entries[i]->p, p))
            return i;
    return -1;
}

static struct entry *add(struct orbit_store *s, const struct orbit_table_params *p, enum entry_state state)
{
    if (s->n == s->cap) {
        int cap = s->cap ? 2 * s->cap : 32;
        struct entry **grown = realloc(s->entries, (size_t)cap * sizeof *grown);
        if (!grown)
            return NULL;
        s->entries = grown;
        s->cap = cap;
    }
    struct entry *en = calloc(1, sizeof *en);
    if (!en)
        return NULL;
    en->p = *p;
    en->state = state;
    s->entries[s->n++] = en;
    return en;
}

/* Not an entry the worker is building: it finds its entry by its parameters when done. */
static void drop(struct orbit_store *s, int i)
{
    struct entry *en = s->entries[i];
    if (en->state == ENTRY_READY) {
        s->ready_bytes -= orbit_store_table_bytes(&en->p);
        orbit_table_free(&en->table);
    }
    free(en);
    s->entries[i] = s->entries[--s->n];
}

/* Least recently used tables go until the kept ones fit the budget; keep stays. */
static void trim(struct orbit_store *s, const struct entry *keep)
{
    while (s->ready_bytes > s->budget) {
        int oldest = -1;
        for (int i = 0; i < s->n; i++)
            if (s->entries[i]->state == ENTRY_READY && s->entries[i] != keep &&
                (oldest < 0 || s->entries[i]->used < s->entries[oldest]->used))
                oldest = i;
        if (oldest < 0)
            return;
        drop(s, oldest);
    }
}

static void free_store(struct orbit_store *s)
{
    while (s->n > 0) {
        if (s->entries[s->n - 1]->state == ENTRY_READY)
            orbit_table_free(&s->entries[s->n - 1]->table);
        free(s->entries[--s->n]);
    }
    free(s->entries);
    pthread_cond_destroy(&s->changed);
    pthread_mutex_destroy(&s->lock);
    free(s);
}

/* Lets go of one reference (the lock held); the last one frees the store. */
static void release(struct orbit_store *s)
{
    int last = --s->refs == 0;
    pthread_mutex_unlock(&s->lock);
    if (last)
        free_store(s);
}

static void *worker_main(void *arg)
{
    struct orbit_store *s = arg;
    pthread_mutex_lock(&s->lock);
    while (!s->quit) {
        struct entry *next = NULL;
        for (int i = 0; i < s->n; i++)
            if (s->entries[i]->state == ENTRY_QUEUED && (!next || s->entries[i]->order < next->order))
                next = s->entries[i];
        if (!next) {
            pthread_cond_wait(&s->changed, &s->lock);
            continue;
        }
        struct orbit_table_params p = next->p;
        next->state = ENTRY_BUILDING;
        pthread_mutex_unlock(&s->lock);
        struct orbit_table t;
        struct error e;
        int rc = orbit_table_build(&t, &p, &e);
        if (rc == 0)
            orbit_table_free_cpu_arrays(&t);
        pthread_mutex_lock(&s->lock);
        /* only this thread moves an entry out of ENTRY_BUILDING, and the owner drops no such entry */
        struct entry *en = NULL;
        for (int i = 0; i < s->n && !en; i++)
            if (s->entries[i]->state == ENTRY_BUILDING && orbit_params_same(&s->entries[i]->p, &p))
                en = s->entries[i];
        if (en && rc == 0) {
            en->table = t;
            en->state = ENTRY_READY;
            en->used = ++s->tick;
            s->ready_bytes += orbit_store_table_bytes(&p);
        } else {
            if (rc == 0)
                orbit_table_free(&t);
            if (en)
                en->state = ENTRY_FAILED;    /* orbit_store_get builds it again, for its error */
        }
        pthread_cond_broadcast(&s->changed);
    }
    release(s);
    return NULL;
}

struct orbit_store *orbit_store_create(size_t budget, struct error *e)
{
    struct orbit_store *s = calloc(1, sizeof *s);
    if (!s) {
        error_set(e, ERROR_RUNTIME, NULL, "out of memory for the orbit tables");
        return NULL;
    }
    pthread_mutex_init(&s->lock, NULL);
    pthread_cond_init(&s->changed, NULL);
    s->budget = budget;
    s->refs = 1;
    return s;
}

void orbit_store_destroy(struct orbit_store *s)
{
    if (!s)
        return;
    pthread_mutex_lock(&s->lock);
    s->quit = 1;
    pthread_cond_broadcast(&s->changed);
    release(s);
}

const struct orbit_table *orbit_store_get(struct orbit_store *s, const struct orbit_table_params *p,
                                          struct error *e)
{
    double t0 = clock_seconds();
    struct entry *en = NULL;
    pthread_mutex_lock(&s->lock);
    for (;;) {
        int i = find(s, p);
        if (i >= 0 && s->entries[i]->state == ENTRY_READY) {
            en = s->entries[i];
            break;
        }
        if (i >= 0 && s->entries[i]->state == ENTRY_BUILDING) {
            /* the worker is on it: waiting is shorter than building it again */
            pthread_cond_wait(&s->changed, &s->lock);
            continue;
        }
        if (i >= 0)
            drop(s, i);                      /* queued: built here, now */
        for (int k = s->n - 1; k >= 0; k--)
            if (s->entries[k]->state == ENTRY_FAILED && orbit_params_same(&s->entries[k]->p, p))
                drop(s, k);
        pthread_mutex_unlock(&s->lock);
        struct orbit_table t;
        int rc = orbit_table_build(&t, p, e);
        pthread_mutex_lock(&s->lock);
        s->caller_builds++;
        if (rc == 0) {
            orbit_table_free_cpu_arrays(&t);
            en = add(s, p, ENTRY_READY);
            if (!en) {
                orbit_table_free(&t);
                error_set(e, ERROR_RUNTIME, NULL, "out of memory for the orbit tables");
            } else {
                en->table = t;
                s->ready_bytes += orbit_store_table_bytes(p);
            }
        }
        break;
    }
    if (en) {
        en->used = ++s->tick;
        trim(s, en);
    }
    s->caller_seconds += clock_seconds() - t0;
    pthread_mutex_unlock(&s->lock);
    return en ? &en->table : NULL;
}

void orbit_store_prefetch(struct orbit_store *s, const struct orbit_table_params *p, int n)
{
    pthread_mutex_lock(&s->lock);
    for (int i = s->n - 1; i >= 0; i--)
        if (s->entries[i]->state == ENTRY_QUEUED || s->entries[i]->state == ENTRY_FAILED)
            drop(s, i);
    size_t room = s->budget;
    unsigned long base = s->tick;
    for (int k = 0; k < n; k++) {
        size_t bytes = orbit_store_table_bytes(&p[k]);
        if (bytes > ORBIT_STORE_AHEAD_MAX_BYTES)
            continue;
        if (bytes > room)
            break;
        room -= bytes;
        int i = find(s, &p[k]);
        if (i >= 0) {
            /* the first of the list is the most recently wanted */
            if (s->entries[i]->state == ENTRY_READY)
                s->entries[i]->used = base + (unsigned long)(n - k);
            continue;
        }
        struct entry *en = add(s, &p[k], ENTRY_QUEUED);
        if (!en)
            break;
        en->order = k;
    }
    s->tick = base + (unsigned long)n + 1;
    trim(s, NULL);
    if (!s->worker_started) {
        pthread_t worker;
        pthread_attr_t attr;
        pthread_attr_init(&attr);
        pthread_attr_setdetachstate(&attr, PTHREAD_CREATE_DETACHED);
        if (pthread_create(&worker, &attr, worker_main, s) == 0) {
            s->worker_started = 1;
            s->refs++;
        }
        pthread_attr_destroy(&attr);
    }
    pthread_cond_broadcast(&s->changed);
    pthread_mutex_unlock(&s->lock);
}

int orbit_store_pending(struct orbit_store *s)
{
    pthread_mutex_lock(&s->lock);
    int pending = 0;
    for (int i = 0; i < s->n; i++)
        pending += s->entries[i]->state == ENTRY_QUEUED || s->entries[i]->state == ENTRY_BUILDING;
    if (!s->worker_started)
        pending = 0;
    pthread_mutex_unlock(&s->lock);
    return pending;
}

double orbit_store_caller_seconds(const struct orbit_store *s)
{
    return s->caller_seconds;
}

int orbit_store_caller_builds(const struct orbit_store *s)
{
    return s->caller_builds;
}

size_t orbit_store_bytes(struct orbit_store *s)
{
    pthread_mutex_lock(&s->lock);
    size_t bytes = s->ready_bytes;
    pthread_mutex_unlock(&s->lock);
    return bytes;
}
