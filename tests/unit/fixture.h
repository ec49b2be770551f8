/* Scene fixtures shared by the test programs (each test_*.c is its own binary: static inline). */
#ifndef BT_TEST_FIXTURE_H
#define BT_TEST_FIXTURE_H
#include <stdio.h>
#include <string.h>
#include "scene/scene.h"
#include "scene/scene_keys.h"

/* assets/scenes/NAME.scene at width x height, with optional "section.key=value" overrides;
 * any error fails the calling test with file:line. */
static inline void fixture_load_scene(struct scene *s, const char *name, int width, int height,
                                      const char *const *sets)
{
    char path[256];
    struct error err;
    snprintf(path, sizeof path, "assets/scenes/%s.scene", name);
    if (scene_load(s, path, &err) != 0)
        fail_msg("%s: %s", err.where, err.message);
    for (int i = 0; sets && sets[i]; i++)
        if (scene_set(s, sets[i], &err) != 0)
            fail_msg("%s: %s", err.where, err.message);
    s->render.width = width;
    s->render.height = height;
    if (scene_validate(s, &err) != 0)
        fail_msg("%s: %s", err.where, err.message);
}

/* A model of the given type with scale and strength 1 and every other parameter 0; the caller sets
 * what its test needs. */
static inline struct model fixture_model(enum model_type type)
{
    struct model m;
    memset(&m, 0, sizeof m);
    m.type = type;
    m.scale = 1.0;
    m.strength = 1.0;
    return m;
}

#endif
