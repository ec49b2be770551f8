/* Shader programs per stage and variant, built once and cached: switching scenes or moving
 * a knob changes uniforms, never the program, unless the variant itself changes. A cache may
 * outlive the renderers that use it (renderer_share_programs): the kiosk keeps one for all its
 * scenes, so that a scene change compiles nothing. */
#ifndef BT_PROGRAMS_H
#define BT_PROGRAMS_H
#include "gl/shader.h"
#include <stdint.h>

#define PROGRAMS_KEY_LEN 12288  /* defines of a single pass over 64 moving, textured objects included */

/* A linked program and where its active uniforms are, read from GL once when it is built
 * (glGetActiveUniform): the stages set uniforms by name every pass without asking GL. */
struct program_uniforms {
    GLuint id;
    int n;
    struct uniform_slot {
        char *name;              /* as GL reports it, an array's "[0]" cut off; its elements too */
        GLint location;
    } *slots;                    /* sorted by name */
};

/* The location of the uniform `name` (an array by its bare name or an element's), -1 where it has no
 * such active uniform (GL ignores a glUniform* at -1, as for an unknown name). */
GLint program_uniform(const struct program_uniforms *p, const char *name);

/* A stage that writes two targets: one program with MRT, or one program per target. */
struct stage_program {
    struct program_uniforms program[2];
    int n_programs;
};

struct program_cache {
    struct shader_target target;
    int mrt;
    /* each variant by its key (targets, defines, files) and the key's hash, which a pass compares
     * first: a frame of the multipass scheme asks for its programs thousands of times; each entry
     * allocated on its own, so that a program handed out stays where it is as the cache grows */
    struct program_entry { uint64_t hash; char *key; struct stage_program sp; } **entries;
    int n, capacity;
    long built;                  /* programs compiled and linked into it so far */
    double build_seconds;        /* wall time their compiles and links took */
};

void program_cache_init(struct program_cache *pc, const struct shader_target *target, int mrt);
/* Whether a renderer with this shader target and MRT choice compiles its programs as pc does. */
int program_cache_fits(const struct program_cache *pc, const struct shader_target *target, int mrt);
void program_cache_release(struct program_cache *pc);
/* The program(s) of a stage: fragment files (NULL-terminated) and variant defines.
 * two_targets: 0 for stages that write one colour (sky). NULL with e on failure. */
const struct stage_program *program_cache_get(struct program_cache *pc, const char *const *fragment_files,
                                              const char *defines, int two_targets, struct error *e);
/* The same with vertex files of its own (NULL: the pass quad's). */
const struct stage_program *program_cache_get_vertex(struct program_cache *pc, const char *const *vertex_files,
                                                     const char *const *fragment_files, const char *defines,
                                                     int two_targets, struct error *e);

#endif
