/* bentray trace: one ray's polyline and outcome as JSON, read back from the GPU after each
 * segment (the only place the pipeline reads back before the end). */
#include "cli/commands.h"
#include "cli/options.h"
#include "render/frame.h"
#include "render/renderer.h"
#include "ref/shade_cpu.h"
#include "ref/straight.h"
#include "physics/orbit_table.h"
#include "physics/accretion.h"
#include "scene/camera.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void usage(FILE *out)
{
    fprintf(out,
            "usage: bentray trace --scene FILE --pixel I J [options]\n"
            "Trace the ray of pixel column I, row J (row 0 at the top) and print its polyline\n"
            "(segment end points) and outcome as JSON. Options as for render: --size, --set,\n"
            "--engine gpu|cpu; GPU: --backend, --precision, --no-mrt, --shader-dir; CPU: --rtol.\n");
}

struct polyline {
    int n, cap;
    float (*points)[4];
};

static int record_point(struct renderer *r, int segment, void *arg)
{
    (void)segment;
    struct polyline *pl = arg;
    struct error e;
    if (pl->n == pl->cap)
        return -1;
    /* the reason first; the renderer then says at which segment the run stopped */
    if (renderer_read_position(r, 0, 0, pl->points[pl->n], &e) != 0) {
        fprintf(stderr, "bentray trace: %s\n", e.message);
        return -1;
    }
    pl->n++;
    return 0;
}

static void print_vec(const char *name, const float *v, const char *after)
{
    printf("  \"%s\": [%.9g, %.9g, %.9g]%s\n", name, v[0], v[1], v[2], after);
}

/* A JSON string: quotes, backslashes and control characters escaped (RFC 8259), bytes >= 0x80
 * passed through (the scene's text is UTF-8). */
static void print_string(const char *text)
{
    putchar('"');
    for (const unsigned char *c = (const unsigned char *)text; *c; c++) {
        if (*c == '"' || *c == '\\')
            printf("\\%c", *c);
        else if (*c == '\n')
            fputs("\\n", stdout);
        else if (*c == '\t')
            fputs("\\t", stdout);
        else if (*c < 0x20 || *c == 0x7f)
            printf("\\u%04x", *c);
        else
            putchar(*c);
    }
    putchar('"');
}

static void print_json(const struct scene *s, long px, long py, const char *engine, const struct dump_record *rec,
                       const struct polyline *pl)
{
    printf("{\n  \"scene\": ");
    print_string(s->name);
    printf(",\n  \"pixel\": [%ld, %ld],\n  \"engine\": ", px, py);
    print_string(engine);
    printf(",\n  \"model\": \"%s\",\n  \"outcome\": \"%s\",\n", model_name(s->model.type),
           dump_outcome_name(rec->outcome));
    if (rec->outcome >= 0) {
        printf("  \"object\": ");
        print_string(s->objects[rec->outcome].name);
        printf(",\n");
        print_vec("hit", rec->hit, ",");
        const struct object *o = &s->objects[rec->outcome];
        if (o->material.accretion) {
            /* the frequency ratio of the disk's light at the camera: its matter's orbit, the
             * static observer's gravitational shift and the camera's motion (docs/RELATIVITY.md);
             * the photon's L_z / E from the ray's final position and direction, a point of the same
             * orbit (an exact orbit's ray may end at its chord's end, past the hit) */
            vec3d hit = v3(rec->hit[0], rec->hit[1], rec->hit[2]);
            vec3d end = v3(rec->position[0], rec->position[1], rec->position[2]);
            vec3d along = v3(rec->direction[0], rec->direction[1], rec->direction[2]);
            double mass = model_gravity_mass(&s->model);
            double lambda_z = photon_lambda_z(mass, v3_sub(end, s->model.center), along, v3_normalize(o->normal));
            double g = camera_doppler(s, camera_view_direction(s, (int)px, (int)py)) *
                       emitted_ratio_shown(s, hit, keplerian_emitter_shift(mass, v3_len(v3_sub(hit, s->model.center)),
                                                                           lambda_z));
            printf("  \"g\": %.9g,\n", g);
        }
    }
    printf("  \"depth\": %.9g,\n  \"steps\": %u,\n", rec->depth, rec->steps);
    printf("  \"color\": [%u, %u, %u],\n", rec->rgba[0], rec->rgba[1], rec->rgba[2]);
    printf("  \"doppler\": %.9g,\n", camera_doppler(s, camera_view_direction(s, (int)px, (int)py)));
    print_vec("final_position", rec->position, ",");
    print_vec("final_direction", rec->direction, ",");
    printf("  \"polyline\": [\n    [%.9g, %.9g, %.9g]", s->camera.position.x, s->camera.position.y,
           s->camera.position.z);
    /* a ray that has ended stays where it ended while the remaining segments run: its end once */
    const float camera[3] = {(float)s->camera.position.x, (float)s->camera.position.y, (float)s->camera.position.z};
    const float *last = camera;
    for (int k = 0; k < pl->n; k++) {
        if (memcmp(pl->points[k], last, 3 * sizeof(float)) == 0)
            continue;
        printf(",\n    [%.9g, %.9g, %.9g]", pl->points[k][0], pl->points[k][1], pl->points[k][2]);
        last = pl->points[k];
    }
    printf("\n  ]\n}\n");
}

/* Points along the orbit a ray on exact orbits follows (render.method = orbit_table), from the orbit
 * table in double precision as the shader interpolates it in float: the camera, ORBIT_TRACE_POINTS
 * points evenly in the angle swept up to where the ray ended (the chord rec->depth counts, where it
 * met an object, else its last chord), and that end: the hit, or its final position. The GPU's
 * own per-segment ends are one chord a segment and would draw the curve as one straight line.
 * 0, or -1 (no table, a radial ray: the chord ends are kept). */
#define ORBIT_TRACE_POINTS 64
static int orbit_polyline(const struct scene *s, long px, long py, const struct dump_record *rec,
                          struct polyline *pl)
{
    vec3d c = s->model.center, from = v3_sub(s->camera.position, c);
    vec3d e1 = v3_normalize(from), d = v3_normalize(camera_ray(s, (int)px, (int)py));
    double along = v3_dot(d, e1);
    vec3d across = v3_sub(d, v3_scale(e1, along));
    double across_length = v3_len(across);
    if (across_length < 1e-12)
        return -1;
    vec3d e2 = v3_scale(across, 1.0 / across_length);
    double psi = atan2(across_length, along);
    struct orbit_table_params p;
    orbit_table_params_for(s, &p);
    struct orbit_table t;
    struct error e;
    if (orbit_table_build(&t, &p, &e) != 0)
        return -1;
    struct orbit_point q;
    double phi_end;
    int n;
    orbit_table_eval(&t, psi, 0.0, &q, &phi_end, &n);
    const float *end = rec->outcome >= 0 ? rec->hit : rec->position;
    int k = rec->outcome >= 0 ? (int)floor(rec->depth) : (int)rec->steps - 1;
    k = k < 0 ? 0 : k >= n ? n - 1 : k;
    double s_a = orbit_table_chord_end(&t, psi, k, n), s_b = orbit_table_chord_end(&t, psi, k + 1, n);
    /* where the end lies in the chord's span of angle (an orbit may wind more than a turn) */
    vec3d to_end = v3_sub(v3((double)end[0], (double)end[1], (double)end[2]), c);
    double phi_a = s_a * phi_end, phi_b = s_b * phi_end;
    const double turn = 2.0 * acos(-1.0);
    double phi = phi_a + fmod(fmod(atan2(v3_dot(to_end, e2), v3_dot(to_end, e1)) - phi_a, turn) + turn, turn);
    phi = phi > phi_b ? phi_b : phi;
    double s_end = phi_end > 0.0 ? phi / phi_end : s_b;
    pl->n = 0;
    for (int i = 1; i <= ORBIT_TRACE_POINTS && pl->n < pl->cap - 1; i++) {
        orbit_table_eval(&t, psi, s_end * i / ORBIT_TRACE_POINTS, &q, &phi_end, &n);
        vec3d at = v3_add(c, v3_scale(v3_add(v3_scale(e1, cos(q.phi)), v3_scale(e2, sin(q.phi))), 1.0 / q.u));
        float point[4] = {(float)at.x, (float)at.y, (float)at.z, 0.0f};
        memcpy(pl->points[pl->n++], point, sizeof point);
    }
    float last[4] = {end[0], end[1], end[2], 0.0f};
    memcpy(pl->points[pl->n++], last, sizeof last);
    orbit_table_free(&t);
    return 0;
}

/* GPU path: a 1x1 ray state for the chosen pixel, the same arithmetic as the full frame. */
static int trace_gpu(const struct common_options *o, const struct scene *s, long px, long py, struct polyline *pl)
{
    int rc = EXIT_RUNTIME;
    struct error e;
    struct gl_context *ctx = gl_context_create(o->backend, &e);
    if (!ctx) {
        fprintf(stderr, "bentray trace: %s\n", e.message);
        return EXIT_RUNTIME;
    }
    struct renderer *r = renderer_create(ctx, s, &e);
    struct render_result res = {0};
    if (s->render.pipeline == PIPELINE_SINGLE)
        fprintf(stderr, "bentray trace: note: the polyline needs the end of every segment, so trace runs the "
                "multipass scheme (render.pipeline = single applies to render)\n");
    int gl_row = s->render.height - 1 - (int)py;
    if (r && renderer_run(r, s, (int)px, gl_row, 1, 1, record_point, pl, &e) == 0 &&
        renderer_read(r, &res, RENDER_READ_STATE, &e) == 0) {
        struct dump d;
        if (result_to_dump(&res, s, "gpu", &d) == 0) {
            char engine[40];
            snprintf(engine, sizeof engine, "gpu %s", renderer_path(r)->name);
            if (scene_on_exact_orbits(s) && renderer_path(r)->fp32)
                orbit_polyline(s, px, py, &d.records[0], pl);
            print_json(s, px, py, engine, &d.records[0], pl);
            dump_free(&d);
            rc = EXIT_OK;
        } else {
            error_set(&e, ERROR_RUNTIME, NULL, "out of memory");
        }
    } else {
        rc = exit_code_of(&e);
    }
    if (rc != EXIT_OK)
        fprintf(stderr, "bentray trace: %s\n", e.message);
    render_result_free(&res);
    renderer_destroy(r);
    gl_context_destroy(ctx);
    return rc;
}

static void record_sample(void *arg, double lambda, vec3d x, vec3d v)
{
    (void)lambda;
    (void)v;
    struct polyline *pl = arg;
    if (pl->n < pl->cap) {
        float p[4] = {(float)x.x, (float)x.y, (float)x.z, 0.0f};
        memcpy(pl->points[pl->n++], p, sizeof p);
    }
}

/* CPU reference: the same ray, sampled at the GPU's segment ends and where it ends. */
static int trace_cpu(const struct common_options *o, const struct scene *s, long px, long py, struct polyline *pl)
{
    struct cpu_render_options opt;
    options_cpu(o, s, &opt);
    vec3d x0 = s->camera.position;
    vec3d v0 = model_initial_velocity(&s->model, x0, camera_ray(s, (int)px, (int)py));
    struct ref_ray ray;
    double segment_length = s->render.steps_per_segment * s->render.step_size;
    ref_trace(s, &opt.ref, x0, v0, &ray, segment_length, record_sample, pl);
    struct dump_record rec;
    unsigned char colour[4];
    struct error e;
    if (ref_pixel_colour(s, &ray, (int)px, (int)py, colour, &e) != 0) {
        fprintf(stderr, "bentray trace: %s%s%s\n", e.where, e.where[0] ? ": " : "", e.message);
        return exit_code_of(&e);
    }
    ref_ray_to_record(&ray, colour, &rec);
    char engine[40];
    snprintf(engine, sizeof engine, "cpu dopri5 rtol %.0e", opt.ref.rtol);
    print_json(s, px, py, engine, &rec, pl);
    return EXIT_OK;
}

/* Loads S from O and follows the ray through pixel (px, py); the command's exit code. */
static int trace_scene(const struct common_options *o, struct scene *s, long px, long py)
{
    int rc = options_load_scene(o, "trace", s);
    if (rc)
        return rc;
    if (px >= s->render.width || py >= s->render.height) {
        fprintf(stderr, "bentray trace: --pixel: %ld %ld is outside the %dx%d image\n", px, py, s->render.width,
                s->render.height);
        return EXIT_USAGE;
    }
    /* one point per segment end, and the end of the ray; on exact orbits a segment is a chord, of
     * which a ray has up to render.max_chords (the integrated count where the GPU falls back) */
    int segments = render_segments(&s->render);
    if (s->render.method == METHOD_ORBIT_TABLE && s->render.max_chords > segments)
        segments = s->render.max_chords;
    struct polyline pl = {0, segments + 2, NULL};
    pl.points = calloc((size_t)pl.cap, sizeof *pl.points);
    if (!pl.points) {
        fprintf(stderr, "bentray trace: out of memory\n");
        return EXIT_RUNTIME;
    }
    /* The per-segment read-back looks at the live ray state, which early ray termination stops
     * updating once a ray is retired; early-z never changes a ray's path (test_acceleration). */
    s->render.early_z = 0;
    rc = options_engine_cpu(o) ? trace_cpu(o, s, px, py, &pl) : trace_gpu(o, s, px, py, &pl);
    free(pl.points);
    return rc;
}

int cmd_trace(int argc, char **argv)
{
    struct common_options o = {.backend = "auto"};
    long px = -1, py = -1;
    enum { PIXEL };
    static const struct option_spec specs[] = {{"--pixel", "I J", PIXEL}, {NULL, NULL, 0}};
    struct option_reader rd = {.cmd = "trace", .own = specs, .common = common_option_specs,
                               .usage = usage, .argc = argc, .argv = argv};
    const struct option_spec *sp;
    const char *v;
    int got;
    while ((got = option_read(&rd, &sp, &v)) > 0) {
        switch (sp->id) {
        case PIXEL:
            /* two values: I here, J the argument after it */
            if (rd.next >= argc || option_parse_int(v, 0, SCENE_MAX_SIZE - 1, &px) ||
                option_parse_int(argv[rd.next], 0, SCENE_MAX_SIZE - 1, &py)) {
                fprintf(stderr, "bentray trace: --pixel: expected two pixel indices I J\n");
                return EXIT_USAGE;
            }
            rd.next++;
            break;
        default:
            if (options_common(&o, "trace", sp->id, v) != 0)
                return EXIT_USAGE;
        }
    }
    if (got < 0)
        return rd.exit_code;
    if (px < 0) {
        fprintf(stderr, "bentray trace: --pixel I J is required\n");
        return EXIT_USAGE;
    }
    if (o.samples) {
        fprintf(stderr, "bentray trace: --samples: trace follows one ray, the one through the pixel's centre; "
                        "render.samples applies to images (bentray render)\n");
        return EXIT_USAGE;
    }
    struct scene *s = options_scene_new("trace");
    if (!s)
        return EXIT_RUNTIME;
    int rc = trace_scene(&o, s, px, py);
    scene_free(s);
    return rc;
}
