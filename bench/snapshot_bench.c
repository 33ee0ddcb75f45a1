/* SPDX-License-Identifier: MIT */
/* The snapshot benchmark app: the sizes of full snapshots and rollback states on the bench scenes,
 * against issue 38's budget, and the time to save, restore and load them.
 *
 * Method: each scene is built by its bench/scenes.c builder and stepped (hook + world step, as
 * impulse2d_bench runs it) to a fixed moment, then measured there. Sizes and counts are
 * deterministic. Contact points: the API gives the touching pairs (i2d_world_counters.contact_count)
 * but no manifolds, so the points are counted again here from the shapes through the public
 * collide functions (every pair with a dynamic body whose bounds come within the speculative
 * distance, filters applied; a pair touches when its manifold has a point, speculative points
 * included, as the engine counts it); the touching pairs found that way are printed beside the
 * engine's count, so a miscount shows. Timings: each operation is run 20 times untimed, then
 * `--reps` times (default 201), each call timed alone with a monotonic clock; the median is
 * printed (the minimum beside it). Every timed buffer is checked before and after the timing:
 * the world restored from it and stepped gives the state hash of the world that was never
 * restored, so a broken path cannot be timed. Times are never asserted on. */

#include "arguments.h"
#include "build_info.h"
#include "timing.h"
#include "scenes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { EXIT_OK = 0, EXIT_CHECK_FAILED = 1, EXIT_USAGE = 2, EXIT_API_ERROR = 3 };

/* Steps run without the scene's hook after a restore, for the hash check. */
#define CHECK_STEPS 5
#define WARM_UP_REPS 20
#define MAX_REPS 100001
/* Issue 38's budget for a rollback state. */
#define BUDGET_PER_BODY 64.0
#define BUDGET_PER_POINT 24.0
/* Points within this separation are in a manifold (collision_constants.hpp: 4 linear slops). */
#define SPECULATIVE_DISTANCE 0.02

/* A measured scene: a bench scene and the step it is measured at. */
typedef struct snapshot_scene {
    const char* name;        /* as printed */
    const char* bench_name;  /* the scenes.c builder */
    int32_t steps;           /* hook + world steps before the measurement */
    const char* note;
} snapshot_scene;

/* large_pyramid, joint_grid and many_pyramids have settled by 120 steps; rain has all its 40
 * columns (11 000 bodies) from step 312; the circles of rain_circles_1k have landed and settled by
 * 600 (the fastest moves at 0.07 m/s): the 1000-body pile of issue 38's 15 us figure. */
static const snapshot_scene scenes[] = {
    {"large_pyramid", "large_pyramid", 120, "5050 boxes, sleep off"},
    {"rain", "rain", 400, "1000 ragdolls (every column spawned), sleep on"},
    {"joint_grid", "joint_grid", 120, "9993 discs, 19794 revolute joints, no contacts"},
    {"many_pyramids", "many_pyramids", 120, "22000 boxes, sleep off"},
    {"pile_1k", "rain_circles_1k", 600, "rain_circles_1k at rest: 1000 circles in an open box, sleep off"},
};
#define SCENE_COUNT ((int32_t)(sizeof scenes / sizeof scenes[0]))

typedef struct options {
    int32_t reps;
    int32_t steps;  /* 0: each scene's own */
    bool chosen[SCENE_COUNT];
    bool any_chosen;
    bool sizes_only;
    bool csv;
} options;

static void usage(FILE* f) {
    fprintf(f,
            "usage: impulse2d_snapshot_bench [--scene NAME[,NAME...]] [--reps R] [--steps N] [--sizes] [--csv]\n"
            "  --scene NAMES  only these (large_pyramid, rain, joint_grid, many_pyramids, pile_1k)\n"
            "  --reps R       timed repetitions of each operation, 1..%d; default 201 (the median is printed)\n"
            "  --steps N      steps before the measurement, 1..100000; default: each scene's own\n"
            "  --sizes        sizes and counts only, no timing (deterministic)\n"
            "  --csv          the sizes table as CSV (scene,steps,dynamic_bodies,touching_pairs,touching_points,\n"
            "                 snapshot_bytes,state_bytes); implies --sizes\n"
            "exit status: 0 every check passed, 1 a restored world went on differently, 2 bad usage, 3 an i2d\n"
            "             call failed\n",
            MAX_REPS);
}

static bool choose_scenes(const char* list, options* opt) {
    const char* p = list;
    while (*p) {
        const char* comma = strchr(p, ',');
        size_t n = comma ? (size_t)(comma - p) : strlen(p);
        int32_t i, found = -1;
        for (i = 0; i < SCENE_COUNT; ++i) {
            if (strlen(scenes[i].name) == n && strncmp(scenes[i].name, p, n) == 0) {
                found = i;
            }
        }
        if (found < 0) {
            fprintf(stderr, "impulse2d_snapshot_bench: no scene '%.*s'\n", (int)n, p);
            return false;
        }
        opt->chosen[found] = true;
        opt->any_chosen = true;
        p += n;
        if (*p == ',') {
            ++p;
        }
    }
    return true;
}

static bool parse_options(int argc, char** argv, options* opt) {
    int i;
    memset(opt, 0, sizeof *opt);
    opt->reps = 201;
    for (i = 1; i < argc; ++i) {
        const char* arg = argv[i];
        const char* value = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(arg, "--reps") == 0 && bench_parse_int(value, 1, MAX_REPS, &opt->reps)) {
            ++i;
        } else if (strcmp(arg, "--steps") == 0 && bench_parse_int(value, 1, 100000, &opt->steps)) {
            ++i;
        } else if (strcmp(arg, "--scene") == 0 && value) {
            if (!choose_scenes(value, opt)) {
                return false;
            }
            ++i;
        } else if (strcmp(arg, "--sizes") == 0) {
            opt->sizes_only = true;
        } else if (strcmp(arg, "--csv") == 0) {
            opt->csv = true;
            opt->sizes_only = true;
        } else if (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0) {
            usage(stdout);
            exit(EXIT_OK);
        } else {
            fprintf(stderr, "impulse2d_snapshot_bench: bad argument '%s'\n", arg);
            return false;
        }
    }
    return true;
}

/* ---- Counting touching contact points through the public API ------------------------------- */

typedef struct contact_count {
    int64_t pairs;   /* touching shape pairs (a manifold with a point) */
    int64_t points;  /* their manifold points */
} contact_count;

static i2d_vec2 world_point(i2d_transform xf, i2d_vec2 p) {
    i2d_vec2 r;
    r.x = xf.q.c * p.x - xf.q.s * p.y + xf.p.x;
    r.y = xf.q.s * p.x + xf.q.c * p.y + xf.p.y;
    return r;
}

/* Collide functions take the kinds in this order (segment, polygon, capsule, circle). */
static int kind_rank(i2d_shape_type type) {
    switch (type) {
        case I2D_SHAPE_SEGMENT:
        case I2D_SHAPE_CHAIN_SEGMENT: return 0;
        case I2D_SHAPE_POLYGON: return 1;
        case I2D_SHAPE_CAPSULE: return 2;
        case I2D_SHAPE_CIRCLE: return 3;
    }
    return 4;
}

/* The number of points of the manifold of two shapes (speculative ones included): the engine's
 * manifold functions, reached through their public twins. Chain segments are taken as plain
 * segments (no scene here has one). -1 on an API error. */
static int32_t manifold_points(i2d_shape_id a, i2d_shape_id b) {
    i2d_shape_type ta = i2d_shape_get_type(a), tb = i2d_shape_get_type(b);
    i2d_transform xa, xb;
    i2d_manifold m;
    if (kind_rank(ta) > kind_rank(tb)) {
        i2d_shape_id s = a;
        i2d_shape_type t = ta;
        a = b, b = s;
        ta = tb, tb = t;
    }
    xa = i2d_body_get_transform(i2d_shape_get_body(a));
    xb = i2d_body_get_transform(i2d_shape_get_body(b));
    memset(&m, 0, sizeof m);
    if (kind_rank(ta) == 0 && kind_rank(tb) == 0) {
        return 0; /* segments never collide */
    }
    if (ta == I2D_SHAPE_CIRCLE) { /* circle against circle: the world-space function has no speculative points */
        i2d_circle ca = i2d_shape_get_circle(a), cb = i2d_shape_get_circle(b);
        i2d_vec2 pa = world_point(xa, ca.center), pb = world_point(xb, cb.center);
        double dx = (double)pb.x - pa.x, dy = (double)pb.y - pa.y;
        return sqrt(dx * dx + dy * dy) - ca.radius - cb.radius <= SPECULATIVE_DISTANCE ? 1 : 0;
    }
    if (kind_rank(ta) == 0) {
        i2d_segment s = i2d_shape_get_segment(a);
        if (tb == I2D_SHAPE_POLYGON) {
            i2d_polygon p = i2d_shape_get_polygon(b);
            m = i2d_collide_segment_polygon(&s, xa, &p, xb);
        } else if (tb == I2D_SHAPE_CAPSULE) {
            i2d_capsule c = i2d_shape_get_capsule(b);
            m = i2d_collide_segment_capsule(&s, xa, &c, xb);
        } else {
            i2d_circle c = i2d_shape_get_circle(b);
            m = i2d_collide_segment_circle(&s, xa, &c, xb);
        }
    } else if (ta == I2D_SHAPE_POLYGON) {
        i2d_polygon p = i2d_shape_get_polygon(a);
        if (tb == I2D_SHAPE_POLYGON) {
            i2d_polygon q = i2d_shape_get_polygon(b);
            m = i2d_collide_polygons(&p, xa, &q, xb);
        } else if (tb == I2D_SHAPE_CAPSULE) {
            i2d_capsule c = i2d_shape_get_capsule(b);
            m = i2d_collide_polygon_capsule(&p, xa, &c, xb);
        } else {
            i2d_circle c = i2d_shape_get_circle(b);
            m = i2d_collide_polygon_circle(&p, xa, &c, xb);
        }
    } else {
        i2d_capsule c = i2d_shape_get_capsule(a);
        if (tb == I2D_SHAPE_CAPSULE) {
            i2d_capsule d = i2d_shape_get_capsule(b);
            m = i2d_collide_capsules(&c, xa, &d, xb);
        } else {
            i2d_circle d = i2d_shape_get_circle(b);
            m = i2d_collide_capsule_circle(&c, xa, &d, xb);
        }
    }
    return i2d_last_status() == I2D_OK ? m.point_count : -1;
}

/* The filter rule of types.h: a shared group decides, else category against mask both ways. */
static bool filters_collide(i2d_filter a, i2d_filter b) {
    if (a.group_index == b.group_index && a.group_index != 0) {
        return a.group_index > 0;
    }
    return (a.category_bits & b.mask_bits) != 0 && (b.category_bits & a.mask_bits) != 0;
}

/* Every pair of shapes with a dynamic body (the scene's dynamic bodies) whose tight bounds come
 * within the speculative distance, counted once. Bodies joined by a joint that does not let them
 * collide are not looked for: in these scenes a shared negative group (rain) or the filter
 * (joint_grid) already keeps them apart. */
static bool count_contacts(const bench_state* state, contact_count* out) {
    i2d_query_filter all = i2d_default_query_filter();
    i2d_shape_id shapes[8];
    i2d_shape_id* found = NULL;
    int32_t found_capacity = 0;
    int32_t i, k, j;
    out->pairs = 0;
    out->points = 0;
    for (i = 0; i < state->body_count; ++i) {
        i2d_body_id body = state->bodies[i];
        int32_t shape_count = i2d_body_get_shapes(body, shapes, 8);
        if (shape_count < 0 || shape_count > 8) {
            free(found);
            return false;
        }
        for (k = 0; k < shape_count; ++k) {
            i2d_shape_id shape = shapes[k];
            i2d_filter filter = i2d_shape_get_filter(shape);
            i2d_aabb box = i2d_shape_get_aabb(shape);
            int32_t n;
            if (i2d_shape_is_sensor(shape)) {
                continue;
            }
            box.min.x -= (float)SPECULATIVE_DISTANCE;
            box.min.y -= (float)SPECULATIVE_DISTANCE;
            box.max.x += (float)SPECULATIVE_DISTANCE;
            box.max.y += (float)SPECULATIVE_DISTANCE;
            n = i2d_world_overlap_aabb_ids(state->world, box, all, found, found_capacity);
            if (n > found_capacity) {
                free(found);
                found_capacity = 2 * n;
                found = (i2d_shape_id*)malloc((size_t)found_capacity * sizeof *found);
                if (!found) {
                    return false;
                }
                n = i2d_world_overlap_aabb_ids(state->world, box, all, found, found_capacity);
            }
            if (n < 0) {
                free(found);
                return false;
            }
            for (j = 0; j < n; ++j) {
                i2d_shape_id other = found[j];
                i2d_body_id other_body = i2d_shape_get_body(other);
                int32_t points;
                if (other_body.bits == body.bits || i2d_shape_is_sensor(other) ||
                    !filters_collide(filter, i2d_shape_get_filter(other))) {
                    continue;
                }
                /* A pair of dynamic shapes is met from both sides: count it from the lower id. */
                if (i2d_body_get_type(other_body) == I2D_BODY_DYNAMIC && other.bits < shape.bits) {
                    continue;
                }
                points = manifold_points(shape, other);
                if (points < 0) {
                    free(found);
                    return false;
                }
                out->pairs += points > 0;
                out->points += points;
            }
        }
    }
    free(found);
    return true;
}

/* ---- Timing --------------------------------------------------------------------------------- */

typedef struct timing {
    double median_ns;
    double min_ns;
} timing;

static timing summarize(double* samples, int32_t n) {
    timing t;
    qsort(samples, (size_t)n, sizeof *samples, bench_compare_doubles);
    t.median_ns = samples[n / 2];
    t.min_ns = samples[0];
    return t;
}

/* What one timed operation needs. */
typedef enum operation {
    OP_SAVE_STATE,
    OP_RESTORE_STATE,
    OP_SAVE_RESTORE_STATE,
    OP_SAVE_SNAPSHOT,
    OP_RESTORE_SNAPSHOT,
    OP_CREATE_FROM_SNAPSHOT,
    OP_COUNT
} operation;

static const char* const op_names[OP_COUNT] = {"save_state", "restore_state", "save+restore_state",
                                               "save_snapshot", "restore_snapshot", "create_from_snapshot"};

typedef struct buffers {
    i2d_world_id world;
    unsigned char* state;        /* the state at the moment measured */
    size_t state_size;
    unsigned char* state_scratch; /* what save_state writes into while timed */
    unsigned char* snapshot;     /* the snapshot at the moment measured */
    size_t snapshot_size;
    unsigned char* snapshot_scratch;
} buffers;

/* Runs one operation once; its duration in ns, or -1 when it failed (the status says why). The
 * world a creation makes is destroyed outside the clock. */
static double run_once(const buffers* b, operation op) {
    double start, end;
    i2d_status status = I2D_OK;
    i2d_world_id created = {0};
    size_t written = 0;
    start = bench_nanoseconds_now();
    switch (op) {
        case OP_SAVE_STATE:
            status = i2d_world_save_state(b->world, b->state_scratch, b->state_size, &written);
            break;
        case OP_RESTORE_STATE: status = i2d_world_restore_state(b->world, b->state, b->state_size); break;
        case OP_SAVE_RESTORE_STATE:
            status = i2d_world_save_state(b->world, b->state_scratch, b->state_size, &written);
            if (status == I2D_OK) {
                status = i2d_world_restore_state(b->world, b->state_scratch, b->state_size);
            }
            break;
        case OP_SAVE_SNAPSHOT:
            status = i2d_world_save_snapshot(b->world, b->snapshot_scratch, b->snapshot_size, &written);
            break;
        case OP_RESTORE_SNAPSHOT:
            status = i2d_world_restore_snapshot(b->world, b->snapshot, b->snapshot_size);
            break;
        case OP_CREATE_FROM_SNAPSHOT:
            created = i2d_world_create_from_snapshot(b->snapshot, b->snapshot_size, NULL);
            break;
        case OP_COUNT: break;
    }
    end = bench_nanoseconds_now();
    if (op == OP_CREATE_FROM_SNAPSHOT) {
        if (I2D_IS_NULL(created) || i2d_world_destroy(created) != I2D_OK) {
            return -1.0;
        }
    }
    return status == I2D_OK ? end - start : -1.0;
}

static bool time_operation(const buffers* b, operation op, int32_t reps, double* samples, timing* out) {
    int32_t r;
    for (r = 0; r < WARM_UP_REPS; ++r) {
        if (run_once(b, op) < 0.0) {
            return false;
        }
    }
    for (r = 0; r < reps; ++r) {
        samples[r] = run_once(b, op);
        if (samples[r] < 0.0) {
            return false;
        }
    }
    *out = summarize(samples, reps);
    return true;
}

/* ---- Checks ---------------------------------------------------------------------------------- */

static uint64_t step_and_hash(i2d_world_id world) {
    int32_t s;
    for (s = 0; s < CHECK_STEPS; ++s) {
        if (i2d_world_step(world, BENCH_TIME_STEP, BENCH_SUBSTEPS) != I2D_OK) {
            return 0;
        }
    }
    return i2d_world_get_state_hash(world);
}

/* From the moment measured (the world is there on entry and on return): the hash after
 * CHECK_STEPS without a restore, and after restoring the state, the snapshot in place and the
 * snapshot as a new world. False when one differs or a call failed. */
static bool check_paths(const buffers* b, const char* when, int* exit_code) {
    uint64_t reference, from_state, from_snapshot, from_new;
    i2d_world_id created;
    reference = step_and_hash(b->world);
    if (i2d_world_restore_state(b->world, b->state, b->state_size) != I2D_OK) {
        *exit_code = EXIT_API_ERROR;
        return false;
    }
    from_state = step_and_hash(b->world);
    if (i2d_world_restore_snapshot(b->world, b->snapshot, b->snapshot_size) != I2D_OK) {
        *exit_code = EXIT_API_ERROR;
        return false;
    }
    from_snapshot = step_and_hash(b->world);
    created = i2d_world_create_from_snapshot(b->snapshot, b->snapshot_size, NULL);
    if (I2D_IS_NULL(created)) {
        *exit_code = EXIT_API_ERROR;
        return false;
    }
    from_new = step_and_hash(created);
    if (i2d_world_destroy(created) != I2D_OK ||
        i2d_world_restore_snapshot(b->world, b->snapshot, b->snapshot_size) != I2D_OK) {
        *exit_code = EXIT_API_ERROR;
        return false;
    }
    if (reference == 0 || from_state != reference || from_snapshot != reference || from_new != reference) {
        fprintf(stderr,
                "impulse2d_snapshot_bench: %s: a restored world went on differently: hash after %d steps %016llx, "
                "from the state %016llx, the snapshot %016llx, a new world %016llx\n",
                when, CHECK_STEPS, (unsigned long long)reference, (unsigned long long)from_state,
                (unsigned long long)from_snapshot, (unsigned long long)from_new);
        *exit_code = EXIT_CHECK_FAILED;
        return false;
    }
    return true;
}

/* ---- One scene ----------------------------------------------------------------------------- */

typedef struct scene_result {
    int32_t steps;
    int32_t bodies;
    int32_t engine_touching; /* i2d_world_counters.contact_count */
    int32_t engine_alive;    /* i2d_world_counters.pair_count */
    contact_count contacts;
    size_t snapshot_size;
    size_t state_size;
    timing times[OP_COUNT];
} scene_result;

static void report_api_error(const char* scene, const char* what) {
    fprintf(stderr, "impulse2d_snapshot_bench: %s: %s failed: %s (%s)\n", scene, what,
            i2d_status_string(i2d_last_status()), i2d_last_error_message());
}

/* The checks and timings, from the moment measured; the buffers are allocated. */
static int measure(const snapshot_scene* scene, const options* opt, buffers* b, double* samples, scene_result* out) {
    int exit_code = EXIT_OK;
    int32_t op;
    if (i2d_world_save_snapshot(b->world, b->snapshot, b->snapshot_size, NULL) != I2D_OK ||
        i2d_world_save_state(b->world, b->state, b->state_size, NULL) != I2D_OK) {
        report_api_error(scene->name, "saving");
        return EXIT_API_ERROR;
    }
    /* A restore of the snapshot makes the world anew: the state is saved again from it, so that
     * the checks and the timings restore a state of the world as it then stands. */
    if (!check_paths(b, scene->name, &exit_code) ||
        i2d_world_save_state(b->world, b->state, b->state_size, NULL) != I2D_OK ||
        !check_paths(b, scene->name, &exit_code)) {
        if (exit_code != EXIT_CHECK_FAILED) {
            report_api_error(scene->name, "a restore");
            exit_code = EXIT_API_ERROR;
        }
        return exit_code;
    }
    if (opt->sizes_only) {
        return EXIT_OK;
    }
    /* Timings, each from the moment measured. */
    for (op = 0; op < OP_COUNT; ++op) {
        if (i2d_world_restore_snapshot(b->world, b->snapshot, b->snapshot_size) != I2D_OK ||
            i2d_world_save_state(b->world, b->state, b->state_size, NULL) != I2D_OK ||
            !time_operation(b, (operation)op, opt->reps, samples, &out->times[op])) {
            report_api_error(scene->name, op_names[op]);
            return EXIT_API_ERROR;
        }
    }
    /* The buffers timed still bring the world back to the same future. */
    if (i2d_world_restore_snapshot(b->world, b->snapshot, b->snapshot_size) != I2D_OK ||
        i2d_world_save_state(b->world, b->state, b->state_size, NULL) != I2D_OK ||
        !check_paths(b, scene->name, &exit_code)) {
        if (exit_code != EXIT_CHECK_FAILED) {
            report_api_error(scene->name, "a restore after the timing");
            exit_code = EXIT_API_ERROR;
        }
        return exit_code;
    }
    return EXIT_OK;
}

/* Builds the scene, steps it to its moment, counts, and measures there. */
static int run_scene(const snapshot_scene* scene, const options* opt, scene_result* out) {
    const bench_scene* bench = bench_find_scene(scene->bench_name);
    bench_state state;
    buffers b;
    double* samples;
    int exit_code;
    int32_t step;
    i2d_world_counters counters;
    memset(&state, 0, sizeof state);
    memset(&b, 0, sizeof b);
    memset(out, 0, sizeof *out);
    out->steps = opt->steps > 0 ? opt->steps : scene->steps;
    if (!bench || !bench->create(&state)) {
        fprintf(stderr, "impulse2d_snapshot_bench: %s: could not build the scene: %s\n", scene->name,
                state.error ? state.error : i2d_last_error_message());
        bench_state_destroy(&state);
        return EXIT_API_ERROR;
    }
    for (step = 0; step < out->steps; ++step) {
        if ((bench->step_hook && !bench->step_hook(&state, step)) ||
            i2d_world_step(state.world, BENCH_TIME_STEP, BENCH_SUBSTEPS) != I2D_OK) {
            report_api_error(scene->name, "a step");
            bench_state_destroy(&state);
            return EXIT_API_ERROR;
        }
    }

    /* Counts and sizes. */
    out->bodies = state.body_count;
    counters = i2d_world_get_counters(state.world);
    out->engine_touching = counters.contact_count;
    out->engine_alive = counters.pair_count;
    if (!count_contacts(&state, &out->contacts)) {
        report_api_error(scene->name, "counting contact points");
        bench_state_destroy(&state);
        return EXIT_API_ERROR;
    }
    b.world = state.world;
    b.state_size = i2d_world_get_state_size(state.world);
    b.snapshot_size = i2d_world_get_snapshot_size(state.world);
    out->state_size = b.state_size;
    out->snapshot_size = b.snapshot_size;
    b.state = (unsigned char*)malloc(b.state_size);
    b.state_scratch = (unsigned char*)malloc(b.state_size);
    b.snapshot = (unsigned char*)malloc(b.snapshot_size);
    b.snapshot_scratch = (unsigned char*)malloc(b.snapshot_size);
    samples = (double*)malloc((size_t)opt->reps * sizeof *samples);
    if (b.state_size == 0 || b.snapshot_size == 0) {
        report_api_error(scene->name, "a size");
        exit_code = EXIT_API_ERROR;
    } else if (!b.state || !b.state_scratch || !b.snapshot || !b.snapshot_scratch || !samples) {
        fprintf(stderr, "impulse2d_snapshot_bench: out of memory\n");
        exit_code = EXIT_API_ERROR;
    } else {
        exit_code = measure(scene, opt, &b, samples, out);
    }
    free(samples);
    free(b.state);
    free(b.state_scratch);
    free(b.snapshot);
    free(b.snapshot_scratch);
    if (!bench_state_destroy(&state) && exit_code == EXIT_OK) {
        exit_code = EXIT_API_ERROR;
    }
    return exit_code;
}

/* ---- Output ---------------------------------------------------------------------------------- */

static void print_sizes_header(void) {
    printf("\nSizes at the step measured (deterministic). points: contact points, counted again from the shapes\n"
           "at the end of the step: the points of every manifold (separation <= 0.02 m, speculative points\n"
           "included, as Box2D counts a contact touching); pairs: shape pairs with such points / the engine's\n"
           "touching pairs (i2d_world_counters.contact_count: a point within the 0.005 m slop when the step\n"
           "ended) / its contacts alive (pair_count: fat bounds overlapping).\n"
           "budget = 64 B x dynamic bodies + 24 B x points (issue 38); ratio = state B / budget B.\n\n");
    printf("%-14s %5s %7s %21s %7s %12s %11s %7s %11s %6s\n", "scene", "steps", "bodies", "pairs pts/touch/alive",
           "points", "snapshot B", "state B", "B/body", "budget B", "ratio");
}

static void print_sizes_row(const snapshot_scene* scene, const scene_result* r) {
    double budget = BUDGET_PER_BODY * r->bodies + BUDGET_PER_POINT * (double)r->contacts.points;
    char pairs[64];
    snprintf(pairs, sizeof pairs, "%lld/%d/%d", (long long)r->contacts.pairs, r->engine_touching, r->engine_alive);
    printf("%-14s %5d %7d %21s %7lld %12zu %11zu %7.1f %11.0f %6.3f\n", scene->name, r->steps, r->bodies, pairs,
           (long long)r->contacts.points, r->snapshot_size, r->state_size,
           r->bodies > 0 ? (double)r->state_size / r->bodies : 0.0, budget,
           budget > 0.0 ? (double)r->state_size / budget : 0.0);
}

static void print_times(const snapshot_scene* scene, const scene_result* r, int32_t reps) {
    const timing* t = r->times;
    const double per_body = r->bodies > 0 ? 1.0 / r->bodies : 0.0;
    int32_t op;
    printf("\n%s (%d steps, %d dynamic bodies; %s): median of %d, after %d untimed\n", scene->name, r->steps,
           r->bodies, scene->note, reps, WARM_UP_REPS);
    printf("  %-22s %12s %12s %12s %10s\n", "operation", "median us", "min us", "ns per body", "GB/s");
    for (op = 0; op < OP_COUNT; ++op) {
        size_t bytes = op <= OP_SAVE_RESTORE_STATE ? r->state_size : r->snapshot_size;
        if (op == OP_SAVE_RESTORE_STATE) {
            bytes *= 2;
        }
        printf("  %-22s %12.2f %12.2f %12.2f %10.2f\n", op_names[op], t[op].median_ns * 1e-3, t[op].min_ns * 1e-3,
               t[op].median_ns * per_body, t[op].median_ns > 0.0 ? (double)bytes / t[op].median_ns : 0.0);
    }
}

int main(int argc, char** argv) {
    options opt;
    scene_result results[SCENE_COUNT];
    int exit_code = EXIT_OK;
    int32_t i;
    memset(results, 0, sizeof results);
    if (!parse_options(argc, argv, &opt)) {
        usage(stderr);
        return EXIT_USAGE;
    }
    if (!bench_check_library_version("impulse2d_snapshot_bench")) {
        return EXIT_API_ERROR;
    }
    if (opt.csv) {
        printf("scene,steps,dynamic_bodies,touching_pairs,touching_points,snapshot_bytes,state_bytes\n");
    } else {
        bench_print_build_line(stdout, "snapshot_bench");
        printf("# sizes and times of snapshots and rollback states, 1 worker, 1/60 s steps with %d substeps;\n"
               "# every buffer is checked: restored and stepped %d times, it gives the hash of the world never "
               "restored\n",
               BENCH_SUBSTEPS, CHECK_STEPS);
    }
    for (i = 0; i < SCENE_COUNT; ++i) {
        int code;
        if (opt.any_chosen && !opt.chosen[i]) {
            continue;
        }
        code = run_scene(&scenes[i], &opt, &results[i]);
        if (code != EXIT_OK) {
            fprintf(stderr, "impulse2d_snapshot_bench: %s: FAILED\n", scenes[i].name);
            exit_code = exit_code == EXIT_OK ? code : exit_code;
            results[i].bodies = -1;
            continue;
        }
        if (opt.csv) {
            printf("%s,%d,%d,%lld,%lld,%zu,%zu\n", scenes[i].name, results[i].steps, results[i].bodies,
                   (long long)results[i].contacts.pairs, (long long)results[i].contacts.points,
                   results[i].snapshot_size, results[i].state_size);
        } else if (!opt.sizes_only) {
            print_times(&scenes[i], &results[i], opt.reps);
        }
        fflush(stdout);
    }
    if (!opt.csv) {
        print_sizes_header();
        for (i = 0; i < SCENE_COUNT; ++i) {
            if ((!opt.any_chosen || opt.chosen[i]) && results[i].bodies >= 0) {
                print_sizes_row(&scenes[i], &results[i]);
            }
        }
        if (!opt.sizes_only) {
            printf("\nTargets (issue 38): state <= budget (ratio <= 1); save+restore of the 1000-body pile (pile_1k) "
                   "<= 15 us;\nsnapshot save and restore >= 1 GB/s (1e9 bytes per second).\n");
        }
    }
    return exit_code;
}
