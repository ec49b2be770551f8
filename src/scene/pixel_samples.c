#include "scene/pixel_samples.h"
#include <math.h>

/* The centre of slice index of n, as an offset from the pixel's centre, on the grid. */
static double slice_centre(int index, int n)
{
    double t = (index + 0.5) / n;
    return floor(t * PIXEL_SAMPLE_GRID + 0.5) / PIXEL_SAMPLE_GRID - 0.5;
}

static int gcd(int a, int b)
{
    while (b) {
        int t = a % b;
        a = b;
        b = t;
    }
    return a;
}

/* The shift c that makes the lattice (k, g k + c) symmetric about the centre: point N-1-k is the
 * mirror of point k when 2 c = g - 1 (mod N). -1 when there is none (N even and g even). */
static int symmetric_shift(int g, int n)
{
    for (int c = 0; c < n; c++)
        if ((2 * c) % n == ((g - 1) % n + n) % n)
            return c;
    return -1;
}

/* Squared distance of the lattice's closest pair, on the torus (the same for every point). */
static long lattice_spacing(int g, int n)
{
    long best = -1;
    for (int k = 1; k < n; k++) {
        long x = k < n - k ? k : n - k, y = ((long)g * k) % n;
        y = y < n - y ? y : n - y;
        long d = x * x + y * y;
        if (best < 0 || d < best)
            best = d;
    }
    return best;
}

static void rotated_grid(int m, struct pixel_samples *out)
{
    int n = m * m;
    for (int i = 0; i < m; i++)
        for (int j = 0; j < m; j++) {
            int k = i * m + j;
            out->dx[k] = slice_centre(i * m + j, n);
            out->dy[k] = slice_centre(j * m + (m - 1 - i), n);
        }
}

static void lattice(int n, struct pixel_samples *out)
{
    int best_g = 1, best_c = symmetric_shift(1, n);
    long best = -1;
    for (int g = 1; g < n; g++) {
        int c = symmetric_shift(g, n);
        if (gcd(g, n) != 1 || c < 0)
            continue;
        long d = lattice_spacing(g, n);
        if (d > best) {
            best = d;
            best_g = g;
            best_c = c;
        }
    }
    for (int k = 0; k < n; k++) {
        out->dx[k] = slice_centre(k, n);
        out->dy[k] = slice_centre((int)(((long)best_g * k + best_c) % n), n);
    }
}

void pixel_samples_make(int n, struct pixel_samples *out)
{
    if (n < 1 || n > SCENE_MAX_SAMPLES)
        n = 1;
    out->n = n;
    int m = (int)lrint(sqrt((double)n));
    if (m * m == n)
        rotated_grid(m, out);
    else
        lattice(n, out);
    /* the centre, where there is one, first */
    out->centre_included = 0;
    for (int k = 0; k < n; k++)
        if (out->dx[k] == 0.0 && out->dy[k] == 0.0) {
            out->dx[k] = out->dx[0];
            out->dy[k] = out->dy[0];
            out->dx[0] = 0.0;
            out->dy[0] = 0.0;
            out->centre_included = 1;
            break;
        }
}
