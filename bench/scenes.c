/* SPDX-License-Identifier: MIT */
/* The benchmark scenes: those of shared/design/scenes.md that the engine can run today (no joints
 * yet), the extras, and the scaling sweep's families. */
#include "scenes.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI_F 3.14159265358979f

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

i2d_simd_path bench_simd_path = I2D_SIMD_AUTOMATIC;
bool bench_contact_recycling = true;
int32_t bench_worker_count = 1;

static bool create_world(bench_state* state, bool enable_sleep) {
    i2d_world_def def = i2d_default_world_def();
    def.enable_sleep = enable_sleep;
    def.simd_path = bench_simd_path;
    def.enable_contact_recycling = bench_contact_recycling;
    def.enable_profile = true;
    def.worker_count = bench_worker_count;
    state->sleep_enabled = enable_sleep;
    state->world = i2d_world_create(&def);
    return !I2D_IS_NULL(state->world);
}

/* Sizes the body arrays once, so that building a scene never reallocates; `marks` is how many
 * bodies the sanity check follows. */
static bool reserve_bodies(bench_state* state, int32_t capacity, int32_t marks) {
    state->bodies = (i2d_body_id*)malloc((size_t)capacity * sizeof *state->bodies);
    state->start_x = (float*)malloc((size_t)capacity * sizeof *state->start_x);
    state->start_y = (float*)malloc((size_t)capacity * sizeof *state->start_y);
    state->marks = (int32_t*)malloc((size_t)(marks > 0 ? marks : 1) * sizeof *state->marks);
    if (!state->bodies || !state->start_x || !state->start_y || !state->marks) {
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

/* A dynamic body with one shape of the default material (density 1, friction 0.6): a circle of
 * radius `size`, or a square box of half extent `size`. */
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
    state->start_x[state->body_count] = position.x;
    state->start_y[state->body_count] = position.y;
    state->body_count++;
    return true;
}

/* Follows the body created last in the sanity check. */
static void mark_last_body(bench_state* state) {
    state->marks[state->mark_count++] = state->body_count - 1;
}

static void set_figure(bench_sanity* out, const char* name, double value) {
    if (out->figure_count < BENCH_MAX_FIGURES) {
        out->figures[out->figure_count].name = name;
        out->figures[out->figure_count].value = value;
        out->figure_count++;
    }
}

/* How many dynamic bodies have their centre in state->region (a NaN centre is not inside). */
static bool count_inside(const bench_state* state, int32_t* inside) {
    int32_t i;
    *inside = 0;
    for (i = 0; i < state->body_count; ++i) {
        i2d_vec2 p = i2d_body_get_position(state->bodies[i]);
        if (i2d_last_status() != I2D_OK) {
            return false;
        }
        *inside += p.x >= state->region.min.x && p.x <= state->region.max.x && p.y >= state->region.min.y &&
                   p.y <= state->region.max.y;
    }
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

/* ---- Pyramids of 1 m boxes ------------------------------------------------------------ */

#define PYRAMID_BOX_HALF 0.5f
/* A pyramid stands while its top box has dropped less than half a box and drifted sideways
 * less than half a box. A settled 100-row pyramid sinks by its contacts' slop (~0.005 m per row);
 * a collapsing one loses metres. */
#define PYRAMID_MAX_DROP 0.5f
#define PYRAMID_MAX_DRIFT 0.5f
/* A box counts as displaced once its centre is this far from where it started. */
#define PYRAMID_DISPLACED 0.25f

/* Adds a pyramid of `rows` rows of 1 m boxes (density 1, friction 0.6): row i (0 = bottom) holds
 * rows - i boxes centred at y = base_y + i + 0.5, from x = left + 0.5 i, 1 m apart, so that
 * neighbouring boxes touch exactly. The top box is marked for the sanity check. */
static bool add_pyramid(bench_state* state, int32_t rows, float left, float base_y) {
    int32_t i, k;
    for (i = 0; i < rows; ++i) {
        for (k = 0; k < rows - i; ++k) {
            i2d_vec2 p = vec2(left + 0.5f * (float)i + (float)k, base_y + (float)i + 0.5f);
            if (!add_dynamic(state, p, false, PYRAMID_BOX_HALF)) {
                return false;
            }
        }
    }
    mark_last_body(state);
    return true;
}

/* How many dynamic bodies are PYRAMID_DISPLACED or more from where they started (or NaN). */
static bool count_displaced(const bench_state* state, int32_t* displaced) {
    int32_t i;
    *displaced = 0;
    for (i = 0; i < state->body_count; ++i) {
        i2d_vec2 p = i2d_body_get_position(state->bodies[i]);
        float dx = p.x - state->start_x[i], dy = p.y - state->start_y[i];
        if (i2d_last_status() != I2D_OK) {
            return false;
        }
        *displaced += !(dx * dx + dy * dy <= PYRAMID_DISPLACED * PYRAMID_DISPLACED);
    }
    return true;
}

/* The marked top boxes: the largest drop below and the largest sideways drift from their start
 * (either NaN when a position is), and how many of all the boxes are displaced. */
static bool sanity_pyramids(const bench_state* state, int32_t steps_run, bench_sanity* out) {
    double drop = 0.0, drift = 0.0;
    int32_t i, displaced;
    (void)steps_run;
    for (i = 0; i < state->mark_count; ++i) {
        int32_t b = state->marks[i];
        i2d_vec2 p = i2d_body_get_position(state->bodies[b]);
        double d, x;
        if (i2d_last_status() != I2D_OK) {
            return false;
        }
        d = (double)state->start_y[b] - (double)p.y;
        x = (double)p.x - (double)state->start_x[b];
        /* Written so that a NaN makes the figure NaN rather than being skipped. */
        if (!(d <= drop)) {
            drop = d;
        }
        if (!(fabs(x) <= fabs(drift))) {
            drift = x;
        }
    }
    if (!count_displaced(state, &displaced)) {
        return false;
    }
    set_figure(out, state->mark_count == 1 ? "top drop m" : "max top drop m", drop);
    set_figure(out, state->mark_count == 1 ? "top x drift m" : "max top x drift m", drift);
    set_figure(out, "boxes moved >0.25m", (double)displaced);
    out->sane = drop < PYRAMID_MAX_DROP && fabs(drift) < PYRAMID_MAX_DRIFT;
    return true;
}

/* ---- large_pyramid (scenes.md): 100 rows, 5050 boxes, sleeping off ------------------------ */

#define LARGE_PYRAMID_ROWS 100

static bool create_large_pyramid(bench_state* state) {
    const int32_t count = LARGE_PYRAMID_ROWS * (LARGE_PYRAMID_ROWS + 1) / 2;
    /* Ground: a static body at (0, -1) holding one 200 x 2 m box: its top face is at y = 0. */
    if (!create_world(state, false) || !reserve_bodies(state, count, 1) ||
        !add_static_box(state, 0.0f, -1.0f, 100.0f, 1.0f)) {
        return false;
    }
    /* Box j of row i sits at x = -50 + 0.5 (i + 1) + (j - i): the bottom row spans -49.5..49.5;
     * the top box starts at (0, 99.5). */
    return add_pyramid(state, LARGE_PYRAMID_ROWS, -49.5f, 0.0f);
}

/* ---- many_pyramids (scenes.md) and the pyramid field of the sweep ------------------------- */

#define FIELD_PYRAMID_ROWS 10
#define FIELD_PYRAMID_BOXES (FIELD_PYRAMID_ROWS * (FIELD_PYRAMID_ROWS + 1) / 2)
#define FIELD_SPACING 11.0f /* 2 * 0.5 * (10 + 1): a pyramid's base plus a one-box gap */

/* `count` 10-row pyramids in rows of `columns`, each row of pyramids on one two-sided segment.
 * All the segments belong to one static body at the origin; segment r lies at y = 11 r from
 * x = -5.5 columns to +5.5 columns. Pyramid (r, c) has its bottom-row centres at
 * x = -5.5 columns + 1 + 11 c + k (k = 0..9). For 400 pyramids in 20 columns this is exactly
 * many_pyramids: segments from -110 to 110, bottom rows from x = -109 + 11 c. */
static bool create_pyramid_field(bench_state* state, int32_t count, int32_t columns) {
    i2d_shape_def def = i2d_default_shape_def();
    int32_t rows = (count + columns - 1) / columns;
    float half_width = 0.5f * FIELD_SPACING * (float)columns;
    i2d_body_id ground;
    int32_t r, p;
    if (!create_world(state, false) || !reserve_bodies(state, count * FIELD_PYRAMID_BOXES, count)) {
        return false;
    }
    ground = create_body(state->world, I2D_BODY_STATIC, vec2(0.0f, 0.0f));
    if (I2D_IS_NULL(ground)) {
        return false;
    }
    for (r = 0; r < rows; ++r) {
        float y = FIELD_SPACING * (float)r;
        i2d_segment segment;
        segment.point1 = vec2(-half_width, y);
        segment.point2 = vec2(half_width, y);
        if (I2D_IS_NULL(i2d_shape_create_segment(ground, &def, segment.point1, segment.point2))) {
            return false;
        }
    }
    for (p = 0; p < count; ++p) {
        int32_t row = p / columns, column = p % columns;
        float left = -half_width + 1.0f + FIELD_SPACING * (float)column;
        if (!add_pyramid(state, FIELD_PYRAMID_ROWS, left, FIELD_SPACING * (float)row)) {
            return false;
        }
    }
    return true;
}

static bool create_many_pyramids(bench_state* state) { return create_pyramid_field(state, 400, 20); }

/* The sweep: as many pyramids as make the body count nearest `bodies`, in a near-square grid. */
static bool create_pyramid_field_sized(bench_state* state, int32_t bodies) {
    int32_t count = (bodies + FIELD_PYRAMID_BOXES / 2) / FIELD_PYRAMID_BOXES;
    int32_t columns = (int32_t)ceil(sqrt((double)count));
    return create_pyramid_field(state, count, columns);
}

static bool create_pyramid_field_1k(bench_state* state) { return create_pyramid_field_sized(state, 1000); }
static bool create_pyramid_field_4k(bench_state* state) { return create_pyramid_field_sized(state, 4000); }
static bool create_pyramid_field_16k(bench_state* state) { return create_pyramid_field_sized(state, 16000); }
static bool create_pyramid_field_64k(bench_state* state) { return create_pyramid_field_sized(state, 64000); }

/* ---- tumbler (scenes.md), with a kinematic drum until joints exist ------------------------- */

#define TUMBLER_CENTER_Y 10.0f
#define TUMBLER_SPEED_DEG 25.0f   /* deg/s, counter-clockwise */
#define TUMBLER_INNER_HALF 9.5f   /* walls centred at +-10, 1 m thick */
#define TUMBLER_GRID 45
#define TUMBLER_MAX_ANGLE_ERROR_DEG 0.01

/* A 20 x 20 hollow square drum of four boxes (density 50) turning at +25 deg/s about (0, 10)
 * and 45 x 45 boxes of 0.25 m inside. scenes.md drives a dynamic drum with a revolute motor
 * (max torque 1e8) from a static ground body; without joints the drum is a kinematic body at the
 * same speed, which keeps the contact load the same. The ground body is created all the same
 * (no shapes), as the joint's anchor will be. */
static bool create_tumbler(bench_state* state) {
    i2d_shape_def drum_def = i2d_default_shape_def();
    i2d_body_def body_def = i2d_default_body_def();
    i2d_rot identity = i2d_make_rot(0.0f);
    int32_t i, j;
    if (!create_world(state, true) || !reserve_bodies(state, TUMBLER_GRID * TUMBLER_GRID, 0) ||
        I2D_IS_NULL(create_body(state->world, I2D_BODY_STATIC, vec2(0.0f, 0.0f)))) {
        return false;
    }
    body_def.type = I2D_BODY_KINEMATIC;
    body_def.position = vec2(0.0f, TUMBLER_CENTER_Y);
    body_def.angular_velocity = TUMBLER_SPEED_DEG * PI_F / 180.0f;
    state->mover_start = body_def.position;
    state->mover = i2d_body_create(state->world, &body_def);
    if (I2D_IS_NULL(state->mover)) {
        return false;
    }
    drum_def.density = 50.0f;
    if (I2D_IS_NULL(i2d_shape_create_offset_box(state->mover, &drum_def, 0.5f, 10.0f, vec2(10.0f, 0.0f), identity)) ||
        I2D_IS_NULL(i2d_shape_create_offset_box(state->mover, &drum_def, 0.5f, 10.0f, vec2(-10.0f, 0.0f), identity)) ||
        I2D_IS_NULL(i2d_shape_create_offset_box(state->mover, &drum_def, 10.0f, 0.5f, vec2(0.0f, 10.0f), identity)) ||
        I2D_IS_NULL(i2d_shape_create_offset_box(state->mover, &drum_def, 10.0f, 0.5f, vec2(0.0f, -10.0f), identity))) {
        return false;
    }
    for (i = 0; i < TUMBLER_GRID; ++i) {
        for (j = 0; j < TUMBLER_GRID; ++j) {
            if (!add_dynamic(state, vec2(-9.0f + 0.4f * (float)j, 1.0f + 0.4f * (float)i), false, 0.125f)) {
                return false;
            }
        }
    }
    return true;
}

/* Boxes whose centre is inside the drum's hollow, in the drum's frame, and the drum's angle
 * against 25 deg/s times the time run. */
static bool sanity_tumbler(const bench_state* state, int32_t steps_run, bench_sanity* out) {
    i2d_transform drum = i2d_body_get_transform(state->mover);
    double expected, angle, error;
    int32_t i, inside = 0;
    if (i2d_last_status() != I2D_OK) {
        return false;
    }
    for (i = 0; i < state->body_count; ++i) {
        i2d_vec2 p = i2d_body_get_position(state->bodies[i]);
        float dx, dy, lx, ly;
        if (i2d_last_status() != I2D_OK) {
            return false;
        }
        /* Into the drum frame: the inverse rotation of (p - drum origin). */
        dx = p.x - drum.p.x;
        dy = p.y - drum.p.y;
        lx = drum.q.c * dx + drum.q.s * dy;
        ly = -drum.q.s * dx + drum.q.c * dy;
        inside += fabsf(lx) <= TUMBLER_INNER_HALF && fabsf(ly) <= TUMBLER_INNER_HALF;
    }
    expected = fmod((double)TUMBLER_SPEED_DEG * (double)steps_run * (double)BENCH_TIME_STEP, 360.0);
    angle = (double)i2d_rot_get_angle(drum.q) * 180.0 / 3.14159265358979323846;
    error = fmod(angle - expected + 540.0, 360.0) - 180.0;
    set_figure(out, "boxes inside", (double)inside);
    set_figure(out, "total", (double)state->body_count);
    set_figure(out, "drum angle error deg", error);
    out->sane = inside == state->body_count && fabs(error) < TUMBLER_MAX_ANGLE_ERROR_DEG &&
                fabs((double)(drum.p.x - state->mover_start.x)) < 1e-4 &&
                fabs((double)(drum.p.y - state->mover_start.y)) < 1e-4;
    return true;
}

/* ---- rain_circles: circles falling into an open box (extra; the sweep's first family) ------ */

#define RAIN_MIN_RADIUS 0.25f
#define RAIN_MAX_RADIUS 0.5f
#define RAIN_PITCH 1.1f   /* grid spacing: the largest diameter plus a gap, so none start touching */
#define RAIN_JITTER 0.04f /* sideways, so the circles do not land in perfect columns */

/* Container and grid grow with the count: about 40 m wide per 1000 circles' square root, walls
 * 1.5 times the height the pile should reach (a circle takes ~0.56 m^2 packed), and the grid
 * starts just above the walls, so the circles rain in through the open top. Sleep is off: with it
 * on, the 1000-circle pile is asleep before its 500 steps end while the larger ones are still
 * raining in, and the sweep would compare a sleeping world with a busy one. */
static bool create_rain(bench_state* state, int32_t count) {
    uint32_t seed = 0x9e3779b9u;
    float half_width = 20.0f * sqrtf((float)count / 1000.0f);
    float pile_height = 0.56f * (float)count / (2.0f * half_width);
    float wall_height = 1.5f * pile_height + 2.0f;
    int32_t columns = (int32_t)((2.0f * half_width - 1.0f) / RAIN_PITCH);
    float left = -0.5f * RAIN_PITCH * (float)(columns - 1);
    int32_t i;

    if (!create_world(state, false) || !reserve_bodies(state, count, 0) ||
        !add_container(state, half_width, wall_height)) {
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
static bool create_rain_64k(bench_state* state) { return create_rain(state, 64000); }

/* Every circle must still be in the container: one outside has tunnelled or been thrown out. */
static bool sanity_inside_all(const bench_state* state, int32_t steps_run, bench_sanity* out) {
    int32_t inside;
    (void)steps_run;
    if (!count_inside(state, &inside)) {
        return false;
    }
    set_figure(out, "inside", (double)inside);
    set_figure(out, "total", (double)state->body_count);
    out->sane = inside == state->body_count;
    return true;
}

/* ---- box_grid: columns of boxes at rest (extra) --------------------------------------------- */

#define GRID_COLUMNS 50
#define GRID_ROWS 20
#define GRID_PITCH 1.1f      /* 1 m boxes 0.1 m apart: each column stands alone */
#define GRID_MAX_DROP 0.25f  /* 20 contacts at ~5 mm slop sink ~0.1 m; a quarter box is a failure */

/* Boxes start exactly touching and stay put: the cost measured is that of 1000 resting contacts.
 * Sleep is off (as Box2D's pyramids run) so that it stays a resting-contact cost once sleep lands. */
static bool create_box_grid(bench_state* state) {
    float left = -0.5f * GRID_PITCH * (float)(GRID_COLUMNS - 1);
    int32_t row, column;
    if (!create_world(state, false) || !reserve_bodies(state, GRID_COLUMNS * GRID_ROWS, GRID_COLUMNS) ||
        !add_static_box(state, 0.0f, -1.0f, -left + 2.0f, 1.0f)) {
        return false;
    }
    for (column = 0; column < GRID_COLUMNS; ++column) {
        for (row = 0; row < GRID_ROWS; ++row) {
            i2d_vec2 p = vec2(left + GRID_PITCH * (float)column, 0.5f + (float)row);
            if (!add_dynamic(state, p, false, 0.5f)) {
                return false;
            }
        }
        mark_last_body(state);
    }
    return true;
}

/* The largest drop of a top-row box from where it started, m, and its largest sideways drift. */
static bool sanity_top_row_drop(const bench_state* state, int32_t steps_run, bench_sanity* out) {
    double drop = 0.0, drift = 0.0;
    int32_t i;
    (void)steps_run;
    for (i = 0; i < state->mark_count; ++i) {
        int32_t b = state->marks[i];
        i2d_vec2 p = i2d_body_get_position(state->bodies[b]);
        double d, x;
        if (i2d_last_status() != I2D_OK) {
            return false;
        }
        d = (double)state->start_y[b] - (double)p.y;
        x = (double)p.x - (double)state->start_x[b];
        /* Written so that a NaN height makes the figure NaN rather than being skipped. */
        if (!(d <= drop)) {
            drop = d;
        }
        if (!(fabs(x) <= fabs(drift))) {
            drift = x;
        }
    }
    set_figure(out, "top-row max drop m", drop);
    set_figure(out, "max x drift m", drift);
    out->sane = drop < GRID_MAX_DROP && fabs(drift) < GRID_MAX_DROP;
    return true;
}

/* ---- sleeping_pile: pyramids and columns of boxes, all asleep (extra) ----------------------- */

#define PILE_PYRAMIDS 10
#define PILE_PYRAMID_ROWS 20
#define PILE_PYRAMID_SPACING 21.0f /* a 20 m base and a 1 m gap */
#define PILE_COLUMNS 50
#define PILE_COLUMN_HEIGHT 20
#define PILE_HALF_WIDTH 135.0f

/* Ten 20-row pyramids (2100 boxes) and 50 lone columns of 20 boxes (1000), 1 m boxes on one
 * static ground: 3100 bodies in 60 islands. The runner steps it, untimed, until every body
 * sleeps (BENCH_SLEEP_FIRST), then times it: what a sleeping pile costs per step. */
static bool create_sleeping_pile(bench_state* state) {
    const int32_t pyramid_boxes = PILE_PYRAMID_ROWS * (PILE_PYRAMID_ROWS + 1) / 2;
    const float columns_left = -PILE_HALF_WIDTH + 3.0f + PILE_PYRAMID_SPACING * (float)PILE_PYRAMIDS;
    int32_t p, column, row;
    if (!create_world(state, true) ||
        !reserve_bodies(state, PILE_PYRAMIDS * pyramid_boxes + PILE_COLUMNS * PILE_COLUMN_HEIGHT, PILE_PYRAMIDS) ||
        !add_static_box(state, 0.0f, -1.0f, PILE_HALF_WIDTH, 1.0f)) {
        return false;
    }
    for (p = 0; p < PILE_PYRAMIDS; ++p) {
        float left = -PILE_HALF_WIDTH + 3.0f + PILE_PYRAMID_SPACING * (float)p;
        if (!add_pyramid(state, PILE_PYRAMID_ROWS, left, 0.0f)) {
            return false;
        }
    }
    for (column = 0; column < PILE_COLUMNS; ++column) {
        for (row = 0; row < PILE_COLUMN_HEIGHT; ++row) {
            i2d_vec2 c = vec2(columns_left + GRID_PITCH * (float)column, 0.5f + (float)row);
            if (!add_dynamic(state, c, false, PYRAMID_BOX_HALF)) {
                return false;
            }
        }
    }
    return true;
}

/* The pile must have stayed asleep through the timed steps and in place: no body awake, none
 * displaced. Also gives the sleeping islands and when the pile fell asleep. */
static bool sanity_sleeping_pile(const bench_state* state, int32_t steps_run, bench_sanity* out) {
    i2d_world_counters counters = i2d_world_get_counters(state->world);
    int32_t awake, displaced;
    (void)steps_run;
    if (i2d_last_status() != I2D_OK || !bench_count_awake(state, &awake) || !count_displaced(state, &displaced)) {
        return false;
    }
    set_figure(out, "awake", (double)awake);
    set_figure(out, "sleeping islands", (double)counters.sleeping_island_count);
    set_figure(out, "asleep after s", (double)state->warm_steps * (double)BENCH_TIME_STEP);
    set_figure(out, "boxes moved >0.25m", (double)displaced);
    out->sane = awake == 0 && displaced == 0;
    return true;
}

/* ---- small: a game-sized room (extra) ------------------------------------------------------- */

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
    if (!create_world(state, true) || !reserve_bodies(state, SMALL_COUNT, 0) ||
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
static bool sanity_small(const bench_state* state, int32_t steps_run, bench_sanity* out) {
    double expected_x = state->mover_start.x, error;
    i2d_vec2 p;
    int32_t step, inside;
    if (!count_inside(state, &inside)) {
        return false;
    }
    for (step = 0; step < steps_run; ++step) {
        expected_x += (double)mover_velocity(step) * (double)BENCH_TIME_STEP;
    }
    p = i2d_body_get_position(state->mover);
    if (i2d_last_status() != I2D_OK) {
        return false;
    }
    error = fabs((double)p.x - expected_x) + fabs((double)(p.y - state->mover_start.y));
    set_figure(out, "inside", (double)inside);
    set_figure(out, "total", (double)state->body_count);
    set_figure(out, "platform error m", error);
    out->sane = inside == state->body_count && error < 1e-3;
    return true;
}

/* ---- fast_bullets: bullets ricocheting in a room of thin walls (extra) ---------------------- */

#define BULLET_COUNT 400
#define BULLET_BOXES 100
#define BULLET_RADIUS 0.05f
#define BULLET_MIN_SPEED 150.0f /* m/s: 2.5 to 5 m per step, 50 to 100 radii */
#define BULLET_MAX_SPEED 300.0f
#define BULLET_ROOM_HALF 20.0f
#define BULLET_WALL_HALF 0.025f /* 5 cm walls: a bullet crosses one in a tenth of a substep */

/* A bouncy bullet (restitution 0.9, no friction) fired in a fixed pseudo-random direction. */
static bool add_bullet(bench_state* state, i2d_vec2 position, uint32_t seed) {
    i2d_body_def def = i2d_default_body_def();
    i2d_shape_def shape = i2d_default_shape_def();
    i2d_circle circle;
    float angle = 2.0f * PI_F * (float)(seed % 1000u) / 1000.0f;
    float speed = BULLET_MIN_SPEED + (BULLET_MAX_SPEED - BULLET_MIN_SPEED) * (float)((seed / 1000u) % 100u) / 100.0f;
    i2d_body_id body;
    def.type = I2D_BODY_DYNAMIC;
    def.position = position;
    def.linear_velocity = vec2(speed * cosf(angle), speed * sinf(angle));
    def.is_bullet = true;
    def.gravity_scale = 0.0f;
    shape.restitution = 0.9f;
    shape.friction = 0.0f;
    circle.center = vec2(0.0f, 0.0f);
    circle.radius = BULLET_RADIUS;
    body = i2d_body_create(state->world, &def);
    if (I2D_IS_NULL(body) || I2D_IS_NULL(i2d_shape_create_circle(body, &shape, &circle))) {
        return false;
    }
    state->bodies[state->body_count] = body;
    state->start_x[state->body_count] = position.x;
    state->start_y[state->body_count] = position.y;
    state->body_count++;
    return true;
}

static bool create_fast_bullets(bench_state* state) {
    const float h = BULLET_ROOM_HALF, t = BULLET_WALL_HALF;
    uint32_t seed = 12345u;
    int32_t i;
    if (!create_world(state, false) || !reserve_bodies(state, BULLET_COUNT + BULLET_BOXES, 0) ||
        !add_static_box(state, 0.0f, -t, h, t) || !add_static_box(state, 0.0f, 2.0f * h + t, h, t) ||
        !add_static_box(state, -h - t, h, t, h) || !add_static_box(state, h + t, h, t, h)) {
        return false;
    }
    state->region = aabb(-h, 0.0f, h, 2.0f * h);
    for (i = 0; i < BULLET_BOXES; ++i) {
        i2d_vec2 p = vec2(-18.0f + 3.6f * (float)(i % 10), 1.0f + 3.6f * (float)(i / 10));
        if (!add_dynamic(state, p, false, 0.3f)) {
            return false;
        }
    }
    for (i = 0; i < BULLET_COUNT; ++i) {
        i2d_vec2 p = vec2(-19.0f + 1.9f * (float)(i % 20), 2.8f + 1.8f * (float)(i / 20));
        seed = seed * 1664525u + 1013904223u; /* an LCG: the same scene on every platform */
        if (!add_bullet(state, p, seed >> 8)) {
            return false;
        }
    }
    return true;
}

/* ---- The table ----------------------------------------------------------------------------- */

static const char tumbler_substitution[] =
    "drum is a KINEMATIC body turning at +25 deg/s about (0, 10), not a dynamic drum on a revolute motor "
    "(no joints yet; scenes.md allows this)";

const bench_scene bench_scenes[] = {
    {"large_pyramid", BENCH_GROUP_SCENES_MD, NULL, 0,
     "100-row pyramid of 5050 1 m boxes on a static box ground (sleep off)", NULL, BENCH_SLEEP_OFF, 500,
     create_large_pyramid, NULL, sanity_pyramids},
    {"many_pyramids", BENCH_GROUP_SCENES_MD, NULL, 0,
     "20 x 20 ten-row pyramids (22000 1 m boxes) on 20 static segments (sleep off)", NULL, BENCH_SLEEP_OFF, 200,
     create_many_pyramids, NULL, sanity_pyramids},
    {"tumbler", BENCH_GROUP_SCENES_MD, NULL, 0,
     "2025 0.25 m boxes in a 20 x 20 hollow drum turning at 25 deg/s (sleep on)", tumbler_substitution,
     BENCH_SLEEP_ON, 750, create_tumbler, NULL, sanity_tumbler},
    {"small", BENCH_GROUP_EXTRA, NULL, 0, "50 circles and boxes in a room with a scripted kinematic platform",
     NULL, BENCH_SLEEP_ON, 500, create_small, small_step_hook, sanity_small},
    {"box_grid", BENCH_GROUP_EXTRA, NULL, 0, "50 x 20 columns of 1 m boxes resting on the ground (sleep off)",
     NULL, BENCH_SLEEP_OFF, 500, create_box_grid, NULL, sanity_top_row_drop},
    {"sleeping_pile", BENCH_GROUP_EXTRA, NULL, 0,
     "10 twenty-row pyramids and 50 columns of 20 boxes (3100 1 m boxes), stepped until all sleep, then timed",
     NULL, BENCH_SLEEP_FIRST, 500, create_sleeping_pile, NULL, sanity_sleeping_pile},
    {"fast_bullets", BENCH_GROUP_EXTRA, NULL, 0,
     "400 bullets (r 5 cm, 150-300 m/s, restitution 0.9) and 100 boxes in a 40 m room of 5 cm walls (sleep off)",
     NULL, BENCH_SLEEP_OFF, 300, create_fast_bullets, NULL, sanity_inside_all},
    {"rain_circles_1k", BENCH_GROUP_SWEEP, "rain_circles", 1000,
     "1000 circles (r 0.25-0.5 m) rain from a grid into an open box (sleep off)", NULL, BENCH_SLEEP_OFF, 500,
     create_rain_1k, NULL, sanity_inside_all},
    {"rain_circles_4k", BENCH_GROUP_SWEEP, "rain_circles", 4000,
     "4000 circles (r 0.25-0.5 m) rain from a grid into an open box (sleep off)", NULL, BENCH_SLEEP_OFF, 500,
     create_rain_4k, NULL, sanity_inside_all},
    {"rain_circles_16k", BENCH_GROUP_SWEEP, "rain_circles", 16000,
     "16000 circles (r 0.25-0.5 m) rain from a grid into an open box (sleep off)", NULL, BENCH_SLEEP_OFF, 500,
     create_rain_16k, NULL, sanity_inside_all},
    {"rain_circles_64k", BENCH_GROUP_SWEEP, "rain_circles", 64000,
     "64000 circles (r 0.25-0.5 m) rain from a grid into an open box (sleep off)", NULL, BENCH_SLEEP_OFF, 500,
     create_rain_64k, NULL, sanity_inside_all},
    {"pyramid_field_1k", BENCH_GROUP_SWEEP, "pyramid_field", 1000,
     "18 ten-row pyramids (990 boxes) on segments, as many_pyramids (sleep off)", NULL, BENCH_SLEEP_OFF, 200,
     create_pyramid_field_1k, NULL, sanity_pyramids},
    {"pyramid_field_4k", BENCH_GROUP_SWEEP, "pyramid_field", 4000,
     "73 ten-row pyramids (4015 boxes) on segments, as many_pyramids (sleep off)", NULL, BENCH_SLEEP_OFF, 200,
     create_pyramid_field_4k, NULL, sanity_pyramids},
    {"pyramid_field_16k", BENCH_GROUP_SWEEP, "pyramid_field", 16000,
     "291 ten-row pyramids (16005 boxes) on segments, as many_pyramids (sleep off)", NULL, BENCH_SLEEP_OFF, 200,
     create_pyramid_field_16k, NULL, sanity_pyramids},
    {"pyramid_field_64k", BENCH_GROUP_SWEEP, "pyramid_field", 64000,
     "1164 ten-row pyramids (64020 boxes) on segments, as many_pyramids (sleep off)", NULL, BENCH_SLEEP_OFF, 200,
     create_pyramid_field_64k, NULL, sanity_pyramids},
};
const int32_t bench_scene_count = (int32_t)(sizeof bench_scenes / sizeof bench_scenes[0]);

const bench_missing_scene bench_missing_scenes[] = {
    {"rain", "1000 ragdolls of 11 capsule bodies held by revolute joints; impulse2d has no joints yet"},
};
const int32_t bench_missing_scene_count = (int32_t)(sizeof bench_missing_scenes / sizeof bench_missing_scenes[0]);

const bench_scene* bench_find_scene(const char* name) {
    int32_t i;
    for (i = 0; i < bench_scene_count; ++i) {
        if (strcmp(bench_scenes[i].name, name) == 0) {
            return &bench_scenes[i];
        }
    }
    return NULL;
}

/* ---- State ------------------------------------------------------------------------------------ */

bool bench_state_destroy(bench_state* state) {
    bool ok = true;
    if (!I2D_IS_NULL(state->world)) {
        ok = i2d_world_destroy(state->world) == I2D_OK;
    }
    free(state->bodies);
    free(state->start_x);
    free(state->start_y);
    free(state->marks);
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
        i2d_transform xf = i2d_body_get_transform(state->bodies[i]);
        i2d_vec2 v;
        float w;
        if (i2d_last_status() != I2D_OK) {
            return false;
        }
        v = i2d_body_get_linear_velocity(state->bodies[i]);
        if (i2d_last_status() != I2D_OK) {
            return false;
        }
        w = i2d_body_get_angular_velocity(state->bodies[i]);
        if (i2d_last_status() != I2D_OK) {
            return false;
        }
        h = fnv1a_float(fnv1a_float(fnv1a_float(fnv1a_float(h, xf.p.x), xf.p.y), xf.q.c), xf.q.s);
        h = fnv1a_float(fnv1a_float(fnv1a_float(h, v.x), v.y), w);
    }
    *hash = h;
    return true;
}

bool bench_count_awake(const bench_state* state, int32_t* awake) {
    int32_t i;
    *awake = 0;
    for (i = 0; i < state->body_count; ++i) {
        bool is_awake = i2d_body_is_awake(state->bodies[i]);
        if (i2d_last_status() != I2D_OK) {
            return false;
        }
        *awake += is_awake;
    }
    return true;
}
