/* Quadrature decoding by a table over (previous ab, new ab): a Gray code changes one line per
 * step, so each of the 16 pairs is a step forward, a step back, no step, or a missed edge. */
#include "input/quadrature.h"

/* both lines changed: marked apart from the steps -1, 0, +1 */
#define MISSED_EDGE 2

/* [previous][new], states (A << 1) | B; clockwise is 0 -> 2 -> 3 -> 1 -> 0 */
static const int8_t gray_step[4][4] = {
    /* to 00         01           10           11 */
    {0,           -1,          +1,          MISSED_EDGE},  /* from 00 */
    {+1,          0,           MISSED_EDGE, -1},           /* from 01 */
    {-1,          MISSED_EDGE, 0,           +1},           /* from 10 */
    {MISSED_EDGE, +1,          -1,          0},            /* from 11 */
};

static uint8_t pack(int a, int b)
{
    return (uint8_t)((a != 0) << 1 | (b != 0));
}

/* the int64_t whose two's-complement bits are u, without the implementation-defined conversion */
static int64_t from_twos_complement(uint64_t u)
{
    return u <= (uint64_t)INT64_MAX ? (int64_t)u : -(int64_t)(UINT64_MAX - u) - 1;
}

int quadrature_init(struct quadrature *q, int counts_per_detent, int a, int b)
{
    if (counts_per_detent != 1 && counts_per_detent != 2 && counts_per_detent != 4)
        return -1;
    q->ab = pack(a, b);
    q->accumulated = 0;
    q->counts_per_detent = counts_per_detent;
    q->detents = 0;
    q->invalid = 0;
    return 0;
}

int quadrature_edge(struct quadrature *q, int a, int b)
{
    uint8_t ab = pack(a, b);
    int step = gray_step[q->ab & 3][ab];
    q->ab = ab;
    if (step == MISSED_EDGE) {
        q->invalid++;
        return 0;
    }
    q->accumulated += step;
    if (q->accumulated != q->counts_per_detent && q->accumulated != -q->counts_per_detent)
        return 0;
    int detent = q->accumulated > 0 ? 1 : -1;
    q->accumulated = 0;
    q->detents = from_twos_complement((uint64_t)q->detents + (uint64_t)(int64_t)detent);
    return detent;
}

int64_t quadrature_detents_since(const struct quadrature *q, int64_t earlier_total)
{
    return from_twos_complement((uint64_t)q->detents - (uint64_t)earlier_total);
}
