#include "ref/reference.h"
#include "physics/escape.h"
#include "ref/dopri5.h"
#include "results/dump.h"
#include "ref/straight.h"
#include "ref/surface.h"
#include <math.h>
#include <string.h>

/* Each accepted step is searched for crossings along this many chords of its dense output: the
 * chords bound where the curve can be, the crossing itself is found on the curve. */
#define SUB_CHORDS 4
/* Bisection halvings of a step fraction: 2^-64 is below double resolution. */
#define ROOT_ITERATIONS 64
/* Golden-section iterations for the extremum of a surface function within one chord. */
#define EXTREMUM_ITERATIONS 48
/* Flat space: one straight segment, ending 1% beyond the bounding sphere as on the GPU. */
#define FLAT_OVERSHOOT 1.01
/* Longest step, as a fraction of the distance from the model's centre. Far from a central mass the
 * force fades (r^-4 for Schwarzschild) and the controller would grow the step until one step
 * carries the ray past the mass without a stage near it: an error estimate of zero, a deflection
 * of zero. No step may be longer than this part of the way in. */
#define CENTRE_STEP_FRACTION 0.25
/* ... measured from at least this fraction of the bounding radius, so that a ray through the
 * centre itself is not forced into ever shorter steps. */
#define CENTRE_FLOOR_FRACTION 1e-3

/* The step limit of CENTRE_STEP_FRACTION at the current state. */
static double centre_step_limit(const struct dopri5 *d, vec3d centre, double floor_radius)
{
    double r = v3_len(v3_sub(v3(d->y[0], d->y[1], d->y[2]), centre));
    double speed = v3_len(v3(d->y[3], d->y[4], d->y[5]));
    if (!(speed > 0.0))
        return INFINITY;
    return CENTRE_STEP_FRACTION * fmax(r, floor_radius) / speed;
}

void ref_options_default(struct ref_options *o, const struct scene *s)
{
    o->rtol = REF_DEFAULT_RTOL;
    o->atol = REF_DEFAULT_RTOL * s->render.bound_radius;
    o->max_steps = 2000000;
    o->min_step = 1e-13 * s->render.bound_radius;
}

enum crossing_role { ROLE_OBJECT, ROLE_BOUND, ROLE_CAPTURE };

struct tracer {
    const struct scene *scene;
    const struct ref_options *opt;
    struct dopri5 d;
    int n_surfaces;
    struct surface surfaces[SCENE_MAX_OBJECTS + 2];  /* objects, then bound, then capture */
    enum crossing_role roles[SCENE_MAX_OBJECTS + 2];
    double sample_interval, next_sample;
    ref_sample_fn sample;
    void *sample_arg;
};

/* A piece of the current step between fractions ta and tb, with the chord's end points. */
struct chord {
    double ta, tb;
    vec3d xa, xb, mid;
    double reach;           /* radius of a sphere about mid that holds the curve over the chord */
};

static double value_at(const struct tracer *t, const struct surface *sf, double theta)
{
    return surface_value(sf, dopri5_dense_x(&t->d, theta));
}

/* g(ta) has sign `side` (nonzero), g(tb) does not: the crossing, to double resolution, taken on
 * the far side so that the point returned is already across. */
static double bisect(const struct tracer *t, const struct surface *sf, double ta, double tb, double side)
{
    for (int i = 0; i < ROOT_ITERATIONS && tb - ta > 0.0; i++) {
        double tm = 0.5 * (ta + tb);
        if (tm <= ta || tm >= tb)
            break;
        if (side * value_at(t, sf, tm) > 0.0)
            ta = tm;
        else
            tb = tm;
    }
    return tb;
}

/* Where side * g is smallest on [ta, tb] (golden section; g is smooth and one chord is short). */
static double extremum(const struct tracer *t, const struct surface *sf, double ta, double tb, double side,
                       double *g_min)
{
    const double ratio = 0.6180339887498949;
    double a = ta, b = tb;
    double c = b - ratio * (b - a), e = a + ratio * (b - a);
    double gc = side * value_at(t, sf, c), ge = side * value_at(t, sf, e);
    for (int i = 0; i < EXTREMUM_ITERATIONS; i++) {
        if (gc < ge) {
            b = e;
            e = c;
            ge = gc;
            c = b - ratio * (b - a);
            gc = side * value_at(t, sf, c);
        } else {
            a = c;
            c = e;
            gc = ge;
            e = a + ratio * (b - a);
            ge = side * value_at(t, sf, e);
        }
    }
    *g_min = gc < ge ? gc : ge;
    return gc < ge ? c : e;
}

/* Could the curve over this chord reach the surface although both ends lie on the same side? */
static int may_touch(const struct surface *sf, const struct chord *ch, double ga, double gb, double side)
{
    if (!sf->is_sphere)
        return fmin(fabs(ga), fabs(gb)) <= ch->reach;
    vec3d d = v3_sub(ch->xb, ch->xa), oc = v3_sub(sf->center, ch->xa);
    if (side > 0.0) {
        double dd = v3_dot(d, d), s = dd > 0.0 ? v3_dot(oc, d) / dd : 0.0;
        s = s < 0.0 ? 0.0 : s > 1.0 ? 1.0 : s;
        double closest = v3_len(v3_sub(oc, v3_scale(d, s)));
        return closest <= sf->radius + ch->reach;
    }
    double farthest = fmax(v3_len(oc), v3_len(v3_sub(ch->xb, sf->center)));
    return farthest >= sf->radius - ch->reach;
}

/* First fraction in (ta, tb] where the curve crosses the surface (and, for an object, lands on
 * it), or -1. */
static double first_crossing(const struct tracer *t, const struct surface *sf, enum crossing_role role,
                             const struct chord *ch)
{
    double ga = surface_value(sf, ch->xa), gb = surface_value(sf, ch->xb);
    double side = ga != 0.0 ? (ga > 0.0 ? 1.0 : -1.0) : (gb > 0.0 ? 1.0 : -1.0);
    double roots[2];
    int n = 0;
    if (ga != 0.0 && side * gb <= 0.0) {
        roots[n++] = bisect(t, sf, ch->ta, ch->tb, side);
    } else if (gb != 0.0 && may_touch(sf, ch, ga, gb, side)) {
        double g_min;
        double tm = extremum(t, sf, ch->ta, ch->tb, side, &g_min);
        if (g_min <= 0.0) {
            /* in and out again within one chord: the entry, then the exit */
            roots[n++] = bisect(t, sf, ch->ta, tm, side);
            roots[n++] = bisect(t, sf, tm, ch->tb, -side);
        }
    }
    for (int i = 0; i < n; i++)
        if (role != ROLE_OBJECT || surface_contains(sf, dopri5_dense_x(&t->d, roots[i])))
            return roots[i];
    return -1.0;
}

/* Is the object's bounding sphere within reach of the chord at all? */
static int chord_near(const struct surface *sf, const struct chord *ch)
{
    double half = 0.5 * v3_len(v3_sub(ch->xb, ch->xa));
    return v3_len(v3_sub(sf->center, ch->mid)) <= sf->bound_radius + half + ch->reach;
}

static void emit_samples_until(struct tracer *t, double lambda_end)
{
    if (!t->sample || t->sample_interval <= 0.0)
        return;
    const struct dopri5 *d = &t->d;
    while (t->next_sample <= lambda_end && t->next_sample <= d->lambda_old + d->h_old) {
        vec3d x, v;
        dopri5_dense(d, (t->next_sample - d->lambda_old) / d->h_old, &x, &v);
        t->sample(t->sample_arg, t->next_sample, x, v);
        t->next_sample += t->sample_interval;
    }
}

static void finish(struct tracer *t, struct ref_ray *out, int32_t outcome, vec3d x, vec3d v, double lambda)
{
    const struct render_settings *rs = &t->scene->render;
    out->outcome = outcome;
    out->position = x;
    out->velocity = v;
    /* around a mass the sky is looked up where the light goes at infinity (physics/escape.h) */
    const struct model *m = &t->scene->model;
    vec3d at_infinity;
    const struct model_ops *ops = model_ops_of(m->type);
    if (outcome == DUMP_SKY && ops->direction_at_infinity && ops->direction_at_infinity(m, x, v, &at_infinity))
        out->velocity = v3_scale(at_infinity, v3_len(v));
    out->lambda = lambda;
    out->depth = lambda / (rs->steps_per_segment * rs->step_size);
    out->steps = t->d.steps;
    out->rejected = t->d.rejected;
    double r = v3_len(v3_sub(x, t->scene->model.center));
    out->min_radius = r < out->min_radius ? r : out->min_radius;
    if (t->sample)
        t->sample(t->sample_arg, lambda, x, v);
}

static void finish_at(struct tracer *t, struct ref_ray *out, int32_t outcome, double theta)
{
    vec3d x, v;
    dopri5_dense(&t->d, theta, &x, &v);
    double lambda = t->d.lambda_old + theta * t->d.h_old;
    emit_samples_until(t, lambda);
    if (outcome >= 0) {
        out->hit = x;
        surface_shading(&t->surfaces[outcome], x, &out->normal, out->uv);
    }
    finish(t, out, outcome, x, v, lambda);
}

/* Search the last accepted step chord by chord; finish the ray and return 1 at its first crossing. */
static int search_step(struct tracer *t, struct ref_ray *out)
{
    const struct dopri5 *d = &t->d;
    vec3d centre = t->scene->model.center;
    struct chord ch = {.ta = 0.0, .xa = dopri5_dense_x(d, 0.0)};
    for (int c = 1; c <= SUB_CHORDS; c++) {
        ch.tb = (double)c / SUB_CHORDS;
        ch.xb = dopri5_dense_x(d, ch.tb);
        vec3d curve_mid = dopri5_dense_x(d, 0.5 * (ch.ta + ch.tb));
        ch.mid = v3_scale(v3_add(ch.xa, ch.xb), 0.5);
        /* twice the mid-chord deviation bounds a parabolic bulge; atol covers the interpolant */
        ch.reach = 2.0 * v3_len(v3_sub(curve_mid, ch.mid)) + 10.0 * t->opt->atol;
        double best = INFINITY;
        int best_k = -1;
        for (int k = 0; k < t->n_surfaces; k++) {
            const struct surface *sf = &t->surfaces[k];
            if (t->roles[k] == ROLE_OBJECT && (sf->degenerate || !chord_near(sf, &ch)))
                continue;
            double root = first_crossing(t, sf, t->roles[k], &ch);
            if (root >= 0.0 && root < best) {
                best = root;
                best_k = k;
            }
        }
        /* winding and closest approach count the chord only up to where the ray ends */
        vec3d end = best_k >= 0 ? dopri5_dense_x(d, best) : ch.xb;
        vec3d ra = v3_sub(ch.xa, centre), rb = v3_sub(end, centre);
        out->winding += atan2(v3_len(v3_cross(ra, rb)), v3_dot(ra, rb));
        double rmin = fmin(v3_len(ra), v3_len(rb));
        out->min_radius = rmin < out->min_radius ? rmin : out->min_radius;
        if (best_k >= 0) {
            enum crossing_role role = t->roles[best_k];
            finish_at(t, out, role == ROLE_OBJECT ? best_k : role == ROLE_BOUND ? DUMP_SKY : DUMP_CAPTURED, best);
            return 1;
        }
        ch.ta = ch.tb;
        ch.xa = ch.xb;
    }
    return 0;
}

static void add_sphere(struct tracer *t, enum crossing_role role, vec3d centre, double radius)
{
    struct surface *sf = &t->surfaces[t->n_surfaces];
    *sf = (struct surface){.is_sphere = 1, .center = centre, .radius = radius, .bound_radius = radius};
    t->roles[t->n_surfaces++] = role;
}

/* Flat space is not integrated: one straight segment, exactly as the GPU's flat model. */
static void trace_straight(struct tracer *t, vec3d x0, vec3d v0, struct ref_ray *out)
{
    const struct render_settings *rs = &t->scene->render;
    vec3d dir = v3_normalize(v0), oc = v3_sub(x0, rs->bound_center);
    double b = v3_dot(oc, dir), c = v3_dot(oc, oc) - rs->bound_radius * rs->bound_radius;
    double exit_distance = sqrt(fmax(b * b - c, 0.0)) - b;
    vec3d end = v3_axpy(exit_distance * FLAT_OVERSHOOT, dir, x0);
    double th;
    int k = straight_first_hit(t->scene, x0, end, &th);
    double seg_len = rs->steps_per_segment * rs->step_size;
    t->d.steps = 1;
    if (k < 0) {
        finish(t, out, DUMP_SKY, end, v0, seg_len);
        out->depth = 1.0;
        return;
    }
    vec3d p = v3_add(x0, v3_scale(v3_sub(end, x0), th));
    out->hit = p;
    surface_shading(&t->surfaces[k], straight_rest_point(t->scene, k, x0, end, th), &out->normal, out->uv);
    finish(t, out, k, p, v0, th * seg_len);
    out->depth = th;
}

void ref_trace(const struct scene *s, const struct ref_options *o, vec3d x0, vec3d v0, struct ref_ray *out,
               double sample_interval, ref_sample_fn sample, void *arg)
{
    static const struct ref_ray empty;
    *out = empty;
    out->min_radius = INFINITY;
    struct tracer t = {.scene = s, .opt = o, .sample_interval = sample_interval, .next_sample = sample_interval,
                       .sample = sample, .sample_arg = arg};
    for (int k = 0; k < s->n_objects; k++) {
        surface_init(&t.surfaces[k], &s->objects[k]);
        t.roles[k] = ROLE_OBJECT;
    }
    t.n_surfaces = s->n_objects;
    const struct render_settings *rs = &s->render;
    double capture = model_capture_radius(&s->model);
    vec3d from_bound = v3_sub(x0, rs->bound_center), from_mass = v3_sub(x0, s->model.center);
    /* a ray that starts outside everything it may travel in ends where it starts, as on the GPU */
    if (capture > 0.0 && v3_len(from_mass) <= capture) {
        finish(&t, out, DUMP_CAPTURED, x0, v0, 0.0);
        return;
    }
    if (v3_len(from_bound) >= rs->bound_radius) {
        finish(&t, out, DUMP_SKY, x0, v0, 0.0);
        return;
    }
    if (model_is_straight(&s->model)) {
        trace_straight(&t, x0, v0, out);
        return;
    }
    add_sphere(&t, ROLE_BOUND, rs->bound_center, rs->bound_radius);
    if (capture > 0.0)
        add_sphere(&t, ROLE_CAPTURE, s->model.center, capture);

    /* the GPU's budget (render_path_budget): segments * steps_per_segment steps of a fixed step, or
     * an adaptive ray's path. Exact orbits (method orbit_table) have none: every ray is followed
     * to its end. */
    double lambda_max = rs->method == METHOD_ORBIT_TABLE ? INFINITY : render_path_budget(rs);
    dopri5_init(&t.d, &s->model, o->rtol, o->atol, o->rtol * v3_len(v0), x0, v0, rs->step_size);
    double floor_radius = CENTRE_FLOOR_FRACTION * rs->bound_radius;
    for (;;) {
        long budget = o->max_steps - t.d.steps - t.d.rejected;
        double h_max = fmin(lambda_max - t.d.lambda, centre_step_limit(&t.d, s->model.center, floor_radius));
        if (budget <= 0 || dopri5_step(&t.d, h_max, o->min_step, budget) != 0) {
            finish(&t, out, DUMP_FAILED, v3(t.d.y[0], t.d.y[1], t.d.y[2]), v3(t.d.y[3], t.d.y[4], t.d.y[5]),
                   t.d.lambda);
            return;
        }
        if (search_step(&t, out))
            return;
        emit_samples_until(&t, t.d.lambda);
        if (t.d.lambda >= lambda_max) {
            finish(&t, out, DUMP_UNFINISHED, v3(t.d.y[0], t.d.y[1], t.d.y[2]), v3(t.d.y[3], t.d.y[4], t.d.y[5]),
                   t.d.lambda);
            return;
        }
    }
}

long ref_integrate(const struct model *m, const struct ref_options *o, double length, vec3d *x, vec3d *v)
{
    struct dopri5 d;
    dopri5_init(&d, m, o->rtol, o->atol, o->rtol * v3_len(*v), *x, *v, fmin(length, 1e-3 * length + 1e-3));
    double floor_radius = CENTRE_FLOOR_FRACTION * fmax(v3_len(v3_sub(*x, m->center)), 1.0);
    while (d.lambda < length) {
        long budget = o->max_steps - d.steps - d.rejected;
        double h_max = fmin(length - d.lambda, centre_step_limit(&d, m->center, floor_radius));
        if (budget <= 0 || dopri5_step(&d, h_max, o->min_step, budget) != 0)
            return -1;
    }
    *x = v3(d.y[0], d.y[1], d.y[2]);
    *v = v3(d.y[3], d.y[4], d.y[5]);
    return d.steps;
}
