/* SPDX-License-Identifier: MIT */
/* The debug draw benchmark: the time of i2d_world_draw on a bench scene (large_pyramid by
 * default) with counting callbacks, against issue 39's target (large_pyramid in at most 0.5 ms).
 *
 * Method: the scene is built by its bench/scenes.c builder and stepped (hook + world step, as
 * impulse2d_bench runs it) to a fixed moment. Every callback of the def is set and only counts,
 * so that what is timed is the engine's walk and the calls, not a renderer. Three passes are
 * timed: the default def (shapes and joints), everything drawn (every flag on), and the default
 * culled to a box around a tenth of the scene's width at its middle. Each is run 20 times untimed,
 * then `--reps` times (default 201), each call timed alone with a monotonic clock; the median is
 * printed with the minimum. The counts are checked before any timing: the default pass must see
 * every shape once, and the culled one fewer shapes but some. Times are never asserted on. */

#include "arguments.h"
#include "build_info.h"
#include "timing.h"
#include "scenes.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { EXIT_OK = 0, EXIT_CHECK_FAILED = 1, EXIT_USAGE = 2, EXIT_API_ERROR = 3 };

#define WARM_UP_REPS 20
#define MAX_REPS 100001
#define DEFAULT_REPS 201
#define DEFAULT_STEPS 120     /* large_pyramid has settled by then (snapshot_bench.c) */
#define CULLED_SHARE 0.1f     /* the culled box's width and height, of the scene's bounds */
#define TARGET_MS 0.5         /* issue 39: large_pyramid drawn in at most this */

/* ---- Counting callbacks ------------------------------------------------------------------------ */

typedef struct counts {
    long long shapes;  /* solid polygons, circles and capsules */
    long long lines;   /* segments */
    long long other;   /* outlines, circles, frames, points, text */
} counts;

static void count_polygon(const i2d_vec2* v, int32_t n, i2d_color c, void* context) {
    (void)v, (void)n, (void)c;
    ++((counts*)context)->other;
}
static void count_solid_polygon(i2d_transform xf, const i2d_vec2* v, int32_t n, float r, i2d_color c, void* context) {
    (void)xf, (void)v, (void)n, (void)r, (void)c;
    ++((counts*)context)->shapes;
}
static void count_circle(i2d_vec2 p, float r, i2d_color c, void* context) {
    (void)p, (void)r, (void)c;
    ++((counts*)context)->other;
}
static void count_solid_circle(i2d_transform xf, float r, i2d_color c, void* context) {
    (void)xf, (void)r, (void)c;
    ++((counts*)context)->shapes;
}
static void count_solid_capsule(i2d_vec2 p1, i2d_vec2 p2, float r, i2d_color c, void* context) {
    (void)p1, (void)p2, (void)r, (void)c;
    ++((counts*)context)->shapes;
}
static void count_segment(i2d_vec2 p1, i2d_vec2 p2, i2d_color c, void* context) {
    (void)p1, (void)p2, (void)c;
    ++((counts*)context)->lines;
}
static void count_transform(i2d_transform xf, void* context) {
    (void)xf;
    ++((counts*)context)->other;
}
static void count_point(i2d_vec2 p, float size, i2d_color c, void* context) {
    (void)p, (void)size, (void)c;
    ++((counts*)context)->other;
}
static void count_string(i2d_vec2 p, const char* text, i2d_color c, void* context) {
    (void)p, (void)text, (void)c;
    ++((counts*)context)->other;
}

static i2d_debug_draw counting_draw(counts* into) {
    i2d_debug_draw d = i2d_default_debug_draw();
    d.draw_polygon = count_polygon;
    d.draw_solid_polygon = count_solid_polygon;
    d.draw_circle = count_circle;
    d.draw_solid_circle = count_solid_circle;
    d.draw_solid_capsule = count_solid_capsule;
    d.draw_segment = count_segment;
    d.draw_transform = count_transform;
    d.draw_point = count_point;
    d.draw_string = count_string;
    d.context = into;
    return d;
}

/* ---- The passes -------------------------------------------------------------------------------- */

typedef enum pass { PASS_DEFAULT, PASS_EVERYTHING, PASS_CULLED, PASS_COUNT } pass;

static const char* const pass_names[PASS_COUNT] = {"shapes+joints", "every flag", "culled (a tenth)"};

/* The def of a pass; bounds: the scene's shapes' bounds. */
static i2d_debug_draw pass_draw(pass p, counts* into, i2d_aabb bounds) {
    i2d_debug_draw d = counting_draw(into);
    if (p == PASS_EVERYTHING) {
        d.draw_joint_extras = d.draw_bounds = d.draw_mass = d.draw_contacts = true;
        d.draw_contact_normals = d.draw_contact_impulses = d.draw_friction_impulses = true;
        d.draw_graph_colors = d.draw_islands = true;
    } else if (p == PASS_CULLED) {
        float cx = 0.5f * (bounds.min.x + bounds.max.x), cy = 0.5f * (bounds.min.y + bounds.max.y);
        float hx = 0.5f * CULLED_SHARE * (bounds.max.x - bounds.min.x);
        float hy = 0.5f * CULLED_SHARE * (bounds.max.y - bounds.min.y);
        d.use_drawing_bounds = true;
        d.drawing_bounds.min.x = cx - hx;
        d.drawing_bounds.min.y = cy - hy;
        d.drawing_bounds.max.x = cx + hx;
        d.drawing_bounds.max.y = cy + hy;
    }
    return d;
}

/* The union of every dynamic body's shapes' bounds (the scene's extent). */
static bool scene_bounds(const bench_state* state, i2d_aabb* out) {
    int32_t i, k;
    bool any = false;
    for (i = 0; i < state->body_count; ++i) {
        i2d_shape_id shapes[8];
        int32_t n = i2d_body_get_shapes(state->bodies[i], shapes, 8);
        if (n < 0) {
            return false;
        }
        for (k = 0; k < n && k < 8; ++k) {
            i2d_aabb a = i2d_shape_get_aabb(shapes[k]);
            if (!any) {
                *out = a;
                any = true;
            }
            out->min.x = a.min.x < out->min.x ? a.min.x : out->min.x;
            out->min.y = a.min.y < out->min.y ? a.min.y : out->min.y;
            out->max.x = a.max.x > out->max.x ? a.max.x : out->max.x;
            out->max.y = a.max.y > out->max.y ? a.max.y : out->max.y;
        }
    }
    return any;
}

/* ---- Timing ------------------------------------------------------------------------------------ */

/* Median and minimum of reps timed calls after the untimed ones; false when a call failed. */
static bool time_pass(i2d_world_id world, const i2d_debug_draw* d, int32_t reps, double* samples, double* median,
                      double* minimum) {
    int32_t r;
    for (r = 0; r < WARM_UP_REPS; ++r) {
        if (i2d_world_draw(world, d) != I2D_OK) {
            return false;
        }
    }
    for (r = 0; r < reps; ++r) {
        double start = bench_nanoseconds_now();
        i2d_status status = i2d_world_draw(world, d);
        samples[r] = bench_nanoseconds_now() - start;
        if (status != I2D_OK) {
            return false;
        }
    }
    qsort(samples, (size_t)reps, sizeof *samples, bench_compare_doubles);
    *median = samples[reps / 2];
    *minimum = samples[0];
    return true;
}

/* ---- The run ----------------------------------------------------------------------------------- */

typedef struct options {
    const char* scene;
    int32_t reps;
    int32_t steps;
} options;

static void usage(FILE* f) {
    fprintf(f,
            "usage: impulse2d_draw_bench [--scene NAME] [--reps R] [--steps N]\n"
            "  --scene NAME  a bench scene (impulse2d_bench --list); default large_pyramid\n"
            "  --reps R      timed draws of each pass, 1..%d; default %d (the median is printed)\n"
            "  --steps N     steps before the measurement, 0..100000; default %d\n"
            "exit status: 0 the counts were right, 1 they were not, 2 bad usage, 3 an i2d call failed\n",
            MAX_REPS, DEFAULT_REPS, DEFAULT_STEPS);
}

static bool parse_options(int argc, char** argv, options* opt) {
    int i;
    opt->scene = "large_pyramid";
    opt->reps = DEFAULT_REPS;
    opt->steps = DEFAULT_STEPS;
    for (i = 1; i < argc; ++i) {
        const char* arg = argv[i];
        const char* value = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(arg, "--reps") == 0 && bench_parse_int(value, 1, MAX_REPS, &opt->reps)) {
            ++i;
        } else if (strcmp(arg, "--steps") == 0 && bench_parse_int(value, 0, 100000, &opt->steps)) {
            ++i;
        } else if (strcmp(arg, "--scene") == 0 && value) {
            opt->scene = value;
            ++i;
        } else if (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0) {
            usage(stdout);
            exit(EXIT_OK);
        } else {
            fprintf(stderr, "impulse2d_draw_bench: bad argument '%s'\n", arg);
            return false;
        }
    }
    return true;
}

static int api_error(const char* what) {
    fprintf(stderr, "impulse2d_draw_bench: %s failed: %s (%s)\n", what, i2d_status_string(i2d_last_status()),
            i2d_last_error_message());
    return EXIT_API_ERROR;
}

/* One untimed draw of each pass: the default sees every shape once, the culled pass some but
 * fewer. */
static int check_counts(i2d_world_id world, i2d_aabb bounds, counts* seen) {
    int32_t p;
    i2d_world_counters counters = i2d_world_get_counters(world);
    for (p = 0; p < PASS_COUNT; ++p) {
        i2d_debug_draw d = pass_draw((pass)p, &seen[p], bounds);
        memset(&seen[p], 0, sizeof seen[p]);
        if (i2d_world_draw(world, &d) != I2D_OK) {
            return api_error("i2d_world_draw");
        }
    }
    if (seen[PASS_DEFAULT].shapes + seen[PASS_DEFAULT].lines < counters.shape_count ||
        seen[PASS_CULLED].shapes <= 0 || seen[PASS_CULLED].shapes >= seen[PASS_DEFAULT].shapes) {
        fprintf(stderr, "impulse2d_draw_bench: wrong counts: %lld shapes and %lld lines of %d shapes, %lld culled\n",
                seen[PASS_DEFAULT].shapes, seen[PASS_DEFAULT].lines, (int)counters.shape_count,
                seen[PASS_CULLED].shapes);
        return EXIT_CHECK_FAILED;
    }
    return EXIT_OK;
}

static int measure(const bench_state* state, const options* opt) {
    counts seen[PASS_COUNT], sink;
    i2d_aabb bounds;
    double* samples;
    int32_t p;
    int code;
    if (!scene_bounds(state, &bounds)) {
        return api_error("reading the scene's bounds");
    }
    code = check_counts(state->world, bounds, seen);
    if (code != EXIT_OK) {
        return code;
    }
    samples = (double*)malloc((size_t)opt->reps * sizeof *samples);
    if (!samples) {
        fprintf(stderr, "impulse2d_draw_bench: out of memory\n");
        return EXIT_API_ERROR;
    }
    printf("%s after %d steps: %d bodies; median of %d draws after %d untimed\n", opt->scene, opt->steps,
           (int)state->body_count, opt->reps, WARM_UP_REPS);
    printf("  %-18s %10s %10s %10s %10s %10s\n", "pass", "median ms", "min ms", "shapes", "lines", "other");
    for (p = 0; p < PASS_COUNT; ++p) {
        i2d_debug_draw d = pass_draw((pass)p, &sink, bounds);
        double median = 0.0, minimum = 0.0;
        if (!time_pass(state->world, &d, opt->reps, samples, &median, &minimum)) {
            free(samples);
            return api_error("i2d_world_draw");
        }
        printf("  %-18s %10.4f %10.4f %10lld %10lld %10lld\n", pass_names[p], median * 1e-6, minimum * 1e-6,
               seen[p].shapes, seen[p].lines, seen[p].other);
    }
    free(samples);
    printf("Target (issue 39): large_pyramid, shapes+joints, at most %.1f ms.\n", TARGET_MS);
    return EXIT_OK;
}

int main(int argc, char** argv) {
    options opt;
    bench_state state;
    const bench_scene* scene;
    int32_t step;
    int code;
    if (!parse_options(argc, argv, &opt)) {
        usage(stderr);
        return EXIT_USAGE;
    }
    if (!bench_check_library_version("impulse2d_draw_bench")) {
        return EXIT_API_ERROR;
    }
    scene = bench_find_scene(opt.scene);
    if (!scene) {
        fprintf(stderr, "impulse2d_draw_bench: no scene '%s'\n", opt.scene);
        return EXIT_USAGE;
    }
    bench_print_build_line(stdout, "draw_bench");
    memset(&state, 0, sizeof state);
    if (!scene->create(&state)) {
        fprintf(stderr, "impulse2d_draw_bench: %s: could not build the scene: %s\n", opt.scene,
                state.error ? state.error : i2d_last_error_message());
        bench_state_destroy(&state);
        return EXIT_API_ERROR;
    }
    for (step = 0; step < opt.steps; ++step) {
        if ((scene->step_hook && !scene->step_hook(&state, step)) ||
            i2d_world_step(state.world, BENCH_TIME_STEP, BENCH_SUBSTEPS) != I2D_OK) {
            bench_state_destroy(&state);
            return api_error("a step");
        }
    }
    code = measure(&state, &opt);
    if (!bench_state_destroy(&state) && code == EXIT_OK) {
        code = EXIT_API_ERROR;
    }
    return code;
}
