/* One frame of a scene, start to finish: context, renderer, passes, read-back. */
#ifndef BT_FRAME_H
#define BT_FRAME_H
#include "io/progress.h"
#include "results/dump.h"
#include "render/renderer.h"

struct frame_info {
    char backend[16];
    char path_name[16];
    char path_description[256];
    char renderer[160];
    char pipeline[16];        /* "multipass", "fused segment" or "single pass" */
    char pipeline_why[400];   /* why that one (renderer_pipeline_why) */
};

/* What a frame should bring back. */
struct frame_request {
    const char *backend;          /* egl, osmesa or auto */
    enum render_read reads;       /* what the caller reads (renderer.h) */
    enum progress_mode progress;  /* a long render reports its rows and samples on stderr (io/progress.h;
                                     it then runs in bands of rows, render/frame_bands.h) */
    int hdr;                      /* also the unclamped colour (render_result.color) */
};

/* Returns 0, or -1 with e (its status tells a user error, exit 2, from a runtime failure, 1). */
int render_frame(const struct scene *s, const struct frame_request *req, struct render_result *out,
                 struct frame_info *info, struct error *e);
/* The whole image of s on renderer r with every sample of every pixel (render.samples,
 * scene/pixel_samples.h), each a whole frame, averaged in linear light into out->rgba; seconds and
 * passes summed over them. Where the scene asks for bloom, or for a gain or tone curve with stars
 * the CPU's pass draws, the frame is read as floats and out->rgba made from them on the CPU
 * (results/bloom.h; out->color kept only where renderer_set_hdr asked for it). The ray state, when asked for, is the pixels' centres': sample 0 where
 * the pattern holds the centre, else one more run that only the state comes from. 0, or -1 with e. */
int frame_run_samples(struct renderer *r, const struct scene *s, struct render_result *out, enum render_read reads,
                      enum progress_mode progress, struct error *e);
/* Per-pixel records (and colours) from a result read with its state, or with its outcomes only
 * (RENDER_READ_OUTCOMES: hit, position, direction, depth and steps are then 0). */
int result_to_dump(const struct render_result *res, const struct scene *s, const char *engine, struct dump *d);
/* The dump's header alone (scene, size, engine), no records: what result_to_dump fills first. */
void result_dump_header(const struct render_result *res, const struct scene *s, const char *engine, struct dump *d);

#endif
