/* Work split over the cores (io/parallel.h): every part runs once with its own index and the
 * count, whatever the count against the cores, and the parts a job takes stay within its bounds. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdatomic.h>
#include "io/parallel.h"

struct tally {
    atomic_int runs[300];
    atomic_int wrong_count;
};

static void count_part(void *arg, int part, int parts)
{
    struct tally *t = arg;
    atomic_fetch_add(&t->runs[part], 1);
    if (parts < 1 || part < 0 || part >= parts)
        atomic_fetch_add(&t->wrong_count, 1);
}

static void test_every_part_once(void **state)
{
    (void)state;
    static const int counts[] = {1, 2, 3, 7, 64, 256};
    for (size_t k = 0; k < sizeof counts / sizeof counts[0]; k++) {
        static struct tally t;
        for (int i = 0; i < 300; i++)
            atomic_init(&t.runs[i], 0);
        atomic_init(&t.wrong_count, 0);
        parallel_run(counts[k], count_part, &t);
        for (int i = 0; i < 300; i++)
            assert_int_equal(atomic_load(&t.runs[i]), i < counts[k] ? 1 : 0);
        assert_int_equal(atomic_load(&t.wrong_count), 0);
    }
}

static void test_parts_bounded(void **state)
{
    (void)state;
    assert_int_equal(parallel_parts(0, 8), 1);
    assert_int_equal(parallel_parts(1, 8), 1);
    assert_int_equal(parallel_parts(100, 1), 1);
    for (int items = 1; items < 20; items++)
        for (int most = 1; most < 20; most++) {
            int n = parallel_parts(items, most);
            assert_true(n >= 1 && n <= items && n <= most);
        }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_part_once),
        cmocka_unit_test(test_parts_bounded),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
