/* SPDX-License-Identifier: MIT */
/* Shape casts, shape overlaps and the array queries (i2d_world_cast_ray_all,
 * i2d_world_overlap_point_ids, i2d_world_overlap_shape_ids) against brute force on random
 * scenes of static circles and axis-aligned boxes, whose distances have closed forms in
 * double precision; and the refused inputs. */
#include <impulse2d/impulse2d.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "api_test_support.h"
#include "check.h"

enum { SHAPES = 120, SAMPLES = 4000, CASES = 150 };

/* A shape as the test placed it: a circle (hy = 0) or an axis-aligned box. */
typedef struct ref {
    i2d_shape_id id;
    double cx, cy;
    double r;      /* circle radius, 0 for boxes */
    double hx, hy; /* box half extents */
    int is_box;
} ref;

typedef struct scene {
    i2d_world_id world;
    ref shapes[SHAPES];
} scene;

/* The query proxy: a disc of radius pr or an axis-aligned box of half extents (px, py). */
typedef struct probe {
    int is_box;
    double pr, px, py;
} probe;

/* Distance from a point to an axis-aligned box (0 inside). */
static double point_box(double x, double y, double cx, double cy, double hx, double hy) {
    double dx = fabs(x - cx) - hx, dy = fabs(y - cy) - hy;
    dx = dx > 0.0 ? dx : 0.0;
    dy = dy > 0.0 ? dy : 0.0;
    return sqrt(dx * dx + dy * dy);
}

/* Gap between the probe centred at (x, y) and the shape: < 0 overlapping. */
static double gap(const probe* p, double x, double y, const ref* s) {
    if (!p->is_box) {
        return s->is_box ? point_box(x, y, s->cx, s->cy, s->hx, s->hy) - p->pr
                         : hypot(x - s->cx, y - s->cy) - s->r - p->pr;
    }
    if (!s->is_box) {
        return point_box(s->cx, s->cy, x, y, p->px, p->py) - s->r;
    }
    /* Two boxes: the Minkowski sum is a box. */
    return point_box(x, y, s->cx, s->cy, s->hx + p->px, s->hy + p->py);
}

static void build_scene(scene* sc, rng* r) {
    i2d_world_def def = i2d_default_world_def();
    sc->world = i2d_world_create(&def);
    i2d_shape_def sd = i2d_default_shape_def();
    for (int i = 0; i < SHAPES; ++i) {
        ref* s = &sc->shapes[i];
        i2d_body_def bd = i2d_default_body_def();
        s->cx = rng_float(r, -20.0f, 20.0f);
        s->cy = rng_float(r, -20.0f, 20.0f);
        bd.position = v2(s->cx, s->cy);
        s->cx = bd.position.x;
        s->cy = bd.position.y;
        i2d_body_id body = i2d_body_create(sc->world, &bd);
        s->is_box = rng_int(r, 2);
        if (s->is_box) {
            s->hx = rng_float(r, 0.1f, 1.5f);
            s->hy = rng_float(r, 0.1f, 1.5f);
            s->r = 0.0;
            s->id = i2d_shape_create_box(body, &sd, (float)s->hx, (float)s->hy);
            s->hx = (float)s->hx;
            s->hy = (float)s->hy;
        } else {
            i2d_circle c;
            c.center = v2(0, 0);
            c.radius = rng_float(r, 0.1f, 1.5f);
            s->r = c.radius;
            s->id = i2d_shape_create_circle(body, &sd, &c);
        }
    }
}

static i2d_shape_proxy make_probe_proxy(const probe* p, double x, double y) {
    if (!p->is_box) {
        i2d_vec2 c = v2(x, y);
        return i2d_make_proxy(&c, 1, (float)p->pr);
    }
    i2d_vec2 corners[4];
    corners[0] = v2(x - p->px, y - p->py);
    corners[1] = v2(x + p->px, y - p->py);
    corners[2] = v2(x + p->px, y + p->py);
    corners[3] = v2(x - p->px, y + p->py);
    return i2d_make_proxy(corners, 4, 0.0f);
}

static int find_shape(const scene* sc, i2d_shape_id id) {
    for (int i = 0; i < SHAPES; ++i) {
        if (I2D_ID_EQUALS(sc->shapes[i].id, id)) {
            return i;
        }
    }
    return -1;
}

/* First fraction at which the probe swept from (x, y) by (dx, dy) touches the shape, by
 * sampling and bisection; -1 when it never does. *clear_miss says whether it stays more
 * than EPS away (misses that are nearly touches are not judged). */
#define EPS 2e-3
static double first_touch(const probe* p, double x, double y, double dx, double dy, const ref* s, int* clear_miss) {
    double closest = 1e30;
    double prev = 0.0;
    for (int k = 0; k <= SAMPLES; ++k) {
        double t = (double)k / SAMPLES;
        double g = gap(p, x + t * dx, y + t * dy, s);
        closest = g < closest ? g : closest;
        if (g <= 0.0) {
            if (k == 0) {
                return 0.0;
            }
            double lo = prev, hi = t;
            for (int i = 0; i < 50; ++i) {
                double mid = 0.5 * (lo + hi);
                if (gap(p, x + mid * dx, y + mid * dy, s) <= 0.0) {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            return hi;
        }
        prev = t;
    }
    *clear_miss = closest > EPS;
    return -1.0;
}

/* A reported fraction is right when it is not later than the first touch (rounding
 * aside) and leaves a gap of at most the cast's 1.25 mm tolerance (plus rounding). */
static int touches_at(const probe* p, double x, double y, double dx, double dy, const ref* s, double reported,
                      double first, double length) {
    const double late = (reported - first) * length;
    const double g = gap(p, x + reported * dx, y + reported * dy, s);
    return late < 1e-4 && g < 1.5e-3;
}

typedef struct hit_list {
    int count;
    i2d_shape_id ids[SHAPES];
    float fractions[SHAPES];
} hit_list;

static float collect_hit(i2d_shape_id shape, i2d_vec2 point, i2d_vec2 normal, float fraction, void* context) {
    hit_list* list = (hit_list*)context;
    (void)point;
    (void)normal;
    if (list->count < SHAPES) {
        list->ids[list->count] = shape;
        list->fractions[list->count] = fraction;
    }
    ++list->count;
    return 1.0f; /* go on unclipped: every hit */
}

static void check_cast(const scene* sc, rng* r, const probe* p) {
    double x = rng_float(r, -22.0f, 22.0f), y = rng_float(r, -22.0f, 22.0f);
    double dx = rng_float(r, -15.0f, 15.0f), dy = rng_float(r, -15.0f, 15.0f);
    double length = hypot(dx, dy);
    i2d_shape_proxy proxy = make_probe_proxy(p, x, y);
    x = 0.0, y = 0.0; /* the proxy's own points carry the position; recompute from them */
    if (!p->is_box) {
        x = proxy.points[0].x, y = proxy.points[0].y;
    } else {
        x = 0.5 * ((double)proxy.points[0].x + proxy.points[2].x);
        y = 0.5 * ((double)proxy.points[0].y + proxy.points[2].y);
    }
    dx = (float)dx, dy = (float)dy;
    i2d_ray_result closest = i2d_world_cast_shape_closest(sc->world, &proxy, v2(dx, dy), i2d_default_query_filter());
    hit_list all = {0};
    I2D_CHECK_STATUS(i2d_world_cast_shape(sc->world, &proxy, v2(dx, dy), i2d_default_query_filter(), collect_hit, &all),
                     I2D_OK);
    double best = 2.0;
    for (int i = 0; i < SHAPES; ++i) {
        int clear_miss = 0;
        double t = first_touch(p, x, y, dx, dy, &sc->shapes[i], &clear_miss);
        best = t >= 0.0 && t < best ? t : best;
        int reported = -1;
        for (int k = 0; k < all.count && k < SHAPES; ++k) {
            reported = I2D_ID_EQUALS(all.ids[k], sc->shapes[i].id) ? k : reported;
        }
        if (t >= 0.0) {
            /* Never late, and stopped within 1.25 mm of touching (a glancing approach
             * covers more path than gap, so the gap is judged, not the fraction). */
            if (reported < 0 || !touches_at(p, x, y, dx, dy, &sc->shapes[i], all.fractions[reported], t, length)) {
                ++i2d_check_failures;
                report("cast: shape %d first touched at %.6f, reported %s %.6f", i,
                       t, reported < 0 ? "nothing" : "", reported < 0 ? 0.0 : all.fractions[reported]);
            }
        } else if (clear_miss && reported >= 0) {
            ++i2d_check_failures;
            report("cast: shape %d is never touched but reported at %.6f", i, all.fractions[reported]);
        }
    }
    if (best <= 1.0) {
        int k0 = find_shape(sc, closest.shape);
        if (!closest.hit || k0 < 0 || !touches_at(p, x, y, dx, dy, &sc->shapes[k0], closest.fraction, best, length)) {
            ++i2d_check_failures;
            report("cast closest: brute force %.6f, library %d %.6f", best, (int)closest.hit, closest.fraction);
        }
        /* The point lies on the hit shape's surface, or inside both it and the probe
         * when the cast starts overlapping (fraction 0); the normal is unit. */
        int k = find_shape(sc, closest.shape);
        if (k >= 0 && closest.hit) {
            const ref* s = &sc->shapes[k];
            const double px = closest.point.x, py = closest.point.y;
            if (closest.fraction == 0.0f) {
                const probe point = {0, 0.0, 0.0, 0.0};
                const double in_probe =
                    p->is_box ? point_box(px, py, x, y, p->px, p->py) : hypot(px - x, py - y) - p->pr;
                I2D_CHECK(gap(&point, px, py, s) < EPS && in_probe < EPS);
            } else {
                double surface = s->is_box ? point_box(px, py, s->cx, s->cy, s->hx, s->hy)
                                           : fabs(hypot(px - s->cx, py - s->cy) - s->r);
                I2D_CHECK(surface < EPS);
            }
            I2D_CHECK_NEAR(hypot(closest.normal.x, closest.normal.y), 1.0, 1e-4);
        }
    }
}

static void check_overlap(const scene* sc, rng* r, const probe* p) {
    double x = rng_float(r, -22.0f, 22.0f), y = rng_float(r, -22.0f, 22.0f);
    i2d_shape_proxy proxy = make_probe_proxy(p, x, y);
    if (!p->is_box) {
        x = proxy.points[0].x, y = proxy.points[0].y;
    } else {
        x = 0.5 * ((double)proxy.points[0].x + proxy.points[2].x);
        y = 0.5 * ((double)proxy.points[0].y + proxy.points[2].y);
    }
    i2d_shape_id ids[SHAPES];
    int total = i2d_world_overlap_shape_ids(sc->world, &proxy, i2d_default_query_filter(), ids, SHAPES);
    I2D_CHECK(total >= 0 && total <= SHAPES);
    for (int i = 0; i < SHAPES; ++i) {
        double g = gap(p, x, y, &sc->shapes[i]);
        int reported = 0;
        for (int k = 0; k < total && k < SHAPES; ++k) {
            reported |= I2D_ID_EQUALS(ids[k], sc->shapes[i].id);
        }
        if ((g < -EPS && !reported) || (g > EPS && reported)) {
            ++i2d_check_failures;
            report("overlap: shape %d gap %.6f, reported %d", i, g, reported);
        }
    }
    /* Truncation: a smaller array gets the first ids and the same total. */
    if (total > 1) {
        i2d_shape_id few[1];
        I2D_CHECK(i2d_world_overlap_shape_ids(sc->world, &proxy, i2d_default_query_filter(), few, 1) == total);
        I2D_CHECK(I2D_ID_EQUALS(few[0], ids[0]));
    }
}

static void check_point_and_ray(const scene* sc, rng* r) {
    probe point = {0, 0.0, 0.0, 0.0};
    double x = rng_float(r, -22.0f, 22.0f), y = rng_float(r, -22.0f, 22.0f);
    i2d_shape_id ids[SHAPES];
    int total = i2d_world_overlap_point_ids(sc->world, v2(x, y), i2d_default_query_filter(), ids, SHAPES);
    I2D_CHECK(total >= 0);
    for (int i = 0; i < SHAPES; ++i) {
        double g = gap(&point, (float)x, (float)y, &sc->shapes[i]);
        int reported = 0;
        for (int k = 0; k < total && k < SHAPES; ++k) {
            reported |= I2D_ID_EQUALS(ids[k], sc->shapes[i].id);
        }
        if ((g < -EPS && !reported) || (g > EPS && reported)) {
            ++i2d_check_failures;
            report("point: shape %d gap %.6f, reported %d", i, g, reported);
        }
    }
    /* A ray is a shape cast of a point: every shape it enters, sorted by fraction. */
    double dx = (float)rng_float(r, -30.0f, 30.0f), dy = (float)rng_float(r, -30.0f, 30.0f);
    double length = hypot(dx, dy);
    i2d_ray_result hits[SHAPES];
    int count = i2d_world_cast_ray_all(sc->world, v2(x, y), v2(dx, dy), i2d_default_query_filter(), hits, SHAPES);
    I2D_CHECK(count >= 0 && count <= SHAPES);
    for (int k = 1; k < count && k < SHAPES; ++k) {
        I2D_CHECK(hits[k - 1].fraction <= hits[k].fraction);
    }
    x = (float)x, y = (float)y;
    for (int i = 0; i < SHAPES; ++i) {
        int clear_miss = 0;
        double t = first_touch(&point, x, y, dx, dy, &sc->shapes[i], &clear_miss);
        int reported = -1;
        for (int k = 0; k < count && k < SHAPES; ++k) {
            reported = I2D_ID_EQUALS(hits[k].shape, sc->shapes[i].id) ? k : reported;
        }
        if (t > 0.0) {
            if (reported < 0 || fabs(hits[reported].fraction - t) * length > EPS) {
                ++i2d_check_failures;
                report("ray all: shape %d entered at %.6f, reported %d", i, t, reported);
            }
        } else if (t < 0.0 && clear_miss && reported >= 0) {
            ++i2d_check_failures;
            report("ray all: shape %d missed but reported", i);
        }
    }
    if (count > 2) {
        i2d_ray_result first[2];
        I2D_CHECK(i2d_world_cast_ray_all(sc->world, v2(x, y), v2(dx, dy), i2d_default_query_filter(), first, 2) ==
                  count);
        I2D_CHECK(I2D_ID_EQUALS(first[0].shape, hits[0].shape) && I2D_ID_EQUALS(first[1].shape, hits[1].shape));
    }
}

I2D_TEST(api_shape_queries_against_brute_force) {
    static scene sc;
    rng r = {1234567};
    g_reports_left = 20;
    build_scene(&sc, &r);
    I2D_REQUIRE(!I2D_IS_NULL(sc.world));
    for (int c = 0; c < CASES; ++c) {
        probe p;
        p.is_box = c % 2;
        p.pr = rng_float(&r, 0.05f, 1.0f);
        p.px = rng_float(&r, 0.05f, 1.0f);
        p.py = rng_float(&r, 0.05f, 1.0f);
        check_cast(&sc, &r, &p);
        check_overlap(&sc, &r, &p);
        check_point_and_ray(&sc, &r);
    }
    i2d_world_destroy(sc.world);
}

/* ---- Refused input: status and message, nothing reported, the world untouched ---- */

static int g_calls;
static i2d_status g_inner_status;

static float count_and_try_to_change(i2d_shape_id shape, i2d_vec2 point, i2d_vec2 normal, float fraction,
                                     void* context) {
    (void)shape, (void)point, (void)normal, (void)fraction;
    ++g_calls;
    /* The world is locked while a query runs: creating a body from here is refused. */
    i2d_body_def bd = i2d_default_body_def();
    i2d_body_id created = i2d_body_create(*(i2d_world_id*)context, &bd);
    g_inner_status = I2D_IS_NULL(created) ? i2d_last_status() : I2D_OK;
    return 1.0f;
}

static bool count_overlap(i2d_shape_id shape, void* context) {
    (void)shape, (void)context;
    ++g_calls;
    return true;
}

I2D_TEST(api_shape_queries_refuse_bad_input) {
    i2d_world_def def = i2d_default_world_def();
    i2d_world_id world = i2d_world_create(&def);
    i2d_body_def bd = i2d_default_body_def();
    i2d_body_id ground = i2d_body_create(world, &bd);
    i2d_shape_def sd = i2d_default_shape_def();
    i2d_shape_create_box(ground, &sd, 5.0f, 0.5f);
    const uint64_t hash = i2d_world_get_state_hash(world);
    const i2d_query_filter all = i2d_default_query_filter();
    i2d_vec2 above = v2(0, 3);
    i2d_shape_proxy ball = i2d_make_proxy(&above, 1, 0.25f);
    I2D_REQUIRE(ball.count == 1);

    /* i2d_make_proxy: NULL, counts, NaN, inf, negative or huge radius. */
    i2d_vec2 bad[2] = {{0.0f, 0.0f}, {NAN, 1.0f}};
    I2D_CHECK(i2d_make_proxy(NULL, 1, 0.1f).count == 0 && i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_make_proxy(&above, 0, 0.1f).count == 0 && i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_make_proxy(&above, 9, 0.1f).count == 0 && i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_make_proxy(bad, 2, 0.1f).count == 0 && i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_make_proxy(&above, 1, -0.1f).count == 0 && i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_make_proxy(&above, 1, INFINITY).count == 0 && i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_make_proxy(&above, 1, 1e6f).count == 0 && i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
    /* Collinear points make a segment, not an error. */
    i2d_vec2 line[3] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {2.0f, 0.0f}};
    I2D_CHECK(i2d_make_proxy(line, 3, 0.0f).count == 2);

    /* Casts: zero, NaN, infinite and huge translations; a proxy of count 0; a NULL fn. */
    g_calls = 0;
    i2d_shape_proxy empty = {0};
    const i2d_vec2 bad_translations[4] = {{0.0f, 0.0f}, {NAN, -1.0f}, {0.0f, -INFINITY}, {0.0f, -1e10f}};
    for (int i = 0; i < 4; ++i) {
        I2D_CHECK_STATUS(i2d_world_cast_shape(world, &ball, bad_translations[i], all, count_and_try_to_change, &world),
                         I2D_ERR_INVALID_ARGUMENT);
        I2D_CHECK(!i2d_world_cast_shape_closest(world, &ball, bad_translations[i], all).hit);
        I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
    }
    I2D_CHECK_STATUS(i2d_world_cast_shape(world, &empty, v2(0, -5), all, count_and_try_to_change, &world),
                     I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK_STATUS(i2d_world_cast_shape(world, NULL, v2(0, -5), all, count_and_try_to_change, &world),
                     I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK_STATUS(i2d_world_cast_shape(world, &ball, v2(0, -5), all, NULL, NULL), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK_STATUS(i2d_world_overlap_shape(world, &empty, all, count_overlap, NULL), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_world_overlap_shape_ids(world, &ball, all, NULL, 4) == -1);
    I2D_CHECK(i2d_world_overlap_shape_ids(world, &ball, all, NULL, -1) == -1);
    I2D_CHECK(i2d_world_overlap_point_ids(world, v2(NAN, 0), all, NULL, 0) == -1);
    I2D_CHECK(i2d_world_cast_ray_all(world, v2(0, 3), v2(0, NAN), all, NULL, 0) == -1);
    I2D_CHECK(g_calls == 0);

    /* A stale world id. */
    i2d_world_def def2 = i2d_default_world_def();
    i2d_world_id gone = i2d_world_create(&def2);
    i2d_world_destroy(gone);
    I2D_CHECK_STATUS(i2d_world_cast_shape(gone, &ball, v2(0, -5), all, count_and_try_to_change, &world),
                     I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(i2d_world_overlap_shape_ids(gone, &ball, all, NULL, 0) == -1);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(i2d_world_cast_ray_all(gone, v2(0, 3), v2(0, -5), all, NULL, 0) == -1);

    /* Good calls work, sizing calls with capacity 0 count, and a callback cannot change
     * the world it is called from. */
    I2D_CHECK(i2d_world_overlap_shape_ids(world, &ball, all, NULL, 0) == 0);
    I2D_CHECK(i2d_world_cast_ray_all(world, v2(0, 3), v2(0, -5), all, NULL, 0) == 1);
    i2d_ray_result down = i2d_world_cast_shape_closest(world, &ball, v2(0, -5), all);
    I2D_CHECK(down.hit);
    /* The ball's bottom (3 - 0.25) meets the top face (0.5) after 2.25 of 5 m. */
    I2D_CHECK_NEAR(down.fraction, 2.25 / 5.0, 1.5e-3 / 5.0);
    I2D_CHECK_NEAR(down.point.y, 0.5, 1e-4);
    I2D_CHECK_NEAR(down.normal.y, 1.0, 1e-5);
    g_calls = 0;
    g_inner_status = I2D_OK;
    I2D_CHECK_STATUS(i2d_world_cast_shape(world, &ball, v2(0, -5), all, count_and_try_to_change, &world), I2D_OK);
    I2D_CHECK(g_calls == 1);
    I2D_CHECK(g_inner_status == I2D_ERR_WORLD_LOCKED);
    I2D_CHECK(i2d_world_get_state_hash(world) == hash);
    I2D_CHECK(i2d_world_get_counters(world).body_count == 1);
    i2d_world_destroy(world);
}

/* ---- Casts that start overlapping: a unit normal and a point from the overlap ------- */

/* Translations from rounding noise to a metre, along a direction none of the exits
 * below takes, so that a normal copied from the translation shows. */
static const float k_overlap_cast_lengths[] = {1e-30f, 1e-6f, 1.0f};
enum { OVERLAP_CAST_LENGTHS = sizeof k_overlap_cast_lengths / sizeof k_overlap_cast_lengths[0] };
static const double k_overlap_cast_dx = 0.6, k_overlap_cast_dy = -0.8;
/* A unit normal and an exit direction agree to float rounding. */
static const double k_overlap_normal_tolerance = 1e-5;
/* A point counts as inside a shape within this of its surface, m. */
static const double k_overlap_inside_tolerance = 1e-5;

typedef bool (*inside_fn)(double x, double y);

typedef struct first_hit {
    int count;
    i2d_vec2 point, normal;
    float fraction;
} first_hit;

static float keep_first_hit(i2d_shape_id shape, i2d_vec2 point, i2d_vec2 normal, float fraction, void* context) {
    first_hit* hit = (first_hit*)context;
    (void)shape;
    if (hit->count++ == 0) {
        hit->point = point;
        hit->normal = normal;
        hit->fraction = fraction;
    }
    return 1.0f;
}

static void check_overlap_hit(const char* call, float cast_length, i2d_vec2 point, i2d_vec2 normal, float fraction,
                              inside_fn in_shape, inside_fn in_proxy, double exit_x, double exit_y) {
    const double length = hypot(normal.x, normal.y);
    const bool ok = fraction == 0.0f && fabs(length - 1.0) <= k_overlap_normal_tolerance &&
                    hypot(normal.x - exit_x, normal.y - exit_y) <= k_overlap_normal_tolerance &&
                    in_shape(point.x, point.y) && in_proxy(point.x, point.y);
    if (!ok) {
        ++i2d_check_failures;
        report("%s, cast %g: fraction %g, normal (%g, %g) (expected (%g, %g)), point (%g, %g) inside shape %d, "
               "proxy %d",
               call, (double)cast_length, (double)fraction, (double)normal.x, (double)normal.y, exit_x, exit_y,
               (double)point.x, (double)point.y, (int)in_shape(point.x, point.y), (int)in_proxy(point.x, point.y));
    }
}

/* The proxy starts inside the world's one shape: both cast calls hit it at fraction 0
 * for every cast length, with the unit normal (exit_x, exit_y) and a point inside both. */
static void check_overlap_casts(i2d_world_id world, const i2d_shape_proxy* proxy, inside_fn in_shape,
                                inside_fn in_proxy, double exit_x, double exit_y) {
    g_reports_left = 12;
    const i2d_query_filter all = i2d_default_query_filter();
    for (int i = 0; i < OVERLAP_CAST_LENGTHS; ++i) {
        const float cast_length = k_overlap_cast_lengths[i];
        const i2d_vec2 t = v2((float)(cast_length * k_overlap_cast_dx), (float)(cast_length * k_overlap_cast_dy));
        const i2d_ray_result closest = i2d_world_cast_shape_closest(world, proxy, t, all);
        I2D_CHECK(i2d_last_status() == I2D_OK && closest.hit);
        check_overlap_hit("i2d_world_cast_shape_closest", cast_length, closest.point, closest.normal,
                          closest.fraction, in_shape, in_proxy, exit_x, exit_y);
        first_hit hit = {0};
        I2D_CHECK_STATUS(i2d_world_cast_shape(world, proxy, t, all, keep_first_hit, &hit), I2D_OK);
        I2D_CHECK(hit.count == 1);
        check_overlap_hit("i2d_world_cast_shape", cast_length, hit.point, hit.normal, hit.fraction, in_shape, in_proxy,
                          exit_x, exit_y);
    }
}

static double distance_to_segment(double x, double y, double ax, double ay, double bx, double by) {
    const double ex = bx - ax, ey = by - ay;
    double t = ((x - ax) * ex + (y - ay) * ey) / (ex * ex + ey * ey);
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    return hypot(x - (ax + t * ex), y - (ay + t * ey));
}

/* A disc at (1.5, 0.2) inside the box [-2, 2] x [-1, 1]: 0.5 m from the right face, 0.8
 * from the top; it leaves soonest by +x. */
static bool in_wide_box(double x, double y) {
    return point_box(x, y, 0.0, 0.0, 2.0, 1.0) <= k_overlap_inside_tolerance;
}
static bool in_small_disc(double x, double y) { return hypot(x - 1.5, y - 0.2) <= 0.25 + k_overlap_inside_tolerance; }

static void run_overlap_disc_in_box(i2d_world_id world) {
    i2d_shape_def sd = i2d_default_shape_def();
    i2d_shape_create_box(make_body(world, I2D_BODY_STATIC, 0.0f, 0.0f), &sd, 2.0f, 1.0f);
    const i2d_vec2 centre = v2(1.5f, 0.2f);
    const i2d_shape_proxy disc = i2d_make_proxy(&centre, 1, 0.25f);
    check_overlap_casts(world, &disc, in_wide_box, in_small_disc, 1.0, 0.0);
}

I2D_TEST(api_shape_cast_overlap_disc_in_box_leaves_by_the_nearest_face) {
    run_in_default_world(run_overlap_disc_in_box);
}

/* The box [0.8, 2.8] x [0.5, 1.5] over the unit box reaches 0.2 m into it along x, 0.5
 * along y: it leaves soonest by +x. */
static bool in_unit_box(double x, double y) {
    return point_box(x, y, 0.0, 0.0, 1.0, 1.0) <= k_overlap_inside_tolerance;
}
static bool in_offset_box(double x, double y) {
    return point_box(x, y, 1.8, 1.0, 1.0, 0.5) <= k_overlap_inside_tolerance;
}

static void run_overlap_box_on_box(i2d_world_id world) {
    i2d_shape_def sd = i2d_default_shape_def();
    i2d_shape_create_box(make_body(world, I2D_BODY_STATIC, 0.0f, 0.0f), &sd, 1.0f, 1.0f);
    const i2d_vec2 corners[4] = {{0.8f, 0.5f}, {2.8f, 0.5f}, {2.8f, 1.5f}, {0.8f, 1.5f}};
    const i2d_shape_proxy box_proxy = i2d_make_proxy(corners, 4, 0.0f);
    check_overlap_casts(world, &box_proxy, in_unit_box, in_offset_box, 1.0, 0.0);
}

I2D_TEST(api_shape_cast_overlap_box_on_box_leaves_along_the_shallower_axis) {
    run_in_default_world(run_overlap_box_on_box);
}

/* A capsule from (0, -0.2) to (0, 0.6), radius 0.1, across the segment from (-1, 0) to
 * (1, 0): 0.3 m up clears it, 0.7 m down, 1.1 m sideways; it leaves soonest by +y. */
static bool on_flat_segment(double x, double y) {
    return distance_to_segment(x, y, -1.0, 0.0, 1.0, 0.0) <= k_overlap_inside_tolerance;
}
static bool in_upright_capsule(double x, double y) {
    return distance_to_segment(x, y, 0.0, -0.2, 0.0, 0.6) <= 0.1 + k_overlap_inside_tolerance;
}

static void run_overlap_capsule_across_segment(i2d_world_id world) {
    i2d_shape_def sd = i2d_default_shape_def();
    i2d_shape_create_segment(make_body(world, I2D_BODY_STATIC, 0.0f, 0.0f), &sd, v2(-1.0f, 0.0f), v2(1.0f, 0.0f));
    const i2d_vec2 ends[2] = {{0.0f, -0.2f}, {0.0f, 0.6f}};
    const i2d_shape_proxy capsule = i2d_make_proxy(ends, 2, 0.1f);
    check_overlap_casts(world, &capsule, on_flat_segment, in_upright_capsule, 0.0, 1.0);
}

I2D_TEST(api_shape_cast_overlap_capsule_across_segment_leaves_the_shorter_way) {
    run_in_default_world(run_overlap_capsule_across_segment);
}

/* Discs on one centre: every way out is as short, and the cast faces back the way it
 * came. */
static bool in_big_disc(double x, double y) { return hypot(x, y) <= 0.5 + k_overlap_inside_tolerance; }
static bool in_centred_disc(double x, double y) { return hypot(x, y) <= 0.25 + k_overlap_inside_tolerance; }

static void run_overlap_coincident_discs(i2d_world_id world) {
    i2d_shape_def sd = i2d_default_shape_def();
    const i2d_circle circle = {{0.0f, 0.0f}, 0.5f};
    i2d_shape_create_circle(make_body(world, I2D_BODY_STATIC, 0.0f, 0.0f), &sd, &circle);
    const i2d_vec2 centre = v2(0.0f, 0.0f);
    const i2d_shape_proxy disc = i2d_make_proxy(&centre, 1, 0.25f);
    check_overlap_casts(world, &disc, in_big_disc, in_centred_disc, -k_overlap_cast_dx, -k_overlap_cast_dy);
}

I2D_TEST(api_shape_cast_overlap_coincident_discs_face_back_along_the_cast) {
    run_in_default_world(run_overlap_coincident_discs);
}
