/* Shader programs per stage and variant, built once and cached: switching scenes or moving
 * a knob changes uniforms, never the program, unless the variant itself changes. */
#ifndef BT_PROGRAMS_H
#define BT_PROGRAMS_H
#include "gl/shader.h"

#define PROGRAMS_MAX 64
#define PROGRAMS_KEY_LEN 1280

/* A stage that writes two targets: one program with MRT, or one program per target. */
struct stage_program {
    GLuint program[2];
    int n_programs;
};

struct program_cache {
    struct shader_target target;
    int mrt;
    struct { char key[PROGRAMS_KEY_LEN]; struct stage_program sp; } entries[PROGRAMS_MAX];
    int n;
};

void program_cache_init(struct program_cache *pc, const struct shader_target *target, int mrt);
void program_cache_release(struct program_cache *pc);
/* The program(s) of a stage: fragment files (NULL-terminated) and variant defines.
 * two_targets: 0 for stages that write one colour (sky). NULL with err on failure. */
const struct stage_program *program_cache_get(struct program_cache *pc, const char *const *fragment_files,
                                              const char *defines, int two_targets, char *err, size_t errlen);
/* The same with vertex files of its own (NULL: the pass quad's). */
const struct stage_program *program_cache_get_vertex(struct program_cache *pc, const char *const *vertex_files,
                                                     const char *const *fragment_files, const char *defines,
                                                     int two_targets, char *err, size_t errlen);

#endif
