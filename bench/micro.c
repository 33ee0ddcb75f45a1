/* SPDX-License-Identifier: MIT */
/* Microbenchmarks of the hot kernels, so that a regression in a scene's time shows where it is:
 *
 * - manifold: each public i2d_collide_* function on 4096 random nearby poses (shapes of the
 *   scenes' sizes, B placed within reach of A so that most calls do the full work): ns per
 *   call. These go through the C API boundary (argument checks, the per-thread status), which
 *   the world's narrowphase does not pay, so they bound the kernels from above.
 * - query: i2d_world_overlap_aabb with 4 x 4 m boxes and i2d_world_cast_ray_closest with 20 m
 *   rays on 65,536 axis-aligned boxes (one per 4 m^2), in the static tree as inserted, after
 *   i2d_world_rebuild_static_tree, and in the dynamic tree: ns per query. The first queries
 *   are checked against brute force (the exit status says whether they agreed).
 * - contact solve: box_grid and large_pyramid from the scene table, stepped past their first
 *   second, then the profile's solve time per touching contact per substep (and per velocity
 *   iteration), the collide time per pair per substep and the bounds time per body per substep.
 * - edits: what a level loader or an editor does in bulk, at 1,000 and 16,000 items, in ns per
 *   item (the same figure at both sizes means linear time): boxes added to one static body
 *   and every other one destroyed (a tile map), bodies made at the origin then placed with
 *   i2d_body_set_transform, and every other one of bodies made at one spot destroyed.
 *
 * Each figure is the median (and minimum) of R samples. Times are never asserted on. */

#include "build_info.h"
#include "timing.h"
#include "scenes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { EXIT_OK = 0, EXIT_MISMATCH = 1, EXIT_USAGE = 2, EXIT_API_ERROR = 3 };

#define MAX_REPEATS 100
#define POSES 4096
#define PI_F 3.14159265358979f

typedef enum output_format { FORMAT_TABLE, FORMAT_CSV, FORMAT_JSON } output_format;

typedef struct options {
    bool quick;       /* small sizes and short samples: checks that the app works (CTest) */
    int32_t repeats;
    output_format format;
} options;

/* ---- Output: one row per measured figure ---------------------------------------------------- */

static output_format g_format = FORMAT_TABLE;
static bool g_first_row = true;

static void print_row(const char* section, const char* name, double median, double min, const char* unit,
                      const char* detail) {
    if (g_format == FORMAT_JSON) {
        printf("%s\n  {\"section\": \"%s\", \"name\": \"%s\", \"median\": %.6g, \"min\": %.6g, \"unit\": \"%s\", "
               "\"detail\": \"",
               g_first_row ? "" : ",", section, name, median, min, unit);
        bench_json_string(stdout, detail);
        printf("\"}");
    } else if (g_format == FORMAT_CSV) {
        printf("%s,%s,%.6g,%.6g,%s,\"%s\"\n", section, name, median, min, unit, detail);
    } else {
        printf("%-9s %-46s %10.2f %10.2f  %-14s %s\n", section, name, median, min, unit, detail);
    }
    g_first_row = false;
    fflush(stdout);
}

/* ---- Poses ---------------------------------------------------------------------------------- */

/* xorshift32 with a fixed seed: the same poses every run. */
static uint32_t g_seed = 0x2545f491u;

static float random_range(float lo, float hi) {
    uint32_t x = g_seed;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    g_seed = x;
    return lo + (hi - lo) * ((float)(x >> 8) * (1.0f / 16777216.0f));
}

static i2d_vec2 vec2(float x, float y) {
    i2d_vec2 v;
    v.x = x;
    v.y = y;
    return v;
}

/* ---- Manifold kernels ------------------------------------------------------------------------- */

static i2d_circle g_circle;    /* r 0.5 */
static i2d_polygon g_box;      /* 1 x 1 m, sharp */
static i2d_polygon g_octagon;  /* regular, circumradius 0.5 m */
static i2d_capsule g_capsule;  /* (-0.5, 0)..(0.5, 0), r 0.25 */
static i2d_segment g_segment;  /* (-2, 0)..(2, 0) */

static i2d_transform g_xa[POSES], g_xb[POSES];
static i2d_circle g_wca[POSES], g_wcb[POSES]; /* world-space circles of the poses */
static i2d_aabb g_wba[POSES], g_wbb[POSES];   /* world-space 1 x 1 m boxes of the poses */

typedef enum kernel_id {
    K_CIRCLES,
    K_AABBS,
    K_AABB_CIRCLE,
    K_CAPSULE_CIRCLE,
    K_SEGMENT_CIRCLE,
    K_POLYGON_CIRCLE,
    K_CAPSULES,
    K_SEGMENT_CAPSULE,
    K_POLYGON_CAPSULE,
    K_SEGMENT_POLYGON,
    K_POLYGONS_BOXES,
    K_POLYGONS_OCTAGONS,
    K_COUNT
} kernel_id;

typedef struct kernel {
    const char* name;
    /* B is placed in A's frame within a disc of this radius (0: along a 4 m segment instead). */
    float reach;
    bool rotate;      /* random rotations (the world-space functions take none) */
} kernel;

static const kernel g_kernels[K_COUNT] = {
    {"i2d_collide_circles", 1.05f, false},
    {"i2d_collide_aabbs", 1.1f, false},
    {"i2d_collide_aabb_circle", 1.1f, false},
    {"i2d_collide_capsule_circle (capsule, r 0.5)", 1.3f, true},
    {"i2d_collide_segment_circle (4 m, r 0.5)", 0.0f, true},
    {"i2d_collide_polygon_circle (box, r 0.5)", 1.2f, true},
    {"i2d_collide_capsules", 1.5f, true},
    {"i2d_collide_segment_capsule", 0.0f, true},
    {"i2d_collide_polygon_capsule (box)", 1.45f, true},
    {"i2d_collide_segment_polygon (box)", 0.0f, true},
    {"i2d_collide_polygons (1 m boxes)", 1.4f, true},
    {"i2d_collide_polygons (octagons)", 1.0f, true},
};

/* The bounding radius of B for the segment kernels' placement band. */
static float segment_band(kernel_id k) {
    return k == K_SEGMENT_CIRCLE ? 0.5f : k == K_SEGMENT_CAPSULE ? 0.75f : 0.71f;
}

static i2d_transform make_transform(i2d_vec2 p, float angle) {
    i2d_transform xf;
    xf.p = p;
    xf.q = i2d_make_rot(angle);
    return xf;
}

static void make_poses(kernel_id k) {
    const kernel* kn = &g_kernels[k];
    int32_t i;
    for (i = 0; i < POSES; ++i) {
        i2d_vec2 pa = vec2(random_range(-100.0f, 100.0f), random_range(-100.0f, 100.0f));
        float angle_a = kn->rotate ? random_range(-PI_F, PI_F) : 0.0f;
        float angle_b = kn->rotate ? random_range(-PI_F, PI_F) : 0.0f;
        i2d_transform xa = make_transform(pa, angle_a);
        i2d_vec2 local, pb;
        if (kn->reach > 0.0f) {
            /* Uniform in the disc. */
            float r = kn->reach * sqrtf(random_range(0.0f, 1.0f)), t = random_range(-PI_F, PI_F);
            local = vec2(r * cosf(t), r * sinf(t));
        } else {
            float band = segment_band(k) + 0.05f;
            local = vec2(random_range(-2.0f - band, 2.0f + band), random_range(-band, band));
        }
        pb = vec2(pa.x + xa.q.c * local.x - xa.q.s * local.y, pa.y + xa.q.s * local.x + xa.q.c * local.y);
        g_xa[i] = xa;
        g_xb[i] = make_transform(pb, angle_b);
        g_wca[i].center = pa;
        g_wca[i].radius = 0.5f;
        g_wcb[i].center = pb;
        g_wcb[i].radius = 0.5f;
        g_wba[i].min = vec2(pa.x - 0.5f, pa.y - 0.5f);
        g_wba[i].max = vec2(pa.x + 0.5f, pa.y + 0.5f);
        g_wbb[i].min = vec2(pb.x - 0.5f, pb.y - 0.5f);
        g_wbb[i].max = vec2(pb.x + 0.5f, pb.y + 0.5f);
    }
}

/* One pass over every pose; returns the sum of point counts (which keeps the calls alive). */
static int32_t run_kernel(kernel_id k) {
    int32_t i, points = 0;
    switch (k) {
#define KERNEL_LOOP(call)                 \
    for (i = 0; i < POSES; ++i) {         \
        points += (call).point_count;     \
    }                                     \
    break
    case K_CIRCLES:
        KERNEL_LOOP(i2d_collide_circles(g_wca[i], g_wcb[i]));
    case K_AABBS:
        KERNEL_LOOP(i2d_collide_aabbs(g_wba[i], g_wbb[i]));
    case K_AABB_CIRCLE:
        KERNEL_LOOP(i2d_collide_aabb_circle(g_wba[i], g_wcb[i]));
    case K_CAPSULE_CIRCLE:
        KERNEL_LOOP(i2d_collide_capsule_circle(&g_capsule, g_xa[i], &g_circle, g_xb[i]));
    case K_SEGMENT_CIRCLE:
        KERNEL_LOOP(i2d_collide_segment_circle(&g_segment, g_xa[i], &g_circle, g_xb[i]));
    case K_POLYGON_CIRCLE:
        KERNEL_LOOP(i2d_collide_polygon_circle(&g_box, g_xa[i], &g_circle, g_xb[i]));
    case K_CAPSULES:
        KERNEL_LOOP(i2d_collide_capsules(&g_capsule, g_xa[i], &g_capsule, g_xb[i]));
    case K_SEGMENT_CAPSULE:
        KERNEL_LOOP(i2d_collide_segment_capsule(&g_segment, g_xa[i], &g_capsule, g_xb[i]));
    case K_POLYGON_CAPSULE:
        KERNEL_LOOP(i2d_collide_polygon_capsule(&g_box, g_xa[i], &g_capsule, g_xb[i]));
    case K_SEGMENT_POLYGON:
        KERNEL_LOOP(i2d_collide_segment_polygon(&g_segment, g_xa[i], &g_box, g_xb[i]));
    case K_POLYGONS_BOXES:
        KERNEL_LOOP(i2d_collide_polygons(&g_box, g_xa[i], &g_box, g_xb[i]));
    case K_POLYGONS_OCTAGONS:
        KERNEL_LOOP(i2d_collide_polygons(&g_octagon, g_xa[i], &g_octagon, g_xb[i]));
#undef KERNEL_LOOP
    default:
        break;
    }
    return points;
}

/* Fraction of the poses with at least one manifold point (speculative points included). */
static double touching_fraction(kernel_id k) {
    int32_t i, touching = 0;
    for (i = 0; i < POSES; ++i) {
        i2d_manifold m;
        switch (k) {
        case K_CIRCLES: m = i2d_collide_circles(g_wca[i], g_wcb[i]); break;
        case K_AABBS: m = i2d_collide_aabbs(g_wba[i], g_wbb[i]); break;
        case K_AABB_CIRCLE: m = i2d_collide_aabb_circle(g_wba[i], g_wcb[i]); break;
        case K_CAPSULE_CIRCLE: m = i2d_collide_capsule_circle(&g_capsule, g_xa[i], &g_circle, g_xb[i]); break;
        case K_SEGMENT_CIRCLE: m = i2d_collide_segment_circle(&g_segment, g_xa[i], &g_circle, g_xb[i]); break;
        case K_POLYGON_CIRCLE: m = i2d_collide_polygon_circle(&g_box, g_xa[i], &g_circle, g_xb[i]); break;
        case K_CAPSULES: m = i2d_collide_capsules(&g_capsule, g_xa[i], &g_capsule, g_xb[i]); break;
        case K_SEGMENT_CAPSULE: m = i2d_collide_segment_capsule(&g_segment, g_xa[i], &g_capsule, g_xb[i]); break;
        case K_POLYGON_CAPSULE: m = i2d_collide_polygon_capsule(&g_box, g_xa[i], &g_capsule, g_xb[i]); break;
        case K_SEGMENT_POLYGON: m = i2d_collide_segment_polygon(&g_segment, g_xa[i], &g_box, g_xb[i]); break;
        case K_POLYGONS_BOXES: m = i2d_collide_polygons(&g_box, g_xa[i], &g_box, g_xb[i]); break;
        default: m = i2d_collide_polygons(&g_octagon, g_xa[i], &g_octagon, g_xb[i]); break;
        }
        touching += m.point_count > 0;
    }
    return (double)touching / (double)POSES;
}

static bool make_shapes(void) {
    i2d_vec2 points[8];
    int32_t i;
    g_circle.center = vec2(0.0f, 0.0f);
    g_circle.radius = 0.5f;
    g_box = i2d_make_box(0.5f, 0.5f);
    for (i = 0; i < 8; ++i) {
        float t = 2.0f * PI_F * (float)i / 8.0f;
        points[i] = vec2(0.5f * cosf(t), 0.5f * sinf(t));
    }
    if (i2d_make_polygon(points, 8, 0.0f, &g_octagon) != I2D_OK || g_box.count != 4) {
        return false;
    }
    g_capsule.center1 = vec2(-0.5f, 0.0f);
    g_capsule.center2 = vec2(0.5f, 0.0f);
    g_capsule.radius = 0.25f;
    g_segment.point1 = vec2(-2.0f, 0.0f);
    g_segment.point2 = vec2(2.0f, 0.0f);
    return true;
}

static bool bench_manifolds(const options* opt) {
    /* Each sample runs for at least this long. */
    const double sample_seconds = opt->quick ? 0.002 : 0.05;
    int32_t k;
    if (!make_shapes()) {
        fprintf(stderr, "impulse2d_bench_micro: making the test shapes failed: %s\n", i2d_last_error_message());
        return false;
    }
    for (k = 0; k < K_COUNT; ++k) {
        double ns[MAX_REPEATS], median, start, elapsed;
        int32_t passes = 1, r, p;
        volatile int32_t sink = 0;
        char detail[96];
        make_poses((kernel_id)k);
        /* Calibrate: passes per sample so that a sample lasts sample_seconds. */
        for (;;) {
            start = bench_seconds_now();
            for (p = 0; p < passes; ++p) {
                sink += run_kernel((kernel_id)k);
            }
            elapsed = bench_seconds_now() - start;
            if (elapsed >= sample_seconds || passes >= (1 << 20)) {
                break;
            }
            passes *= 2;
        }
        for (r = 0; r < opt->repeats; ++r) {
            start = bench_seconds_now();
            for (p = 0; p < passes; ++p) {
                sink += run_kernel((kernel_id)k);
            }
            ns[r] = 1e9 * (bench_seconds_now() - start) / ((double)passes * POSES);
        }
        (void)sink;
        median = bench_sort_median(ns, opt->repeats);
        snprintf(detail, sizeof detail, "%.0f%% of poses give points", 100.0 * touching_fraction((kernel_id)k));
        print_row("manifold", g_kernels[k].name, median, ns[0], "ns/call", detail);
    }
    return true;
}

/* ---- Tree queries ------------------------------------------------------------------------------ */

typedef struct box_field {
    int32_t count;
    float half_side;   /* of the square they are spread over, m */
    i2d_aabb* boxes;   /* world boxes, for the brute-force check */
} box_field;

static bool count_hit(i2d_shape_id shape, void* context) {
    (void)shape;
    ++*(int32_t*)context;
    return true;
}

/* A world of `count` axis-aligned boxes (half sizes 0.1-0.6 m), one body each, spread one per
 * 4 m^2; static or dynamic (gravity off, never stepped). */
static i2d_world_id make_box_world(box_field* field, i2d_body_type type) {
    i2d_world_def world_def = i2d_default_world_def();
    i2d_shape_def shape_def = i2d_default_shape_def();
    i2d_world_id world;
    int32_t i;
    world_def.gravity = vec2(0.0f, 0.0f);
    world = i2d_world_create(&world_def);
    if (I2D_IS_NULL(world)) {
        return world;
    }
    g_seed = 0x1234567u;
    for (i = 0; i < field->count; ++i) {
        i2d_body_def body_def = i2d_default_body_def();
        float hx = random_range(0.1f, 0.6f), hy = random_range(0.1f, 0.6f);
        i2d_body_id body;
        body_def.type = type;
        body_def.position = vec2(random_range(-field->half_side, field->half_side),
                                 random_range(-field->half_side, field->half_side));
        body = i2d_body_create(world, &body_def);
        if (I2D_IS_NULL(body) || I2D_IS_NULL(i2d_shape_create_box(body, &shape_def, hx, hy))) {
            i2d_world_destroy(world);
            return I2D_NULL_WORLD_ID;
        }
        field->boxes[i].min = vec2(body_def.position.x - hx, body_def.position.y - hy);
        field->boxes[i].max = vec2(body_def.position.x + hx, body_def.position.y + hy);
    }
    return world;
}

#define QUERY_HALF 2.0f
#define RAY_LENGTH 20.0f
#define CHECKED_QUERIES 200

static i2d_aabb query_box(float half_side) {
    i2d_vec2 c = vec2(random_range(-half_side, half_side), random_range(-half_side, half_side));
    i2d_aabb q;
    q.min = vec2(c.x - QUERY_HALF, c.y - QUERY_HALF);
    q.max = vec2(c.x + QUERY_HALF, c.y + QUERY_HALF);
    return q;
}

/* Overlap queries against brute force over the boxes; false on a disagreement or an API error. */
static bool check_queries(i2d_world_id world, const box_field* field, const char* label, bool* agreed) {
    i2d_query_filter filter = i2d_default_query_filter();
    int32_t q, i;
    g_seed = 0x51ed27u;
    for (q = 0; q < CHECKED_QUERIES; ++q) {
        i2d_aabb box = query_box(field->half_side);
        int32_t hits = 0, expected = 0;
        if (i2d_world_overlap_aabb(world, box, filter, count_hit, &hits) != I2D_OK) {
            return false;
        }
        for (i = 0; i < field->count; ++i) {
            const i2d_aabb* b = &field->boxes[i];
            expected += b->min.x <= box.max.x && box.min.x <= b->max.x && b->min.y <= box.max.y &&
                        box.min.y <= b->max.y;
        }
        if (hits != expected) {
            fprintf(stderr, "impulse2d_bench_micro: %s: query %d found %d shapes, brute force %d\n", label, (int)q,
                    (int)hits, (int)expected);
            *agreed = false;
        }
    }
    return true;
}

/* Times `queries` overlap queries and as many ray casts, drawn beforehand (the same every run). */
static bool time_queries(i2d_world_id world, const box_field* field, const char* label, const options* opt) {
    i2d_query_filter filter = i2d_default_query_filter();
    const int32_t queries = opt->quick ? 2000 : 100000;
    double ns[MAX_REPEATS], ray_ns[MAX_REPEATS], median, ray_median;
    int32_t r, q, hits = 0, ray_hits = 0;
    char name[96], detail[96];
    i2d_aabb* boxes = (i2d_aabb*)malloc((size_t)queries * sizeof *boxes);
    i2d_vec2* rays = (i2d_vec2*)malloc((size_t)queries * 2 * sizeof *rays); /* origin, translation */
    bool ok = boxes && rays;
    g_seed = 0xabcdefu;
    for (q = 0; ok && q < queries; ++q) {
        float t;
        boxes[q] = query_box(field->half_side);
        rays[2 * q] = vec2(random_range(-field->half_side, field->half_side),
                           random_range(-field->half_side, field->half_side));
        t = random_range(-PI_F, PI_F);
        rays[2 * q + 1] = vec2(RAY_LENGTH * cosf(t), RAY_LENGTH * sinf(t));
    }
    for (r = 0; ok && r < opt->repeats; ++r) {
        double start = bench_seconds_now();
        hits = 0;
        for (q = 0; ok && q < queries; ++q) {
            ok = i2d_world_overlap_aabb(world, boxes[q], filter, count_hit, &hits) == I2D_OK;
        }
        ns[r] = 1e9 * (bench_seconds_now() - start) / (double)queries;
        ray_hits = 0;
        start = bench_seconds_now();
        for (q = 0; q < queries; ++q) {
            ray_hits += i2d_world_cast_ray_closest(world, rays[2 * q], rays[2 * q + 1], filter).hit;
        }
        ray_ns[r] = 1e9 * (bench_seconds_now() - start) / (double)queries;
    }
    free(boxes);
    free(rays);
    if (!ok) {
        return false;
    }
    median = bench_sort_median(ns, opt->repeats);
    ray_median = bench_sort_median(ray_ns, opt->repeats);
    snprintf(name, sizeof name, "overlap_aabb 4x4 m, %s", label);
    snprintf(detail, sizeof detail, "%d boxes, %.2f hits/query", (int)field->count, (double)hits / (double)queries);
    print_row("query", name, median, ns[0], "ns/query", detail);
    snprintf(name, sizeof name, "cast_ray_closest 20 m, %s", label);
    snprintf(detail, sizeof detail, "%d boxes, %.0f%% of rays hit", (int)field->count,
             100.0 * (double)ray_hits / (double)queries);
    print_row("query", name, ray_median, ray_ns[0], "ns/ray", detail);
    return true;
}

static bool bench_queries(const options* opt, bool* agreed) {
    box_field field;
    i2d_world_id world;
    bool ok;
    field.count = opt->quick ? 4096 : 65536;
    field.half_side = sqrtf(4.0f * (float)field.count) * 0.5f;
    field.boxes = (i2d_aabb*)malloc((size_t)field.count * sizeof *field.boxes);
    if (!field.boxes) {
        fprintf(stderr, "impulse2d_bench_micro: out of memory\n");
        return false;
    }
    world = make_box_world(&field, I2D_BODY_STATIC);
    ok = !I2D_IS_NULL(world) && check_queries(world, &field, "static tree", agreed) &&
         time_queries(world, &field, "static tree as inserted", opt) &&
         i2d_world_rebuild_static_tree(world) == I2D_OK && check_queries(world, &field, "rebuilt tree", agreed) &&
         time_queries(world, &field, "static tree rebuilt", opt);
    if (!I2D_IS_NULL(world)) {
        i2d_world_destroy(world);
    }
    if (ok) {
        world = make_box_world(&field, I2D_BODY_DYNAMIC);
        ok = !I2D_IS_NULL(world) && check_queries(world, &field, "dynamic tree", agreed) &&
             time_queries(world, &field, "dynamic tree", opt);
        if (!I2D_IS_NULL(world)) {
            i2d_world_destroy(world);
        }
    }
    if (!ok) {
        fprintf(stderr, "impulse2d_bench_micro: queries: %s: %s\n", i2d_status_string(i2d_last_status()),
                i2d_last_error_message());
    }
    free(field.boxes);
    return ok;
}

/* ---- Contact solve, from the engine's profile on resting stacks -------------------------------- */

static bool bench_solve(const options* opt, const char* scene_name) {
    const bench_scene* scene = bench_find_scene(scene_name);
    const int32_t warm = opt->quick ? 2 : 60, steps = opt->quick ? 3 : 60;
    const int32_t passes = 2; /* the soft step solves, then relaxes, every substep */
    double solve[MAX_REPEATS], collide[MAX_REPEATS], bounds[MAX_REPEATS], pairs_ms[MAX_REPEATS];
    double median_solve, median_collide, median_bounds, median_pairs;
    i2d_world_counters c;
    int32_t r, s, contacts = 0, pairs = 0, bodies = 0;
    char name[96], detail[128];
    if (!scene) {
        fprintf(stderr, "impulse2d_bench_micro: no scene %s\n", scene_name);
        return false;
    }
    for (r = 0; r < opt->repeats; ++r) {
        bench_state state;
        double sums[4] = {0.0, 0.0, 0.0, 0.0};
        memset(&state, 0, sizeof state);
        if (!scene->create(&state)) {
            fprintf(stderr, "impulse2d_bench_micro: %s: create failed: %s\n", scene_name,
                    state.error ? state.error : i2d_last_error_message());
            bench_state_destroy(&state);
            return false;
        }
        for (s = 0; s < warm + steps; ++s) {
            i2d_profile p;
            if (i2d_world_step(state.world, BENCH_TIME_STEP, BENCH_SUBSTEPS) != I2D_OK) {
                fprintf(stderr, "impulse2d_bench_micro: %s: step failed: %s\n", scene_name, i2d_last_error_message());
                bench_state_destroy(&state);
                return false;
            }
            if (s < warm) {
                continue;
            }
            p = i2d_world_get_profile(state.world);
            sums[0] += p.solve;
            sums[1] += p.collide;
            sums[2] += p.update_bounds;
            sums[3] += p.pairs;
        }
        c = i2d_world_get_counters(state.world);
        contacts = c.contact_count;
        pairs = c.pair_count;
        bodies = state.body_count;
        bench_state_destroy(&state);
        solve[r] = 1e6 * sums[0] / ((double)steps * BENCH_SUBSTEPS * (double)contacts);
        collide[r] = 1e6 * sums[1] / ((double)steps * (double)pairs); /* once per step */
        bounds[r] = 1e6 * sums[2] / ((double)steps * (double)bodies);
        pairs_ms[r] = sums[3] / (double)steps;
    }
    /* median_of sorts: each array's [0] is its minimum afterwards. */
    median_solve = bench_sort_median(solve, opt->repeats);
    median_collide = bench_sort_median(collide, opt->repeats);
    median_bounds = bench_sort_median(bounds, opt->repeats);
    median_pairs = bench_sort_median(pairs_ms, opt->repeats);
    snprintf(name, sizeof name, "solve per contact, %s", scene_name);
    snprintf(detail, sizeof detail, "%d touching contacts, %d passes per substep: %.1f ns/contact/pass",
             (int)contacts, (int)passes, median_solve / (double)passes);
    print_row("solve", name, median_solve, solve[0], "ns/contact/ss", detail);
    snprintf(name, sizeof name, "collide per pair, %s", scene_name);
    snprintf(detail, sizeof detail, "%d pairs (fat bounds overlapping)", (int)pairs);
    print_row("solve", name, median_collide, collide[0], "ns/pair/step", detail);
    snprintf(name, sizeof name, "update_bounds per body, %s", scene_name);
    snprintf(detail, sizeof detail, "%d dynamic bodies", (int)bodies);
    print_row("solve", name, median_bounds, bounds[0], "ns/body/step", detail);
    snprintf(name, sizeof name, "pairs stage per step, %s", scene_name);
    print_row("solve", name, 1e3 * median_pairs, 1e3 * pairs_ms[0], "us/step",
              "finding new pairs (broadphase) over the 4 substeps");
    return true;
}

/* ---- Edits in bulk ------------------------------------------------------------------------------- */

enum { EDIT_KINDS = 4 };
static const char* const g_edit_names[EDIT_KINDS] = {
    "static body: boxes added", "static body: every other box destroyed",
    "bodies made at the origin, then placed", "bodies at one spot: every other destroyed"};

static i2d_vec2 grid_place(int32_t i) { return vec2(2.0f * (float)(i % 128), 2.0f * (float)(i / 128)); }

/* One sample of each edit at `count` items, ns per item, in a world of its own. */
static bool sample_edits(int32_t count, double ns[EDIT_KINDS]) {
    i2d_world_def world_def = i2d_default_world_def();
    i2d_world_id world = i2d_world_create(&world_def);
    i2d_body_def static_def = i2d_default_body_def(), dynamic_def = i2d_default_body_def();
    i2d_shape_def shape_def = i2d_default_shape_def();
    i2d_shape_id* shapes = (i2d_shape_id*)malloc((size_t)count * sizeof *shapes);
    i2d_body_id* bodies = (i2d_body_id*)malloc((size_t)count * sizeof *bodies);
    i2d_body_id map;
    double start;
    int32_t i;
    bool ok = !I2D_IS_NULL(world) && shapes && bodies;
    dynamic_def.type = I2D_BODY_DYNAMIC;
    shape_def.filter.group_index = -1; /* the bodies at one spot never collide with each other */
    map = ok ? i2d_body_create(world, &static_def) : (i2d_body_id){0};
    start = bench_nanoseconds_now();
    for (i = 0; ok && i < count; ++i) {
        shapes[i] = i2d_shape_create_offset_box(map, &shape_def, 0.5f, 0.5f, grid_place(i), i2d_make_rot(0.0f));
        ok = !I2D_IS_NULL(shapes[i]);
    }
    ns[0] = (bench_nanoseconds_now() - start) / (double)count;
    start = bench_nanoseconds_now();
    for (i = 0; ok && i < count; i += 2) {
        ok = i2d_shape_destroy(shapes[i]) == I2D_OK;
    }
    ns[1] = (bench_nanoseconds_now() - start) / (double)((count + 1) / 2);
    for (i = 0; ok && i < count; ++i) {
        bodies[i] = i2d_body_create(world, i % 2 == 0 ? &static_def : &dynamic_def);
        ok = !I2D_IS_NULL(bodies[i]) && !I2D_IS_NULL(i2d_shape_create_circle(bodies[i], &shape_def, &g_circle));
    }
    start = bench_nanoseconds_now();
    for (i = 0; ok && i < count; i += 2) {
        ok = i2d_body_set_transform(bodies[i], grid_place(i), i2d_make_rot(0.0f)) == I2D_OK;
    }
    ns[2] = (bench_nanoseconds_now() - start) / (double)((count + 1) / 2);
    start = bench_nanoseconds_now();
    for (i = 1; ok && i < count; i += 2) {
        ok = i2d_body_destroy(bodies[i]) == I2D_OK;
    }
    ns[3] = (bench_nanoseconds_now() - start) / (double)(count / 2);
    free(shapes);
    free(bodies);
    if (!I2D_IS_NULL(world)) {
        i2d_world_destroy(world);
    }
    return ok;
}

static bool bench_edits(const options* opt) {
    const int32_t sizes[2] = {opt->quick ? 100 : 1000, opt->quick ? 400 : 16000};
    double ns[EDIT_KINDS][MAX_REPEATS];
    int32_t size, kind, r;
    for (size = 0; size < 2; ++size) {
        for (r = 0; r < opt->repeats; ++r) {
            double sample[EDIT_KINDS];
            if (!sample_edits(sizes[size], sample)) {
                return false;
            }
            for (kind = 0; kind < EDIT_KINDS; ++kind) {
                ns[kind][r] = sample[kind];
            }
        }
        for (kind = 0; kind < EDIT_KINDS; ++kind) {
            char detail[64];
            const double median = bench_sort_median(ns[kind], opt->repeats);
            snprintf(detail, sizeof detail, "%d items", (int)sizes[size]);
            print_row("edits", g_edit_names[kind], median, ns[kind][0], "ns/item", detail);
        }
    }
    return true;
}

/* ---- Main ---------------------------------------------------------------------------------------- */

static void usage(FILE* f) {
    fprintf(f, "usage: impulse2d_bench_micro [--quick] [--repeat R] [--csv | --json]\n"
               "  --quick       small sizes and short samples (a smoke run, figures not meaningful)\n"
               "  --repeat R    samples per figure, 1..%d; default 5\n"
               "  --csv, --json machine-readable output instead of the table\n"
               "exit status: 0 ok, 1 a query disagreed with brute force, 2 bad usage, 3 an i2d call failed\n",
               MAX_REPEATS);
}

static bool parse_options(int argc, char** argv, options* opt) {
    int i;
    memset(opt, 0, sizeof *opt);
    opt->repeats = 5;
    for (i = 1; i < argc; ++i) {
        const char* arg = argv[i];
        if (strcmp(arg, "--quick") == 0) {
            opt->quick = true;
        } else if (strcmp(arg, "--repeat") == 0 && i + 1 < argc) {
            char* end;
            long value = strtol(argv[i + 1], &end, 10);
            if (end == argv[i + 1] || *end != '\0' || value < 1 || value > MAX_REPEATS) {
                usage(stderr);
                return false;
            }
            opt->repeats = (int32_t)value;
            ++i;
        } else if (strcmp(arg, "--csv") == 0) {
            opt->format = FORMAT_CSV;
        } else if (strcmp(arg, "--json") == 0) {
            opt->format = FORMAT_JSON;
        } else if (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0) {
            usage(stdout);
            exit(EXIT_OK);
        } else {
            fprintf(stderr, "impulse2d_bench_micro: bad argument '%s'\n", arg);
            usage(stderr);
            return false;
        }
    }
    return true;
}

int main(int argc, char** argv) {
    options opt;
    bool ok, agreed = true;
    if (!parse_options(argc, argv, &opt)) {
        return EXIT_USAGE;
    }
    if (!bench_check_library_version("impulse2d_bench_micro")) {
        return EXIT_API_ERROR;
    }
    g_format = opt.format;
    if (opt.format == FORMAT_JSON) {
        printf("{\"build\": {");
        bench_print_build_json(stdout);
        printf(", \"quick\": %s, \"repeats\": %d},\n \"rows\": [", opt.quick ? "true" : "false", (int)opt.repeats);
    } else {
        bench_print_build_line(stdout, "bench_micro");
        printf("# median and min of %d samples%s; manifold calls go through the C API boundary\n", (int)opt.repeats,
               opt.quick ? " (--quick: figures not meaningful)" : "");
        if (opt.format == FORMAT_CSV) {
            printf("section,name,median,min,unit,detail\n");
        } else {
            printf("%-9s %-46s %10s %10s  %-14s %s\n", "section", "kernel", "median", "min", "unit", "detail");
        }
    }
    ok = bench_manifolds(&opt) && bench_queries(&opt, &agreed) && bench_solve(&opt, "box_grid") &&
         (opt.quick || bench_solve(&opt, "large_pyramid")) && bench_edits(&opt);
    if (opt.format == FORMAT_JSON) {
        printf("\n ], \"queries_agree_with_brute_force\": %s}\n", agreed ? "true" : "false");
    }
    if (!ok) {
        return EXIT_API_ERROR;
    }
    return agreed ? EXIT_OK : EXIT_MISMATCH;
}
