/* SPDX-License-Identifier: MIT */
/* C API queries against brute force: overlap and ray queries on random scenes, filters, order and edge cases. */
#include <impulse2d/impulse2d.h>

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "api_test_support.h"
#include "check.h"
#include "ref_shape.h"

/* ---- The scene: shapes drawn at random into the reference model (ref_shape.h) ------- */

/* A random filter over four bits, sometimes the default. */
static i2d_filter random_filter(rng* r) {
    i2d_filter f = i2d_default_filter();
    if (rng_int(r, 4) != 0) {
        f.category_bits = UINT64_C(1) << rng_int(r, 4);
        if (rng_int(r, 3) == 0) {
            f.category_bits |= UINT64_C(1) << rng_int(r, 4);
        }
        f.mask_bits = rng_int(r, 3) == 0 ? UINT64_MAX : (uint64_t)rng_int(r, 16);
    }
    f.group_index = rng_int(r, 5) - 2; /* groups matter for contacts, never for queries */
    return f;
}

/* A circle or a box; scene_build checks afterwards that every one was made. */
static void add_random_shape(scene* s, rng* r, int body) {
    i2d_filter filter = random_filter(r);
    if (rng_int(r, 2) == 0) {
        i2d_vec2 center = v2(rng_float(r, -2.0f, 2.0f), rng_float(r, -2.0f, 2.0f));
        scene_add_circle(s, body, filter, center, rng_float(r, 0.1f, 4.0f));
    } else {
        scene_add_box(s, body, filter, v2(rng_float(r, 0.1f, 5.0f), rng_float(r, 0.1f, 5.0f)));
    }
}

/* A few hundred shapes on static, kinematic and dynamic bodies in [-40, 40]^2, turned at
 * random (moving ones also spin), then the kinds of change the broadphase must follow:
 * destroyed shapes and bodies, new filters, teleports to new positions and angles. */
static bool scene_build(scene* s, uint64_t seed) {
    if (!scene_init(s)) {
        return false;
    }
    rng r = {seed};
    static const i2d_body_type types[3] = {I2D_BODY_STATIC, I2D_BODY_KINEMATIC, I2D_BODY_DYNAMIC};
    for (int i = 0; i < 150; ++i) {
        i2d_body_type type = types[rng_int(&r, 3)];
        i2d_vec2 p = v2(rng_float(&r, -40.0f, 40.0f), rng_float(&r, -40.0f, 40.0f));
        i2d_rot q = random_rot(&r);
        i2d_vec2 v = v2(0.0f, 0.0f);
        if (type != I2D_BODY_STATIC) {
            v = v2(rng_float(&r, -3.0f, 3.0f), rng_float(&r, -3.0f, 3.0f));
        }
        int b = scene_add_body(s, type, p, q, v);
        if (b < 0) {
            return false;
        }
        int shapes = 1 + rng_int(&r, 3);
        for (int k = 0; k < shapes; ++k) {
            add_random_shape(s, &r, b);
        }
        if (!scene_spin(s, b, rng_float(&r, -2.0f, 2.0f))) {
            return false;
        }
    }
    for (int k = 0; k < s->shape_count; ++k) {
        if (!s->shapes[k].alive) {
            return false;
        }
    }

    for (int n = 0; n < 15; ++n) { /* destroy shapes */
        scene_destroy_shape(s, rng_int(&r, s->shape_count));
    }
    for (int n = 0; n < 6; ++n) { /* destroy bodies with their shapes */
        scene_destroy_body(s, rng_int(&r, s->body_count));
    }
    for (int n = 0; n < 30; ++n) { /* new filters */
        ref_shape* ref = &s->shapes[rng_int(&r, s->shape_count)];
        i2d_filter f = random_filter(&r);
        if (ref->alive && i2d_shape_set_filter(ref->id, f) == I2D_OK) {
            ref->filter = f;
        }
    }
    for (int n = 0; n < 15; ++n) { /* teleports */
        int b = rng_int(&r, s->body_count);
        i2d_vec2 p = v2(rng_float(&r, -40.0f, 40.0f), rng_float(&r, -40.0f, 40.0f));
        i2d_rot q = random_rot(&r);
        if (s->body_alive[b] && i2d_body_set_transform(s->bodies[b], p, q) != I2D_OK) {
            return false;
        }
    }
    return true;
}

/* ---- Brute force overlap ------------------------------------------------------------ */

/* The exact tests, shape_overlaps_aabb, shape_contains_point and classify(), and the
 * comparison of a reported set, check_reported_set, are in ref_shape.h. */

static bool same_sequence(const i2d_shape_id* a, const i2d_shape_id* b, int n) {
    for (int i = 0; i < n; ++i) {
        if (!I2D_ID_EQUALS(a[i], b[i])) {
            return false;
        }
    }
    return true;
}

/* Room given to the FFI variant, i2d_world_overlap_aabb_ids. */
enum { LIST_MAX = 1024 };

/* One AABB query, through both entry points: brute-force set, repeatable order, the
 * FFI variant's total and partial fill, and a callback that stops after one shape. */
static int check_aabb_query(const scene* s, i2d_aabb q, i2d_query_filter qf, int index, int* nonempty) {
    static id_list first, again, stop;
    static i2d_shape_id ids[LIST_MAX + 1];
    int bad = 0;
    first.count = 0;
    first.limit = 0;
    if (i2d_world_overlap_aabb(s->world, q, qf, collect, &first) != I2D_OK) {
        report("aabb query %d: status %s", index, i2d_status_string(i2d_last_status()));
        return 1;
    }
    *nonempty += first.count > 0 ? 1 : 0;
    bad += check_reported_set(s, &first, shape_overlaps_aabb, &q, qf, "aabb query", index);

    again.count = 0;
    again.limit = 0;
    i2d_world_overlap_aabb(s->world, q, qf, collect, &again);
    if (again.count != first.count || !same_sequence(first.ids, again.ids, first.count)) {
        ++bad;
        report("aabb query %d: repeating the query changed the sequence", index);
    }

    int32_t total = i2d_world_overlap_aabb_ids(s->world, q, qf, ids, LIST_MAX);
    if (total != first.count || !same_sequence(first.ids, ids, first.count)) {
        ++bad;
        report("aabb query %d: overlap_aabb_ids gave %d ids, the callback %d, or another order", index, (int)total,
               first.count);
    }
    total = i2d_world_overlap_aabb_ids(s->world, q, qf, NULL, 0);
    if (total != first.count) {
        ++bad;
        report("aabb query %d: overlap_aabb_ids(NULL, 0) = %d, expected %d", index, (int)total, first.count);
    }
    if (first.count >= 2) {
        int capacity = first.count / 2;
        ids[capacity].bits = UINT64_C(0xdeadbeef);
        total = i2d_world_overlap_aabb_ids(s->world, q, qf, ids, capacity);
        if (total != first.count || !same_sequence(first.ids, ids, capacity) || ids[capacity].bits != 0xdeadbeef) {
            ++bad;
            report("aabb query %d: capacity %d returned %d (expected %d), a different prefix, or wrote past it", index,
                   capacity, (int)total, first.count);
        }
    }
    if (first.count >= 1) {
        stop.count = 0;
        stop.limit = 1;
        i2d_world_overlap_aabb(s->world, q, qf, collect, &stop);
        if (stop.count != 1 || !I2D_ID_EQUALS(stop.ids[0], first.ids[0])) {
            ++bad;
            report("aabb query %d: a callback returning false got %d calls", index, stop.count);
        }
    }
    return bad;
}

static int check_point_query(const scene* s, i2d_vec2 p, i2d_query_filter qf, int index, int* nonempty) {
    static id_list first, again, stop;
    int bad = 0;
    first.count = 0;
    first.limit = 0;
    if (i2d_world_overlap_point(s->world, p, qf, collect, &first) != I2D_OK) {
        report("point query %d: status %s", index, i2d_status_string(i2d_last_status()));
        return 1;
    }
    *nonempty += first.count > 0 ? 1 : 0;
    bad += check_reported_set(s, &first, shape_contains_point, &p, qf, "point query", index);
    again.count = 0;
    again.limit = 0;
    i2d_world_overlap_point(s->world, p, qf, collect, &again);
    if (again.count != first.count || !same_sequence(first.ids, again.ids, first.count)) {
        ++bad;
        report("point query %d: repeating the query changed the sequence", index);
    }
    if (first.count >= 1) {
        stop.count = 0;
        stop.limit = 1;
        i2d_world_overlap_point(s->world, p, qf, collect, &stop);
        if (stop.count != 1 || !I2D_ID_EQUALS(stop.ids[0], first.ids[0])) {
            ++bad;
            report("point query %d: a callback returning false got %d calls", index, stop.count);
        }
    }
    return bad;
}

/* ---- Brute force rays ---------------------------------------------------------------- */

/* FRACTION_TOL, GRAZING_SPREAD, classify_ray and check_ray_surface are in ref_shape.h. */

/* One ray against the brute force. Rays whose answer hinges on a near-tangent or
 * near-boundary case (within EPS) are counted in *skipped and not judged. */
static int check_ray(const scene* s, const ray_case* ray, i2d_query_filter qf, int index, int* skipped, int* hits) {
    double best = INFINITY, ambiguous = INFINITY;
    for (int k = 0; k < s->shape_count; ++k) {
        const ref_shape* ref = &s->shapes[k];
        if (!ref->alive || !filter_passes(ref->filter, qf)) {
            continue;
        }
        ray_class c = classify_ray(ref, ray);
        if (c.kind == RAY_HIT) {
            best = fmin(best, c.t);
        } else if (c.kind == RAY_AMBIGUOUS) {
            ambiguous = fmin(ambiguous, c.t);
        }
    }
    if (ambiguous < INFINITY && ambiguous <= best + 1e-4) {
        ++*skipped;
        return 0;
    }

    i2d_ray_result r = i2d_world_cast_ray_closest(s->world, v2((float)ray->ox, (float)ray->oy),
                                                  v2((float)ray->dx, (float)ray->dy), qf);
    if (i2d_last_status() != I2D_OK) {
        report("ray %d: status %s", index, i2d_status_string(i2d_last_status()));
        return 1;
    }
    if (best == INFINITY) {
        if (r.hit) {
            report("ray %d from (%g, %g) by (%g, %g): hit at %g, brute force hits nothing", index, ray->ox, ray->oy,
                   ray->dx, ray->dy, r.fraction);
            return 1;
        }
        return 0;
    }
    ++*hits;
    if (!r.hit) {
        report("ray %d from (%g, %g) by (%g, %g): no hit, brute force hits at %g", index, ray->ox, ray->oy, ray->dx,
               ray->dy, best);
        return 1;
    }
    int k = find_shape(s, r.shape);
    if (k < 0 || !s->shapes[k].alive || !filter_passes(s->shapes[k].filter, qf)) {
        report("ray %d: hit an unknown, destroyed or filtered-out shape", index);
        return 1;
    }
    int bad = 0;
    if (fabs(r.fraction - best) > FRACTION_TOL) {
        ++bad;
        report("ray %d from (%g, %g) by (%g, %g): fraction %.9g, brute force %.9g", index, ray->ox, ray->oy, ray->dx,
               ray->dy, r.fraction, best);
    }
    /* The shape reported must itself be entered at that fraction (ties may go either way). */
    ray_hit own = ray_shape(&s->shapes[k], 0.0, ray);
    if (!own.hit || fabs(own.t - r.fraction) > FRACTION_TOL) {
        ++bad;
        report("ray %d: the shape reported is entered at %g, not at the fraction %g", index, own.hit ? own.t : -1.0,
               r.fraction);
        return bad;
    }
    /* Points within 1e-4 m plus 1e-6 of the ray's length: the scene stays within 50 m of
     * the origin. */
    return bad + check_ray_surface(&s->shapes[k], ray, &r, 1e-4 + 1e-6 * ray_length(ray), "ray", index);
}

static i2d_aabb random_query_box(rng* r) {
    float cx = rng_float(r, -50.0f, 50.0f), cy = rng_float(r, -50.0f, 50.0f);
    float hx, hy;
    switch (rng_int(r, 10)) {
    case 0: /* a point */
        hx = hy = 0.0f;
        break;
    case 1: /* a segment */
        hx = rng_float(r, 0.0f, 8.0f);
        hy = 0.0f;
        break;
    case 2: /* most of the world */
        hx = rng_float(r, 30.0f, 100.0f);
        hy = rng_float(r, 30.0f, 100.0f);
        break;
    default:
        hx = rng_float(r, 0.0f, 8.0f);
        hy = rng_float(r, 0.0f, 8.0f);
        break;
    }
    return box(cx - hx, cy - hy, cx + hx, cy + hy);
}

/* Hundreds of random AABBs, points and rays against the brute force. */
static void run_random_queries(scene* s, uint64_t seed) {
    rng r = {seed};
    g_reports_left = 20;
    int bad = scene_refresh(s, 0.0); /* bounds within 1e-4 m: the scene stays near the origin */
    I2D_CHECK(alive_shape_count(s) >= 200);

    enum { QUERIES = 400 };
    int nonempty_boxes = 0, nonempty_points = 0, skipped = 0, hits = 0;
    for (int i = 0; i < QUERIES; ++i) {
        i2d_query_filter qf = random_query_filter(&r);
        bad += check_aabb_query(s, random_query_box(&r), qf, i, &nonempty_boxes);
    }
    for (int i = 0; i < QUERIES; ++i) {
        i2d_query_filter qf = random_query_filter(&r);
        i2d_vec2 p = v2(rng_float(&r, -45.0f, 45.0f), rng_float(&r, -45.0f, 45.0f));
        bad += check_point_query(s, p, qf, i, &nonempty_points);
    }
    for (int i = 0; i < QUERIES; ++i) {
        i2d_query_filter qf = random_query_filter(&r);
        ray_case ray = random_ray(s, &r, -50.0f, 50.0f);
        bad += check_ray(s, &ray, qf, i, &skipped, &hits);
    }
    printf("queries: %d shapes; %d/%d boxes and %d/%d points found shapes; %d rays hit, %d skipped as grazing\n",
           alive_shape_count(s), nonempty_boxes, QUERIES, nonempty_points, QUERIES, hits, skipped);
    I2D_CHECK(bad == 0);
    /* The scene is dense enough for the comparisons to mean something. */
    I2D_CHECK(nonempty_boxes >= QUERIES / 3);
    I2D_CHECK(nonempty_points >= QUERIES / 10);
    I2D_CHECK(hits >= QUERIES / 4);
    I2D_CHECK(skipped <= QUERIES / 10);
}

I2D_TEST(api_queries_random_scene) {
    static scene s;
    if (scene_build(&s, 0x1234u)) {
        run_random_queries(&s, 0x5678u);
    } else {
        I2D_CHECK(!"scene_build");
    }
    scene_destroy(&s);
}

/* The same after a few steps without gravity: moved bodies, pushed-apart dynamic ones. */
I2D_TEST(api_queries_random_scene_stepped) {
    static scene s;
    if (scene_build(&s, 0x9abcu)) {
        for (int i = 0; i < 5; ++i) {
            I2D_CHECK_STATUS(i2d_world_step(s.world, 1.0f / 60.0f, 4), I2D_OK);
        }
        run_random_queries(&s, 0xdef0u);
    } else {
        I2D_CHECK(!"scene_build");
    }
    scene_destroy(&s);
}

/* ---- Exact cases ------------------------------------------------------------------------ */

typedef struct small_world {
    i2d_world_id world;
    i2d_shape_id square;   /* box half extents (1, 1) at the origin */
    i2d_shape_id disc;     /* circle radius 1 at (10, 0) */
} small_world;

static bool small_world_build(small_world* w) {
    i2d_world_def world_def = i2d_default_world_def();
    w->world = i2d_world_create(&world_def);
    if (I2D_IS_NULL(w->world)) {
        return false;
    }
    i2d_body_def def = i2d_default_body_def();
    i2d_body_id a = i2d_body_create(w->world, &def);
    def.position = v2(10.0f, 0.0f);
    i2d_body_id b = i2d_body_create(w->world, &def);
    i2d_shape_def shape_def = i2d_default_shape_def();
    w->square = i2d_shape_create_box(a, &shape_def, 1.0f, 1.0f);
    i2d_circle circle = {{0.0f, 0.0f}, 1.0f};
    w->disc = i2d_shape_create_circle(b, &shape_def, &circle);
    return !I2D_IS_NULL(w->square) && !I2D_IS_NULL(w->disc);
}

/* The ids an AABB query reports, through the FFI variant. */
static int query_ids(i2d_world_id world, i2d_aabb q, i2d_query_filter f, i2d_shape_id* out) {
    return (int)i2d_world_overlap_aabb_ids(world, q, f, out, 8);
}

static int query_point(i2d_world_id world, i2d_vec2 p, i2d_query_filter f, id_list* out) {
    out->count = 0;
    out->limit = 0;
    i2d_world_overlap_point(world, p, f, collect, out);
    return out->count;
}

/* Touching counts as overlapping; a bounding box that overlaps is not enough. */
static void run_touching(const small_world* w) {
    const i2d_query_filter all = i2d_default_query_filter();
    i2d_shape_id ids[8];
    static id_list list;
    /* An AABB whose left edge lies on the square's right edge, x = 1. */
    I2D_CHECK(query_ids(w->world, box(1.0f, -0.5f, 2.0f, 0.5f), all, ids) == 1);
    I2D_CHECK(I2D_ID_EQUALS(ids[0], w->square));
    /* Touching only at the corner (1, 1). */
    I2D_CHECK(query_ids(w->world, box(1.0f, 1.0f, 2.0f, 2.0f), all, ids) == 1);
    /* Just apart. */
    I2D_CHECK(query_ids(w->world, box(1.0001f, -0.5f, 2.0f, 0.5f), all, ids) == 0);
    /* An AABB whose left edge touches the disc at (11, 0). */
    I2D_CHECK(query_ids(w->world, box(11.0f, -0.5f, 12.0f, 0.5f), all, ids) == 1);
    I2D_CHECK(I2D_ID_EQUALS(ids[0], w->disc));
    /* Inside the disc's bounding box corner but 0.13 m from the disc. */
    I2D_CHECK(query_ids(w->world, box(10.8f, 0.8f, 11.8f, 1.8f), all, ids) == 0);
    /* A zero-size AABB on the square's edge. */
    I2D_CHECK(query_ids(w->world, box(-1.0f, 0.25f, -1.0f, 0.25f), all, ids) == 1);

    /* Points on the boundary are inside. */
    I2D_CHECK(query_point(w->world, v2(1.0f, 0.5f), all, &list) == 1);
    I2D_CHECK(query_point(w->world, v2(1.0f, 1.0f), all, &list) == 1);
    I2D_CHECK(query_point(w->world, v2(11.0f, 0.0f), all, &list) == 1);
    I2D_CHECK(I2D_ID_EQUALS(list.ids[0], w->disc));
    I2D_CHECK(query_point(w->world, v2(10.0f, 1.0f), all, &list) == 1);
    I2D_CHECK(query_point(w->world, v2(1.0f, 1.0001f), all, &list) == 0);
    I2D_CHECK(query_point(w->world, v2(10.8f, 0.8f), all, &list) == 0); /* in the disc's bounds only */
}

I2D_TEST(api_queries_touching) {
    small_world w;
    if (small_world_build(&w)) {
        run_touching(&w);
    } else {
        I2D_CHECK(!"small_world_build");
    }
    if (!I2D_IS_NULL(w.world)) {
        i2d_world_destroy(w.world);
    }
}

/* Rays: entry fraction and normal, starting inside, too short, zero length. */
static void run_ray_cases(const small_world* w) {
    const i2d_query_filter all = i2d_default_query_filter();
    /* From (-5, 0) to the right: enters the square at x = -1, fraction 0.4. */
    i2d_ray_result r = i2d_world_cast_ray_closest(w->world, v2(-5.0f, 0.0f), v2(10.0f, 0.0f), all);
    I2D_CHECK(r.hit && I2D_ID_EQUALS(r.shape, w->square));
    I2D_CHECK_NEAR(r.fraction, 0.4, 1e-6);
    I2D_CHECK_NEAR(r.point.x, -1.0, 1e-5);
    I2D_CHECK_NEAR(r.normal.x, -1.0, 1e-6);
    I2D_CHECK_NEAR(r.normal.y, 0.0, 1e-6);
    /* From inside the square: the square is not hit, the disc beyond is (x = 9). */
    r = i2d_world_cast_ray_closest(w->world, v2(0.0f, 0.0f), v2(20.0f, 0.0f), all);
    I2D_CHECK(r.hit && I2D_ID_EQUALS(r.shape, w->disc));
    I2D_CHECK_NEAR(r.fraction, 0.45, 1e-6);
    I2D_CHECK_NEAR(r.normal.x, -1.0, 1e-6);
    /* Downwards onto the disc's top (10, 1). */
    r = i2d_world_cast_ray_closest(w->world, v2(10.0f, 5.0f), v2(0.0f, -8.0f), all);
    I2D_CHECK(r.hit && I2D_ID_EQUALS(r.shape, w->disc));
    I2D_CHECK_NEAR(r.fraction, 0.5, 1e-6);
    I2D_CHECK_NEAR(r.point.y, 1.0, 1e-5);
    I2D_CHECK_NEAR(r.normal.y, 1.0, 1e-6);
    /* From inside the disc, nothing beyond. */
    r = i2d_world_cast_ray_closest(w->world, v2(10.0f, 0.0f), v2(20.0f, 0.0f), all);
    I2D_CHECK(!r.hit);
    /* Too short to reach the square (ends at x = -2). */
    r = i2d_world_cast_ray_closest(w->world, v2(-5.0f, 0.0f), v2(3.0f, 0.0f), all);
    I2D_CHECK(!r.hit);
    /* Zero translation hits nothing, outside or inside a shape. */
    r = i2d_world_cast_ray_closest(w->world, v2(-5.0f, 0.0f), v2(0.0f, 0.0f), all);
    I2D_CHECK(!r.hit);
    r = i2d_world_cast_ray_closest(w->world, v2(0.0f, 0.0f), v2(0.0f, 0.0f), all);
    I2D_CHECK(!r.hit);
    /* Pointing away. */
    r = i2d_world_cast_ray_closest(w->world, v2(-5.0f, 0.0f), v2(-10.0f, 0.0f), all);
    I2D_CHECK(!r.hit);
}

I2D_TEST(api_queries_ray_cases) {
    small_world w;
    if (small_world_build(&w)) {
        run_ray_cases(&w);
    } else {
        I2D_CHECK(!"small_world_build");
    }
    if (!I2D_IS_NULL(w.world)) {
        i2d_world_destroy(w.world);
    }
}

/* A static square of half extents (1, 1) turned by 45 degrees at the origin: the diamond
 * |x| + |y| <= sqrt(2). Points, boxes and rays that would give the opposite answer for
 * the unturned square or for the diamond's bounding box. */
static void run_turned_square(i2d_world_id world) {
    const double root2 = 1.41421356237309505;
    i2d_body_def def = i2d_default_body_def();
    def.rotation = i2d_make_rot(0.785398163f);
    i2d_body_id body = i2d_body_create(world, &def);
    i2d_shape_def shape_def = i2d_default_shape_def();
    i2d_shape_id square = i2d_shape_create_box(body, &shape_def, 1.0f, 1.0f);
    I2D_REQUIRE(!I2D_IS_NULL(square));
    const i2d_query_filter all = i2d_default_query_filter();

    i2d_aabb bounds = i2d_shape_get_aabb(square);
    I2D_CHECK_NEAR(bounds.min.x, -root2, 1e-5);
    I2D_CHECK_NEAR(bounds.min.y, -root2, 1e-5);
    I2D_CHECK_NEAR(bounds.max.x, root2, 1e-5);
    I2D_CHECK_NEAR(bounds.max.y, root2, 1e-5);

    static id_list list;
    I2D_CHECK(query_point(world, v2(0.0f, 1.40f), all, &list) == 1); /* near the top corner, inside */
    I2D_CHECK(query_point(world, v2(1.40f, 0.0f), all, &list) == 1);
    I2D_CHECK(query_point(world, v2(0.0f, 1.43f), all, &list) == 0); /* just above the corner */
    I2D_CHECK(query_point(world, v2(0.9f, 0.9f), all, &list) == 0);  /* inside the unturned square */
    I2D_CHECK(query_point(world, v2(0.7f, 0.7f), all, &list) == 1);  /* 1.4 < sqrt(2) */

    i2d_shape_id ids[8];
    /* Inside the diamond's bounds, beyond its edge x + y = sqrt(2). */
    I2D_CHECK(query_ids(world, box(0.8f, 0.8f, 1.0f, 1.0f), all, ids) == 0);
    I2D_CHECK(query_ids(world, box(0.6f, 0.6f, 1.0f, 1.0f), all, ids) == 1);
    /* A thin box across the top corner, and one just above it. */
    I2D_CHECK(query_ids(world, box(-0.5f, 1.40f, 0.5f, 1.41f), all, ids) == 1);
    I2D_CHECK(query_ids(world, box(-0.5f, 1.42f, 0.5f, 1.50f), all, ids) == 0);

    /* From (-5, 0.5) to the right: enters the upper left edge x - y = -sqrt(2) at
     * x = 0.5 - sqrt(2), whose outward normal is (-1, 1) / sqrt(2). */
    i2d_ray_result r = i2d_world_cast_ray_closest(world, v2(-5.0f, 0.5f), v2(10.0f, 0.0f), all);
    I2D_CHECK(r.hit && I2D_ID_EQUALS(r.shape, square));
    I2D_CHECK_NEAR(r.fraction, (5.0 + 0.5 - root2) / 10.0, 1e-6);
    I2D_CHECK_NEAR(r.point.x, 0.5 - root2, 1e-5);
    I2D_CHECK_NEAR(r.point.y, 0.5, 1e-5);
    I2D_CHECK_NEAR(r.normal.x, -1.0 / root2, 1e-5);
    I2D_CHECK_NEAR(r.normal.y, 1.0 / root2, 1e-5);
    /* Above the diamond, where the unturned square would be hit: y = 1.2 enters at
     * x = 1.2 - sqrt(2) instead of -1. */
    r = i2d_world_cast_ray_closest(world, v2(-5.0f, 1.2f), v2(10.0f, 0.0f), all);
    I2D_CHECK(r.hit);
    I2D_CHECK_NEAR(r.point.x, 1.2 - root2, 1e-5);
    /* Past the top corner: nothing. */
    r = i2d_world_cast_ray_closest(world, v2(-5.0f, 1.45f), v2(10.0f, 0.0f), all);
    I2D_CHECK(!r.hit);
}

I2D_TEST(api_queries_turned_square) { run_in_default_world(run_turned_square); }

/* The filter rule on three concentric circles with radii 1, 2, 3:
 *   A: category 1, mask all;  B: category 2, mask 1;  C: category 4, mask 2.
 * A shape is seen when (category & query mask) != 0 and (mask & query category) != 0. */
static void run_filter_rule(i2d_world_id world) {
    i2d_body_def def = i2d_default_body_def();
    i2d_body_id body = i2d_body_create(world, &def);
    static const i2d_filter filters[3] = {{1, UINT64_MAX, 0}, {2, 1, 0}, {4, 2, 0}};
    i2d_shape_id shapes[3];
    for (int i = 0; i < 3; ++i) {
        i2d_shape_def shape_def = i2d_default_shape_def();
        shape_def.filter = filters[i];
        i2d_circle circle = {{0.0f, 0.0f}, (float)(i + 1)};
        shapes[i] = i2d_shape_create_circle(body, &shape_def, &circle);
        I2D_REQUIRE(!I2D_IS_NULL(shapes[i]));
    }
    typedef struct filter_case {
        i2d_query_filter filter;
        bool sees[3];
        int ray_hits; /* index of the shape the ray from (-10, 0) hits first, -1 none */
    } filter_case;
    static const filter_case cases[] = {
        {{1, UINT64_MAX}, {true, true, false}, 1},
        {{2, 4}, {false, false, true}, 2},
        {{3, 6}, {false, true, true}, 2},
        {{0, UINT64_MAX}, {false, false, false}, -1},
        {{UINT64_MAX, 1}, {true, false, false}, 0},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        const filter_case* fc = &cases[c];
        i2d_shape_id ids[8];
        int n = query_ids(world, box(-0.5f, -0.5f, 0.5f, 0.5f), fc->filter, ids);
        static id_list points;
        query_point(world, v2(0.0f, 0.0f), fc->filter, &points);
        int expected = 0;
        for (int i = 0; i < 3; ++i) {
            expected += fc->sees[i] ? 1 : 0;
            bool in_ids = false, in_points = false;
            for (int k = 0; k < n && k < 8; ++k) {
                in_ids = in_ids || I2D_ID_EQUALS(ids[k], shapes[i]);
            }
            for (int k = 0; k < points.count; ++k) {
                in_points = in_points || I2D_ID_EQUALS(points.ids[k], shapes[i]);
            }
            if (in_ids != fc->sees[i] || in_points != fc->sees[i]) {
                ++i2d_check_failures;
                fprintf(stderr, "%s:%d: filter case %d: shape %d seen by aabb %d, point %d, expected %d\n", __FILE__,
                        __LINE__, (int)c, i, in_ids, in_points, fc->sees[i]);
            }
        }
        I2D_CHECK(n == expected && points.count == expected);
        i2d_ray_result r = i2d_world_cast_ray_closest(world, v2(-10.0f, 0.0f), v2(20.0f, 0.0f), fc->filter);
        if (fc->ray_hits < 0) {
            I2D_CHECK(!r.hit);
        } else {
            I2D_CHECK(r.hit && I2D_ID_EQUALS(r.shape, shapes[fc->ray_hits]));
            I2D_CHECK_NEAR(r.fraction, (10.0 - (fc->ray_hits + 1)) / 20.0, 1e-6);
        }
    }
}

/* The default query filter sees every shape, whatever bits the shape's filter uses. */
static void run_default_sees_all(i2d_world_id world) {
    i2d_body_def def = i2d_default_body_def();
    i2d_body_id body = i2d_body_create(world, &def);
    i2d_shape_def shape_def = i2d_default_shape_def();
    shape_def.filter.category_bits = UINT64_C(1) << 63;
    shape_def.filter.mask_bits = UINT64_C(1) << 40;
    i2d_shape_id odd = i2d_shape_create_box(body, &shape_def, 1.0f, 1.0f);
    I2D_REQUIRE(!I2D_IS_NULL(odd));
    i2d_shape_id ids[8];
    I2D_CHECK(query_ids(world, box(-0.5f, -0.5f, 0.5f, 0.5f), i2d_default_query_filter(), ids) == 1);
    I2D_CHECK(I2D_ID_EQUALS(ids[0], odd));
}

I2D_TEST(api_queries_default_filter_sees_all) { run_in_default_world(run_default_sees_all); }

I2D_TEST(api_queries_filter_rule) { run_in_default_world(run_filter_rule); }
