/* SPDX-License-Identifier: MIT */
/* Reference geometry shared by the C99 query tests: a shape as the test recorded it, and
 * exact ray casts and overlap tests against it in double precision, which the library's
 * float answers are judged by. Static functions: each test file gets its own copy. */
#ifndef I2D_TEST_REF_SHAPE_H
#define I2D_TEST_REF_SHAPE_H

#include <impulse2d/impulse2d.h>

#include <math.h>
#include <stdbool.h>

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

#endif
