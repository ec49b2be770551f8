/* One frame of a scene, start to finish: context, renderer, passes, read-back. */
#ifndef BT_FRAME_H
#define BT_FRAME_H
#include "ref/dump.h"
#include "render/renderer.h"

struct frame_info {
    char backend[16];
    char path_name[16];
    char path_description[256];
    char renderer[160];
    char pipeline[16];        /* "multipass", "fused segment" or "single pass" */
    char pipeline_why[200];   /* why that one (renderer_pipeline_why) */
};

/* Returns 0, or -1 with err; *bad_input tells a user error (exit 2) from a runtime failure (1). */
int render_frame(const struct scene *s, const char *backend, struct render_result *out, int with_state,
                 struct frame_info *info, char *err, size_t errlen, int *bad_input);
/* Per-pixel records (and colours) from a result read with its state. */
int result_to_dump(const struct render_result *res, const struct scene *s, const char *engine, struct dump *d);

#endif
