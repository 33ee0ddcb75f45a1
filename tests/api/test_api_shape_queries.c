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
        /* The point lies on the hit shape's surface, the normal is unit. */
        int k = find_shape(sc, closest.shape);
        if (k >= 0 && closest.hit) {
            const ref* s = &sc->shapes[k];
            double surface = s->is_box ? point_box(closest.point.x, closest.point.y, s->cx, s->cy, s->hx, s->hy)
                                       : fabs(hypot(closest.point.x - s->cx, closest.point.y - s->cy) - s->r);
            I2D_CHECK(surface < EPS);
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
