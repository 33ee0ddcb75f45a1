/* SPDX-License-Identifier: MIT */
/* Many small worlds, as reinforcement learning steps them: the time per world step of
 * count lander-sized worlds stepped in turn with i2d_world_step, then all in one
 * i2d_worlds_step call on 1, 2 and (if the machine has them) 4 workers.
 *
 * A world: a ground of ten static segments, a hexagon lander on two legs held by revolute
 * joints with limits and motors, resting on the ground, and eight debris circles falling
 * onto it, so each step has contacts, joints and bodies awake (sleep is off, as an
 * environment that keeps acting never lets its bodies sleep). Each way is timed over
 * steps_per_round steps, rounds times, alternating, and the median round is printed as
 * microseconds per world step, with the speed-up of each batch over stepping in turn; the
 * final state hashes of all ways are compared (they must agree: exit 1 otherwise). Times
 * are never asserted on.
 *
 * Usage: impulse2d_batch_bench [world_count (default 256)] [rounds (default 5)] */

#include <impulse2d/impulse2d.h>

#include "arguments.h"
#include "build_info.h"
#include "timing.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

enum { EXIT_OK = 0, EXIT_CHECK_FAILED = 1, EXIT_USAGE = 2, EXIT_API_ERROR = 3 };

#define MAX_WORLDS 4096
#define MAX_ROUNDS 99
#define STEPS_PER_ROUND 60
#define SETTLE_STEPS 30
#define SUBSTEPS 4
#define GROUND_SEGMENTS 10
#define DEBRIS 8
#define WAYS 4 /* in turn, then batches of 1, 2 and 4 workers */

static const float dt = 1.0f / 60.0f;
static const int32_t batch_workers[WAYS] = {0, 1, 2, 4};

static i2d_body_id add_body(i2d_world_id world, i2d_body_type type, float x, float y) {
    i2d_body_def def = i2d_default_body_def();
    def.type = type;
    def.position = (i2d_vec2){x, y};
    return i2d_body_create(world, &def);
}

static void add_leg(i2d_world_id world, i2d_body_id lander, float side, const i2d_shape_def* shape) {
    i2d_body_id leg = add_body(world, I2D_BODY_DYNAMIC, side * 0.6f, 0.5f);
    i2d_shape_create_box(leg, shape, 0.08f, 0.35f);
    i2d_revolute_joint_def hinge = i2d_default_revolute_joint_def();
    hinge.base.body_a = lander;
    hinge.base.body_b = leg;
    hinge.base.local_anchor_a = (i2d_vec2){side * 0.5f, -0.3f};
    hinge.base.local_anchor_b = (i2d_vec2){0.0f, 0.35f};
    hinge.enable_limit = true;
    hinge.lower_angle = -0.6f;
    hinge.upper_angle = 0.6f;
    hinge.enable_motor = true;
    hinge.max_motor_torque = 40.0f;
    hinge.motor_speed = 0.3f * side;
    i2d_joint_create_revolute(world, &hinge);
}

static i2d_world_id make_lander_world(int32_t seed) {
    i2d_world_def world_def = i2d_default_world_def();
    world_def.enable_sleep = false;
    i2d_world_id world = i2d_world_create(&world_def);
    i2d_shape_def shape = i2d_default_shape_def();
    i2d_body_id ground = add_body(world, I2D_BODY_STATIC, 0.0f, 0.0f);
    for (int32_t k = 0; k < GROUND_SEGMENTS; ++k) {
        const float x0 = -10.0f + 2.0f * (float)k, wobble = 0.05f * (float)((seed + k) % 5);
        const i2d_vec2 end = {x0 + 2.0f, 0.05f * (float)((seed + k + 1) % 5)};
        i2d_shape_create_segment(ground, &shape, (i2d_vec2){x0, wobble}, end);
    }
    i2d_body_id lander = add_body(world, I2D_BODY_DYNAMIC, 0.0f, 1.3f);
    const i2d_vec2 hexagon[6] = {{-0.5f, -0.3f}, {0.5f, -0.3f}, {0.7f, 0.0f}, {0.4f, 0.4f}, {-0.4f, 0.4f}, {-0.7f, 0.0f}};
    i2d_shape_create_polygon(lander, &shape, hexagon, 6);
    add_leg(world, lander, -1.0f, &shape);
    add_leg(world, lander, 1.0f, &shape);
    for (int32_t k = 0; k < DEBRIS; ++k) {
        i2d_body_id debris = add_body(world, I2D_BODY_DYNAMIC, -3.0f + 0.8f * (float)k, 2.0f + 0.3f * (float)(k % 3));
        i2d_circle circle = {{0.0f, 0.0f}, 0.1f + 0.02f * (float)((seed + k) % 4)};
        i2d_shape_create_circle(debris, &shape, &circle);
    }
    return world;
}

static bool step_way(const i2d_world_id* worlds, int32_t count, int32_t workers) {
    if (workers == 0) {
        for (int32_t w = 0; w < count; ++w) {
            if (i2d_world_step(worlds[w], dt, SUBSTEPS) != I2D_OK) {
                return false;
            }
        }
        return true;
    }
    i2d_batch_def def = i2d_default_batch_def();
    def.worker_count = workers;
    return i2d_worlds_step(worlds, count, dt, SUBSTEPS, &def) == I2D_OK;
}

static bool parse_arguments(int argc, char** argv, int32_t* count, int32_t* rounds) {
    *count = 256;
    *rounds = 5;
    if (argc > 3 || (argc > 1 && !bench_parse_int(argv[1], 1, MAX_WORLDS / WAYS, count)) ||
        (argc > 2 && !bench_parse_int(argv[2], 1, MAX_ROUNDS, rounds))) {
        fprintf(stderr, "usage: impulse2d_batch_bench [world_count 1..%d] [rounds 1..%d]\n", MAX_WORLDS / WAYS,
                MAX_ROUNDS);
        return false;
    }
    return true;
}

int main(int argc, char** argv) {
    int32_t count = 0, rounds = 0;
    if (!bench_check_library_version("impulse2d_batch_bench")) {
        return EXIT_API_ERROR;
    }
    if (!parse_arguments(argc, argv, &count, &rounds)) {
        return EXIT_USAGE;
    }
    bench_print_build_line(stdout, "impulse2d_batch_bench");
    static i2d_world_id worlds[WAYS][MAX_WORLDS / WAYS];
    for (int32_t way = 0; way < WAYS; ++way) {
        for (int32_t w = 0; w < count; ++w) {
            worlds[way][w] = make_lander_world(w);
        }
        for (int32_t s = 0; s < SETTLE_STEPS; ++s) {
            step_way(worlds[way], count, batch_workers[way]);
        }
    }
    static double micros[WAYS][MAX_ROUNDS];
    for (int32_t r = 0; r < rounds; ++r) {
        for (int32_t way = 0; way < WAYS; ++way) {
            const double start = bench_seconds_now();
            for (int32_t s = 0; s < STEPS_PER_ROUND; ++s) {
                if (!step_way(worlds[way], count, batch_workers[way])) {
                    fprintf(stderr, "step refused: %s\n", i2d_last_error_message());
                    return EXIT_API_ERROR;
                }
            }
            micros[way][r] = 1e6 * (bench_seconds_now() - start) / ((double)STEPS_PER_ROUND * count);
        }
    }
    printf("%d lander worlds (%d bodies, 2 joints each), %d rounds of %d steps, median us per world step:\n",
           (int)count, 3 + DEBRIS, (int)rounds, STEPS_PER_ROUND);
    const double in_turn = bench_sort_median(micros[0], rounds);
    printf("  in turn (i2d_world_step)       %8.3f\n", in_turn);
    for (int32_t way = 1; way < WAYS; ++way) {
        const double batched = bench_sort_median(micros[way], rounds);
        printf("  one batch, %d worker%s          %8.3f  (%.2fx in turn)\n", (int)batch_workers[way],
               batch_workers[way] == 1 ? " " : "s", batched, in_turn / batched);
    }
    int32_t differing = 0;
    for (int32_t w = 0; w < count; ++w) {
        const uint64_t hash = i2d_world_get_state_hash(worlds[0][w]);
        for (int32_t way = 1; way < WAYS; ++way) {
            differing += i2d_world_get_state_hash(worlds[way][w]) != hash;
        }
    }
    printf("final state hashes: %s\n", differing == 0 ? "the same in every way" : "DIFFER");
    for (int32_t way = 0; way < WAYS; ++way) {
        for (int32_t w = 0; w < count; ++w) {
            i2d_world_destroy(worlds[way][w]);
        }
    }
    return differing == 0 ? EXIT_OK : EXIT_CHECK_FAILED;
}
