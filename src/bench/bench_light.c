/* The image's light at the kiosk's 1280x720: what each addition to demo.scene's view costs, from the
 * disk alone (its matter at rest at one temperature, each channel clipped at white, a black sky) to
 * the disk's emission, the filmic curve and gain, the point stars (on the CPU after the frame, or on
 * the GPU in its own pass) and the bloom; and the bloom alone at 1920x1080. */
#include <stdlib.h>
#include "bench/bench.h"
#include "io/parallel.h"
#include "results/bloom.h"

/* The additions, each on top of the ones above it. */
enum addition { BARE, EMISSION, CURVE, STARS_CPU, STARS_GPU, BLOOM, ADDITIONS };
static const char *const addition_names[ADDITIONS] = {
    "the disk alone: its matter at rest at one temperature, each channel clipped at white, a black sky",
    "+ the disk's emission: each point's orbit and temperature (docs/RELATIVITY.md)",
    "+ the filmic curve and gain 2 (`render.tone_curve`, `render.gain`)",
    "+ point stars and the Milky Way, drawn on the CPU after the frame (`[sky] stars`, `star_pass = cpu`)",
    "the same stars drawn on the GPU in the frame's own pass instead (`star_pass = gpu`, the kiosk's)",
    "+ bloom 0.15 (`render.bloom`), with the stars on the CPU",
};

/* demo.scene as shipped, taken back to the additions up to a. */
static void with_additions(struct scene *s, const struct scene *shipped, enum addition a)
{
    *s = *shipped;
    s->render.bloom = a >= BLOOM ? (shipped->render.bloom > 0.0 ? shipped->render.bloom : 0.15) : 0.0;
    s->render.star_pass = a == STARS_GPU ? STAR_PASS_GPU : STAR_PASS_CPU;
    if (a < STARS_CPU) {
        s->sky.stars = 0;
        s->sky.milky_way = 0.0;
    }
    if (a < CURVE) {
        s->render.tone_curve = TONE_CURVE_CLIP;
        s->render.gain = 1.0;
    }
    for (int i = 0; i < s->n_objects && a < EMISSION; i++)
        s->objects[i].material.accretion = 0;
}

/* The light section, its scene loaded into S. */
static int light_on(struct bench *b, struct scene *s, struct error *e)
{
    if (bench_load_scene(s, "demo", b->quick ? 64 : 1280, b->quick ? 36 : 720, e) != 0)
        return -1;
    s->render.samples = 1;
    struct scene *shipped = malloc(sizeof *shipped);
    FILE *csv = shipped ? bench_data_file(b, "light.csv", e) : NULL;
    if (!shipped || !csv) {
        free(shipped);
        return shipped ? -1 : error_set(e, ERROR_RUNTIME, NULL, "out of memory for a scene");
    }
    *shipped = *s;
    fprintf(csv, "addition,width,height,gpu_seconds,star_seconds,bloom_seconds\n");
    fprintf(b->md, "## The image's light\n\nWhat each addition to demo.scene's view costs at %dx%d, one ray a pixel "
                   "(docs/SCENES.md, docs/STARS.md, docs/RELATIVITY.md), each on top of the ones above it. The GPU's "
                   "frame, then on the CPU the stars of the CPU's pass and the bloom (where either is drawn there, or "
                   "the curve must come after the stars, the frame is read as floats and the 8-bit image made on the "
                   "CPU: src/results/bloom.h); median seconds per frame of %d runs.\n\n| addition | GPU frame | stars "
                   "on the CPU | bloom on the CPU | total | ratio to the disk alone |\n|---|---|---|---|---|---|\n",
            s->render.width, s->render.height, b->runs);
    int rc = 0;
    double bare = 0.0, bloom_720 = 0.0;
    for (int a = 0; a < ADDITIONS && rc == 0; a++) {
        with_additions(s, shipped, (enum addition)a);
        bench_progress(b, "light: demo at %dx%d, %s", s->render.width, s->render.height, addition_names[a]);
        struct frame_times times;
        rc = bench_frame_times(b, s, b->runs, &times, NULL, e);
        if (rc != 0)
            break;
        double gpu = times.gpu, stars = times.stars, bloom = times.bloom;
        b->done++;
        double total = gpu + stars + bloom;
        bare = a == BARE ? total : bare;
        bloom_720 = a == BLOOM ? bloom : bloom_720;
        fprintf(b->md, "| %s | %.3f | %.3f | %.3f | %.3f | %.2f |\n", addition_names[a], gpu, stars, bloom, total,
                bare > 0.0 ? total / bare : 0.0);
        fprintf(csv, "%d,%d,%d,%.5f,%.5f,%.5f\n", a, s->render.width, s->render.height, gpu, stars, bloom);
    }
    if (rc == 0 && !b->quick) {
        /* the bloom alone at a larger size */
        with_additions(s, shipped, BLOOM);
        s->render.width = 1920;
        s->render.height = 1080;
        bench_progress(b, "light: demo at 1920x1080 with bloom");
        struct frame_times times;
        rc = bench_frame_times(b, s, b->runs, &times, NULL, e);
        double gpu = times.gpu, stars = times.stars, bloom = times.bloom;
        if (rc == 0) {
            b->done++;
            fprintf(b->md, "\nAt 1920x1080 with everything: GPU frame %.3f s, stars %.3f s, bloom %.3f s.\n", gpu, stars,
                    bloom);
            fprintf(csv, "%d,1920,1080,%.5f,%.5f,%.5f\n", BLOOM, gpu, stars, bloom);
        }
    }
    if (rc == 0) {
        /* the bloom's rows split over the cores (io/parallel.h): a Pi 4 has four, each 2-4 times
         * slower than one of this machine's */
        int cores = parallel_parts(1 << 20, 1 << 20);
        double per_pi = bloom_720 * cores / 4.0;   /* the same work on four cores as fast as these */
        fprintf(b->md, "\nEach of the bloom's %d Gaussians is drawn on an image of a pyramid where it is one to two "
                       "pixels wide, so the bloom costs about the same whatever the image shows and whatever "
                       "`bloom_radius`: the full image is read and written a few times for each, its rows split over "
                       "the %d cores here. On a Raspberry Pi 4 (an estimate: its four Cortex-A72 cores are each 2-4 "
                       "times slower than one of this machine's, and the rows split over them alike) the %.0f ms of "
                       "the bloom at %dx%d would be about %.0f-%.0f ms. The kiosk draws no bloom; it draws the stars on "
                       "the GPU.\n\n",
                BLOOM_LEVELS, cores, 1e3 * bloom_720, b->quick ? 64 : 1280, b->quick ? 36 : 720,
                2e3 * per_pi, 4e3 * per_pi);
    }
    fclose(csv);
    free(shipped);
    return rc;
}

int bench_light(struct bench *b, struct error *e)
{
    return bench_with_scene(b, light_on, e);
}
