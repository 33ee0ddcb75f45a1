/* SPDX-License-Identifier: MIT */
/* Any joint kind's def, made and created the same way by the C API's joint tests
 * (test_api_joints.c) and the API fuzzer (tests/fuzz/fuzz_api.cpp, which includes it as
 * C++): the default def of a kind, its cookie, the create call of its kind, and where
 * each kind's float settings are in its def. Static inline: each includer gets its own. */
#ifndef I2D_TESTS_ANY_JOINT_DEF_H
#define I2D_TESTS_ANY_JOINT_DEF_H

#include <impulse2d/impulse2d.h>

#include <stddef.h>
#include <stdint.h>
#include <string.h>

/* The kinds are I2D_JOINT_DISTANCE (0) to I2D_JOINT_WHEEL (7). */
enum { JOINT_KIND_COUNT = 8 };

/* Any kind's def. The base is every def's first member, so it is at the union's address. */
typedef union any_def {
    i2d_distance_joint_def distance;
    i2d_filter_joint_def filter;
    i2d_motor_joint_def motor;
    i2d_mouse_joint_def mouse;
    i2d_prismatic_joint_def prismatic;
    i2d_revolute_joint_def revolute;
    i2d_weld_joint_def weld;
    i2d_wheel_joint_def wheel;
} any_def;

static inline i2d_joint_base* base_of(any_def* d) { return &d->revolute.base; }

static inline any_def default_def(i2d_joint_type kind, i2d_body_id a, i2d_body_id b) {
    any_def d;
    memset(&d, 0, sizeof d);
    switch (kind) {
        case I2D_JOINT_DISTANCE: d.distance = i2d_default_distance_joint_def(); break;
        case I2D_JOINT_FILTER: d.filter = i2d_default_filter_joint_def(); break;
        case I2D_JOINT_MOTOR: d.motor = i2d_default_motor_joint_def(); break;
        case I2D_JOINT_MOUSE: d.mouse = i2d_default_mouse_joint_def(); break;
        case I2D_JOINT_PRISMATIC: d.prismatic = i2d_default_prismatic_joint_def(); break;
        case I2D_JOINT_REVOLUTE: d.revolute = i2d_default_revolute_joint_def(); break;
        case I2D_JOINT_WELD: d.weld = i2d_default_weld_joint_def(); break;
        case I2D_JOINT_WHEEL: d.wheel = i2d_default_wheel_joint_def(); break;
    }
    base_of(&d)->body_a = a;
    base_of(&d)->body_b = b;
    return d;
}

static inline uint32_t* cookie_of(any_def* d, i2d_joint_type kind) {
    switch (kind) {
        case I2D_JOINT_DISTANCE: return &d->distance.internal_cookie;
        case I2D_JOINT_FILTER: return &d->filter.internal_cookie;
        case I2D_JOINT_MOTOR: return &d->motor.internal_cookie;
        case I2D_JOINT_MOUSE: return &d->mouse.internal_cookie;
        case I2D_JOINT_PRISMATIC: return &d->prismatic.internal_cookie;
        case I2D_JOINT_REVOLUTE: return &d->revolute.internal_cookie;
        case I2D_JOINT_WELD: return &d->weld.internal_cookie;
        case I2D_JOINT_WHEEL: return &d->wheel.internal_cookie;
    }
    return NULL;
}

/* Creates a joint of the kind; def NULL passes NULL to the kind's create. */
static inline i2d_joint_id create_any(i2d_world_id world, i2d_joint_type kind, const any_def* d) {
    switch (kind) {
        case I2D_JOINT_DISTANCE: return i2d_joint_create_distance(world, d ? &d->distance : NULL);
        case I2D_JOINT_FILTER: return i2d_joint_create_filter(world, d ? &d->filter : NULL);
        case I2D_JOINT_MOTOR: return i2d_joint_create_motor(world, d ? &d->motor : NULL);
        case I2D_JOINT_MOUSE: return i2d_joint_create_mouse(world, d ? &d->mouse : NULL);
        case I2D_JOINT_PRISMATIC: return i2d_joint_create_prismatic(world, d ? &d->prismatic : NULL);
        case I2D_JOINT_REVOLUTE: return i2d_joint_create_revolute(world, d ? &d->revolute : NULL);
        case I2D_JOINT_WELD: return i2d_joint_create_weld(world, d ? &d->weld : NULL);
        case I2D_JOINT_WHEEL: return i2d_joint_create_wheel(world, d ? &d->wheel : NULL);
    }
    return I2D_NULL_JOINT_ID;
}

/* Where a float setting of a kind's def is, and its name as a refusal's message gives it. */
typedef struct def_float {
    i2d_joint_type kind;
    const char* name;  /* as the message names it */
    size_t offset;
} def_float;

#define DEF_FLOAT(KIND, type, field) {KIND, #field, offsetof(type, field)}

/* Every float of every kind's settings (not the base's), by kind. */
static const def_float k_def_floats[] = {
    DEF_FLOAT(I2D_JOINT_REVOLUTE, i2d_revolute_joint_def, reference_angle),
    DEF_FLOAT(I2D_JOINT_REVOLUTE, i2d_revolute_joint_def, lower_angle),
    DEF_FLOAT(I2D_JOINT_REVOLUTE, i2d_revolute_joint_def, upper_angle),
    DEF_FLOAT(I2D_JOINT_REVOLUTE, i2d_revolute_joint_def, motor_speed),
    DEF_FLOAT(I2D_JOINT_REVOLUTE, i2d_revolute_joint_def, max_motor_torque),
    DEF_FLOAT(I2D_JOINT_REVOLUTE, i2d_revolute_joint_def, hertz),
    DEF_FLOAT(I2D_JOINT_REVOLUTE, i2d_revolute_joint_def, damping_ratio),
    DEF_FLOAT(I2D_JOINT_REVOLUTE, i2d_revolute_joint_def, target_angle),
    DEF_FLOAT(I2D_JOINT_PRISMATIC, i2d_prismatic_joint_def, local_axis_a.x),
    DEF_FLOAT(I2D_JOINT_PRISMATIC, i2d_prismatic_joint_def, local_axis_a.y),
    DEF_FLOAT(I2D_JOINT_PRISMATIC, i2d_prismatic_joint_def, reference_angle),
    DEF_FLOAT(I2D_JOINT_PRISMATIC, i2d_prismatic_joint_def, lower_translation),
    DEF_FLOAT(I2D_JOINT_PRISMATIC, i2d_prismatic_joint_def, upper_translation),
    DEF_FLOAT(I2D_JOINT_PRISMATIC, i2d_prismatic_joint_def, motor_speed),
    DEF_FLOAT(I2D_JOINT_PRISMATIC, i2d_prismatic_joint_def, max_motor_force),
    DEF_FLOAT(I2D_JOINT_PRISMATIC, i2d_prismatic_joint_def, hertz),
    DEF_FLOAT(I2D_JOINT_PRISMATIC, i2d_prismatic_joint_def, damping_ratio),
    DEF_FLOAT(I2D_JOINT_PRISMATIC, i2d_prismatic_joint_def, target_translation),
    DEF_FLOAT(I2D_JOINT_DISTANCE, i2d_distance_joint_def, length),
    DEF_FLOAT(I2D_JOINT_DISTANCE, i2d_distance_joint_def, min_length),
    DEF_FLOAT(I2D_JOINT_DISTANCE, i2d_distance_joint_def, max_length),
    DEF_FLOAT(I2D_JOINT_DISTANCE, i2d_distance_joint_def, hertz),
    DEF_FLOAT(I2D_JOINT_DISTANCE, i2d_distance_joint_def, damping_ratio),
    DEF_FLOAT(I2D_JOINT_DISTANCE, i2d_distance_joint_def, motor_speed),
    DEF_FLOAT(I2D_JOINT_DISTANCE, i2d_distance_joint_def, max_motor_force),
    DEF_FLOAT(I2D_JOINT_WELD, i2d_weld_joint_def, reference_angle),
    DEF_FLOAT(I2D_JOINT_WELD, i2d_weld_joint_def, linear_hertz),
    DEF_FLOAT(I2D_JOINT_WELD, i2d_weld_joint_def, angular_hertz),
    DEF_FLOAT(I2D_JOINT_WELD, i2d_weld_joint_def, linear_damping_ratio),
    DEF_FLOAT(I2D_JOINT_WELD, i2d_weld_joint_def, angular_damping_ratio),
    DEF_FLOAT(I2D_JOINT_WHEEL, i2d_wheel_joint_def, local_axis_a.x),
    DEF_FLOAT(I2D_JOINT_WHEEL, i2d_wheel_joint_def, local_axis_a.y),
    DEF_FLOAT(I2D_JOINT_WHEEL, i2d_wheel_joint_def, hertz),
    DEF_FLOAT(I2D_JOINT_WHEEL, i2d_wheel_joint_def, damping_ratio),
    DEF_FLOAT(I2D_JOINT_WHEEL, i2d_wheel_joint_def, lower_translation),
    DEF_FLOAT(I2D_JOINT_WHEEL, i2d_wheel_joint_def, upper_translation),
    DEF_FLOAT(I2D_JOINT_WHEEL, i2d_wheel_joint_def, motor_speed),
    DEF_FLOAT(I2D_JOINT_WHEEL, i2d_wheel_joint_def, max_motor_torque),
    DEF_FLOAT(I2D_JOINT_MOTOR, i2d_motor_joint_def, linear_offset.x),
    DEF_FLOAT(I2D_JOINT_MOTOR, i2d_motor_joint_def, linear_offset.y),
    DEF_FLOAT(I2D_JOINT_MOTOR, i2d_motor_joint_def, angular_offset),
    DEF_FLOAT(I2D_JOINT_MOTOR, i2d_motor_joint_def, max_force),
    DEF_FLOAT(I2D_JOINT_MOTOR, i2d_motor_joint_def, max_torque),
    DEF_FLOAT(I2D_JOINT_MOTOR, i2d_motor_joint_def, correction_factor),
    DEF_FLOAT(I2D_JOINT_MOUSE, i2d_mouse_joint_def, target.x),
    DEF_FLOAT(I2D_JOINT_MOUSE, i2d_mouse_joint_def, target.y),
    DEF_FLOAT(I2D_JOINT_MOUSE, i2d_mouse_joint_def, hertz),
    DEF_FLOAT(I2D_JOINT_MOUSE, i2d_mouse_joint_def, damping_ratio),
    DEF_FLOAT(I2D_JOINT_MOUSE, i2d_mouse_joint_def, max_force),
};

enum { DEF_FLOAT_COUNT = (int)(sizeof k_def_floats / sizeof k_def_floats[0]) };

static inline void set_def_float(any_def* d, size_t offset, float value) {
    memcpy((char*)d + offset, &value, sizeof value);
}

#endif
