/* A scene's stated quality against one comparison with the CPU reference. */
#include "results/quality.h"
#include <math.h>
#include <stdio.h>

int quality_stated(const struct quality_bound *q)
{
    return q->differing_percent >= 0.0 || q->exit_p99 >= 0.0 || q->hit_p99 >= 0.0;
}

/* Appends one line for one bound; returns 1 when it is missed. */
static int check_one(const char *what, const char *unit, double measured, double bound, char *report, size_t len,
                     size_t *used)
{
    if (bound < 0.0)
        return 0;
    int missed = !isnan(measured) && !(measured <= bound);
    int n;
    if (isnan(measured))
        n = snprintf(report + *used, len - *used, "%s: no pixels to measure, bound %g%s: met\n", what, bound, unit);
    else
        n = snprintf(report + *used, len - *used, "%s %.3g%s %s %g%s: %s\n", what, measured, unit,
                     missed ? ">" : "<=", bound, unit, missed ? "MISSED" : "met");
    if (n > 0)
        *used += (size_t)n < len - *used ? (size_t)n : len - *used - 1;
    return missed;
}

int quality_check(const struct quality_bound *q, const struct compare_result *r, char *report, size_t len)
{
    if (len == 0)
        return -1;
    report[0] = '\0';
    if (!quality_stated(q))
        return -1;
    size_t used = 0;
    int missed = 0;
    missed += check_one("differing outcomes", "%", 100.0 * r->outcome_fraction, q->differing_percent, report, len,
                        &used);
    missed += check_one("exit p99", " rad", r->sky_angle.p99, q->exit_p99, report, len, &used);
    missed += check_one("hit p99", " of size", r->hit_relative.p99, q->hit_p99, report, len, &used);
    return missed;
}
