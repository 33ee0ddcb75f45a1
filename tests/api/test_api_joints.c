/* SPDX-License-Identifier: MIT */
/* Joints through the C API: defaults, creation of every kind, every refusal (status, a
 * message naming the field, and the world untouched: state hash, joint count and the
 * bodies' sleep unchanged), stale ids, getters on the wrong kind, the round trip of every
 * setting, measures, and the joint events of a breakable joint. */
#include <impulse2d/impulse2d.h>

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "any_joint_def.h"
#include "api_test_support.h"
#include "check.h"

/* ---- Fixture ---------------------------------------------------------------------- */

static const char* const k_kind_names[JOINT_KIND_COUNT] = {"distance",  "filter",   "motor", "mouse",
                                                           "prismatic", "revolute", "weld",  "wheel"};

/* Mismatch reports per test (api_test_support.h): a broken rule shows without a flood. */
static const int k_report_budget = 20;

/* Distinct user data, so that a value read back is known to be the one given. */
static int k_marker;

/* Fixed-step settings of the one test that steps. */
static const float k_time_step = 1.0f / 60.0f;
static const int k_substeps = 4;

typedef struct fixture {
    i2d_world_id world, other_world;
    i2d_body_id ground;      /* static, with a box so that queries find something */
    i2d_body_id a, b;        /* dynamic boxes, apart */
    i2d_body_id kinematic;
    i2d_body_id second_static;
    i2d_body_id foreign;     /* dynamic, of other_world */
} fixture;

/* A body with a 1 m box, so that it has mass and queries find it. */
static i2d_body_id make_box_body(i2d_world_id world, i2d_body_type type, float x, float y) {
    i2d_body_id body = make_body(world, type, x, y);
    i2d_shape_def shape = i2d_default_shape_def();
    i2d_shape_create_box(body, &shape, 0.5f, 0.5f);
    return body;
}

static fixture make_fixture(void) {
    fixture f;
    i2d_world_def def = i2d_default_world_def();
    f.world = i2d_world_create(&def);
    f.other_world = i2d_world_create(&def);
    f.ground = make_box_body(f.world, I2D_BODY_STATIC, 0.0f, -1.0f);
    f.a = make_box_body(f.world, I2D_BODY_DYNAMIC, 0.0f, 4.0f);
    f.b = make_box_body(f.world, I2D_BODY_DYNAMIC, 3.0f, 4.0f);
    f.kinematic = make_box_body(f.world, I2D_BODY_KINEMATIC, -3.0f, 4.0f);
    f.second_static = make_box_body(f.world, I2D_BODY_STATIC, 10.0f, -1.0f);
    f.foreign = make_box_body(f.other_world, I2D_BODY_DYNAMIC, 0.0f, 4.0f);
    return f;
}

static void free_fixture(fixture* f) {
    i2d_world_destroy(f->world);
    i2d_world_destroy(f->other_world);
}

static i2d_joint_id create_default(const fixture* f, i2d_joint_type kind) {
    any_def d = default_def(kind, f->a, f->b);
    return create_any(f->world, kind, &d);
}

/* A joint of every kind between a and b, with the defaults; joints[k] is of kind k. */
static void create_one_of_each_kind(const fixture* f, i2d_joint_id joints[JOINT_KIND_COUNT]) {
    for (int k = 0; k < JOINT_KIND_COUNT; ++k) {
        joints[k] = create_default(f, (i2d_joint_type)k);
    }
}

/* ---- Refusal checks ------------------------------------------------------------------- */

/* What a refused call must leave as it was. The two dynamic bodies are put to sleep first,
 * so that a refused call that woke them (as every accepted change does) shows. */
typedef struct snapshot {
    uint64_t hash;
    int32_t joints;
    bool awake_a, awake_b;
} snapshot;

static snapshot take_snapshot(const fixture* f) {
    snapshot s;
    s.hash = i2d_world_get_state_hash(f->world);
    s.joints = i2d_world_get_joint_count(f->world);
    s.awake_a = i2d_body_is_awake(f->a);
    s.awake_b = i2d_body_is_awake(f->b);
    return s;
}

static snapshot settle(const fixture* f) {
    i2d_body_set_awake(f->a, false);
    i2d_body_set_awake(f->b, false);
    return take_snapshot(f);
}

/* Reads the status and message before any other call, then the world. */
static void check_refusal_at(int line, const fixture* f, const snapshot* before, const char* call,
                             i2d_status returned, i2d_status expected, const char* field) {
    const i2d_status last = i2d_last_status();
    char message[512];
    snprintf(message, sizeof message, "%s", i2d_last_error_message() ? i2d_last_error_message() : "");
    if (returned != expected || last != expected) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s returned %s (last %s), expected %s; message \"%s\"\n", __FILE__, line, call,
                i2d_status_string(returned), i2d_status_string(last), i2d_status_string(expected), message);
    }
    if (field != NULL && strstr(message, field) == NULL) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: message \"%s\" does not name %s\n", __FILE__, line, call, message, field);
    }
    const snapshot after = take_snapshot(f);
    if (after.hash != before->hash || after.joints != before->joints || after.awake_a != before->awake_a ||
        after.awake_b != before->awake_b) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s changed the world (joints %d -> %d, awake %d%d -> %d%d)\n", __FILE__, line, call,
                before->joints, after.joints, before->awake_a, before->awake_b, after.awake_a, after.awake_b);
    }
}

/* A call returning a status, refused with `expected` and a message naming `field`. */
#define CHECK_REFUSED(f, expected, field, call)                                                   \
    do {                                                                                          \
        const snapshot before_ = settle(f);                                                       \
        const i2d_status returned_ = (call);                                                      \
        check_refusal_at(__LINE__, (f), &before_, #call, returned_, (expected), (field));         \
    } while (0)

/* A create, refused: a null id, then as above. */
#define CHECK_CREATE_REFUSED(f, expected, field, call)                                            \
    do {                                                                                          \
        const snapshot before_ = settle(f);                                                       \
        const i2d_joint_id id_ = (call);                                                          \
        check_refusal_at(__LINE__, (f), &before_, #call,                                          \
                         id_.bits == 0 ? i2d_last_status() : I2D_OK, (expected), (field));        \
    } while (0)

/* ---- Defaults ------------------------------------------------------------------------- */

static bool default_base_ok(const i2d_joint_base* base) {
    return base->body_a.bits == 0 && base->body_b.bits == 0 && base->local_anchor_a.x == 0.0f &&
           base->local_anchor_a.y == 0.0f && base->local_anchor_b.x == 0.0f && base->local_anchor_b.y == 0.0f &&
           !base->collide_connected && base->force_threshold == FLT_MAX && base->torque_threshold == FLT_MAX &&
           base->user_data == NULL;
}

I2D_TEST(api_joint_defaults) {
    g_reports_left = k_report_budget;
    const i2d_world_def world = i2d_default_world_def();
    I2D_CHECK(world.joint_hertz == 60.0f && world.joint_damping_ratio == 2.0f);

    const i2d_revolute_joint_def r = i2d_default_revolute_joint_def();
    I2D_CHECK(default_base_ok(&r.base) && r.internal_cookie != 0);
    I2D_CHECK(r.reference_angle == 0.0f && !r.enable_limit && r.lower_angle == 0.0f && r.upper_angle == 0.0f);
    I2D_CHECK(!r.enable_motor && r.motor_speed == 0.0f && r.max_motor_torque == 0.0f && !r.enable_spring);
    I2D_CHECK(r.hertz == 0.0f && r.damping_ratio == 0.0f && r.target_angle == 0.0f);

    const i2d_prismatic_joint_def p = i2d_default_prismatic_joint_def();
    I2D_CHECK(default_base_ok(&p.base) && p.internal_cookie != 0);
    I2D_CHECK(p.local_axis_a.x == 1.0f && p.local_axis_a.y == 0.0f && p.reference_angle == 0.0f);
    I2D_CHECK(!p.enable_limit && p.lower_translation == 0.0f && p.upper_translation == 0.0f && !p.enable_motor);
    I2D_CHECK(p.motor_speed == 0.0f && p.max_motor_force == 0.0f && !p.enable_spring && p.hertz == 0.0f);
    I2D_CHECK(p.damping_ratio == 0.0f && p.target_translation == 0.0f);

    const i2d_distance_joint_def d = i2d_default_distance_joint_def();
    I2D_CHECK(default_base_ok(&d.base) && d.internal_cookie != 0);
    I2D_CHECK(d.length == 1.0f && !d.enable_limit && d.min_length == 0.0f && d.max_length == 1e5f);
    I2D_CHECK(!d.enable_spring && d.hertz == 0.0f && d.damping_ratio == 0.0f && !d.enable_motor);
    I2D_CHECK(d.motor_speed == 0.0f && d.max_motor_force == 0.0f);

    const i2d_weld_joint_def w = i2d_default_weld_joint_def();
    I2D_CHECK(default_base_ok(&w.base) && w.internal_cookie != 0);
    I2D_CHECK(w.reference_angle == 0.0f && w.linear_hertz == 0.0f && w.angular_hertz == 0.0f);
    I2D_CHECK(w.linear_damping_ratio == 1.0f && w.angular_damping_ratio == 1.0f);

    const i2d_wheel_joint_def h = i2d_default_wheel_joint_def();
    I2D_CHECK(default_base_ok(&h.base) && h.internal_cookie != 0);
    I2D_CHECK(h.local_axis_a.x == 0.0f && h.local_axis_a.y == 1.0f && h.enable_spring);
    I2D_CHECK(h.hertz == 1.0f && fabsf(h.damping_ratio - 0.7f) == 0.0f && !h.enable_limit);
    I2D_CHECK(h.lower_translation == 0.0f && h.upper_translation == 0.0f && !h.enable_motor);
    I2D_CHECK(h.motor_speed == 0.0f && h.max_motor_torque == 0.0f);

    const i2d_motor_joint_def m = i2d_default_motor_joint_def();
    I2D_CHECK(default_base_ok(&m.base) && m.internal_cookie != 0);
    I2D_CHECK(m.linear_offset.x == 0.0f && m.linear_offset.y == 0.0f && m.angular_offset == 0.0f);
    I2D_CHECK(m.max_force == 1.0f && m.max_torque == 1.0f && m.correction_factor == 0.3f);

    const i2d_mouse_joint_def u = i2d_default_mouse_joint_def();
    I2D_CHECK(default_base_ok(&u.base) && u.internal_cookie != 0);
    I2D_CHECK(u.target.x == 0.0f && u.target.y == 0.0f && u.hertz == 4.0f && u.damping_ratio == 1.0f);
    I2D_CHECK(u.max_force == 1000.0f);

    const i2d_filter_joint_def fl = i2d_default_filter_joint_def();
    I2D_CHECK(default_base_ok(&fl.base) && fl.internal_cookie != 0);
    I2D_CHECK(i2d_last_status() == I2D_OK);
}

/* ---- Creation ------------------------------------------------------------------------- */

I2D_TEST(api_joint_create_every_kind) {
    g_reports_left = k_report_budget;
    fixture f = make_fixture();
    i2d_joint_id joints[JOINT_KIND_COUNT];
    for (int k = 0; k < JOINT_KIND_COUNT; ++k) {
        any_def d = default_def((i2d_joint_type)k, f.a, f.b);
        base_of(&d)->local_anchor_a = v2(0.25f, -0.5f);
        base_of(&d)->local_anchor_b = v2(-0.125f, 0.75f);
        base_of(&d)->user_data = &k_marker;
        joints[k] = create_any(f.world, (i2d_joint_type)k, &d);
        I2D_REQUIRE(joints[k].bits != 0);
        I2D_CHECK(i2d_last_status() == I2D_OK);
        I2D_CHECK(i2d_joint_is_valid(joints[k]));
        I2D_CHECK(i2d_joint_get_type(joints[k]) == (i2d_joint_type)k);
        I2D_CHECK(i2d_joint_get_world(joints[k]).bits == f.world.bits);
        I2D_CHECK(i2d_joint_get_body_a(joints[k]).bits == f.a.bits);
        I2D_CHECK(i2d_joint_get_body_b(joints[k]).bits == f.b.bits);
        I2D_CHECK(i2d_joint_get_local_anchor_a(joints[k]).x == 0.25f);
        I2D_CHECK(i2d_joint_get_local_anchor_b(joints[k]).y == 0.75f);
        I2D_CHECK(!i2d_joint_get_collide_connected(joints[k]));
        I2D_CHECK(i2d_joint_get_force_threshold(joints[k]) == FLT_MAX);
        I2D_CHECK(i2d_joint_get_user_data(joints[k]) == &k_marker);
        I2D_CHECK(i2d_joint_get_reaction_force(joints[k]).x == 0.0f);
        I2D_CHECK(i2d_joint_get_reaction_torque(joints[k]) == 0.0f);
        I2D_CHECK(i2d_world_get_joint_count(f.world) == k + 1);
    }
    /* Ids are distinct and of one world. */
    for (int k = 1; k < JOINT_KIND_COUNT; ++k) {
        I2D_CHECK(joints[k].bits != joints[k - 1].bits);
    }
    /* A joint to a static or kinematic body is fine when the other is dynamic. */
    any_def d = default_def(I2D_JOINT_REVOLUTE, f.ground, f.a);
    I2D_CHECK(create_any(f.world, I2D_JOINT_REVOLUTE, &d).bits != 0);
    d = default_def(I2D_JOINT_WELD, f.a, f.kinematic);
    I2D_CHECK(create_any(f.world, I2D_JOINT_WELD, &d).bits != 0);
    /* A mouse joint's body_a is any body. */
    d = default_def(I2D_JOINT_MOUSE, f.ground, f.b);
    I2D_CHECK(create_any(f.world, I2D_JOINT_MOUSE, &d).bits != 0);
    I2D_CHECK(i2d_world_get_joint_count(f.world) == JOINT_KIND_COUNT + 3);
    I2D_CHECK(i2d_world_get_joint_count(f.other_world) == 0);
    free_fixture(&f);
}

I2D_TEST(api_joint_create_wakes_bodies) {
    g_reports_left = k_report_budget;
    fixture f = make_fixture();
    settle(&f);
    I2D_REQUIRE(!i2d_body_is_awake(f.a) && !i2d_body_is_awake(f.b));
    i2d_joint_id j = create_default(&f, I2D_JOINT_DISTANCE);
    I2D_CHECK(i2d_body_is_awake(f.a) && i2d_body_is_awake(f.b));
    settle(&f);
    I2D_CHECK_STATUS(i2d_distance_joint_set_length(j, 2.0f), I2D_OK);
    I2D_CHECK(i2d_body_is_awake(f.a) && i2d_body_is_awake(f.b));
    settle(&f);
    I2D_CHECK_STATUS(i2d_joint_wake_bodies(j), I2D_OK);
    I2D_CHECK(i2d_body_is_awake(f.a) && i2d_body_is_awake(f.b));
    settle(&f);
    I2D_CHECK_STATUS(i2d_joint_destroy(j), I2D_OK);
    I2D_CHECK(i2d_body_is_awake(f.a) && i2d_body_is_awake(f.b));
    free_fixture(&f);
}

/* Refusals every kind shares: the def, its bodies, its base. */
I2D_TEST(api_joint_create_refusals_common) {
    g_reports_left = k_report_budget;
    fixture f = make_fixture();
    for (int k = 0; k < JOINT_KIND_COUNT; ++k) {
        const i2d_joint_type kind = (i2d_joint_type)k;
        const bool mouse = kind == I2D_JOINT_MOUSE;
        any_def d = default_def(kind, f.a, f.b);

        CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "NULL", create_any(f.world, kind, NULL));
        *cookie_of(&d, kind) = 0;
        CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "not initialised", create_any(f.world, kind, &d));
        d = default_def(kind, f.a, f.b);
        CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_HANDLE, "world", create_any(I2D_NULL_WORLD_ID, kind, &d));

        /* Bodies. */
        d = default_def(kind, I2D_NULL_BODY_ID, f.b);
        CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_HANDLE, "body_a", create_any(f.world, kind, &d));
        d = default_def(kind, f.a, I2D_NULL_BODY_ID);
        CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_HANDLE, "body_b", create_any(f.world, kind, &d));
        d = default_def(kind, f.a, f.a);
        CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "same body", create_any(f.world, kind, &d));
        d = default_def(kind, f.a, f.foreign);
        CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "another world", create_any(f.world, kind, &d));
        d = default_def(kind, f.foreign, f.a);
        CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "another world", create_any(f.world, kind, &d));
        d = default_def(kind, f.a, f.b);
        CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "another world", create_any(f.other_world, kind, &d));
        d = default_def(kind, f.ground, f.second_static);
        CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "dynamic", create_any(f.world, kind, &d));
        d = default_def(kind, f.ground, f.kinematic);
        CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "dynamic", create_any(f.world, kind, &d));
        if (mouse) {
            d = default_def(kind, f.a, f.ground);
            CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "body_b", create_any(f.world, kind, &d));
        }
        /* An id of another kind where a body id belongs. */
        i2d_body_id world_as_body;
        world_as_body.bits = f.world.bits;
        d = default_def(kind, world_as_body, f.b);
        CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_HANDLE, "body_a", create_any(f.world, kind, &d));

        /* The base. */
        const float bad_values[] = {NAN, INFINITY, -INFINITY};
        for (int v = 0; v < 3; ++v) {
            d = default_def(kind, f.a, f.b);
            base_of(&d)->local_anchor_a.x = bad_values[v];
            CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "local_anchor_a", create_any(f.world, kind, &d));
            d = default_def(kind, f.a, f.b);
            base_of(&d)->local_anchor_b.y = bad_values[v];
            CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "local_anchor_b", create_any(f.world, kind, &d));
            d = default_def(kind, f.a, f.b);
            base_of(&d)->force_threshold = bad_values[v];
            CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "force_threshold", create_any(f.world, kind, &d));
            d = default_def(kind, f.a, f.b);
            base_of(&d)->torque_threshold = bad_values[v];
            CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "torque_threshold", create_any(f.world, kind, &d));
        }
        d = default_def(kind, f.a, f.b);
        base_of(&d)->local_anchor_a = v2(2e5f, 0.0f);
        CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "local_anchor_a", create_any(f.world, kind, &d));
        d = default_def(kind, f.a, f.b);
        base_of(&d)->local_anchor_b = v2(0.0f, -2e5f);
        CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "local_anchor_b", create_any(f.world, kind, &d));
        d = default_def(kind, f.a, f.b);
        base_of(&d)->force_threshold = -1.0f;
        CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "force_threshold", create_any(f.world, kind, &d));
        d = default_def(kind, f.a, f.b);
        base_of(&d)->torque_threshold = -0.5f;
        CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "torque_threshold", create_any(f.world, kind, &d));
    }
    /* Bodies destroyed before the create: their ids are stale. */
    i2d_body_id doomed = make_box_body(f.world, I2D_BODY_DYNAMIC, 6.0f, 4.0f);
    I2D_CHECK_STATUS(i2d_body_destroy(doomed), I2D_OK);
    any_def d = default_def(I2D_JOINT_REVOLUTE, f.a, doomed);
    CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_HANDLE, "body_b", create_any(f.world, I2D_JOINT_REVOLUTE, &d));
    free_fixture(&f);
}

/* ---- Per-kind settings in the def ------------------------------------------------------ */

typedef struct def_value {
    i2d_joint_type kind;
    const char* name;
    size_t offset;
    float value;
} def_value;

#define DEF_VALUE(KIND, type, field, value) {KIND, #field, offsetof(type, field), value}
/* A vector's component, named in the message by the whole vector. */
#define DEF_COMPONENT(KIND, type, vector, component, value) {KIND, #vector, offsetof(type, vector.component), value}

/* Finite values outside each setting's range. */
static const def_value k_def_out_of_range[] = {
    DEF_VALUE(I2D_JOINT_REVOLUTE, i2d_revolute_joint_def, lower_angle, -3.12f),
    DEF_VALUE(I2D_JOINT_REVOLUTE, i2d_revolute_joint_def, upper_angle, 3.12f),
    DEF_VALUE(I2D_JOINT_REVOLUTE, i2d_revolute_joint_def, max_motor_torque, -1.0f),
    DEF_VALUE(I2D_JOINT_REVOLUTE, i2d_revolute_joint_def, hertz, -1.0f),
    DEF_VALUE(I2D_JOINT_REVOLUTE, i2d_revolute_joint_def, damping_ratio, -0.5f),
    DEF_VALUE(I2D_JOINT_PRISMATIC, i2d_prismatic_joint_def, max_motor_force, -1.0f),
    DEF_VALUE(I2D_JOINT_PRISMATIC, i2d_prismatic_joint_def, hertz, -1.0f),
    DEF_VALUE(I2D_JOINT_PRISMATIC, i2d_prismatic_joint_def, damping_ratio, -1.0f),
    DEF_VALUE(I2D_JOINT_DISTANCE, i2d_distance_joint_def, length, 0.004f),
    DEF_VALUE(I2D_JOINT_DISTANCE, i2d_distance_joint_def, length, 1.5e5f),
    DEF_VALUE(I2D_JOINT_DISTANCE, i2d_distance_joint_def, length, -1.0f),
    DEF_VALUE(I2D_JOINT_DISTANCE, i2d_distance_joint_def, min_length, -0.1f),
    DEF_VALUE(I2D_JOINT_DISTANCE, i2d_distance_joint_def, hertz, -1.0f),
    DEF_VALUE(I2D_JOINT_DISTANCE, i2d_distance_joint_def, damping_ratio, -1.0f),
    DEF_VALUE(I2D_JOINT_DISTANCE, i2d_distance_joint_def, max_motor_force, -1.0f),
    DEF_VALUE(I2D_JOINT_WELD, i2d_weld_joint_def, linear_hertz, -1.0f),
    DEF_VALUE(I2D_JOINT_WELD, i2d_weld_joint_def, angular_hertz, -1.0f),
    DEF_VALUE(I2D_JOINT_WELD, i2d_weld_joint_def, linear_damping_ratio, -1.0f),
    DEF_VALUE(I2D_JOINT_WELD, i2d_weld_joint_def, angular_damping_ratio, -1.0f),
    DEF_VALUE(I2D_JOINT_WHEEL, i2d_wheel_joint_def, hertz, -1.0f),
    DEF_VALUE(I2D_JOINT_WHEEL, i2d_wheel_joint_def, damping_ratio, -1.0f),
    DEF_VALUE(I2D_JOINT_WHEEL, i2d_wheel_joint_def, max_motor_torque, -1.0f),
    DEF_COMPONENT(I2D_JOINT_MOTOR, i2d_motor_joint_def, linear_offset, x, 2e9f),
    DEF_VALUE(I2D_JOINT_MOTOR, i2d_motor_joint_def, max_force, -1.0f),
    DEF_VALUE(I2D_JOINT_MOTOR, i2d_motor_joint_def, max_torque, -1.0f),
    DEF_VALUE(I2D_JOINT_MOTOR, i2d_motor_joint_def, correction_factor, -0.1f),
    DEF_VALUE(I2D_JOINT_MOTOR, i2d_motor_joint_def, correction_factor, 1.1f),
    DEF_COMPONENT(I2D_JOINT_MOUSE, i2d_mouse_joint_def, target, y, -2e9f),
    DEF_VALUE(I2D_JOINT_MOUSE, i2d_mouse_joint_def, hertz, -1.0f),
    DEF_VALUE(I2D_JOINT_MOUSE, i2d_mouse_joint_def, damping_ratio, -1.0f),
    DEF_VALUE(I2D_JOINT_MOUSE, i2d_mouse_joint_def, max_force, -1.0f),
};

/* The edges of the ranges, which must be accepted. */
static const def_value k_def_in_range[] = {
    DEF_VALUE(I2D_JOINT_REVOLUTE, i2d_revolute_joint_def, lower_angle, -3.11f),
    DEF_VALUE(I2D_JOINT_REVOLUTE, i2d_revolute_joint_def, hertz, 0.0f),
    DEF_VALUE(I2D_JOINT_DISTANCE, i2d_distance_joint_def, length, 0.005f),
    DEF_VALUE(I2D_JOINT_DISTANCE, i2d_distance_joint_def, length, 1e5f),
    DEF_VALUE(I2D_JOINT_MOTOR, i2d_motor_joint_def, correction_factor, 0.0f),
    DEF_VALUE(I2D_JOINT_MOTOR, i2d_motor_joint_def, correction_factor, 1.0f),
    DEF_VALUE(I2D_JOINT_MOUSE, i2d_mouse_joint_def, max_force, FLT_MAX),
    DEF_VALUE(I2D_JOINT_WELD, i2d_weld_joint_def, reference_angle, -100.0f),
};

I2D_TEST(api_joint_create_refusals_settings) {
    g_reports_left = k_report_budget;
    fixture f = make_fixture();
    const float bad_values[] = {NAN, INFINITY, -INFINITY};
    for (size_t i = 0; i < sizeof k_def_floats / sizeof k_def_floats[0]; ++i) {
        const def_float* row = &k_def_floats[i];
        for (int v = 0; v < 3; ++v) {
            any_def d = default_def(row->kind, f.a, f.b);
            set_def_float(&d, row->offset, bad_values[v]);
            CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, row->name, create_any(f.world, row->kind, &d));
        }
    }
    for (size_t i = 0; i < sizeof k_def_out_of_range / sizeof k_def_out_of_range[0]; ++i) {
        const def_value* row = &k_def_out_of_range[i];
        any_def d = default_def(row->kind, f.a, f.b);
        set_def_float(&d, row->offset, row->value);
        CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, row->name, create_any(f.world, row->kind, &d));
    }
    /* Bounds out of order; zero axes. */
    any_def d = default_def(I2D_JOINT_REVOLUTE, f.a, f.b);
    d.revolute.lower_angle = 0.5f;
    d.revolute.upper_angle = 0.25f;
    CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "lower_angle", create_any(f.world, I2D_JOINT_REVOLUTE, &d));
    d = default_def(I2D_JOINT_PRISMATIC, f.a, f.b);
    d.prismatic.lower_translation = 1.0f;
    CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "lower_translation",
                         create_any(f.world, I2D_JOINT_PRISMATIC, &d));
    d = default_def(I2D_JOINT_WHEEL, f.a, f.b);
    d.wheel.upper_translation = -1.0f;
    CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "upper_translation", create_any(f.world, I2D_JOINT_WHEEL, &d));
    d = default_def(I2D_JOINT_DISTANCE, f.a, f.b);
    d.distance.min_length = 3.0f;
    d.distance.max_length = 2.0f;
    CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "min_length", create_any(f.world, I2D_JOINT_DISTANCE, &d));
    d = default_def(I2D_JOINT_PRISMATIC, f.a, f.b);
    d.prismatic.local_axis_a = v2(0.0f, 0.0f);
    CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "local_axis_a", create_any(f.world, I2D_JOINT_PRISMATIC, &d));
    d = default_def(I2D_JOINT_WHEEL, f.a, f.b);
    d.wheel.local_axis_a = v2(1e-30f, -1e-30f);
    CHECK_CREATE_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "local_axis_a", create_any(f.world, I2D_JOINT_WHEEL, &d));

    for (size_t i = 0; i < sizeof k_def_in_range / sizeof k_def_in_range[0]; ++i) {
        const def_value* row = &k_def_in_range[i];
        d = default_def(row->kind, f.a, f.b);
        set_def_float(&d, row->offset, row->value);
        if (create_any(f.world, row->kind, &d).bits == 0) {
            ++i2d_check_failures;
            report("%s joint with %s = %g refused: %s", k_kind_names[row->kind], row->name,
                    (double)row->value, i2d_last_error_message());
        }
    }
    free_fixture(&f);
}

/* What a def becomes: axes at unit length, a distance joint's range clamped into the
 * lengths it can hold. */
I2D_TEST(api_joint_create_normalises) {
    g_reports_left = k_report_budget;
    fixture f = make_fixture();
    any_def d = default_def(I2D_JOINT_PRISMATIC, f.a, f.b);
    d.prismatic.local_axis_a = v2(3.0f, 4.0f);
    i2d_joint_id prismatic = create_any(f.world, I2D_JOINT_PRISMATIC, &d);
    I2D_CHECK_NEAR(i2d_prismatic_joint_get_local_axis_a(prismatic).x, 0.6f, 1e-7);
    I2D_CHECK_NEAR(i2d_prismatic_joint_get_local_axis_a(prismatic).y, 0.8f, 1e-7);
    d = default_def(I2D_JOINT_WHEEL, f.a, f.b);
    d.wheel.local_axis_a = v2(-1e30f, 0.0f);
    i2d_joint_id wheel = create_any(f.world, I2D_JOINT_WHEEL, &d);
    I2D_CHECK(i2d_wheel_joint_get_local_axis_a(wheel).x == -1.0f && i2d_wheel_joint_get_local_axis_a(wheel).y == 0.0f);
    d = default_def(I2D_JOINT_DISTANCE, f.a, f.b);
    d.distance.max_length = FLT_MAX;
    i2d_joint_id rope = create_any(f.world, I2D_JOINT_DISTANCE, &d);
    I2D_CHECK(i2d_distance_joint_get_min_length(rope) == 0.005f);
    I2D_CHECK(i2d_distance_joint_get_max_length(rope) == 1e5f);
    I2D_CHECK_STATUS(i2d_distance_joint_set_length_range(rope, 0.0f, 1e9f), I2D_OK);
    I2D_CHECK(i2d_distance_joint_get_min_length(rope) == 0.005f);
    I2D_CHECK(i2d_distance_joint_get_max_length(rope) == 1e5f);
    free_fixture(&f);
}

/* ---- Every setter and getter ------------------------------------------------------------ */

typedef float (*get_float_fn)(i2d_joint_id);
typedef i2d_status (*set_float_fn)(i2d_joint_id, float);
typedef bool (*get_bool_fn)(i2d_joint_id);
typedef i2d_status (*set_bool_fn)(i2d_joint_id, bool);
typedef i2d_vec2 (*get_vec2_fn)(i2d_joint_id);
typedef i2d_status (*set_vec2_fn)(i2d_joint_id, i2d_vec2);

typedef struct float_setting {
    i2d_joint_type kind;
    const char* name;
    get_float_fn get;
    set_float_fn set;
    float good;  /* accepted from the defaults, in table order */
    float bad;   /* a finite value out of range; NaN when every finite value is accepted */
} float_setting;

#define FLOAT_SETTING(KIND, kind, field, good, bad) \
    {KIND, #field, i2d_##kind##_joint_get_##field, i2d_##kind##_joint_set_##field, good, bad}

static const float_setting k_float_settings[] = {
    FLOAT_SETTING(I2D_JOINT_REVOLUTE, revolute, reference_angle, 0.5f, NAN),
    FLOAT_SETTING(I2D_JOINT_REVOLUTE, revolute, lower_angle, -0.75f, -3.2f),
    FLOAT_SETTING(I2D_JOINT_REVOLUTE, revolute, upper_angle, 1.25f, 3.2f),
    FLOAT_SETTING(I2D_JOINT_REVOLUTE, revolute, motor_speed, -2.0f, NAN),
    FLOAT_SETTING(I2D_JOINT_REVOLUTE, revolute, max_motor_torque, 40.0f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_REVOLUTE, revolute, hertz, 3.0f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_REVOLUTE, revolute, damping_ratio, 0.25f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_REVOLUTE, revolute, target_angle, 0.125f, NAN),
    FLOAT_SETTING(I2D_JOINT_PRISMATIC, prismatic, reference_angle, -0.5f, NAN),
    FLOAT_SETTING(I2D_JOINT_PRISMATIC, prismatic, lower_translation, -1.5f, NAN),
    FLOAT_SETTING(I2D_JOINT_PRISMATIC, prismatic, upper_translation, 2.5f, NAN),
    FLOAT_SETTING(I2D_JOINT_PRISMATIC, prismatic, motor_speed, 1.5f, NAN),
    FLOAT_SETTING(I2D_JOINT_PRISMATIC, prismatic, max_motor_force, 100.0f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_PRISMATIC, prismatic, hertz, 2.0f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_PRISMATIC, prismatic, damping_ratio, 0.5f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_PRISMATIC, prismatic, target_translation, 0.75f, NAN),
    FLOAT_SETTING(I2D_JOINT_DISTANCE, distance, length, 2.5f, 0.001f),
    FLOAT_SETTING(I2D_JOINT_DISTANCE, distance, min_length, 0.5f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_DISTANCE, distance, max_length, 4.0f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_DISTANCE, distance, hertz, 5.0f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_DISTANCE, distance, damping_ratio, 0.7f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_DISTANCE, distance, motor_speed, -0.5f, NAN),
    FLOAT_SETTING(I2D_JOINT_DISTANCE, distance, max_motor_force, 20.0f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_WELD, weld, reference_angle, 0.3f, NAN),
    FLOAT_SETTING(I2D_JOINT_WELD, weld, linear_hertz, 10.0f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_WELD, weld, angular_hertz, 12.0f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_WELD, weld, linear_damping_ratio, 0.2f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_WELD, weld, angular_damping_ratio, 0.4f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_WHEEL, wheel, hertz, 4.0f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_WHEEL, wheel, damping_ratio, 0.9f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_WHEEL, wheel, lower_translation, -0.25f, NAN),
    FLOAT_SETTING(I2D_JOINT_WHEEL, wheel, upper_translation, 0.25f, NAN),
    FLOAT_SETTING(I2D_JOINT_WHEEL, wheel, motor_speed, 6.0f, NAN),
    FLOAT_SETTING(I2D_JOINT_WHEEL, wheel, max_motor_torque, 15.0f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_MOTOR, motor, angular_offset, 1.0f, NAN),
    FLOAT_SETTING(I2D_JOINT_MOTOR, motor, max_force, 50.0f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_MOTOR, motor, max_torque, 25.0f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_MOTOR, motor, correction_factor, 0.6f, 1.5f),
    FLOAT_SETTING(I2D_JOINT_MOUSE, mouse, hertz, 8.0f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_MOUSE, mouse, damping_ratio, 0.5f, -1.0f),
    FLOAT_SETTING(I2D_JOINT_MOUSE, mouse, max_force, 500.0f, -1.0f),
};

typedef struct bool_setting {
    i2d_joint_type kind;
    const char* name;
    get_bool_fn get;
    set_bool_fn set;
} bool_setting;

#define BOOL_SETTING(KIND, kind, field) {KIND, #field, i2d_##kind##_joint_get_##field, i2d_##kind##_joint_set_##field}

static const bool_setting k_bool_settings[] = {
    BOOL_SETTING(I2D_JOINT_REVOLUTE, revolute, enable_limit),
    BOOL_SETTING(I2D_JOINT_REVOLUTE, revolute, enable_motor),
    BOOL_SETTING(I2D_JOINT_REVOLUTE, revolute, enable_spring),
    BOOL_SETTING(I2D_JOINT_PRISMATIC, prismatic, enable_limit),
    BOOL_SETTING(I2D_JOINT_PRISMATIC, prismatic, enable_motor),
    BOOL_SETTING(I2D_JOINT_PRISMATIC, prismatic, enable_spring),
    BOOL_SETTING(I2D_JOINT_DISTANCE, distance, enable_limit),
    BOOL_SETTING(I2D_JOINT_DISTANCE, distance, enable_spring),
    BOOL_SETTING(I2D_JOINT_DISTANCE, distance, enable_motor),
    BOOL_SETTING(I2D_JOINT_WHEEL, wheel, enable_spring),
    BOOL_SETTING(I2D_JOINT_WHEEL, wheel, enable_limit),
    BOOL_SETTING(I2D_JOINT_WHEEL, wheel, enable_motor),
};

typedef struct vec2_setting {
    i2d_joint_type kind;
    const char* name;
    get_vec2_fn get;
    set_vec2_fn set;
    i2d_vec2 good, expected;  /* expected: what reads back (axes are normalised) */
    i2d_vec2 bad;
} vec2_setting;

#define VEC2_SETTING(KIND, kind, field, gx, gy, ex, ey, bx, by)                                    \
    {KIND, #field, i2d_##kind##_joint_get_##field, i2d_##kind##_joint_set_##field, {gx, gy}, {ex, ey}, \
     {bx, by}}

static const vec2_setting k_vec2_settings[] = {
    VEC2_SETTING(I2D_JOINT_PRISMATIC, prismatic, local_axis_a, 0.0f, -2.0f, 0.0f, -1.0f, 0.0f, 0.0f),
    VEC2_SETTING(I2D_JOINT_WHEEL, wheel, local_axis_a, 5.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f),
    VEC2_SETTING(I2D_JOINT_MOTOR, motor, linear_offset, 1.5f, -2.5f, 1.5f, -2.5f, 2e9f, 0.0f),
    VEC2_SETTING(I2D_JOINT_MOUSE, mouse, target, -7.0f, 3.0f, -7.0f, 3.0f, 0.0f, -2e9f),
};

#define COUNT_OF(array) (sizeof(array) / sizeof((array)[0]))

I2D_TEST(api_joint_settings_round_trip) {
    g_reports_left = k_report_budget;
    fixture f = make_fixture();
    i2d_joint_id joints[JOINT_KIND_COUNT];
    create_one_of_each_kind(&f, joints);
    for (size_t i = 0; i < COUNT_OF(k_float_settings); ++i) {
        const float_setting* s = &k_float_settings[i];
        settle(&f);
        const i2d_status status = s->set(joints[s->kind], s->good);
        const float read = s->get(joints[s->kind]);
        if (status != I2D_OK || read != s->good || !i2d_body_is_awake(f.a) || !i2d_body_is_awake(f.b)) {
            ++i2d_check_failures;
            report("%s %s: set %g gave %s, read %g, bodies awake %d%d", k_kind_names[s->kind], s->name,
                   (double)s->good, i2d_status_string(status), (double)read, i2d_body_is_awake(f.a),
                   i2d_body_is_awake(f.b));
        }
    }
    for (size_t i = 0; i < COUNT_OF(k_bool_settings); ++i) {
        const bool_setting* s = &k_bool_settings[i];
        const bool flipped = !s->get(joints[s->kind]);
        settle(&f);
        const i2d_status status = s->set(joints[s->kind], flipped);
        if (status != I2D_OK || s->get(joints[s->kind]) != flipped || !i2d_body_is_awake(f.a)) {
            ++i2d_check_failures;
            report("%s %s did not flip (%s)", k_kind_names[s->kind], s->name,
                    i2d_status_string(status));
        }
    }
    for (size_t i = 0; i < COUNT_OF(k_vec2_settings); ++i) {
        const vec2_setting* s = &k_vec2_settings[i];
        settle(&f);
        const i2d_status status = s->set(joints[s->kind], s->good);
        const i2d_vec2 read = s->get(joints[s->kind]);
        if (status != I2D_OK || read.x != s->expected.x || read.y != s->expected.y || !i2d_body_is_awake(f.a)) {
            ++i2d_check_failures;
            report("%s %s: read (%g, %g), status %s", k_kind_names[s->kind], s->name,
                    (double)read.x, (double)read.y, i2d_status_string(status));
        }
    }
    /* The shared settings, on every kind. */
    for (int k = 0; k < JOINT_KIND_COUNT; ++k) {
        const i2d_joint_id j = joints[k];
        I2D_CHECK_STATUS(i2d_joint_set_local_anchor_a(j, v2(0.5f, -0.25f)), I2D_OK);
        I2D_CHECK_STATUS(i2d_joint_set_local_anchor_b(j, v2(-1e5f, 1e5f)), I2D_OK);
        I2D_CHECK_STATUS(i2d_joint_set_collide_connected(j, true), I2D_OK);
        I2D_CHECK_STATUS(i2d_joint_set_force_threshold(j, 12.0f), I2D_OK);
        I2D_CHECK_STATUS(i2d_joint_set_torque_threshold(j, 0.0f), I2D_OK);
        I2D_CHECK_STATUS(i2d_joint_set_user_data(j, &k_marker), I2D_OK);
        I2D_CHECK(i2d_joint_get_local_anchor_a(j).x == 0.5f && i2d_joint_get_local_anchor_a(j).y == -0.25f);
        I2D_CHECK(i2d_joint_get_local_anchor_b(j).x == -1e5f && i2d_joint_get_local_anchor_b(j).y == 1e5f);
        I2D_CHECK(i2d_joint_get_collide_connected(j));
        I2D_CHECK(i2d_joint_get_force_threshold(j) == 12.0f && i2d_joint_get_torque_threshold(j) == 0.0f);
        I2D_CHECK(i2d_joint_get_user_data(j) == &k_marker);
        I2D_CHECK_STATUS(i2d_joint_set_collide_connected(j, false), I2D_OK);
        I2D_CHECK(!i2d_joint_get_collide_connected(j));
    }
    /* Both bounds at once. */
    I2D_CHECK_STATUS(i2d_revolute_joint_set_limits(joints[I2D_JOINT_REVOLUTE], 2.0f, 3.0f), I2D_OK);
    I2D_CHECK(i2d_revolute_joint_get_lower_angle(joints[I2D_JOINT_REVOLUTE]) == 2.0f);
    I2D_CHECK(i2d_revolute_joint_get_upper_angle(joints[I2D_JOINT_REVOLUTE]) == 3.0f);
    I2D_CHECK_STATUS(i2d_prismatic_joint_set_limits(joints[I2D_JOINT_PRISMATIC], -5.0f, -4.0f), I2D_OK);
    I2D_CHECK(i2d_prismatic_joint_get_lower_translation(joints[I2D_JOINT_PRISMATIC]) == -5.0f);
    I2D_CHECK(i2d_prismatic_joint_get_upper_translation(joints[I2D_JOINT_PRISMATIC]) == -4.0f);
    I2D_CHECK_STATUS(i2d_wheel_joint_set_limits(joints[I2D_JOINT_WHEEL], 1.0f, 1.0f), I2D_OK);
    I2D_CHECK(i2d_wheel_joint_get_lower_translation(joints[I2D_JOINT_WHEEL]) == 1.0f);
    I2D_CHECK(i2d_wheel_joint_get_upper_translation(joints[I2D_JOINT_WHEEL]) == 1.0f);
    I2D_CHECK_STATUS(i2d_distance_joint_set_length_range(joints[I2D_JOINT_DISTANCE], 6.0f, 7.0f), I2D_OK);
    I2D_CHECK(i2d_distance_joint_get_min_length(joints[I2D_JOINT_DISTANCE]) == 6.0f);
    I2D_CHECK(i2d_distance_joint_get_max_length(joints[I2D_JOINT_DISTANCE]) == 7.0f);
    free_fixture(&f);
}

I2D_TEST(api_joint_setter_refusals) {
    g_reports_left = k_report_budget;
    fixture f = make_fixture();
    i2d_joint_id joints[JOINT_KIND_COUNT];
    create_one_of_each_kind(&f, joints);
    const float non_finite[] = {NAN, INFINITY, -INFINITY};
    for (size_t i = 0; i < COUNT_OF(k_float_settings); ++i) {
        const float_setting* s = &k_float_settings[i];
        const i2d_joint_id j = joints[s->kind];
        const float before = s->get(j);
        for (int v = 0; v < 3; ++v) {
            CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, s->name, s->set(j, non_finite[v]));
        }
        CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, s->name, s->set(j, s->bad));
        I2D_CHECK(s->get(j) == before);
    }
    for (size_t i = 0; i < COUNT_OF(k_vec2_settings); ++i) {
        const vec2_setting* s = &k_vec2_settings[i];
        const i2d_joint_id j = joints[s->kind];
        const i2d_vec2 before = s->get(j);
        for (int v = 0; v < 3; ++v) {
            CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, s->name, s->set(j, v2(non_finite[v], 0.0f)));
            CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, s->name, s->set(j, v2(1.0f, non_finite[v])));
        }
        CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, s->name, s->set(j, s->bad));
        I2D_CHECK(s->get(j).x == before.x && s->get(j).y == before.y);
    }
    for (int k = 0; k < JOINT_KIND_COUNT; ++k) {
        const i2d_joint_id j = joints[k];
        for (int v = 0; v < 3; ++v) {
            CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "local_anchor_a",
                          i2d_joint_set_local_anchor_a(j, v2(non_finite[v], 0.0f)));
            CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "local_anchor_b",
                          i2d_joint_set_local_anchor_b(j, v2(0.0f, non_finite[v])));
            CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "force_threshold",
                          i2d_joint_set_force_threshold(j, non_finite[v]));
            CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "torque_threshold",
                          i2d_joint_set_torque_threshold(j, non_finite[v]));
        }
        CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "local_anchor_a", i2d_joint_set_local_anchor_a(j, v2(1.5e5f, 0)));
        CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "local_anchor_b", i2d_joint_set_local_anchor_b(j, v2(0, -2e5f)));
        CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "force_threshold", i2d_joint_set_force_threshold(j, -1.0f));
        CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "torque_threshold", i2d_joint_set_torque_threshold(j, -1.0f));
        I2D_CHECK(i2d_joint_get_local_anchor_a(j).x == 0.0f && i2d_joint_get_force_threshold(j) == FLT_MAX);
    }

    /* A single bound is held to the current other one; a pair to itself. */
    const i2d_joint_id r = joints[I2D_JOINT_REVOLUTE];
    I2D_CHECK_STATUS(i2d_revolute_joint_set_limits(r, -0.5f, 0.5f), I2D_OK);
    CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "lower_angle", i2d_revolute_joint_set_lower_angle(r, 0.6f));
    CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "upper_angle", i2d_revolute_joint_set_upper_angle(r, -0.6f));
    CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "lower_angle", i2d_revolute_joint_set_limits(r, 0.2f, 0.1f));
    CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "lower_angle", i2d_revolute_joint_set_limits(r, -3.2f, 0.1f));
    CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "upper_angle", i2d_revolute_joint_set_limits(r, 0.0f, NAN));
    I2D_CHECK(i2d_revolute_joint_get_lower_angle(r) == -0.5f && i2d_revolute_joint_get_upper_angle(r) == 0.5f);

    const i2d_joint_id p = joints[I2D_JOINT_PRISMATIC];
    I2D_CHECK_STATUS(i2d_prismatic_joint_set_limits(p, -1.0f, 1.0f), I2D_OK);
    CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "lower_translation", i2d_prismatic_joint_set_lower_translation(p, 2));
    CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "upper_translation", i2d_prismatic_joint_set_upper_translation(p, -2));
    CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "lower_translation", i2d_prismatic_joint_set_limits(p, 1.0f, 0.0f));
    I2D_CHECK(i2d_prismatic_joint_get_lower_translation(p) == -1.0f);

    const i2d_joint_id w = joints[I2D_JOINT_WHEEL];
    I2D_CHECK_STATUS(i2d_wheel_joint_set_limits(w, -1.0f, 1.0f), I2D_OK);
    CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "lower_translation", i2d_wheel_joint_set_lower_translation(w, 2.0f));
    CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "upper_translation", i2d_wheel_joint_set_upper_translation(w, -2.0f));
    CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "lower_translation", i2d_wheel_joint_set_limits(w, 1.0f, -1.0f));
    I2D_CHECK(i2d_wheel_joint_get_upper_translation(w) == 1.0f);

    const i2d_joint_id d = joints[I2D_JOINT_DISTANCE];
    I2D_CHECK_STATUS(i2d_distance_joint_set_length_range(d, 1.0f, 2.0f), I2D_OK);
    CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "min_length", i2d_distance_joint_set_min_length(d, 3.0f));
    CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "max_length", i2d_distance_joint_set_max_length(d, 0.5f));
    CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "min_length", i2d_distance_joint_set_length_range(d, 2.0f, 1.0f));
    CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "max_length", i2d_distance_joint_set_length_range(d, 1.0f, -1.0f));
    CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, "length", i2d_distance_joint_set_length(d, 2e5f));
    I2D_CHECK(i2d_distance_joint_get_min_length(d) == 1.0f && i2d_distance_joint_get_max_length(d) == 2.0f);
    free_fixture(&f);
}

/* Getters of one kind on a joint of another: zero and INVALID_ARGUMENT; setters refused. */
I2D_TEST(api_joint_wrong_kind) {
    g_reports_left = k_report_budget;
    fixture f = make_fixture();
    i2d_joint_id joints[JOINT_KIND_COUNT];
    create_one_of_each_kind(&f, joints);
    for (int k = 0; k < JOINT_KIND_COUNT; ++k) {
        for (size_t i = 0; i < COUNT_OF(k_float_settings); ++i) {
            const float_setting* s = &k_float_settings[i];
            if ((int)s->kind == k) {
                continue;
            }
            const float read = s->get(joints[k]);
            if (read != 0.0f || i2d_last_status() != I2D_ERR_INVALID_ARGUMENT) {
                ++i2d_check_failures;
                report("%s getter %s on a %s joint: %g, %s", k_kind_names[s->kind], s->name,
                        k_kind_names[k], (double)read, i2d_status_string(i2d_last_status()));
            }
            CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, k_kind_names[k], s->set(joints[k], s->good));
        }
        for (size_t i = 0; i < COUNT_OF(k_bool_settings); ++i) {
            const bool_setting* s = &k_bool_settings[i];
            if ((int)s->kind == k) {
                continue;
            }
            I2D_CHECK(!s->get(joints[k]) && i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
            CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, k_kind_names[s->kind], s->set(joints[k], true));
        }
        for (size_t i = 0; i < COUNT_OF(k_vec2_settings); ++i) {
            const vec2_setting* s = &k_vec2_settings[i];
            if ((int)s->kind == k) {
                continue;
            }
            const i2d_vec2 read = s->get(joints[k]);
            I2D_CHECK(read.x == 0.0f && read.y == 0.0f && i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
            CHECK_REFUSED(&f, I2D_ERR_INVALID_ARGUMENT, k_kind_names[k], s->set(joints[k], s->good));
        }
    }
    /* The measures and outputs too. */
    const i2d_joint_id filter = joints[I2D_JOINT_FILTER];
    const get_float_fn measures[] = {
        i2d_revolute_joint_get_angle,          i2d_revolute_joint_get_motor_torque, i2d_prismatic_joint_get_translation,
        i2d_prismatic_joint_get_speed,         i2d_prismatic_joint_get_motor_force, i2d_distance_joint_get_current_length,
        i2d_distance_joint_get_motor_force,    i2d_wheel_joint_get_motor_torque,    i2d_wheel_joint_get_translation,
    };
    for (size_t i = 0; i < COUNT_OF(measures); ++i) {
        I2D_CHECK(measures[i](filter) == 0.0f && i2d_last_status() == I2D_ERR_INVALID_ARGUMENT);
    }
    free_fixture(&f);
}

/* ---- Ids ----------------------------------------------------------------------------- */

/* Every call taking a joint id refuses this one with INVALID_HANDLE. */
static void check_joint_id_refused(const fixture* f, i2d_joint_id j, const char* what) {
    I2D_CHECK(!i2d_joint_is_valid(j));
    CHECK_REFUSED(f, I2D_ERR_INVALID_HANDLE, "joint", i2d_joint_destroy(j));
    CHECK_REFUSED(f, I2D_ERR_INVALID_HANDLE, "joint", i2d_joint_set_user_data(j, &k_marker));
    CHECK_REFUSED(f, I2D_ERR_INVALID_HANDLE, "joint", i2d_joint_wake_bodies(j));
    CHECK_REFUSED(f, I2D_ERR_INVALID_HANDLE, "joint", i2d_joint_set_collide_connected(j, true));
    CHECK_REFUSED(f, I2D_ERR_INVALID_HANDLE, "joint", i2d_revolute_joint_set_hertz(j, 1.0f));
    CHECK_REFUSED(f, I2D_ERR_INVALID_HANDLE, "joint", i2d_mouse_joint_set_target(j, v2(1.0f, 1.0f)));
    const bool zero = i2d_joint_get_body_a(j).bits == 0 && i2d_last_status() == I2D_ERR_INVALID_HANDLE &&
                      i2d_joint_get_world(j).bits == 0 && i2d_joint_get_user_data(j) == NULL &&
                      i2d_joint_get_reaction_torque(j) == 0.0f && i2d_distance_joint_get_length(j) == 0.0f &&
                      i2d_last_status() == I2D_ERR_INVALID_HANDLE && i2d_revolute_joint_get_angle(j) == 0.0f &&
                      i2d_last_status() == I2D_ERR_INVALID_HANDLE;
    if (!zero) {
        ++i2d_check_failures;
        report("%s joint id: a getter answered or did not record INVALID_HANDLE", what);
    }
}

I2D_TEST(api_joint_ids_go_stale) {
    g_reports_left = k_report_budget;
    fixture f = make_fixture();
    check_joint_id_refused(&f, I2D_NULL_JOINT_ID, "null");
    i2d_joint_id as_joint;
    as_joint.bits = f.a.bits;  /* a body id where a joint id belongs */
    check_joint_id_refused(&f, as_joint, "body");
    as_joint.bits = f.world.bits;
    check_joint_id_refused(&f, as_joint, "world");

    /* Destroyed: stale, and a new joint in the same slot does not revive it. */
    i2d_joint_id j = create_default(&f, I2D_JOINT_REVOLUTE);
    I2D_REQUIRE(j.bits != 0);
    /* A joint id where a body id belongs. */
    i2d_body_id as_body;
    as_body.bits = j.bits;
    I2D_CHECK(!i2d_body_is_valid(as_body));
    I2D_CHECK_STATUS(i2d_joint_destroy(j), I2D_OK);
    I2D_CHECK(i2d_world_get_joint_count(f.world) == 0);
    check_joint_id_refused(&f, j, "destroyed");
    i2d_joint_id reused = create_default(&f, I2D_JOINT_WELD);
    I2D_CHECK(reused.bits != j.bits && i2d_joint_is_valid(reused));
    check_joint_id_refused(&f, j, "destroyed, slot reused");

    /* Destroying a body destroys its joints (and only those). */
    any_def d = default_def(I2D_JOINT_DISTANCE, f.ground, f.b);
    const i2d_joint_id to_ground = create_any(f.world, I2D_JOINT_DISTANCE, &d);
    I2D_CHECK(i2d_world_get_joint_count(f.world) == 2);
    I2D_CHECK_STATUS(i2d_body_destroy(f.a), I2D_OK);
    check_joint_id_refused(&f, reused, "body destroyed");
    I2D_CHECK(i2d_joint_is_valid(to_ground) && i2d_world_get_joint_count(f.world) == 1);

    /* The world's destruction: every id stale. */
    i2d_world_id world = f.world;
    I2D_CHECK_STATUS(i2d_world_destroy(world), I2D_OK);
    I2D_CHECK(!i2d_joint_is_valid(to_ground));
    I2D_CHECK(i2d_joint_get_type(to_ground) == I2D_JOINT_DISTANCE && i2d_last_status() == I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(i2d_world_get_joint_count(world) == 0 && i2d_last_status() == I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(i2d_world_get_joint_events(world).count == 0 && i2d_last_status() == I2D_ERR_INVALID_HANDLE);
    i2d_world_destroy(f.other_world);
}

/* ---- Inside callbacks -------------------------------------------------------------- */

typedef struct locked_probe {
    const fixture* f;
    i2d_joint_id joint;
    i2d_status create, destroy, set_hertz, set_anchor, set_collide, wake, set_user_data;
    void* user_data_read;
    int calls;
} locked_probe;

static bool probe_locked(i2d_shape_id shape, void* context) {
    (void)shape;
    locked_probe* p = (locked_probe*)context;
    if (p->calls++ > 0) {
        return false;
    }
    any_def d = default_def(I2D_JOINT_REVOLUTE, p->f->a, p->f->b);
    p->create = create_any(p->f->world, I2D_JOINT_REVOLUTE, &d).bits == 0 ? i2d_last_status() : I2D_OK;
    p->destroy = i2d_joint_destroy(p->joint);
    p->set_hertz = i2d_revolute_joint_set_hertz(p->joint, 2.0f);
    p->set_anchor = i2d_joint_set_local_anchor_a(p->joint, v2(1.0f, 0.0f));
    p->set_collide = i2d_joint_set_collide_connected(p->joint, true);
    p->wake = i2d_joint_wake_bodies(p->joint);
    p->set_user_data = i2d_joint_set_user_data(p->joint, &k_marker);
    p->user_data_read = i2d_joint_get_user_data(p->joint);
    return false;
}

I2D_TEST(api_joint_world_locked) {
    g_reports_left = k_report_budget;
    fixture f = make_fixture();
    locked_probe probe;
    memset(&probe, 0, sizeof probe);
    probe.f = &f;
    probe.joint = create_default(&f, I2D_JOINT_REVOLUTE);
    const snapshot before = settle(&f);
    i2d_aabb everywhere;
    everywhere.min = v2(-100.0f, -100.0f);
    everywhere.max = v2(100.0f, 100.0f);
    I2D_CHECK_STATUS(i2d_world_overlap_aabb(f.world, everywhere, i2d_default_query_filter(), probe_locked, &probe),
                     I2D_OK);
    I2D_REQUIRE(probe.calls == 1);
    I2D_CHECK(probe.create == I2D_ERR_WORLD_LOCKED && probe.destroy == I2D_ERR_WORLD_LOCKED);
    I2D_CHECK(probe.set_hertz == I2D_ERR_WORLD_LOCKED && probe.set_anchor == I2D_ERR_WORLD_LOCKED);
    I2D_CHECK(probe.set_collide == I2D_ERR_WORLD_LOCKED && probe.wake == I2D_ERR_WORLD_LOCKED);
    /* User data does not touch the simulation: allowed, as for bodies. */
    I2D_CHECK(probe.set_user_data == I2D_OK && probe.user_data_read == &k_marker);
    const snapshot after = take_snapshot(&f);
    I2D_CHECK(after.hash == before.hash && after.joints == 1 && !after.awake_a && !after.awake_b);
    I2D_CHECK(i2d_revolute_joint_get_hertz(probe.joint) == 0.0f && !i2d_joint_get_collide_connected(probe.joint));
    I2D_CHECK(i2d_joint_get_local_anchor_a(probe.joint).x == 0.0f);
    free_fixture(&f);
}

/* ---- Measures ------------------------------------------------------------------------ */

I2D_TEST(api_joint_measures) {
    g_reports_left = k_report_budget;
    fixture f = make_fixture(); /* a at (0, 4), b at (3, 4) */
    any_def d = default_def(I2D_JOINT_DISTANCE, f.a, f.b);
    base_of(&d)->local_anchor_a = v2(0.0f, 0.5f);
    base_of(&d)->local_anchor_b = v2(0.0f, -0.5f);
    i2d_joint_id distance = create_any(f.world, I2D_JOINT_DISTANCE, &d);
    I2D_CHECK_NEAR(i2d_distance_joint_get_current_length(distance), sqrt(3.0 * 3.0 + 1.0), 1e-5);

    d = default_def(I2D_JOINT_PRISMATIC, f.a, f.b);
    i2d_joint_id prismatic = create_any(f.world, I2D_JOINT_PRISMATIC, &d);
    I2D_CHECK_NEAR(i2d_prismatic_joint_get_translation(prismatic), 3.0, 1e-5);
    I2D_CHECK_STATUS(i2d_body_set_linear_velocity(f.b, v2(2.0f, 7.0f)), I2D_OK);
    I2D_CHECK_NEAR(i2d_prismatic_joint_get_speed(prismatic), 2.0, 1e-5);

    d = default_def(I2D_JOINT_WHEEL, f.a, f.b); /* axis (0, 1): b is level with a */
    i2d_joint_id wheel = create_any(f.world, I2D_JOINT_WHEEL, &d);
    I2D_CHECK_NEAR(i2d_wheel_joint_get_translation(wheel), 0.0, 1e-5);

    d = default_def(I2D_JOINT_REVOLUTE, f.a, f.b);
    d.revolute.reference_angle = 0.25f;
    i2d_joint_id revolute = create_any(f.world, I2D_JOINT_REVOLUTE, &d);
    I2D_CHECK_STATUS(i2d_body_set_transform(f.b, v2(3.0f, 4.0f), i2d_make_rot(1.0f)), I2D_OK);
    I2D_CHECK_NEAR(i2d_revolute_joint_get_angle(revolute), 0.75, 1e-5);
    /* No step yet: no motor output. */
    I2D_CHECK(i2d_revolute_joint_get_motor_torque(revolute) == 0.0f && i2d_last_status() == I2D_OK);
    free_fixture(&f);
}

/* ---- Joint events (needs the joint solver) ---------------------------------------------- */

/* A 1 kg box hangs from a static body on a revolute joint whose force threshold (1 N) is
 * below its weight (10 N): every step lists it, with its public id and user data; a twin
 * with the default threshold never is. */
I2D_TEST(api_joint_events_threshold) {
    g_reports_left = k_report_budget;
    i2d_world_def world_def = i2d_default_world_def();
    const i2d_world_id world = i2d_world_create(&world_def);
    const i2d_body_id anchor = make_box_body(world, I2D_BODY_STATIC, 0.0f, 10.0f);
    i2d_body_id boxes[2];
    i2d_joint_id joints[2];
    const float box_mass = 1.0f; /* density 1 on a 1 m square */
    const float weight = box_mass * 10.0f;
    for (int i = 0; i < 2; ++i) {
        boxes[i] = make_box_body(world, I2D_BODY_DYNAMIC, 5.0f * (float)i, 8.0f);
        i2d_revolute_joint_def def = i2d_default_revolute_joint_def();
        def.base.body_a = anchor;
        def.base.body_b = boxes[i];
        def.base.local_anchor_a = v2(5.0f * (float)i, -1.0f);
        def.base.local_anchor_b = v2(0.0f, 1.0f);
        def.base.user_data = i == 0 ? &k_marker : NULL;
        if (i == 0) {
            def.base.force_threshold = 1.0f;
        }
        joints[i] = i2d_joint_create_revolute(world, &def);
        I2D_REQUIRE(joints[i].bits != 0);
    }
    I2D_CHECK(i2d_world_get_joint_events(world).count == 0);
    const int steps = 30;
    for (int s = 0; s < steps; ++s) {
        I2D_REQUIRE(i2d_world_step(world, k_time_step, k_substeps) == I2D_OK);
    }
    const i2d_joint_events events = i2d_world_get_joint_events(world);
    I2D_CHECK(i2d_last_status() == I2D_OK);
    I2D_REQUIRE(events.count == 1);
    I2D_CHECK(events.events[0].joint.bits == joints[0].bits);
    I2D_CHECK(events.events[0].user_data == &k_marker);
    I2D_CHECK(i2d_joint_is_valid(events.events[0].joint));
    /* The joint holds the box's weight up: the force on B is m g upward. */
    const i2d_vec2 force = i2d_joint_get_reaction_force(joints[0]);
    I2D_CHECK_NEAR(force.y, weight, 0.05 * weight);
    I2D_CHECK_NEAR(force.x, 0.0, 0.05 * weight);
    /* Breaking it between steps is safe, and it is gone from the next step's array. */
    I2D_CHECK_STATUS(i2d_joint_destroy(events.events[0].joint), I2D_OK);
    I2D_REQUIRE(i2d_world_step(world, k_time_step, k_substeps) == I2D_OK);
    I2D_CHECK(i2d_world_get_joint_events(world).count == 0);
    I2D_CHECK(i2d_world_get_joint_count(world) == 1);
    /* A threshold set between steps counts from the next step on. */
    I2D_CHECK_STATUS(i2d_joint_set_force_threshold(joints[1], 1.0f), I2D_OK);
    I2D_REQUIRE(i2d_world_step(world, k_time_step, k_substeps) == I2D_OK);
    const i2d_joint_events later = i2d_world_get_joint_events(world);
    I2D_REQUIRE(later.count == 1);
    I2D_CHECK(later.events[0].joint.bits == joints[1].bits);
    i2d_world_destroy(world);
}
