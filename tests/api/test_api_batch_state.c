/* SPDX-License-Identifier: MIT */
/* i2d_worlds_get_body_states, i2d_worlds_set_body_velocities and
 * i2d_worlds_get_contact_event_counts: bodies and events of several worlds per call give
 * and take what the one-world calls do, and bad input (a null, stale or wrong-kind id, a
 * non-finite velocity, NULL or negative counts, a locked world) is refused whole: a
 * message naming the element, the output arrays and every world unchanged. */
#include <string.h>

#include "test_api_errors.h"

enum { SETTLE_STEPS = 10 };

/* A byte the calls never write, to see that a refused call wrote nothing. */
#define UNTOUCHED 0x5a

static bool all_bytes(const void* p, size_t size, unsigned char value) {
    const unsigned char* bytes = (const unsigned char*)p;
    for (size_t i = 0; i < size; ++i) {
        if (bytes[i] != value) {
            return false;
        }
    }
    return true;
}

static void check_message_has_at(int line, const char* what, const char* needle) {
    const char* message = i2d_last_error_message();
    if (message == NULL || strstr(message, needle) == NULL) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: message \"%s\" lacks \"%s\"\n", __FILE__, line, what,
                message != NULL ? message : "(null)", needle);
    }
}
#define CHECK_MESSAGE_HAS(what, needle) check_message_has_at(__LINE__, (what), (needle))

/* a stepped, b not: the two balls differ, and each read matches the one-body getters. */
static void run_states_across_worlds(const fixture* a, const fixture* b) {
    for (int s = 0; s < SETTLE_STEPS; ++s) {
        I2D_REQUIRE(step_ok(a->world));
    }
    const i2d_body_id bodies[4] = {a->body[FIX_BALL], b->body[FIX_BALL], a->body[FIX_GROUND], b->body[FIX_MOVER]};
    i2d_transform transforms[4];
    i2d_vec2 linear[4];
    float angular[4];
    bool awake[4];
    I2D_CHECK_STATUS(i2d_worlds_get_body_states(bodies, 4, transforms, linear, angular, awake), I2D_OK);
    for (int i = 0; i < 4; ++i) {
        const i2d_transform t = i2d_body_get_transform(bodies[i]);
        const i2d_vec2 v = i2d_body_get_linear_velocity(bodies[i]);
        I2D_CHECK(memcmp(&t, &transforms[i], sizeof t) == 0);
        I2D_CHECK(v.x == linear[i].x && v.y == linear[i].y);
        I2D_CHECK(i2d_body_get_angular_velocity(bodies[i]) == angular[i]);
        I2D_CHECK(i2d_body_is_awake(bodies[i]) == awake[i]);
    }
    I2D_CHECK(transforms[0].p.x != transforms[1].p.x || transforms[0].p.y != transforms[1].p.y);
    I2D_CHECK(awake[3]); /* a spinning kinematic body */
    /* Any array may be skipped; count 0 needs no arrays. */
    float angular_only[4];
    I2D_CHECK_STATUS(i2d_worlds_get_body_states(bodies, 4, NULL, NULL, angular_only, NULL), I2D_OK);
    I2D_CHECK(memcmp(angular_only, angular, sizeof angular) == 0);
    I2D_CHECK_STATUS(i2d_worlds_get_body_states(NULL, 0, NULL, NULL, NULL, NULL), I2D_OK);
}

I2D_TEST(api_worlds_get_body_states_reads_each_world_as_its_getters) { run_on_twins(run_states_across_worlds); }

static void run_bad_state_reads(const fixture* a, const fixture* b) {
    i2d_world_id gone = make_world(-10.0f);
    i2d_body_def def = i2d_default_body_def();
    def.type = I2D_BODY_DYNAMIC;
    const i2d_body_id of_gone_world = i2d_body_create(gone, &def);
    i2d_world_destroy(gone);
    i2d_body_id destroyed = i2d_body_create(a->world, &def);
    i2d_body_destroy(destroyed);
    const struct {
        const char* what;
        i2d_body_id bad;
        const char* needle;
    } cases[] = {
        {"null id", {0}, "bodies[1]: body id is null"},
        {"destroyed body", destroyed, "bodies[1]: body id is stale"},
        {"destroyed world", of_gone_world, "bodies[1]"},
        {"shape id as a body", {a->shape[FIX_BALL_CIRCLE].bits}, "bodies[1]"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        const i2d_body_id bodies[2] = {b->body[FIX_BALL], cases[k].bad};
        i2d_transform transforms[2];
        float angular[2];
        memset(transforms, UNTOUCHED, sizeof transforms);
        memset(angular, UNTOUCHED, sizeof angular);
        I2D_CHECK_STATUS(i2d_worlds_get_body_states(bodies, 2, transforms, NULL, angular, NULL),
                         I2D_ERR_INVALID_HANDLE);
        CHECK_MESSAGE_HAS(cases[k].what, cases[k].needle);
        I2D_CHECK(all_bytes(transforms, sizeof transforms, UNTOUCHED) && all_bytes(angular, sizeof angular, UNTOUCHED));
    }
    i2d_transform one;
    I2D_CHECK_STATUS(i2d_worlds_get_body_states(NULL, 1, &one, NULL, NULL, NULL), I2D_ERR_INVALID_ARGUMENT);
    CHECK_MESSAGE_HAS("NULL bodies", "bodies is NULL");
    I2D_CHECK_STATUS(i2d_worlds_get_body_states(a->body, -1, &one, NULL, NULL, NULL), I2D_ERR_INVALID_ARGUMENT);
    CHECK_MESSAGE_HAS("negative count", "count is -1");
}

I2D_TEST(api_worlds_get_body_states_bad_input_refused_nothing_written) { run_on_twins(run_bad_state_reads); }

/* The velocities land in each body's own world, as the one-world call sets them. */
static void run_velocities_across_worlds(const fixture* a, const fixture* b) {
    const i2d_body_id bodies[3] = {a->body[FIX_BALL], b->body[FIX_BALL], a->body[FIX_GROUND]};
    const i2d_vec2 linear[3] = {{1.5f, 2.0f}, {-3.0f, 0.25f}, {9.0f, 9.0f}};
    const float angular[3] = {0.5f, -1.0f, 7.0f};
    I2D_CHECK_STATUS(i2d_worlds_set_body_velocities(bodies, 3, linear, angular), I2D_OK);
    for (int i = 0; i < 2; ++i) {
        const i2d_vec2 v = i2d_body_get_linear_velocity(bodies[i]);
        I2D_CHECK(v.x == linear[i].x && v.y == linear[i].y);
        I2D_CHECK(i2d_body_get_angular_velocity(bodies[i]) == angular[i]);
    }
    const i2d_vec2 ground = i2d_body_get_linear_velocity(a->body[FIX_GROUND]);
    I2D_CHECK(ground.x == 0.0f && ground.y == 0.0f && i2d_body_get_angular_velocity(a->body[FIX_GROUND]) == 0.0f);
    /* Angular only: the linear velocities stay. */
    const float spin[2] = {2.0f, 3.0f};
    I2D_CHECK_STATUS(i2d_worlds_set_body_velocities(bodies, 2, NULL, spin), I2D_OK);
    I2D_CHECK(i2d_body_get_angular_velocity(bodies[1]) == 3.0f && i2d_body_get_linear_velocity(bodies[1]).x == -3.0f);
    /* The same as the one-world call: a twin set through it steps to the same bits. */
    const i2d_vec2 b_linear = {1.5f, 2.0f};
    const float b_angular = 2.0f;
    I2D_CHECK_STATUS(i2d_world_set_body_velocities(b->world, &b->body[FIX_BALL], 1, &b_linear, &b_angular), I2D_OK);
    check_twins_agree_after_steps(a, b);
}

I2D_TEST(api_worlds_set_body_velocities_sets_each_world_as_its_own_call) {
    run_on_twins(run_velocities_across_worlds);
}

static void run_bad_velocity_writes(const fixture* a, const fixture* b) {
    static snapshot before_a, before_b;
    snapshot_take(a, &before_a);
    snapshot_take(b, &before_b);
    const i2d_body_id bodies[2] = {a->body[FIX_BALL], b->body[FIX_BALL]};
    for (int k = 0; k < NON_FINITE_COUNT; ++k) {
        const i2d_vec2 linear[2] = {{1.0f, 1.0f}, {k_non_finite[k], 0.0f}};
        const float angular[2] = {1.0f, k_non_finite[k]};
        I2D_CHECK_STATUS(i2d_worlds_set_body_velocities(bodies, 2, linear, NULL), I2D_ERR_INVALID_ARGUMENT);
        CHECK_MESSAGE_HAS("non-finite linear velocity", "linear[1]");
        I2D_CHECK_STATUS(i2d_worlds_set_body_velocities(bodies, 2, NULL, angular), I2D_ERR_INVALID_ARGUMENT);
        CHECK_MESSAGE_HAS("non-finite angular velocity", "angular[1]");
    }
    const i2d_body_id with_null[2] = {a->body[FIX_BALL], {0}};
    const float angular[2] = {1.0f, 1.0f};
    I2D_CHECK_STATUS(i2d_worlds_set_body_velocities(with_null, 2, NULL, angular), I2D_ERR_INVALID_HANDLE);
    CHECK_MESSAGE_HAS("null id", "bodies[1]: body id is null");
    I2D_CHECK_STATUS(i2d_worlds_set_body_velocities(NULL, 2, NULL, angular), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK_STATUS(i2d_worlds_set_body_velocities(bodies, -2, NULL, angular), I2D_ERR_INVALID_ARGUMENT);
    CHECK_UNCHANGED("refused velocity writes, world a", a, &before_a);
    CHECK_UNCHANGED("refused velocity writes, world b", b, &before_b);
    check_twins_agree_after_steps(a, b);
}

I2D_TEST(api_worlds_set_body_velocities_bad_input_refused_no_world_changed) { run_on_twins(run_bad_velocity_writes); }

/* From inside a query callback on world b, a write naming bodies of a and b is refused. */
typedef struct write_in_query {
    i2d_body_id bodies[2];
    i2d_status status;
} write_in_query;

static bool write_from_query(i2d_shape_id shape, void* context) {
    (void)shape;
    write_in_query* q = (write_in_query*)context;
    const float angular[2] = {4.0f, 4.0f};
    q->status = i2d_worlds_set_body_velocities(q->bodies, 2, NULL, angular);
    return false;
}

static void run_write_locked_in_query(const fixture* a, const fixture* b) {
    static snapshot before_a;
    snapshot_take(a, &before_a);
    write_in_query q = {{a->body[FIX_BALL], b->body[FIX_BALL]}, I2D_OK};
    i2d_world_overlap_aabb(b->world, box(-100, -100, 100, 100), i2d_default_query_filter(), write_from_query, &q);
    I2D_CHECK_STATUS(q.status, I2D_ERR_WORLD_LOCKED);
    CHECK_UNCHANGED("write from a query callback", a, &before_a);
}

I2D_TEST(api_worlds_set_body_velocities_refused_when_a_world_is_locked) { run_on_twins(run_write_locked_in_query); }

/* A ball dropped onto the ground in one world gives begin events; the counts are the
 * ones i2d_world_get_contact_events reports for each world. */
static void run_event_counts(const fixture* a, const fixture* b) {
    i2d_world_id drop = make_world(-10.0f);
    I2D_REQUIRE(!I2D_IS_NULL(drop));
    i2d_body_def ground_def = i2d_default_body_def();
    i2d_body_id ground = i2d_body_create(drop, &ground_def);
    i2d_shape_def shape = i2d_default_shape_def();
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_segment(ground, &shape, (i2d_vec2){-5, 0}, (i2d_vec2){5, 0})));
    i2d_body_def ball_def = i2d_default_body_def();
    ball_def.type = I2D_BODY_DYNAMIC;
    ball_def.position = (i2d_vec2){0.0f, 0.6f};
    const i2d_circle circle = {{0.0f, 0.0f}, 0.5f};
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_circle(i2d_body_create(drop, &ball_def), &shape, &circle)));
    const i2d_world_id worlds[3] = {a->world, drop, b->world};
    int32_t begins[3], ends[3];
    int32_t total_begins = 0;
    for (int s = 0; s < 30; ++s) {
        I2D_REQUIRE(step_ok(drop) && step_ok(a->world));
        I2D_CHECK_STATUS(i2d_worlds_get_contact_event_counts(worlds, 3, begins, ends), I2D_OK);
        for (int i = 0; i < 3; ++i) {
            const i2d_contact_events e = i2d_world_get_contact_events(worlds[i]);
            I2D_CHECK(begins[i] == e.begin_count && ends[i] == e.end_count);
        }
        total_begins += begins[1];
    }
    I2D_CHECK(total_begins >= 1);
    I2D_CHECK_STATUS(i2d_worlds_get_contact_event_counts(worlds, 3, NULL, ends), I2D_OK);
    /* Refused whole: a destroyed world among good ones, NULL worlds, a negative count. */
    i2d_world_destroy(drop);
    memset(begins, UNTOUCHED, sizeof begins);
    I2D_CHECK_STATUS(i2d_worlds_get_contact_event_counts(worlds, 3, begins, NULL), I2D_ERR_INVALID_HANDLE);
    CHECK_MESSAGE_HAS("destroyed world", "worlds[1]: world id is stale");
    I2D_CHECK(all_bytes(begins, sizeof begins, UNTOUCHED));
    I2D_CHECK_STATUS(i2d_worlds_get_contact_event_counts(NULL, 1, begins, NULL), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK_STATUS(i2d_worlds_get_contact_event_counts(worlds, -1, begins, NULL), I2D_ERR_INVALID_ARGUMENT);
}

I2D_TEST(api_worlds_get_contact_event_counts_match_each_worlds_events) { run_on_twins(run_event_counts); }
