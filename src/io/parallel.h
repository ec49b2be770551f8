/* Work split over the cores: the one way bentray runs independent parts of a job at once (the orbit
 * table's rows, the stars of the sky, the bloom). */
#ifndef BT_PARALLEL_H
#define BT_PARALLEL_H

/* The parts a job of `items` independent items is split into: one a core, at most `most`, at
 * most `items`, at least 1. */
int parallel_parts(int items, int most);
/* fn(arg, part, parts) for every part from 0 to parts - 1 (parallel_parts), part 0 on this thread
 * and each other on a thread of its own (where one cannot start, its part runs here after part 0);
 * returns when every part has. A part takes items part, part + parts, part + 2 parts ..., or any
 * split of its own that depends on part and parts alone. */
void parallel_run(int parts, void (*fn)(void *arg, int part, int parts), void *arg);

#endif
