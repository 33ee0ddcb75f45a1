/* SPDX-License-Identifier: MIT */
/* The benchmark scenes this stage can run (circles and axis-aligned boxes, no rotation, no joints). */
#include "scenes.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define TIME_STEP (1.0f / 60.0f)

/* ---- Helpers ------------------------------------------------------------------------ */

static i2d_vec2 vec2(float x, float y) {
    i2d_vec2 v;
    v.x = x;
    v.y = y;
    return v;
}

static i2d_aabb aabb(float min_x, float min_y, float max_x, float max_y) {
    i2d_aabb b;
    b.min = vec2(min_x, min_y);
    b.max = vec2(max_x, max_y);
    return b;
}

static bool create_world(bench_state* state, bool enable_sleep) {
    i2d_world_def def = i2d_default_world_def();
    def.enable_sleep = enable_sleep;
    state->world = i2d_world_create(&def);
    return !I2D_IS_NULL(state->world);
}

/* Sizes the body arrays once, so that building a scene never reallocates. */
static bool reserve_bodies(bench_state* state, int32_t capacity) {
    state->bodies = (i2d_body_id*)malloc((size_t)capacity * sizeof *state->bodies);
    state->start_y = (float*)malloc((size_t)capacity * sizeof *state->start_y);
    if (!state->bodies || !state->start_y) {
        state->error = "out of memory";
        return false;
    }
    state->body_capacity = capacity;
    return true;
}

static i2d_body_id create_body(i2d_world_id world, i2d_body_type type, i2d_vec2 position) {
    i2d_body_def def = i2d_default_body_def();
    def.type = type;
    def.position = position;
    return i2d_body_create(world, &def);
}

/* A static box centred at (x, y): the scenes' floors and walls. */
static bool add_static_box(bench_state* state, float x, float y, float half_width, float half_height) {
    i2d_shape_def def = i2d_default_shape_def();
    i2d_body_id body = create_body(state->world, I2D_BODY_STATIC, vec2(x, y));
    if (I2D_IS_NULL(body)) {
        return false;
    }
    return !I2D_IS_NULL(i2d_shape_create_box(body, &def, half_width, half_height));
}

/* A floor with its top at y = 0 and two walls standing on it, inner faces at +-half_width.
 * Thick (2 m) so that nothing falling at the scenes' speeds can pass through in one substep. */
static bool add_container(bench_state* state, float half_width, float wall_height) {
    const float thickness = 2.0f;
    float wall_x = half_width + 0.5f * thickness;
    return add_static_box(state, 0.0f, -0.5f * thickness, half_width + thickness, 0.5f * thickness) &&
           add_static_box(state, -wall_x, 0.5f * wall_height, 0.5f * thickness, 0.5f * wall_height) &&
           add_static_box(state, wall_x, 0.5f * wall_height, 0.5f * thickness, 0.5f * wall_height);
}

/* A dynamic body with one shape: a circle of radius `size`, or a box of half extent `size`. */
static bool add_dynamic(bench_state* state, i2d_vec2 position, bool is_circle, float size) {
    i2d_shape_def def = i2d_default_shape_def();
    i2d_body_id body;
    i2d_shape_id shape;
    if (state->body_count == state->body_capacity) {
        state->error = "more bodies than reserved";
        return false;
    }
    body = create_body(state->world, I2D_BODY_DYNAMIC, position);
    if (I2D_IS_NULL(body)) {
        return false;
    }
    if (is_circle) {
        i2d_circle circle;
        circle.center = vec2(0.0f, 0.0f);
        circle.radius = size;
        shape = i2d_shape_create_circle(body, &def, &circle);
    } else {
        shape = i2d_shape_create_box(body, &def, size, size);
    }
    if (I2D_IS_NULL(shape)) {
        return false;
    }
    state->bodies[state->body_count] = body;
    state->start_y[state->body_count] = position.y;
    state->body_count++;
    return true;
}

/* Share of the dynamic bodies whose centre lies in state->region (a NaN centre does not). */
static bool fraction_inside(const bench_state* state, double* fraction) {
    int32_t i, inside = 0;
    for (i = 0; i < state->body_count; ++i) {
        i2d_vec2 p = i2d_body_get_position(state->bodies[i]);
        if (i2d_last_status() != I2D_OK) {
            return false;
        }
        inside += p.x >= state->region.min.x && p.x <= state->region.max.x && p.y >= state->region.min.y &&
                  p.y <= state->region.max.y;
    }
    *fraction = state->body_count > 0 ? (double)inside / (double)state->body_count : 1.0;
    return true;
}

/* xorshift32 (Marsaglia 2003) with a fixed seed: every run builds exactly the same scene. */
static uint32_t next_random(uint32_t* seed) {
    uint32_t x = *seed;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *seed = x;
    return x;
}

static float random_range(uint32_t* seed, float lo, float hi) {
    /* The top 24 bits: exactly representable as a float in [0, 1). */
    float unit = (float)(next_random(seed) >> 8) * (1.0f / 16777216.0f);
    return lo + (hi - lo) * unit;
}

/* ---- rain: circles falling into an open box ------------------------------------------ */

#define RAIN_MIN_RADIUS 0.25f
#define RAIN_MAX_RADIUS 0.5f
#define RAIN_PITCH 1.1f   /* grid spacing: the largest diameter plus a gap, so none start touching */
#define RAIN_JITTER 0.04f /* sideways, so the circles do not land in perfect columns */

/* Container and grid grow with the count: about 40 m wide per 1000 circles' square root, walls
 * 1.5 times the height the pile should reach (a circle takes ~0.56 m^2 packed), and the grid
 * starts just above the walls, so the circles rain in through the open top. */
static bool create_rain(bench_state* state, int32_t count) {
    uint32_t seed = 0x9e3779b9u;
    float half_width = 20.0f * sqrtf((float)count / 1000.0f);
    float pile_height = 0.56f * (float)count / (2.0f * half_width);
    float wall_height = 1.5f * pile_height + 2.0f;
    int32_t columns = (int32_t)((2.0f * half_width - 1.0f) / RAIN_PITCH);
    float left = -0.5f * RAIN_PITCH * (float)(columns - 1);
    int32_t i;

    if (!create_world(state, true) || !reserve_bodies(state, count) || !add_container(state, half_width, wall_height)) {
        return false;
    }
    /* The top is open: a circle above the container is still on its way in. */
    state->region = aabb(-half_width, 0.0f, half_width, FLT_MAX);
    for (i = 0; i < count; ++i) {
        float radius = random_range(&seed, RAIN_MIN_RADIUS, RAIN_MAX_RADIUS);
        float x = left + RAIN_PITCH * (float)(i % columns) + random_range(&seed, -RAIN_JITTER, RAIN_JITTER);
        float y = wall_height + 1.0f + RAIN_PITCH * (float)(i / columns);
        if (!add_dynamic(state, vec2(x, y), true, radius)) {
            return false;
        }
    }
    return true;
}

static bool create_rain_1k(bench_state* state) { return create_rain(state, 1000); }
static bool create_rain_4k(bench_state* state) { return create_rain(state, 4000); }
static bool create_rain_16k(bench_state* state) { return create_rain(state, 16000); }

/* Every circle must still be in the container: one outside has tunnelled or been thrown out. */
static bool sanity_inside_all(const bench_state* state, int32_t steps_run, double* figure, bool* sane) {
    (void)steps_run;
    if (!fraction_inside(state, figure)) {
        return false;
    }
    *sane = *figure == 1.0;
    return true;
}

/* ---- box_grid: columns of boxes at rest ----------------------------------------------- */

#define GRID_COLUMNS 50
#define GRID_ROWS 20
#define GRID_PITCH 1.1f      /* 1 m boxes 0.1 m apart: each column stands alone */
#define GRID_MAX_DROP 0.25f  /* 20 contacts at ~5 mm slop sink ~0.1 m; a quarter box is a failure */

/* Boxes start exactly touching and stay put: the cost measured is that of 1000 resting contacts.
 * Sleep is off (as Box2D's pyramids run) so that it stays a resting-contact cost once sleep lands. */
static bool create_box_grid(bench_state* state) {
    float left = -0.5f * GRID_PITCH * (float)(GRID_COLUMNS - 1);
    int32_t row, column;
    if (!create_world(state, false) || !reserve_bodies(state, GRID_COLUMNS * GRID_ROWS) ||
        !add_static_box(state, 0.0f, -1.0f, -left + 2.0f, 1.0f)) {
        return false;
    }
    state->region = aabb(-FLT_MAX, 0.0f, FLT_MAX, FLT_MAX);
    for (column = 0; column < GRID_COLUMNS; ++column) {
        for (row = 0; row < GRID_ROWS; ++row) {
            i2d_vec2 p = vec2(left + GRID_PITCH * (float)column, 0.5f + (float)row);
            if (!add_dynamic(state, p, false, 0.5f)) {
                return false;
            }
        }
    }
    return true;
}

/* The largest drop of a top-row box from where it started, m. */
static bool sanity_top_row_drop(const bench_state* state, int32_t steps_run, double* figure, bool* sane) {
    float top = -FLT_MAX, drop = 0.0f;
    int32_t i;
    (void)steps_run;
    for (i = 0; i < state->body_count; ++i) {
        top = state->start_y[i] > top ? state->start_y[i] : top;
    }
    for (i = 0; i < state->body_count; ++i) {
        i2d_vec2 p;
        if (state->start_y[i] != top) {
            continue;
        }
        p = i2d_body_get_position(state->bodies[i]);
        if (i2d_last_status() != I2D_OK) {
            return false;
        }
        /* Written so that a NaN height makes the drop NaN rather than being skipped. */
        if (!(state->start_y[i] - p.y <= drop)) {
            drop = state->start_y[i] - p.y;
        }
    }
    *figure = drop;
    *sane = drop < GRID_MAX_DROP;
    return true;
}

/* ---- small: a game-sized room ----------------------------------------------------------- */

#define SMALL_COUNT 50
#define SMALL_COLUMNS 10
#define SMALL_HALF_WIDTH 10.0f
#define MOVER_SPEED 2.0f
#define MOVER_PERIOD 60 /* steps between turns of the kinematic platform */

/* 50 bodies, half circles and half boxes, fall into a room with a kinematic platform that a
 * per-step hook turns round every second: the fixed per-step cost that most games pay. */
static bool create_small(bench_state* state) {
    i2d_shape_def def = i2d_default_shape_def();
    int32_t i;
    if (!create_world(state, true) || !reserve_bodies(state, SMALL_COUNT) ||
        !add_container(state, SMALL_HALF_WIDTH, 14.0f)) {
        return false;
    }
    state->region = aabb(-SMALL_HALF_WIDTH, 0.0f, SMALL_HALF_WIDTH, FLT_MAX);
    state->mover_start = vec2(-1.0f, 3.0f);
    state->mover = create_body(state->world, I2D_BODY_KINEMATIC, state->mover_start);
    if (I2D_IS_NULL(state->mover) || I2D_IS_NULL(i2d_shape_create_box(state->mover, &def, 2.0f, 0.2f))) {
        return false;
    }
    for (i = 0; i < SMALL_COUNT; ++i) {
        /* Odd rows shifted by half a body, so that bodies land off-centre instead of in columns. */
        int32_t row = i / SMALL_COLUMNS;
        float x = -7.2f + 1.6f * (float)(i % SMALL_COLUMNS) + 0.4f * (float)(row % 2);
        i2d_vec2 p = vec2(x, 5.0f + 1.6f * (float)row);
        if (!add_dynamic(state, p, i % 2 == 0, 0.4f)) {
            return false;
        }
    }
    return true;
}

/* The platform's scripted velocity: right for a period, then left, and so on. */
static float mover_velocity(int32_t step) {
    return (step / MOVER_PERIOD) % 2 == 0 ? MOVER_SPEED : -MOVER_SPEED;
}

static bool small_step_hook(bench_state* state, int32_t step) {
    if (step % MOVER_PERIOD != 0) {
        return true;
    }
    return i2d_body_set_linear_velocity(state->mover, vec2(mover_velocity(step), 0.0f)) == I2D_OK;
}

/* Every body in the room, and the kinematic platform where its script put it (within 1 mm). */
static bool sanity_small(const bench_state* state, int32_t steps_run, double* figure, bool* sane) {
    double expected_x = state->mover_start.x;
    i2d_vec2 p;
    int32_t step;
    if (!fraction_inside(state, figure)) {
        return false;
    }
    for (step = 0; step < steps_run; ++step) {
        expected_x += (double)mover_velocity(step) * (double)TIME_STEP;
    }
    p = i2d_body_get_position(state->mover);
    if (i2d_last_status() != I2D_OK) {
        return false;
    }
    *sane = *figure == 1.0 && fabs((double)p.x - expected_x) < 1e-3 &&
            fabs((double)(p.y - state->mover_start.y)) < 1e-3;
    return true;
}

/* ---- The table ----------------------------------------------------------------------------- */

const bench_scene bench_scenes[] = {
    {"rain_1k", "1000 circles (r 0.25-0.5 m) rain from a grid into an open box", 500, "fraction inside",
     create_rain_1k, NULL, sanity_inside_all},
    {"rain_4k", "4000 circles (r 0.25-0.5 m) rain from a grid into an open box", 500, "fraction inside",
     create_rain_4k, NULL, sanity_inside_all},
    {"rain_16k", "16000 circles (r 0.25-0.5 m) rain from a grid into an open box", 500, "fraction inside",
     create_rain_16k, NULL, sanity_inside_all},
    {"box_grid", "50 x 20 columns of 1 m boxes resting on the ground (sleep off)", 500, "top-row max drop m",
     create_box_grid, NULL, sanity_top_row_drop},
    {"small", "50 circles and boxes in a room with a scripted kinematic platform", 500, "fraction inside",
     create_small, small_step_hook, sanity_small},
};
const int32_t bench_scene_count = (int32_t)(sizeof bench_scenes / sizeof bench_scenes[0]);

/* ---- State ------------------------------------------------------------------------------------ */

bool bench_state_destroy(bench_state* state) {
    bool ok = true;
    if (!I2D_IS_NULL(state->world)) {
        ok = i2d_world_destroy(state->world) == I2D_OK;
    }
    free(state->bodies);
    free(state->start_y);
    memset(state, 0, sizeof *state);
    return ok;
}

static uint64_t fnv1a_float(uint64_t hash, float value) {
    unsigned char bytes[sizeof value];
    size_t i;
    memcpy(bytes, &value, sizeof value);
    for (i = 0; i < sizeof value; ++i) {
        hash = (hash ^ bytes[i]) * 0x100000001b3ull;
    }
    return hash;
}

bool bench_state_hash(const bench_state* state, uint64_t* hash) {
    uint64_t h = 0xcbf29ce484222325ull;
    int32_t i;
    for (i = 0; i < state->body_count; ++i) {
        i2d_vec2 p = i2d_body_get_position(state->bodies[i]);
        i2d_vec2 v;
        if (i2d_last_status() != I2D_OK) {
            return false;
        }
        v = i2d_body_get_linear_velocity(state->bodies[i]);
        if (i2d_last_status() != I2D_OK) {
            return false;
        }
        h = fnv1a_float(fnv1a_float(fnv1a_float(fnv1a_float(h, p.x), p.y), v.x), v.y);
    }
    *hash = h;
    return true;
}
