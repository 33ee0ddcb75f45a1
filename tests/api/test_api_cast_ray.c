/* SPDX-License-Identifier: MIT */
/* C API ray casts with callbacks, and queries while the world changes, against brute force; tree heights. */
#include <impulse2d/impulse2d.h>

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api_test_support.h"
#include "check.h"
#include "ref_shape.h"

/* ---- Small helpers ---------------------------------------------------------------- */

static int compare_ids(const void* a, const void* b) {
    uint64_t x = ((const i2d_shape_id*)a)->bits, y = ((const i2d_shape_id*)b)->bits;
    return x < y ? -1 : (x > y ? 1 : 0);
}

/* ---- The scenes: shapes drawn at random into the reference model (ref_shape.h) ------- */

/* A random filter over four bits, often the default. */
static i2d_filter random_filter(rng* r) {
    i2d_filter f = i2d_default_filter();
    if (rng_int(r, 3) == 0) {
        f.category_bits = UINT64_C(1) << rng_int(r, 4);
        f.mask_bits = rng_int(r, 3) == 0 ? UINT64_MAX : (uint64_t)rng_int(r, 16);
    }
    return f;
}

/* A circle or a box, sizes from 0.1 m to `size` m. */
static bool scene_add_shape(scene* s, rng* r, int body, float size) {
    i2d_filter filter = random_filter(r);
    if (rng_int(r, 2) == 0) {
        i2d_vec2 center = v2(rng_float(r, -1.0f, 1.0f), rng_float(r, -1.0f, 1.0f));
        return scene_add_circle(s, body, filter, center, rng_float(r, 0.1f, size));
    }
    return scene_add_box(s, body, filter, v2(rng_float(r, 0.1f, size), rng_float(r, 0.1f, size)));
}

/* Ray hits are checked to 1e-4 m plus 1e-6 of the ray's length and of its origin's
 * distance from the origin: bodies here move hundreds of metres out. */
static double point_tol(const ray_case* ray) {
    return 1e-4 + 1e-6 * (ray_length(ray) + fabs(ray->ox) + fabs(ray->oy));
}

/* Likewise bounds (scene_refresh). */
static const double k_bounds_relative_tol = 1e-6;

/* ---- Callback logs ---------------------------------------------------------------- */

enum { LOG_MAX = 2400 };
enum { MODE_ALL, MODE_CLIP, MODE_STOP, MODE_IGNORE };

typedef struct ray_log {
    int mode;
    int count;
    i2d_ray_result reports[LOG_MAX]; /* as the callback was called: hit is true */
    float clip;         /* MODE_CLIP, MODE_IGNORE: the fraction last returned (1 at the start) */
    int clip_violations; /* reports beyond the clip */
    uint64_t salt;      /* MODE_IGNORE: which shapes to ignore */
    i2d_shape_id also_ignore;
} ray_log;

/* MODE_IGNORE ignores about a third of the shapes, chosen by id, and also_ignore. */
static bool is_ignored(const ray_log* log, i2d_shape_id shape) {
    if (I2D_ID_EQUALS(shape, log->also_ignore)) {
        return true;
    }
    return ((shape.bits ^ log->salt) * UINT64_C(0x9E3779B97F4A7C15)) >> 62 == 0;
}

static float log_ray(i2d_shape_id shape, i2d_vec2 point, i2d_vec2 normal, float fraction, void* context) {
    ray_log* log = (ray_log*)context;
    if (log->count < LOG_MAX) {
        i2d_ray_result* r = &log->reports[log->count];
        r->shape = shape;
        r->point = point;
        r->normal = normal;
        r->fraction = fraction;
        r->hit = true;
    }
    ++log->count;
    switch (log->mode) {
    case MODE_ALL:
        return 1.0f;
    case MODE_STOP:
        return 0.0f;
    case MODE_IGNORE:
        if (is_ignored(log, shape)) {
            return -1.0f;
        }
        /* fall through */
    default:
        if (!(fraction <= log->clip)) {
            ++log->clip_violations;
        }
        log->clip = fraction;
        return fraction;
    }
}

static void log_reset(ray_log* log, int mode) {
    log->mode = mode;
    log->count = 0;
    log->clip = 1.0f;
    log->clip_violations = 0;
}

/* A reported hit is a shape of the scene, alive, seen by the filter, really on the ray
 * (not clearly missed), entered at the fraction reported, with the right point and normal. */
static int check_report(const scene* s, const ray_case* ray, i2d_query_filter qf, const i2d_ray_result* r,
                        const char* what, int index) {
    int k = find_shape(s, r->shape);
    if (k < 0 || !s->shapes[k].alive) {
        report("%s %d: reported %s shape 0x%llx", what, index, k < 0 ? "an unknown" : "a destroyed",
               (unsigned long long)r->shape.bits);
        return 1;
    }
    const ref_shape* ref = &s->shapes[k];
    if (!filter_passes(ref->filter, qf)) {
        report("%s %d: shape %d reported though the filter excludes it", what, index, k);
        return 1;
    }
    if (!(r->fraction >= 0.0f && r->fraction <= 1.0f)) {
        report("%s %d: fraction %g outside [0, 1]", what, index, r->fraction);
        return 1;
    }
    ray_class c = classify_ray(ref, ray);
    if (c.kind == RAY_MISS) {
        report("%s %d: shape %d (%s at %g, %g) reported at %g but the ray misses it", what, index, k,
               ref->type == I2D_SHAPE_CIRCLE ? "circle" : "box", ref->cx, ref->cy, r->fraction);
        return 1;
    }
    if (c.kind == RAY_HIT) {
        if (fabs(r->fraction - c.t) > FRACTION_TOL) {
            report("%s %d: shape %d reported at fraction %.9g, enters at %.9g", what, index, k, r->fraction, c.t);
            return 1;
        }
        return check_ray_surface(ref, ray, r, point_tol(ray), what, index);
    }
    return 0;
}

static i2d_status cast(const scene* s, const ray_case* ray, i2d_query_filter qf, ray_log* log) {
    return i2d_world_cast_ray(s->world, v2((float)ray->ox, (float)ray->oy), v2((float)ray->dx, (float)ray->dy), qf,
                              log_ray, log);
}

/* ---- Callback semantics on random scenes ------------------------------------------------ */

/* Static, kinematic and dynamic bodies with one to three shapes in [-40, 40]^2, turned at
 * random (moving ones also spin), some destroyed, a few steps without gravity. */
static bool build_random_scene(scene* s, uint64_t seed, int bodies) {
    if (!scene_init(s)) {
        return false;
    }
    rng r = {seed};
    static const i2d_body_type types[3] = {I2D_BODY_STATIC, I2D_BODY_KINEMATIC, I2D_BODY_DYNAMIC};
    for (int i = 0; i < bodies; ++i) {
        i2d_vec2 p = v2(rng_float(&r, -40.0f, 40.0f), rng_float(&r, -40.0f, 40.0f));
        i2d_vec2 v = v2(rng_float(&r, -3.0f, 3.0f), rng_float(&r, -3.0f, 3.0f));
        i2d_rot q = random_rot(&r);
        int b = scene_add_body(s, types[rng_int(&r, 3)], p, q, v);
        int shapes = 1 + rng_int(&r, 3);
        for (int k = 0; k < shapes; ++k) {
            if (!scene_add_shape(s, &r, b, 4.0f)) {
                return false;
            }
        }
        if (!scene_spin(s, b, rng_float(&r, -2.0f, 2.0f))) {
            return false;
        }
    }
    for (int n = 0; n < 15; ++n) {
        scene_destroy_shape(s, rng_int(&r, s->shape_count));
    }
    for (int n = 0; n < 5; ++n) {
        scene_destroy_body(s, rng_int(&r, s->body_count));
    }
    for (int n = 0; n < 3; ++n) {
        if (i2d_world_step(s->world, k_dt, 4) != I2D_OK) {
            return false;
        }
    }
    return true;
}

/* The brute force's view of one ray: the clear hits and the nearest of them, and
 * whether an unclear shape could change the answer. */
typedef struct ray_truth {
    int clear_hits;
    double best;        /* nearest clear hit */
    int best_shape;
    double ambiguous;   /* nearest unclear entry */
    int ambiguous_count;
} ray_truth;

/* skip_ignored: leave out the shapes a MODE_IGNORE log ignores. */
static ray_truth brute_force_ray(const scene* s, const ray_case* ray, i2d_query_filter qf, const ray_log* ignoring) {
    ray_truth t = {0, INFINITY, -1, INFINITY, 0};
    for (int k = 0; k < s->shape_count; ++k) {
        const ref_shape* ref = &s->shapes[k];
        if (!ref->alive || !filter_passes(ref->filter, qf)) {
            continue;
        }
        if (ignoring != NULL && is_ignored(ignoring, ref->id)) {
            continue;
        }
        ray_class c = classify_ray(ref, ray);
        if (c.kind == RAY_HIT) {
            ++t.clear_hits;
            if (c.t < t.best) {
                t.best = c.t;
                t.best_shape = k;
            }
        } else if (c.kind == RAY_AMBIGUOUS) {
            ++t.ambiguous_count;
            t.ambiguous = fmin(t.ambiguous, c.t);
        }
    }
    return t;
}

/* Return 1: every hit shape once, with its fraction, point and normal. */
static int check_visit_all(const scene* s, const ray_case* ray, i2d_query_filter qf, int index, ray_log* log,
                           int* total_hits) {
    static bool seen[MAX_SHAPES];
    log_reset(log, MODE_ALL);
    if (cast(s, ray, qf, log) != I2D_OK) {
        report("ray %d: status %s", index, i2d_status_string(i2d_last_status()));
        return 1;
    }
    int bad = 0;
    memset(seen, 0, sizeof seen);
    for (int i = 0; i < log->count && i < LOG_MAX; ++i) {
        bad += check_report(s, ray, qf, &log->reports[i], "visit-all ray", index);
        int k = find_shape(s, log->reports[i].shape);
        if (k >= 0) {
            if (seen[k]) {
                ++bad;
                report("visit-all ray %d: shape %d reported twice", index, k);
            }
            seen[k] = true;
        }
    }
    for (int k = 0; k < s->shape_count; ++k) {
        const ref_shape* ref = &s->shapes[k];
        if (ref->alive && !seen[k] && filter_passes(ref->filter, qf) && classify_ray(ref, ray).kind == RAY_HIT) {
            ++bad;
            report("visit-all ray %d from (%g, %g) by (%g, %g): shape %d (%s at %g, %g) is hit at %g but was not "
                   "reported",
                   index, ray->ox, ray->oy, ray->dx, ray->dy, k, ref->type == I2D_SHAPE_CIRCLE ? "circle" : "box",
                   ref->cx, ref->cy, classify_ray(ref, ray).t);
        }
    }
    *total_hits += log->count;
    return bad;
}

/* Return the fraction: the reports never go beyond the clip, and the last one is the
 * closest hit, the same as i2d_world_cast_ray_closest. */
static int check_clip(const scene* s, const ray_case* ray, i2d_query_filter qf, int index, ray_log* log,
                      int* skipped) {
    log_reset(log, MODE_CLIP);
    if (cast(s, ray, qf, log) != I2D_OK) {
        report("clip ray %d: status %s", index, i2d_status_string(i2d_last_status()));
        return 1;
    }
    int bad = 0;
    for (int i = 0; i < log->count && i < LOG_MAX; ++i) {
        bad += check_report(s, ray, qf, &log->reports[i], "clip ray", index);
    }
    if (log->clip_violations != 0) {
        ++bad;
        report("clip ray %d: %d reports beyond the clip returned before", index, log->clip_violations);
    }
    i2d_ray_result closest =
        i2d_world_cast_ray_closest(s->world, v2((float)ray->ox, (float)ray->oy), v2((float)ray->dx, (float)ray->dy), qf);
    if (log->count == 0) {
        if (closest.hit) {
            ++bad;
            report("clip ray %d: no report, cast_ray_closest hits at %g", index, closest.fraction);
        }
    } else {
        const i2d_ray_result* last = &log->reports[log->count - 1];
        if (!closest.hit || !I2D_ID_EQUALS(last->shape, closest.shape) || last->fraction != closest.fraction ||
            fabsf(last->point.x - closest.point.x) > 1e-5f || fabsf(last->point.y - closest.point.y) > 1e-5f ||
            fabsf(last->normal.x - closest.normal.x) > 1e-6f || fabsf(last->normal.y - closest.normal.y) > 1e-6f) {
            ++bad;
            report("clip ray %d: last report (0x%llx at %.9g) differs from cast_ray_closest (%s 0x%llx at %.9g)", index,
                   (unsigned long long)last->shape.bits, last->fraction, closest.hit ? "hit" : "no hit",
                   (unsigned long long)closest.shape.bits, closest.fraction);
        }
    }
    /* And both are the brute force's nearest hit, unless an unclear shape is as near. */
    ray_truth t = brute_force_ray(s, ray, qf, NULL);
    if (t.ambiguous < INFINITY && t.ambiguous <= t.best + 1e-4) {
        ++*skipped;
        return bad;
    }
    if (t.clear_hits == 0) {
        if (log->count != 0) {
            ++bad;
            report("clip ray %d: %d reports, brute force hits nothing", index, log->count);
        }
    } else if (log->count == 0 || fabs(log->reports[log->count - 1].fraction - t.best) > FRACTION_TOL) {
        ++bad;
        report("clip ray %d from (%g, %g) by (%g, %g): ends at %g, brute force nearest %.9g (shape %d)", index, ray->ox,
               ray->oy, ray->dx, ray->dy, log->count > 0 ? log->reports[log->count - 1].fraction : -1.0f, t.best,
               t.best_shape);
    }
    return bad;
}

/* Return 0: the cast stops after the first report. */
static int check_stop(const scene* s, const ray_case* ray, i2d_query_filter qf, int index, ray_log* log) {
    log_reset(log, MODE_STOP);
    if (cast(s, ray, qf, log) != I2D_OK) {
        report("stop ray %d: status %s", index, i2d_status_string(i2d_last_status()));
        return 1;
    }
    ray_truth t = brute_force_ray(s, ray, qf, NULL);
    int bad = 0;
    if (log->count > 1) {
        ++bad;
        report("stop ray %d: %d reports after returning 0", index, log->count);
    } else if (log->count == 1) {
        bad += check_report(s, ray, qf, &log->reports[0], "stop ray", index);
    }
    if (t.clear_hits > 0 && log->count != 1) {
        ++bad;
        report("stop ray %d: %d reports, brute force hits %d shapes", index, log->count, t.clear_hits);
    }
    if (t.clear_hits == 0 && t.ambiguous_count == 0 && log->count != 0) {
        ++bad;
        report("stop ray %d: %d reports, brute force hits nothing", index, log->count);
    }
    return bad;
}

/* Return -1 for some shapes (among them the nearest hit), the fraction for the others:
 * ignored shapes do not clip; the last report is the nearest shape not ignored. */
static int check_ignore(const scene* s, const ray_case* ray, i2d_query_filter qf, int index, ray_log* log,
                        uint64_t salt, int* skipped, int* ignored_nearer) {
    ray_truth all = brute_force_ray(s, ray, qf, NULL);
    log_reset(log, MODE_IGNORE);
    log->salt = salt;
    log->also_ignore = all.best_shape >= 0 ? s->shapes[all.best_shape].id : I2D_NULL_SHAPE_ID;
    if (cast(s, ray, qf, log) != I2D_OK) {
        report("ignore ray %d: status %s", index, i2d_status_string(i2d_last_status()));
        return 1;
    }
    int bad = 0;
    for (int i = 0; i < log->count && i < LOG_MAX; ++i) {
        bad += check_report(s, ray, qf, &log->reports[i], "ignore ray", index);
    }
    if (log->clip_violations != 0) {
        ++bad;
        report("ignore ray %d: %d reports beyond the clip", index, log->clip_violations);
    }
    ray_truth kept = brute_force_ray(s, ray, qf, log);
    if (kept.ambiguous < INFINITY && kept.ambiguous <= kept.best + 1e-4) {
        ++*skipped;
        return bad;
    }
    /* The last report that was not ignored. */
    int last = -1;
    for (int i = 0; i < log->count && i < LOG_MAX; ++i) {
        if (!is_ignored(log, log->reports[i].shape)) {
            last = i;
        }
    }
    if (kept.clear_hits == 0) {
        if (last >= 0) {
            ++bad;
            report("ignore ray %d: a kept shape reported, brute force hits none", index);
        }
        return bad;
    }
    *ignored_nearer += all.best < kept.best ? 1 : 0;
    if (last < 0 || fabs(log->reports[last].fraction - kept.best) > FRACTION_TOL) {
        ++bad;
        report("ignore ray %d from (%g, %g) by (%g, %g): nearest kept report at %g, brute force %.9g (ignored nearest "
               "%.9g)",
               index, ray->ox, ray->oy, ray->dx, ray->dy, last >= 0 ? log->reports[last].fraction : -1.0f, kept.best,
               all.best);
    }
    return bad;
}

static void run_callback_semantics(scene* s, uint64_t seed) {
    static ray_log log;
    rng r = {seed};
    g_reports_left = 25;
    int bad = scene_refresh(s, k_bounds_relative_tol);
    enum { RAYS = 300 };
    int total_hits = 0, skipped = 0, ignore_skipped = 0, ignored_nearer = 0;
    for (int i = 0; i < RAYS; ++i) {
        i2d_query_filter qf = random_query_filter(&r);
        ray_case ray = random_ray(s, &r, -50.0f, 50.0f);
        bad += check_visit_all(s, &ray, qf, i, &log, &total_hits);
        bad += check_clip(s, &ray, qf, i, &log, &skipped);
        bad += check_stop(s, &ray, qf, i, &log);
        bad += check_ignore(s, &ray, qf, i, &log, rng_next(&r), &ignore_skipped, &ignored_nearer);
    }
    printf("cast_ray: %d shapes, %d rays, %d hits reported; %d clip and %d ignore rays skipped as grazing; %d rays "
           "with an ignored nearer shape\n",
           alive_shape_count(s), RAYS, total_hits, skipped, ignore_skipped, ignored_nearer);
    I2D_CHECK(bad == 0);
    /* Dense enough to mean something: several hits per ray on average. */
    I2D_CHECK(total_hits >= 2 * RAYS);
    I2D_CHECK(skipped <= RAYS / 10);
    I2D_CHECK(ignored_nearer >= RAYS / 4);
}

I2D_TEST(api_cast_ray_callback_random) {
    static scene s;
    if (build_random_scene(&s, 0xCA57u, 150)) {
        run_callback_semantics(&s, 0x5EEDu);
    } else {
        I2D_CHECK(!"build_random_scene");
    }
    scene_destroy(&s);
}

/* ---- Exact cases ----------------------------------------------------------------------- */

/* Returns -1 for the shapes in `ignored`, and for the others the fraction (clip_others)
 * or 1; remembers the last shape not ignored. */
typedef struct ignoring {
    i2d_shape_id ignored[2];
    bool clip_others;
    int calls, kept_calls;
    i2d_shape_id last_kept;
    float last_kept_fraction;
} ignoring;

static float ignore_some(i2d_shape_id shape, i2d_vec2 point, i2d_vec2 normal, float fraction, void* context) {
    ignoring* ig = (ignoring*)context;
    (void)point;
    (void)normal;
    ++ig->calls;
    if (I2D_ID_EQUALS(shape, ig->ignored[0]) || I2D_ID_EQUALS(shape, ig->ignored[1])) {
        return -1.0f;
    }
    ++ig->kept_calls;
    ig->last_kept = shape;
    ig->last_kept_fraction = fraction;
    return ig->clip_others ? fraction : 1.0f;
}

/* Five unit circles on the x axis at x = 4, 8, 12, 16, 20; rays from the origin along +x. */
static void run_row_cases(i2d_world_id world) {
    i2d_shape_id discs[5];
    i2d_body_def def = i2d_default_body_def();
    i2d_shape_def shape_def = i2d_default_shape_def();
    for (int i = 0; i < 5; ++i) {
        def.position = v2(4.0f * (float)(i + 1), 0.0f);
        i2d_body_id b = i2d_body_create(world, &def);
        i2d_circle c = {{0.0f, 0.0f}, 1.0f};
        discs[i] = i2d_shape_create_circle(b, &shape_def, &c);
        I2D_REQUIRE(!I2D_IS_NULL(discs[i]));
    }
    static ray_log log;
    const i2d_query_filter all = i2d_default_query_filter();
    const i2d_vec2 origin = v2(0.0f, 0.0f), along = v2(25.0f, 0.0f);

    /* 1: all five, each at (4 (i + 1) - 1) / 25, normal (-1, 0). */
    log_reset(&log, MODE_ALL);
    I2D_CHECK_STATUS(i2d_world_cast_ray(world, origin, along, all, log_ray, &log), I2D_OK);
    I2D_CHECK(log.count == 5);
    for (int i = 0; i < log.count && i < 5; ++i) {
        int which = -1;
        for (int k = 0; k < 5; ++k) {
            which = I2D_ID_EQUALS(log.reports[i].shape, discs[k]) ? k : which;
        }
        I2D_REQUIRE(which >= 0);
        I2D_CHECK_NEAR(log.reports[i].fraction, (4.0 * (which + 1) - 1.0) / 25.0, 1e-6);
        I2D_CHECK_NEAR(log.reports[i].point.x, 4.0 * (which + 1) - 1.0, 1e-5);
        I2D_CHECK_NEAR(log.reports[i].normal.x, -1.0, 1e-6);
        I2D_CHECK_NEAR(log.reports[i].normal.y, 0.0, 1e-6);
    }

    /* Clip: ends on the first disc. */
    log_reset(&log, MODE_CLIP);
    I2D_CHECK_STATUS(i2d_world_cast_ray(world, origin, along, all, log_ray, &log), I2D_OK);
    I2D_REQUIRE(log.count >= 1);
    I2D_CHECK(I2D_ID_EQUALS(log.reports[log.count - 1].shape, discs[0]));
    I2D_CHECK_NEAR(log.reports[log.count - 1].fraction, 3.0 / 25.0, 1e-6);
    I2D_CHECK(log.clip_violations == 0);

    /* 0: one report. */
    log_reset(&log, MODE_STOP);
    I2D_CHECK_STATUS(i2d_world_cast_ray(world, origin, along, all, log_ray, &log), I2D_OK);
    I2D_CHECK(log.count == 1);

    /* -1 for the first two, clip otherwise: ends on the third, whatever the order. */
    ignoring ig;
    memset(&ig, 0, sizeof ig);
    ig.ignored[0] = discs[0];
    ig.ignored[1] = discs[1];
    ig.clip_others = true;
    I2D_CHECK_STATUS(i2d_world_cast_ray(world, origin, along, all, ignore_some, &ig), I2D_OK);
    I2D_CHECK(I2D_ID_EQUALS(ig.last_kept, discs[2]));
    I2D_CHECK_NEAR(ig.last_kept_fraction, 11.0 / 25.0, 1e-6);
    /* -1 for one disc (each in turn, whatever order the cast visits them in), 1 for the
     * others: -1 neither stops nor clips, so all five are reported. */
    for (int k = 0; k < 10; ++k) {
        /* Both ways along the row, so that some cast meets the ignored disc first. */
        const bool back = k >= 5;
        memset(&ig, 0, sizeof ig);
        ig.ignored[0] = discs[k % 5];
        I2D_CHECK_STATUS(i2d_world_cast_ray(world, back ? v2(24.0f, 0.0f) : origin, back ? v2(-25.0f, 0.0f) : along,
                                            all, ignore_some, &ig),
                         I2D_OK);
        I2D_CHECK(ig.calls == 5);
        I2D_CHECK(ig.kept_calls == 4);
    }

    /* A ray that starts inside disc 0 does not report it. */
    log_reset(&log, MODE_ALL);
    I2D_CHECK_STATUS(i2d_world_cast_ray(world, v2(4.0f, 0.0f), v2(21.0f, 0.0f), all, log_ray, &log), I2D_OK);
    I2D_CHECK(log.count == 4);
    for (int i = 0; i < log.count && i < LOG_MAX; ++i) {
        I2D_CHECK(!I2D_ID_EQUALS(log.reports[i].shape, discs[0]));
    }
    /* Zero translation and a ray that misses: no report. */
    log_reset(&log, MODE_ALL);
    I2D_CHECK_STATUS(i2d_world_cast_ray(world, origin, v2(0.0f, 0.0f), all, log_ray, &log), I2D_OK);
    I2D_CHECK(log.count == 0);
    I2D_CHECK_STATUS(i2d_world_cast_ray(world, v2(0.0f, 2.0f), along, all, log_ray, &log), I2D_OK);
    I2D_CHECK(log.count == 0);
    /* A query filter that sees nothing. */
    I2D_CHECK_STATUS(i2d_world_cast_ray(world, origin, along, query_filter(0, UINT64_MAX), log_ray, &log), I2D_OK);
    I2D_CHECK(log.count == 0);
}

I2D_TEST(api_cast_ray_row_cases) { run_in_default_world(run_row_cases); }

/* ---- Refused input and the lock ---------------------------------------------------------- */

typedef struct lock_probe {
    i2d_world_id world;
    i2d_body_id body;
    i2d_shape_id shape;
    int calls;
    int refused;  /* changes refused with WORLD_LOCKED */
    int attempts; /* changes tried */
    int reads_ok;
} lock_probe;

static void expect_locked(lock_probe* p, i2d_status status, const char* what) {
    ++p->attempts;
    if (status == I2D_ERR_WORLD_LOCKED && i2d_last_status() == I2D_ERR_WORLD_LOCKED) {
        ++p->refused;
    } else {
        fprintf(stderr, "%s: %s inside a ray callback: %s, expected I2D_ERR_WORLD_LOCKED\n", __FILE__, what,
                i2d_status_string(status));
    }
}

static float probe_ray(i2d_shape_id shape, i2d_vec2 point, i2d_vec2 normal, float fraction, void* context) {
    lock_probe* p = (lock_probe*)context;
    (void)point;
    (void)normal;
    ++p->calls;
    if (p->calls > 1) {
        return 1.0f;
    }
    i2d_body_def body_def = i2d_default_body_def();
    i2d_shape_def shape_def = i2d_default_shape_def();
    i2d_circle circle = {{0.0f, 0.0f}, 0.5f};
    i2d_body_id created = i2d_body_create(p->world, &body_def);
    expect_locked(p, I2D_IS_NULL(created) ? i2d_last_status() : I2D_OK, "i2d_body_create");
    i2d_shape_id shape_created = i2d_shape_create_circle(p->body, &shape_def, &circle);
    expect_locked(p, I2D_IS_NULL(shape_created) ? i2d_last_status() : I2D_OK, "i2d_shape_create_circle");
    shape_created = i2d_shape_create_box(p->body, &shape_def, 1.0f, 1.0f);
    expect_locked(p, I2D_IS_NULL(shape_created) ? i2d_last_status() : I2D_OK, "i2d_shape_create_box");
    expect_locked(p, i2d_shape_destroy(shape), "i2d_shape_destroy");
    expect_locked(p, i2d_body_destroy(p->body), "i2d_body_destroy");
    expect_locked(p, i2d_body_set_transform(p->body, v2(50.0f, 50.0f), identity_rot()), "i2d_body_set_transform");
    expect_locked(p, i2d_shape_set_filter(shape, i2d_default_filter()), "i2d_shape_set_filter");
    expect_locked(p, i2d_world_step(p->world, k_dt, 4), "i2d_world_step");
    expect_locked(p, i2d_world_rebuild_static_tree(p->world), "i2d_world_rebuild_static_tree");
    expect_locked(p, i2d_world_set_gravity(p->world, v2(0.0f, 5.0f)), "i2d_world_set_gravity");
    expect_locked(p, i2d_world_destroy(p->world), "i2d_world_destroy");
    /* Reads and nested queries work. */
    i2d_vec2 pos = i2d_body_get_position(p->body);
    p->reads_ok += i2d_last_status() == I2D_OK && pos.x == 10.0f ? 1 : 0;
    i2d_ray_result r = i2d_world_cast_ray_closest(p->world, v2(0.0f, 0.0f), v2(20.0f, 0.0f), i2d_default_query_filter());
    p->reads_ok += i2d_last_status() == I2D_OK && r.hit ? 1 : 0;
    i2d_contact_events e = i2d_world_get_contact_events(p->world);
    p->reads_ok += i2d_last_status() == I2D_OK && e.begin_count >= 0 ? 1 : 0;
    return fraction;
}

static void run_lock(i2d_world_id world) {
    i2d_body_def def = i2d_default_body_def();
    def.position = v2(10.0f, 0.0f);
    i2d_body_id body = i2d_body_create(world, &def);
    i2d_shape_def shape_def = i2d_default_shape_def();
    i2d_shape_id shape = i2d_shape_create_box(body, &shape_def, 1.0f, 1.0f);
    I2D_REQUIRE(!I2D_IS_NULL(shape));
    I2D_REQUIRE(i2d_world_step(world, k_dt, 4) == I2D_OK);
    i2d_world_counters before = i2d_world_get_counters(world);

    lock_probe p;
    memset(&p, 0, sizeof p);
    p.world = world;
    p.body = body;
    p.shape = shape;
    I2D_CHECK_STATUS(i2d_world_cast_ray(world, v2(0.0f, 0.0f), v2(20.0f, 0.0f), i2d_default_query_filter(), probe_ray,
                                        &p),
                     I2D_OK);
    I2D_CHECK(p.calls == 1);
    I2D_CHECK(p.attempts == 11 && p.refused == p.attempts);
    I2D_CHECK(p.reads_ok == 3);

    /* Nothing changed. */
    I2D_CHECK(i2d_world_is_valid(world));
    I2D_CHECK(i2d_body_is_valid(body) && i2d_shape_is_valid(shape));
    i2d_vec2 pos = i2d_body_get_position(body);
    I2D_CHECK(pos.x == 10.0f && pos.y == 0.0f);
    i2d_world_counters after = i2d_world_get_counters(world);
    I2D_CHECK(after.body_count == before.body_count && after.shape_count == before.shape_count);
    i2d_vec2 g = i2d_world_get_gravity(world);
    I2D_CHECK(g.x == 0.0f && g.y == -10.0f);
    /* And the world is unlocked after the cast. */
    I2D_CHECK_STATUS(i2d_world_step(world, k_dt, 4), I2D_OK);
}

I2D_TEST(api_cast_ray_callback_locked) {
    i2d_world_def def = i2d_default_world_def();
    i2d_world_id world = i2d_world_create(&def);
    I2D_REQUIRE(!I2D_IS_NULL(world));
    run_lock(world);
    if (i2d_world_is_valid(world)) {
        i2d_world_destroy(world);
    }
}

static float count_calls(i2d_shape_id shape, i2d_vec2 point, i2d_vec2 normal, float fraction, void* context) {
    (void)shape;
    (void)point;
    (void)normal;
    ++*(int*)context;
    return fraction;
}

I2D_TEST(api_cast_ray_refused_input) {
    i2d_world_def def = i2d_default_world_def();
    i2d_world_id world = i2d_world_create(&def);
    I2D_REQUIRE(!I2D_IS_NULL(world));
    i2d_body_def body_def = i2d_default_body_def();
    body_def.position = v2(5.0f, 0.0f);
    i2d_body_id body = i2d_body_create(world, &body_def);
    i2d_shape_def shape_def = i2d_default_shape_def();
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_box(body, &shape_def, 1.0f, 1.0f)));
    const i2d_query_filter all = i2d_default_query_filter();
    const i2d_vec2 o = v2(0.0f, 0.0f), d = v2(10.0f, 0.0f);
    int calls = 0;

    I2D_CHECK_STATUS(i2d_world_cast_ray(world, o, d, all, NULL, &calls), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT && i2d_last_error_message()[0] != '\0');
    static const float bad_values[3] = {NAN, INFINITY, -INFINITY};
    for (int i = 0; i < 3; ++i) {
        const float x = bad_values[i];
        I2D_CHECK_STATUS(i2d_world_cast_ray(world, v2(x, 0.0f), d, all, count_calls, &calls), I2D_ERR_INVALID_ARGUMENT);
        I2D_CHECK_STATUS(i2d_world_cast_ray(world, v2(0.0f, x), d, all, count_calls, &calls), I2D_ERR_INVALID_ARGUMENT);
        I2D_CHECK_STATUS(i2d_world_cast_ray(world, o, v2(x, 0.0f), all, count_calls, &calls), I2D_ERR_INVALID_ARGUMENT);
        I2D_CHECK_STATUS(i2d_world_cast_ray(world, o, v2(10.0f, x), all, count_calls, &calls),
                         I2D_ERR_INVALID_ARGUMENT);
    }
    I2D_CHECK(calls == 0);
    I2D_CHECK_STATUS(i2d_world_cast_ray(I2D_NULL_WORLD_ID, o, d, all, count_calls, &calls), I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(calls == 0);
    /* A good call still works (and hits the box once). */
    I2D_CHECK_STATUS(i2d_world_cast_ray(world, o, d, all, count_calls, &calls), I2D_OK);
    I2D_CHECK(calls == 1);
    i2d_world_destroy(world);
    I2D_CHECK_STATUS(i2d_world_cast_ray(world, o, d, all, count_calls, &calls), I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(calls == 1);
}

/* ---- Queries while the world changes -------------------------------------------------- */

/* The region the alive shapes occupy. */
static i2d_aabb scene_extent(const scene* s) {
    double lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
    for (int k = 0; k < s->shape_count; ++k) {
        if (s->shapes[k].alive) {
            lo_x = fmin(lo_x, s->shapes[k].cx);
            lo_y = fmin(lo_y, s->shapes[k].cy);
            hi_x = fmax(hi_x, s->shapes[k].cx);
            hi_y = fmax(hi_y, s->shapes[k].cy);
        }
    }
    if (lo_x > hi_x) {
        return box(-1.0f, -1.0f, 1.0f, 1.0f);
    }
    return box((float)lo_x, (float)lo_y, (float)hi_x, (float)hi_y);
}

typedef struct query_stats {
    int boxes_nonempty, points_nonempty, ray_hits, ray_skipped;
} query_stats;

/* Random AABB, point and closest-ray queries over the scene's current extent. */
static int run_exact_queries(scene* s, rng* r, int queries, query_stats* stats) {
    static id_list list;
    int bad = scene_refresh(s, k_bounds_relative_tol);
    i2d_aabb ext = scene_extent(s);
    /* Near shapes: drawn from around a random alive shape half of the time. */
    for (int i = 0; i < queries; ++i) {
        i2d_query_filter qf = random_query_filter(r);
        float cx, cy;
        int k = rng_int(r, s->shape_count);
        if (rng_int(r, 2) == 0 && s->shapes[k].alive) {
            cx = (float)s->shapes[k].cx + rng_float(r, -3.0f, 3.0f);
            cy = (float)s->shapes[k].cy + rng_float(r, -3.0f, 3.0f);
        } else {
            cx = rng_float(r, ext.min.x, ext.max.x);
            cy = rng_float(r, ext.min.y, ext.max.y);
        }
        float hx = rng_float(r, 0.0f, 6.0f), hy = rng_float(r, 0.0f, 6.0f);
        i2d_aabb q = box(cx - hx, cy - hy, cx + hx, cy + hy);
        list.count = 0;
        if (i2d_world_overlap_aabb(s->world, q, qf, collect, &list) != I2D_OK) {
            ++bad;
            report("aabb query %d: status %s", i, i2d_status_string(i2d_last_status()));
            continue;
        }
        stats->boxes_nonempty += list.count > 0 ? 1 : 0;
        bad += check_reported_set(s, &list, shape_overlaps_aabb, &q, qf, "aabb query", i);

        i2d_vec2 p = v2(cx, cy);
        list.count = 0;
        if (i2d_world_overlap_point(s->world, p, qf, collect, &list) != I2D_OK) {
            ++bad;
            report("point query %d: status %s", i, i2d_status_string(i2d_last_status()));
            continue;
        }
        stats->points_nonempty += list.count > 0 ? 1 : 0;
        bad += check_reported_set(s, &list, shape_contains_point, &p, qf, "point query", i);

        ray_case ray;
        ray.ox = cx;
        ray.oy = cy;
        float angle = rng_float(r, 0.0f, 6.2831853f), length = rng_float(r, 5.0f, 60.0f);
        ray.dx = (float)(length * cos(angle));
        ray.dy = (float)(length * sin(angle));
        ray_truth t = brute_force_ray(s, &ray, qf, NULL);
        if (t.ambiguous < INFINITY && t.ambiguous <= t.best + 1e-4) {
            ++stats->ray_skipped;
            continue;
        }
        i2d_ray_result rr = i2d_world_cast_ray_closest(s->world, v2(cx, cy), v2((float)ray.dx, (float)ray.dy), qf);
        if (t.clear_hits == 0) {
            if (rr.hit) {
                ++bad;
                report("ray %d: hit 0x%llx at %g, brute force hits nothing", i, (unsigned long long)rr.shape.bits,
                       rr.fraction);
            }
            continue;
        }
        ++stats->ray_hits;
        if (!rr.hit) {
            ++bad;
            report("ray %d: no hit, brute force hits shape %d at %g", i, t.best_shape, t.best);
        } else if (fabs(rr.fraction - t.best) > FRACTION_TOL) {
            ++bad;
            report("ray %d: hit at %.9g, brute force nearest %.9g", i, rr.fraction, t.best);
        } else {
            bad += check_report(s, &ray, qf, &rr, "closest ray", i);
        }
    }
    return bad;
}

/* Bodies move far (up to 15 m/s for 6 s) and spin, are teleported farther to new angles,
 * destroyed and created; after each second the queries still agree with brute force. */
static void run_moving_queries(scene* s, uint64_t seed) {
    rng r = {seed};
    g_reports_left = 25;
    static const i2d_body_type types[5] = {I2D_BODY_STATIC, I2D_BODY_STATIC, I2D_BODY_KINEMATIC, I2D_BODY_DYNAMIC,
                                           I2D_BODY_DYNAMIC};
    for (int i = 0; i < 300; ++i) {
        i2d_body_type type = types[rng_int(&r, 5)];
        float speed = type == I2D_BODY_KINEMATIC ? 15.0f : 8.0f;
        i2d_vec2 p = v2(rng_float(&r, -50.0f, 50.0f), rng_float(&r, -50.0f, 50.0f));
        i2d_rot q = random_rot(&r);
        int b = scene_add_body(s, type, p, q, v2(rng_float(&r, -speed, speed), rng_float(&r, -speed, speed)));
        int shapes = 1 + rng_int(&r, 2);
        for (int k = 0; k < shapes; ++k) {
            I2D_REQUIRE(scene_add_shape(s, &r, b, 2.0f));
        }
        I2D_REQUIRE(scene_spin(s, b, rng_float(&r, -3.0f, 3.0f)));
    }
    query_stats stats;
    memset(&stats, 0, sizeof stats);
    int bad = 0;
    for (int round = 0; round < 6; ++round) {
        for (int step = 0; step < 60; ++step) {
            I2D_REQUIRE(i2d_world_step(s->world, k_dt, 4) == I2D_OK);
        }
        bad += run_exact_queries(s, &r, 60, &stats);
        /* Changes between steps, then one step and the queries again. */
        for (int n = 0; n < 8; ++n) {
            scene_destroy_shape(s, rng_int(&r, s->shape_count));
        }
        for (int n = 0; n < 4; ++n) {
            scene_destroy_body(s, rng_int(&r, s->body_count));
        }
        for (int n = 0; n < 10; ++n) {
            int b = rng_int(&r, s->body_count);
            if (s->body_alive[b]) {
                i2d_vec2 to = v2(rng_float(&r, -200.0f, 200.0f), rng_float(&r, -200.0f, 200.0f));
                I2D_CHECK_STATUS(i2d_body_set_transform(s->bodies[b], to, random_rot(&r)), I2D_OK);
            }
        }
        for (int n = 0; n < 12; ++n) {
            i2d_body_type type = types[rng_int(&r, 5)];
            i2d_vec2 p = v2(rng_float(&r, -100.0f, 100.0f), rng_float(&r, -100.0f, 100.0f));
            i2d_rot q = random_rot(&r);
            int b = scene_add_body(s, type, p, q, v2(rng_float(&r, -8.0f, 8.0f), rng_float(&r, -8.0f, 8.0f)));
            I2D_REQUIRE(scene_add_shape(s, &r, b, 2.0f));
        }
        /* Queries right after the changes, before any step: the trees must already know. */
        bad += run_exact_queries(s, &r, 30, &stats);
        I2D_REQUIRE(i2d_world_step(s->world, k_dt, 4) == I2D_OK);
        bad += run_exact_queries(s, &r, 30, &stats);
        I2D_CHECK(i2d_world_get_counters(s->world).shape_count == alive_shape_count(s));
    }
    i2d_aabb ext = scene_extent(s);
    printf("moving queries: %d shapes over (%.0f, %.0f)-(%.0f, %.0f); %d boxes and %d points found shapes, %d rays hit, "
           "%d skipped\n",
           alive_shape_count(s), ext.min.x, ext.min.y, ext.max.x, ext.max.y, stats.boxes_nonempty,
           stats.points_nonempty, stats.ray_hits, stats.ray_skipped);
    I2D_CHECK(bad == 0);
    /* The bodies did spread far, and the queries found things. */
    I2D_CHECK(ext.max.x - ext.min.x > 200.0f);
    I2D_CHECK(stats.boxes_nonempty >= 200);
    I2D_CHECK(stats.points_nonempty >= 40);
    I2D_CHECK(stats.ray_hits >= 150);
    I2D_CHECK(stats.ray_skipped <= 60);
}

I2D_TEST(api_cast_ray_queries_while_moving) {
    static scene s;
    if (scene_init(&s)) {
        run_moving_queries(&s, 0x40E5u);
    } else {
        I2D_CHECK(!"scene_init");
    }
    scene_destroy(&s);
}

/* ---- Rebuilding the static tree ------------------------------------------------------- */

enum { FIXED_QUERIES = 200 };

typedef struct query_answers {
    int aabb_count[FIXED_QUERIES];
    int point_count[FIXED_QUERIES];
    uint64_t aabb_hash[FIXED_QUERIES], point_hash[FIXED_QUERIES], all_hits_hash[FIXED_QUERIES];
    int all_hits_count[FIXED_QUERIES];
    i2d_ray_result closest[FIXED_QUERIES];
} query_answers;

/* An order-free digest of a set of ids. */
static uint64_t set_hash(i2d_shape_id* ids, int n) {
    qsort(ids, (size_t)n, sizeof ids[0], compare_ids);
    uint64_t h = UINT64_C(1469598103934665603);
    for (int i = 0; i < n; ++i) {
        h = (h ^ ids[i].bits) * UINT64_C(1099511628211);
    }
    return h;
}

static void answer_fixed_queries(const scene* s, uint64_t seed, query_answers* a) {
    static id_list list;
    static ray_log log;
    rng r = {seed};
    for (int i = 0; i < FIXED_QUERIES; ++i) {
        float cx = rng_float(&r, -60.0f, 60.0f), cy = rng_float(&r, -60.0f, 60.0f);
        float hx = rng_float(&r, 0.0f, 10.0f), hy = rng_float(&r, 0.0f, 10.0f);
        i2d_query_filter qf = random_query_filter(&r);
        list.count = 0;
        i2d_world_overlap_aabb(s->world, box(cx - hx, cy - hy, cx + hx, cy + hy), qf, collect, &list);
        a->aabb_count[i] = list.count;
        a->aabb_hash[i] = set_hash(list.ids, list.count < MAX_SHAPES ? list.count : MAX_SHAPES);
        list.count = 0;
        i2d_world_overlap_point(s->world, v2(cx, cy), qf, collect, &list);
        a->point_count[i] = list.count;
        a->point_hash[i] = set_hash(list.ids, list.count < MAX_SHAPES ? list.count : MAX_SHAPES);
        float angle = rng_float(&r, 0.0f, 6.2831853f), length = rng_float(&r, 10.0f, 100.0f);
        i2d_vec2 d = v2((float)(length * cos(angle)), (float)(length * sin(angle)));
        a->closest[i] = i2d_world_cast_ray_closest(s->world, v2(cx, cy), d, qf);
        log_reset(&log, MODE_ALL);
        i2d_world_cast_ray(s->world, v2(cx, cy), d, qf, log_ray, &log);
        a->all_hits_count[i] = log.count;
        list.count = 0;
        for (int k = 0; k < log.count && k < LOG_MAX; ++k) {
            list.ids[list.count++] = log.reports[k].shape;
        }
        a->all_hits_hash[i] = set_hash(list.ids, list.count);
    }
}

static int compare_answers(const query_answers* x, const query_answers* y, const char* when) {
    int bad = 0;
    for (int i = 0; i < FIXED_QUERIES; ++i) {
        const i2d_ray_result* a = &x->closest[i];
        const i2d_ray_result* b = &y->closest[i];
        bool same_ray = a->hit == b->hit &&
                        (!a->hit || (I2D_ID_EQUALS(a->shape, b->shape) && a->fraction == b->fraction &&
                                     a->point.x == b->point.x && a->point.y == b->point.y &&
                                     a->normal.x == b->normal.x && a->normal.y == b->normal.y));
        if (x->aabb_count[i] != y->aabb_count[i] || x->aabb_hash[i] != y->aabb_hash[i] ||
            x->point_count[i] != y->point_count[i] || x->point_hash[i] != y->point_hash[i] ||
            x->all_hits_count[i] != y->all_hits_count[i] || x->all_hits_hash[i] != y->all_hits_hash[i] || !same_ray) {
            ++bad;
            report("query %d differs %s: aabb %d/%d, point %d/%d, all hits %d/%d, closest %s", i, when,
                   x->aabb_count[i], y->aabb_count[i], x->point_count[i], y->point_count[i], x->all_hits_count[i],
                   y->all_hits_count[i], same_ray ? "same" : "different");
        }
    }
    return bad;
}

static void run_rebuild(scene* s, uint64_t seed) {
    rng r = {seed};
    g_reports_left = 25;
    /* A large static level, turned pieces, some dynamic bodies at rest among it. */
    for (int i = 0; i < 900; ++i) {
        i2d_vec2 p = v2(rng_float(&r, -60.0f, 60.0f), rng_float(&r, -60.0f, 60.0f));
        int b = scene_add_body(s, I2D_BODY_STATIC, p, random_rot(&r), v2(0.0f, 0.0f));
        I2D_REQUIRE(scene_add_shape(s, &r, b, 2.5f));
    }
    for (int i = 0; i < 100; ++i) {
        i2d_vec2 p = v2(rng_float(&r, -60.0f, 60.0f), rng_float(&r, -60.0f, 60.0f));
        int b = scene_add_body(s, I2D_BODY_DYNAMIC, p, random_rot(&r), v2(0.0f, 0.0f));
        I2D_REQUIRE(scene_add_shape(s, &r, b, 1.0f));
    }
    static query_answers before, after;
    query_stats stats;
    memset(&stats, 0, sizeof stats);

    int bad = run_exact_queries(s, &r, 100, &stats);
    answer_fixed_queries(s, 77, &before);
    I2D_CHECK_STATUS(i2d_world_rebuild_static_tree(s->world), I2D_OK);
    answer_fixed_queries(s, 77, &after);
    bad += compare_answers(&before, &after, "after the first rebuild");
    bad += run_exact_queries(s, &r, 100, &stats);

    /* The rebuilt tree keeps working as the level changes: add and remove statics. */
    for (int i = 0; i < 100; ++i) {
        i2d_vec2 p = v2(rng_float(&r, -60.0f, 60.0f), rng_float(&r, -60.0f, 60.0f));
        int b = scene_add_body(s, I2D_BODY_STATIC, p, random_rot(&r), v2(0.0f, 0.0f));
        I2D_REQUIRE(scene_add_shape(s, &r, b, 2.5f));
    }
    for (int i = 0; i < 80; ++i) {
        int b = rng_int(&r, 900);
        scene_destroy_body(s, b);
    }
    bad += run_exact_queries(s, &r, 100, &stats);
    answer_fixed_queries(s, 78, &before);
    I2D_CHECK_STATUS(i2d_world_rebuild_static_tree(s->world), I2D_OK);
    I2D_CHECK_STATUS(i2d_world_rebuild_static_tree(s->world), I2D_OK); /* twice: the same */
    answer_fixed_queries(s, 78, &after);
    bad += compare_answers(&before, &after, "after the second rebuild");

    /* Stepping after a rebuild: the dynamic bodies push apart, the statics stay. */
    for (int i = 0; i < 30; ++i) {
        I2D_REQUIRE(i2d_world_step(s->world, k_dt, 4) == I2D_OK);
    }
    bad += run_exact_queries(s, &r, 100, &stats);
    printf("rebuild: %d shapes; %d boxes and %d points found shapes, %d rays hit\n", alive_shape_count(s),
           stats.boxes_nonempty, stats.points_nonempty, stats.ray_hits);
    I2D_CHECK(bad == 0);
    I2D_CHECK(stats.boxes_nonempty >= 200);
    I2D_CHECK(stats.ray_hits >= 100);
}

I2D_TEST(api_cast_ray_rebuild_static_tree) {
    static scene s;
    if (scene_init(&s)) {
        run_rebuild(&s, 0x7EEEu);
    } else {
        I2D_CHECK(!"scene_init");
    }
    scene_destroy(&s);
}

/* ---- Tree heights ------------------------------------------------------------------ */

static int height_bound(int n) { return (int)(3.0 * log2((double)n) + 4.0); }

static void check_heights(i2d_world_id world, int statics, int kinematics, int dynamics, const char* when) {
    i2d_world_counters c = i2d_world_get_counters(world);
    printf("tree heights %s: static %d (%d shapes), kinematic %d (%d), dynamic %d (%d)\n", when,
           (int)c.static_tree_height, statics, (int)c.kinematic_tree_height, kinematics, (int)c.dynamic_tree_height,
           dynamics);
    int before = i2d_check_failures;
    I2D_CHECK(c.static_tree_height >= 1 && c.static_tree_height <= height_bound(statics));
    I2D_CHECK(c.kinematic_tree_height >= 1 && c.kinematic_tree_height <= height_bound(kinematics));
    I2D_CHECK(c.dynamic_tree_height >= 1 && c.dynamic_tree_height <= height_bound(dynamics));
    I2D_CHECK(c.shape_count == statics + kinematics + dynamics);
    if (i2d_check_failures != before) {
        fprintf(stderr, "  (tree heights %s; bounds %d, %d, %d)\n", when, height_bound(statics),
                height_bound(kinematics), height_bound(dynamics));
    }
}

static void run_heights(i2d_world_id world) {
    rng r = {0x4EE7u};
    enum { STATICS = 3000, KINEMATICS = 300, DYNAMICS = 1500 };
    i2d_shape_def def = i2d_default_shape_def();
    /* Statics in a sorted sweep, the worst order for an incremental tree without rotations. */
    for (int i = 0; i < STATICS; ++i) {
        i2d_body_def bd = i2d_default_body_def();
        bd.position = v2(-300.0f + 0.2f * (float)i, (float)(i % 7) * 3.0f);
        i2d_body_id b = i2d_body_create(world, &bd);
        I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_box(b, &def, 0.1f, 0.1f)));
    }
    for (int i = 0; i < KINEMATICS; ++i) {
        i2d_body_def bd = i2d_default_body_def();
        bd.type = I2D_BODY_KINEMATIC;
        bd.position = v2(rng_float(&r, -300.0f, 300.0f), rng_float(&r, 50.0f, 100.0f));
        bd.linear_velocity = v2(rng_float(&r, -10.0f, 10.0f), rng_float(&r, -10.0f, 10.0f));
        i2d_body_id b = i2d_body_create(world, &bd);
        I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_box(b, &def, 0.3f, 0.3f)));
    }
    for (int i = 0; i < DYNAMICS; ++i) {
        i2d_body_def bd = i2d_default_body_def();
        bd.type = I2D_BODY_DYNAMIC;
        bd.position = v2(-300.0f + 0.4f * (float)i, 200.0f + (float)(i % 5) * 2.0f);
        bd.linear_velocity = v2(rng_float(&r, -5.0f, 5.0f), rng_float(&r, -5.0f, 5.0f));
        i2d_body_id b = i2d_body_create(world, &bd);
        i2d_circle c = {{0.0f, 0.0f}, 0.15f};
        I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_circle(b, &def, &c)));
    }
    check_heights(world, STATICS, KINEMATICS, DYNAMICS, "after creation");
    for (int i = 0; i < 30; ++i) {
        I2D_REQUIRE(i2d_world_step(world, k_dt, 2) == I2D_OK);
    }
    check_heights(world, STATICS, KINEMATICS, DYNAMICS, "after 30 steps");
    I2D_CHECK_STATUS(i2d_world_rebuild_static_tree(world), I2D_OK);
    check_heights(world, STATICS, KINEMATICS, DYNAMICS, "after rebuilding the static tree");
}

I2D_TEST(api_cast_ray_tree_heights) { run_in_world(0.0f, run_heights); }

/* Bodies made at one spot (a loader that makes them at the origin and places them after,
 * an emitter) share one box: the trees must stay as shallow as for spread bodies, through
 * placing, stepping and destroying, and still find each body where it was placed. */
enum { SPOT_BODIES = 2000, SPOT_COLUMNS = 50 };

static i2d_vec2 spot_place(int i) { return v2(2.0f * (float)(i % SPOT_COLUMNS), 2.0f * (float)(i / SPOT_COLUMNS)); }

static void check_spot_heights(i2d_world_id world, int statics, int dynamics, const char* when) {
    i2d_world_counters c = i2d_world_get_counters(world);
    printf("tree heights, bodies made at one spot, %s: static %d (%d shapes), dynamic %d (%d)\n", when,
           (int)c.static_tree_height, statics, (int)c.dynamic_tree_height, dynamics);
    I2D_CHECK(c.static_tree_height <= height_bound(statics));
    I2D_CHECK(c.dynamic_tree_height <= height_bound(dynamics));
}

static void run_bodies_made_at_one_spot(i2d_world_id world) {
    static i2d_body_id statics[SPOT_BODIES], dynamics[SPOT_BODIES];
    i2d_shape_def def = i2d_default_shape_def();
    def.filter.group_index = -1; /* the dynamic ones never collide with each other */
    for (int i = 0; i < SPOT_BODIES; ++i) {
        i2d_body_def bd = i2d_default_body_def();
        statics[i] = i2d_body_create(world, &bd);
        I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_box(statics[i], &def, 0.5f, 0.5f)));
        bd.type = I2D_BODY_DYNAMIC;
        bd.position = v2(0.0f, -50.0f);
        dynamics[i] = i2d_body_create(world, &bd);
        i2d_circle circle = {{0.0f, 0.0f}, 0.25f};
        I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_circle(dynamics[i], &def, &circle)));
    }
    check_spot_heights(world, SPOT_BODIES, SPOT_BODIES, "as made");
    for (int i = 0; i < SPOT_BODIES; ++i) {
        I2D_CHECK_STATUS(i2d_body_set_transform(statics[i], spot_place(i), i2d_make_rot(0.0f)), I2D_OK);
    }
    check_spot_heights(world, SPOT_BODIES, SPOT_BODIES, "with the static ones placed");
    I2D_REQUIRE(i2d_world_step(world, k_dt, 4) == I2D_OK);
    for (int i = 0; i < SPOT_BODIES; i += 2) {
        i2d_body_destroy(dynamics[i]);
    }
    I2D_REQUIRE(i2d_world_step(world, k_dt, 4) == I2D_OK);
    check_spot_heights(world, SPOT_BODIES, SPOT_BODIES / 2, "after a step, half the dynamic ones destroyed");
    int misplaced = 0;
    for (int i = 0; i < SPOT_BODIES; i += 37) {
        const i2d_vec2 p = spot_place(i);
        const i2d_aabb inside = {{p.x - 0.1f, p.y - 0.1f}, {p.x + 0.1f, p.y + 0.1f}};
        i2d_shape_id found[4];
        const int32_t count = i2d_world_overlap_aabb_ids(world, inside, i2d_default_query_filter(), found, 4);
        misplaced += count == 1 && I2D_ID_EQUALS(i2d_shape_get_body(found[0]), statics[i]) ? 0 : 1;
    }
    I2D_CHECK(misplaced == 0);
}

I2D_TEST(api_cast_ray_bodies_made_at_one_spot_keep_the_trees_shallow) {
    run_in_world(0.0f, run_bodies_made_at_one_spot);
}
