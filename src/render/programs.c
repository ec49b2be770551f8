#include "render/programs.h"
#include "gl/caps.h"
#include "gl/draw_check.h"
#include "io/clock.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int by_name(const void *a, const void *b)
{
    return strcmp(((const struct uniform_slot *)a)->name, ((const struct uniform_slot *)b)->name);
}

static void uniforms_release(struct program_uniforms *p)
{
    for (int i = 0; i < p->n; i++)
        free(p->slots[i].name);
    free(p->slots);
    if (p->id)
        glDeleteProgram(p->id);
    memset(p, 0, sizeof *p);
}

static int add_slot(struct program_uniforms *p, int *capacity, const char *name, GLint location)
{
    if (p->n == *capacity) {
        int grown = *capacity ? 2 * *capacity : 32;
        struct uniform_slot *slots = realloc(p->slots, (size_t)grown * sizeof *slots);
        if (!slots)
            return -1;
        p->slots = slots;
        *capacity = grown;
    }
    p->slots[p->n].name = strdup(name);
    if (!p->slots[p->n].name)
        return -1;
    p->slots[p->n++].location = location;
    return 0;
}

/* The active uniforms of a linked program and their locations: each by its name, an array also by
 * its bare name and by every element's ("u_light_color[2]"); -1 when out of memory. */
static int uniforms_read(struct program_uniforms *p, GLuint id, struct error *e)
{
    GLint count = 0, longest = 0;
    memset(p, 0, sizeof *p);
    p->id = id;
    glGetProgramiv(id, GL_ACTIVE_UNIFORMS, &count);
    glGetProgramiv(id, GL_ACTIVE_UNIFORM_MAX_LENGTH, &longest);
    size_t name_len = (size_t)longest + 16;
    char *name = malloc(name_len), *element = malloc(name_len);
    int capacity = 0, rc = name && element ? 0 : -1;
    for (GLint i = 0; i < count && rc == 0; i++) {
        GLsizei length = 0;
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(id, (GLuint)i, longest + 1, &length, &size, &type, name);
        name[length] = '\0';
        char *bracket = strstr(name, "[0]");
        int array = bracket && bracket[3] == '\0';
        if (array)
            *bracket = '\0';
        rc = add_slot(p, &capacity, name, glGetUniformLocation(id, name));
        for (GLint k = 0; array && k < size && rc == 0; k++) {
            snprintf(element, name_len, "%s[%d]", name, (int)k);
            rc = add_slot(p, &capacity, element, glGetUniformLocation(id, element));
        }
    }
    free(name);
    free(element);
    if (rc != 0)
        return error_set(e, ERROR_RUNTIME, NULL, "out of memory listing a program's uniforms");
    if (p->n > 0)
        qsort(p->slots, (size_t)p->n, sizeof *p->slots, by_name);
    return 0;
}

GLint program_uniform(const struct program_uniforms *p, const char *name)
{
    struct uniform_slot key = {(char *)name, -1};
    const struct uniform_slot *slot =
        p->n > 0 ? bsearch(&key, p->slots, (size_t)p->n, sizeof *p->slots, by_name) : NULL;
    return slot ? slot->location : -1;
}

void program_cache_init(struct program_cache *pc, const struct shader_target *target, int mrt)
{
    memset(pc, 0, sizeof *pc);
    pc->target = *target;
    pc->mrt = mrt;
}

int program_cache_fits(const struct program_cache *pc, const struct shader_target *target, int mrt)
{
    return pc->mrt == mrt && pc->target.dialect == target->dialect &&
           pc->target.fragment_highp == target->fragment_highp &&
           pc->target.draw_buffers_ext == target->draw_buffers_ext && pc->target.state_packed == target->state_packed &&
           !target->capture && !pc->target.capture;
}

void program_cache_release(struct program_cache *pc)
{
    for (int i = 0; i < pc->n; i++) {
        for (int k = 0; k < pc->entries[i]->sp.n_programs; k++)
            uniforms_release(&pc->entries[i]->sp.program[k]);
        free(pc->entries[i]->key);
        free(pc->entries[i]);
    }
    free(pc->entries);
    pc->entries = NULL;
    pc->n = pc->capacity = 0;
}

static uint64_t key_part(uint64_t h, const char *text)
{
    for (const unsigned char *c = (const unsigned char *)text; *c; c++)
        h = (h ^ *c) * 1099511628211u;
    return (h ^ 0xffu) * 1099511628211u;
}

/* The variant's key as text: PROGRAMS_KEY_LEN - 1 characters at most. */
static int write_key(char *key, int two_targets, const char *defines, const char *const *vertex,
                     const char *const *fragment_files, struct error *e)
{
    size_t used = snprintf(key, PROGRAMS_KEY_LEN, "%d|%s|%s|", two_targets, defines, vertex[0]);
    for (int i = 0; fragment_files[i] && used < PROGRAMS_KEY_LEN; i++)
        used += snprintf(key + used, PROGRAMS_KEY_LEN - used, "%s,", fragment_files[i]);
    if (used >= PROGRAMS_KEY_LEN)
        return error_set(e, ERROR_RUNTIME, NULL, "internal: program variant key too long");
    return 0;
}

/* Whether a program may leave fragments undrawn on purpose (a `discard`): the draw check cannot tell
 * those from a draw the driver skipped. */
static int may_discard(const char *const *fragment_files)
{
    int found = 0;
    for (int i = 0; fragment_files[i] && !found; i++) {
        struct error e;
        char *text = shader_load_text(fragment_files[i], &e);
        found = text && strstr(text, "discard;") != NULL;
        free(text);
    }
    return found;
}

/* Whether the driver draws with each program of a new variant (gl/draw_check.h), where the check can
 * tell: the pass quad's programs that never discard. 0, or -1 with e naming the stage.
 * BT_FAULT=draw_skipped: the driver skips every draw with the intersection stage in one pass, as
 * VC4's skips a program its register allocator cannot hold (docs/HARDWARE.md). */
static int variant_draws(const struct stage_program *sp, const char *const *vertex_files,
                         const char *const *fragment_files, const char *defines, struct error *e)
{
    if (vertex_files || may_discard(fragment_files))
        return 0;
    const char *stage = fragment_files[0];
    for (int i = 1; fragment_files[i]; i++)
        stage = fragment_files[i];
    int intersect_in_one = strcmp(stage, "stage_intersect.glsl") == 0 && !strstr(defines, "#define HIT_");
    int fault = gl_fault("draw_skipped") && intersect_in_one;
    for (int k = 0; k < sp->n_programs; k++)
        if (draw_check_program(sp->program[k].id, fault) == 0)
            return error_set(e, ERROR_RUNTIME, NULL, "the GPU's driver draws nothing with the program of %.*s (a quad "
                             "drawn into a texel cleared to two colours left each as it was): it could not build the "
                             "program for this GPU, as VC4's cannot one that needs more registers than it has (`make "
                             "shader-stats`, docs/HARDWARE.md)%s%s", (int)(strlen(stage) - 5), stage,
                             intersect_in_one ? "; render.hit_shading = separate draws this stage in smaller passes" : "",
                             fault ? " (BT_FAULT=draw_skipped)" : "");
    return 0;
}

const struct stage_program *program_cache_get(struct program_cache *pc, const char *const *fragment_files,
                                              const char *defines, int two_targets, struct error *e)
{
    return program_cache_get_vertex(pc, NULL, fragment_files, defines, two_targets, e);
}

const struct stage_program *program_cache_get_vertex(struct program_cache *pc, const char *const *vertex_files,
                                                     const char *const *fragment_files, const char *defines,
                                                     int two_targets, struct error *e)
{
    static const char *const quad_vertex[] = {"quad_vertex.glsl", NULL};
    const char *const *vertex = vertex_files ? vertex_files : quad_vertex;
    /* the key's parts hashed as they are (FNV-1a, each part ended by a byte no text holds); the key
     * itself is written only to confirm a hash that matches, or for a new variant */
    uint64_t hash = key_part(14695981039346656037u, two_targets ? "2" : "1");
    hash = key_part(key_part(hash, defines), vertex[0]);
    for (int i = 0; fragment_files[i]; i++)
        hash = key_part(hash, fragment_files[i]);
    char key[PROGRAMS_KEY_LEN];
    int have_key = 0;
    for (int i = 0; i < pc->n; i++) {
        if (pc->entries[i]->hash != hash)
            continue;
        if (!have_key && write_key(key, two_targets, defines, vertex, fragment_files, e) != 0)
            return NULL;
        have_key = 1;
        if (strcmp(pc->entries[i]->key, key) == 0)
            return &pc->entries[i]->sp;
    }
    if (!have_key && write_key(key, two_targets, defines, vertex, fragment_files, e) != 0)
        return NULL;
    struct program_entry *entry = calloc(1, sizeof *entry);
    char *kept = entry ? strdup(key) : NULL;
    if (pc->n == pc->capacity && kept) {
        int capacity = pc->capacity ? 2 * pc->capacity : 16;
        struct program_entry **grown = realloc(pc->entries, (size_t)capacity * sizeof *grown);
        if (grown) {
            pc->entries = grown;
            pc->capacity = capacity;
        }
    }
    if (!kept || pc->n == pc->capacity) {
        free(kept);
        free(entry);
        error_set(e, ERROR_RUNTIME, NULL, "out of memory for a shader variant");
        return NULL;
    }
    GLuint ids[2] = {0, 0};
    int n_programs;
    double t0 = clock_seconds();
    struct shader_target t = pc->target;
    /* the extension only where a program takes derivatives: the GPU's star pass (sky_colour.glsl) */
    t.derivatives_ext = t.derivatives_ext && strstr(defines, "#define GPU_STARS 1\n") != NULL;
    char full[PROGRAMS_KEY_LEN + 64];
    if (!two_targets) {
        snprintf(full, sizeof full, "#define BT_TARGET 0\n%s", defines);
        t.draw_buffers_ext = 0;
        ids[0] = shader_program_build(&t, full, vertex, fragment_files, e);
        n_programs = 1;
    } else if (pc->mrt) {
        snprintf(full, sizeof full, "#define BT_MRT 1\n#define BT_TARGET 0\n%s", defines);
        t.draw_buffers_ext = t.dialect == DIALECT_GLSL_ES_100;
        ids[0] = shader_program_build(&t, full, vertex, fragment_files, e);
        n_programs = 1;
    } else {
        t.draw_buffers_ext = 0;
        for (int k = 0; k < 2; k++) {
            snprintf(full, sizeof full, "#define BT_TARGET %d\n%s", k, defines);
            ids[k] = shader_program_build(&t, full, vertex, fragment_files, e);
            if (!ids[k])
                break;
        }
        n_programs = 2;
    }
    pc->build_seconds += clock_seconds() - t0;
    struct stage_program sp;
    memset(&sp, 0, sizeof sp);
    sp.n_programs = n_programs;
    int failed = 0;
    for (int k = 0; k < n_programs; k++)
        failed |= !ids[k] || uniforms_read(&sp.program[k], ids[k], e) != 0;
    failed = failed || variant_draws(&sp, vertex_files, fragment_files, defines, e) != 0;
    if (failed) {
        free(kept);
        free(entry);
        for (int k = 0; k < n_programs; k++) {
            if (sp.program[k].id)
                uniforms_release(&sp.program[k]);
            else if (ids[k])
                glDeleteProgram(ids[k]);
        }
        return NULL;
    }
    entry->key = kept;
    entry->hash = hash;
    entry->sp = sp;
    pc->entries[pc->n++] = entry;
    pc->built++;
    return &entry->sp;
}
