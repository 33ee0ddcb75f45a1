/* SPDX-License-Identifier: MIT */
/* Bulk state (i2d_world_get/set_body_*) against the per-body calls, the checks that
 * refuse a call without writing anything, and the struct self-description. */
#include <impulse2d/impulse2d.h>

#include <stddef.h>
#include <string.h>

#include "api_test_support.h"
#include "check.h"

#define BODY_COUNT 24

/* A scene with every kind of body: a static ground, kinematic and dynamic boxes and
 * circles (some fixed-rotation), resting and falling. */
typedef struct scene {
    i2d_world_id world;
    i2d_body_id bodies[BODY_COUNT];
} scene;

static void make_scene(scene* s) {
    i2d_world_def world_def = i2d_default_world_def();
    s->world = i2d_world_create(&world_def);
    i2d_shape_def shape_def = i2d_default_shape_def();
    rng r = {42};
    for (int i = 0; i < BODY_COUNT; ++i) {
        i2d_body_def def = i2d_default_body_def();
        def.type = i == 0 ? I2D_BODY_STATIC : (i % 7 == 3 ? I2D_BODY_KINEMATIC : I2D_BODY_DYNAMIC);
        def.position = i == 0 ? v2(0.0f, -1.0f) : v2(rng_float(&r, -8.0f, 8.0f), 0.5f + 1.2f * (float)i);
        def.rotation = i2d_make_rot(rng_float(&r, -3.0f, 3.0f));
        def.fixed_rotation = i % 5 == 4;
        s->bodies[i] = i2d_body_create(s->world, &def);
        if (i == 0) {
            i2d_shape_create_box(s->bodies[i], &shape_def, 20.0f, 1.0f);
        } else if (i % 2 == 0) {
            i2d_shape_create_box(s->bodies[i], &shape_def, 0.4f, 0.3f);
        } else {
            i2d_circle c = {{0.0f, 0.0f}, 0.35f};
            i2d_shape_create_circle(s->bodies[i], &shape_def, &c);
        }
    }
    for (int i = 0; i < 30; ++i) {
        i2d_world_step(s->world, 1.0f / 60.0f, 4);
    }
}

static int same_transform(i2d_transform a, i2d_transform b) { return memcmp(&a, &b, sizeof a) == 0; }

static int same_vec2(i2d_vec2 a, i2d_vec2 b) { return memcmp(&a, &b, sizeof a) == 0; }

/* ---- Reads agree with the per-body getters, bit for bit ------------------------------ */

I2D_TEST(api_bulk_reads_match_per_body_getters) {
    scene s;
    make_scene(&s);
    i2d_transform xf[BODY_COUNT + 1];
    i2d_vec2 linear[BODY_COUNT + 1];
    float angular[BODY_COUNT + 1];
    memset(xf, 0x5A, sizeof xf);
    memset(linear, 0x5A, sizeof linear);
    memset(angular, 0x5A, sizeof angular);
    const i2d_transform sentinel = xf[BODY_COUNT];

    I2D_CHECK_STATUS(i2d_world_get_body_transforms(s.world, s.bodies, BODY_COUNT, xf), I2D_OK);
    I2D_CHECK_STATUS(i2d_world_get_body_velocities(s.world, s.bodies, BODY_COUNT, linear, angular), I2D_OK);
    int moving = 0;
    for (int i = 0; i < BODY_COUNT; ++i) {
        I2D_CHECK(same_transform(xf[i], i2d_body_get_transform(s.bodies[i])));
        I2D_CHECK(same_vec2(linear[i], i2d_body_get_linear_velocity(s.bodies[i])));
        I2D_CHECK(angular[i] == i2d_body_get_angular_velocity(s.bodies[i]));
        moving += linear[i].y != 0.0f;
    }
    I2D_CHECK(moving > BODY_COUNT / 2); /* the scene is falling: the values are not all zero */
    I2D_CHECK(same_transform(xf[BODY_COUNT], sentinel)); /* nothing written past count */

    /* Either velocity array may be skipped; a list may repeat and reorder ids. */
    i2d_body_id picked[3] = {s.bodies[5], s.bodies[2], s.bodies[5]};
    float spin[3];
    I2D_CHECK_STATUS(i2d_world_get_body_velocities(s.world, picked, 3, NULL, spin), I2D_OK);
    I2D_CHECK(spin[0] == angular[5] && spin[1] == angular[2] && spin[2] == angular[5]);
    I2D_CHECK_STATUS(i2d_world_get_body_transforms(s.world, NULL, 0, NULL), I2D_OK);
    i2d_world_destroy(s.world);
}

/* ---- Writes do what the per-body setters do, to the last bit ------------------------- */

/* Sets every body's velocities and half the transforms, once through the bulk calls and
 * once body by body on an identical world; then both worlds step and must stay equal. */
I2D_TEST(api_bulk_writes_match_per_body_setters) {
    scene bulk, single;
    make_scene(&bulk);
    make_scene(&single);
    I2D_REQUIRE(i2d_world_get_state_hash(bulk.world) == i2d_world_get_state_hash(single.world));

    i2d_vec2 linear[BODY_COUNT];
    float angular[BODY_COUNT];
    i2d_transform xf[BODY_COUNT / 2];
    i2d_body_id moved[BODY_COUNT / 2];
    rng r = {7};
    for (int i = 0; i < BODY_COUNT; ++i) {
        linear[i] = v2(rng_float(&r, -3.0f, 3.0f), rng_float(&r, -3.0f, 3.0f));
        angular[i] = rng_float(&r, -4.0f, 4.0f);
    }
    for (int i = 0; i < BODY_COUNT / 2; ++i) {
        moved[i] = bulk.bodies[2 * i + 1];
        xf[i].p = v2(rng_float(&r, -9.0f, 9.0f), rng_float(&r, 2.0f, 30.0f));
        xf[i].q = i2d_make_rot(rng_float(&r, -3.0f, 3.0f));
    }
    I2D_CHECK_STATUS(i2d_world_set_body_velocities(bulk.world, bulk.bodies, BODY_COUNT, linear, angular), I2D_OK);
    I2D_CHECK_STATUS(i2d_world_set_body_transforms(bulk.world, moved, BODY_COUNT / 2, xf), I2D_OK);
    for (int i = 0; i < BODY_COUNT; ++i) {
        I2D_CHECK_STATUS(i2d_body_set_linear_velocity(single.bodies[i], linear[i]), I2D_OK);
        I2D_CHECK_STATUS(i2d_body_set_angular_velocity(single.bodies[i], angular[i]), I2D_OK);
    }
    for (int i = 0; i < BODY_COUNT / 2; ++i) {
        I2D_CHECK_STATUS(i2d_body_set_transform(single.bodies[2 * i + 1], xf[i].p, xf[i].q), I2D_OK);
    }
    /* The per-body rules hold: the static ground ignores a velocity, fixed-rotation
     * bodies ignore a spin, the others take what they were given. */
    I2D_CHECK(same_vec2(i2d_body_get_linear_velocity(bulk.bodies[0]), v2(0.0f, 0.0f)));
    I2D_CHECK(i2d_body_get_angular_velocity(bulk.bodies[4]) == 0.0f);
    I2D_CHECK(same_vec2(i2d_body_get_linear_velocity(bulk.bodies[2]), linear[2]));
    I2D_CHECK(same_transform(i2d_body_get_transform(bulk.bodies[3]), i2d_body_get_transform(single.bodies[3])));
    I2D_CHECK(i2d_world_get_state_hash(bulk.world) == i2d_world_get_state_hash(single.world));
    for (int i = 0; i < 60; ++i) {
        i2d_world_step(bulk.world, 1.0f / 60.0f, 4);
        i2d_world_step(single.world, 1.0f / 60.0f, 4);
    }
    I2D_CHECK(i2d_world_get_state_hash(bulk.world) == i2d_world_get_state_hash(single.world));
    i2d_world_destroy(bulk.world);
    i2d_world_destroy(single.world);
}

/* A sleeping body wakes when the bulk call gives it a velocity, as the per-body one does. */
I2D_TEST(api_bulk_velocity_wakes_sleeping_body) {
    scene s;
    make_scene(&s);
    i2d_body_id body = s.bodies[2];
    I2D_REQUIRE(i2d_body_set_awake(body, false) == I2D_OK);
    I2D_REQUIRE(!i2d_body_is_awake(body));
    i2d_vec2 v = v2(0.0f, 0.0f);
    I2D_CHECK_STATUS(i2d_world_set_body_velocities(s.world, &body, 1, &v, NULL), I2D_OK);
    I2D_CHECK(!i2d_body_is_awake(body)); /* zero velocity: no reason to wake */
    v = v2(1.0f, 0.0f);
    I2D_CHECK_STATUS(i2d_world_set_body_velocities(s.world, &body, 1, &v, NULL), I2D_OK);
    I2D_CHECK(i2d_body_is_awake(body));
    i2d_world_destroy(s.world);
}

/* ---- Waking: what a write wakes and whose rest timer it restarts --------------------- */

#define STEP_TIME (1.0f / 60.0f)
#define SUBSTEPS 4

/* Two boxes resting on a ground a little apart: their fat boxes overlap, so they share a
 * contact, but it has no points, so they are separate islands that fall asleep on their
 * own timers. */
typedef struct neighbours {
    i2d_world_id world;
    i2d_body_id moved, other;
} neighbours;

#define NEIGHBOUR_GAP 0.05f /* m: more than the speculative distance, less than two margins */

static void make_neighbours(neighbours* n, bool enable_sleep) {
    i2d_world_def world_def = i2d_default_world_def();
    world_def.enable_sleep = enable_sleep;
    n->world = i2d_world_create(&world_def);
    i2d_shape_def shape_def = i2d_default_shape_def();
    i2d_body_def def = i2d_default_body_def();
    def.position = v2(0.0f, -1.0f);
    i2d_shape_create_box(i2d_body_create(n->world, &def), &shape_def, 10.0f, 1.0f);
    def.type = I2D_BODY_DYNAMIC;
    def.position = v2(0.0f, 0.5f);
    n->moved = i2d_body_create(n->world, &def);
    i2d_shape_create_box(n->moved, &shape_def, 0.5f, 0.5f);
    def.position = v2(1.0f + NEIGHBOUR_GAP, 0.5f);
    n->other = i2d_body_create(n->world, &def);
    i2d_shape_create_box(n->other, &shape_def, 0.5f, 0.5f);
}

/* Steps until the body sleeps; the step count, or -1 if it is still awake after limit. */
static int steps_until_asleep(i2d_world_id world, i2d_body_id body, int limit) {
    for (int step = 1; step <= limit; ++step) {
        i2d_world_step(world, STEP_TIME, SUBSTEPS);
        if (!i2d_body_is_awake(body)) {
            return step;
        }
    }
    return -1;
}

/* With nothing asleep, a bulk write still restarts the rest timer of what the moved body
 * touches, as waking it does: the neighbour (in an island of its own) falls asleep that
 * much later than in an untouched world, and at the same step as after the per-body call. */
I2D_TEST(api_bulk_transform_restarts_rest_timers_of_neighbours) {
    neighbours untouched, bulk, single;
    make_neighbours(&untouched, true);
    make_neighbours(&bulk, true);
    make_neighbours(&single, true);
    /* Rest for most of time_to_sleep (0.5 s): both still awake. */
    const int rest_steps = 20;
    for (int i = 0; i < rest_steps; ++i) {
        i2d_world_step(untouched.world, STEP_TIME, SUBSTEPS);
        i2d_world_step(bulk.world, STEP_TIME, SUBSTEPS);
        i2d_world_step(single.world, STEP_TIME, SUBSTEPS);
    }
    I2D_REQUIRE(i2d_body_is_awake(bulk.other) && i2d_body_is_awake(bulk.moved));
    I2D_REQUIRE(i2d_world_get_counters(bulk.world).sleeping_island_count == 0);

    /* The moved body is put back where it is: only the timers can change. */
    i2d_transform xf = i2d_body_get_transform(bulk.moved);
    I2D_CHECK_STATUS(i2d_world_set_body_transforms(bulk.world, &bulk.moved, 1, &xf), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_set_transform(single.moved, xf.p, xf.q), I2D_OK);

    const int limit = 120;
    const int untouched_sleeps = steps_until_asleep(untouched.world, untouched.other, limit);
    const int bulk_sleeps = steps_until_asleep(bulk.world, bulk.other, limit);
    const int single_sleeps = steps_until_asleep(single.world, single.other, limit);
    I2D_CHECK(untouched_sleeps > 0 && bulk_sleeps > 0);
    I2D_CHECK(bulk_sleeps >= untouched_sleeps + rest_steps / 2); /* the timer started over */
    I2D_CHECK(bulk_sleeps == single_sleeps);
    I2D_CHECK(i2d_world_get_state_hash(bulk.world) == i2d_world_get_state_hash(single.world));
    i2d_world_destroy(untouched.world);
    i2d_world_destroy(bulk.world);
    i2d_world_destroy(single.world);
}

/* A body put to sleep next to the moved one wakes with the bulk write, in a world that
 * sleeps and in one that does not (where only i2d_body_set_awake puts bodies to sleep). */
I2D_TEST(api_bulk_transform_wakes_sleeping_neighbours) {
    for (int enable_sleep = 0; enable_sleep < 2; ++enable_sleep) {
        neighbours n;
        make_neighbours(&n, enable_sleep != 0);
        i2d_world_step(n.world, STEP_TIME, SUBSTEPS);
        I2D_REQUIRE(i2d_body_set_awake(n.other, false) == I2D_OK);
        I2D_REQUIRE(!i2d_body_is_awake(n.other) && i2d_body_is_awake(n.moved));
        i2d_transform xf = i2d_body_get_transform(n.moved);
        xf.p.x -= 0.01f;
        I2D_CHECK_STATUS(i2d_world_set_body_transforms(n.world, &n.moved, 1, &xf), I2D_OK);
        I2D_CHECK(i2d_body_is_awake(n.other));
        I2D_CHECK(i2d_world_get_counters(n.world).sleeping_island_count == 0);
        i2d_world_destroy(n.world);
    }
}

/* ---- Writes at scale: the same as per-body calls, whatever sleeps ------------------- */

/* Enough bodies that a write crosses the 256-body chunks of i2d_world_set_body_transforms
 * and the trees take re-insertions in bulk. */
#define PILE_ROWS 12
#define PILE_COLUMNS 50
#define PILE_COUNT (PILE_ROWS * PILE_COLUMNS)
#define PILE_WRITES 423     /* bodies in one bulk write (some listed twice): not a multiple of 4 */
#define PILE_STEPS 120      /* steps after the write that must stay bit for bit equal */
#define PILE_SETTLE_STEPS 90
#define ROTATION_STRETCH 1.0004f /* c^2 + s^2 off 1 by 8e-4, within the 1e-3 accepted */

typedef struct pile {
    i2d_world_id world;
    i2d_body_id bodies[PILE_COUNT];
} pile;

/* Boxes, circles and capsules resting on a ground in loose rows: most touch their
 * neighbours, some only have their fat boxes overlap. A fraction is then put to sleep
 * when asked, so that the write must wake islands. */
static void make_pile(pile* p, bool enable_sleep, bool some_asleep) {
    i2d_world_def world_def = i2d_default_world_def();
    world_def.enable_sleep = enable_sleep;
    p->world = i2d_world_create(&world_def);
    i2d_shape_def shape_def = i2d_default_shape_def();
    i2d_body_def ground_def = i2d_default_body_def();
    ground_def.position = v2(0.0f, -1.0f);
    i2d_shape_create_box(i2d_body_create(p->world, &ground_def), &shape_def, 100.0f, 1.0f);
    for (int i = 0; i < PILE_COUNT; ++i) {
        i2d_body_def def = i2d_default_body_def();
        def.type = I2D_BODY_DYNAMIC;
        def.position = v2(-40.0f + 1.6f * (float)(i % PILE_COLUMNS), 0.6f + 1.1f * (float)(i / PILE_COLUMNS));
        p->bodies[i] = i2d_body_create(p->world, &def);
        if (i % 3 == 0) {
            i2d_shape_create_box(p->bodies[i], &shape_def, 0.5f, 0.5f);
        } else if (i % 3 == 1) {
            i2d_circle c = {{0.0f, 0.0f}, 0.5f};
            i2d_shape_create_circle(p->bodies[i], &shape_def, &c);
        } else {
            i2d_shape_create_capsule(p->bodies[i], &shape_def, v2(-0.3f, 0.0f), v2(0.3f, 0.0f), 0.25f);
        }
    }
    for (int i = 0; i < PILE_SETTLE_STEPS; ++i) {
        i2d_world_step(p->world, STEP_TIME, SUBSTEPS);
    }
    for (int i = 0; some_asleep && i < PILE_COUNT; i += 7) {
        i2d_body_set_awake(p->bodies[i], false);
    }
}

/* The first step (0 = right after the write) at which the worlds differ in hash or in
 * which bodies are awake, or -1. */
static int first_difference(const pile* a, const pile* b, int steps) {
    for (int step = 0; step <= steps; ++step) {
        if (step > 0) {
            i2d_world_step(a->world, STEP_TIME, SUBSTEPS);
            i2d_world_step(b->world, STEP_TIME, SUBSTEPS);
        }
        if (i2d_world_get_state_hash(a->world) != i2d_world_get_state_hash(b->world)) {
            return step;
        }
        for (int i = 0; i < PILE_COUNT; ++i) {
            if (i2d_body_is_awake(a->bodies[i]) != i2d_body_is_awake(b->bodies[i])) {
                return step;
            }
        }
    }
    return -1;
}

static int count_awake(const pile* p) {
    int awake = 0;
    for (int i = 0; i < PILE_COUNT; ++i) {
        awake += i2d_body_is_awake(p->bodies[i]);
    }
    return awake;
}

/* One bulk write of PILE_WRITES bodies in a random order against the same poses set
 * body by body, in worlds that sleep or not and with islands asleep or not (the bulk
 * call wakes what it touches only when something sleeps, and restarts rest timers only
 * when they count): then PILE_STEPS steps, every one the same to the bit. The poses mix
 * small nudges (the fat boxes still hold the shapes), teleports (re-insertions) and
 * bodies left where they are, and some rotations are a little off unit length, so that
 * the bulk call's normalisation must round as the per-body call's does. */
static void check_bulk_write_matches_per_body(bool enable_sleep, bool some_asleep) {
    pile bulk, single;
    make_pile(&bulk, enable_sleep, some_asleep);
    make_pile(&single, enable_sleep, some_asleep);
    I2D_REQUIRE(i2d_world_get_state_hash(bulk.world) == i2d_world_get_state_hash(single.world));
    const int awake_before = count_awake(&bulk);
    I2D_CHECK(some_asleep ? awake_before < PILE_COUNT : awake_before == PILE_COUNT);

    static int picked[PILE_WRITES];
    static i2d_body_id ids[PILE_WRITES];
    static i2d_transform xf[PILE_WRITES];
    rng r = {enable_sleep * 2 + some_asleep + 11};
    for (int k = 0; k < PILE_WRITES; ++k) {
        const int i = rng_int(&r, PILE_COUNT);
        picked[k] = i;
        ids[k] = bulk.bodies[i];
        xf[k] = i2d_body_get_transform(bulk.bodies[i]);
        const int kind = rng_int(&r, 3);
        if (kind == 0) { /* a nudge within the fat box's margin */
            xf[k].p.x += rng_float(&r, -0.02f, 0.02f);
            xf[k].q = i2d_make_rot(i2d_rot_get_angle(xf[k].q) + rng_float(&r, -0.01f, 0.01f));
        } else if (kind == 1) { /* a teleport above the pile */
            xf[k].p = v2(rng_float(&r, -40.0f, 40.0f), rng_float(&r, 15.0f, 30.0f));
            xf[k].q = i2d_make_rot(rng_float(&r, -3.0f, 3.0f));
        }
        if (k % 5 == 0) { /* off unit length within the tolerance: normalising changes bits */
            xf[k].q.c *= ROTATION_STRETCH;
            xf[k].q.s *= ROTATION_STRETCH;
        }
    }
    I2D_CHECK_STATUS(i2d_world_set_body_transforms(bulk.world, ids, PILE_WRITES, xf), I2D_OK);
    for (int k = 0; k < PILE_WRITES; ++k) {
        I2D_CHECK_STATUS(i2d_body_set_transform(single.bodies[picked[k]], xf[k].p, xf[k].q), I2D_OK);
    }
    if (some_asleep) {
        I2D_CHECK(count_awake(&bulk) > awake_before); /* the write woke islands */
    }
    const int differs = first_difference(&bulk, &single, PILE_STEPS);
    if (differs >= 0) {
        ++i2d_check_failures;
        fprintf(stderr, "sleep %d, some asleep %d: bulk and per-body worlds differ at step %d\n", enable_sleep,
                some_asleep, differs);
    }
    i2d_world_destroy(bulk.world);
    i2d_world_destroy(single.world);
}

I2D_TEST(api_bulk_transforms_match_per_body_in_sleeping_worlds) {
    check_bulk_write_matches_per_body(true, false);
    check_bulk_write_matches_per_body(true, true);
}

I2D_TEST(api_bulk_transforms_match_per_body_in_worlds_without_sleep) {
    check_bulk_write_matches_per_body(false, false);
    check_bulk_write_matches_per_body(false, true);
}

/* ---- Refused calls name the index and change nothing --------------------------------- */

static int message_has(const char* text) { return strstr(i2d_last_error_message(), text) != NULL; }

/* Runs every bulk call with bodies[bad] replaced by `id`: each must answer the status,
 * name the index, and leave the outputs and the world untouched. */
static void check_refused_id(scene* s, i2d_body_id id, int bad, i2d_status expected, const char* detail) {
    i2d_body_id list[BODY_COUNT];
    memcpy(list, s->bodies, sizeof list);
    list[bad] = id;
    char where[32];
    snprintf(where, sizeof where, "bodies[%d]", bad);
    const uint64_t before = i2d_world_get_state_hash(s->world);

    i2d_transform xf[BODY_COUNT], xf_copy[BODY_COUNT];
    i2d_vec2 linear[BODY_COUNT], linear_copy[BODY_COUNT];
    float angular[BODY_COUNT], angular_copy[BODY_COUNT];
    memset(xf, 0x33, sizeof xf);
    memset(linear, 0x33, sizeof linear);
    memset(angular, 0x33, sizeof angular);
    memcpy(xf_copy, xf, sizeof xf);
    memcpy(linear_copy, linear, sizeof linear);
    memcpy(angular_copy, angular, sizeof angular);

    I2D_CHECK_STATUS(i2d_world_get_body_transforms(s->world, list, BODY_COUNT, xf), expected);
    I2D_CHECK(message_has(where) && message_has(detail));
    I2D_CHECK_STATUS(i2d_world_get_body_velocities(s->world, list, BODY_COUNT, linear, angular), expected);
    I2D_CHECK(message_has(where) && message_has(detail));
    I2D_CHECK(memcmp(xf, xf_copy, sizeof xf) == 0);
    I2D_CHECK(memcmp(linear, linear_copy, sizeof linear) == 0);
    I2D_CHECK(memcmp(angular, angular_copy, sizeof angular) == 0);

    /* Valid values for the setters, so that only the id can be the reason. */
    for (int i = 0; i < BODY_COUNT; ++i) {
        linear[i] = v2(1.0f, 2.0f);
        angular[i] = 0.5f;
        xf[i].p = v2(0.0f, 50.0f + (float)i);
        xf[i].q = i2d_make_rot(0.25f);
    }
    I2D_CHECK_STATUS(i2d_world_set_body_velocities(s->world, list, BODY_COUNT, linear, angular), expected);
    I2D_CHECK(message_has(where));
    I2D_CHECK_STATUS(i2d_world_set_body_transforms(s->world, list, BODY_COUNT, xf), expected);
    I2D_CHECK(message_has(where));
    I2D_CHECK(i2d_world_get_state_hash(s->world) == before);
}

I2D_TEST(api_bulk_refuses_bad_ids_by_index) {
    scene s, other;
    make_scene(&s);
    make_scene(&other);
    i2d_body_def def = i2d_default_body_def();
    i2d_body_id doomed = i2d_body_create(s.world, &def);
    i2d_body_destroy(doomed);
    i2d_body_id null_id = {0};
    i2d_body_id shape_as_body;
    i2d_shape_id shape;
    I2D_REQUIRE(i2d_body_get_shapes(s.bodies[6], &shape, 1) == 1);
    shape_as_body.bits = shape.bits;

    check_refused_id(&s, doomed, 7, I2D_ERR_INVALID_HANDLE, "stale");
    check_refused_id(&s, null_id, 0, I2D_ERR_INVALID_HANDLE, "null");
    check_refused_id(&s, shape_as_body, BODY_COUNT - 1, I2D_ERR_INVALID_HANDLE, "not a body id");
    check_refused_id(&s, other.bodies[3], 11, I2D_ERR_INVALID_HANDLE, "another world");
    i2d_body_id orphan = other.bodies[3];
    i2d_world_destroy(other.world);
    check_refused_id(&s, orphan, 12, I2D_ERR_INVALID_HANDLE, "world was destroyed");
    i2d_world_destroy(s.world);
}

I2D_TEST(api_bulk_refuses_bad_values_and_arguments) {
    scene s;
    make_scene(&s);
    const uint64_t before = i2d_world_get_state_hash(s.world);
    i2d_vec2 linear[BODY_COUNT];
    float angular[BODY_COUNT];
    i2d_transform xf[BODY_COUNT];
    for (int i = 0; i < BODY_COUNT; ++i) {
        linear[i] = v2(0.5f, -0.5f);
        angular[i] = 1.0f;
        xf[i].p = v2((float)i, 40.0f);
        xf[i].q = i2d_make_rot(0.1f * (float)i);
    }
    linear[9].y = NAN;
    I2D_CHECK_STATUS(i2d_world_set_body_velocities(s.world, s.bodies, BODY_COUNT, linear, angular),
                     I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(message_has("linear[9].y is NaN"));
    linear[9].y = 0.0f;
    angular[BODY_COUNT - 1] = INFINITY;
    I2D_CHECK_STATUS(i2d_world_set_body_velocities(s.world, s.bodies, BODY_COUNT, linear, angular),
                     I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(message_has("angular[23]"));
    xf[4].q.c = 2.0f;
    I2D_CHECK_STATUS(i2d_world_set_body_transforms(s.world, s.bodies, BODY_COUNT, xf), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(message_has("transforms[4]") && message_has("unit rotation"));
    xf[4].q = i2d_make_rot(0.0f);
    xf[17].p.x = 2e9f;
    I2D_CHECK_STATUS(i2d_world_set_body_transforms(s.world, s.bodies, BODY_COUNT, xf), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(message_has("transforms[17]"));
    I2D_CHECK(i2d_world_get_state_hash(s.world) == before); /* none of the good ones was applied */

    I2D_CHECK_STATUS(i2d_world_get_body_transforms(s.world, s.bodies, -1, xf), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(message_has("count"));
    I2D_CHECK_STATUS(i2d_world_get_body_transforms(s.world, NULL, 3, xf), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK_STATUS(i2d_world_get_body_transforms(s.world, s.bodies, 3, NULL), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK_STATUS(i2d_world_set_body_transforms(s.world, s.bodies, 3, NULL), I2D_ERR_INVALID_ARGUMENT);
    i2d_world_id null_world = {0};
    I2D_CHECK_STATUS(i2d_world_get_body_transforms(null_world, s.bodies, 3, xf), I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(i2d_world_get_state_hash(s.world) == before);
    i2d_world_destroy(s.world);
}

/* Inside a query callback the world is locked: reads work, writes are refused. */
typedef struct locked_probe {
    scene* s;
    i2d_status get, set_velocity, set_transform;
} locked_probe;

static bool probe_while_locked(i2d_shape_id shape, void* context) {
    (void)shape;
    locked_probe* p = (locked_probe*)context;
    i2d_transform xf[BODY_COUNT];
    i2d_vec2 v[BODY_COUNT];
    p->get = i2d_world_get_body_transforms(p->s->world, p->s->bodies, BODY_COUNT, xf);
    memset(v, 0, sizeof v);
    p->set_velocity = i2d_world_set_body_velocities(p->s->world, p->s->bodies, BODY_COUNT, v, NULL);
    p->set_transform = i2d_world_set_body_transforms(p->s->world, p->s->bodies, BODY_COUNT, xf);
    return false;
}

I2D_TEST(api_bulk_writes_refused_while_locked) {
    scene s;
    make_scene(&s);
    locked_probe probe = {&s, I2D_OK, I2D_OK, I2D_OK};
    i2d_aabb everything = {{-100.0f, -100.0f}, {100.0f, 100.0f}};
    const uint64_t before = i2d_world_get_state_hash(s.world);
    I2D_CHECK_STATUS(i2d_world_overlap_aabb(s.world, everything, i2d_default_query_filter(), probe_while_locked, &probe),
                     I2D_OK);
    I2D_CHECK(probe.get == I2D_OK);
    I2D_CHECK(probe.set_velocity == I2D_ERR_WORLD_LOCKED);
    I2D_CHECK(probe.set_transform == I2D_ERR_WORLD_LOCKED);
    I2D_CHECK(i2d_world_get_state_hash(s.world) == before);
    i2d_world_destroy(s.world);
}

/* ---- Self-description ---------------------------------------------------------------- */

/* C99 has no alignof: the offset of a member after a char is its alignment. */
#define ALIGN_PROBE(type) \
    struct align_##type {   \
        char c;             \
        type t;             \
    };
ALIGN_PROBE(i2d_struct_info)
ALIGN_PROBE(i2d_vec2)
ALIGN_PROBE(i2d_transform)
ALIGN_PROBE(i2d_body_id)
ALIGN_PROBE(i2d_world_def)
ALIGN_PROBE(i2d_body_def)
ALIGN_PROBE(i2d_shape_def)
ALIGN_PROBE(i2d_filter)
ALIGN_PROBE(i2d_body_move_event)
ALIGN_PROBE(i2d_contact_events)
ALIGN_PROBE(i2d_ray_result)
ALIGN_PROBE(i2d_polygon)
ALIGN_PROBE(i2d_manifold)
ALIGN_PROBE(i2d_world_counters)
ALIGN_PROBE(i2d_profile)
#define C_ALIGN(type) ((int32_t)offsetof(struct align_##type, t))

typedef struct expected_info {
    const char* name;
    int32_t size, align;
} expected_info;

I2D_TEST(api_struct_infos_match_this_compiler) {
    const i2d_struct_info* infos = NULL;
    const int32_t count = i2d_get_struct_infos(&infos);
    I2D_REQUIRE(infos != NULL && count >= 30);
    I2D_CHECK(i2d_get_struct_infos(NULL) == count);
    I2D_CHECK(i2d_last_status() == I2D_OK);
    const expected_info expected[] = {
        {"i2d_struct_info", sizeof(i2d_struct_info), C_ALIGN(i2d_struct_info)},
        {"i2d_vec2", sizeof(i2d_vec2), C_ALIGN(i2d_vec2)},
        {"i2d_transform", sizeof(i2d_transform), C_ALIGN(i2d_transform)},
        {"i2d_body_id", sizeof(i2d_body_id), C_ALIGN(i2d_body_id)},
        {"i2d_world_def", sizeof(i2d_world_def), C_ALIGN(i2d_world_def)},
        {"i2d_body_def", sizeof(i2d_body_def), C_ALIGN(i2d_body_def)},
        {"i2d_shape_def", sizeof(i2d_shape_def), C_ALIGN(i2d_shape_def)},
        {"i2d_filter", sizeof(i2d_filter), C_ALIGN(i2d_filter)},
        {"i2d_body_move_event", sizeof(i2d_body_move_event), C_ALIGN(i2d_body_move_event)},
        {"i2d_contact_events", sizeof(i2d_contact_events), C_ALIGN(i2d_contact_events)},
        {"i2d_ray_result", sizeof(i2d_ray_result), C_ALIGN(i2d_ray_result)},
        {"i2d_polygon", sizeof(i2d_polygon), C_ALIGN(i2d_polygon)},
        {"i2d_manifold", sizeof(i2d_manifold), C_ALIGN(i2d_manifold)},
        {"i2d_world_counters", sizeof(i2d_world_counters), C_ALIGN(i2d_world_counters)},
        {"i2d_profile", sizeof(i2d_profile), C_ALIGN(i2d_profile)},
    };
    for (size_t e = 0; e < sizeof expected / sizeof expected[0]; ++e) {
        int found = 0;
        for (int32_t i = 0; i < count; ++i) {
            if (strcmp(infos[i].name, expected[e].name) == 0) {
                ++found;
                if (infos[i].size != expected[e].size || infos[i].align != expected[e].align) {
                    ++i2d_check_failures;
                    fprintf(stderr, "%s: library says size %d align %d, C says %d, %d\n", expected[e].name,
                            infos[i].size, infos[i].align, expected[e].size, expected[e].align);
                }
            }
        }
        if (found != 1) {
            ++i2d_check_failures;
            fprintf(stderr, "%s listed %d times\n", expected[e].name, found);
        }
    }
    for (int32_t i = 0; i < count; ++i) {
        I2D_CHECK(strncmp(infos[i].name, "i2d_", 4) == 0);
        I2D_CHECK(infos[i].size > 0 && infos[i].align > 0 && infos[i].size % infos[i].align == 0);
    }
}
