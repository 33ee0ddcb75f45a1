/* SPDX-License-Identifier: MIT */
/* Issue 43's ragdoll heap as a fidelity benchmark: ragdolls dropped in layers of ten onto the
 * ground (as tests/physics/test_joints_ragdoll.cpp drops them), once for each spacing between
 * neighbours in a layer. One heap is one outcome of a chaotic pile-up; the spread over spacings
 * says what the engine does, the single test scene only what it did once.
 *
 * For each spacing it prints the widest joint gap (the distance between a joint's two anchors
 * in the world, after each step) with the step and joint where it was, how many steps the
 * widest gap of the heap stayed above 20 mm and above 60 mm (a joint held open that long
 * likely has another ragdoll's limb between its bodies: 60 mm is about an arm's thickness),
 * and when every body slept. Deterministic: the same figures on every run.
 *
 * Usage: impulse2d_ragdoll_heap [--count N] [--spacings S,S,...] [--height H] [--seconds T]
 *                               [--no-continuous]
 *   --count N          ragdolls, 1..1000; default 100 (ten layers)
 *   --spacings LIST    metres between neighbours in a layer, each 0.3..2; default
 *                      0.78,0.79,0.8,0.81,0.82,0.83,0.85
 *   --height H         metres from the ground to the lowest layer's feet, 0..100; default 2
 *                      (--count 1 --height 20: one ragdoll landing at 20 m/s, no heap)
 *   --seconds T        the longest a heap is stepped waiting for sleep, 1..600; default 30
 *   --no-continuous    continuous collision off
 * Exit status: 0 every heap ran, 2 bad usage, 3 an i2d call failed. Never an assertion on the
 * figures: the physics tests hold the bounds. */

#include <impulse2d/impulse2d.h>

#include "arguments.h"
#include "build_info.h"
#include "ragdoll.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { EXIT_OK = 0, EXIT_USAGE = 2, EXIT_API_ERROR = 3 };

#define MAX_RAGDOLLS 1000
#define MAX_SPACINGS 32
#define PER_LAYER 10
#define SUBSTEPS 4

static const float time_step = 1.0f / 60.0f;
static const float layer_height = 2.0f; /* m between layers */
static const float feet_above_spawn = 0.275f; /* m: where bench_ragdoll_create puts the feet */
static const double held_open_gap = 0.06;     /* m: about an arm's thickness */
static const double open_gap = 0.02;          /* m */
static const float min_spacing = 0.3f, max_spacing = 2.0f; /* m */
static const double max_height = 100.0;                     /* m */

typedef struct options {
    int32_t count;
    int32_t seconds;
    float height; /* m: the lowest layer's feet above the ground */
    bool continuous;
    int32_t spacing_count;
    float spacings[MAX_SPACINGS];
} options;

typedef struct heap_result {
    double widest_gap; /* m */
    int32_t widest_step, widest_ragdoll, widest_bone;
    int32_t steps_open, steps_held_open; /* steps whose widest gap passed open_gap, held_open_gap */
    int32_t asleep_step;                 /* -1: still awake when the time ran out */
} heap_result;

static bool parse_spacings(const char* text, options* opt) {
    char* end = NULL;
    opt->spacing_count = 0;
    if (!text) {
        return false;
    }
    for (;;) {
        const double value = strtod(text, &end);
        if (end == text || !(value >= min_spacing && value <= max_spacing) || opt->spacing_count == MAX_SPACINGS) {
            return false;
        }
        opt->spacings[opt->spacing_count++] = (float)value;
        if (*end == '\0') {
            return true;
        }
        if (*end != ',') {
            return false;
        }
        text = end + 1;
    }
}

static bool parse_height(const char* text, float* out) {
    char* end = NULL;
    const double value = text ? strtod(text, &end) : -1.0;
    if (!text || end == text || *end != '\0' || !(value >= 0.0 && value <= max_height)) {
        return false;
    }
    *out = (float)value;
    return true;
}

static bool parse_options(int argc, char** argv, options* opt) {
    int i;
    opt->count = 100;
    opt->seconds = 30;
    opt->height = 2.0f;
    opt->continuous = true;
    parse_spacings("0.78,0.79,0.8,0.81,0.82,0.83,0.85", opt);
    for (i = 1; i < argc; ++i) {
        const char* arg = argv[i];
        const char* value = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(arg, "--count") == 0 && bench_parse_int(value, 1, MAX_RAGDOLLS, &opt->count)) {
            ++i;
        } else if (strcmp(arg, "--seconds") == 0 && bench_parse_int(value, 1, 600, &opt->seconds)) {
            ++i;
        } else if (strcmp(arg, "--spacings") == 0 && parse_spacings(value, opt)) {
            ++i;
        } else if (strcmp(arg, "--height") == 0 && parse_height(value, &opt->height)) {
            ++i;
        } else if (strcmp(arg, "--no-continuous") == 0) {
            opt->continuous = false;
        } else {
            fprintf(stderr,
                    "usage: impulse2d_ragdoll_heap [--count 1..%d] [--spacings S,S,... (each %.1f..%.1f m)] "
                    "[--height 0..%.0f m] [--seconds 1..600] [--no-continuous]\n",
                    MAX_RAGDOLLS, (double)min_spacing, (double)max_spacing, max_height);
            return false;
        }
    }
    return true;
}

static double joint_gap(i2d_joint_id joint) {
    const i2d_vec2 a = i2d_body_get_world_point(i2d_joint_get_body_a(joint), i2d_joint_get_local_anchor_a(joint));
    const i2d_vec2 b = i2d_body_get_world_point(i2d_joint_get_body_b(joint), i2d_joint_get_local_anchor_b(joint));
    return hypot((double)a.x - (double)b.x, (double)a.y - (double)b.y);
}

/* A world with a ground 100 m wide and count ragdolls in layers, each its own filter group. */
static i2d_world_id build_heap(const options* opt, float spacing, bench_ragdoll* dolls) {
    i2d_world_def world_def = i2d_default_world_def();
    i2d_body_def ground_def = i2d_default_body_def();
    i2d_shape_def ground_shape = i2d_default_shape_def();
    i2d_world_id world;
    i2d_body_id ground;
    int32_t i;
    world_def.enable_continuous = opt->continuous;
    world = i2d_world_create(&world_def);
    ground_def.position = (i2d_vec2){0.0f, -0.5f};
    ground = i2d_body_create(world, &ground_def);
    if (I2D_IS_NULL(ground) || I2D_IS_NULL(i2d_shape_create_box(ground, &ground_shape, 50.0f, 0.5f))) {
        return world;
    }
    for (i = 0; i < opt->count; ++i) {
        const int32_t layer = i / PER_LAYER, column = i % PER_LAYER;
        const i2d_vec2 spawn = {spacing * ((float)column - 0.5f * (float)(PER_LAYER - 1)),
                                opt->height + layer_height * (float)layer - feet_above_spawn};
        const bench_ragdoll_def def = bench_default_ragdoll_def(spawn, i + 1);
        if (!bench_ragdoll_create(world, &def, &dolls[i])) {
            i2d_world_destroy(world);
            return (i2d_world_id){0};
        }
    }
    return world;
}

/* The widest gap of the heap after this step, and where. */
static double widest_gap_now(const bench_ragdoll* dolls, int32_t count, int32_t* ragdoll, int32_t* bone) {
    double widest = 0.0;
    int32_t i, b;
    for (i = 0; i < count; ++i) {
        for (b = 1; b < BENCH_BONE_COUNT; ++b) {
            const double gap = joint_gap(dolls[i].joints[b]);
            if (gap > widest) {
                widest = gap;
                *ragdoll = i;
                *bone = b;
            }
        }
    }
    return widest;
}

static bool run_heap(const options* opt, float spacing, heap_result* out) {
    static bench_ragdoll dolls[MAX_RAGDOLLS];
    const int32_t steps = (int32_t)lround(opt->seconds / (double)time_step);
    const i2d_world_id world = build_heap(opt, spacing, dolls);
    int32_t k;
    memset(out, 0, sizeof *out);
    out->asleep_step = -1;
    if (I2D_IS_NULL(world) || i2d_world_get_counters(world).body_count != 1 + opt->count * BENCH_BONE_COUNT) {
        if (!I2D_IS_NULL(world)) {
            i2d_world_destroy(world);
        }
        return false;
    }
    for (k = 1; k <= steps; ++k) {
        int32_t ragdoll = -1, bone = -1;
        double gap;
        if (i2d_world_step(world, time_step, SUBSTEPS) != I2D_OK) {
            i2d_world_destroy(world);
            return false;
        }
        gap = widest_gap_now(dolls, opt->count, &ragdoll, &bone);
        out->steps_open += gap > open_gap;
        out->steps_held_open += gap > held_open_gap;
        if (gap > out->widest_gap) {
            out->widest_gap = gap;
            out->widest_step = k;
            out->widest_ragdoll = ragdoll;
            out->widest_bone = bone;
        }
        if (i2d_world_get_counters(world).awake_body_count == 0) {
            out->asleep_step = k;
            break;
        }
    }
    i2d_world_destroy(world);
    return true;
}

static const char* bone_name(int32_t bone) {
    static const char* const names[BENCH_BONE_COUNT] = {"hip",       "torso",          "head",
                                                        "upper leg", "lower leg",      "upper leg",
                                                        "lower leg", "upper arm",      "lower arm",
                                                        "upper arm", "lower arm"};
    return bone >= 0 && bone < BENCH_BONE_COUNT ? names[bone] : "-";
}

int main(int argc, char** argv) {
    options opt;
    int32_t s;
    if (!bench_check_library_version("impulse2d_ragdoll_heap")) {
        return EXIT_API_ERROR;
    }
    if (!parse_options(argc, argv, &opt)) {
        return EXIT_USAGE;
    }
    bench_print_build_line(stdout, "impulse2d_ragdoll_heap");
    printf("# %d ragdolls in layers of %d, %.0f m apart from %.1f m up; 1/60 s steps, %d substeps; continuous "
           "collision %s; up to %d s\n",
           (int)opt.count, PER_LAYER, (double)layer_height, (double)opt.height, SUBSTEPS,
           opt.continuous ? "on" : "off", (int)opt.seconds);
    printf("# widest: the widest joint gap after any step (anchors' distance), at that step and joint (the bone\n"
           "# the joint holds); >20/>60 mm: steps whose widest gap passed 20 or 60 mm (60: a limb's thickness)\n");
    printf("spacing_m  widest_mm  step  ragdoll  bone        steps>20mm  steps>60mm  asleep_s\n");
    for (s = 0; s < opt.spacing_count; ++s) {
        heap_result r;
        if (!run_heap(&opt, opt.spacings[s], &r)) {
            fprintf(stderr, "impulse2d_ragdoll_heap: spacing %.2f: %s\n", (double)opt.spacings[s],
                    i2d_last_error_message());
            return EXIT_API_ERROR;
        }
        printf("%9.2f  %9.2f  %4d  %7d  %-10s  %10d  %10d  ", (double)opt.spacings[s], 1000.0 * r.widest_gap,
               (int)r.widest_step, (int)r.widest_ragdoll, bone_name(r.widest_bone), (int)r.steps_open,
               (int)r.steps_held_open);
        if (r.asleep_step > 0) {
            printf("%8.2f\n", r.asleep_step * (double)time_step);
        } else {
            printf("   awake\n");
        }
    }
    return EXIT_OK;
}
