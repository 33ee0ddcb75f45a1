/* SPDX-License-Identifier: MIT */
/* The character mover benchmark: the time per i2d_world_move_character call in a platformer
 * level of 1,000 static shapes and 100 dynamic ones (issue 39's target: at most 2 us a call).
 *
 * The level: a ground of 400 one-metre tiles, 200 low steps on it (0.1 to 0.25 m high, which
 * the characters step onto), 200 platforms and 200 bricks above it, all static; 100 crates
 * dropped on the ground and left to settle. Characters (capsules 1.8 m tall, radius 0.3,
 * the default character def: they step, snap and push crates) walk along it at 4 m/s as a
 * game moves them at 60 Hz: gravity while airborne, the returned velocity fed back, turning
 * round when a wall stops them. Each frame steps the world (untimed), then moves every
 * character; the moves of a frame are timed together with a monotonic clock and divided by
 * the character count. Printed: the median, the 90th percentile and the least over the frames,
 * and what the moves met: the share of moves that ended on the ground, the shapes a move
 * touched, and how much of the walk the level let through (walls and crates stop some).
 * Times are never asserted on. */

#include <impulse2d/impulse2d.h>

#include "arguments.h"
#include "build_info.h"
#include "timing.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { EXIT_OK = 0, EXIT_CHECK_FAILED = 1, EXIT_USAGE = 2, EXIT_API_ERROR = 3 };

#define GROUND_TILES 400
#define LOW_STEPS 200
#define PLATFORMS 200
#define BRICKS 200
#define CRATES 100
#define MAX_CHARACTERS 256
#define MAX_FRAMES 100000
#define SETTLE_STEPS 120
#define SUBSTEPS 4
#define WALK_SPEED 4.0f
#define GRAVITY 10.0f

static const float dt = 1.0f / 60.0f;

typedef struct options {
    int32_t frames;
    int32_t characters;
} options;

typedef struct character {
    i2d_vec2 position;
    i2d_vec2 velocity;
    float direction; /* +1 right, -1 left */
    i2d_character_result last;
} character;

/* splitmix64: the same level on every platform. */
static uint64_t g_seed = 0x5EEDu;
static double next_unit(void) {
    uint64_t z = (g_seed += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    z ^= z >> 31;
    return (double)(z >> 11) / 9007199254740992.0;
}
static float uniform(float lo, float hi) { return lo + (hi - lo) * (float)next_unit(); }

static void usage(FILE* f) {
    fprintf(f,
            "usage: impulse2d_mover_bench [--frames N] [--characters K]\n"
            "  --frames N      frames timed, 1..%d; default 600\n"
            "  --characters K  characters moved each frame, 1..%d; default 16\n",
            MAX_FRAMES, MAX_CHARACTERS);
}

static bool parse_options(int argc, char** argv, options* opt) {
    opt->frames = 600;
    opt->characters = 16;
    for (int i = 1; i < argc; i += 2) {
        const char* value = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(argv[i], "--frames") == 0 && bench_parse_int(value, 1, MAX_FRAMES, &opt->frames)) {
            continue;
        }
        if (strcmp(argv[i], "--characters") == 0 && bench_parse_int(value, 1, MAX_CHARACTERS, &opt->characters)) {
            continue;
        }
        return false;
    }
    return true;
}

/* A static box body: centre and half extents. */
static bool static_box(i2d_world_id world, float x, float y, float hx, float hy) {
    i2d_body_def bd = i2d_default_body_def();
    bd.position.x = x;
    bd.position.y = y;
    const i2d_body_id body = i2d_body_create(world, &bd);
    const i2d_shape_def sd = i2d_default_shape_def();
    return !I2D_IS_NULL(i2d_shape_create_box(body, &sd, hx, hy));
}

/* The level described at the top; false (with the library's message) on failure. */
static bool build_level(i2d_world_id world) {
    const float half_length = 0.5f * GROUND_TILES;
    for (int i = 0; i < GROUND_TILES; ++i) {
        if (!static_box(world, -half_length + (float)i + 0.5f, -0.5f, 0.5f, 0.5f)) {
            return false;
        }
    }
    for (int i = 0; i < LOW_STEPS; ++i) {
        const float h = uniform(0.1f, 0.25f);
        if (!static_box(world, uniform(-half_length, half_length), 0.5f * h, uniform(0.3f, 1.5f), 0.5f * h)) {
            return false;
        }
    }
    for (int i = 0; i < PLATFORMS; ++i) {
        if (!static_box(world, uniform(-half_length, half_length), uniform(2.5f, 6.0f), uniform(1.0f, 3.0f), 0.2f)) {
            return false;
        }
    }
    for (int i = 0; i < BRICKS; ++i) {
        if (!static_box(world, uniform(-half_length, half_length), uniform(3.0f, 8.0f), 0.5f, 0.5f)) {
            return false;
        }
    }
    const i2d_shape_def sd = i2d_default_shape_def();
    for (int i = 0; i < CRATES; ++i) {
        i2d_body_def bd = i2d_default_body_def();
        bd.type = I2D_BODY_DYNAMIC;
        bd.position.x = -half_length + (float)(i + 1) * (2.0f * half_length / (CRATES + 1));
        bd.position.y = 1.5f;
        const i2d_body_id crate = i2d_body_create(world, &bd);
        if (I2D_IS_NULL(i2d_shape_create_box(crate, &sd, 0.4f, 0.4f))) {
            return false;
        }
    }
    for (int i = 0; i < SETTLE_STEPS; ++i) {
        if (i2d_world_step(world, dt, SUBSTEPS) != I2D_OK) {
            return false;
        }
    }
    return true;
}

/* One game frame's velocity for a character: walking its way, falling while airborne. */
static i2d_vec2 frame_velocity(const character* c) {
    i2d_vec2 v;
    v.x = WALK_SPEED * c->direction;
    v.y = c->velocity.y;
    if (!c->last.on_ground) {
        v.y -= GRAVITY * dt;
    }
    return v;
}

int main(int argc, char** argv) {
    options opt;
    if (!parse_options(argc, argv, &opt)) {
        usage(stderr);
        return EXIT_USAGE;
    }
    if (!bench_check_library_version("impulse2d_mover_bench")) {
        return EXIT_API_ERROR;
    }
    bench_print_build_line(stdout, "mover_bench");
    const i2d_world_def wd = i2d_default_world_def();
    const i2d_world_id world = i2d_world_create(&wd);
    if (I2D_IS_NULL(world) || !build_level(world)) {
        fprintf(stderr, "impulse2d_mover_bench: building the level failed: %s\n", i2d_last_error_message());
        return EXIT_API_ERROR;
    }
    const i2d_world_counters counters = i2d_world_get_counters(world);
    printf("# level: %d shapes (%d static, %d dynamic), %d characters, %d frames at 60 Hz\n", counters.shape_count,
           GROUND_TILES + LOW_STEPS + PLATFORMS + BRICKS, CRATES, opt.characters, opt.frames);

    static character characters[MAX_CHARACTERS];
    const i2d_capsule capsule = {{0.0f, 0.3f}, {0.0f, 1.5f}, 0.3f};
    const i2d_character_def def = i2d_default_character_def();
    for (int k = 0; k < opt.characters; ++k) {
        character* c = &characters[k];
        memset(c, 0, sizeof *c);
        c->position.x = -0.5f * GROUND_TILES + 10.0f + (float)k * ((float)GROUND_TILES - 20.0f) / (float)opt.characters;
        c->position.y = 1.0f;
        c->direction = (k % 2) == 0 ? 1.0f : -1.0f;
    }
    double* per_call = (double*)malloc(sizeof(double) * (size_t)opt.frames);
    if (per_call == NULL) {
        return EXIT_API_ERROR;
    }
    long grounded = 0, touched = 0;
    double walked = 0.0;
    for (int f = 0; f < opt.frames; ++f) {
        if (i2d_world_step(world, dt, SUBSTEPS) != I2D_OK) {
            fprintf(stderr, "impulse2d_mover_bench: step failed: %s\n", i2d_last_error_message());
            return EXIT_API_ERROR;
        }
        i2d_vec2 velocities[MAX_CHARACTERS];
        for (int k = 0; k < opt.characters; ++k) {
            velocities[k] = frame_velocity(&characters[k]);
        }
        const double start = bench_nanoseconds_now();
        for (int k = 0; k < opt.characters; ++k) {
            character* c = &characters[k];
            if (i2d_world_move_character(world, &def, &capsule, c->position, velocities[k], dt, &c->last) != I2D_OK) {
                fprintf(stderr, "impulse2d_mover_bench: move failed: %s\n", i2d_last_error_message());
                return EXIT_API_ERROR;
            }
            c->position = c->last.position;
        }
        per_call[f] = (bench_nanoseconds_now() - start) / (double)opt.characters;
        for (int k = 0; k < opt.characters; ++k) {
            character* c = &characters[k];
            c->velocity = c->last.velocity;
            grounded += c->last.on_ground ? 1 : 0;
            touched += c->last.hit_count;
            walked += fabs((double)c->last.velocity.x) * dt;
            /* Stopped by a wall, or near the level's end: turn round. */
            const float end = 0.5f * GROUND_TILES - 5.0f;
            if (c->last.velocity.x == 0.0f) {
                c->direction = -c->direction;
            } else if (c->position.x > end) {
                c->direction = -1.0f;
            } else if (c->position.x < -end) {
                c->direction = 1.0f;
            }
            if (!isfinite(c->position.x) || !isfinite(c->position.y)) {
                fprintf(stderr, "impulse2d_mover_bench: a character's position is not finite\n");
                return EXIT_CHECK_FAILED;
            }
        }
    }
    qsort(per_call, (size_t)opt.frames, sizeof(double), bench_compare_doubles);
    const double calls = (double)opt.frames * (double)opt.characters;
    printf("mover_bench,move_character,median_us %.3f,p90_us %.3f,min_us %.3f,grounded %.1f%%,shapes_per_move %.2f,"
           "walking %.1f%%\n",
           per_call[opt.frames / 2] * 1e-3, per_call[(opt.frames * 9) / 10] * 1e-3, per_call[0] * 1e-3,
           100.0 * (double)grounded / calls, (double)touched / calls,
           100.0 * walked / (calls * (double)WALK_SPEED * (double)dt));
    free(per_call);
    i2d_world_destroy(world);
    return EXIT_OK;
}
