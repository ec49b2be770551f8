#include "results/dump_scene.h"
#include <stdint.h>
#include <stdio.h>
#include <string.h>

_Static_assert(SCENE_MAX_OBJECTS <= DUMP_MAX_OBJECTS, "a dump must hold every object of a scene");
_Static_assert(SCENE_MAX_SIZE <= DUMP_MAX_SIDE && SCENE_MAX_PIXELS <= DUMP_MAX_PIXELS,
               "a dump must hold every image a scene can ask for");

double object_size(const struct object *o)
{
    switch (o->type) {
    case PRIM_SPHERE:
    case PRIM_DISK:
        return o->radius;
    case PRIM_TRIANGLE: {
        double longest = 0.0;
        for (int i = 0; i < 3; i++) {
            double edge = v3_len(v3_sub(o->vertex[(i + 1) % 3], o->vertex[i]));
            longest = edge > longest ? edge : longest;
        }
        return longest;
    }
    case PRIM_RECT:
    default:
        return v3_len(v3_add(o->axis_u, o->axis_v));
    }
}

void dump_describe_scene(struct dump *d, const struct scene *s)
{
    /* the field guards against comparing unrelated dumps: a name longer than it keeps its start and
     * ends in '~' and a hash of the whole name, so that two names sharing their first characters
     * still differ */
    size_t room = sizeof d->scene - 1, length = strlen(s->name);
    if (length <= room) {
        memcpy(d->scene, s->name, length + 1);
    } else {
        uint32_t h = 2166136261u;
        for (const unsigned char *c = (const unsigned char *)s->name; *c; c++)
            h = (h ^ *c) * 16777619u;
        snprintf(d->scene, sizeof d->scene, "%.*s~%08x", (int)(room - 9), s->name, (unsigned)h);
    }
    d->n_objects = s->n_objects;
    for (int i = 0; i < s->n_objects; i++)
        d->object_size[i] = (float)object_size(&s->objects[i]);
}
