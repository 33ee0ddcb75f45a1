/* SPDX-License-Identifier: MIT */
/* The reference model of the C99 query tests (test_api_queries.c, test_api_cast_ray.c):
 * a shape as the test recorded it, exact ray casts and overlap tests against it in double
 * precision, which the library's float answers are judged by, and a scene that keeps a
 * world and the model of its shapes in step. Which scenes and queries to draw is each
 * test file's own. Static functions: each test file gets its own copy. */
#ifndef I2D_TEST_REF_SHAPE_H
#define I2D_TEST_REF_SHAPE_H

#include <impulse2d/impulse2d.h>

#include <math.h>
#include <stdbool.h>
#include <string.h>

#include "api_test_support.h"

typedef struct ref_shape {
    i2d_shape_id id;
    int body; /* index into scene.bodies */
    i2d_shape_type type;
    i2d_vec2 local_center; /* circles; boxes are centred on the body origin */
    float radius;
    i2d_vec2 half;
    i2d_filter filter;
    bool alive;
    /* Refreshed from the body transform: the world centre, and the world direction of the
     * box's local x axis (the body's rotation; local y is (-uy, ux)). Bodies turn, so a
     * box is axis-aligned only in its own frame. */
    double cx, cy;
    double ux, uy;
} ref_shape;

/* Float rounding in the library can move a boundary by about 1e-5 m, so the tests judge
 * only shapes that overlap (or are hit) with a margin of EPS, or miss by EPS. */
#define EPS 1e-3

/* A world offset (dx, dy) from the shape's centre, in the box's frame. */
static void to_box_frame(const ref_shape* s, double dx, double dy, double* lx, double* ly) {
    *lx = s->ux * dx + s->uy * dy;
    *ly = -s->uy * dx + s->ux * dy;
}

typedef struct ray_case {
    double ox, oy, dx, dy;
} ray_case;

typedef struct ray_hit {
    bool hit;
    double t;    /* fraction where the ray enters */
    int axis;    /* boxes: the slab entered last, in the box's frame: 0 = local x, 1 = local y */
    bool corner; /* boxes: both slabs entered at nearly the same fraction */
} ray_hit;

static const ray_hit k_no_hit = {false, 0.0, -1, false};

/* Circle: the smaller root of |o + t d - c|^2 = r^2; no hit from inside (closed disc). */
static ray_hit ray_circle(double cx, double cy, double r, const ray_case* ray) {
    if (r <= 0.0) {
        return k_no_hit;
    }
    double mx = ray->ox - cx, my = ray->oy - cy;
    double c = mx * mx + my * my - r * r;
    if (c <= 0.0) {
        return k_no_hit;
    }
    double a = ray->dx * ray->dx + ray->dy * ray->dy;
    double b = mx * ray->dx + my * ray->dy;
    double disc = b * b - a * c;
    if (a == 0.0 || disc < 0.0) {
        return k_no_hit;
    }
    double t = (-b - sqrt(disc)) / a;
    if (t < 0.0 || t > 1.0) {
        return k_no_hit;
    }
    ray_hit h = {true, t, -1, false};
    return h;
}

/* Box: slab test in the box's frame (a rigid motion keeps the fraction); no hit from
 * inside (closed box). */
static ray_hit ray_box(const ref_shape* s, double hx, double hy, const ray_case* ray) {
    if (hx <= 0.0 || hy <= 0.0) {
        return k_no_hit;
    }
    double o[2], d[2];
    to_box_frame(s, ray->ox - s->cx, ray->oy - s->cy, &o[0], &o[1]);
    to_box_frame(s, ray->dx, ray->dy, &d[0], &d[1]);
    double h[2] = {hx, hy};
    if (fabs(o[0]) <= h[0] && fabs(o[1]) <= h[1]) {
        return k_no_hit;
    }
    double enter[2] = {-INFINITY, -INFINITY};
    double t_exit = INFINITY;
    for (int i = 0; i < 2; ++i) {
        if (d[i] == 0.0) {
            if (fabs(o[i]) > h[i]) {
                return k_no_hit;
            }
            continue;
        }
        double t1 = (-h[i] - o[i]) / d[i];
        double t2 = (h[i] - o[i]) / d[i];
        enter[i] = fmin(t1, t2);
        t_exit = fmin(t_exit, fmax(t1, t2));
    }
    int axis = enter[0] >= enter[1] ? 0 : 1;
    double t = enter[axis];
    if (t > t_exit || t < 0.0 || t > 1.0) {
        return k_no_hit;
    }
    ray_hit hit = {true, t, axis, fabs(enter[0] - enter[1]) <= 1e-4};
    return hit;
}

static ray_hit ray_shape(const ref_shape* s, double delta, const ray_case* ray) {
    if (s->type == I2D_SHAPE_CIRCLE) {
        return ray_circle(s->cx, s->cy, s->radius + delta, ray);
    }
    return ray_box(s, s->half.x + delta, s->half.y + delta, ray);
}

static double ray_length(const ray_case* ray) { return sqrt(ray->dx * ray->dx + ray->dy * ray->dy); }

/* The fraction a library working in float may be off by; shapes grown and shrunk by EPS
 * that disagree, or are entered more than GRAZING_SPREAD apart, are judged neither hit
 * nor missed. */
#define FRACTION_TOL 1e-5
#define GRAZING_SPREAD 1e-3

enum { RAY_MISS, RAY_HIT, RAY_AMBIGUOUS };

typedef struct ray_class {
    int kind;
    double t; /* RAY_HIT: the exact entry; RAY_AMBIGUOUS: the earliest entry of the three */
} ray_class;

static ray_class classify_ray(const ref_shape* ref, const ray_case* ray) {
    ray_hit exact = ray_shape(ref, 0.0, ray);
    ray_hit grown = ray_shape(ref, EPS, ray);
    ray_hit shrunk = ray_shape(ref, -EPS, ray);
    ray_class c;
    if (exact.hit && grown.hit && shrunk.hit && shrunk.t - grown.t <= GRAZING_SPREAD) {
        c.kind = RAY_HIT;
        c.t = exact.t;
    } else if (!exact.hit && !grown.hit && !shrunk.hit) {
        c.kind = RAY_MISS;
        c.t = INFINITY;
    } else {
        c.kind = RAY_AMBIGUOUS;
        c.t = INFINITY;
        c.t = exact.hit ? fmin(c.t, exact.t) : c.t;
        c.t = grown.hit ? fmin(c.t, grown.t) : c.t;
        c.t = shrunk.hit ? fmin(c.t, shrunk.t) : c.t;
    }
    return c;
}

/* Checks a reported hit's point (within point_tol of origin + fraction * translation, and
 * on the surface) and unit normal against the exact entry of shape ref. */
static int check_ray_surface(const ref_shape* ref, const ray_case* ray, const i2d_ray_result* r, double point_tol,
                             const char* what, int index) {
    int bad = 0;
    double px = ray->ox + r->fraction * ray->dx, py = ray->oy + r->fraction * ray->dy;
    if (fabs(r->point.x - px) > point_tol || fabs(r->point.y - py) > point_tol) {
        ++bad;
        report("%s %d: point (%g, %g) is not origin + fraction * translation (%g, %g)", what, index, r->point.x,
               r->point.y, px, py);
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
        report("%s %d: point (%g, %g) is not on the surface of the shape hit", what, index, r->point.x, r->point.y);
    }
    double n_length = sqrt((double)r->normal.x * r->normal.x + (double)r->normal.y * r->normal.y);
    if (fabs(n_length - 1.0) > 1e-4) {
        ++bad;
        report("%s %d: normal (%g, %g) is not unit", what, index, r->normal.x, r->normal.y);
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
        report("%s %d: normal (%g, %g) is not the surface normal of the %s hit", what, index, r->normal.x, r->normal.y,
               ref->type == I2D_SHAPE_CIRCLE ? "circle" : "box");
    }
    return bad;
}

/* ---- Overlap: exact tests on the shape grown by delta (shrunk when negative) ---------- */

typedef bool (*overlap_test)(const ref_shape* s, double delta, const void* query);

static bool circle_overlaps_aabb(double cx, double cy, double r, const i2d_aabb* q) {
    double dx = fmax(fmax(q->min.x - cx, 0.0), cx - q->max.x);
    double dy = fmax(fmax(q->min.y - cy, 0.0), cy - q->max.y);
    return r >= 0.0 && dx * dx + dy * dy <= r * r;
}

/* A turned box (centre c, local axes u = (ux, uy) and v = (-uy, ux), half extents hx, hy)
 * against an AABB: the separating axis test on the four edge normals, the AABB's x and y
 * and the box's u and v. Exact for two rectangles. */
static bool box_overlaps_aabb(const ref_shape* s, double hx, double hy, const i2d_aabb* q) {
    const double ux = s->ux, uy = s->uy;
    const double qx = 0.5 * ((double)q->min.x + q->max.x), qy = 0.5 * ((double)q->min.y + q->max.y);
    const double qhx = 0.5 * ((double)q->max.x - q->min.x), qhy = 0.5 * ((double)q->max.y - q->min.y);
    const double dx = qx - s->cx, dy = qy - s->cy;
    /* The box projected on x and y. */
    if (fabs(dx) > fabs(ux) * hx + fabs(uy) * hy + qhx || fabs(dy) > fabs(uy) * hx + fabs(ux) * hy + qhy) {
        return false;
    }
    /* The AABB projected on u and v. */
    const double du = ux * dx + uy * dy, dv = -uy * dx + ux * dy;
    return fabs(du) <= hx + fabs(ux) * qhx + fabs(uy) * qhy && fabs(dv) <= hy + fabs(uy) * qhx + fabs(ux) * qhy;
}

static bool shape_overlaps_aabb(const ref_shape* s, double delta, const void* query) {
    const i2d_aabb* q = (const i2d_aabb*)query;
    if (s->type == I2D_SHAPE_CIRCLE) {
        return circle_overlaps_aabb(s->cx, s->cy, s->radius + delta, q);
    }
    double hx = s->half.x + delta, hy = s->half.y + delta;
    return hx >= 0.0 && hy >= 0.0 && box_overlaps_aabb(s, hx, hy, q);
}

static bool shape_contains_point(const ref_shape* s, double delta, const void* query) {
    const i2d_vec2* p = (const i2d_vec2*)query;
    double dx = p->x - s->cx, dy = p->y - s->cy;
    if (s->type == I2D_SHAPE_CIRCLE) {
        double r = s->radius + delta;
        return r >= 0.0 && dx * dx + dy * dy <= r * r;
    }
    double hx = s->half.x + delta, hy = s->half.y + delta, lx, ly;
    to_box_frame(s, dx, dy, &lx, &ly);
    return hx >= 0.0 && hy >= 0.0 && fabs(lx) <= hx && fabs(ly) <= hy;
}

enum { CLEARLY_OUT, CLEARLY_IN, ON_EDGE };

static int classify(const ref_shape* s, overlap_test test, const void* query) {
    if (test(s, -EPS, query)) {
        return CLEARLY_IN;
    }
    if (!test(s, EPS, query)) {
        return CLEARLY_OUT;
    }
    return ON_EDGE;
}


/* ---- The scene: a world and the model of every shape in it, kept in step ------------- */

enum { MAX_BODIES = 1200, MAX_SHAPES = 2400 };

typedef struct scene {
    i2d_world_id world;
    int body_count;
    i2d_body_id bodies[MAX_BODIES];
    bool body_alive[MAX_BODIES];
    int shape_count;
    ref_shape shapes[MAX_SHAPES];
} scene;

/* An empty scene in a world without gravity. */
static bool scene_init(scene* s) {
    memset(s, 0, sizeof *s);
    s->world = make_world(0.0f);
    return !I2D_IS_NULL(s->world);
}

/* Destroys the scene's world, if it was made. */
static void scene_destroy(scene* s) {
    if (!I2D_IS_NULL(s->world)) {
        i2d_world_destroy(s->world);
    }
}

/* Uniform angle in [-pi, pi): bodies start turned so that rotated boxes are queried from
 * the start, not only after collisions have turned them. */
static i2d_rot random_rot(rng* r) { return i2d_make_rot(rng_float(r, -3.14159265f, 3.14159265f)); }

/* Returns the body's index, -1 when the scene is full or the world refused it. Static
 * bodies are given no velocity. */
static int scene_add_body(scene* s, i2d_body_type type, i2d_vec2 position, i2d_rot rotation, i2d_vec2 velocity) {
    if (s->body_count >= MAX_BODIES) {
        return -1;
    }
    i2d_body_def def = i2d_default_body_def();
    def.type = type;
    def.position = position;
    def.rotation = rotation;
    def.linear_velocity = type == I2D_BODY_STATIC ? v2(0.0f, 0.0f) : velocity;
    i2d_body_id id = i2d_body_create(s->world, &def);
    if (I2D_IS_NULL(id)) {
        return -1;
    }
    int b = s->body_count++;
    s->bodies[b] = id;
    s->body_alive[b] = true;
    return b;
}

/* A new model entry for a shape on body b, or NULL when the scene is full. */
static ref_shape* scene_new_shape(scene* s, int body, i2d_filter filter, i2d_shape_def* def) {
    if (s->shape_count >= MAX_SHAPES || body < 0) {
        return NULL;
    }
    ref_shape* ref = &s->shapes[s->shape_count++];
    memset(ref, 0, sizeof *ref);
    ref->body = body;
    ref->filter = filter;
    *def = i2d_default_shape_def();
    def->filter = filter;
    return ref;
}

/* A circle (or a box of half extents `half` centred on the body origin) on body b, in the
 * world and in the model; false when the scene is full or the world refused it. */
static bool scene_add_circle(scene* s, int body, i2d_filter filter, i2d_vec2 center, float radius) {
    i2d_shape_def def;
    ref_shape* ref = scene_new_shape(s, body, filter, &def);
    if (ref == NULL) {
        return false;
    }
    ref->type = I2D_SHAPE_CIRCLE;
    ref->local_center = center;
    ref->radius = radius;
    i2d_circle circle = {center, radius};
    ref->id = i2d_shape_create_circle(s->bodies[body], &def, &circle);
    ref->alive = !I2D_IS_NULL(ref->id);
    return ref->alive;
}

static bool scene_add_box(scene* s, int body, i2d_filter filter, i2d_vec2 half) {
    i2d_shape_def def;
    ref_shape* ref = scene_new_shape(s, body, filter, &def);
    if (ref == NULL) {
        return false;
    }
    ref->type = I2D_SHAPE_POLYGON;
    ref->half = half;
    ref->id = i2d_shape_create_box(s->bodies[body], &def, half.x, half.y);
    ref->alive = !I2D_IS_NULL(ref->id);
    return ref->alive;
}

/* Spins a body once its shapes give it inertia (static bodies ignore the spin). */
static bool scene_spin(scene* s, int body, float w) {
    return body >= 0 && i2d_body_set_angular_velocity(s->bodies[body], w) == I2D_OK;
}

/* Destroys body b with its shapes, if it is alive. */
static void scene_destroy_body(scene* s, int b) {
    if (b < 0 || !s->body_alive[b] || i2d_body_destroy(s->bodies[b]) != I2D_OK) {
        return;
    }
    s->body_alive[b] = false;
    for (int k = 0; k < s->shape_count; ++k) {
        if (s->shapes[k].body == b) {
            s->shapes[k].alive = false;
        }
    }
}

static void scene_destroy_shape(scene* s, int k) {
    if (k >= 0 && s->shapes[k].alive && i2d_shape_destroy(s->shapes[k].id) == I2D_OK) {
        s->shapes[k].alive = false;
    }
}

static int alive_shape_count(const scene* s) {
    int n = 0;
    for (int k = 0; k < s->shape_count; ++k) {
        n += s->shapes[k].alive ? 1 : 0;
    }
    return n;
}

/* Reads the bodies' transforms into the model and checks the library's local polygons
 * and tight bounds agree with it, so that the brute force describes the same shapes the
 * library has. Bounds may be off by 1e-4 m plus relative_tol times |x| + |y| of the
 * shape's centre (float spacing grows with the distance from the origin). */
static int scene_refresh(scene* s, double relative_tol) {
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
        double tol = 1e-4 + relative_tol * (fabs(ref->cx) + fabs(ref->cy));
        if (fabs(b.min.x - (ref->cx - hx)) > tol || fabs(b.min.y - (ref->cy - hy)) > tol ||
            fabs(b.max.x - (ref->cx + hx)) > tol || fabs(b.max.y - (ref->cy + hy)) > tol) {
            ++bad;
            report("shape %d: i2d_shape_get_aabb (%g, %g)-(%g, %g), expected (%g, %g)-(%g, %g)", k, b.min.x, b.min.y,
                   b.max.x, b.max.y, ref->cx - hx, ref->cy - hy, ref->cx + hx, ref->cy + hy);
        }
    }
    return bad;
}

/* Shape index by id, -1 for an id the scene never had: an open-addressing table rebuilt
 * when shapes are added. */
enum { ID_TABLE = 8192 };
static int g_id_table[ID_TABLE];
static const scene* g_id_table_scene;
static int g_id_table_count;

static uint32_t id_hash(uint64_t bits) { return (uint32_t)((bits * UINT64_C(0x9E3779B97F4A7C15)) >> 51); }

static int find_shape(const scene* s, i2d_shape_id id) {
    if (g_id_table_scene != s || g_id_table_count != s->shape_count) {
        for (int i = 0; i < ID_TABLE; ++i) {
            g_id_table[i] = -1;
        }
        for (int k = 0; k < s->shape_count; ++k) {
            uint32_t i = id_hash(s->shapes[k].id.bits);
            while (g_id_table[i] >= 0) {
                i = (i + 1) & (ID_TABLE - 1);
            }
            g_id_table[i] = k;
        }
        g_id_table_scene = s;
        g_id_table_count = s->shape_count;
    }
    for (uint32_t i = id_hash(id.bits); g_id_table[i] >= 0; i = (i + 1) & (ID_TABLE - 1)) {
        if (I2D_ID_EQUALS(s->shapes[g_id_table[i]].id, id)) {
            return g_id_table[i];
        }
    }
    return -1;
}

/* ---- Queries on the scene ------------------------------------------------------------ */

/* The filter rule of queries: the shape's category meets the query's mask and the other
 * way round (groups matter for contacts only). */
static bool filter_passes(i2d_filter shape, i2d_query_filter query) {
    return (shape.category_bits & query.mask_bits) != 0 && (shape.mask_bits & query.category_bits) != 0;
}

/* Half the time the default; else categories and masks over four bits, masks sometimes all. */
static i2d_query_filter random_query_filter(rng* r) {
    if (rng_int(r, 2) == 0) {
        return i2d_default_query_filter();
    }
    return query_filter((uint64_t)rng_int(r, 16), rng_int(r, 4) == 0 ? UINT64_MAX : (uint64_t)rng_int(r, 16));
}

/* A ray from a point in [lo, hi)^2 or, one in five, from the centre of a shape (which
 * must then not be hit), 0.2 to 1 times hi - lo long in any direction. */
static ray_case random_ray(const scene* s, rng* r, float lo, float hi) {
    ray_case ray;
    int k = rng_int(r, s->shape_count);
    if (rng_int(r, 5) == 0 && s->shapes[k].alive) {
        ray.ox = s->shapes[k].cx;
        ray.oy = s->shapes[k].cy;
    } else {
        ray.ox = rng_float(r, lo, hi);
        ray.oy = rng_float(r, lo, hi);
    }
    float angle = rng_float(r, 0.0f, 6.2831853f);
    float length = rng_float(r, 0.2f * (hi - lo), hi - lo);
    /* Store what the library will see: float inputs. */
    ray.ox = (float)ray.ox;
    ray.oy = (float)ray.oy;
    ray.dx = (float)(length * cos(angle));
    ray.dy = (float)(length * sin(angle));
    return ray;
}

/* The ids a query reports, in order; the callback stops the query after `limit` (0:
 * never). Ids past the room are counted, not kept. */
typedef struct id_list {
    int count;
    int limit;
    i2d_shape_id ids[MAX_SHAPES];
} id_list;

static bool collect(i2d_shape_id shape, void* context) {
    id_list* list = (id_list*)context;
    if (list->count < MAX_SHAPES) {
        list->ids[list->count] = shape;
    }
    ++list->count;
    return list->limit == 0 || list->count < list->limit;
}

/* Compares what an overlap query reported with the brute force: no unknown, destroyed,
 * filtered-out, clearly-outside or repeated shape; no clearly-inside shape left out. */
static int check_reported_set(const scene* s, const id_list* list, overlap_test test, const void* query,
                              i2d_query_filter qf, const char* what, int index) {
    static bool seen[MAX_SHAPES];
    memset(seen, 0, sizeof seen);
    int bad = 0;
    for (int i = 0; i < list->count && i < MAX_SHAPES; ++i) {
        int k = find_shape(s, list->ids[i]);
        if (k < 0 || !s->shapes[k].alive) {
            ++bad;
            report("%s %d: reported %s shape (bits 0x%llx)", what, index, k < 0 ? "an unknown" : "a destroyed",
                   (unsigned long long)list->ids[i].bits);
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

#endif
