/* Scene files and --set: every section reaches the struct, every bad fixture fails at its line with
 * its message, and the limits hold. Runs from the repository root (fixtures, docs). */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "scene/scene.h"
#include "scene/scene_keys.h"

#define BAD_DIR "tests/scenes_bad"

/* ---- temporary files ------------------------------------------------------------------------ */

static void write_file(const char *path, const char *text, size_t len)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(text, 1, len, f), len);
    assert_int_equal(fclose(f), 0);
}

/* A scene in a fresh file under /tmp; the caller unlinks it. */
static void temp_scene(char path[64], const char *text)
{
    int fd;
    strcpy(path, "/tmp/bentray_scene_XXXXXX");
    fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    write_file(path, text, strlen(text));
}

static int load_text(struct scene *s, const char *text, struct error *err)
{
    char path[64];
    int rc;
    temp_scene(path, text);
    rc = scene_load(s, path, err);
    unlink(path);
    return rc;
}

/* A directory with a scene file and its assets, removed again by remove_dir(). */
struct scene_dir {
    char dir[64];
    char files[16][128];
    int n;
};

static void make_dir(struct scene_dir *d)
{
    memset(d, 0, sizeof *d);
    strcpy(d->dir, "/tmp/bentray_scenedir_XXXXXX");
    assert_non_null(mkdtemp(d->dir));
}

static const char *dir_file(struct scene_dir *d, const char *name, const char *text)
{
    assert_true(d->n < 16);
    char *path = d->files[d->n++];
    assert_true(strlen(d->dir) + 1 + strlen(name) < sizeof d->files[0]);
    strcpy(path, d->dir);
    strcat(path, "/");
    strcat(path, name);
    write_file(path, text, strlen(text));
    return path;
}

static void remove_dir(struct scene_dir *d)
{
    for (int i = 0; i < d->n; i++)
        unlink(d->files[i]);
    rmdir(d->dir);
}

/* cmocka 1.1 compares only floats; scene values are doubles */
#define assert_near(a, b, tol) check_near((a), (b), (tol), #a, __LINE__)
static void check_near(double a, double b, double tol, const char *what, int line)
{
    if (!(fabs(a - b) <= tol))
        fail_msg("line %d: %s is %.17g, expected %.17g", line, what, a, b);
}

#define assert_vec(v, x, y, z) check_vec((v), (x), (y), (z), #v, __LINE__)
static void check_vec(vec3d v, double x, double y, double z, const char *what, int line)
{
    if (!(fabs(v.x - x) <= 1e-12 && fabs(v.y - y) <= 1e-12 && fabs(v.z - z) <= 1e-12))
        fail_msg("line %d: %s is (%.17g %.17g %.17g), expected (%g %g %g)", line, what, v.x, v.y, v.z,
                 x, y, z);
}

static void assert_contains(const char *text, const char *part)
{
    if (!strstr(text, part))
        fail_msg("\"%s\" does not contain \"%s\"", text, part);
}

/* ---- defaults and a complete scene ---------------------------------------------------------- */

static void test_defaults(void **state)
{
    struct scene s;
    struct error err;
    (void)state;
    scene_defaults(&s);
    assert_vec(s.camera.position, 0, 0, 10);
    assert_vec(s.camera.look_at, 0, 0, 0);
    assert_vec(s.camera.up, 0, 1, 0);
    assert_near(s.camera.fov_deg, 60, 0);
    assert_int_equal(s.render.width, 320);
    assert_int_equal(s.render.height, 240);
    assert_int_equal(s.render.method, METHOD_RK4);
    assert_near(s.render.step_size, 0.05, 0);
    assert_int_equal(s.render.steps_per_segment, 10);
    /* no segments given: a path of 3 bounding-sphere diameters, at 10 steps of 0.05 a segment */
    assert_int_equal(s.render.segments, 0);
    assert_near(s.render.max_path, 0, 0);
    assert_near(render_path_budget(&s.render), 300, 1e-12);
    assert_int_equal(render_segments(&s.render), 600);
    assert_vec(s.render.unfinished_color, 1, 0, 1);
    assert_int_equal(s.render.steps_per_pass, 10);
    assert_near(s.render.bound_radius, 50, 0);
    assert_int_equal(s.render.precision, PRECISION_AUTO);
    assert_int_equal(s.render.mrt, MRT_AUTO);
    assert_int_equal(s.model.type, MODEL_FLAT);
    assert_near(s.model.beta, 8.0 / 3.0, 1e-15);
    assert_near(s.model.ross_a, 0.375, 0);
    assert_near(s.model.zeta, -1, 0);
    assert_near(s.model.mass, 1, 0);
    assert_int_equal(s.sky.type, SKY_COLOR);
    assert_vec(s.sky.color, 0.02, 0.02, 0.05);
    assert_vec(s.ambient_light, 1, 1, 1);
    assert_int_equal(s.n_objects, 0);
    assert_string_equal(s.dir, ".");
    assert_int_equal(scene_validate(&s, &err), 0);
}

static const char good_scene[] =
    "; every section once\n"
    "[scene]\n"
    "name = orbit\n"
    "description = a sphere, a ring and a wall near a mass\n"
    "\n"
    "[camera]\n"
    "position = 0 2 20\n"
    "look_at = 0 0 0\n"
    "up = 0 1 0\n"
    "fov = 45\n"
    "\n"
    "[render]\n"
    "width = 640\n"
    "height = 480\n"
    "method = euler\n"
    "step = 0.1\n"
    "steps_per_segment = 20\n"
    "segments = 40\n"
    "steps_per_pass = 5\n"
    "bound_radius = 60\n"
    "bound_center = 1 0 0\n"
    "precision = fp16\n"
    "mrt = off\n"
    "\n"
    "[model]\n"
    "type = schwarzschild\n"
    "center = 0 0 0.5\n"
    "mass = 1.5\n"
    "\n"
    "[lighting]\n"
    "ambient = 0.1 0.2 0.3\n"
    "\n"
    "[light sun]\n"
    "position = 10 20 30\n"
    "color = 1 0.9 0.8\n"
    "\n"
    "[light fill]\n"
    "color = 0.2 0.2 0.2\n"
    "\n"
    "[sky]\n"
    "type = cubemap\n"
    "color = 0 0 0\n"
    "cubemap = stars\n"
    "\n"
    "[object earth]\n"
    "type = sphere\n"
    "center = 5 0 0\n"
    "radius = 2\n"
    "pole = 0 0 1\n"
    "texture = earth.png\n"
    "ambient = 0.1\n"
    "diffuse = 0.7\n"
    "specular = 0.5\n"
    "shininess = 64\n"
    "\n"
    "[object ring]\n"
    "type = disk\n"
    "center = 0 0 0\n"
    "normal = 0 1 0.1\n"
    "radius = 8\n"
    "inner_radius = 4\n"
    "checker = 12\n"
    "checker_color = 1 1 1\n"
    "emission = 0.5 0.4 0.3\n"
    "\n"
    "[object wall]\n"
    "type = rect\n"
    "center = 0 0 -15\n"
    "axis_u = 10 0 0\n"
    "axis_v = 0 5 0\n"
    "texture = earth.png\n"
    "\n"
    "[object tri]\n"
    "type = triangle\n"
    "v0 = -1 0 -5\n"
    "v1 = 1 0 -5\n"
    "v2 = 0 1 -5\n"
    "uv0 = 0 0\n"
    "uv1 = 1 0\n"
    "uv2 = 0.5 1\n"
    "color = 0.9 0.1 0.1\n";

static void test_good_scene_round_trip(void **state)
{
    static const char *const faces[6] = {"px", "nx", "py", "ny", "pz", "nz"};
    struct scene_dir d;
    struct scene s;
    struct error err;
    char expect[256];
    const char *path;
    (void)state;

    make_dir(&d);
    dir_file(&d, "earth.png", "not really a PNG: only existence is checked here");
    for (int i = 0; i < 6; i++) {
        char face[32];
        snprintf(face, sizeof face, "stars_%s.png", faces[i]);
        dir_file(&d, face, "face");
    }
    path = dir_file(&d, "good.scene", good_scene);
    if (scene_load(&s, path, &err) != 0)
        fail_msg("%s: %s", err.where, err.message);
    assert_int_equal(scene_validate(&s, &err), 0);

    assert_string_equal(s.path, path);
    assert_string_equal(s.dir, d.dir);
    assert_string_equal(s.name, "orbit");
    assert_string_equal(s.description, "a sphere, a ring and a wall near a mass");
    assert_vec(s.camera.position, 0, 2, 20);
    assert_vec(s.camera.look_at, 0, 0, 0);
    assert_vec(s.camera.up, 0, 1, 0);
    assert_near(s.camera.fov_deg, 45, 0);

    assert_int_equal(s.render.width, 640);
    assert_int_equal(s.render.height, 480);
    assert_int_equal(s.render.method, METHOD_EULER);
    assert_near(s.render.step_size, 0.1, 0);
    assert_int_equal(s.render.steps_per_segment, 20);
    assert_int_equal(s.render.segments, 40);
    assert_int_equal(s.render.steps_per_pass, 5);
    assert_near(s.render.bound_radius, 60, 0);
    assert_vec(s.render.bound_center, 1, 0, 0);
    assert_int_equal(s.render.precision, PRECISION_FP16);
    assert_int_equal(s.render.mrt, MRT_OFF);

    assert_int_equal(s.model.type, MODEL_SCHWARZSCHILD);
    assert_vec(s.model.center, 0, 0, 0.5);
    assert_near(s.model.mass, 1.5, 0);

    assert_vec(s.ambient_light, 0.1, 0.2, 0.3);
    assert_int_equal(s.n_lights, 2);
    assert_string_equal(s.lights[0].name, "sun");
    assert_vec(s.lights[0].position, 10, 20, 30);
    assert_vec(s.lights[0].color, 1, 0.9, 0.8);
    assert_string_equal(s.lights[1].name, "fill");
    assert_vec(s.lights[1].color, 0.2, 0.2, 0.2);

    assert_int_equal(s.sky.type, SKY_CUBEMAP);
    assert_vec(s.sky.color, 0, 0, 0);
    snprintf(expect, sizeof expect, "%s/stars", d.dir);
    assert_string_equal(s.sky.cubemap, expect);

    assert_int_equal(s.n_objects, 4);
    const struct object *earth = &s.objects[0], *ring = &s.objects[1];
    const struct object *wall = &s.objects[2], *tri = &s.objects[3];
    assert_string_equal(earth->name, "earth");
    assert_int_equal(earth->type, PRIM_SPHERE);
    assert_vec(earth->center, 5, 0, 0);
    assert_near(earth->radius, 2, 0);
    assert_vec(earth->pole, 0, 0, 1);
    assert_near(earth->material.ambient, 0.1, 0);
    assert_near(earth->material.diffuse, 0.7, 0);
    assert_near(earth->material.specular, 0.5, 0);
    assert_near(earth->material.shininess, 64, 0);
    assert_vec(earth->material.color, 0.8, 0.8, 0.8);

    assert_int_equal(ring->type, PRIM_DISK);
    assert_vec(ring->normal, 0, 1, 0.1);
    assert_near(ring->radius, 8, 0);
    assert_near(ring->inner_radius, 4, 0);
    assert_near(ring->material.checker, 12, 0);
    assert_vec(ring->material.checker_color, 1, 1, 1);
    assert_vec(ring->material.emission, 0.5, 0.4, 0.3);
    assert_int_equal(ring->material.texture, -1);

    assert_int_equal(wall->type, PRIM_RECT);
    assert_vec(wall->center, 0, 0, -15);
    assert_vec(wall->axis_u, 10, 0, 0);
    assert_vec(wall->axis_v, 0, 5, 0);

    assert_int_equal(tri->type, PRIM_TRIANGLE);
    assert_vec(tri->vertex[0], -1, 0, -5);
    assert_vec(tri->vertex[1], 1, 0, -5);
    assert_vec(tri->vertex[2], 0, 1, -5);
    assert_near(tri->uv[2][0], 0.5, 0);
    assert_near(tri->uv[2][1], 1, 0);
    assert_vec(tri->material.color, 0.9, 0.1, 0.1);

    /* one file, two objects: stored once */
    assert_int_equal(s.n_textures, 1);
    snprintf(expect, sizeof expect, "%s/earth.png", d.dir);
    assert_string_equal(s.textures[0], expect);
    assert_int_equal(earth->material.texture, 0);
    assert_int_equal(wall->material.texture, 0);
    remove_dir(&d);
}

static void test_name_and_dir_from_path(void **state)
{
    struct scene_dir d;
    struct scene s;
    struct error err;
    (void)state;
    make_dir(&d);
    const char *path = dir_file(&d, "black.hole.scene", "[camera]\nfov = 30\n");
    assert_int_equal(scene_load(&s, path, &err), 0);
    assert_string_equal(s.name, "black.hole");
    assert_string_equal(s.dir, d.dir);

    /* a bare file name lives in the current directory */
    char cwd[1024];
    assert_non_null(getcwd(cwd, sizeof cwd));
    assert_int_equal(chdir(d.dir), 0);
    int rc = scene_load(&s, "black.hole.scene", &err);
    assert_int_equal(chdir(cwd), 0);
    assert_int_equal(rc, 0);
    assert_string_equal(s.dir, ".");
    assert_string_equal(s.name, "black.hole");
    remove_dir(&d);
}

static void test_missing_file(void **state)
{
    struct scene s;
    struct error err;
    (void)state;
    assert_int_equal(scene_load(&s, "/nonexistent/dir/x.scene", &err), -1);
    assert_string_equal(err.where, "/nonexistent/dir/x.scene");
    assert_contains(err.message, "No such file");
}

/* Notation that is only layout: BOM, CRLF, indentation, comments, ':' for '='. */
static void test_layout(void **state)
{
    static const char text[] =
        "\xEF\xBB\xBF; a comment\r\n"
        "# another comment\r\n"
        "[camera]   ; inline comment after a header\r\n"
        "    fov = 35 ; inline comment\r\n"
        "\tposition: 1 2 12\r\n"
        "  [ object ball ]\r\n"
        "type = sphere\r\n"
        "    radius = 3\r\n";
    struct scene s;
    struct error err;
    (void)state;
    if (load_text(&s, text, &err) != 0)
        fail_msg("%s: %s", err.where, err.message);
    assert_near(s.camera.fov_deg, 35, 0);
    assert_vec(s.camera.position, 1, 2, 12);
    assert_int_equal(s.n_objects, 1);
    assert_string_equal(s.objects[0].name, "ball");
    assert_near(s.objects[0].radius, 3, 0);
}

/* ---- bad fixtures ----------------------------------------------------------------------------- */

/* line 0: the file loads and scene_validate() refuses it, naming only the file */
static const struct {
    const char *file;
    int line;
    const char *words;
} bad_scenes[] = {
    {"unknown_section", 5, "unknown section [camrea] (did you mean [camera]?"},
    {"unknown_key", 4, "unknown key 'radiuss' in [object earth]"},
    {"unknown_light_key", 3, "unknown key 'intensity'"},
    {"model_key_before_type", 3, "set type first"},
    {"model_key_wrong_type", 4, "does not apply to model 'schwarzschild'"},
    {"object_key_before_type", 2, "set type first"},
    {"object_key_wrong_type", 4, "does not apply to object type 'sphere'"},
    {"object_without_type", 1, "has no type"},
    {"object_without_name", 1, "needs a name"},
    {"bad_object_name", 1, "bad object name"},
    {"camera_with_name", 1, "takes no name"},
    {"duplicate_object", 4, "appears twice (lines 1 and 4)"},
    {"duplicate_object_reopened", 6, "appears twice (lines 2 and 6)"},
    {"duplicate_light", 3, "appears twice"},
    {"duplicate_section", 5, "[camera] appears twice"},
    {"duplicate_key", 4, "already set at line 2"},
    {"too_many_lights", 9, "too many lights"},
    {"key_outside_section", 1, "before any section"},
    {"negative_radius", 3, "expected a number > 0, got \"-1\""},
    {"inner_radius_negative", 3, "a number >= 0"},
    {"nan_number", 2, "not a finite number"},
    {"inf_number", 2, "not a finite number"},
    {"overflow_number", 2, "too large"},
    {"fov_range", 2, "> 0 and < 180"},
    {"vector_too_short", 2, "3 numbers"},
    {"vector_too_long", 2, "3 numbers"},
    {"vector_comma", 2, "3 numbers"},
    {"zero_normal", 3, "not all zero"},
    {"color_range", 2, "each from 0 to 1000"},
    {"uv_count", 3, "2 numbers"},
    {"trailing_garbage", 2, "an integer"},
    {"not_integer", 2, "an integer"},
    {"integer_plus_sign", 3, "expected an integer from 0 to 100000, got \"+32\""},
    {"integer_range", 2, "from 1 to 8192"},
    {"bad_choice", 2, "one of euler, rk4, dopri5"},
    {"empty_value", 2, "key 'fov' in [camera] has an empty value"},
    {"scene_name_too_long", 2, "1 to 63 characters"},
    {"long_line", 3, "characters long"},
    {"syntax_no_equals", 2, "syntax error"},
    {"header_unclosed", 1, "without ']'"},
    {"text_after_header", 1, "unexpected text"},
    {"missing_texture", 3, "no_such_texture.png"},
    {"missing_cubemap", 3, "no_such_sky_px.png"},
    {"camera_at_look_at", 0, "same point"},
    {"camera_up_parallel", 0, "parallel"},
    {"camera_outside_bound", 0, "outside the bounding sphere"},
    {"camera_in_horizon", 0, "horizon radius 2M = 4"},
    {"steps_not_multiple", 0, "multiple of render.steps_per_pass"},
    {"embedded_without_pair", 0, "needs render.method = dopri5"},
    {"step_outside_bounds", 0, "must lie within render.step_min"},
    {"batch_range", 2, "from 1 to 16"},
    {"quality_negative", 2, "from 0 to 3.15"},
    {"observer_too_fast", 0, "speed 1.13137 c; it must stay below 0.999 c"},
    {"effects_without_black_body", 0, "give [sky], a [light] or an emitting [object] a temperature"},
    /* line -1: refused by the load, as a whole section ([kiosk] is checked as the file writes it) */
    {"kiosk_key_unknown", -1, "mass_key = model.mass: not a number of this scene"},
    {"kiosk_range_outside", -1, "own value 28 lies outside mass_min .. mass_max (30 .. 50)"},
    {"kiosk_range_without_key", -1, "speed_min, speed_max and speed_steps need speed_key"},
    {"kiosk_shadow_too_large", -1, "mass_max = 2: the black hole's shadow would span 107 degrees of the view's 50, "
                                    "more than 60% of its height: visitors would look at black; with this camera "
                                    "and view, mass_max = 0.526 keeps it within"},
    {"kiosk_mass_into_horizon", -1, "mass_max = 6 puts the camera at or inside the black hole's horizon"},
    {"temperature_negative", 2, "from 0 to 1000000"},
    {"moving_in_curved_space", 0, "[object ball] moves, but light is bent here (model schwarzschild)"},
    {"object_too_fast", 0, "[object ball]: velocity has speed 1 c"},
    {"clock_in_curved_space", 0, "[object dial] carries a clock, but light is bent here (model lorenz)"},
    {"rect_not_orthogonal", 0, "orthogonal"},
    {"disk_inner_too_large", 0, "smaller than radius"},
    {"sky_cubemap_without_prefix", 0, "no cubemap"},
};

static void test_bad_fixtures(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof bad_scenes / sizeof bad_scenes[0]; i++) {
        struct scene s;
        struct error err;
        char path[256], where[300];
        snprintf(path, sizeof path, "%s/%s.scene", BAD_DIR, bad_scenes[i].file);
        int rc = scene_load(&s, path, &err);
        if (bad_scenes[i].line != 0) {
            if (rc == 0)
                fail_msg("%s loaded without error", path);
            if (bad_scenes[i].line > 0)
                snprintf(where, sizeof where, "%s:%d", path, bad_scenes[i].line);
            else
                snprintf(where, sizeof where, "%s", path);
        } else {
            if (rc != 0)
                fail_msg("%s should load, got %s: %s", path, err.where, err.message);
            if (scene_validate(&s, &err) == 0)
                fail_msg("%s passed validation", path);
            snprintf(where, sizeof where, "%s", path);
        }
        if (strcmp(err.where, where) != 0 || !strstr(err.message, bad_scenes[i].words))
            fail_msg("%s: expected \"%s\" with \"%s\", got \"%s\": %s", bad_scenes[i].file, where,
                     bad_scenes[i].words, err.where, err.message);
    }
}

/* The black hole's shadow seen by the static observer at the camera (the kiosk's bound on the mass
 * knob): its angular radius alpha from the direction to the hole obeys sin(alpha) = 3 sqrt(3) M / r
 * sqrt(1 - 2M/r), with alpha = 90 degrees at the photon sphere r = 3M and beyond 90 inside it. */
static void test_shadow_size(void **state)
{
    (void)state;
    static struct scene s;
    scene_defaults(&s);
    s.model.type = MODEL_SCHWARZSCHILD;
    s.model.center = v3(0.0, 0.0, 0.0);
    s.camera.position = v3(0.0, 0.0, 6.0);
    s.model.mass = 1.0;                               /* r = 6M: sin(alpha) = sqrt(3)/2 sqrt(2/3) */
    assert_true(fabs(scene_shadow_diameter_deg(&s) - 90.0) < 1e-9);
    s.model.mass = 2.0;                               /* r = 3M: half the sky */
    assert_true(fabs(scene_shadow_diameter_deg(&s) - 180.0) < 1e-9);
    s.model.mass = 2.4;                               /* inside the photon sphere: more than half */
    double inside = 2.0 * (180.0 - asin(3.0 * sqrt(3.0) * 2.4 / 6.0 * sqrt(1.0 - 4.8 / 6.0)) * 180.0 / 3.14159265358979323846);
    assert_true(fabs(scene_shadow_diameter_deg(&s) - inside) < 1e-9);
    s.model.mass = 3.0;                               /* the camera on the horizon */
    assert_true(scene_shadow_diameter_deg(&s) == 360.0);
    s.model.mass = 1e-6;                              /* far away: 2 b_c / r */
    double far = 2.0 * 3.0 * sqrt(3.0) * 1e-6 / 6.0 * 180.0 / 3.14159265358979323846;
    assert_true(fabs(scene_shadow_diameter_deg(&s) / far - 1.0) < 1e-5);
    s.model.mass = 0.0;
    assert_true(scene_shadow_diameter_deg(&s) == 0.0);
    s.model.type = MODEL_LORENZ;
    s.model.mass = 1.0;
    assert_true(scene_shadow_diameter_deg(&s) == 0.0);
    /* the largest mass for a given shadow is its inverse, rounded down to three digits */
    s.model.type = MODEL_SCHWARZSCHILD;
    const double spans[] = {1.0, 30.0, 90.0, 179.0, 250.0};
    for (size_t i = 0; i < sizeof spans / sizeof spans[0]; i++) {
        double m = scene_mass_for_shadow(&s, spans[i]);
        s.model.mass = m;
        assert_true(scene_shadow_diameter_deg(&s) <= spans[i]);
        s.model.mass = m * 1.01;
        assert_true(scene_shadow_diameter_deg(&s) > spans[i]);
    }
}

/* Every shipped black hole bounds its mass knob in [kiosk] so that the shadow stays within 60% of
 * the view's height, and not much below it: the knob's range is the widest the exhibit can show. */
static void test_shipped_black_holes_bound_the_mass_knob(void **state)
{
    (void)state;
    static const char *const scenes[] = {"schwarzschild", "blackhole_flight", "demo", "neutron_star"};
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++) {
        static struct scene s;
        struct error e;
        char path[128];
        snprintf(path, sizeof path, "assets/scenes/%s.scene", scenes[i]);
        if (scene_load(&s, path, &e) != 0)
            fail_msg("%s: %s", e.where, e.message);
        assert_string_equal(s.kiosk.mass.key, "model.mass");
        double own = scene_shadow_diameter_deg(&s);
        s.model.mass = s.kiosk.mass.max;
        double limit = SCENE_KIOSK_SHADOW_MAX_FRACTION * s.camera.fov_deg, across = scene_shadow_diameter_deg(&s);
        print_message("%s: shadow %.1f degrees at the scene's own mass, %.1f at mass_max %g; %.1f allowed\n",
                      scenes[i], own, across, s.kiosk.mass.max, limit);
        assert_true(across <= limit && across >= 0.8 * limit);
    }
}

/* A fixture nobody checks is a fixture that can rot. */
static void test_every_fixture_is_in_the_table(void **state)
{
    DIR *dir = opendir(BAD_DIR);
    struct dirent *e;
    int count = 0;
    (void)state;
    assert_non_null(dir);
    while ((e = readdir(dir)) != NULL) {
        size_t n = strlen(e->d_name);
        int found = 0;
        if (n < 7 || strcmp(e->d_name + n - 6, ".scene") != 0)
            continue;
        count++;
        for (size_t i = 0; i < sizeof bad_scenes / sizeof bad_scenes[0]; i++)
            if (strlen(bad_scenes[i].file) == n - 6 && strncmp(bad_scenes[i].file, e->d_name, n - 6) == 0)
                found = 1;
        if (!found)
            fail_msg("%s/%s has no entry in bad_scenes", BAD_DIR, e->d_name);
    }
    closedir(dir);
    assert_int_equal(count, (int)(sizeof bad_scenes / sizeof bad_scenes[0]));
}

/* ---- specific errors ---------------------------------------------------------------------------- */

static void test_duplicate_objects(void **state)
{
    struct scene s;
    struct error err;
    (void)state;
    assert_int_equal(load_text(&s, "[object a]\ntype = sphere\n[object b]\ntype = disk\n"
                               "[object a]\ntype = rect\n", &err), -1);
    assert_contains(err.where, ":5");
    assert_contains(err.message, "[object a] appears twice (lines 1 and 5)");
    /* different names are different objects */
    assert_int_equal(load_text(&s, "[object a]\ntype = sphere\n[object b]\ntype = sphere\n", &err), 0);
    assert_int_equal(s.n_objects, 2);
}

static void test_model_keys_follow_the_type(void **state)
{
    struct scene s;
    struct error err;
    (void)state;
    assert_int_equal(load_text(&s, "[model]\ntype = schwarzschild\nrho = 28\n", &err), -1);
    assert_contains(err.where, ":3");
    assert_contains(err.message, "key 'rho' in [model] does not apply to model 'schwarzschild'");
    assert_contains(err.message, "lorenz");

    /* 'beta' is Lorenz's beta or Roessler's b, by model type */
    assert_int_equal(load_text(&s, "[model]\ntype = lorenz\nbeta = 3\n", &err), 0);
    assert_near(s.model.beta, 3, 0);
    assert_near(s.model.ross_b, 2, 0);
    assert_int_equal(load_text(&s, "[model]\ntype = rossler\nbeta = 0.5\nalpha = 0.2\ngamma = 5.7\n",
                               &err), 0);
    assert_near(s.model.ross_b, 0.5, 0);
    assert_near(s.model.ross_a, 0.2, 0);
    assert_near(s.model.ross_c, 5.7, 0);
    assert_near(s.model.beta, 8.0 / 3.0, 1e-15);

    assert_int_equal(load_text(&s, "[model]\ntype = flat\ncenter = 1 2 3\n", &err), -1);
    assert_contains(err.message, "does not apply to model 'flat'");
    assert_int_equal(load_text(&s, "[model]\ntype = potential\nprofile = polynomial\nradius = 3\n"
                               "strength = 2\ncenter = 1 0 0\n", &err), 0);
    assert_int_equal(s.model.profile, PROFILE_POLYNOMIAL);
    assert_near(s.model.radius, 3, 0);
    assert_near(s.model.strength, 2, 0);
    assert_int_equal(load_text(&s, "[model]\ntype = refraction\namplitude = 0.1\nshell_radius = 3\n"
                               "shell_width = 1\nnoise_amplitude = 0\nnoise_frequency = 2\n", &err), 0);
    assert_near(s.model.shell_radius, 3, 0);
}

static void test_textures(void **state)
{
    struct scene_dir d;
    struct scene s;
    struct error err;
    char text[2048];
    size_t used = 0;
    (void)state;
    make_dir(&d);
    for (int i = 0; i < SCENE_MAX_TEXTURES + 1; i++) {
        char name[32];
        snprintf(name, sizeof name, "t%d.png", i);
        dir_file(&d, name, "x");
        used += (size_t)snprintf(text + used, sizeof text - used,
                                 "[object o%d]\ntype = sphere\ntexture = t%d.png\n", i, i);
    }
    /* one object more than textures allowed, each with its own file */
    const char *path = dir_file(&d, "many.scene", text);
    assert_int_equal(scene_load(&s, path, &err), -1);
    assert_contains(err.message, "too many textures");
    assert_contains(err.where, ":27");

    /* the same file through different objects: one slot */
    path = dir_file(&d, "shared.scene", "[object a]\ntype = sphere\ntexture = t0.png\n"
                    "[object b]\ntype = disk\ntexture = t0.png\n[object c]\ntype = rect\n");
    assert_int_equal(scene_load(&s, path, &err), 0);
    assert_int_equal(s.n_textures, 1);
    assert_int_equal(s.objects[0].material.texture, 0);
    assert_int_equal(s.objects[1].material.texture, 0);
    assert_int_equal(s.objects[2].material.texture, -1);

    /* missing, and a directory instead of a file */
    path = dir_file(&d, "missing.scene", "[object a]\ntype = sphere\ntexture = nope.png\n");
    assert_int_equal(scene_load(&s, path, &err), -1);
    assert_contains(err.where, ":3");
    assert_contains(err.message, "nope.png");
    assert_contains(err.message, "No such file");
    path = dir_file(&d, "dir.scene", "[object a]\ntype = sphere\ntexture = .\n");
    assert_int_equal(scene_load(&s, path, &err), -1);
    assert_contains(err.message, "not a regular file");
    remove_dir(&d);
}

static void test_cubemap_names_missing_face(void **state)
{
    static const char *const faces[5] = {"px", "nx", "py", "pz", "nz"};
    struct scene_dir d;
    struct scene s;
    struct error err;
    (void)state;
    make_dir(&d);
    for (int i = 0; i < 5; i++) {
        char face[32];
        snprintf(face, sizeof face, "sky_%s.png", faces[i]);
        dir_file(&d, face, "face");
    }
    const char *path = dir_file(&d, "sky.scene", "[sky]\ntype = cubemap\ncubemap = sky\n");
    assert_int_equal(scene_load(&s, path, &err), -1);
    assert_contains(err.message, "face ny");
    assert_contains(err.message, "sky_ny.png");
    remove_dir(&d);
}

/* ---- limits ------------------------------------------------------------------------------------ */

static char *objects_text(int count)
{
    size_t cap = (size_t)count * 40 + 1;
    char *text = malloc(cap);
    size_t used = 0;
    assert_non_null(text);
    text[0] = '\0';
    for (int i = 0; i < count; i++)
        used += (size_t)snprintf(text + used, cap - used, "[object o%d]\ntype = sphere\n", i);
    return text;
}

static void test_limits(void **state)
{
    struct scene s;
    struct error err;
    char *text;
    char line[512];
    (void)state;

    text = objects_text(SCENE_MAX_OBJECTS);
    assert_int_equal(load_text(&s, text, &err), 0);
    assert_int_equal(s.n_objects, SCENE_MAX_OBJECTS);
    free(text);
    text = objects_text(SCENE_MAX_OBJECTS + 1);
    assert_int_equal(load_text(&s, text, &err), -1);
    assert_contains(err.message, "too many objects");
    snprintf(line, sizeof line, ":%d", 2 * SCENE_MAX_OBJECTS + 1);
    assert_contains(err.where, line);
    free(text);

    assert_int_equal(load_text(&s, "[light a]\n[light b]\n[light c]\n[light d]\n", &err), 0);
    assert_int_equal(s.n_lights, SCENE_MAX_LIGHTS);

    /* the longest line inih can take, and one more character */
    snprintf(line, sizeof line, "[scene]\ndescription = %0*d\n", 197 - 14, 0);
    assert_int_equal(load_text(&s, line, &err), 0);
    assert_int_equal(strlen(s.description), 197 - 14);
    snprintf(line, sizeof line, "[scene]\ndescription = %0*d\n", 198 - 14, 0);
    assert_int_equal(load_text(&s, line, &err), -1);
    assert_contains(err.where, ":2");
    assert_contains(err.message, "198 characters");

    assert_int_equal(load_text(&s, "[render]\nwidth = 8192\nheight = 1\nsegments = 100000\n"
                               "steps_per_segment = 10000\nsteps_per_pass = 64\n", &err), 0);
    assert_int_equal(load_text(&s, "[render]\nsteps_per_pass = 65\n", &err), -1);
    assert_int_equal(load_text(&s, "[render]\nsegments = 100001\n", &err), -1);
    assert_int_equal(load_text(&s, "[render]\nstep = 1e6\n", &err), 0);
    assert_int_equal(load_text(&s, "[render]\nstep = 1.000001e6\n", &err), -1);

    /* a file over the size limit is refused before parsing, even if it is all comments */
    {
        size_t n = SCENE_MAX_FILE_BYTES + 1;
        char *big = malloc(n + 1);
        char path[64];
        assert_non_null(big);
        memset(big, '\n', n);
        big[n] = '\0';
        temp_scene(path, big);
        assert_int_equal(scene_load(&s, path, &err), -1);
        assert_string_equal(err.where, path);
        assert_contains(err.message, "larger than");
        unlink(path);
        big[n - 1] = '\0';  /* exactly at the limit: fine */
        assert_int_equal(load_text(&s, big, &err), 0);
        free(big);
    }
}

static void test_nul_byte(void **state)
{
    static const char text[] = "[camera]\nfov = 4\0005\n";
    char path[64];
    struct scene s;
    struct error err;
    (void)state;
    temp_scene(path, "");
    write_file(path, text, sizeof text - 1);
    assert_int_equal(scene_load(&s, path, &err), -1);
    unlink(path);
    assert_contains(err.where, ":2");
    assert_contains(err.message, "NUL");
}

/* ---- --set ------------------------------------------------------------------------------------- */

static void load_good(struct scene *s)
{
    struct error err;
    if (load_text(s, "[object earth]\ntype = sphere\nradius = 2\n[light sun]\ncolor = 1 1 1\n", &err))
        fail_msg("%s: %s", err.where, err.message);
}

static void test_set_overrides(void **state)
{
    struct scene s;
    struct error err;
    (void)state;
    load_good(&s);
    assert_int_equal(scene_set(&s, "camera.fov=75", &err), 0);
    assert_near(s.camera.fov_deg, 75, 0);
    assert_int_equal(scene_set(&s, " render.width = 800 ", &err), 0);
    assert_int_equal(s.render.width, 800);
    assert_int_equal(scene_set(&s, "render.method=euler", &err), 0);
    assert_int_equal(s.render.method, METHOD_EULER);
    assert_int_equal(scene_set(&s, "camera.position=1 2 3", &err), 0);
    assert_vec(s.camera.position, 1, 2, 3);
    assert_int_equal(scene_set(&s, "object.earth.radius=4.5", &err), 0);
    assert_near(s.objects[0].radius, 4.5, 0);
    assert_int_equal(scene_set(&s, "object.earth.color=0.1 0.2 0.3", &err), 0);
    assert_vec(s.objects[0].material.color, 0.1, 0.2, 0.3);
    assert_int_equal(scene_set(&s, "light.sun.position=0 50 0", &err), 0);
    assert_vec(s.lights[0].position, 0, 50, 0);
    assert_int_equal(scene_set(&s, "scene.name=renamed", &err), 0);
    assert_string_equal(s.name, "renamed");
    assert_int_equal(scene_set(&s, "scene.description=", &err), 0);
    assert_string_equal(s.description, "");
}

/* A scene that names no method takes exact orbits where they apply: around a Schwarzschild mass
 * with fixed steps, also when --set makes it one; a named method, or adaptive steps, keep their own. */
static void test_method_defaults_to_exact_orbits(void **state)
{
    struct scene s;
    struct error err;
    (void)state;
    assert_int_equal(load_text(&s, "[model]\ntype = schwarzschild\nmass = 0.5\n", &err), 0);
    assert_int_equal(s.render.method, METHOD_ORBIT_TABLE);
    assert_int_equal(scene_set(&s, "render.step_control=doubling", &err), 0);
    assert_int_equal(s.render.method, METHOD_RK4);
    assert_int_equal(scene_set(&s, "render.step_control=fixed", &err), 0);
    assert_int_equal(s.render.method, METHOD_ORBIT_TABLE);
    assert_int_equal(scene_set(&s, "model.type=lorenz", &err), 0);
    assert_int_equal(s.render.method, METHOD_RK4);
    assert_int_equal(load_text(&s, "[render]\nmethod = rk4\n[model]\ntype = schwarzschild\nmass = 0.5\n", &err), 0);
    assert_int_equal(s.render.method, METHOD_RK4);
    assert_int_equal(load_text(&s, "[model]\ntype = flat\n", &err), 0);
    assert_int_equal(s.render.method, METHOD_RK4);
    assert_int_equal(scene_set(&s, "model.type=schwarzschild", &err), 0);
    assert_int_equal(s.render.method, METHOD_ORBIT_TABLE);
    assert_int_equal(scene_set(&s, "render.method=dopri5", &err), 0);
    assert_int_equal(scene_set(&s, "model.type=flat", &err), 0);
    assert_int_equal(scene_set(&s, "model.type=schwarzschild", &err), 0);
    assert_int_equal(s.render.method, METHOD_DOPRI5);
}

/* Switching the model keeps every parameter: --set model.type=x then model.mass=y, in order. */
static void test_set_model_type_resets_nothing(void **state)
{
    struct scene s;
    struct error err;
    (void)state;
    load_good(&s);
    assert_int_equal(scene_set(&s, "model.mass=3", &err), -1);
    assert_contains(err.message, "does not apply to model 'flat'");
    assert_int_equal(scene_set(&s, "model.type=lorenz", &err), 0);
    assert_int_equal(scene_set(&s, "model.rho=30", &err), 0);
    assert_int_equal(scene_set(&s, "model.type=schwarzschild", &err), 0);
    assert_int_equal(s.model.type, MODEL_SCHWARZSCHILD);
    assert_near(s.model.rho, 30, 0);
    assert_near(s.model.mass, 1, 0);
    assert_int_equal(scene_set(&s, "model.mass=0.5", &err), 0);
    assert_near(s.model.mass, 0.5, 0);
    assert_int_equal(scene_set(&s, "model.rho=31", &err), -1);
    assert_contains(err.message, "key 'rho' in [model] does not apply to model 'schwarzschild'");
}

static void test_set_rejects(void **state)
{
    static const struct {
        const char *assignment;
        const char *words;
    } bad[] = {
        {"camera.fov", "expected section.key=value"},
        {"fov=40", "no '.'"},
        {"camrea.fov=40", "unknown section [camrea]"},
        {"camera.fovv=40", "did you mean 'fov'"},
        {"camera.fov=200", "expected a number > 0 and < 180, got \"200\""},
        {"camera.fov=nan", "not a finite number"},
        {"camera.fov=45 46", "expected a number"},
        {"camera.up=0 0 0", "not all zero"},
        {"render.width=12.5", "an integer"},
        {"render.height=0", "from 1 to 8192"},
        {"render.precision=fp64", "one of auto, fp32, fp16"},
        {"render.step=1e-400", "too large or too small"},
        {"object.moon.radius=1", "no object named 'moon'"},
        {"object.earth=1", "expected object.NAME.key=value"},
        {"object.earth.normal=0 1 0", "does not apply to object type 'sphere'"},
        {"object.earth.radius=-1", "expected a number > 0"},
        {"object.earth.texture=nope.png", "nope.png"},
        {"light.moon.color=1 1 1", "no light named 'moon'"},
        {"light.sun.radius=1", "unknown key 'radius' in [light sun]"},
        {"sky.cubemap=nowhere", "nowhere_px.png"},
    };
    struct scene s, before;
    struct error err;
    (void)state;
    load_good(&s);
    before = s;
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char where[256];
        if (scene_set(&s, bad[i].assignment, &err) == 0)
            fail_msg("--set %s was accepted", bad[i].assignment);
        snprintf(where, sizeof where, "--set %s", bad[i].assignment);
        assert_string_equal(err.where, where);
        if (!strstr(err.message, bad[i].words))
            fail_msg("--set %s: \"%s\" lacks \"%s\"", bad[i].assignment, err.message, bad[i].words);
    }
    /* a refused value leaves the scene as it was */
    assert_memory_equal(&s, &before, sizeof s);
}

/* ---- validation ------------------------------------------------------------------------------ */

static void test_validate(void **state)
{
    struct scene s;
    struct error err;
    (void)state;
    load_good(&s);
    assert_int_equal(scene_validate(&s, &err), 0);

    assert_int_equal(scene_set(&s, "model.type=schwarzschild", &err), 0);
    assert_int_equal(scene_set(&s, "model.mass=5", &err), 0);
    assert_int_equal(scene_validate(&s, &err), -1);
    assert_string_equal(err.where, s.path);
    assert_contains(err.message, "horizon radius 2M = 10");
    assert_int_equal(scene_set(&s, "model.mass=4.9", &err), 0);
    assert_int_equal(scene_validate(&s, &err), 0);

    assert_int_equal(scene_set(&s, "render.steps_per_pass=3", &err), 0);
    assert_int_equal(scene_validate(&s, &err), -1);
    assert_contains(err.message, "multiple");
    assert_int_equal(scene_set(&s, "render.steps_per_pass=5", &err), 0);
    assert_int_equal(scene_validate(&s, &err), 0);

    /* almost orthogonal rect axes pass, a clear tilt does not */
    assert_int_equal(load_text(&s, "[object w]\ntype = rect\naxis_u = 1 0 0\naxis_v = 1e-7 1 0\n",
                               &err), 0);
    assert_int_equal(scene_validate(&s, &err), 0);
    assert_int_equal(scene_set(&s, "object.w.axis_v=1e-5 1 0", &err), 0);
    assert_int_equal(scene_validate(&s, &err), -1);
    assert_contains(err.message, "orthogonal");

    /* degenerate triangles are allowed: they never hit */
    assert_int_equal(load_text(&s, "[object t]\ntype = triangle\nv0 = 0 0 0\nv1 = 0 0 0\nv2 = 0 0 0\n",
                               &err), 0);
    assert_int_equal(scene_validate(&s, &err), 0);
}

/* A ray's budget (docs/SCENES.md, [render]): fixed steps take it from segments or from max_path,
 * never both; adaptive steps always from max_path, with segments as the most a frame runs; a
 * budget beyond the segments a frame may run is refused. */
/* scene_set_number (the kiosk's knobs) takes a number as --set takes its text: the same values
 * stored, the same values refused in the same words, and only keys that are numbers. */
static void test_set_number(void **state)
{
    (void)state;
    static struct scene a, b;
    struct error ea, eb;
    static const struct {
        const char *key;
        double value;
    } cases[] = {
        {"model.rho", 28.0},          {"model.rho", 0.1 + 0.2},       {"model.rho", -1.0},
        {"model.rho", 1e300},         {"model.rho", 5e-320},          {"camera.fov", 179.5},
        {"camera.fov", 0.0},          {"camera.fov", 180.0},          {"render.step", 1e-3},
        {"render.bound_radius", 0.0}, {"model.sigma", 10.000000000000002},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        assert_int_equal(scene_load(&a, "assets/scenes/lorenz.scene", &ea), 0);
        b = a;
        char text[128];
        snprintf(text, sizeof text, "%s=%.17g", cases[k].key, cases[k].value);
        int ra = scene_set_number(&a, cases[k].key, cases[k].value, &ea);
        int rb = scene_set(&b, text, &eb);
        print_message("%s: %s%s\n", text, ra ? "refused: " : "set", ra ? ea.message : "");
        assert_int_equal(ra, rb);
        if (ra == 0) {
            double x = NAN, y = NAN;
            assert_int_equal(scene_get_number(&a, cases[k].key, &x), 0);
            assert_int_equal(scene_get_number(&b, cases[k].key, &y), 0);
            assert_memory_equal(&x, &y, sizeof x);
            assert_memory_equal(&x, &cases[k].value, sizeof x);
        } else {
            /* the same reason; the quoted value differs only in its quotes */
            const char *expected = strstr(eb.message, "expected");
            assert_non_null(expected);
            assert_non_null(strstr(ea.message, "expected"));
            size_t n = (size_t)(strstr(expected, ", got") - expected);
            assert_int_equal(strncmp(strstr(ea.message, "expected"), expected, n), 0);
            const char *why_b = strstr(expected, " ("), *why_a = strstr(ea.message, " (");
            assert_true((why_a == NULL) == (why_b == NULL));
            if (why_b)
                assert_string_equal(why_a, why_b);
        }
    }
    assert_int_equal(scene_load(&a, "assets/scenes/lorenz.scene", &ea), 0);
    assert_int_equal(scene_set_number(&a, "camera.position", 1.0, &ea), -1);
    assert_non_null(strstr(ea.message, "not a number of this scene"));
    assert_int_equal(scene_set_number(&a, "model.mass", 1.0, &ea), -1);   /* Lorenz has no mass */
    assert_int_equal(scene_set_number(&a, "object.x.radius", 1.0, &ea), -1);
    assert_int_equal(scene_set_number(&a, "nonsense", 1.0, &ea), -1);
}

static void test_budget(void **state)
{
    struct scene s;
    struct error err;
    (void)state;
    assert_int_equal(load_text(&s, "[render]\nstep = 0.5\nsteps_per_segment = 2\nsteps_per_pass = 2\n"
                                   "bound_radius = 20\n[model]\ntype = lorenz\n", &err), 0);
    assert_int_equal(scene_validate(&s, &err), 0);
    /* no budget: 3 diameters = 120, at 1 a segment */
    assert_near(render_path_budget(&s.render), 120.0, 1e-12);
    assert_int_equal(render_segments(&s.render), 120);
    assert_int_equal(scene_set(&s, "render.max_path=25.5", &err), 0);
    assert_int_equal(scene_validate(&s, &err), 0);
    /* fixed steps run whole segments: the path rounded up to them, on both engines */
    assert_int_equal(render_segments(&s.render), 26);
    assert_near(render_path_budget(&s.render), 26.0, 1e-12);
    /* an override of one replaces the other: the segments given, the path cleared */
    assert_int_equal(scene_set(&s, "render.segments=7", &err), 0);
    assert_near(s.render.max_path, 0.0, 0.0);
    assert_near(render_path_budget(&s.render), 7.0, 1e-12);
    assert_int_equal(scene_set(&s, "render.max_path=25.5", &err), 0);
    assert_int_equal(s.render.segments, 0);
    /* adaptive: the path is the budget, the segments the most a frame runs (both kept) */
    assert_int_equal(scene_set(&s, "render.step_control=doubling", &err), 0);
    assert_int_equal(scene_set(&s, "render.segments=7", &err), 0);
    assert_int_equal(scene_validate(&s, &err), 0);
    assert_near(render_path_budget(&s.render), 25.5, 1e-12);
    assert_int_equal(render_segments(&s.render), 7);
    assert_int_equal(scene_set(&s, "render.segments=0", &err), 0);
    assert_int_equal(render_segments(&s.render), 2 * 26);
    /* fixed steps with segments: the paper's count */
    assert_int_equal(scene_set(&s, "render.step_control=fixed", &err), 0);
    assert_int_equal(scene_set(&s, "render.max_path=0", &err), 0);
    assert_int_equal(scene_set(&s, "render.segments=7", &err), 0);
    assert_near(render_path_budget(&s.render), 7.0, 1e-12);
    /* a budget that would take more segments than a frame runs */
    assert_int_equal(scene_set(&s, "render.segments=0", &err), 0);
    assert_int_equal(scene_set(&s, "render.max_path=1e9", &err), 0);
    assert_int_equal(scene_validate(&s, &err), -1);
    assert_contains(err.message, "takes 1000000000 segments");
    assert_int_equal(scene_set(&s, "render.max_path=-1", &err), -1);
    assert_int_equal(scene_set(&s, "render.max_path=2e9", &err), -1);
    /* flat space takes no steps: its budget is not refused */
    assert_int_equal(scene_set(&s, "model.type=flat", &err), 0);
    assert_int_equal(scene_validate(&s, &err), 0);
    /* a file that gives a fixed step's budget both ways is refused, naming both keys */
    assert_int_equal(load_text(&s, "[render]\nsegments = 7\nmax_path = 25.5\n", &err), 0);
    assert_int_equal(scene_validate(&s, &err), -1);
    assert_contains(err.message, "render.segments = 7 and render.max_path = 25.5 both set the budget");
}

/* ---- documentation ------------------------------------------------------------------------------ */

static void test_every_key_is_documented(void **state)
{
    FILE *f = fopen("docs/SCENES.md", "rb");
    char *doc;
    long n;
    (void)state;
    assert_non_null(f);
    assert_int_equal(fseek(f, 0, SEEK_END), 0);
    n = ftell(f);
    assert_true(n > 0);
    rewind(f);
    doc = malloc((size_t)n + 1);
    assert_non_null(doc);
    assert_int_equal(fread(doc, 1, (size_t)n, f), (size_t)n);
    doc[n] = '\0';
    fclose(f);
    for (int i = 0; i < SECTION_COUNT; i++) {
        char heading[64];
        snprintf(heading, sizeof heading, "[%s", scene_section_name((enum scene_section_kind)i));
        assert_contains(doc, heading);
    }
    for (int i = 0; i < scene_key_count; i++) {
        char name[64];
        snprintf(name, sizeof name, "`%s`", scene_keys[i].name);
        if (!strstr(doc, name))
            fail_msg("docs/SCENES.md does not mention key %s of [%s]", name,
                     scene_section_name(scene_keys[i].section));
    }
    free(doc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_defaults),
        cmocka_unit_test(test_good_scene_round_trip),
        cmocka_unit_test(test_name_and_dir_from_path),
        cmocka_unit_test(test_missing_file),
        cmocka_unit_test(test_layout),
        cmocka_unit_test(test_bad_fixtures),
        cmocka_unit_test(test_every_fixture_is_in_the_table),
        cmocka_unit_test(test_shadow_size),
        cmocka_unit_test(test_shipped_black_holes_bound_the_mass_knob),
        cmocka_unit_test(test_duplicate_objects),
        cmocka_unit_test(test_model_keys_follow_the_type),
        cmocka_unit_test(test_textures),
        cmocka_unit_test(test_cubemap_names_missing_face),
        cmocka_unit_test(test_limits),
        cmocka_unit_test(test_nul_byte),
        cmocka_unit_test(test_set_overrides),
        cmocka_unit_test(test_method_defaults_to_exact_orbits),
        cmocka_unit_test(test_set_model_type_resets_nothing),
        cmocka_unit_test(test_set_rejects),
        cmocka_unit_test(test_validate),
        cmocka_unit_test(test_budget),
        cmocka_unit_test(test_set_number),
        cmocka_unit_test(test_every_key_is_documented),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
