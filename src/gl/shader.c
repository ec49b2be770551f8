#include "gl/shader.h"
#include <errno.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct embedded_file { const char *name; const char *text; };
extern const struct embedded_file embedded_shaders[];

#define SHADER_MAX_FILES 16
#define SHADER_MAX_BYTES (1 << 20)

static const char *shader_dir;

void shader_set_directory(const char *dir) { shader_dir = dir; }

/* A file under the directory the user named (--shader-dir): one that cannot be opened or is too
 * large is the user's, no memory for it the machine's. */
static char *read_file(const char *path, struct error *e)
{
    /* never waits: a FIFO or a device there is refused, not read */
    int fd = open(path, O_RDONLY | O_NONBLOCK);
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0) {
        int errnum = errno;
        if (fd >= 0)
            close(fd);
        error_set(e, error_status_of_errno(errnum), NULL, "cannot read shader %s: %s", path, strerror(errnum));
        return NULL;
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        error_set(e, ERROR_INPUT, NULL, "cannot read shader %s: not a regular file", path);
        return NULL;
    }
    FILE *f = fdopen(fd, "rb");
    if (!f) {
        int errnum = errno;
        close(fd);
        error_set(e, ERROR_RUNTIME, NULL, "cannot read shader %s: %s", path, strerror(errnum));
        return NULL;
    }
    char *buf = malloc(SHADER_MAX_BYTES + 1);
    if (!buf) {
        fclose(f);
        error_set(e, ERROR_RUNTIME, NULL, "cannot read shader %s: out of memory", path);
        return NULL;
    }
    size_t n = fread(buf, 1, SHADER_MAX_BYTES + 1, f);
    int failed = ferror(f);
    fclose(f);
    if (failed) {
        error_set(e, ERROR_INPUT, NULL, "cannot read shader %s: a read failed", path);
        free(buf);
        return NULL;
    }
    if (n > SHADER_MAX_BYTES) {
        error_set(e, ERROR_INPUT, NULL, "shader %s is larger than %d bytes", path, SHADER_MAX_BYTES);
        free(buf);
        return NULL;
    }
    buf[n] = '\0';
    return buf;
}

/* GLSL ES 1.00 has no line continuation (ES 3.00 added it; Mesa accepts it in 1.00, drivers that
 * keep to the 1.00 grammar do not): a macro written over several lines with a backslash at their
 * ends is joined into one line here, in place, and the newlines it took are put after it, so that
 * every later line keeps its number in compiler messages. */
static char *join_continued_lines(char *text)
{
    char *out = text;
    int owed = 0;
    for (const char *in = text; *in;) {
        if (in[0] == '\\' && in[1] == '\n') {
            *out++ = ' ';
            in += 2;
            owed++;
            continue;
        }
        *out++ = *in;
        if (*in++ == '\n')
            for (; owed > 0; owed--)
                *out++ = '\n';
    }
    *out = '\0';
    return text;
}

char *shader_load_text(const char *name, struct error *e)
{
    if (shader_dir) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", shader_dir, name);
        char *text = read_file(path, e);
        return text ? join_continued_lines(text) : NULL;
    }
    for (const struct embedded_file *f = embedded_shaders; f->name; f++)
        if (strcmp(f->name, name) == 0) {
            char *text = strdup(f->text);
            if (!text)
                error_set(e, ERROR_RUNTIME, NULL, "cannot read shader %s: out of memory", name);
            return text ? join_continued_lines(text) : NULL;
        }
    error_set(e, ERROR_RUNTIME, NULL, "no shader named %s is built in", name);
    return NULL;
}

void shader_stage_names(char *out, size_t n)
{
    size_t used = 0;
    out[0] = '\0';
    for (const struct embedded_file *f = embedded_shaders; f->name && used < n; f++) {
        size_t len = strlen(f->name);
        if (strncmp(f->name, "stage_", 6) == 0 && len > 11)
            used += snprintf(out + used, n - used, "%s%.*s", used ? ", " : "", (int)(len - 11), f->name + 6);
    }
}

/* The parts of a shader's source joined into one malloc'd text, as the GL compiles it; NULL where
 * memory runs out. */
static char *join_sources(const char *const *src, int n_src)
{
    size_t len = 1;
    for (int i = 0; i < n_src; i++)
        len += strlen(src[i]);
    char *whole = malloc(len);
    if (!whole)
        return NULL;
    whole[0] = '\0';
    for (int i = 0, used = 0; i < n_src; i++) {
        size_t part = strlen(src[i]);
        memcpy(whole + used, src[i], part + 1);
        used += (int)part;
    }
    return whole;
}

/* The file that names a shader: its own (last) one, after the files whose functions it calls. */
static const char *own_file(const char *const *files)
{
    int last = 0;
    while (files[last + 1])
        last++;
    return files[last];
}

/* The whole source of a shader whose own file is the capture's, to the target's capture. */
static void capture_source(const struct shader_target *t, const char *const *files, const char *whole)
{
    if (whole && strcmp(own_file(files), t->capture_file) == 0)
        t->capture(whole, t->capture_arg);
}

/* BT_SHADER_DUMP=DIR (docs/LIMITS.md): every program built is written whole into DIR, its vertex
 * and fragment shaders as PID-N-STAGE.vert and .frag (STAGE: the fragment shader's own file), new
 * files only; a file that cannot be written is said on stderr, and the program is built all the
 * same. The real compilers of the exhibit's GPUs read them (tests/gpus/shader_stats.sh). */
static void dump_program(const char *dir, const char *vertex_whole, const char *fragment_whole,
                         const char *const *fragment)
{
    static unsigned dumped;
    char stem[64];
    snprintf(stem, sizeof stem, "%s", own_file(fragment));
    char *dot = strrchr(stem, '.');
    if (dot)
        *dot = '\0';
    unsigned n = dumped++;
    const char *texts[2] = {vertex_whole, fragment_whole};
    const char *ext[2] = {"vert", "frag"};
    for (int i = 0; i < 2; i++) {
        char path[1200];
        snprintf(path, sizeof path, "%s/%ld-%04u-%s.%s", dir, (long)getpid(), n, stem, ext[i]);
        int fd = open(path, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
        size_t len = texts[i] ? strlen(texts[i]) : 0;
        ssize_t wrote = fd >= 0 && texts[i] ? write(fd, texts[i], len) : -1;
        int errnum = texts[i] ? errno : ENOMEM;
        int closed = fd >= 0 ? close(fd) : -1;
        if (wrote != (ssize_t)len || closed != 0)
            fprintf(stderr, "bentray: BT_SHADER_DUMP: cannot write %s: %s\n", path,
                    wrote >= 0 && closed == 0 ? "a short write" : strerror(errnum));
    }
}

static void preamble(const struct shader_target *t, GLenum stage, char *out, size_t n)
{
    const char *packed = t->state_packed ? "#define STATE_PACKED 1\n" : "";
    if (t->dialect == DIALECT_GLSL_130) {
        /* Desktop GL (compatibility profile): GLSL 1.30 accepts the ES 1.00 source as is;
         * precision qualifiers are accepted and have no effect. */
        snprintf(out, n, "#version 130\n#define BT_DESKTOP 1\n%s", packed);
        return;
    }
    if (stage == GL_VERTEX_SHADER) {
        snprintf(out, n, "#version 100\nprecision highp float;\n");
        return;
    }
    snprintf(out, n, "#version 100\n%s%s%s%s",
             t->draw_buffers_ext ? "#extension GL_EXT_draw_buffers : require\n" : "",
             t->derivatives_ext ? "#extension GL_OES_standard_derivatives : enable\n" : "",
             t->fragment_highp ? "precision highp float;\nprecision highp sampler2D;\n"
                               : "precision mediump float;\n", packed);
}

/* Driver logs say "S:L(C): ..." with S the source string; each file after the preamble
 * starts with "#line 1 S", so S maps back to a file name. */
static void translate_log(const char *log, const char *const *files, int n_files, char *out, size_t n)
{
    size_t used = 0;
    out[0] = '\0';
    for (const char *line = log; *line && used + 1 < n;) {
        const char *end = strchr(line, '\n');
        size_t len = end ? (size_t)(end - line) : strlen(line);
        int s = -1, l = -1, consumed = 0;
        if (sscanf(line, "%d:%d%n", &s, &l, &consumed) == 2 && s >= 1 && s <= n_files)
            used += snprintf(out + used, n - used, "  %s:%d%.*s\n", files[s - 1], l, (int)(len - consumed),
                             line + consumed);
        else
            used += snprintf(out + used, n - used, "  %.*s\n", (int)len, line);
        if (used >= n)
            break;
        line = end ? end + 1 : line + len;
    }
}

/* One shader compiled; its whole source into *whole (malloc'd) where whole is not NULL. */
static GLuint compile(const struct shader_target *t, GLenum stage, const char *defines,
                      const char *const *files, char **whole, struct error *e)
{
    const char *src[2 * SHADER_MAX_FILES + 2];
    char *texts[SHADER_MAX_FILES] = {0};
    char lines[SHADER_MAX_FILES][96];
    char pre[256];
    int n_files = 0, n_src = 0;
    GLuint sh = 0;

    preamble(t, stage, pre, sizeof pre);
    src[n_src++] = pre;
    src[n_src++] = defines ? defines : "";
    for (; files[n_files]; n_files++) {
        if (n_files == SHADER_MAX_FILES) {
            error_set(e, ERROR_RUNTIME, NULL, "too many shader files (at most %d)", SHADER_MAX_FILES);
            goto out;
        }
        texts[n_files] = shader_load_text(files[n_files], e);
        if (!texts[n_files])
            goto out;
        /* the file's name in a comment, so that a reader of the whole source (bentray info --shader)
         * knows which file each #line's number stands for */
        snprintf(lines[n_files], sizeof lines[n_files], "\n// shaders_es/%.48s\n#line 1 %d\n", files[n_files],
                 n_files + 1);
        src[n_src++] = lines[n_files];
        src[n_src++] = texts[n_files];
    }
    if (whole)
        *whole = join_sources(src, n_src);
    if (t->capture && stage == GL_FRAGMENT_SHADER) {
        char *text = whole ? *whole : join_sources(src, n_src);
        capture_source(t, files, text);
        if (!whole)
            free(text);
    }
    sh = glCreateShader(stage);
    glShaderSource(sh, n_src, src, NULL);
    glCompileShader(sh);
    GLint ok = 0;
    glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096] = "", mapped[4096];
        glGetShaderInfoLog(sh, sizeof log, NULL, log);
        translate_log(log, files, n_files, mapped, sizeof mapped);
        error_set(e, ERROR_RUNTIME, NULL, "%s shader (%s%s) does not compile:\n%s",
                  stage == GL_VERTEX_SHADER ? "vertex" : "fragment", files[0], n_files > 1 ? ", ..." : "", mapped);
        glDeleteShader(sh);
        sh = 0;
    }
out:
    for (int i = 0; i < n_files && i < SHADER_MAX_FILES; i++)
        free(texts[i]);
    return sh;
}

GLuint shader_program_build(const struct shader_target *target, const char *defines,
                            const char *const *vertex, const char *const *fragment,
                            struct error *e)
{
    const char *dump = getenv("BT_SHADER_DUMP");
    char *vertex_whole = NULL, *fragment_whole = NULL;
    int dumping = dump && *dump;
    GLuint vs = compile(target, GL_VERTEX_SHADER, defines, vertex, dumping ? &vertex_whole : NULL, e);
    GLuint fs = vs ? compile(target, GL_FRAGMENT_SHADER, defines, fragment, dumping ? &fragment_whole : NULL, e) : 0;
    if (dumping && vs && fs)
        dump_program(dump, vertex_whole, fragment_whole, fragment);
    free(vertex_whole);
    free(fragment_whole);
    if (!fs) {
        if (vs)
            glDeleteShader(vs);
        return 0;
    }
    GLuint prog = glCreateProgram();
    glAttachShader(prog, vs);
    glAttachShader(prog, fs);
    glBindAttribLocation(prog, 0, "a_corner");
    glBindAttribLocation(prog, 0, "a_rest_position");   /* a mesh's first attribute (stage_polygons.c) */
    glLinkProgram(prog);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(prog, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[2048] = "";
        glGetProgramInfoLog(prog, sizeof log, NULL, log);
        error_set(e, ERROR_RUNTIME, NULL, "program (%s + %s) does not link: %s", vertex[0], fragment[0], log);
        glDeleteProgram(prog);
        return 0;
    }
    return prog;
}
