/* SPDX-License-Identifier: MIT */
/* C API bad input, part 2: setters, forces and impulses, steps, queries, overflow, calls
 * from inside query callbacks, and the world-free functions of collision.h. Every refusal
 * of capi.md answers its status with a message and leaves the world as it was (the
 * fixture and snapshots of test_api_errors.h). */
#include "test_api_errors.h"

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

/* ---- Setters, forces and impulses with non-finite or out-of-range values ------------- */

/* A call with one argument replaced by `value`; every other argument is valid. */
typedef i2d_status (*float_call)(const fixture* f, float value);

typedef struct float_call_row {
    const char* name;
    float_call call;
} float_call_row;

static i2d_vec2 ball_position(const fixture* f) { return i2d_body_get_position(f->body[FIX_BALL]); }

static i2d_status call_gravity_x(const fixture* f, float v) { return i2d_world_set_gravity(f->world, v2(v, -10.0f)); }
static i2d_status call_gravity_y(const fixture* f, float v) { return i2d_world_set_gravity(f->world, v2(0.0f, v)); }
static i2d_status call_shift_x(const fixture* f, float v) { return i2d_world_shift_origin(f->world, v2(v, 1.0f)); }
static i2d_status call_shift_y(const fixture* f, float v) { return i2d_world_shift_origin(f->world, v2(1.0f, v)); }
static i2d_status call_transform_px(const fixture* f, float v) {
    return i2d_body_set_transform(f->body[FIX_BALL], v2(v, 1.0f), rot(1.0f, 0.0f));
}
static i2d_status call_transform_py(const fixture* f, float v) {
    return i2d_body_set_transform(f->body[FIX_BALL], v2(1.0f, v), rot(0.0f, 1.0f));
}
static i2d_status call_transform_qc(const fixture* f, float v) {
    return i2d_body_set_transform(f->body[FIX_BALL], ball_position(f), rot(v, 0.0f));
}
static i2d_status call_transform_qs(const fixture* f, float v) {
    return i2d_body_set_transform(f->body[FIX_BALL], ball_position(f), rot(0.0f, v));
}
/* Static bodies can be teleported and turned too: checked the same way. */
static i2d_status call_static_transform_qs(const fixture* f, float v) {
    return i2d_body_set_transform(f->body[FIX_GROUND], v2(0.0f, -1.0f), rot(0.6f, v));
}
static i2d_status call_velocity_x(const fixture* f, float v) {
    return i2d_body_set_linear_velocity(f->body[FIX_BALL], v2(v, 0.0f));
}
static i2d_status call_velocity_y(const fixture* f, float v) {
    return i2d_body_set_linear_velocity(f->body[FIX_BALL], v2(0.0f, v));
}
/* Documented: ignored for static bodies but still checked. */
static i2d_status call_static_velocity_x(const fixture* f, float v) {
    return i2d_body_set_linear_velocity(f->body[FIX_GROUND], v2(v, 0.0f));
}
static i2d_status call_kinematic_velocity_y(const fixture* f, float v) {
    return i2d_body_set_linear_velocity(f->body[FIX_MOVER], v2(0.0f, v));
}
static i2d_status call_angular_velocity(const fixture* f, float v) {
    return i2d_body_set_angular_velocity(f->body[FIX_BALL], v);
}
/* Documented: ignored for static bodies but still checked. */
static i2d_status call_static_angular_velocity(const fixture* f, float v) {
    return i2d_body_set_angular_velocity(f->body[FIX_GROUND], v);
}
static i2d_status call_kinematic_angular_velocity(const fixture* f, float v) {
    return i2d_body_set_angular_velocity(f->body[FIX_MOVER], v);
}
static i2d_status call_force_x(const fixture* f, float v) {
    return i2d_body_apply_force(f->body[FIX_BALL], v2(v, 0.0f), ball_position(f), true);
}
static i2d_status call_force_y(const fixture* f, float v) {
    return i2d_body_apply_force(f->body[FIX_BALL], v2(0.0f, v), ball_position(f), true);
}
static i2d_status call_force_point_x(const fixture* f, float v) {
    return i2d_body_apply_force(f->body[FIX_BALL], v2(5.0f, 5.0f), v2(v, 0.0f), true);
}
static i2d_status call_force_point_y(const fixture* f, float v) {
    return i2d_body_apply_force(f->body[FIX_BALL], v2(5.0f, 5.0f), v2(0.0f, v), false);
}
static i2d_status call_force_to_center_x(const fixture* f, float v) {
    return i2d_body_apply_force_to_center(f->body[FIX_BALL], v2(v, 1.0f), true);
}
static i2d_status call_force_to_center_y(const fixture* f, float v) {
    return i2d_body_apply_force_to_center(f->body[FIX_BALL], v2(1.0f, v), false);
}
static i2d_status call_static_force_to_center(const fixture* f, float v) {
    return i2d_body_apply_force_to_center(f->body[FIX_GROUND], v2(v, 1.0f), true);
}
static i2d_status call_torque(const fixture* f, float v) { return i2d_body_apply_torque(f->body[FIX_BALL], v, true); }
static i2d_status call_torque_no_wake(const fixture* f, float v) {
    return i2d_body_apply_torque(f->body[FIX_BALL], v, false);
}
static i2d_status call_static_torque(const fixture* f, float v) {
    return i2d_body_apply_torque(f->body[FIX_GROUND], v, true);
}
static i2d_status call_kinematic_torque(const fixture* f, float v) {
    return i2d_body_apply_torque(f->body[FIX_MOVER], v, true);
}
static i2d_status call_impulse_x(const fixture* f, float v) {
    return i2d_body_apply_linear_impulse(f->body[FIX_BALL], v2(v, 0.0f), ball_position(f), true);
}
static i2d_status call_impulse_y(const fixture* f, float v) {
    return i2d_body_apply_linear_impulse(f->body[FIX_BALL], v2(0.0f, v), ball_position(f), true);
}
static i2d_status call_impulse_point_x(const fixture* f, float v) {
    return i2d_body_apply_linear_impulse(f->body[FIX_BALL], v2(5.0f, 5.0f), v2(v, 0.0f), true);
}
static i2d_status call_impulse_point_y(const fixture* f, float v) {
    return i2d_body_apply_linear_impulse(f->body[FIX_BALL], v2(5.0f, 5.0f), v2(0.0f, v), false);
}
static i2d_status call_angular_impulse(const fixture* f, float v) {
    return i2d_body_apply_angular_impulse(f->body[FIX_BALL], v, true);
}
static i2d_status call_angular_impulse_no_wake(const fixture* f, float v) {
    return i2d_body_apply_angular_impulse(f->body[FIX_BALL], v, false);
}
static i2d_status call_kinematic_angular_impulse(const fixture* f, float v) {
    return i2d_body_apply_angular_impulse(f->body[FIX_MOVER], v, true);
}
static i2d_status call_friction(const fixture* f, float v) {
    return i2d_shape_set_friction(f->shape[FIX_BALL_CIRCLE], v);
}
static i2d_status call_restitution(const fixture* f, float v) {
    return i2d_shape_set_restitution(f->shape[FIX_BALL_BOX], v);
}
static i2d_status call_capsule_friction(const fixture* f, float v) {
    return i2d_shape_set_friction(f->shape[FIX_MOVER_CAPSULE], v);
}
static i2d_status call_segment_restitution(const fixture* f, float v) {
    return i2d_shape_set_restitution(f->shape[FIX_GROUND_SEGMENT], v);
}
static i2d_status call_step_time(const fixture* f, float v) { return i2d_world_step(f->world, v, 4); }

static const float_call_row k_float_calls[] = {
    {"i2d_world_set_gravity gravity.x", call_gravity_x},
    {"i2d_world_set_gravity gravity.y", call_gravity_y},
    {"i2d_world_shift_origin new_origin.x", call_shift_x},
    {"i2d_world_shift_origin new_origin.y", call_shift_y},
    {"i2d_body_set_transform position.x", call_transform_px},
    {"i2d_body_set_transform position.y", call_transform_py},
    {"i2d_body_set_transform rotation.c", call_transform_qc},
    {"i2d_body_set_transform rotation.s", call_transform_qs},
    {"i2d_body_set_transform rotation.s (static body)", call_static_transform_qs},
    {"i2d_body_set_linear_velocity v.x", call_velocity_x},
    {"i2d_body_set_linear_velocity v.y", call_velocity_y},
    {"i2d_body_set_linear_velocity v.x (static body)", call_static_velocity_x},
    {"i2d_body_set_linear_velocity v.y (kinematic body)", call_kinematic_velocity_y},
    {"i2d_body_set_angular_velocity", call_angular_velocity},
    {"i2d_body_set_angular_velocity (static body)", call_static_angular_velocity},
    {"i2d_body_set_angular_velocity (kinematic body)", call_kinematic_angular_velocity},
    {"i2d_body_apply_force force.x", call_force_x},
    {"i2d_body_apply_force force.y", call_force_y},
    {"i2d_body_apply_force point.x", call_force_point_x},
    {"i2d_body_apply_force point.y", call_force_point_y},
    {"i2d_body_apply_force_to_center force.x", call_force_to_center_x},
    {"i2d_body_apply_force_to_center force.y", call_force_to_center_y},
    {"i2d_body_apply_force_to_center force.x (static body)", call_static_force_to_center},
    {"i2d_body_apply_torque", call_torque},
    {"i2d_body_apply_torque (wake false)", call_torque_no_wake},
    {"i2d_body_apply_torque (static body)", call_static_torque},
    {"i2d_body_apply_torque (kinematic body)", call_kinematic_torque},
    {"i2d_body_apply_linear_impulse impulse.x", call_impulse_x},
    {"i2d_body_apply_linear_impulse impulse.y", call_impulse_y},
    {"i2d_body_apply_linear_impulse point.x", call_impulse_point_x},
    {"i2d_body_apply_linear_impulse point.y", call_impulse_point_y},
    {"i2d_body_apply_angular_impulse", call_angular_impulse},
    {"i2d_body_apply_angular_impulse (wake false)", call_angular_impulse_no_wake},
    {"i2d_body_apply_angular_impulse (kinematic body)", call_kinematic_angular_impulse},
    {"i2d_shape_set_friction", call_friction},
    {"i2d_shape_set_friction (capsule)", call_capsule_friction},
    {"i2d_shape_set_restitution", call_restitution},
    {"i2d_shape_set_restitution (segment)", call_segment_restitution},
    {"i2d_world_step time_step", call_step_time},
};

typedef struct float_call_value {
    const char* name;
    float_call call;
    float value;
} float_call_value;

/* Finite values outside the documented ranges. (Any finite angular velocity, torque and
 * angular impulse is in range.) */
static const float_call_value k_out_of_range_calls[] = {
    {"i2d_world_shift_origin new_origin.x", call_shift_x, 2e9f},
    {"i2d_world_shift_origin new_origin.y", call_shift_y, -1.5e9f},
    {"i2d_body_set_transform position.x", call_transform_px, 2e9f},
    {"i2d_body_set_transform position.y", call_transform_py, -2e9f},
    {"i2d_body_set_transform rotation.c (c = 1.01, s = 0)", call_transform_qc, 1.01f},
    {"i2d_body_set_transform rotation.s (c = 0, s = -2)", call_transform_qs, -2.0f},
    {"i2d_body_set_transform rotation.c (zero rotation)", call_transform_qc, 0.0f},
    {"i2d_body_set_transform rotation.s (static body, (0.6, 0.6))", call_static_transform_qs, 0.6f},
    {"i2d_body_apply_force point.x", call_force_point_x, 2e9f},
    {"i2d_body_apply_linear_impulse point.y", call_impulse_point_y, -2e9f},
    {"i2d_shape_set_friction", call_friction, -0.5f},
    {"i2d_shape_set_friction", call_friction, -1e-30f},
    {"i2d_shape_set_friction (capsule)", call_capsule_friction, -1.0f},
    {"i2d_shape_set_restitution", call_restitution, -0.5f},
    {"i2d_shape_set_restitution", call_restitution, 100.5f},
    {"i2d_shape_set_restitution (segment)", call_segment_restitution, -0.1f},
    {"i2d_world_step time_step", call_step_time, -1.0f / 60.0f},
    {"i2d_world_step time_step", call_step_time, -1e-30f},
    {"i2d_world_step time_step", call_step_time, 1001.0f},
};

static void run_setters_refused(const fixture* a, const fixture* b) {
    static snapshot before, twin;
    snapshot_take(a, &before);
    snapshot_take(b, &twin);
    CHECK_SAME_SNAPSHOT("building the twins", &twin, &before);
    char what[160];
    for (size_t i = 0; i < sizeof k_float_calls / sizeof k_float_calls[0]; ++i) {
        for (int k = 0; k < NON_FINITE_COUNT; ++k) {
            i2d_status status = k_float_calls[i].call(a, k_non_finite[k]);
            snprintf(what, sizeof what, "%s = %g", k_float_calls[i].name, k_non_finite[k]);
            CHECK_REFUSED(what, status, I2D_ERR_INVALID_ARGUMENT);
            CHECK_UNCHANGED(what, a, &before);
        }
    }
    for (size_t i = 0; i < sizeof k_out_of_range_calls / sizeof k_out_of_range_calls[0]; ++i) {
        i2d_status status = k_out_of_range_calls[i].call(a, k_out_of_range_calls[i].value);
        snprintf(what, sizeof what, "%s = %g", k_out_of_range_calls[i].name, k_out_of_range_calls[i].value);
        CHECK_REFUSED(what, status, I2D_ERR_INVALID_ARGUMENT);
        CHECK_UNCHANGED(what, a, &before);
    }
    /* Rotations that are not unit length within 1e-3, on a dynamic, a static and a
     * kinematic body. */
    for (int i = 0; i < k_bad_rotation_count; ++i) {
        const i2d_rot q = rot(k_bad_rotations[i].c, k_bad_rotations[i].s);
        for (int body = 0; body < FIX_BODIES; ++body) {
            i2d_status status = i2d_body_set_transform(a->body[body], v2(2.0f, 3.0f), q);
            snprintf(what, sizeof what, "i2d_body_set_transform (body %d) rotation %s", body, k_bad_rotations[i].name);
            CHECK_REFUSED(what, status, I2D_ERR_INVALID_ARGUMENT);
            CHECK_UNCHANGED(what, a, &before);
        }
    }
    /* A bad rotation with a good position, a good rotation with a bad position. */
    CHECK_REFUSED("i2d_body_set_transform(NaN position, make_rot(0.3))",
                  i2d_body_set_transform(a->body[FIX_BALL], v2(NAN, 0.0f), i2d_make_rot(0.3f)),
                  I2D_ERR_INVALID_ARGUMENT);
    CHECK_UNCHANGED("i2d_body_set_transform(NaN position, make_rot(0.3))", a, &before);
    /* A static body neither sleeps nor wakes. */
    CHECK_REFUSED("i2d_body_set_awake(static, false)", i2d_body_set_awake(a->body[FIX_GROUND], false),
                  I2D_ERR_INVALID_ARGUMENT);
    CHECK_UNCHANGED("i2d_body_set_awake(static, false)", a, &before);
    CHECK_REFUSED("i2d_body_set_awake(static, true)", i2d_body_set_awake(a->body[FIX_GROUND], true),
                  I2D_ERR_INVALID_ARGUMENT);
    CHECK_UNCHANGED("i2d_body_set_awake(static, true)", a, &before);
    /* A body type outside the enumeration (C code can pass any integer). */
    {
        const int bad_types[] = {-1, 3, 7, 1 << 20};
        for (int i = 0; i < 4; ++i) {
            i2d_body_type bad;
            memcpy(&bad, &bad_types[i], sizeof bad);
            snprintf(what, sizeof what, "i2d_body_set_type(ball, %d)", bad_types[i]);
            CHECK_REFUSED(what, i2d_body_set_type(a->body[FIX_BALL], bad), I2D_ERR_INVALID_ARGUMENT);
            CHECK_UNCHANGED(what, a, &before);
        }
    }
    check_twins_agree_after_steps(a, b);
}

I2D_TEST(api_errors_setters_bad_values) { run_on_twins(run_setters_refused); }

/* Any finite angular velocity is accepted; spins beyond 1e5 rad/s are clamped to it where
 * they enter (a finite 1e30 once became NaN within a step). */
static const float k_spins[] = {0.0f, -0.0f, 1.0f, -1e-3f, 100.0f, -1e6f, FLT_MAX, -FLT_MAX};
enum { SPIN_COUNT = sizeof k_spins / sizeof k_spins[0] };
static const float k_max_spin = 1.0e5f;

static float stored_spin(float w) { return w > k_max_spin ? k_max_spin : (w < -k_max_spin ? -k_max_spin : w); }

/* Angular velocities are stored for bodies that can turn and ignored (but accepted) for
 * static and fixed-rotation ones; unit rotations within 1e-3 are accepted and stored
 * normalised, and the shapes turn with the body. */
static void run_setter_edges_accepted(const fixture* f) {
    i2d_body_id ball = f->body[FIX_BALL], mover = f->body[FIX_MOVER], ground = f->body[FIX_GROUND];
    i2d_body_def def = i2d_default_body_def();
    def.type = I2D_BODY_DYNAMIC;
    def.position = v2(20.0f, 5.0f);
    def.fixed_rotation = true;
    i2d_body_id fixed = i2d_body_create(f->world, &def);
    i2d_shape_def shape_def = i2d_default_shape_def();
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_box(fixed, &shape_def, 0.5f, 0.5f)));
    char what[160];
    for (int i = 0; i < SPIN_COUNT; ++i) {
        const float w = k_spins[i];
        snprintf(what, sizeof what, "i2d_body_set_angular_velocity(dynamic ball, %g)", w);
        CHECK_ACCEPTED(what, i2d_body_set_angular_velocity(ball, w));
        I2D_CHECK(i2d_body_get_angular_velocity(ball) == stored_spin(w));
        snprintf(what, sizeof what, "i2d_body_set_angular_velocity(kinematic mover, %g)", w);
        CHECK_ACCEPTED(what, i2d_body_set_angular_velocity(mover, w));
        I2D_CHECK(i2d_body_get_angular_velocity(mover) == stored_spin(w));
        snprintf(what, sizeof what, "i2d_body_set_angular_velocity(static ground, %g)", w);
        CHECK_ACCEPTED(what, i2d_body_set_angular_velocity(ground, w));
        I2D_CHECK(i2d_body_get_angular_velocity(ground) == 0.0f);
        snprintf(what, sizeof what, "i2d_body_set_angular_velocity(fixed-rotation body, %g)", w);
        CHECK_ACCEPTED(what, i2d_body_set_angular_velocity(fixed, w));
        I2D_CHECK(i2d_body_get_angular_velocity(fixed) == 0.0f);
    }
    /* Torques and angular impulses of any finite size are accepted too. */
    CHECK_ACCEPTED("i2d_body_set_angular_velocity(ball, 0)", i2d_body_set_angular_velocity(ball, 0.0f));
    CHECK_ACCEPTED("i2d_body_apply_torque(ball, -1e30)", i2d_body_apply_torque(ball, -1e30f, true));
    CHECK_ACCEPTED("i2d_body_apply_torque(ground, 1e30)", i2d_body_apply_torque(ground, 1e30f, true));
    CHECK_ACCEPTED("i2d_body_apply_angular_impulse(ball, 0)", i2d_body_apply_angular_impulse(ball, 0.0f, true));
    CHECK_ACCEPTED("i2d_body_apply_angular_impulse(fixed, 1e30)", i2d_body_apply_angular_impulse(fixed, 1e30f, true));
    I2D_CHECK(i2d_body_get_angular_velocity(fixed) == 0.0f);
    CHECK_ACCEPTED("i2d_body_apply_angular_impulse(mover, 5)", i2d_body_apply_angular_impulse(mover, 5.0f, true));
    I2D_CHECK(i2d_body_get_angular_velocity(mover) == stored_spin(k_spins[SPIN_COUNT - 1])); /* kinematic: infinite inertia */

    for (int i = 0; i < k_unit_rotation_count; ++i) {
        const float x = 2.0f + (float)i;
        for (int body = 0; body < FIX_BODIES; ++body) {
            i2d_status status =
                i2d_body_set_transform(f->body[body], v2(x, 3.0f), rot(k_unit_rotations[i].c, k_unit_rotations[i].s));
            snprintf(what, sizeof what, "i2d_body_set_transform (body %d) rotation %s", body, k_unit_rotations[i].name);
            check_accepted_at(__FILE__, __LINE__, what, status);
            i2d_vec2 p = i2d_body_get_position(f->body[body]);
            I2D_CHECK(p.x == x && p.y == 3.0f);
            check_stored_rotation_at(__FILE__, __LINE__, what, i2d_body_get_rotation(f->body[body]),
                                     k_unit_rotations[i].c, k_unit_rotations[i].s);
        }
    }
    /* A quarter turn carries the ball's circle, at (0.3, 0) in the body frame, to
     * (0, 0.3) from the body origin. */
    CHECK_ACCEPTED("i2d_body_set_transform(ball, (1, 2), quarter turn)",
                   i2d_body_set_transform(ball, v2(1.0f, 2.0f), rot(0.0f, 1.0f)));
    i2d_aabb bounds = i2d_shape_get_aabb(f->shape[FIX_BALL_CIRCLE]);
    I2D_CHECK_NEAR(0.5 * (bounds.min.x + bounds.max.x), 1.0, 1e-6);
    I2D_CHECK_NEAR(0.5 * (bounds.min.y + bounds.max.y), 2.3, 1e-6);
    CHECK_ACCEPTED("i2d_body_set_transform(ball, make_rot(0.3))",
                   i2d_body_set_transform(ball, v2(1.0f, 2.0f), i2d_make_rot(0.3f)));
    i2d_rot q = i2d_body_get_rotation(ball);
    I2D_CHECK_NEAR(q.c, cos(0.3), 1e-6);
    I2D_CHECK_NEAR(q.s, sin(0.3), 1e-6);
}

I2D_TEST(api_errors_setter_edges_accepted) { run_on_fixture(run_setter_edges_accepted); }

/* ---- Body frame getters with bad points --------------------------------------------- */

typedef i2d_vec2 (*point_getter)(i2d_body_id body, i2d_vec2 point);

typedef struct point_getter_row {
    const char* name;
    point_getter get;
} point_getter_row;

static const point_getter_row k_point_getters[] = {
    {"i2d_body_get_world_point", i2d_body_get_world_point},
    {"i2d_body_get_local_point", i2d_body_get_local_point},
    {"i2d_body_get_world_point_velocity", i2d_body_get_world_point_velocity},
};

/* NaN, infinite and far points: refused with the zero vector, nothing changed. */
static void run_point_getters(const fixture* f) {
    static snapshot before;
    snapshot_take(f, &before);
    static const float bad[] = {NAN, INFINITY, -INFINITY, 2e9f, -1e30f};
    char what[160];
    for (size_t g = 0; g < sizeof k_point_getters / sizeof k_point_getters[0]; ++g) {
        for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
            for (int axis = 0; axis < 2; ++axis) {
                i2d_vec2 point = axis == 0 ? v2(bad[k], 1.0f) : v2(1.0f, bad[k]);
                i2d_vec2 out = k_point_getters[g].get(f->body[FIX_BALL], point);
                snprintf(what, sizeof what, "%s(ball, (%g, %g))", k_point_getters[g].name, point.x, point.y);
                CHECK_REFUSED(what, i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
                I2D_CHECK(out.x == 0.0f && out.y == 0.0f);
            }
        }
        /* A good point answers (the moving mover gives non-zero answers everywhere). */
        i2d_vec2 out = k_point_getters[g].get(f->body[FIX_MOVER], v2(1.0f, 1.0f));
        snprintf(what, sizeof what, "%s(mover, (1, 1))", k_point_getters[g].name);
        CHECK_ACCEPTED(what, i2d_last_status());
        I2D_CHECK(out.x != 0.0f || out.y != 0.0f);
    }
    CHECK_UNCHANGED("the body frame getters", f, &before);
}

I2D_TEST(api_errors_point_getters_bad_input) { run_on_fixture(run_point_getters); }

/* ---- Steps -------------------------------------------------------------------------- */

static void run_step_bad_values(const fixture* a, const fixture* b) {
    static snapshot before;
    snapshot_take(a, &before);
    char what[128];
    static const int32_t bad_substeps[] = {0, -1, 1001, INT32_MIN, INT32_MAX};
    for (size_t i = 0; i < sizeof bad_substeps / sizeof bad_substeps[0]; ++i) {
        snprintf(what, sizeof what, "i2d_world_step substep_count = %d", (int)bad_substeps[i]);
        CHECK_REFUSED(what, i2d_world_step(a->world, 1.0f / 60.0f, bad_substeps[i]), I2D_ERR_INVALID_ARGUMENT);
        CHECK_UNCHANGED(what, a, &before);
    }
    /* Both arguments bad at once. */
    CHECK_REFUSED("i2d_world_step(NaN, 0)", i2d_world_step(a->world, NAN, 0), I2D_ERR_INVALID_ARGUMENT);
    CHECK_UNCHANGED("i2d_world_step(NaN, 0)", a, &before);

    /* A zero time step is accepted and does nothing: the spinning mover does not turn. */
    CHECK_ACCEPTED("i2d_world_step(0, 4)", i2d_world_step(a->world, 0.0f, 4));
    CHECK_UNCHANGED("i2d_world_step(0, 4)", a, &before);
    check_twins_agree_after_steps(a, b);

    /* The edges of the substep range are accepted. */
    CHECK_ACCEPTED("i2d_world_step(1/60, 1)", i2d_world_step(a->world, 1.0f / 60.0f, 1));
    CHECK_ACCEPTED("i2d_world_step(1/60, 1000)", i2d_world_step(a->world, 1.0f / 60.0f, 1000));
}

I2D_TEST(api_errors_step_bad_values) { run_on_twins(run_step_bad_values); }

/* ---- Queries ------------------------------------------------------------------------ */

static bool count_shape(i2d_shape_id shape, void* context) {
    (void)shape;
    ++*(int*)context;
    return true;
}

static void run_query_bad_arguments(const fixture* f) {
    static snapshot before;
    snapshot_take(f, &before);
    const i2d_query_filter filter = i2d_default_query_filter();
    const i2d_aabb everything = box(-100.0f, -100.0f, 100.0f, 100.0f);
    i2d_shape_id out[8];
    char what[160];
    int calls = 0;

    CHECK_REFUSED("i2d_world_overlap_aabb with NULL fn",
                  i2d_world_overlap_aabb(f->world, everything, filter, NULL, &calls), I2D_ERR_INVALID_ARGUMENT);
    CHECK_REFUSED("i2d_world_overlap_point with NULL fn",
                  i2d_world_overlap_point(f->world, v2(0.0f, 0.0f), filter, NULL, &calls), I2D_ERR_INVALID_ARGUMENT);

    i2d_aabb bad[32];
    int bad_count = 0;
    bad_aabbs(bad, &bad_count);
    for (int i = 0; i < bad_count; ++i) {
        snprintf(what, sizeof what, "aabb (%g, %g)-(%g, %g)", bad[i].min.x, bad[i].min.y, bad[i].max.x, bad[i].max.y);
        calls = 0;
        CHECK_REFUSED(what, i2d_world_overlap_aabb(f->world, bad[i], filter, count_shape, &calls),
                      I2D_ERR_INVALID_ARGUMENT);
        I2D_CHECK(calls == 0);
        out[0].bits = 12345;
        int32_t n = i2d_world_overlap_aabb_ids(f->world, bad[i], filter, out, 8);
        CHECK_REFUSED(what, i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
        I2D_CHECK(n == -1);
        I2D_CHECK(out[0].bits == 12345); /* nothing written */
    }
    for (int axis = 0; axis < 2; ++axis) {
        for (int k = 0; k < NON_FINITE_COUNT; ++k) {
            i2d_vec2 point = axis == 0 ? v2(k_non_finite[k], 0.0f) : v2(0.0f, k_non_finite[k]);
            snprintf(what, sizeof what, "i2d_world_overlap_point (%g, %g)", point.x, point.y);
            calls = 0;
            CHECK_REFUSED(what, i2d_world_overlap_point(f->world, point, filter, count_shape, &calls),
                          I2D_ERR_INVALID_ARGUMENT);
            I2D_CHECK(calls == 0);
        }
    }

    /* Output buffers for the FFI variant: negative capacity, NULL out with capacity. */
    int32_t n = i2d_world_overlap_aabb_ids(f->world, everything, filter, out, -1);
    CHECK_REFUSED("i2d_world_overlap_aabb_ids capacity -1", i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(n == -1);
    n = i2d_world_overlap_aabb_ids(f->world, everything, filter, NULL, 4);
    CHECK_REFUSED("i2d_world_overlap_aabb_ids NULL out, capacity 4", i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(n == -1);
    /* NULL with capacity 0 is how a caller sizes its buffer: it returns the total. */
    n = i2d_world_overlap_aabb_ids(f->world, everything, filter, NULL, 0);
    CHECK_ACCEPTED("i2d_world_overlap_aabb_ids NULL out, capacity 0", i2d_last_status());
    I2D_CHECK(n == FIX_SHAPES);

    /* Rays with a bad origin or translation hit nothing and say why. */
    for (int field = 0; field < 4; ++field) {
        for (int k = 0; k < NON_FINITE_COUNT; ++k) {
            i2d_vec2 origin = v2(0.0f, 5.0f);
            i2d_vec2 translation = v2(0.0f, -10.0f);
            float* slot[4] = {&origin.x, &origin.y, &translation.x, &translation.y};
            *slot[field] = k_non_finite[k];
            i2d_ray_result r = i2d_world_cast_ray_closest(f->world, origin, translation, filter);
            snprintf(what, sizeof what, "i2d_world_cast_ray_closest origin (%g, %g) translation (%g, %g)", origin.x,
                     origin.y, translation.x, translation.y);
            CHECK_REFUSED(what, i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
            I2D_CHECK(!r.hit);
            I2D_CHECK(I2D_IS_NULL(r.shape));
        }
    }
    CHECK_UNCHANGED("the refused queries", f, &before);

    /* The same ray with valid input does hit the ground, so the refusals are about the input. */
    i2d_ray_result r = i2d_world_cast_ray_closest(f->world, v2(10.0f, 5.0f), v2(0.0f, -10.0f), filter);
    CHECK_ACCEPTED("i2d_world_cast_ray_closest valid", i2d_last_status());
    I2D_CHECK(r.hit && I2D_ID_EQUALS(r.shape, f->shape[FIX_GROUND_BOX]));
}

I2D_TEST(api_errors_query_bad_arguments) { run_on_fixture(run_query_bad_arguments); }

/* ---- The casts' translation bound: its length, as documented ---------------------- */

/* Every cast refuses a translation longer than 1e9 m, however it is split between x and
 * y, and takes one exactly that long. */
typedef struct cast_translation_row {
    float x, y;
    bool accepted;
} cast_translation_row;

static const cast_translation_row k_cast_translations[] = {
    {1.0e9f, 1.0e9f, false},  /* 1.41e9 m */
    {7.1e8f, 7.1e8f, false},  /* 1.004e9 m, though each component is within 1e9 */
    {-7.1e8f, 7.1e8f, false},
    {1.0e9f, 0.0f, true},     /* exactly the bound */
    {0.0f, -1.0e9f, true},
};
enum { CAST_TRANSLATION_COUNT = sizeof k_cast_translations / sizeof k_cast_translations[0] };

static float count_cast_hit(i2d_shape_id shape, i2d_vec2 point, i2d_vec2 normal, float fraction, void* context) {
    (void)shape, (void)point, (void)normal, (void)fraction;
    ++*(int*)context;
    return 1.0f;
}

/* The call just made answered as the row says; a refusal names the field and the limit. */
static void check_cast_translation_answer(const char* what, i2d_status returned, bool accepted) {
    if (accepted) {
        CHECK_ACCEPTED(what, returned);
        return;
    }
    char message[256];
    copy_message(message, sizeof message, i2d_last_error_message());
    CHECK_REFUSED(what, returned, I2D_ERR_INVALID_ARGUMENT);
    if (strstr(message, "translation") == NULL || strstr(message, "1e+09") == NULL) {
        ++i2d_check_failures;
        fprintf(stderr, "%s: the message \"%s\" does not name both the field and the limit\n", what, message);
    }
}

static void run_cast_translation_bound(const fixture* f) {
    static snapshot before;
    snapshot_take(f, &before);
    const i2d_query_filter filter = i2d_default_query_filter();
    const i2d_vec2 origin = v2(0.0f, 50.0f);
    const i2d_shape_proxy ball = i2d_make_proxy(&origin, 1, 0.25f);
    I2D_REQUIRE(ball.count == 1);
    char what[160];
    for (int i = 0; i < CAST_TRANSLATION_COUNT; ++i) {
        const cast_translation_row row = k_cast_translations[i];
        const i2d_vec2 t = v2(row.x, row.y);
        int calls = 0;
        snprintf(what, sizeof what, "i2d_world_cast_shape translation (%g, %g)", t.x, t.y);
        check_cast_translation_answer(what, i2d_world_cast_shape(f->world, &ball, t, filter, count_cast_hit, &calls),
                                      row.accepted);
        snprintf(what, sizeof what, "i2d_world_cast_shape_closest translation (%g, %g)", t.x, t.y);
        const i2d_ray_result shape_hit = i2d_world_cast_shape_closest(f->world, &ball, t, filter);
        check_cast_translation_answer(what, i2d_last_status(), row.accepted);
        snprintf(what, sizeof what, "i2d_world_cast_ray translation (%g, %g)", t.x, t.y);
        check_cast_translation_answer(what, i2d_world_cast_ray(f->world, origin, t, filter, count_cast_hit, &calls),
                                      row.accepted);
        snprintf(what, sizeof what, "i2d_world_cast_ray_closest translation (%g, %g)", t.x, t.y);
        const i2d_ray_result ray_hit = i2d_world_cast_ray_closest(f->world, origin, t, filter);
        check_cast_translation_answer(what, i2d_last_status(), row.accepted);
        snprintf(what, sizeof what, "i2d_world_cast_ray_all translation (%g, %g)", t.x, t.y);
        const int32_t all = i2d_world_cast_ray_all(f->world, origin, t, filter, NULL, 0);
        check_cast_translation_answer(what, i2d_last_status(), row.accepted);
        if (!row.accepted) {
            I2D_CHECK(calls == 0 && !shape_hit.hit && !ray_hit.hit && all == -1);
        }
    }
    CHECK_UNCHANGED("the casts with long translations", f, &before);
}

I2D_TEST(api_errors_cast_translation_bound_is_a_length) { run_on_fixture(run_cast_translation_bound); }

/* ---- Overflow of accumulated forces, torques and velocities ------------------------- */

/* Forces accumulate until the step. The accumulated force is not observable directly,
 * so the test cancels it: after F accepted and F refused, -F must bring the total back to
 * exactly 0, which a step then shows as a body that does not move. Had the refused call
 * left anything behind (inf, a clamped FLT_MAX), the total would not cancel. */
static void run_force_overflow(i2d_world_id world) {
    i2d_body_def body_def = i2d_default_body_def();
    body_def.type = I2D_BODY_DYNAMIC;
    i2d_body_id body = i2d_body_create(world, &body_def); /* no shapes: 1 kg */
    I2D_REQUIRE(!I2D_IS_NULL(body));
    I2D_CHECK(i2d_body_get_mass(body) == 1.0f);

    const i2d_vec2 origin = v2(0.0f, 0.0f);
    CHECK_ACCEPTED("first force 3e38", i2d_body_apply_force(body, v2(3e38f, 0.0f), origin, true));
    /* 3e38 + 3e38 overflows to inf: refused, and the first force is kept as it was. */
    CHECK_REFUSED("second force 3e38", i2d_body_apply_force(body, v2(3e38f, 0.0f), origin, true),
                  I2D_ERR_INVALID_ARGUMENT);
    CHECK_REFUSED("second force 3e38 to the centre", i2d_body_apply_force_to_center(body, v2(3e38f, 0.0f), true),
                  I2D_ERR_INVALID_ARGUMENT);
    CHECK_ACCEPTED("first force -3e38 on y", i2d_body_apply_force_to_center(body, v2(0.0f, -3e38f), true));
    CHECK_REFUSED("second force -3e38 on y", i2d_body_apply_force(body, v2(0.0f, -3e38f), origin, true),
                  I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_body_get_linear_velocity(body).x == 0.0f); /* forces act at the step */

    CHECK_ACCEPTED("cancelling force", i2d_body_apply_force(body, v2(-3e38f, 3e38f), origin, true));
    I2D_CHECK_STATUS(i2d_world_step(world, 1.0f / 60.0f, 1), I2D_OK);
    i2d_vec2 v = i2d_body_get_linear_velocity(body);
    i2d_vec2 p = i2d_body_get_position(body);
    I2D_CHECK(v.x == 0.0f && v.y == 0.0f);
    I2D_CHECK(p.x == 0.0f && p.y == 0.0f);

    /* Forces do act on this body: 120 N on 1 kg for 1/60 s adds 2 m/s. */
    CHECK_ACCEPTED("force 120 N", i2d_body_apply_force(body, v2(120.0f, 0.0f), origin, true));
    I2D_CHECK_STATUS(i2d_world_step(world, 1.0f / 60.0f, 1), I2D_OK);
    I2D_CHECK_NEAR(i2d_body_get_linear_velocity(body).x, 2.0, 1e-5);
}

I2D_TEST(api_errors_force_overflow) { run_in_world(0.0f, run_force_overflow); }

/* A unit box of density 1 at the origin: m = 1 kg, I = m (1 + 1) / 12 = 1/6 kg m^2. */
static i2d_body_id unit_box_body(i2d_world_id world) {
    i2d_body_def body_def = i2d_default_body_def();
    body_def.type = I2D_BODY_DYNAMIC;
    i2d_body_id body = i2d_body_create(world, &body_def);
    i2d_shape_def shape_def = i2d_default_shape_def();
    if (I2D_IS_NULL(i2d_shape_create_box(body, &shape_def, 0.5f, 0.5f))) {
        return I2D_NULL_BODY_ID;
    }
    return body;
}

/* Torques accumulate like forces; the same cancelling shows that a refused torque (or a
 * force whose torque about the centre overflows) left nothing behind. */
static void run_torque_overflow(i2d_world_id world) {
    i2d_body_id body = unit_box_body(world);
    I2D_REQUIRE(!I2D_IS_NULL(body));
    const double inertia = 1.0 / 6.0;
    I2D_CHECK_NEAR(i2d_body_get_rotational_inertia(body), inertia, 1e-7);
    const float dt = 1.0f / 60.0f;

    CHECK_ACCEPTED("first torque 3e38", i2d_body_apply_torque(body, 3e38f, true));
    CHECK_REFUSED("second torque 3e38", i2d_body_apply_torque(body, 3e38f, true), I2D_ERR_INVALID_ARGUMENT);
    /* A finite force whose lever arm makes the torque overflow: 1e30 N at 1e9 m. */
    CHECK_REFUSED("force 1e30 N at 1e9 m", i2d_body_apply_force(body, v2(0.0f, 1e30f), v2(1e9f, 0.0f), true),
                  I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_body_get_angular_velocity(body) == 0.0f); /* torques act at the step */
    CHECK_ACCEPTED("cancelling torque", i2d_body_apply_torque(body, -3e38f, false));
    I2D_CHECK_STATUS(i2d_world_step(world, dt, 4), I2D_OK);
    I2D_CHECK(i2d_body_get_angular_velocity(body) == 0.0f);
    i2d_vec2 v = i2d_body_get_linear_velocity(body);
    I2D_CHECK(v.x == 0.0f && v.y == 0.0f);
    i2d_rot q = i2d_body_get_rotation(body);
    I2D_CHECK(q.c == 1.0f && q.s == 0.0f);

    /* Torques do act on this body: 1 N m for 1/60 s adds dt / I rad/s. */
    CHECK_ACCEPTED("torque 1 N m", i2d_body_apply_torque(body, 1.0f, true));
    I2D_CHECK_STATUS(i2d_world_step(world, dt, 4), I2D_OK);
    I2D_CHECK_NEAR(i2d_body_get_angular_velocity(body), dt / inertia, 1e-6);
}

I2D_TEST(api_errors_torque_overflow) { run_in_world(0.0f, run_torque_overflow); }

/* An impulse changes the velocity at once, and the result enters within the world's
 * maximum_linear_speed: a huge finite impulse is accepted and clamped (direction kept),
 * one whose velocity change alone overflows float is refused and changes nothing. */
static void run_impulse_overflow(i2d_world_id world) {
    const float max_speed = i2d_default_world_def().maximum_linear_speed;
    i2d_body_def body_def = i2d_default_body_def();
    body_def.type = I2D_BODY_DYNAMIC;
    i2d_body_id body = i2d_body_create(world, &body_def); /* no shapes: 1 kg */
    I2D_REQUIRE(!I2D_IS_NULL(body));
    I2D_CHECK(i2d_body_get_mass(body) == 1.0f);
    const i2d_vec2 origin = v2(0.0f, 0.0f);
    CHECK_ACCEPTED("first impulse 3e38", i2d_body_apply_linear_impulse(body, v2(3e38f, 0.0f), origin, true));
    I2D_CHECK(i2d_body_get_linear_velocity(body).x == max_speed);
    CHECK_ACCEPTED("second impulse 3e38", i2d_body_apply_linear_impulse(body, v2(3e38f, 0.0f), origin, true));
    i2d_vec2 v = i2d_body_get_linear_velocity(body);
    I2D_CHECK(v.x == max_speed && v.y == 0.0f);

    /* A light body: 3e38 N s on 0.01 kg is an infinite velocity change. */
    i2d_body_id light = i2d_body_create(world, &body_def);
    i2d_shape_def shape_def = i2d_default_shape_def();
    shape_def.density = 1.0f;
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_box(light, &shape_def, 0.05f, 0.05f)));
    CHECK_ACCEPTED("velocity -3 on y", i2d_body_set_linear_velocity(light, v2(0.0f, -3.0f)));
    CHECK_REFUSED("impulse -3e38 on y", i2d_body_apply_linear_impulse(light, v2(0.0f, -3e38f), origin, false),
                  I2D_ERR_INVALID_ARGUMENT);
    v = i2d_body_get_linear_velocity(light);
    I2D_CHECK(v.x == 0.0f && v.y == -3.0f);
}

I2D_TEST(api_errors_impulse_overflow) { run_in_world(0.0f, run_impulse_overflow); }

/* The spin overflows too: angular impulses, and linear impulses far from the centre. A
 * refused impulse changes neither velocity. */
static void run_angular_impulse_overflow(i2d_world_id world) {
    i2d_body_id body = unit_box_body(world);
    I2D_REQUIRE(!I2D_IS_NULL(body));
    /* J / I = 6 J: 5e37 N m s gives 3e38 rad/s. */
    CHECK_ACCEPTED("first angular impulse 5e37", i2d_body_apply_angular_impulse(body, 5e37f, true));
    const float w = i2d_body_get_angular_velocity(body);
    I2D_CHECK(w == k_max_spin); /* 3e38 rad/s, clamped where it enters */
    CHECK_REFUSED("angular impulse 1e38 (6e38 rad/s)", i2d_body_apply_angular_impulse(body, 1e38f, true),
                  I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_body_get_angular_velocity(body) == w);

    /* A linear impulse whose velocity change is fine but whose spin change is not:
     * 1e30 N s at 1e8 m adds 1e30 m/s and 6e38 rad/s. Refused whole. */
    CHECK_ACCEPTED("spin 0", i2d_body_set_angular_velocity(body, 0.0f));
    CHECK_REFUSED("impulse 1e30 at 1e8 m", i2d_body_apply_linear_impulse(body, v2(0.0f, 1e30f), v2(1e8f, 0.0f), true),
                  I2D_ERR_INVALID_ARGUMENT);
    i2d_vec2 v = i2d_body_get_linear_velocity(body);
    I2D_CHECK(v.x == 0.0f && v.y == 0.0f);
    I2D_CHECK(i2d_body_get_angular_velocity(body) == 0.0f);
    /* The same from a spin set directly, on the other side. */
    CHECK_ACCEPTED("spin -3e38", i2d_body_set_angular_velocity(body, -3e38f));
    CHECK_REFUSED("impulse 1e30 at -1e8 m",
                  i2d_body_apply_linear_impulse(body, v2(0.0f, 1e30f), v2(-1e8f, 0.0f), false),
                  I2D_ERR_INVALID_ARGUMENT);
    CHECK_REFUSED("angular impulse -1e38", i2d_body_apply_angular_impulse(body, -1e38f, false),
                  I2D_ERR_INVALID_ARGUMENT);
    v = i2d_body_get_linear_velocity(body);
    I2D_CHECK(v.x == 0.0f && v.y == 0.0f);
    I2D_CHECK(i2d_body_get_angular_velocity(body) == -k_max_spin);
    /* And one that fits: 1 N s at 1 m, dv = 1 m/s, dw = 6 rad/s. */
    CHECK_ACCEPTED("spin 0 again", i2d_body_set_angular_velocity(body, 0.0f));
    CHECK_ACCEPTED("impulse 1 at 1 m", i2d_body_apply_linear_impulse(body, v2(0.0f, 1.0f), v2(1.0f, 0.0f), true));
    I2D_CHECK_NEAR(i2d_body_get_linear_velocity(body).y, 1.0, 1e-6);
    I2D_CHECK_NEAR(i2d_body_get_angular_velocity(body), 6.0, 1e-5);
}

I2D_TEST(api_errors_angular_impulse_overflow) { run_in_world(0.0f, run_angular_impulse_overflow); }

/* ---- Calls from inside query callbacks --------------------------------------------- */

typedef struct lock_probe {
    const fixture* f;
    const snapshot* before;
    bool probed;
    int shapes_seen;
} lock_probe;

/* The call must answer WORLD_LOCKED and leave the fixture as it was. */
#define CHECK_LOCKED(f, before, call)                                    \
    do {                                                                 \
        i2d_status locked_status_ = (call);                              \
        CHECK_REFUSED(#call, locked_status_, I2D_ERR_WORLD_LOCKED);      \
        CHECK_UNCHANGED(#call, (f), (before));                           \
    } while (0)

/* The creation must return the null id with WORLD_LOCKED and leave the fixture as it was. */
#define CHECK_LOCKED_CREATE(f, before, id_expr)                                        \
    do {                                                                               \
        bool created_ = !I2D_IS_NULL(id_expr);                                         \
        CHECK_REFUSED(#id_expr, i2d_last_status(), I2D_ERR_WORLD_LOCKED);              \
        I2D_CHECK(!created_);                                                          \
        CHECK_UNCHANGED(#id_expr, (f), (before));                                      \
    } while (0)

static const i2d_vec2 k_triangle[3] = {{0.0f, 0.0f}, {0.5f, 0.0f}, {0.0f, 0.5f}};

static void try_changes_while_locked(const fixture* f, const snapshot* before) {
    i2d_body_id ball = f->body[FIX_BALL];
    i2d_body_def body_def = i2d_default_body_def();
    body_def.type = I2D_BODY_DYNAMIC;
    i2d_shape_def shape_def = i2d_default_shape_def();
    i2d_circle circle = {{0.0f, 0.0f}, 0.25f};
    const i2d_polygon square = i2d_make_box(0.25f, 0.25f);

    CHECK_LOCKED(f, before, i2d_world_step(f->world, 1.0f / 60.0f, 4));
    CHECK_LOCKED(f, before, i2d_world_destroy(f->world));
    CHECK_LOCKED_CREATE(f, before, i2d_body_create(f->world, &body_def));
    CHECK_LOCKED(f, before, i2d_body_destroy(f->body[FIX_MOVER]));
    CHECK_LOCKED_CREATE(f, before, i2d_shape_create_circle(ball, &shape_def, &circle));
    CHECK_LOCKED_CREATE(f, before, i2d_shape_create_box(ball, &shape_def, 0.5f, 0.5f));
    CHECK_LOCKED_CREATE(f, before, i2d_shape_create_offset_box(ball, &shape_def, 0.5f, 0.5f, v2(1.0f, 0.0f),
                                                               i2d_make_rot(0.5f)));
    CHECK_LOCKED_CREATE(f, before, i2d_shape_create_polygon(ball, &shape_def, k_triangle, 3));
    CHECK_LOCKED_CREATE(f, before, i2d_shape_create_polygon_from(ball, &shape_def, &square));
    CHECK_LOCKED_CREATE(f, before, i2d_shape_create_capsule(ball, &shape_def, v2(0.0f, 0.0f), v2(1.0f, 0.0f), 0.25f));
    CHECK_LOCKED_CREATE(f, before, i2d_shape_create_segment(f->body[FIX_GROUND], &shape_def, v2(0.0f, 5.0f),
                                                            v2(1.0f, 5.0f)));
    CHECK_LOCKED(f, before, i2d_shape_destroy(f->shape[FIX_BALL_BOX]));
    CHECK_LOCKED(f, before, i2d_shape_destroy(f->shape[FIX_MOVER_CAPSULE]));
    CHECK_LOCKED(f, before, i2d_body_set_transform(ball, v2(3.0f, 3.0f), rot(1.0f, 0.0f)));
    CHECK_LOCKED(f, before, i2d_body_set_transform(ball, v2(0.0f, k_ball_y), rot(0.0f, 1.0f)));
    CHECK_LOCKED(f, before, i2d_body_set_linear_velocity(ball, v2(0.0f, 7.0f)));
    CHECK_LOCKED(f, before, i2d_body_set_angular_velocity(ball, 0.0f));
    CHECK_LOCKED(f, before, i2d_body_set_angular_velocity(ball, 5.0f));
    CHECK_LOCKED(f, before, i2d_body_set_angular_velocity(f->body[FIX_MOVER], -1.0f));
    CHECK_LOCKED(f, before, i2d_body_apply_force(ball, v2(0.0f, 100.0f), v2(0.0f, 0.0f), true));
    CHECK_LOCKED(f, before, i2d_body_apply_force_to_center(ball, v2(0.0f, 100.0f), true));
    CHECK_LOCKED(f, before, i2d_body_apply_torque(ball, 100.0f, true));
    CHECK_LOCKED(f, before, i2d_body_apply_linear_impulse(ball, v2(0.0f, 100.0f), v2(0.0f, 0.0f), true));
    CHECK_LOCKED(f, before, i2d_body_apply_angular_impulse(ball, 100.0f, true));
    CHECK_LOCKED(f, before, i2d_body_set_awake(ball, false));
    CHECK_LOCKED(f, before, i2d_body_set_awake(ball, true));
    CHECK_LOCKED(f, before, i2d_body_set_type(ball, I2D_BODY_STATIC));
    CHECK_LOCKED(f, before, i2d_body_set_type(f->body[FIX_GROUND], I2D_BODY_DYNAMIC));
    CHECK_LOCKED(f, before, i2d_world_set_gravity(f->world, v2(0.0f, 10.0f)));
    CHECK_LOCKED(f, before, i2d_world_shift_origin(f->world, v2(100.0f, -50.0f)));
    CHECK_LOCKED(f, before, i2d_shape_set_friction(f->shape[FIX_BALL_CIRCLE], 0.1f));
    CHECK_LOCKED(f, before, i2d_shape_set_restitution(f->shape[FIX_BALL_CIRCLE], 0.9f));
    CHECK_LOCKED(f, before, i2d_shape_set_filter(f->shape[FIX_BALL_CIRCLE], i2d_default_filter()));
    CHECK_LOCKED(f, before, i2d_shape_set_friction(f->shape[FIX_MOVER_CAPSULE], 0.1f));
}

/* Getters, user data and nested queries still work inside a callback. */
static void try_reads_while_locked(const fixture* f, const snapshot* before, i2d_shape_id reported) {
    I2D_CHECK(i2d_shape_is_valid(reported));
    i2d_vec2 p = i2d_body_get_position(f->body[FIX_BALL]);
    CHECK_ACCEPTED("i2d_body_get_position inside a callback", i2d_last_status());
    I2D_CHECK(p.x == 0.0f && p.y == k_ball_y);
    i2d_world_counters counters = i2d_world_get_counters(f->world);
    CHECK_ACCEPTED("i2d_world_get_counters inside a callback", i2d_last_status());
    I2D_CHECK(counters.shape_count == FIX_SHAPES);

    /* The rotation getters and the body frame. */
    i2d_body_id ball = f->body[FIX_BALL], mover = f->body[FIX_MOVER];
    float inertia = i2d_body_get_rotational_inertia(ball);
    CHECK_ACCEPTED("i2d_body_get_rotational_inertia inside a callback", i2d_last_status());
    I2D_CHECK(inertia > 0.0f);
    i2d_vec2 local_com = i2d_body_get_local_center_of_mass(ball);
    CHECK_ACCEPTED("i2d_body_get_local_center_of_mass inside a callback", i2d_last_status());
    /* The circle (pi 0.25 kg) sits at x = 0.3, the box (1.28 kg) at the origin. */
    I2D_CHECK_NEAR(local_com.x, 0.3 * (0.25 * 3.14159265) / (0.25 * 3.14159265 + 1.28), 1e-6);
    I2D_CHECK_NEAR(local_com.y, 0.0, 1e-6);
    i2d_vec2 w = i2d_body_get_world_point(mover, v2(1.0f, 0.0f));
    CHECK_ACCEPTED("i2d_body_get_world_point inside a callback", i2d_last_status());
    i2d_vec2 l = i2d_body_get_local_point(mover, w);
    CHECK_ACCEPTED("i2d_body_get_local_point inside a callback", i2d_last_status());
    I2D_CHECK_NEAR(l.x, 1.0, 1e-5);
    I2D_CHECK_NEAR(l.y, 0.0, 1e-5);
    i2d_vec2 pv = i2d_body_get_world_point_velocity(mover, w);
    CHECK_ACCEPTED("i2d_body_get_world_point_velocity inside a callback", i2d_last_status());
    I2D_CHECK(pv.y > 0.0f); /* spinning counter-clockwise at 0.5 rad/s, a point ahead of the centre */
    i2d_capsule cap = i2d_shape_get_capsule(f->shape[FIX_MOVER_CAPSULE]);
    CHECK_ACCEPTED("i2d_shape_get_capsule inside a callback", i2d_last_status());
    I2D_CHECK(cap.radius == 0.2f);
    i2d_segment seg = i2d_shape_get_segment(f->shape[FIX_GROUND_SEGMENT]);
    CHECK_ACCEPTED("i2d_shape_get_segment inside a callback", i2d_last_status());
    I2D_CHECK(seg.point2.x == -17.0f);
    i2d_rot q = i2d_make_rot(0.5f);
    CHECK_ACCEPTED("i2d_make_rot inside a callback", i2d_last_status());
    I2D_CHECK_NEAR(i2d_rot_get_angle(q), 0.5, 1e-6);

    static int marker;
    void* old_body_data = i2d_body_get_user_data(ball);
    CHECK_ACCEPTED("i2d_body_set_user_data inside a callback", i2d_body_set_user_data(ball, &marker));
    I2D_CHECK(i2d_body_get_user_data(ball) == &marker);
    CHECK_ACCEPTED("i2d_body_set_user_data back", i2d_body_set_user_data(ball, old_body_data));
    i2d_shape_id circle = f->shape[FIX_BALL_CIRCLE];
    void* old_shape_data = i2d_shape_get_user_data(circle);
    CHECK_ACCEPTED("i2d_shape_set_user_data inside a callback", i2d_shape_set_user_data(circle, &marker));
    I2D_CHECK(i2d_shape_get_user_data(circle) == &marker);
    CHECK_ACCEPTED("i2d_shape_set_user_data back", i2d_shape_set_user_data(circle, old_shape_data));

    const i2d_query_filter filter = i2d_default_query_filter();
    int nested = 0;
    CHECK_ACCEPTED("nested i2d_world_overlap_aabb",
                   i2d_world_overlap_aabb(f->world, box(-100.0f, -100.0f, 100.0f, 100.0f), filter, count_shape,
                                          &nested));
    I2D_CHECK(nested == FIX_SHAPES);
    nested = 0;
    CHECK_ACCEPTED("nested i2d_world_overlap_point",
                   i2d_world_overlap_point(f->world, v2(10.0f, -1.0f), filter, count_shape, &nested));
    I2D_CHECK(nested == 1); /* only the ground contains (10, -1) */
    i2d_shape_id ids[8];
    int32_t n = i2d_world_overlap_aabb_ids(f->world, box(-100.0f, -100.0f, 100.0f, 100.0f), filter, ids, 8);
    CHECK_ACCEPTED("nested i2d_world_overlap_aabb_ids", i2d_last_status());
    I2D_CHECK(n == FIX_SHAPES);
    i2d_ray_result r = i2d_world_cast_ray_closest(f->world, v2(10.0f, 5.0f), v2(0.0f, -10.0f), filter);
    CHECK_ACCEPTED("nested i2d_world_cast_ray_closest", i2d_last_status());
    I2D_CHECK(r.hit && I2D_ID_EQUALS(r.shape, f->shape[FIX_GROUND_BOX]));

    /* The end of a nested query must not unlock the outer one. */
    CHECK_LOCKED(f, before, i2d_body_set_linear_velocity(ball, v2(0.0f, 7.0f)));
    CHECK_LOCKED(f, before, i2d_body_apply_torque(ball, 1.0f, true));
    CHECK_UNCHANGED("the reads inside a callback", f, before);
}

static bool probe_locked_world(i2d_shape_id shape, void* context) {
    lock_probe* probe = (lock_probe*)context;
    ++probe->shapes_seen;
    if (!probe->probed) {
        probe->probed = true;
        try_changes_while_locked(probe->f, probe->before);
        try_reads_while_locked(probe->f, probe->before, shape);
    }
    return true;
}

static void run_locked_in_callbacks(const fixture* a, const fixture* b) {
    static snapshot before;
    snapshot_take(a, &before);
    const i2d_query_filter filter = i2d_default_query_filter();

    lock_probe probe = {a, &before, false, 0};
    CHECK_ACCEPTED("i2d_world_overlap_aabb around a probing callback",
                   i2d_world_overlap_aabb(a->world, box(-100.0f, -100.0f, 100.0f, 100.0f), filter,
                                          probe_locked_world, &probe));
    I2D_CHECK(probe.probed);
    I2D_CHECK(probe.shapes_seen == FIX_SHAPES); /* the outer query went on to the end */

    /* The same from a point query's callback (a point inside the ball's circle only). */
    lock_probe point_probe = {a, &before, false, 0};
    CHECK_ACCEPTED("i2d_world_overlap_point around a probing callback",
                   i2d_world_overlap_point(a->world, v2(0.6f, k_ball_y), filter, probe_locked_world, &point_probe));
    I2D_CHECK(point_probe.probed);
    I2D_CHECK(point_probe.shapes_seen == 1);

    CHECK_UNCHANGED("the queries with probing callbacks", a, &before);
    check_twins_agree_after_steps(a, b);

    /* Once the queries have returned, the world takes changes again. */
    CHECK_ACCEPTED("i2d_body_set_linear_velocity after the query",
                   i2d_body_set_linear_velocity(a->body[FIX_BALL], v2(0.0f, 7.0f)));
    I2D_CHECK(i2d_body_get_linear_velocity(a->body[FIX_BALL]).y == 7.0f);
    CHECK_ACCEPTED("i2d_body_set_angular_velocity after the query",
                   i2d_body_set_angular_velocity(a->body[FIX_BALL], 3.0f));
    I2D_CHECK(i2d_body_get_angular_velocity(a->body[FIX_BALL]) == 3.0f);
    CHECK_ACCEPTED("i2d_body_apply_torque after the query", i2d_body_apply_torque(a->body[FIX_BALL], 1.0f, true));
    CHECK_ACCEPTED("i2d_world_step after the query", i2d_world_step(a->world, 1.0f / 60.0f, 4));
}

I2D_TEST(api_errors_locked_in_query_callbacks) { run_on_twins(run_locked_in_callbacks); }

/* ---- Order of checks: handle, then lock, then arguments ---------------------------- */

typedef struct order_probe {
    const fixture* f;
    const snapshot* before;
    i2d_body_id stale;
    bool probed;
} order_probe;

static bool probe_check_order(i2d_shape_id shape, void* context) {
    (void)shape;
    order_probe* probe = (order_probe*)context;
    if (probe->probed) {
        return false;
    }
    probe->probed = true;
    const fixture* f = probe->f;
    const i2d_body_id ball = f->body[FIX_BALL];
    /* Locked wins over bad arguments... */
    CHECK_LOCKED(f, probe->before, i2d_body_set_linear_velocity(ball, v2(NAN, 0.0f)));
    CHECK_LOCKED(f, probe->before, i2d_body_set_angular_velocity(ball, INFINITY));
    CHECK_LOCKED(f, probe->before, i2d_body_set_transform(ball, v2(0.0f, 0.0f), rot(2.0f, 0.0f)));
    CHECK_LOCKED(f, probe->before, i2d_body_apply_torque(ball, NAN, true));
    CHECK_LOCKED(f, probe->before, i2d_body_apply_angular_impulse(ball, -INFINITY, true));
    CHECK_LOCKED(f, probe->before, i2d_body_apply_force_to_center(ball, v2(0.0f, NAN), true));
    CHECK_LOCKED(f, probe->before, i2d_world_step(f->world, NAN, 0));
    CHECK_LOCKED(f, probe->before, i2d_world_set_gravity(f->world, v2(INFINITY, 0.0f)));
    CHECK_LOCKED(f, probe->before, i2d_world_shift_origin(f->world, v2(NAN, 0.0f)));
    CHECK_LOCKED(f, probe->before, i2d_shape_set_friction(f->shape[FIX_BALL_BOX], -1.0f));
    CHECK_LOCKED_CREATE(f, probe->before, i2d_body_create(f->world, NULL));
    CHECK_LOCKED_CREATE(f, probe->before, i2d_shape_create_circle(ball, NULL, NULL));
    CHECK_LOCKED_CREATE(f, probe->before, i2d_shape_create_box(ball, NULL, -1.0f, NAN));
    CHECK_LOCKED_CREATE(f, probe->before,
                        i2d_shape_create_offset_box(ball, NULL, 1.0f, 1.0f, v2(0.0f, 0.0f), rot(0.0f, 0.0f)));
    CHECK_LOCKED_CREATE(f, probe->before, i2d_shape_create_polygon(ball, NULL, NULL, 2));
    CHECK_LOCKED_CREATE(f, probe->before, i2d_shape_create_polygon_from(ball, NULL, NULL));
    CHECK_LOCKED_CREATE(f, probe->before, i2d_shape_create_capsule(ball, NULL, v2(0.0f, 0.0f), v2(0.0f, 0.0f), -1.0f));
    CHECK_LOCKED_CREATE(f, probe->before, i2d_shape_create_segment(ball, NULL, v2(NAN, 0.0f), v2(0.0f, 0.0f)));
    /* ...and a bad handle wins over the lock. */
    CHECK_REFUSED("stale body inside a callback", i2d_body_set_linear_velocity(probe->stale, v2(NAN, 0.0f)),
                  I2D_ERR_INVALID_HANDLE);
    CHECK_REFUSED("stale body torque inside a callback", i2d_body_apply_torque(probe->stale, NAN, true),
                  I2D_ERR_INVALID_HANDLE);
    CHECK_REFUSED("null body inside a callback", i2d_body_apply_force(I2D_NULL_BODY_ID, v2(1, 0), v2(0, 0), true),
                  I2D_ERR_INVALID_HANDLE);
    i2d_shape_id created = i2d_shape_create_capsule(probe->stale, NULL, v2(0.0f, 0.0f), v2(0.0f, 0.0f), -1.0f);
    CHECK_REFUSED("i2d_shape_create_capsule(stale body) inside a callback", i2d_last_status(), I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(I2D_IS_NULL(created));
    CHECK_UNCHANGED("the order probe", f, probe->before);
    return false;
}

static void run_check_order(const fixture* f) {
    /* A stale body id: created and destroyed before the snapshot. */
    i2d_body_def body_def = i2d_default_body_def();
    i2d_body_id stale = i2d_body_create(f->world, &body_def);
    I2D_CHECK_STATUS(i2d_body_destroy(stale), I2D_OK);

    static snapshot before;
    snapshot_take(f, &before);

    /* Bad handle wins over bad arguments. */
    CHECK_REFUSED("null body, NaN velocity", i2d_body_set_linear_velocity(I2D_NULL_BODY_ID, v2(NAN, 0.0f)),
                  I2D_ERR_INVALID_HANDLE);
    CHECK_REFUSED("stale body, NaN velocity", i2d_body_set_linear_velocity(stale, v2(NAN, 0.0f)),
                  I2D_ERR_INVALID_HANDLE);
    CHECK_REFUSED("stale body, bad rotation", i2d_body_set_transform(stale, v2(NAN, 0.0f), rot(0.0f, 0.0f)),
                  I2D_ERR_INVALID_HANDLE);
    CHECK_REFUSED("null body, NaN angular impulse", i2d_body_apply_angular_impulse(I2D_NULL_BODY_ID, NAN, true),
                  I2D_ERR_INVALID_HANDLE);
    CHECK_REFUSED("stale body, NaN angular velocity", i2d_body_set_angular_velocity(stale, NAN),
                  I2D_ERR_INVALID_HANDLE);
    CHECK_REFUSED("null world, NaN step", i2d_world_step(I2D_NULL_WORLD_ID, NAN, 0), I2D_ERR_INVALID_HANDLE);
    CHECK_REFUSED("null world, NULL fn",
                  i2d_world_overlap_aabb(I2D_NULL_WORLD_ID, box(1.0f, 1.0f, 0.0f, 0.0f), i2d_default_query_filter(),
                                         NULL, NULL),
                  I2D_ERR_INVALID_HANDLE);
    i2d_body_id body = i2d_body_create(I2D_NULL_WORLD_ID, NULL);
    CHECK_REFUSED("i2d_body_create(null world, NULL)", i2d_last_status(), I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(I2D_IS_NULL(body));
    i2d_shape_id shape = i2d_shape_create_circle(stale, NULL, NULL);
    CHECK_REFUSED("i2d_shape_create_circle(stale body, NULL, NULL)", i2d_last_status(), I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(I2D_IS_NULL(shape));
    shape = i2d_shape_create_box(I2D_NULL_BODY_ID, NULL, NAN, -1.0f);
    CHECK_REFUSED("i2d_shape_create_box(null body, NULL, NaN, -1)", i2d_last_status(), I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(I2D_IS_NULL(shape));
    shape = i2d_shape_create_polygon(I2D_NULL_BODY_ID, NULL, NULL, 9);
    CHECK_REFUSED("i2d_shape_create_polygon(null body, NULL, NULL, 9)", i2d_last_status(), I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(I2D_IS_NULL(shape));
    shape = i2d_shape_create_polygon_from(stale, NULL, NULL);
    CHECK_REFUSED("i2d_shape_create_polygon_from(stale body, NULL, NULL)", i2d_last_status(), I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(I2D_IS_NULL(shape));
    shape = i2d_shape_create_offset_box(stale, NULL, -1.0f, NAN, v2(NAN, 0.0f), rot(2.0f, 0.0f));
    CHECK_REFUSED("i2d_shape_create_offset_box(stale body, bad everything)", i2d_last_status(),
                  I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(I2D_IS_NULL(shape));
    shape = i2d_shape_create_segment(I2D_NULL_BODY_ID, NULL, v2(0.0f, 0.0f), v2(0.0f, 0.0f));
    CHECK_REFUSED("i2d_shape_create_segment(null body, NULL, zero length)", i2d_last_status(),
                  I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(I2D_IS_NULL(shape));
    i2d_vec2 point = i2d_body_get_world_point(stale, v2(NAN, 0.0f));
    CHECK_REFUSED("i2d_body_get_world_point(stale body, NaN)", i2d_last_status(), I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(point.x == 0.0f && point.y == 0.0f);
    CHECK_UNCHANGED("calls with bad handles and bad arguments", f, &before);

    order_probe probe = {f, &before, stale, false};
    CHECK_ACCEPTED("query around the order probe",
                   i2d_world_overlap_aabb(f->world, box(-100.0f, -100.0f, 100.0f, 100.0f), i2d_default_query_filter(),
                                          probe_check_order, &probe));
    I2D_CHECK(probe.probed);
}

I2D_TEST(api_errors_check_order) { run_on_fixture(run_check_order); }

/* ---- Pure collision functions ------------------------------------------------------- */

static const float_field k_circle_floats[] = {
    {"center.x", offsetof(i2d_circle, center.x)},
    {"center.y", offsetof(i2d_circle, center.y)},
    {"radius", offsetof(i2d_circle, radius)},
};

static void check_no_manifold_at(int line, const char* what, i2d_manifold m) {
    check_refused_at(__FILE__, line, what, i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    if (m.point_count != 0) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: point_count %d, expected 0\n", __FILE__, line, what, (int)m.point_count);
    }
}

I2D_TEST(api_errors_collide_bad_input) {
    const i2d_circle good = {{0.0f, 0.0f}, 1.0f};
    const i2d_aabb good_box = box(-1.0f, -1.0f, 1.0f, 1.0f);
    char what[128];
    for (size_t i = 0; i < sizeof k_circle_floats / sizeof k_circle_floats[0]; ++i) {
        for (int k = 0; k < NON_FINITE_COUNT; ++k) {
            i2d_circle bad = good;
            set_float_at(&bad, k_circle_floats[i].offset, k_non_finite[k]);
            snprintf(what, sizeof what, "i2d_collide_circles with %s = %g", k_circle_floats[i].name, k_non_finite[k]);
            check_no_manifold_at(__LINE__, what, i2d_collide_circles(good, bad));
            check_no_manifold_at(__LINE__, what, i2d_collide_circles(bad, good));
            snprintf(what, sizeof what, "i2d_collide_aabb_circle with %s = %g", k_circle_floats[i].name,
                     k_non_finite[k]);
            check_no_manifold_at(__LINE__, what, i2d_collide_aabb_circle(good_box, bad));
        }
    }
    i2d_circle negative = good;
    negative.radius = -0.5f;
    check_no_manifold_at(__LINE__, "i2d_collide_circles negative radius", i2d_collide_circles(good, negative));
    check_no_manifold_at(__LINE__, "i2d_collide_aabb_circle negative radius",
                         i2d_collide_aabb_circle(good_box, negative));

    i2d_aabb bad[32];
    int bad_count = 0;
    bad_aabbs(bad, &bad_count);
    for (int i = 0; i < bad_count; ++i) {
        snprintf(what, sizeof what, "aabb (%g, %g)-(%g, %g)", bad[i].min.x, bad[i].min.y, bad[i].max.x, bad[i].max.y);
        check_no_manifold_at(__LINE__, what, i2d_collide_aabbs(good_box, bad[i]));
        check_no_manifold_at(__LINE__, what, i2d_collide_aabbs(bad[i], good_box));
        check_no_manifold_at(__LINE__, what, i2d_collide_aabb_circle(bad[i], good));
    }
    /* Valid overlapping input reports a contact, so the zeros above come from the checks. */
    i2d_manifold m = i2d_collide_circles(good, good);
    CHECK_ACCEPTED("i2d_collide_circles valid", i2d_last_status());
    I2D_CHECK(m.point_count == 1);
}

/* The functions of placed shapes, each with one broken input: which one says `broken`. */
enum { BROKEN_NONE, BROKEN_NULL_A, BROKEN_NULL_B, BROKEN_SHAPE_A, BROKEN_SHAPE_B, BROKEN_KINDS };

typedef i2d_manifold (*placed_collide)(i2d_transform xfa, i2d_transform xfb, int broken);

/* Valid shapes of each kind about the origin, all overlapping each other, and one invalid
 * shape of each kind (negative radius, centres too close, NaN, a count of 9). */
static const i2d_circle k_good_circle = {{0.0f, 0.0f}, 0.5f};
static const i2d_circle k_bad_circle = {{0.0f, 0.0f}, -0.5f};
static const i2d_capsule k_good_capsule = {{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.25f};
static const i2d_capsule k_bad_capsule = {{0.0f, 0.0f}, {0.004f, 0.0f}, 0.25f};
static const i2d_segment k_good_segment = {{-1.0f, 0.0f}, {1.0f, 0.0f}};
static const i2d_segment k_bad_segment = {{0.0f, 0.0f}, {NAN, 0.0f}};

static i2d_polygon good_polygon(void) { return i2d_make_box(0.5f, 0.5f); }
static i2d_polygon bad_polygon(void) {
    i2d_polygon p = i2d_make_box(0.5f, 0.5f);
    p.count = 9;
    return p;
}

/* Shape a or b of a wrapper below: NULL, the invalid one or the valid one, by `broken`. */
#define SIDE_A(good, bad) (broken == BROKEN_NULL_A ? NULL : broken == BROKEN_SHAPE_A ? (bad) : (good))
#define SIDE_B(good, bad) (broken == BROKEN_NULL_B ? NULL : broken == BROKEN_SHAPE_B ? (bad) : (good))

static i2d_manifold collide_capsule_circle(i2d_transform xfa, i2d_transform xfb, int broken) {
    const i2d_capsule* a = SIDE_A(&k_good_capsule, &k_bad_capsule);
    const i2d_circle* b = SIDE_B(&k_good_circle, &k_bad_circle);
    return i2d_collide_capsule_circle(a, xfa, b, xfb);
}
static i2d_manifold collide_segment_circle(i2d_transform xfa, i2d_transform xfb, int broken) {
    const i2d_segment* a = SIDE_A(&k_good_segment, &k_bad_segment);
    const i2d_circle* b = SIDE_B(&k_good_circle, &k_bad_circle);
    return i2d_collide_segment_circle(a, xfa, b, xfb);
}
static i2d_manifold collide_polygon_circle(i2d_transform xfa, i2d_transform xfb, int broken) {
    const i2d_polygon good = good_polygon(), bad = bad_polygon();
    const i2d_polygon* a = SIDE_A(&good, &bad);
    const i2d_circle* b = SIDE_B(&k_good_circle, &k_bad_circle);
    return i2d_collide_polygon_circle(a, xfa, b, xfb);
}
static i2d_manifold collide_capsules(i2d_transform xfa, i2d_transform xfb, int broken) {
    const i2d_capsule* a = SIDE_A(&k_good_capsule, &k_bad_capsule);
    const i2d_capsule* b = SIDE_B(&k_good_capsule, &k_bad_capsule);
    return i2d_collide_capsules(a, xfa, b, xfb);
}
static i2d_manifold collide_segment_capsule(i2d_transform xfa, i2d_transform xfb, int broken) {
    const i2d_segment* a = SIDE_A(&k_good_segment, &k_bad_segment);
    const i2d_capsule* b = SIDE_B(&k_good_capsule, &k_bad_capsule);
    return i2d_collide_segment_capsule(a, xfa, b, xfb);
}
static i2d_manifold collide_polygon_capsule(i2d_transform xfa, i2d_transform xfb, int broken) {
    const i2d_polygon good = good_polygon(), bad = bad_polygon();
    const i2d_polygon* a = SIDE_A(&good, &bad);
    const i2d_capsule* b = SIDE_B(&k_good_capsule, &k_bad_capsule);
    return i2d_collide_polygon_capsule(a, xfa, b, xfb);
}
static i2d_manifold collide_segment_polygon(i2d_transform xfa, i2d_transform xfb, int broken) {
    const i2d_polygon good = good_polygon(), bad = bad_polygon();
    const i2d_segment* a = SIDE_A(&k_good_segment, &k_bad_segment);
    const i2d_polygon* b = SIDE_B(&good, &bad);
    return i2d_collide_segment_polygon(a, xfa, b, xfb);
}
static i2d_manifold collide_polygons(i2d_transform xfa, i2d_transform xfb, int broken) {
    const i2d_polygon good = good_polygon(), bad = bad_polygon();
    const i2d_polygon* a = SIDE_A(&good, &bad);
    const i2d_polygon* b = SIDE_B(&good, &bad);
    return i2d_collide_polygons(a, xfa, b, xfb);
}

typedef struct placed_collide_row {
    const char* name;
    placed_collide call;
} placed_collide_row;

static const placed_collide_row k_placed_collides[] = {
    {"i2d_collide_capsule_circle", collide_capsule_circle},
    {"i2d_collide_segment_circle", collide_segment_circle},
    {"i2d_collide_polygon_circle", collide_polygon_circle},
    {"i2d_collide_capsules", collide_capsules},
    {"i2d_collide_segment_capsule", collide_segment_capsule},
    {"i2d_collide_polygon_capsule", collide_polygon_capsule},
    {"i2d_collide_segment_polygon", collide_segment_polygon},
    {"i2d_collide_polygons", collide_polygons},
};

static i2d_transform xform(float x, float y, float c, float s) {
    i2d_transform t;
    t.p = v2(x, y);
    t.q = rot(c, s);
    return t;
}

/* Placed-shape manifolds: NULL shapes, invalid shapes, NaN or infinite positions and
 * rotations that are not unit length, on either side. */
I2D_TEST(api_errors_collide_placed_bad_input) {
    static const char* const broken_names[] = {"", "NULL shape a", "NULL shape b", "invalid shape a",
                                               "invalid shape b"};
    const i2d_transform id = xform(0.0f, 0.0f, 1.0f, 0.0f);
    const i2d_transform xfb_ok = xform(0.1f, 0.2f, 0.6f, 0.8f);
    char what[192];
    for (size_t f = 0; f < sizeof k_placed_collides / sizeof k_placed_collides[0]; ++f) {
        const placed_collide_row* row = &k_placed_collides[f];
        for (int broken = BROKEN_NULL_A; broken < BROKEN_KINDS; ++broken) {
            snprintf(what, sizeof what, "%s with %s", row->name, broken_names[broken]);
            check_no_manifold_at(__LINE__, what, row->call(id, xfb_ok, broken));
        }
        for (int side = 0; side < 2; ++side) {
            for (int k = 0; k < NON_FINITE_COUNT; ++k) {
                i2d_transform bad = xfb_ok;
                bad.p.y = k_non_finite[k];
                snprintf(what, sizeof what, "%s with xf%c.p.y = %g", row->name, side == 0 ? 'a' : 'b', k_non_finite[k]);
                check_no_manifold_at(__LINE__, what, side == 0 ? row->call(bad, xfb_ok, 0) : row->call(id, bad, 0));
                bad = xfb_ok;
                bad.q.s = k_non_finite[k];
                snprintf(what, sizeof what, "%s with xf%c.q.s = %g", row->name, side == 0 ? 'a' : 'b', k_non_finite[k]);
                check_no_manifold_at(__LINE__, what, side == 0 ? row->call(bad, xfb_ok, 0) : row->call(id, bad, 0));
            }
            for (int r = 0; r < k_bad_rotation_count; ++r) {
                i2d_transform bad = xform(0.1f, 0.2f, k_bad_rotations[r].c, k_bad_rotations[r].s);
                snprintf(what, sizeof what, "%s with xf%c.q = %s", row->name, side == 0 ? 'a' : 'b',
                         k_bad_rotations[r].name);
                check_no_manifold_at(__LINE__, what, side == 0 ? row->call(bad, xfb_ok, 0) : row->call(id, bad, 0));
            }
        }
        /* The same shapes, valid and overlapping: a contact, so the refusals come from
         * the checks. Rotations within 1e-3 of unit length are taken. */
        i2d_manifold m = row->call(id, xfb_ok, BROKEN_NONE);
        snprintf(what, sizeof what, "%s valid", row->name);
        check_accepted_at(__FILE__, __LINE__, what, i2d_last_status());
        I2D_CHECK(m.point_count >= 1);
        m = row->call(xform(0.0f, 0.0f, 1.0004f, 0.0f), xform(0.1f, 0.2f, 0.0f, -0.9996f), BROKEN_NONE);
        snprintf(what, sizeof what, "%s with rotations 4e-4 off unit length", row->name);
        check_accepted_at(__FILE__, __LINE__, what, i2d_last_status());
        I2D_CHECK(m.point_count >= 1);
    }
}

/* A world-free call refused (I2D_ERR_INVALID_ARGUMENT with a message) that gave the zero
 * value. gave_zero holds the call, so it is made before the status is read. */
static void check_pure_refused_at(int line, const char* what, bool gave_zero) {
    check_refused_at(__FILE__, line, what, i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    if (!gave_zero) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: refused, but did not give the zero value\n", __FILE__, line, what);
    }
}
#define CHECK_PURE_REFUSED(what, gave_zero) check_pure_refused_at(__LINE__, (what), (gave_zero))

/* The zero values. */
static bool no_polygon(i2d_polygon p) { return p.count == 0; }
static bool no_mass(i2d_mass_data md) { return md.mass == 0.0f && md.rotational_inertia == 0.0f; }
static bool missed(i2d_cast_output c) { return !c.hit; }

/* The world-free makers, mass and ray functions: each refusal says why and gives the
 * zero value (i2d_make_polygon leaves its output untouched). */
I2D_TEST(api_errors_pure_functions_bad_input) {
    char what[160];
    for (int k = 0; k < NON_FINITE_COUNT; ++k) {
        i2d_make_rot(k_non_finite[k]);
        snprintf(what, sizeof what, "i2d_make_rot(%g)", k_non_finite[k]);
        check_refused_at(__FILE__, __LINE__, what, i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
        i2d_rot_get_angle(rot(k_non_finite[k], 0.0f));
        snprintf(what, sizeof what, "i2d_rot_get_angle(c = %g)", k_non_finite[k]);
        check_refused_at(__FILE__, __LINE__, what, i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
        i2d_rot_get_angle(rot(0.0f, k_non_finite[k]));
        snprintf(what, sizeof what, "i2d_rot_get_angle(s = %g)", k_non_finite[k]);
        check_refused_at(__FILE__, __LINE__, what, i2d_last_status(), I2D_ERR_INVALID_ARGUMENT);
    }

    /* Boxes: sizes must be finite and > 0; offset boxes take a centre and a unit rotation. */
    static const float bad_halves[] = {0.0f, -1.0f, NAN, INFINITY};
    for (size_t i = 0; i < sizeof bad_halves / sizeof bad_halves[0]; ++i) {
        snprintf(what, sizeof what, "i2d_make_box(%g, 1)", bad_halves[i]);
        CHECK_PURE_REFUSED(what, no_polygon(i2d_make_box(bad_halves[i], 1.0f)));
        snprintf(what, sizeof what, "i2d_make_box(1, %g)", bad_halves[i]);
        CHECK_PURE_REFUSED(what, no_polygon(i2d_make_box(1.0f, bad_halves[i])));
        snprintf(what, sizeof what, "i2d_make_offset_box(%g, 1, ...)", bad_halves[i]);
        CHECK_PURE_REFUSED(what, no_polygon(i2d_make_offset_box(bad_halves[i], 1.0f, v2(0.0f, 0.0f), rot(1.0f, 0.0f))));
    }
    for (int k = 0; k < NON_FINITE_COUNT; ++k) {
        snprintf(what, sizeof what, "i2d_make_offset_box centre.x %g", k_non_finite[k]);
        CHECK_PURE_REFUSED(what,
                           no_polygon(i2d_make_offset_box(1.0f, 1.0f, v2(k_non_finite[k], 0.0f), rot(1.0f, 0.0f))));
    }
    for (int r = 0; r < k_bad_rotation_count; ++r) {
        const i2d_rot q = rot(k_bad_rotations[r].c, k_bad_rotations[r].s);
        snprintf(what, sizeof what, "i2d_make_offset_box rotation %s", k_bad_rotations[r].name);
        CHECK_PURE_REFUSED(what, no_polygon(i2d_make_offset_box(1.0f, 1.0f, v2(0.0f, 0.0f), q)));
    }

    /* i2d_make_polygon: the same point sets the shape creator refuses, plus radii. */
    i2d_polygon out, sentinel;
    memset(&sentinel, 0x5a, sizeof sentinel);
    for (int i = 0; i < k_bad_point_set_count; ++i) {
        const point_set* set = &k_bad_point_sets[i];
        out = sentinel;
        i2d_status status = i2d_make_polygon(set->points, set->count, 0.0f, &out);
        snprintf(what, sizeof what, "i2d_make_polygon %s", set->name);
        check_refused_at(__FILE__, __LINE__, what, status, I2D_ERR_INVALID_ARGUMENT);
        I2D_CHECK(memcmp(&out, &sentinel, sizeof out) == 0);
    }
    static const float bad_radii[] = {-0.1f, NAN, INFINITY};
    for (size_t i = 0; i < sizeof bad_radii / sizeof bad_radii[0]; ++i) {
        out = sentinel;
        i2d_status status = i2d_make_polygon(k_triangle, 3, bad_radii[i], &out);
        snprintf(what, sizeof what, "i2d_make_polygon radius %g", bad_radii[i]);
        check_refused_at(__FILE__, __LINE__, what, status, I2D_ERR_INVALID_ARGUMENT);
        I2D_CHECK(memcmp(&out, &sentinel, sizeof out) == 0);
    }
    for (int k = 0; k < NON_FINITE_COUNT; ++k) {
        i2d_vec2 points[3] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}};
        points[2].x = k_non_finite[k];
        out = sentinel;
        i2d_status status = i2d_make_polygon(points, 3, 0.0f, &out);
        snprintf(what, sizeof what, "i2d_make_polygon points[2].x = %g", k_non_finite[k]);
        check_refused_at(__FILE__, __LINE__, what, status, I2D_ERR_INVALID_ARGUMENT);
        I2D_CHECK(memcmp(&out, &sentinel, sizeof out) == 0);
    }
    CHECK_REFUSED("i2d_make_polygon(NULL points)", i2d_make_polygon(NULL, 3, 0.0f, &out), I2D_ERR_INVALID_ARGUMENT);
    CHECK_REFUSED("i2d_make_polygon(NULL out)", i2d_make_polygon(k_triangle, 3, 0.0f, NULL), I2D_ERR_INVALID_ARGUMENT);

    /* Mass: NULL, invalid shapes, negative or non-finite density. */
    const i2d_polygon square = i2d_make_box(0.5f, 0.5f), broken_square = bad_polygon();
    static const float bad_densities[] = {-1.0f, -1e-30f, NAN, INFINITY};
    for (size_t i = 0; i < sizeof bad_densities / sizeof bad_densities[0]; ++i) {
        snprintf(what, sizeof what, "i2d_compute_circle_mass density %g", bad_densities[i]);
        CHECK_PURE_REFUSED(what, no_mass(i2d_compute_circle_mass(&k_good_circle, bad_densities[i])));
        snprintf(what, sizeof what, "i2d_compute_capsule_mass density %g", bad_densities[i]);
        CHECK_PURE_REFUSED(what, no_mass(i2d_compute_capsule_mass(&k_good_capsule, bad_densities[i])));
        snprintf(what, sizeof what, "i2d_compute_polygon_mass density %g", bad_densities[i]);
        CHECK_PURE_REFUSED(what, no_mass(i2d_compute_polygon_mass(&square, bad_densities[i])));
    }
    CHECK_PURE_REFUSED("i2d_compute_circle_mass(NULL)", no_mass(i2d_compute_circle_mass(NULL, 1.0f)));
    CHECK_PURE_REFUSED("i2d_compute_circle_mass(negative radius)",
                       no_mass(i2d_compute_circle_mass(&k_bad_circle, 1.0f)));
    CHECK_PURE_REFUSED("i2d_compute_capsule_mass(NULL)", no_mass(i2d_compute_capsule_mass(NULL, 1.0f)));
    CHECK_PURE_REFUSED("i2d_compute_capsule_mass(centres 0.004 apart)",
                       no_mass(i2d_compute_capsule_mass(&k_bad_capsule, 1.0f)));
    CHECK_PURE_REFUSED("i2d_compute_polygon_mass(NULL)", no_mass(i2d_compute_polygon_mass(NULL, 1.0f)));
    CHECK_PURE_REFUSED("i2d_compute_polygon_mass(count 9)", no_mass(i2d_compute_polygon_mass(&broken_square, 1.0f)));

    /* Ray casts: NULL or invalid shapes, bad transforms, non-finite rays. */
    const i2d_transform id = xform(0.0f, 0.0f, 1.0f, 0.0f);
    const i2d_vec2 o = v2(-5.0f, 0.1f), d = v2(10.0f, 0.0f);
    i2d_cast_output c;
    CHECK_PURE_REFUSED("i2d_ray_cast_circle(NULL)", missed(i2d_ray_cast_circle(NULL, id, o, d)));
    CHECK_PURE_REFUSED("i2d_ray_cast_circle(negative radius)", missed(i2d_ray_cast_circle(&k_bad_circle, id, o, d)));
    CHECK_PURE_REFUSED("i2d_ray_cast_capsule(NULL)", missed(i2d_ray_cast_capsule(NULL, id, o, d)));
    CHECK_PURE_REFUSED("i2d_ray_cast_capsule(too short)", missed(i2d_ray_cast_capsule(&k_bad_capsule, id, o, d)));
    CHECK_PURE_REFUSED("i2d_ray_cast_segment(NULL)", missed(i2d_ray_cast_segment(NULL, id, o, d)));
    CHECK_PURE_REFUSED("i2d_ray_cast_segment(NaN point)", missed(i2d_ray_cast_segment(&k_bad_segment, id, o, d)));
    CHECK_PURE_REFUSED("i2d_ray_cast_polygon(NULL)", missed(i2d_ray_cast_polygon(NULL, id, o, d)));
    CHECK_PURE_REFUSED("i2d_ray_cast_polygon(count 9)", missed(i2d_ray_cast_polygon(&broken_square, id, o, d)));
    for (int r = 0; r < k_bad_rotation_count; ++r) {
        const i2d_transform bad = xform(0.0f, 0.0f, k_bad_rotations[r].c, k_bad_rotations[r].s);
        snprintf(what, sizeof what, "i2d_ray_cast_polygon rotation %s", k_bad_rotations[r].name);
        CHECK_PURE_REFUSED(what, missed(i2d_ray_cast_polygon(&square, bad, o, d)));
        snprintf(what, sizeof what, "i2d_ray_cast_capsule rotation %s", k_bad_rotations[r].name);
        CHECK_PURE_REFUSED(what, missed(i2d_ray_cast_capsule(&k_good_capsule, bad, o, d)));
    }
    for (int k = 0; k < NON_FINITE_COUNT; ++k) {
        const float x = k_non_finite[k];
        snprintf(what, sizeof what, "i2d_ray_cast_circle xf.p.x = %g", x);
        CHECK_PURE_REFUSED(what, missed(i2d_ray_cast_circle(&k_good_circle, xform(x, 0.0f, 1.0f, 0.0f), o, d)));
        snprintf(what, sizeof what, "i2d_ray_cast_segment origin.y = %g", x);
        CHECK_PURE_REFUSED(what, missed(i2d_ray_cast_segment(&k_good_segment, id, v2(0.0f, x), v2(0.0f, -10.0f))));
        snprintf(what, sizeof what, "i2d_ray_cast_polygon translation.x = %g", x);
        CHECK_PURE_REFUSED(what, missed(i2d_ray_cast_polygon(&square, id, o, v2(x, 0.0f))));
    }
    /* The same casts with valid input hit, so the refusals are about the input. */
    c = i2d_ray_cast_polygon(&square, id, o, d);
    CHECK_ACCEPTED("i2d_ray_cast_polygon valid", i2d_last_status());
    I2D_CHECK(c.hit);
    c = i2d_ray_cast_segment(&k_good_segment, id, v2(0.0f, 5.0f), v2(0.0f, -10.0f));
    CHECK_ACCEPTED("i2d_ray_cast_segment valid", i2d_last_status());
    I2D_CHECK(c.hit);
}
