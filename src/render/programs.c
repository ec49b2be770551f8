#include "render/programs.h"
#include <stdio.h>
#include <string.h>

void program_cache_init(struct program_cache *pc, const struct shader_target *target, int mrt)
{
    memset(pc, 0, sizeof *pc);
    pc->target = *target;
    pc->mrt = mrt;
}

void program_cache_release(struct program_cache *pc)
{
    for (int i = 0; i < pc->n; i++)
        for (int k = 0; k < pc->entries[i].sp.n_programs; k++)
            glDeleteProgram(pc->entries[i].sp.program[k]);
    pc->n = 0;
}

const struct stage_program *program_cache_get(struct program_cache *pc, const char *const *fragment_files,
                                              const char *defines, int two_targets, char *err, size_t errlen)
{
    return program_cache_get_vertex(pc, NULL, fragment_files, defines, two_targets, err, errlen);
}

const struct stage_program *program_cache_get_vertex(struct program_cache *pc, const char *const *vertex_files,
                                                     const char *const *fragment_files, const char *defines,
                                                     int two_targets, char *err, size_t errlen)
{
    static const char *const quad_vertex[] = {"quad_vertex.glsl", NULL};
    const char *const *vertex = vertex_files ? vertex_files : quad_vertex;
    char key[PROGRAMS_KEY_LEN];
    size_t used = snprintf(key, sizeof key, "%d|%s|%s|", two_targets, defines, vertex[0]);
    for (int i = 0; fragment_files[i] && used < sizeof key; i++)
        used += snprintf(key + used, sizeof key - used, "%s,", fragment_files[i]);
    if (used >= sizeof key) {
        snprintf(err, errlen, "internal: program variant key too long");
        return NULL;
    }
    for (int i = 0; i < pc->n; i++)
        if (strcmp(pc->entries[i].key, key) == 0)
            return &pc->entries[i].sp;
    if (pc->n == PROGRAMS_MAX) {
        snprintf(err, errlen, "internal: more than %d shader variants", PROGRAMS_MAX);
        return NULL;
    }
    struct stage_program sp = {{0, 0}, 0};
    struct shader_target t = pc->target;
    char full[PROGRAMS_KEY_LEN + 64];
    if (!two_targets) {
        snprintf(full, sizeof full, "#define BT_TARGET 0\n%s", defines);
        t.draw_buffers_ext = 0;
        sp.program[0] = shader_program_build(&t, full, vertex, fragment_files, err, errlen);
        sp.n_programs = 1;
    } else if (pc->mrt) {
        snprintf(full, sizeof full, "#define BT_MRT 1\n#define BT_TARGET 0\n%s", defines);
        t.draw_buffers_ext = t.dialect == DIALECT_GLSL_ES_100;
        sp.program[0] = shader_program_build(&t, full, vertex, fragment_files, err, errlen);
        sp.n_programs = 1;
    } else {
        t.draw_buffers_ext = 0;
        for (int k = 0; k < 2; k++) {
            snprintf(full, sizeof full, "#define BT_TARGET %d\n%s", k, defines);
            sp.program[k] = shader_program_build(&t, full, vertex, fragment_files, err, errlen);
            if (!sp.program[k])
                break;
        }
        sp.n_programs = 2;
    }
    for (int k = 0; k < sp.n_programs; k++)
        if (!sp.program[k]) {
            for (int j = 0; j < sp.n_programs; j++)
                if (sp.program[j])
                    glDeleteProgram(sp.program[j]);
            return NULL;
        }
    snprintf(pc->entries[pc->n].key, sizeof pc->entries[pc->n].key, "%s", key);
    pc->entries[pc->n].sp = sp;
    return &pc->entries[pc->n++].sp;
}
