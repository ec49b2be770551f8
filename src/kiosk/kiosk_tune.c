/* Each scene's preview size for the preview rate (kiosk_tune.h). */
#include "kiosk/kiosk_tune.h"
#include <math.h>
#include <stdlib.h>
#include "io/clock.h"
#include "gl/caps.h"

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The median seconds of KIOSK_TUNE_FRAMES previews of st, each drawn whole (every tile). */
static int preview_seconds(struct kiosk_view *v, const struct kiosk_state *st, double *out, struct error *e)
{
    double t[KIOSK_TUNE_FRAMES];
    for (int k = 0; k < KIOSK_TUNE_FRAMES; k++) {
        double t0 = clock_seconds();
        if (kiosk_view_preview(v, st, e) != 0)
            return -1;
        while (kiosk_view_preview_pending(v))
            if (kiosk_view_refine(v, e) != 0)
                return -1;
        t[k] = clock_seconds() - t0;
        if (gl_fault("slow_previews"))
            t[k] = fmax(t[k] * KIOSK_TUNE_SLOW_FACTOR,
                        KIOSK_TUNE_SLOW_PIXEL * v->preview_width * v->preview_height);
    }
    qsort(t, KIOSK_TUNE_FRAMES, sizeof t[0], by_value);
    *out = t[KIOSK_TUNE_FRAMES / 2];
    return 0;
}

static int side(int configured, double factor)
{
    int s = (int)lround(configured * factor);
    return s < KIOSK_TUNE_MIN_SIDE ? KIOSK_TUNE_MIN_SIDE : s > configured ? configured : s;
}

int kiosk_tune_previews(struct kiosk_view *v, const struct kiosk_config *c, const struct scene *scenes,
                        int (*between)(void *arg), void *arg, FILE *log, struct error *e)
{
    const struct kiosk_main *k = &c->kiosk;
    if (k->preview_rate <= 0)
        return 0;
    double budget = 1.0 / k->preview_rate;
    int rc = 0;
    v->prefetch_off = 1;
    for (int i = 0; i < k->n_scenes && rc == 0; i++) {
        if (between && between(arg))
            break;
        struct kiosk_state st;
        kiosk_state_reset(&st, c);
        st.scene = i;
        if ((rc = kiosk_view_load(v, i, &scenes[i], e)) != 0)
            break;
        double factor = 1.0, first = 0.0, t = 0.0;
        for (int round = 0; round < KIOSK_TUNE_ROUNDS; round++) {
            if ((rc = preview_seconds(v, &st, &t, e)) != 0)
                break;
            if (round == 0)
                first = t;
            int w = v->preview_width, h = v->preview_height;
            if (t <= budget || (w == KIOSK_TUNE_MIN_SIDE && h == KIOSK_TUNE_MIN_SIDE))
                break;
            /* the cost follows the pixels: both sides by the square root of the ratio */
            factor *= sqrt(KIOSK_TUNE_MARGIN * budget / t);
            kiosk_view_set_preview_size(v, i, side(k->preview_width, factor), side(k->preview_height, factor));
        }
        if (rc != 0)
            break;
        if (v->preview_width == k->preview_width && v->preview_height == k->preview_height)
            fprintf(log, "bentray kiosk: %s: previews of %dx%d take %.0f ms here, within the %d a second asked for\n",
                    scenes[i].name, k->preview_width, k->preview_height, 1e3 * first, k->preview_rate);
        else
            fprintf(log, "bentray kiosk: %s: previews of %dx%d take %.0f ms here, more than the %d a second asked "
                    "for allow: previews at %dx%d (%.0f ms)%s\n", scenes[i].name, k->preview_width,
                    k->preview_height, 1e3 * first, k->preview_rate, v->preview_width, v->preview_height, 1e3 * t,
                    t > budget ? ", the smallest tried, still over" : "");
    }
    v->prefetch_off = 0;
    kiosk_view_unload(v);
    return rc;
}
