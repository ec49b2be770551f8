/* What a dump records about its scene: the name and each object's length scale. */
#ifndef BT_DUMP_SCENE_H
#define BT_DUMP_SCENE_H
#include "results/dump.h"
#include "scene/scene.h"

/* Length scale of an object: sphere radius, disk outer radius, longest triangle edge, rectangle
 * half-diagonal. Hit-point errors are divided by it to give relative errors. */
double object_size(const struct object *o);
/* Fill d->scene, d->n_objects and d->object_size from s. */
void dump_describe_scene(struct dump *d, const struct scene *s);

#endif
