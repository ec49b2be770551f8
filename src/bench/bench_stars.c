/* The stars of the sky ([sky] stars, milky_way): what drawing them adds to a frame whose rays the
 * GPU traced, on the CPU after the rays or on the GPU in the frame's own pass, star_sky.scene at
 * 1920x1080 and at the kiosk's 1280x720 with no stars, the Milky Way alone, its own 30000 stars and
 * ten times as many. */
#include <stdlib.h>
#include "bench/bench.h"

static const struct {
    int stars;
    int milky_way;
    const char *what;
} star_configs[] = {
    {0, 0, "no stars, no Milky Way"},
    {0, 1, "the Milky Way alone"},
    {30000, 1, "30000 stars and the Milky Way (the scene)"},
    {300000, 1, "300000 stars and the Milky Way"},
};
#define STAR_CONFIGS (int)(sizeof star_configs / sizeof star_configs[0])

/* One table of the stars section at the scene's size: each sky with its stars drawn by the CPU's
 * pass after the rays and by the GPU's in the frame's own pass (render.star_pass = gpu). */
static int stars_table(struct bench *b, struct scene *s, FILE *csv, double milky_way, struct error *e)
{
    fprintf(b->md, "\nAt %dx%d:\n\n| sky | CPU pass: GPU seconds | star seconds | total | ratio to no stars "
                   "| GPU pass: seconds | ratio to no stars |\n|---|---|---|---|---|---|---|\n",
            s->render.width, s->render.height);
    double none = 0.0, none_gpu = 0.0;
    int rc = 0;
    for (int k = 0; k < (b->quick ? 2 : STAR_CONFIGS) && rc == 0; k++) {
        s->sky.stars = star_configs[k].stars;
        s->sky.milky_way = star_configs[k].milky_way ? milky_way : 0.0;
        bench_progress(b, "stars: %s at %dx%d", star_configs[k].what, s->render.width, s->render.height);
        struct frame_times cpu_pass, gpu_pass;
        s->render.star_pass = STAR_PASS_CPU;
        rc = bench_frame_times(b, s, b->runs, &cpu_pass, NULL, e);
        s->render.star_pass = STAR_PASS_GPU;
        if (rc == 0)
            rc = bench_frame_times(b, s, b->runs, &gpu_pass, NULL, e);
        s->render.star_pass = STAR_PASS_CPU;
        if (rc != 0)
            break;
        double gpu = cpu_pass.gpu, stars = cpu_pass.stars, on_gpu = gpu_pass.gpu;
        b->done++;
        double total = gpu + stars;
        none = k == 0 ? total : none;
        none_gpu = k == 0 ? on_gpu : none_gpu;
        fprintf(b->md, "| %s | %.3f | %.3f | %.3f | %.2f | %.3f | %.2f |\n", star_configs[k].what, gpu, stars, total,
                none > 0.0 ? total / none : 0.0, on_gpu, none_gpu > 0.0 ? on_gpu / none_gpu : 0.0);
        fprintf(csv, "%d,%d,%d,%g,%.5f,%.5f,%.5f\n", s->render.width, s->render.height, s->sky.stars, s->sky.milky_way,
                gpu, stars, on_gpu);
    }
    return rc;
}

/* The stars section, its scene loaded into S. */
static int stars_on(struct bench *b, struct scene *s, struct error *e)
{
    if (bench_load_scene(s, "star_sky", b->quick ? 64 : 1920, b->quick ? 36 : 1080, e) != 0)
        return -1;
    FILE *csv = bench_data_file(b, "stars.csv", e);
    if (!csv)
        return -1;
    fprintf(csv, "width,height,stars,milky_way,gpu_seconds,star_seconds,gpu_pass_seconds\n");
    double milky_way = s->sky.milky_way;
    fprintf(b->md, "## Stars of the sky\n\n`[sky] stars` and `milky_way` (docs/STARS.md): star_sky.scene. The GPU "
                   "traces the rays; the stars and the Milky Way are then drawn either on the CPU's cores from the "
                   "rays' exit directions (`render.star_pass = cpu`, the reference, what `bentray render` does), or "
                   "by the GPU in the frame's own pass (`gpu`, what the kiosk does, at 1280x720 its refined frame). "
                   "Median seconds per frame of %d runs.\n",
            b->runs);
    int rc = stars_table(b, s, csv, milky_way, e);
    if (rc == 0 && !b->quick) {
        s->render.width = 1280;
        s->render.height = 720;
        rc = stars_table(b, s, csv, milky_way, e);
    }
    fprintf(b->md, "\n");
    fclose(csv);
    return rc;
}

int bench_stars(struct bench *b, struct error *e)
{
    return bench_with_scene(b, stars_on, e);
}
