/* SPDX-License-Identifier: MIT */
/* Benchmark scenes, built through the public C API so that the benchmark measures what users get.
 *
 * A scene is a row of a table: a name, a builder, an optional per-step hook (game logic that is
 * timed with the step, as Box2D's benchmark times its spawning), a default step count and a
 * sanity check whose figure is printed beside the time, so that a fast but broken run shows. */
#ifndef IMPULSE2D_BENCH_SCENES_H
#define IMPULSE2D_BENCH_SCENES_H

#include <impulse2d/impulse2d.h>

/* The world of one run and what its hook and sanity check need to find in it. */
typedef struct bench_state {
    i2d_world_id world;
    i2d_body_id* bodies;     /* the dynamic bodies, in creation order */
    float* start_y;          /* each dynamic body's starting height, m */
    int32_t body_count;
    int32_t body_capacity;
    i2d_aabb region;         /* where every dynamic body must stay (the sanity check) */
    i2d_body_id mover;       /* a kinematic body the hook drives; null when none */
    i2d_vec2 mover_start;
    /* Set when a failure did not come from an i2d_ call (then read i2d_last_error_message()). */
    const char* error;
} bench_state;

typedef struct bench_scene {
    const char* name;
    const char* description;
    int32_t steps;           /* default step count */
    const char* sanity_name; /* what the sanity figure is, with its unit */
    /* Creates the world and the scene in state (zeroed by the caller). False on failure. */
    bool (*create)(bench_state* state);
    /* Runs before world step number `step` (0-based); NULL when the scene has none. */
    bool (*step_hook)(bench_state* state, int32_t step);
    /* After `steps_run` steps: the scene's figure and whether it is sane. False on failure. */
    bool (*sanity)(const bench_state* state, int32_t steps_run, double* figure, bool* sane);
} bench_scene;

extern const bench_scene bench_scenes[];
extern const int32_t bench_scene_count;

/* Destroys the world (if any) and frees the arrays; leaves state zeroed. False if the destroy failed. */
bool bench_state_destroy(bench_state* state);

/* FNV-1a over the bits of every dynamic body's position and velocity, in creation order: equal
 * inputs on the same binary must give equal hashes. False on failure. */
bool bench_state_hash(const bench_state* state, uint64_t* hash);

#endif
