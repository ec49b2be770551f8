/* Shader programs from shaders_es/ (GLSL ES 1.00), embedded in the binary or read from a
 * directory, behind a preamble generated for the context's dialect and the pass variant. */
#ifndef BT_SHADER_H
#define BT_SHADER_H
#include "gl/context.h"
#include "gl/gl_api.h"
#include <stddef.h>

struct shader_target {
    enum shading_dialect dialect;
    int fragment_highp;        /* the fragment stage has highp float */
    int draw_buffers_ext;      /* GLSL ES 1.00 needs #extension GL_EXT_draw_buffers for gl_FragData[1] */
    int derivatives_ext;       /* and #extension GL_OES_standard_derivatives for dFdx, dFdy */
    int state_packed;          /* the packed path's programs: #define STATE_PACKED 1 (render/path.h) */
    /* every fragment shader compiled whose files include capture_file is handed to capture whole, as
     * the GL compiles it: preamble, defines, each file after its #line (bentray info --shader) */
    const char *capture_file;
    void (*capture)(const char *source, void *arg);
    void *capture_arg;
};

/* Load shader files from DIR instead of the embedded copies (development); NULL resets. */
void shader_set_directory(const char *dir);
/* Text of one shader file, malloc'd; NULL with E filled: a file under the directory that cannot
 * be opened (error_status_of_errno) or is too large is the user's, the rest the machine's. */
char *shader_load_text(const char *name, struct error *e);

/* The stages of the pipeline, the built-in stage_NAME.glsl files, as "fill, frame, ..." into out. */
void shader_stage_names(char *out, size_t n);
/* Compile and link a program. vertex/fragment are NULL-terminated lists of file names,
 * concatenated in order after the preamble; defines is extra preamble text ("#define X 1\n...").
 * The vertex attribute a_corner is bound to location 0. Returns 0 with E filled on failure
 * (ERROR_RUNTIME for a program that does not compile or link, shader_load_text's status for a
 * file); compiler messages name the file and line. */
GLuint shader_program_build(const struct shader_target *target, const char *defines,
                            const char *const *vertex, const char *const *fragment,
                            struct error *e);

#endif
