#include "io/parallel.h"
#include <pthread.h>
#include <unistd.h>

/* parts a job may take (the CPU-limit bench's most threads) */
#define PARALLEL_MAX 256

int parallel_parts(int items, int most)
{
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    int n = cores < 1 ? 1 : cores > PARALLEL_MAX ? PARALLEL_MAX : (int)cores;
    n = n > most ? most : n;
    n = n > items ? items : n;
    return n < 1 ? 1 : n;
}

struct part {
    void (*fn)(void *arg, int part, int parts);
    void *arg;
    int part, parts;
    pthread_t thread;
};

static void *run_part(void *p)
{
    struct part *w = p;
    w->fn(w->arg, w->part, w->parts);
    return NULL;
}

void parallel_run(int parts, void (*fn)(void *arg, int part, int parts), void *arg)
{
    parts = parts < 1 ? 1 : parts > PARALLEL_MAX ? PARALLEL_MAX : parts;
    struct part w[PARALLEL_MAX];
    int started[PARALLEL_MAX] = {0};
    for (int i = 0; i < parts; i++) {
        w[i] = (struct part){fn, arg, i, parts, 0};
        started[i] = i > 0 && pthread_create(&w[i].thread, NULL, run_part, &w[i]) == 0;
    }
    fn(arg, 0, parts);
    for (int i = 1; i < parts; i++) {
        if (started[i])
            pthread_join(w[i].thread, NULL);
        else
            fn(arg, i, parts);   /* a thread that did not start: its part here */
    }
}
