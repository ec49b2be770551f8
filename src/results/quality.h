/* A scene's stated quality ([quality]: upper bounds on its error against the CPU reference) held
 * against one comparison. */
#ifndef BT_QUALITY_H
#define BT_QUALITY_H
#include <stddef.h>
#include "results/compare.h"
#include "scene/scene.h"

/* 1 when the scene states at least one bound. */
int quality_stated(const struct quality_bound *q);

/* Hold r against q: one line per stated bound into report ("exit p99 0.00016 rad <= 0.001: met").
 * A statistic over no pixels (no sky pixel, no hit) meets its bound. Returns the number of bounds
 * missed; -1 when q states none. */
int quality_check(const struct quality_bound *q, const struct compare_result *r, char *report, size_t len);

#endif
