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

/* ---- Small helpers ---------------------------------------------------------------- */

/* Collects the ids a query reports, in order; stops the query after `limit` (0: never). */
enum { LIST_MAX = 1024 };

typedef struct id_list {
    int count;
    int limit;
    i2d_shape_id ids[LIST_MAX];
} id_list;

static bool collect(i2d_shape_id shape, void* context) {
    id_list* list = (id_list*)context;
    if (list->count < LIST_MAX) {
        list->ids[list->count] = shape;
    }
    ++list->count;
    return list->limit == 0 || list->count < list->limit;
}

static bool same_sequence(const i2d_shape_id* a, const i2d_shape_id* b, int n) {
    for (int i = 0; i < n; ++i) {
        if (!I2D_ID_EQUALS(a[i], b[i])) {
            return false;
        }
    }
    return true;
}

/* ---- The reference model: every shape's exact geometry, kept by the test ----------- */

enum { MAX_BODIES = 200, MAX_SHAPES = 600 };

typedef struct scene {
    i2d_world_id world;
    int body_count;
    i2d_body_id bodies[MAX_BODIES];
    bool body_alive[MAX_BODIES];
    int shape_count;
    ref_shape shapes[MAX_SHAPES];
} scene;

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

static i2d_query_filter random_query_filter(rng* r) {
    if (rng_int(r, 2) == 0) {
        return i2d_default_query_filter();
    }
    return query_filter((uint64_t)rng_int(r, 16), rng_int(r, 4) == 0 ? UINT64_MAX : (uint64_t)rng_int(r, 16));
}

static bool filter_passes(i2d_filter shape, i2d_query_filter query) {
    return (shape.category_bits & query.mask_bits) != 0 && (shape.mask_bits & query.category_bits) != 0;
}

static void add_random_shape(scene* s, rng* r, int body) {
    if (s->shape_count >= MAX_SHAPES) {
        return;
    }
    ref_shape* ref = &s->shapes[s->shape_count];
    memset(ref, 0, sizeof *ref);
    ref->body = body;
    ref->filter = random_filter(r);
    i2d_shape_def def = i2d_default_shape_def();
    def.filter = ref->filter;
    if (rng_int(r, 2) == 0) {
        ref->type = I2D_SHAPE_CIRCLE;
        ref->local_center = v2(rng_float(r, -2.0f, 2.0f), rng_float(r, -2.0f, 2.0f));
        ref->radius = rng_float(r, 0.1f, 4.0f);
        i2d_circle circle = {ref->local_center, ref->radius};
        ref->id = i2d_shape_create_circle(s->bodies[body], &def, &circle);
    } else {
        ref->type = I2D_SHAPE_POLYGON;
        ref->half = v2(rng_float(r, 0.1f, 5.0f), rng_float(r, 0.1f, 5.0f));
        ref->id = i2d_shape_create_box(s->bodies[body], &def, ref->half.x, ref->half.y);
    }
    ref->alive = !I2D_IS_NULL(ref->id);
    ++s->shape_count;
}

/* Uniform angle in [-pi, pi): bodies start turned so that rotated boxes are queried from
 * the start, not only after collisions have turned them. */
static i2d_rot random_rot(rng* r) { return i2d_make_rot(rng_float(r, -3.14159265f, 3.14159265f)); }

/* A few hundred shapes on static, kinematic and dynamic bodies in [-40, 40]^2, turned at
 * random (moving ones also spin), then the kinds of change the broadphase must follow:
 * destroyed shapes and bodies, new filters, teleports to new positions and angles. */
static bool scene_build(scene* s, uint64_t seed) {
    memset(s, 0, sizeof *s);
    rng r = {seed};
    i2d_world_def world_def = i2d_default_world_def();
    world_def.gravity = v2(0.0f, 0.0f);
    s->world = i2d_world_create(&world_def);
    if (I2D_IS_NULL(s->world)) {
        return false;
    }
    static const i2d_body_type types[3] = {I2D_BODY_STATIC, I2D_BODY_KINEMATIC, I2D_BODY_DYNAMIC};
    s->body_count = 150;
    for (int b = 0; b < s->body_count; ++b) {
        i2d_body_def def = i2d_default_body_def();
        def.type = types[rng_int(&r, 3)];
        def.position = v2(rng_float(&r, -40.0f, 40.0f), rng_float(&r, -40.0f, 40.0f));
        def.rotation = random_rot(&r);
        if (def.type != I2D_BODY_STATIC) {
            def.linear_velocity = v2(rng_float(&r, -3.0f, 3.0f), rng_float(&r, -3.0f, 3.0f));
        }
        s->bodies[b] = i2d_body_create(s->world, &def);
        if (I2D_IS_NULL(s->bodies[b])) {
            return false;
        }
        s->body_alive[b] = true;
        int shapes = 1 + rng_int(&r, 3);
        for (int k = 0; k < shapes; ++k) {
            add_random_shape(s, &r, b);
        }
        /* A spin set once the shapes give the body its inertia (static bodies ignore it). */
        if (i2d_body_set_angular_velocity(s->bodies[b], rng_float(&r, -2.0f, 2.0f)) != I2D_OK) {
            return false;
        }
    }
    for (int k = 0; k < s->shape_count; ++k) {
        if (!s->shapes[k].alive) {
            return false;
        }
    }

    for (int n = 0; n < 15; ++n) { /* destroy shapes */
        ref_shape* ref = &s->shapes[rng_int(&r, s->shape_count)];
        if (ref->alive && i2d_shape_destroy(ref->id) == I2D_OK) {
            ref->alive = false;
        }
    }
    for (int n = 0; n < 6; ++n) { /* destroy bodies with their shapes */
        int b = rng_int(&r, s->body_count);
        if (s->body_alive[b] && i2d_body_destroy(s->bodies[b]) == I2D_OK) {
            s->body_alive[b] = false;
            for (int k = 0; k < s->shape_count; ++k) {
                if (s->shapes[k].body == b) {
                    s->shapes[k].alive = false;
                }
            }
        }
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

static int alive_shape_count(const scene* s) {
    int n = 0;
    for (int k = 0; k < s->shape_count; ++k) {
        n += s->shapes[k].alive ? 1 : 0;
    }
    return n;
}

/* Reads the bodies' transforms into the model and checks the library's local polygons
 * and tight bounds agree with it, so that the brute force below describes the same
 * shapes the library has. */
static int scene_refresh(scene* s) {
    int bad = 0;
    for (int k = 0; k < s->shape_count; ++k) {
        ref_shape* ref = &s->shapes[k];
        if (!ref->alive) {
            continue;
        }
        i2d_transform xf = i2d_body_get_transform(s->bodies[ref->body]);
        const double c = xf.q.c, sn = xf.q.s;
        if (fabs(c * c + sn * sn - 1.0) > 1e-5) {
            ++bad;
            report("shape %d: body rotation (%g, %g) is not normalised", k, c, sn);
        }
        ref->ux = c;
        ref->uy = sn;
        ref->cx = (double)xf.p.x + c * ref->local_center.x - sn * ref->local_center.y;
        ref->cy = (double)xf.p.y + sn * ref->local_center.x + c * ref->local_center.y;
        double hx, hy; /* half extents of the world bounds */
        if (ref->type == I2D_SHAPE_CIRCLE) {
            hx = hy = ref->radius;
        } else {
            /* The box in its body frame: the corners (+-half.x, +-half.y). */
            i2d_polygon poly = i2d_shape_get_polygon(ref->id);
            bool corners = poly.count == 4 && poly.radius == 0.0f;
            for (int i = 0; i < poly.count && i < 4; ++i) {
                corners = corners && fabs(poly.vertices[i].x) == ref->half.x && fabs(poly.vertices[i].y) == ref->half.y;
            }
            if (!corners) {
                ++bad;
                report("shape %d: i2d_shape_get_polygon is not the box (+-%g, +-%g)", k, ref->half.x, ref->half.y);
            }
            hx = fabs(c) * ref->half.x + fabs(sn) * ref->half.y;
            hy = fabs(sn) * ref->half.x + fabs(c) * ref->half.y;
        }
        i2d_aabb b = i2d_shape_get_aabb(ref->id);
        if (fabs(b.min.x - (ref->cx - hx)) > 1e-4 || fabs(b.min.y - (ref->cy - hy)) > 1e-4 ||
            fabs(b.max.x - (ref->cx + hx)) > 1e-4 || fabs(b.max.y - (ref->cy + hy)) > 1e-4) {
            ++bad;
            report("shape %d: i2d_shape_get_aabb (%g, %g)-(%g, %g), expected (%g, %g)-(%g, %g)", k, b.min.x, b.min.y,
                   b.max.x, b.max.y, ref->cx - hx, ref->cy - hy, ref->cx + hx, ref->cy + hy);
        }
    }
    return bad;
}

static int find_shape(const scene* s, i2d_shape_id id) {
    for (int k = 0; k < s->shape_count; ++k) {
        if (I2D_ID_EQUALS(s->shapes[k].id, id)) {
            return k;
        }
    }
    return -1;
}

/* ---- Brute force overlap ------------------------------------------------------------ */

/* The exact tests, shape_overlaps_aabb, shape_contains_point and classify(), are in
 * ref_shape.h. */

/* Compares what a query reported with the brute force: no unknown, destroyed, filtered
 * out, clearly-outside or repeated shape; no clearly-inside shape left out. */
static int check_reported_set(const scene* s, const i2d_shape_id* ids, int n, overlap_test test, const void* query,
                              i2d_query_filter qf, const char* what, int index) {
    static bool seen[MAX_SHAPES];
    memset(seen, 0, sizeof seen);
    int bad = 0;
    for (int i = 0; i < n; ++i) {
        int k = find_shape(s, ids[i]);
        if (k < 0 || !s->shapes[k].alive) {
            ++bad;
            report("%s %d: reported %s shape (bits 0x%llx)", what, index, k < 0 ? "an unknown" : "a destroyed",
                   (unsigned long long)ids[i].bits);
            continue;
        }
        if (seen[k]) {
            ++bad;
            report("%s %d: shape %d reported twice", what, index, k);
        }
        seen[k] = true;
        if (!filter_passes(s->shapes[k].filter, qf)) {
            ++bad;
            report("%s %d: shape %d reported though the filter excludes it", what, index, k);
        } else if (classify(&s->shapes[k], test, query) == CLEARLY_OUT) {
            ++bad;
            report("%s %d: shape %d reported though it is clearly outside", what, index, k);
        }
    }
    for (int k = 0; k < s->shape_count; ++k) {
        const ref_shape* ref = &s->shapes[k];
        if (ref->alive && !seen[k] && filter_passes(ref->filter, qf) && classify(ref, test, query) == CLEARLY_IN) {
            ++bad;
            report("%s %d: shape %d (%s at %g, %g) overlaps but was not reported", what, index, k,
                   ref->type == I2D_SHAPE_CIRCLE ? "circle" : "box", ref->cx, ref->cy);
        }
    }
    return bad;
}

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
    bad += check_reported_set(s, first.ids, first.count, shape_overlaps_aabb, &q, qf, "aabb query", index);

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
    bad += check_reported_set(s, first.ids, first.count, shape_contains_point, &p, qf, "point query", index);
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

/* The fraction a library working in float may be off by, and the spread between the
 * shape grown and shrunk by EPS above which a hit is too grazing to judge. */
#define FRACTION_TOL 1e-5
#define GRAZING_SPREAD 1e-3

/* Checks the hit's point, and its normal against the exact entry of shape ref. */
static int check_ray_surface(const ref_shape* ref, const ray_case* ray, const i2d_ray_result* r, int index) {
    int bad = 0;
    double length = sqrt(ray->dx * ray->dx + ray->dy * ray->dy);
    double px = ray->ox + r->fraction * ray->dx, py = ray->oy + r->fraction * ray->dy;
    if (fabs(r->point.x - px) > 1e-4 + 1e-6 * length || fabs(r->point.y - py) > 1e-4 + 1e-6 * length) {
        ++bad;
        report("ray %d: point (%g, %g) is not origin + fraction * translation (%g, %g)", index, r->point.x, r->point.y,
               px, py);
    }
    const double tol = 1e-3;
    double dx = r->point.x - ref->cx, dy = r->point.y - ref->cy;
    bool on_surface;
    if (ref->type == I2D_SHAPE_CIRCLE) {
        on_surface = fabs(sqrt(dx * dx + dy * dy) - ref->radius) <= tol;
    } else {
        double lx, ly;
        to_box_frame(ref, dx, dy, &lx, &ly);
        bool inside = fabs(lx) <= ref->half.x + tol && fabs(ly) <= ref->half.y + tol;
        on_surface = inside && (fabs(fabs(lx) - ref->half.x) <= tol || fabs(fabs(ly) - ref->half.y) <= tol);
    }
    if (!on_surface) {
        ++bad;
        report("ray %d: point (%g, %g) is not on the surface of the shape hit", index, r->point.x, r->point.y);
    }

    double n_length = sqrt((double)r->normal.x * r->normal.x + (double)r->normal.y * r->normal.y);
    if (fabs(n_length - 1.0) > 1e-4) {
        ++bad;
        report("ray %d: normal (%g, %g) is not unit", index, r->normal.x, r->normal.y);
    }
    ray_hit exact = ray_shape(ref, 0.0, ray);
    bool normal_ok;
    if (ref->type == I2D_SHAPE_CIRCLE) {
        double ex = (ray->ox + exact.t * ray->dx - ref->cx) / ref->radius;
        double ey = (ray->oy + exact.t * ray->dy - ref->cy) / ref->radius;
        normal_ok = fabs(r->normal.x - ex) <= 1e-3 && fabs(r->normal.y - ey) <= 1e-3;
    } else {
        /* The face of the slab entered last, facing the ray; either face at a corner. The
         * faces' normals are the box's local axes u = (ux, uy) and v = (-uy, ux). */
        double du, dv;
        to_box_frame(ref, ray->dx, ray->dy, &du, &dv);
        double su = du > 0.0 ? -1.0 : 1.0, sv = dv > 0.0 ? -1.0 : 1.0;
        bool is_u = fabs(r->normal.x - su * ref->ux) <= 1e-4 && fabs(r->normal.y - su * ref->uy) <= 1e-4;
        bool is_v = fabs(r->normal.x + sv * ref->uy) <= 1e-4 && fabs(r->normal.y - sv * ref->ux) <= 1e-4;
        normal_ok = exact.corner ? (is_u || is_v) : (exact.axis == 0 ? is_u : is_v);
    }
    if (!normal_ok) {
        ++bad;
        report("ray %d: normal (%g, %g) is not the surface normal of the %s hit", index, r->normal.x, r->normal.y,
               ref->type == I2D_SHAPE_CIRCLE ? "circle" : "box");
    }
    return bad;
}

/* One ray against the brute force. Rays whose answer hinges on a near-tangent or
 * near-boundary case (within EPS) are counted in *skipped and not judged. */
static int check_ray(const scene* s, const ray_case* ray, i2d_query_filter qf, int index, int* skipped, int* hits) {
    double best = INFINITY, ambiguous = INFINITY;
    for (int k = 0; k < s->shape_count; ++k) {
        const ref_shape* ref = &s->shapes[k];
        if (!ref->alive || !filter_passes(ref->filter, qf)) {
            continue;
        }
        ray_hit exact = ray_shape(ref, 0.0, ray);
        ray_hit grown = ray_shape(ref, EPS, ray);
        ray_hit shrunk = ray_shape(ref, -EPS, ray);
        if (exact.hit && grown.hit && shrunk.hit && shrunk.t - grown.t <= GRAZING_SPREAD) {
            best = fmin(best, exact.t);
        } else if (exact.hit || grown.hit || shrunk.hit) {
            double earliest = INFINITY;
            earliest = exact.hit ? fmin(earliest, exact.t) : earliest;
            earliest = grown.hit ? fmin(earliest, grown.t) : earliest;
            earliest = shrunk.hit ? fmin(earliest, shrunk.t) : earliest;
            ambiguous = fmin(ambiguous, earliest);
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
    return bad + check_ray_surface(&s->shapes[k], ray, &r, index);
}

static ray_case random_ray(const scene* s, rng* r) {
    ray_case ray;
    /* One ray in five starts at the centre of a shape: that shape must not be hit. */
    int k = rng_int(r, s->shape_count);
    if (rng_int(r, 5) == 0 && s->shapes[k].alive) {
        ray.ox = s->shapes[k].cx;
        ray.oy = s->shapes[k].cy;
    } else {
        ray.ox = rng_float(r, -50.0f, 50.0f);
        ray.oy = rng_float(r, -50.0f, 50.0f);
    }
    float angle = rng_float(r, 0.0f, 6.2831853f);
    float length = rng_float(r, 20.0f, 100.0f);
    /* Store what the library will see: float inputs. */
    ray.ox = (float)ray.ox;
    ray.oy = (float)ray.oy;
    ray.dx = (float)(length * cos(angle));
    ray.dy = (float)(length * sin(angle));
    return ray;
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
    int bad = scene_refresh(s);
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
        ray_case ray = random_ray(s, &r);
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
    if (!I2D_IS_NULL(s.world)) {
        i2d_world_destroy(s.world);
    }
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
    if (!I2D_IS_NULL(s.world)) {
        i2d_world_destroy(s.world);
    }
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
