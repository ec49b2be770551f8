/* The program cache's uniform locations (src/render/programs.c): read from GL once per program, they
 * must be what GL itself answers, for plain uniforms, arrays by their bare name and by each element,
 * and -1 for a name the program does not use, in every stage program a frame builds. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include "hard_cases.h"
#include "render/programs.h"

static void expect_same_as_gl(const struct program_uniforms *p, const char *name)
{
    GLint gl = glGetUniformLocation(p->id, name);
    GLint cached = program_uniform(p, name);
    if (gl != cached)
        fail_msg("%s: cached location %d, GL says %d", name, cached, gl);
}

/* The intersection stage's program of a batch of three lit objects (its defines as
 * object_batch_defines writes them): plain uniforms, vec4 arrays set by their bare name, light
 * arrays set element by element. */
static void test_locations_match_gl(void **state)
{
    (void)state;
    hc_context();
    struct gl_caps caps;
    struct error ge;
    if (gl_caps_probe(&caps, hc_context(), &ge) != 0)
        fail_msg("probe: %s", ge.message);
    struct program_cache pc;
    program_cache_init(&pc, &caps.shader, 1);
    static const char *const files[] = {"common.glsl", "prim_sphere.glsl", "observer.glsl", "shade.glsl",
                                        "stage_intersect.glsl", NULL};
    const char *defines = "#define BATCH_SIZE 3\n#define LIGHT_COUNT 2\n#define HAS_PRIM_SPHERE 1\n"
                          "#define BATCH_TESTS TEST_SPHERE(0) TEST_SPHERE(1) TEST_SPHERE(2)\n"
                          "#define BATCH_SLOTS_SPHERE SELECT_SLOT(0) SELECT_SLOT(1) SELECT_SLOT(2)\n";
    const struct stage_program *sp = program_cache_get(&pc, files, defines, 1, &ge);
    if (!sp)
        fail_msg("%s", ge.message);
    const struct program_uniforms *p = &sp->program[0];
    assert_true(p->n > 10);
    static const char *const names[] = {"u_inv_size", "u_segment_index", "u_hit", "u_geometry", "u_materials",
                                        "u_light_position[0]", "u_light_position[1]", "u_light_color[1]",
                                        "u_camera_position", "u_no_such_uniform", "u_geometry[14]", ""};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++)
        expect_same_as_gl(p, names[k]);
    assert_int_equal(program_uniform(p, "u_no_such_uniform"), -1);
    assert_true(program_uniform(p, "u_geometry") >= 0);
    assert_true(program_uniform(p, "u_light_color[1]") >= 0);
    /* every active uniform the program lists is found under its own name */
    for (int i = 0; i < p->n; i++)
        expect_same_as_gl(p, p->slots[i].name);
    program_cache_release(&pc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_locations_match_gl),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
