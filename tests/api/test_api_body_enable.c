/* SPDX-License-Identifier: MIT */
/* i2d_body_disable, i2d_body_enable, i2d_body_is_enabled through the public API: queries
 * and sensors skip a disabled body and find it again once it is enabled; shapes, joints,
 * poses and types change on it while it is away; bad ids and locked worlds are refused
 * with the world untouched, and a call that finds the body so already changes nothing; a
 * snapshot holding disabled bodies, restored and stepped, and a replay of a recording
 * with disables and enables, give the hashes of the world that never stopped. */
#include <stdlib.h>
#include <string.h>

#include "api_test_support.h"

/* ---- Helpers ----------------------------------------------------------------------- */

static i2d_body_id add_box(i2d_world_id world, i2d_body_type type, float x, float y, float half) {
    i2d_body_id body = make_body(world, type, x, y);
    i2d_shape_def def = i2d_default_shape_def();
    if (I2D_IS_NULL(body) || I2D_IS_NULL(i2d_shape_create_box(body, &def, half, half))) {
        return I2D_NULL_BODY_ID;
    }
    return body;
}

static i2d_shape_id first_shape(i2d_body_id body) {
    i2d_shape_id shape = I2D_NULL_SHAPE_ID;
    i2d_body_get_shapes(body, &shape, 1);
    return shape;
}

static int32_t shapes_in(i2d_world_id world, i2d_aabb area) {
    return i2d_world_overlap_aabb_ids(world, area, i2d_default_query_filter(), NULL, 0);
}

static int32_t shapes_at(i2d_world_id world, i2d_vec2 point) {
    return i2d_world_overlap_point_ids(world, point, i2d_default_query_filter(), NULL, 0);
}

static int32_t shapes_under_circle(i2d_world_id world, i2d_vec2 center, float radius) {
    const i2d_shape_proxy proxy = i2d_make_proxy(&center, 1, radius);
    return i2d_world_overlap_shape_ids(world, &proxy, i2d_default_query_filter(), NULL, 0);
}

/* The shape the ray along +x from (-3, y) meets first; the null id when none. */
static i2d_shape_id first_hit_along_x(i2d_world_id world, float y) {
    const i2d_ray_result hit = i2d_world_cast_ray_closest(world, v2(-3.0f, y), v2(20.0f, 0.0f),
                                                          i2d_default_query_filter());
    return hit.hit ? hit.shape : I2D_NULL_SHAPE_ID;
}

static i2d_shape_id first_swept_along_x(i2d_world_id world, float y) {
    const i2d_vec2 start = v2(-3.0f, y);
    const i2d_shape_proxy proxy = i2d_make_proxy(&start, 1, 0.1f);
    const i2d_ray_result hit = i2d_world_cast_shape_closest(world, &proxy, v2(20.0f, 0.0f),
                                                            i2d_default_query_filter());
    return hit.hit ? hit.shape : I2D_NULL_SHAPE_ID;
}

typedef struct bytes {
    unsigned char* data;
    size_t size, capacity;
} bytes;

static void append_bytes(const void* data, size_t size, void* context) {
    bytes* out = (bytes*)context;
    if (out->size + size > out->capacity) {
        size_t capacity = out->capacity * 2 + size + 4096;
        unsigned char* grown = (unsigned char*)realloc(out->data, capacity);
        if (grown == NULL) {
            return; /* the recording comes out short and the test says so */
        }
        out->data = grown;
        out->capacity = capacity;
    }
    memcpy(out->data + out->size, data, size);
    out->size += size;
}

/* ---- Queries and sensors ------------------------------------------------------------- */

/* A crate at the origin and a wall at x = 5: every kind of query skips the crate while it
 * is disabled (a shape made on it meanwhile too) and the wall once it is disabled as well;
 * enabled, both are found at once, the crate where it was put while away. */
static void queries_skip_a_disabled_body(i2d_world_id world) {
    const i2d_body_id crate = add_box(world, I2D_BODY_DYNAMIC, 0.0f, 0.0f, 0.5f);
    const i2d_body_id wall = add_box(world, I2D_BODY_STATIC, 5.0f, 0.0f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(crate) && !I2D_IS_NULL(wall));
    const i2d_shape_id crate_shape = first_shape(crate), wall_shape = first_shape(wall);
    const i2d_aabb around_crate = box(-1.0f, -1.0f, 1.0f, 1.0f);
    I2D_CHECK(shapes_in(world, around_crate) == 1);
    I2D_CHECK(I2D_ID_EQUALS(first_hit_along_x(world, 0.0f), crate_shape));

    I2D_REQUIRE(i2d_body_disable(crate) == I2D_OK);
    I2D_CHECK(!i2d_body_is_enabled(crate));
    I2D_CHECK(shapes_in(world, around_crate) == 0);
    I2D_CHECK(shapes_at(world, v2(0.0f, 0.0f)) == 0);
    I2D_CHECK(shapes_under_circle(world, v2(0.0f, 0.0f), 0.3f) == 0);
    I2D_CHECK(I2D_ID_EQUALS(first_hit_along_x(world, 0.0f), wall_shape));
    I2D_CHECK(I2D_ID_EQUALS(first_swept_along_x(world, 0.0f), wall_shape));
    I2D_CHECK(i2d_world_cast_ray_all(world, v2(-3.0f, 0.0f), v2(20.0f, 0.0f), i2d_default_query_filter(), NULL, 0) ==
              1);
    /* Getters still work on it; a shape made on it is not found either. */
    I2D_CHECK(i2d_body_get_shape_count(crate) == 1 && i2d_body_get_mass(crate) > 0.0f);
    i2d_shape_def def = i2d_default_shape_def();
    i2d_circle circle;
    circle.center = v2(0.0f, 0.0f);
    circle.radius = 0.8f;
    const i2d_shape_id added = i2d_shape_create_circle(crate, &def, &circle);
    I2D_REQUIRE(!I2D_IS_NULL(added));
    I2D_CHECK(shapes_in(world, around_crate) == 0);

    I2D_REQUIRE(i2d_body_disable(wall) == I2D_OK); /* static: it leaves the static tree */
    I2D_CHECK(I2D_IS_NULL(first_hit_along_x(world, 0.0f)) && I2D_IS_NULL(first_swept_along_x(world, 0.0f)));
    I2D_CHECK(shapes_at(world, v2(5.0f, 0.0f)) == 0);
    I2D_REQUIRE(step_ok(world));
    I2D_CHECK(shapes_in(world, box(-10.0f, -10.0f, 10.0f, 10.0f)) == 0);

    /* Moved while away: its shapes' bounds follow, and it is found there once enabled. */
    I2D_REQUIRE(i2d_body_set_transform(crate, v2(0.0f, 3.0f), identity_rot()) == I2D_OK);
    I2D_CHECK_NEAR(i2d_shape_get_aabb(crate_shape).min.y, 2.5f, 1e-6);
    I2D_CHECK(shapes_in(world, box(-1.0f, 2.0f, 1.0f, 4.0f)) == 0);
    I2D_REQUIRE(i2d_body_enable(crate) == I2D_OK);
    I2D_REQUIRE(i2d_body_enable(wall) == I2D_OK);
    I2D_CHECK(i2d_body_is_enabled(crate) && i2d_body_is_enabled(wall));
    I2D_CHECK(shapes_in(world, box(-1.0f, 2.0f, 1.0f, 4.0f)) == 2);
    I2D_CHECK(shapes_at(world, v2(0.0f, 3.0f)) == 2);
    I2D_CHECK(shapes_in(world, around_crate) == 0);
    I2D_CHECK(I2D_ID_EQUALS(first_hit_along_x(world, 0.0f), wall_shape));
    I2D_CHECK(I2D_ID_EQUALS(first_swept_along_x(world, 0.0f), wall_shape));
    const i2d_shape_id crate_hit = first_hit_along_x(world, 3.0f);
    I2D_CHECK(I2D_ID_EQUALS(crate_hit, crate_shape) || I2D_ID_EQUALS(crate_hit, added));
    I2D_CHECK(step_ok(world));
}

I2D_TEST(api_body_enable_queries_skip_a_disabled_body) { run_in_world(0.0f, queries_skip_a_disabled_body); }

/* A ball inside a sensor: disabling the ball ends its visit (reported at the next step),
 * and no visit begins while it is away; enabling it begins one again. The same when the
 * sensor's own body is disabled. */
static void sensor_visits_end_and_come_back(i2d_world_id world) {
    const i2d_body_id post = make_body(world, I2D_BODY_STATIC, 0.0f, 0.0f);
    i2d_shape_def sensor_def = i2d_default_shape_def();
    sensor_def.is_sensor = true;
    I2D_REQUIRE(!I2D_IS_NULL(post) && !I2D_IS_NULL(i2d_shape_create_box(post, &sensor_def, 2.0f, 2.0f)));
    const i2d_body_id ball = make_body(world, I2D_BODY_DYNAMIC, 0.0f, 0.0f);
    i2d_shape_def ball_def = i2d_default_shape_def();
    i2d_circle circle;
    circle.center = v2(0.0f, 0.0f);
    circle.radius = 0.25f;
    I2D_REQUIRE(!I2D_IS_NULL(ball) && !I2D_IS_NULL(i2d_shape_create_circle(ball, &ball_def, &circle)));
    I2D_REQUIRE(step_ok(world));
    I2D_CHECK(i2d_world_get_sensor_events(world).begin_count == 1);

    const i2d_body_id away[2] = {ball, post};
    for (int k = 0; k < 2; ++k) {
        I2D_REQUIRE(i2d_body_disable(away[k]) == I2D_OK);
        I2D_REQUIRE(step_ok(world));
        i2d_sensor_events events = i2d_world_get_sensor_events(world);
        I2D_CHECK(events.end_count == 1 && events.begin_count == 0);
        I2D_REQUIRE(step_ok(world));
        events = i2d_world_get_sensor_events(world);
        I2D_CHECK(events.end_count == 0 && events.begin_count == 0);
        I2D_REQUIRE(i2d_body_enable(away[k]) == I2D_OK);
        I2D_REQUIRE(step_ok(world));
        events = i2d_world_get_sensor_events(world);
        I2D_CHECK(events.begin_count == 1 && events.end_count == 0);
    }
}

I2D_TEST(api_body_enable_sensor_visits_end_and_come_back) { run_in_world(0.0f, sensor_visits_end_and_come_back); }

/* ---- Changes made while a body is away ------------------------------------------------- */

/* An origin shift moves a disabled body with the rest: enabled, it is found where the
 * shift put it. */
static void origin_shift_moves_a_disabled_body(i2d_world_id world) {
    const i2d_body_id crate = add_box(world, I2D_BODY_DYNAMIC, 100.0f, 50.0f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(crate));
    I2D_REQUIRE(i2d_body_disable(crate) == I2D_OK);
    I2D_REQUIRE(i2d_world_shift_origin(world, v2(100.0f, 50.0f)) == I2D_OK);
    const i2d_vec2 at = i2d_body_get_position(crate);
    I2D_CHECK(at.x == 0.0f && at.y == 0.0f);
    I2D_CHECK(i2d_shape_get_aabb(first_shape(crate)).min.x == -0.5f);
    I2D_CHECK(shapes_at(world, v2(0.0f, 0.0f)) == 0);
    I2D_REQUIRE(step_ok(world));
    I2D_REQUIRE(i2d_body_enable(crate) == I2D_OK);
    I2D_CHECK(shapes_at(world, v2(0.0f, 0.0f)) == 1);
    I2D_CHECK(shapes_in(world, box(99.0f, 49.0f, 101.0f, 51.0f)) == 0);
    I2D_CHECK(step_ok(world));
}

I2D_TEST(api_body_enable_origin_shift_moves_a_disabled_body) {
    run_in_world(0.0f, origin_shift_moves_a_disabled_body);
}

/* A body disabled keeps taking changes: a joint made to it, a shape, a type change, a
 * filter, a geometry, its destruction. None of it reaches the stages until it is enabled
 * (the hinge to it holds nothing, so its partner falls), and the world keeps stepping. */
static void changes_while_disabled(i2d_world_id world) {
    const i2d_body_id ground = add_box(world, I2D_BODY_STATIC, 0.0f, -0.5f, 0.5f);
    const i2d_body_id held = add_box(world, I2D_BODY_DYNAMIC, 0.0f, 10.0f, 0.25f);
    const i2d_body_id frame = add_box(world, I2D_BODY_STATIC, 0.0f, 12.0f, 0.25f);
    I2D_REQUIRE(!I2D_IS_NULL(ground) && !I2D_IS_NULL(held) && !I2D_IS_NULL(frame));
    I2D_REQUIRE(i2d_body_disable(frame) == I2D_OK);

    i2d_revolute_joint_def hinge = i2d_default_revolute_joint_def();
    hinge.base.body_a = frame;
    hinge.base.body_b = held;
    hinge.base.local_anchor_a = v2(0.0f, -1.0f);
    hinge.base.local_anchor_b = v2(0.0f, 1.0f);
    const i2d_joint_id joint = i2d_joint_create_revolute(world, &hinge);
    I2D_REQUIRE(!I2D_IS_NULL(joint));
    I2D_REQUIRE(i2d_body_set_type(frame, I2D_BODY_KINEMATIC) == I2D_OK);
    I2D_REQUIRE(i2d_body_set_type(frame, I2D_BODY_STATIC) == I2D_OK);
    i2d_shape_def def = i2d_default_shape_def();
    const i2d_shape_id extra = i2d_shape_create_box(frame, &def, 3.0f, 0.1f);
    I2D_REQUIRE(!I2D_IS_NULL(extra));
    i2d_filter filter = i2d_default_filter();
    filter.category_bits = 2;
    I2D_CHECK(i2d_shape_set_filter(extra, filter) == I2D_OK);
    i2d_circle circle;
    circle.center = v2(0.0f, 0.0f);
    circle.radius = 0.4f;
    I2D_CHECK(i2d_shape_set_circle(first_shape(frame), &circle) == I2D_OK);
    for (int k = 0; k < 20; ++k) {
        I2D_REQUIRE(step_ok(world));
    }
    I2D_CHECK(i2d_body_get_position(held).y < 9.5f); /* the hinge to the frame holds nothing */
    I2D_CHECK(shapes_at(world, v2(0.0f, 12.0f)) == 0);

    /* Enabled, the frame pulls the box back up and its shapes are found. */
    I2D_REQUIRE(i2d_body_enable(frame) == I2D_OK);
    I2D_CHECK(shapes_at(world, v2(0.0f, 12.0f)) == 2);
    for (int k = 0; k < 180; ++k) {
        I2D_REQUIRE(step_ok(world));
    }
    I2D_CHECK_NEAR(i2d_body_get_position(held).y, 10.0f, 0.02f);

    /* A disabled body is destroyed with its joints and shapes. */
    I2D_REQUIRE(i2d_body_disable(held) == I2D_OK);
    I2D_REQUIRE(i2d_body_destroy(held) == I2D_OK);
    I2D_CHECK(!i2d_joint_is_valid(joint));
    I2D_REQUIRE(i2d_body_disable(frame) == I2D_OK);
    I2D_REQUIRE(i2d_body_destroy(frame) == I2D_OK);
    I2D_CHECK(i2d_world_get_counters(world).body_count == 1);
    I2D_CHECK(step_ok(world));
}

I2D_TEST(api_body_enable_changes_made_while_disabled_wait_for_it) { run_in_world(-10.0f, changes_while_disabled); }

/* ---- Refusals and no-ops --------------------------------------------------------------- */

typedef struct locked_probe {
    i2d_body_id enabled_body, disabled_body;
    i2d_status disable, enable;
    bool called;
} locked_probe;

static bool call_from_inside(i2d_shape_id shape, void* context) {
    (void)shape;
    locked_probe* probe = (locked_probe*)context;
    probe->disable = i2d_body_disable(probe->enabled_body);
    probe->enable = i2d_body_enable(probe->disabled_body);
    probe->called = true;
    return false;
}

/* A box resting on the ground (its contact in the state hash): a bad id of every sort and
 * a call from inside a query callback are refused, and the hash, the counters and the
 * flags are as they were. */
static void refusals_leave_the_world_untouched(i2d_world_id world) {
    const i2d_body_id ground = add_box(world, I2D_BODY_STATIC, 0.0f, -0.5f, 0.5f);
    const i2d_body_id crate = add_box(world, I2D_BODY_DYNAMIC, 0.0f, 0.5f, 0.5f);
    const i2d_body_id parked = add_box(world, I2D_BODY_DYNAMIC, 5.0f, 5.0f, 0.5f);
    const i2d_body_id gone = make_body(world, I2D_BODY_DYNAMIC, 0.0f, 0.0f);
    const i2d_world_id other = make_world(0.0f);
    const i2d_body_id of_gone_world = make_body(other, I2D_BODY_DYNAMIC, 0.0f, 0.0f);
    I2D_REQUIRE(!I2D_IS_NULL(ground) && !I2D_IS_NULL(crate) && !I2D_IS_NULL(parked) && !I2D_IS_NULL(gone));
    I2D_REQUIRE(!I2D_IS_NULL(of_gone_world));
    I2D_REQUIRE(i2d_body_destroy(gone) == I2D_OK);
    I2D_REQUIRE(i2d_world_destroy(other) == I2D_OK);
    I2D_REQUIRE(i2d_body_disable(parked) == I2D_OK);
    for (int k = 0; k < 10; ++k) {
        I2D_REQUIRE(step_ok(world));
    }
    const uint64_t hash = i2d_world_get_state_hash(world);
    const i2d_world_counters counters = i2d_world_get_counters(world);
    I2D_REQUIRE(counters.contact_count == 1);

    i2d_body_id shape_as_body;
    shape_as_body.bits = first_shape(crate).bits;
    const i2d_body_id bad[4] = {I2D_NULL_BODY_ID, gone, shape_as_body, of_gone_world};
    for (int k = 0; k < 4; ++k) {
        check_refused_at(__FILE__, __LINE__, "i2d_body_disable(bad id)", i2d_body_disable(bad[k]),
                         I2D_ERR_INVALID_HANDLE);
        check_refused_at(__FILE__, __LINE__, "i2d_body_enable(bad id)", i2d_body_enable(bad[k]),
                         I2D_ERR_INVALID_HANDLE);
        I2D_CHECK(!i2d_body_is_enabled(bad[k]));
    }

    locked_probe probe;
    memset(&probe, 0, sizeof probe);
    probe.enabled_body = crate;
    probe.disabled_body = parked;
    I2D_REQUIRE(i2d_world_overlap_aabb(world, box(-10.0f, -10.0f, 10.0f, 10.0f), i2d_default_query_filter(),
                                       call_from_inside, &probe) == I2D_OK);
    I2D_CHECK(probe.called && probe.disable == I2D_ERR_WORLD_LOCKED && probe.enable == I2D_ERR_WORLD_LOCKED);

    I2D_CHECK(i2d_world_get_state_hash(world) == hash);
    const i2d_world_counters after = i2d_world_get_counters(world);
    I2D_CHECK(after.pair_count == counters.pair_count && after.contact_count == counters.contact_count);
    I2D_CHECK(after.awake_body_count == counters.awake_body_count);
    I2D_CHECK(i2d_body_is_enabled(crate) && !i2d_body_is_enabled(parked));
}

I2D_TEST(api_body_enable_refuses_bad_ids_and_a_locked_world_untouched) {
    run_in_world(-10.0f, refusals_leave_the_world_untouched);
}

/* Enabling an enabled body and disabling a disabled one change nothing: not the hash, not
 * the counters, and a rollback state saved before still restores (nor do waking and
 * sleeping a disabled body). A real change is a structural one: a state saved before it
 * is refused. */
static void no_ops_when_already_so(i2d_world_id world) {
    const i2d_body_id ground = add_box(world, I2D_BODY_STATIC, 0.0f, -0.5f, 0.5f);
    const i2d_body_id crate = add_box(world, I2D_BODY_DYNAMIC, 0.0f, 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(ground) && !I2D_IS_NULL(crate));
    for (int k = 0; k < 10; ++k) {
        I2D_REQUIRE(step_ok(world));
    }
    const size_t size = i2d_world_get_state_size(world);
    unsigned char* state = (unsigned char*)malloc(size + 256);
    I2D_REQUIRE(state != NULL);
    size_t written = 0;

    I2D_REQUIRE(i2d_world_save_state(world, state, size + 256, &written) == I2D_OK);
    uint64_t hash = i2d_world_get_state_hash(world);
    i2d_world_counters counters = i2d_world_get_counters(world);
    I2D_CHECK(i2d_body_enable(crate) == I2D_OK && i2d_body_enable(ground) == I2D_OK);
    I2D_CHECK(i2d_world_get_state_hash(world) == hash);
    I2D_CHECK(i2d_world_get_counters(world).pair_count == counters.pair_count);
    I2D_CHECK(i2d_world_get_counters(world).awake_body_count == counters.awake_body_count);
    I2D_CHECK(i2d_world_restore_state(world, state, written) == I2D_OK);

    I2D_REQUIRE(i2d_body_disable(crate) == I2D_OK);
    check_refused_at(__FILE__, __LINE__, "a state saved before the disable", i2d_world_restore_state(world, state, written),
                     I2D_ERR_INVALID_SNAPSHOT);
    I2D_CHECK(!i2d_body_is_enabled(crate));
    I2D_REQUIRE(i2d_world_save_state(world, state, size + 256, &written) == I2D_OK);
    hash = i2d_world_get_state_hash(world);
    counters = i2d_world_get_counters(world);
    I2D_CHECK(i2d_body_disable(crate) == I2D_OK);
    I2D_CHECK(!i2d_body_is_enabled(crate));
    /* Waking or putting to sleep a disabled body does nothing to it either. */
    I2D_CHECK(i2d_body_set_awake(crate, true) == I2D_OK && !i2d_body_is_awake(crate));
    I2D_CHECK(i2d_body_set_awake(crate, false) == I2D_OK && !i2d_body_is_awake(crate));
    I2D_CHECK(i2d_world_get_state_hash(world) == hash);
    I2D_CHECK(i2d_world_get_counters(world).pair_count == counters.pair_count);
    I2D_CHECK(i2d_world_restore_state(world, state, written) == I2D_OK);
    free(state);
}

I2D_TEST(api_body_enable_no_ops_when_already_so) { run_in_world(-10.0f, no_ops_when_already_so); }

/* ---- Snapshots and replays ------------------------------------------------------------- */

/* A scene with a body of every sort to disable: a shelf (static) with a crate on it, a
 * pile of three boxes, a bob hanging from a pivot, a box sliding across the ground. */
enum { SHELF, CRATE, PILE_LOW, PILE_MID, PILE_TOP, PIVOT, BOB, SLIDER, SCENE_BODIES };

typedef struct enable_scene {
    i2d_body_id bodies[SCENE_BODIES];
} enable_scene;

static bool build_scene(i2d_world_id world, enable_scene* s) {
    if (I2D_IS_NULL(add_box(world, I2D_BODY_STATIC, 0.0f, -10.0f, 10.0f))) {
        return false;
    }
    s->bodies[SHELF] = add_box(world, I2D_BODY_STATIC, 6.0f, 2.0f, 1.0f);
    s->bodies[CRATE] = add_box(world, I2D_BODY_DYNAMIC, 6.0f, 3.5f, 0.5f);
    s->bodies[PILE_LOW] = add_box(world, I2D_BODY_DYNAMIC, -4.0f, 0.5f, 0.5f);
    s->bodies[PILE_MID] = add_box(world, I2D_BODY_DYNAMIC, -4.0f, 1.5f, 0.5f);
    s->bodies[PILE_TOP] = add_box(world, I2D_BODY_DYNAMIC, -4.0f, 2.5f, 0.5f);
    s->bodies[PIVOT] = make_body(world, I2D_BODY_STATIC, 0.0f, 8.0f);
    s->bodies[BOB] = add_box(world, I2D_BODY_DYNAMIC, 1.0f, 7.0f, 0.25f);
    s->bodies[SLIDER] = add_box(world, I2D_BODY_DYNAMIC, -8.0f, 0.5f, 0.5f);
    for (int k = 0; k < SCENE_BODIES; ++k) {
        if (I2D_IS_NULL(s->bodies[k])) {
            return false;
        }
    }
    i2d_revolute_joint_def hinge = i2d_default_revolute_joint_def();
    hinge.base.body_a = s->bodies[PIVOT];
    hinge.base.body_b = s->bodies[BOB];
    hinge.base.local_anchor_b = v2(-1.0f, 1.0f);
    return !I2D_IS_NULL(i2d_joint_create_revolute(world, &hinge)) &&
           i2d_body_set_linear_velocity(s->bodies[SLIDER], v2(3.0f, 0.0f)) == I2D_OK;
}

/* The calls made at step k of a run, on bodies found by index in whichever world runs. */
static void script(i2d_world_id world, const enable_scene* s, int k) {
    i2d_body_id b[SCENE_BODIES];
    for (int i = 0; i < SCENE_BODIES; ++i) {
        b[i] = i2d_body_in_world(s->bodies[i], world);
    }
    switch (k) {
        case 5:
            i2d_body_disable(b[SHELF]);
            i2d_body_disable(b[PILE_MID]);
            i2d_body_disable(b[PIVOT]);
            i2d_body_disable(b[SLIDER]);
            break;
        case 12: {
            i2d_shape_def def = i2d_default_shape_def();
            i2d_shape_create_box(b[SLIDER], &def, 0.2f, 0.8f);
            i2d_body_apply_linear_impulse(b[SLIDER], v2(0.0f, 2.0f), i2d_body_get_world_center_of_mass(b[SLIDER]),
                                          true);
            i2d_body_set_transform(b[SLIDER], v2(-8.0f, 3.0f), identity_rot());
            break;
        }
        case 30:
            i2d_body_enable(b[PIVOT]);
            i2d_body_enable(b[SLIDER]);
            i2d_body_disable(b[BOB]);
            break;
        case 45:
            i2d_body_enable(b[BOB]);
            i2d_body_enable(b[SHELF]);
            break;
        case 60:
            i2d_body_enable(b[PILE_MID]); /* inside the fallen top box: pushed apart */
            break;
        default: break;
    }
}

enum { BEFORE_SAVE = 20, AFTER_SAVE = 100 };

/* A world saved with disabled bodies in it (some with shapes made while away, one with a
 * velocity), then restored in place and made anew from the snapshot: both step through
 * the same calls to the same hashes as the world that was never saved. */
I2D_TEST(api_body_enable_snapshot_with_disabled_bodies_steps_as_never_saved) {
    const i2d_world_def def = i2d_default_world_def();
    const i2d_world_id world = i2d_world_create(&def);
    enable_scene s;
    I2D_REQUIRE(!I2D_IS_NULL(world));
    if (!build_scene(world, &s)) {
        i2d_world_destroy(world);
        I2D_REQUIRE(false);
    }
    for (int k = 0; k < BEFORE_SAVE; ++k) {
        script(world, &s, k);
        I2D_REQUIRE(step_ok(world));
    }
    /* Saved away, with the velocity it slid at and the impulse it was given since. */
    const i2d_vec2 kept = i2d_body_get_linear_velocity(s.bodies[SLIDER]);
    I2D_CHECK(!i2d_body_is_enabled(s.bodies[SLIDER]) && kept.x > 2.0f && kept.y > 0.0f);
    const size_t size = i2d_world_get_snapshot_size(world);
    unsigned char* snapshot = (unsigned char*)malloc(size);
    I2D_REQUIRE(snapshot != NULL);
    I2D_REQUIRE(i2d_world_save_snapshot(world, snapshot, size, NULL) == I2D_OK);

    uint64_t hashes[AFTER_SAVE];
    for (int k = 0; k < AFTER_SAVE; ++k) {
        script(world, &s, BEFORE_SAVE + k);
        I2D_REQUIRE(step_ok(world));
        hashes[k] = i2d_world_get_state_hash(world);
    }
    const i2d_world_id copy = i2d_world_create_from_snapshot(snapshot, size, NULL);
    I2D_CHECK(!I2D_IS_NULL(copy));
    I2D_CHECK(i2d_world_restore_snapshot(world, snapshot, size) == I2D_OK);
    int first_mismatch[2] = {-1, -1};
    const i2d_world_id runs[2] = {world, copy};
    for (int r = 0; r < 2; ++r) {
        if (I2D_IS_NULL(runs[r])) {
            continue;
        }
        I2D_CHECK(!i2d_body_is_enabled(i2d_body_in_world(s.bodies[PIVOT], runs[r])));
        for (int k = 0; k < AFTER_SAVE; ++k) {
            script(runs[r], &s, BEFORE_SAVE + k);
            I2D_REQUIRE(step_ok(runs[r]));
            if (i2d_world_get_state_hash(runs[r]) != hashes[k] && first_mismatch[r] < 0) {
                first_mismatch[r] = k;
            }
        }
    }
    if (first_mismatch[0] >= 0 || first_mismatch[1] >= 0) {
        fprintf(stderr, "    first mismatch after the save: restored %d, made anew %d\n", first_mismatch[0],
                first_mismatch[1]);
    }
    I2D_CHECK(first_mismatch[0] < 0 && first_mismatch[1] < 0);
    I2D_CHECK(i2d_body_is_enabled(s.bodies[PILE_MID]));
    free(snapshot);
    if (!I2D_IS_NULL(copy)) {
        i2d_world_destroy(copy);
    }
    i2d_world_destroy(world);
}

/* A recording of the same run replays with every step's hash as recorded. */
I2D_TEST(api_body_enable_replay_of_disables_and_enables_never_diverges) {
    const i2d_world_def def = i2d_default_world_def();
    const i2d_world_id world = i2d_world_create(&def);
    enable_scene s;
    bytes recording;
    memset(&recording, 0, sizeof recording);
    I2D_REQUIRE(!I2D_IS_NULL(world));
    if (!build_scene(world, &s) || i2d_world_start_recording(world, append_bytes, &recording) != I2D_OK) {
        i2d_world_destroy(world);
        I2D_REQUIRE(false);
    }
    const int steps = BEFORE_SAVE + AFTER_SAVE;
    for (int k = 0; k < steps; ++k) {
        script(world, &s, k);
        I2D_REQUIRE(step_ok(world));
    }
    I2D_CHECK(i2d_world_stop_recording(world) == I2D_OK);
    const uint64_t hash = i2d_world_get_state_hash(world);
    i2d_world_destroy(world);

    const i2d_replay_id replay = i2d_replay_open(recording.data, recording.size, NULL);
    I2D_CHECK(replay.bits != 0);
    if (replay.bits != 0) {
        I2D_CHECK(i2d_replay_get_step_count(replay) == steps);
        I2D_CHECK(i2d_replay_step(replay, steps) == steps);
        I2D_CHECK(i2d_replay_get_divergent_step(replay) == -1);
        I2D_CHECK(i2d_world_get_state_hash(i2d_replay_get_world(replay)) == hash);
        I2D_CHECK(i2d_replay_close(replay) == I2D_OK);
    }
    free(recording.data);
}
