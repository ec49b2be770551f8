/* A ray's budget (docs/SCENES.md, [render]): a path, derived from the scene's size where the scene
 * sets none; adaptive rays spend it whatever their step lengths; rays that spend it show
 * render.unfinished_color on both engines. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include "hard_cases.h"

/* A black hole of mass 0.5 with the camera 2.7 from it, a bounding sphere of 14.8 and no budget of
 * its own: the scene a newcomer writes first. */
static void minimal_black_hole(struct scene *s)
{
    scene_defaults(s);
    snprintf(s->name, sizeof s->name, "minimal");
    s->model.type = MODEL_SCHWARZSCHILD;
    s->model.mass = 0.5;
    s->camera.position = v3(0.0, 0.0, 2.7);
    s->camera.look_at = v3(0.0, 0.0, 0.0);
    s->camera.fov_deg = 120.0;
    s->render.bound_radius = 14.8;
    s->sky.type = SKY_COLOR;
    s->sky.color = v3(0.2, 0.3, 0.5);
}

/* The default budget is 3 diameters of the bounding sphere: every ray of the minimal scene ends,
 * on the GPU as on the reference. The paper's budget of 30 segments of 10 x 0.05 (what the
 * defaults were) leaves most of them travelling: the test tells the two apart. */
static void test_default_budget_lets_rays_finish(void **state)
{
    (void)state;
    static struct scene s;
    struct cpu_image cpu;
    struct hc_gpu g;
    minimal_black_hole(&s);
    assert_int_equal(s.render.segments, 0);
    /* 3 diameters, 88.8, in whole segments of 10 x 0.05: 178 of them */
    assert_int_equal(render_segments(&s.render), 178);
    assert_true(fabs(render_path_budget(&s.render) - 89.0) < 1e-9);
    hc_render_both(&s, 24, 16, &cpu, &g);
    long n = 24 * 16;
    printf("  default budget %g in %d segments: unfinished GPU %ld, CPU %ld of %ld\n", render_path_budget(&s.render),
           render_segments(&s.render), hc_count_outcome(&g.dump, DUMP_UNFINISHED),
           hc_count_outcome(&cpu.dump, DUMP_UNFINISHED), n);
    assert_int_equal(hc_count_outcome(&g.dump, DUMP_UNFINISHED), 0);
    assert_int_equal(hc_count_outcome(&cpu.dump, DUMP_UNFINISHED), 0);
    hc_gpu_free(&g);
    cpu_image_free(&cpu);

    s.render.segments = 30;
    hc_gpu_render(&s, &g);
    long old = hc_count_outcome(&g.dump, DUMP_UNFINISHED);
    printf("  30 segments (a path of 15): unfinished GPU %ld of %ld\n", old, n);
    assert_true(old * 2 > n);
    hc_gpu_free(&g);
}

/* Rays still travelling at the end of their budget show render.unfinished_color, on the GPU and on
 * the CPU reference, and no other pixel does (the colour is not one the scene shows). The budget
 * is not a whole number of segments: both engines stop at the same path, rounded up to them, so
 * the same rays are unfinished on both. */
static void test_unfinished_rays_show_their_colour(void **state)
{
    (void)state;
    static const char *const sets[] = {"render.max_path=12.3", "render.unfinished_color=0.25 0.5 1", NULL};
    static struct scene s;
    struct cpu_image cpu;
    struct hc_gpu g;
    hc_load(&s, "lorenz", 32, 24, sets);
    hc_render_both(&s, 32, 24, &cpu, &g);
    const unsigned char want[3] = {64, 128, 255};
    const struct dump *engines[2] = {&g.dump, &cpu.dump};
    for (int e = 0; e < 2; e++) {
        const struct dump *d = engines[e];
        long unfinished = 0, coloured = 0;
        for (int i = 0; i < d->width * d->height; i++) {
            const struct dump_record *r = &d->records[i];
            int is_colour = abs(r->rgba[0] - want[0]) <= 1 && abs(r->rgba[1] - want[1]) <= 1 &&
                            abs(r->rgba[2] - want[2]) <= 1;
            unfinished += r->outcome == DUMP_UNFINISHED;
            coloured += is_colour;
            if (r->outcome == DUMP_UNFINISHED && !is_colour)
                fail_msg("%s: unfinished pixel %d is %d %d %d", d->engine, i, r->rgba[0], r->rgba[1], r->rgba[2]);
        }
        printf("  %s: %ld unfinished, %ld pixels of the colour\n", d->engine, unfinished, coloured);
        assert_true(unfinished > d->width * d->height / 10);
        assert_int_equal(coloured, unfinished);
    }
    assert_true(fabs(render_path_budget(&s.render) - 12.5) < 1e-6);   /* step 0.5 x 1 x 25 */
    long differ = 0;
    for (int i = 0; i < 32 * 24; i++)
        differ += (g.dump.records[i].outcome == DUMP_UNFINISHED) != (cpu.dump.records[i].outcome == DUMP_UNFINISHED);
    printf("  unfinished on one engine only: %ld\n", differ);
    assert_int_equal(differ, 0);
    hc_gpu_free(&g);
    cpu_image_free(&cpu);
}

/* An adaptive ray's budget is its path: the GPU's rays carry the path they travelled (position.w)
 * and none goes beyond render.max_path; the unfinished ones have spent it to float rounding (the
 * sum of a few hundred steps in 32 bits: 1e-4 relative is a hundred times what it accumulates).
 * Which rays finish is then the reference's choice too, whatever step lengths each controller
 * picks: the rays that differ are those the chaotic flow sends elsewhere (the outcome differences
 * of the scene at its own settings, docs/ACCURACY.md), bounded here by 15% of the image. */
static void test_adaptive_budget_is_a_path(void **state)
{
    (void)state;
    static const char *const controls[2][3] = {
        {"render.step_control=doubling", "render.max_path=20", NULL},
        {"render.method=dopri5", "render.step_control=embedded", NULL},
    };
    for (int c = 0; c < 2; c++) {
        static struct scene s;
        struct cpu_image cpu;
        struct hc_gpu g;
        hc_load(&s, "lorenz", 32, 24, controls[c]);
        if (c == 1)
            s.render.max_path = 20.0;
        hc_render_both(&s, 32, 24, &cpu, &g);
        double budget = render_path_budget(&s.render);
        assert_true(fabs(budget - 20.0) < 1e-12);
        long n = 32 * 24, both = 0, only_gpu = 0, only_cpu = 0;
        for (int i = 0; i < n; i++) {
            float travelled = g.res.position[4 * i + 3];
            int gpu_unfinished = g.dump.records[i].outcome == DUMP_UNFINISHED;
            int cpu_unfinished = cpu.dump.records[i].outcome == DUMP_UNFINISHED;
            assert_true(travelled >= 0.0f);
            assert_true(travelled <= budget * (1.0 + 1e-4));
            if (gpu_unfinished && !(fabs(travelled - budget) <= 1e-4 * budget))
                fail_msg("%s: unfinished ray %d travelled %g of %g", controls[c][0], i, travelled, budget);
            both += gpu_unfinished && cpu_unfinished;
            only_gpu += gpu_unfinished && !cpu_unfinished;
            only_cpu += !gpu_unfinished && cpu_unfinished;
        }
        printf("  %s: unfinished on both %ld, GPU only %ld, CPU only %ld of %ld\n", controls[c][0], both, only_gpu,
               only_cpu, n);
        assert_true(both > n / 10);
        assert_true((only_gpu + only_cpu) * 100 <= 15 * n);
        hc_gpu_free(&g);
        cpu_image_free(&cpu);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_default_budget_lets_rays_finish),
        cmocka_unit_test(test_unfinished_rays_show_their_colour),
        cmocka_unit_test(test_adaptive_budget_is_a_path),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
