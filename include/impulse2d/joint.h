/* SPDX-License-Identifier: MIT */
/* Joints: constraints between two bodies, solved in the same soft step as contacts.
 *
 * A joint holds two bodies at anchor points given in each body's frame (relative to the
 * body origin). Rigid parts of a joint are soft constraints as stiff as the substep
 * allows (i2d_world_def.joint_hertz); springs, limits and motors are exact within the
 * step. Joined bodies share an island: they sleep and wake together, and by default
 * (collide_connected false) they do not collide with each other.
 *
 * Creation follows the rest of the API: a def from i2d_default_<kind>_joint_def(),
 * edited, then i2d_joint_create_<kind>(). A joint needs two different bodies of one
 * world, at least one of them dynamic. Destroying a body destroys its joints. Every
 * setter checks its value as the def would, wakes the two bodies, and is refused with
 * I2D_ERR_WORLD_LOCKED inside a callback. The angles that take any finite value
 * (reference_angle, target_angle, angular_offset) are stored wound into (-pi, pi], by
 * def and setter alike: the same pose, and what their getters read back. Getters on a
 * stale id, or on a joint of another kind, return a zero value and record
 * I2D_ERR_INVALID_HANDLE or I2D_ERR_INVALID_ARGUMENT. */
#ifndef IMPULSE2D_JOINT_H
#define IMPULSE2D_JOINT_H

#include "base.h"
#include "id.h"
#include "types.h"

typedef struct i2d_joint_id { uint64_t bits; } i2d_joint_id;

#ifdef __cplusplus
#define I2D_NULL_JOINT_ID (i2d_joint_id{0})
#else
#define I2D_NULL_JOINT_ID ((i2d_joint_id){0})
#endif

typedef enum i2d_joint_type {
    I2D_JOINT_DISTANCE = 0, /**< keeps two points at a length, or within a range (a rope) */
    I2D_JOINT_FILTER,       /**< no constraint: only stops the two bodies colliding */
    I2D_JOINT_MOTOR,        /**< drives B toward an offset pose in A's frame */
    I2D_JOINT_MOUSE,        /**< pulls a point of B toward a target (dragging with a mouse) */
    I2D_JOINT_PRISMATIC,    /**< B slides along an axis fixed in A, without turning */
    I2D_JOINT_REVOLUTE,     /**< a hinge: one shared point, free to turn */
    I2D_JOINT_WELD,         /**< holds B's pose in A's frame, rigid or springy */
    I2D_JOINT_WHEEL         /**< B slides on a spring along an axis of A and turns freely */
} i2d_joint_type;

/** The first member of every joint def. */
typedef struct i2d_joint_base {
    i2d_body_id body_a, body_b;
    /** m, in each body's frame (relative to its origin); default (0, 0). Within 1e5 m. */
    i2d_vec2 local_anchor_a, local_anchor_b;
    /** Whether the two bodies may still collide with each other; default false. */
    bool collide_connected;
    /** A joint whose reaction force (N) or torque (N m) passes these after a step is
     *  listed by i2d_world_get_joint_events; default FLT_MAX (never). Range [0, FLT_MAX]. */
    float force_threshold, torque_threshold;
    void* user_data;
} i2d_joint_base;

/** A hinge at the anchors. Angles are of B relative to A, minus reference_angle. */
typedef struct i2d_revolute_joint_def {
    i2d_joint_base base;
    /** rad: angle_b - angle_a when the joint angle is 0; default 0; any finite angle;
     *  stored wound into (-pi, pi] */
    float reference_angle;
    bool enable_limit;          /**< default false */
    float lower_angle, upper_angle;  /**< rad, lower <= upper, within [-0.99 pi, 0.99 pi] */
    bool enable_motor;          /**< default false */
    float motor_speed;          /**< rad/s */
    float max_motor_torque;     /**< N m, >= 0 */
    bool enable_spring;         /**< default false: a spring toward target_angle */
    float hertz, damping_ratio; /**< Hz and ratio, range [0, 1e5]; default 0 */
    float target_angle;         /**< rad; any finite angle; stored wound into (-pi, pi] */
    uint32_t internal_cookie;
} i2d_revolute_joint_def;

/** B slides along local_axis_a (in A's frame) and keeps its angle relative to A. */
typedef struct i2d_prismatic_joint_def {
    i2d_joint_base base;
    i2d_vec2 local_axis_a;      /**< default (1, 0); normalised, must not be zero */
    float reference_angle;      /**< rad; any finite angle; stored wound into (-pi, pi] */
    bool enable_limit;
    float lower_translation, upper_translation;  /**< m, finite, lower <= upper */
    bool enable_motor;
    float motor_speed;          /**< m/s */
    float max_motor_force;      /**< N, >= 0 */
    bool enable_spring;
    float hertz, damping_ratio; /**< range [0, 1e5] */
    float target_translation;   /**< m */
    uint32_t internal_cookie;
} i2d_prismatic_joint_def;

/** Keeps the anchors `length` apart (a rod), or springy, or within [min, max] (a rope:
 *  enable_spring with hertz 0 and enable_limit with min_length 0). */
typedef struct i2d_distance_joint_def {
    i2d_joint_base base;
    float length;               /**< rest length, m; default 1; range [0.005, 1e5] */
    bool enable_limit;
    /** m, 0 <= min <= max (FLT_MAX: no maximum); default 0 and 1e5. Clamped to
     *  [0.005, 1e5] when stored, so a getter reads 0.005 for a minimum of 0. */
    float min_length, max_length;
    bool enable_spring;         /**< default false: a rigid rod */
    float hertz, damping_ratio; /**< range [0, 1e5] */
    bool enable_motor;
    float motor_speed;          /**< m/s, positive lengthens */
    float max_motor_force;      /**< N, >= 0 */
    uint32_t internal_cookie;
} i2d_distance_joint_def;

/** Holds B's pose relative to A; hertz 0 makes that part rigid. */
typedef struct i2d_weld_joint_def {
    i2d_joint_base base;
    float reference_angle;      /**< rad; any finite angle; stored wound into (-pi, pi] */
    float linear_hertz, angular_hertz;               /**< range [0, 1e5]; default 0 */
    float linear_damping_ratio, angular_damping_ratio;  /**< range [0, 1e5]; default 1 */
    uint32_t internal_cookie;
} i2d_weld_joint_def;

/** A vehicle wheel: B (the wheel) on a spring along local_axis_a (the suspension) of A
 *  (the chassis), free to turn, with a motor on the turning. */
typedef struct i2d_wheel_joint_def {
    i2d_joint_base base;
    i2d_vec2 local_axis_a;      /**< default (0, 1); normalised, must not be zero */
    bool enable_spring;         /**< default true */
    float hertz, damping_ratio; /**< default 1 Hz and 0.7; range [0, 1e5] */
    bool enable_limit;
    float lower_translation, upper_translation;  /**< m, finite, lower <= upper */
    bool enable_motor;
    float motor_speed;          /**< rad/s */
    float max_motor_torque;     /**< N m, >= 0 */
    uint32_t internal_cookie;
} i2d_wheel_joint_def;

/** Drives B toward the pose (linear_offset, angular_offset) in A's frame (of B's origin),
 *  with at most max_force and max_torque. */
typedef struct i2d_motor_joint_def {
    i2d_joint_base base;
    i2d_vec2 linear_offset;     /**< m, within 1e9 */
    float angular_offset;       /**< rad; any finite angle; stored wound into (-pi, pi] */
    float max_force;            /**< N, default 1 */
    float max_torque;           /**< N m, default 1 */
    float correction_factor;    /**< share of the pose error removed per step, [0, 1]; default 0.3 */
    uint32_t internal_cookie;
} i2d_motor_joint_def;

/** Pulls B's anchor (base.local_anchor_b) toward a world point with a damped spring of
 *  at most max_force: stiffness m (2 pi hertz)^2 and damping 2 m damping_ratio (2 pi
 *  hertz), m the mass of B, the same wherever B is held, so B hangs g / (2 pi hertz)^2
 *  below the target and a box dragged over a floor of friction mu stops within
 *  mu g / (2 pi hertz)^2 of it. body_a is any body of the world (often a static one); it
 *  is not moved. Like every joint it stops its two bodies colliding unless
 *  base.collide_connected: make body_a a body without shapes, not the ground B lies on.
 *  body_b must be dynamic. */
typedef struct i2d_mouse_joint_def {
    i2d_joint_base base;
    i2d_vec2 target;            /**< m, world, within 1e9 */
    float hertz;                /**< default 4; range [0, 1e5] */
    float damping_ratio;        /**< default 1; range [0, 1e5] */
    float max_force;            /**< N, default 1000 */
    uint32_t internal_cookie;
} i2d_mouse_joint_def;

/** No constraint: only keeps the two bodies from colliding. */
typedef struct i2d_filter_joint_def {
    i2d_joint_base base;
    uint32_t internal_cookie;
} i2d_filter_joint_def;

I2D_API i2d_revolute_joint_def i2d_default_revolute_joint_def(void);
I2D_API i2d_prismatic_joint_def i2d_default_prismatic_joint_def(void);
I2D_API i2d_distance_joint_def i2d_default_distance_joint_def(void);
I2D_API i2d_weld_joint_def i2d_default_weld_joint_def(void);
I2D_API i2d_wheel_joint_def i2d_default_wheel_joint_def(void);
I2D_API i2d_motor_joint_def i2d_default_motor_joint_def(void);
I2D_API i2d_mouse_joint_def i2d_default_mouse_joint_def(void);
I2D_API i2d_filter_joint_def i2d_default_filter_joint_def(void);

/** Null id and a status on a bad def: a NULL def or one not from its default function,
 *  same body twice, bodies of two worlds (or not of `world`), no dynamic body, a stale
 *  body id, NaN or inf anywhere, a value out of range; I2D_ERR_WORLD_LOCKED inside a
 *  callback. */
I2D_API i2d_joint_id i2d_joint_create_revolute(i2d_world_id world, const i2d_revolute_joint_def* def);
I2D_API i2d_joint_id i2d_joint_create_prismatic(i2d_world_id world, const i2d_prismatic_joint_def* def);
I2D_API i2d_joint_id i2d_joint_create_distance(i2d_world_id world, const i2d_distance_joint_def* def);
I2D_API i2d_joint_id i2d_joint_create_weld(i2d_world_id world, const i2d_weld_joint_def* def);
I2D_API i2d_joint_id i2d_joint_create_wheel(i2d_world_id world, const i2d_wheel_joint_def* def);
I2D_API i2d_joint_id i2d_joint_create_motor(i2d_world_id world, const i2d_motor_joint_def* def);
I2D_API i2d_joint_id i2d_joint_create_mouse(i2d_world_id world, const i2d_mouse_joint_def* def);
I2D_API i2d_joint_id i2d_joint_create_filter(i2d_world_id world, const i2d_filter_joint_def* def);

/** Wakes the two bodies; they may collide again. */
I2D_API i2d_status i2d_joint_destroy(i2d_joint_id joint);
I2D_API bool i2d_joint_is_valid(i2d_joint_id joint);
I2D_API i2d_joint_type i2d_joint_get_type(i2d_joint_id joint);
I2D_API i2d_world_id i2d_joint_get_world(i2d_joint_id joint);
I2D_API i2d_body_id i2d_joint_get_body_a(i2d_joint_id joint);
I2D_API i2d_body_id i2d_joint_get_body_b(i2d_joint_id joint);
I2D_API i2d_vec2 i2d_joint_get_local_anchor_a(i2d_joint_id joint);
I2D_API i2d_vec2 i2d_joint_get_local_anchor_b(i2d_joint_id joint);
I2D_API i2d_status i2d_joint_set_local_anchor_a(i2d_joint_id joint, i2d_vec2 anchor);
I2D_API i2d_status i2d_joint_set_local_anchor_b(i2d_joint_id joint, i2d_vec2 anchor);
I2D_API bool i2d_joint_get_collide_connected(i2d_joint_id joint);
I2D_API i2d_status i2d_joint_set_collide_connected(i2d_joint_id joint, bool collide);
I2D_API float i2d_joint_get_force_threshold(i2d_joint_id joint);
I2D_API i2d_status i2d_joint_set_force_threshold(i2d_joint_id joint, float threshold);
I2D_API float i2d_joint_get_torque_threshold(i2d_joint_id joint);
I2D_API i2d_status i2d_joint_set_torque_threshold(i2d_joint_id joint, float threshold);
/** The force the joint applied to body B in the last step, N (on A: its negative). */
I2D_API i2d_vec2 i2d_joint_get_reaction_force(i2d_joint_id joint);
/** The torque the joint applied to body B in the last step, N m, about B's centre of
 *  mass and beyond that of the force. */
I2D_API float i2d_joint_get_reaction_torque(i2d_joint_id joint);
I2D_API void* i2d_joint_get_user_data(i2d_joint_id joint);
/** Allowed inside callbacks. */
I2D_API i2d_status i2d_joint_set_user_data(i2d_joint_id joint, void* user_data);
/** Wakes the two bodies. */
I2D_API i2d_status i2d_joint_wake_bodies(i2d_joint_id joint);

/* ---- Revolute ---- */
/** rad, B relative to A minus the reference angle, in (-pi, pi]. */
I2D_API float i2d_revolute_joint_get_angle(i2d_joint_id joint);
/** The motor's torque in the last step, N m. */
I2D_API float i2d_revolute_joint_get_motor_torque(i2d_joint_id joint);
I2D_API float i2d_revolute_joint_get_reference_angle(i2d_joint_id joint);
I2D_API i2d_status i2d_revolute_joint_set_reference_angle(i2d_joint_id joint, float angle);
I2D_API bool i2d_revolute_joint_get_enable_limit(i2d_joint_id joint);
I2D_API i2d_status i2d_revolute_joint_set_enable_limit(i2d_joint_id joint, bool enable);
I2D_API float i2d_revolute_joint_get_lower_angle(i2d_joint_id joint);
/** Refused when it would pass the upper angle (and the upper setter the lower one; the
 *  same for every kind's single-bound setters). */
I2D_API i2d_status i2d_revolute_joint_set_lower_angle(i2d_joint_id joint, float angle);
I2D_API float i2d_revolute_joint_get_upper_angle(i2d_joint_id joint);
I2D_API i2d_status i2d_revolute_joint_set_upper_angle(i2d_joint_id joint, float angle);
/** Both at once: lower <= upper. */
I2D_API i2d_status i2d_revolute_joint_set_limits(i2d_joint_id joint, float lower, float upper);
I2D_API bool i2d_revolute_joint_get_enable_motor(i2d_joint_id joint);
I2D_API i2d_status i2d_revolute_joint_set_enable_motor(i2d_joint_id joint, bool enable);
I2D_API float i2d_revolute_joint_get_motor_speed(i2d_joint_id joint);
I2D_API i2d_status i2d_revolute_joint_set_motor_speed(i2d_joint_id joint, float speed);
I2D_API float i2d_revolute_joint_get_max_motor_torque(i2d_joint_id joint);
I2D_API i2d_status i2d_revolute_joint_set_max_motor_torque(i2d_joint_id joint, float torque);
I2D_API bool i2d_revolute_joint_get_enable_spring(i2d_joint_id joint);
I2D_API i2d_status i2d_revolute_joint_set_enable_spring(i2d_joint_id joint, bool enable);
I2D_API float i2d_revolute_joint_get_hertz(i2d_joint_id joint);
I2D_API i2d_status i2d_revolute_joint_set_hertz(i2d_joint_id joint, float hertz);
I2D_API float i2d_revolute_joint_get_damping_ratio(i2d_joint_id joint);
I2D_API i2d_status i2d_revolute_joint_set_damping_ratio(i2d_joint_id joint, float ratio);
I2D_API float i2d_revolute_joint_get_target_angle(i2d_joint_id joint);
I2D_API i2d_status i2d_revolute_joint_set_target_angle(i2d_joint_id joint, float angle);

/* ---- Prismatic ---- */
/** m along the axis, of B's anchor from A's. */
I2D_API float i2d_prismatic_joint_get_translation(i2d_joint_id joint);
/** m/s along the axis. */
I2D_API float i2d_prismatic_joint_get_speed(i2d_joint_id joint);
/** The motor's force in the last step, N. */
I2D_API float i2d_prismatic_joint_get_motor_force(i2d_joint_id joint);
I2D_API i2d_vec2 i2d_prismatic_joint_get_local_axis_a(i2d_joint_id joint);
I2D_API i2d_status i2d_prismatic_joint_set_local_axis_a(i2d_joint_id joint, i2d_vec2 axis);
I2D_API float i2d_prismatic_joint_get_reference_angle(i2d_joint_id joint);
I2D_API i2d_status i2d_prismatic_joint_set_reference_angle(i2d_joint_id joint, float angle);
I2D_API bool i2d_prismatic_joint_get_enable_limit(i2d_joint_id joint);
I2D_API i2d_status i2d_prismatic_joint_set_enable_limit(i2d_joint_id joint, bool enable);
I2D_API float i2d_prismatic_joint_get_lower_translation(i2d_joint_id joint);
I2D_API i2d_status i2d_prismatic_joint_set_lower_translation(i2d_joint_id joint, float translation);
I2D_API float i2d_prismatic_joint_get_upper_translation(i2d_joint_id joint);
I2D_API i2d_status i2d_prismatic_joint_set_upper_translation(i2d_joint_id joint, float translation);
I2D_API i2d_status i2d_prismatic_joint_set_limits(i2d_joint_id joint, float lower, float upper);
I2D_API bool i2d_prismatic_joint_get_enable_motor(i2d_joint_id joint);
I2D_API i2d_status i2d_prismatic_joint_set_enable_motor(i2d_joint_id joint, bool enable);
I2D_API float i2d_prismatic_joint_get_motor_speed(i2d_joint_id joint);
I2D_API i2d_status i2d_prismatic_joint_set_motor_speed(i2d_joint_id joint, float speed);
I2D_API float i2d_prismatic_joint_get_max_motor_force(i2d_joint_id joint);
I2D_API i2d_status i2d_prismatic_joint_set_max_motor_force(i2d_joint_id joint, float force);
I2D_API bool i2d_prismatic_joint_get_enable_spring(i2d_joint_id joint);
I2D_API i2d_status i2d_prismatic_joint_set_enable_spring(i2d_joint_id joint, bool enable);
I2D_API float i2d_prismatic_joint_get_hertz(i2d_joint_id joint);
I2D_API i2d_status i2d_prismatic_joint_set_hertz(i2d_joint_id joint, float hertz);
I2D_API float i2d_prismatic_joint_get_damping_ratio(i2d_joint_id joint);
I2D_API i2d_status i2d_prismatic_joint_set_damping_ratio(i2d_joint_id joint, float ratio);
I2D_API float i2d_prismatic_joint_get_target_translation(i2d_joint_id joint);
I2D_API i2d_status i2d_prismatic_joint_set_target_translation(i2d_joint_id joint, float translation);

/* ---- Distance ---- */
/** m, between the two anchors now. */
I2D_API float i2d_distance_joint_get_current_length(i2d_joint_id joint);
/** The motor's force in the last step, N. */
I2D_API float i2d_distance_joint_get_motor_force(i2d_joint_id joint);
I2D_API float i2d_distance_joint_get_length(i2d_joint_id joint);
I2D_API i2d_status i2d_distance_joint_set_length(i2d_joint_id joint, float length);
I2D_API bool i2d_distance_joint_get_enable_limit(i2d_joint_id joint);
I2D_API i2d_status i2d_distance_joint_set_enable_limit(i2d_joint_id joint, bool enable);
I2D_API float i2d_distance_joint_get_min_length(i2d_joint_id joint);
I2D_API i2d_status i2d_distance_joint_set_min_length(i2d_joint_id joint, float length);
I2D_API float i2d_distance_joint_get_max_length(i2d_joint_id joint);
I2D_API i2d_status i2d_distance_joint_set_max_length(i2d_joint_id joint, float length);
I2D_API i2d_status i2d_distance_joint_set_length_range(i2d_joint_id joint, float min_length, float max_length);
I2D_API bool i2d_distance_joint_get_enable_spring(i2d_joint_id joint);
I2D_API i2d_status i2d_distance_joint_set_enable_spring(i2d_joint_id joint, bool enable);
I2D_API float i2d_distance_joint_get_hertz(i2d_joint_id joint);
I2D_API i2d_status i2d_distance_joint_set_hertz(i2d_joint_id joint, float hertz);
I2D_API float i2d_distance_joint_get_damping_ratio(i2d_joint_id joint);
I2D_API i2d_status i2d_distance_joint_set_damping_ratio(i2d_joint_id joint, float ratio);
I2D_API bool i2d_distance_joint_get_enable_motor(i2d_joint_id joint);
I2D_API i2d_status i2d_distance_joint_set_enable_motor(i2d_joint_id joint, bool enable);
I2D_API float i2d_distance_joint_get_motor_speed(i2d_joint_id joint);
I2D_API i2d_status i2d_distance_joint_set_motor_speed(i2d_joint_id joint, float speed);
I2D_API float i2d_distance_joint_get_max_motor_force(i2d_joint_id joint);
I2D_API i2d_status i2d_distance_joint_set_max_motor_force(i2d_joint_id joint, float force);

/* ---- Weld ---- */
I2D_API float i2d_weld_joint_get_reference_angle(i2d_joint_id joint);
I2D_API i2d_status i2d_weld_joint_set_reference_angle(i2d_joint_id joint, float angle);
I2D_API float i2d_weld_joint_get_linear_hertz(i2d_joint_id joint);
I2D_API i2d_status i2d_weld_joint_set_linear_hertz(i2d_joint_id joint, float hertz);
I2D_API float i2d_weld_joint_get_angular_hertz(i2d_joint_id joint);
I2D_API i2d_status i2d_weld_joint_set_angular_hertz(i2d_joint_id joint, float hertz);
I2D_API float i2d_weld_joint_get_linear_damping_ratio(i2d_joint_id joint);
I2D_API i2d_status i2d_weld_joint_set_linear_damping_ratio(i2d_joint_id joint, float ratio);
I2D_API float i2d_weld_joint_get_angular_damping_ratio(i2d_joint_id joint);
I2D_API i2d_status i2d_weld_joint_set_angular_damping_ratio(i2d_joint_id joint, float ratio);

/* ---- Wheel ---- */
/** The motor's torque in the last step, N m. */
I2D_API float i2d_wheel_joint_get_motor_torque(i2d_joint_id joint);
/** m along the axis (the suspension's travel). */
I2D_API float i2d_wheel_joint_get_translation(i2d_joint_id joint);
I2D_API i2d_vec2 i2d_wheel_joint_get_local_axis_a(i2d_joint_id joint);
I2D_API i2d_status i2d_wheel_joint_set_local_axis_a(i2d_joint_id joint, i2d_vec2 axis);
I2D_API bool i2d_wheel_joint_get_enable_spring(i2d_joint_id joint);
I2D_API i2d_status i2d_wheel_joint_set_enable_spring(i2d_joint_id joint, bool enable);
I2D_API float i2d_wheel_joint_get_hertz(i2d_joint_id joint);
I2D_API i2d_status i2d_wheel_joint_set_hertz(i2d_joint_id joint, float hertz);
I2D_API float i2d_wheel_joint_get_damping_ratio(i2d_joint_id joint);
I2D_API i2d_status i2d_wheel_joint_set_damping_ratio(i2d_joint_id joint, float ratio);
I2D_API bool i2d_wheel_joint_get_enable_limit(i2d_joint_id joint);
I2D_API i2d_status i2d_wheel_joint_set_enable_limit(i2d_joint_id joint, bool enable);
I2D_API float i2d_wheel_joint_get_lower_translation(i2d_joint_id joint);
I2D_API i2d_status i2d_wheel_joint_set_lower_translation(i2d_joint_id joint, float translation);
I2D_API float i2d_wheel_joint_get_upper_translation(i2d_joint_id joint);
I2D_API i2d_status i2d_wheel_joint_set_upper_translation(i2d_joint_id joint, float translation);
I2D_API i2d_status i2d_wheel_joint_set_limits(i2d_joint_id joint, float lower, float upper);
I2D_API bool i2d_wheel_joint_get_enable_motor(i2d_joint_id joint);
I2D_API i2d_status i2d_wheel_joint_set_enable_motor(i2d_joint_id joint, bool enable);
I2D_API float i2d_wheel_joint_get_motor_speed(i2d_joint_id joint);
I2D_API i2d_status i2d_wheel_joint_set_motor_speed(i2d_joint_id joint, float speed);
I2D_API float i2d_wheel_joint_get_max_motor_torque(i2d_joint_id joint);
I2D_API i2d_status i2d_wheel_joint_set_max_motor_torque(i2d_joint_id joint, float torque);

/* ---- Motor ---- */
I2D_API i2d_vec2 i2d_motor_joint_get_linear_offset(i2d_joint_id joint);
I2D_API i2d_status i2d_motor_joint_set_linear_offset(i2d_joint_id joint, i2d_vec2 offset);
I2D_API float i2d_motor_joint_get_angular_offset(i2d_joint_id joint);
I2D_API i2d_status i2d_motor_joint_set_angular_offset(i2d_joint_id joint, float offset);
I2D_API float i2d_motor_joint_get_max_force(i2d_joint_id joint);
I2D_API i2d_status i2d_motor_joint_set_max_force(i2d_joint_id joint, float force);
I2D_API float i2d_motor_joint_get_max_torque(i2d_joint_id joint);
I2D_API i2d_status i2d_motor_joint_set_max_torque(i2d_joint_id joint, float torque);
I2D_API float i2d_motor_joint_get_correction_factor(i2d_joint_id joint);
I2D_API i2d_status i2d_motor_joint_set_correction_factor(i2d_joint_id joint, float factor);

/* ---- Mouse ---- */
I2D_API i2d_vec2 i2d_mouse_joint_get_target(i2d_joint_id joint);
I2D_API i2d_status i2d_mouse_joint_set_target(i2d_joint_id joint, i2d_vec2 target);
I2D_API float i2d_mouse_joint_get_hertz(i2d_joint_id joint);
I2D_API i2d_status i2d_mouse_joint_set_hertz(i2d_joint_id joint, float hertz);
I2D_API float i2d_mouse_joint_get_damping_ratio(i2d_joint_id joint);
I2D_API i2d_status i2d_mouse_joint_set_damping_ratio(i2d_joint_id joint, float ratio);
I2D_API float i2d_mouse_joint_get_max_force(i2d_joint_id joint);
I2D_API i2d_status i2d_mouse_joint_set_max_force(i2d_joint_id joint, float force);

/* ---- Joint events ---- */
/** A joint whose reaction force or torque passed its threshold in the last step (a
 *  breakable joint: destroy it between steps). */
typedef struct i2d_joint_event {
    i2d_joint_id joint;
    void* user_data;
} i2d_joint_event;
typedef struct i2d_joint_events {
    const i2d_joint_event* events;
    int32_t count;
} i2d_joint_events;
/** Valid until the next step or the world's destruction; the same order every run. */
I2D_API i2d_joint_events i2d_world_get_joint_events(i2d_world_id world);
/** Joints alive in the world; 0 for an invalid id. */
I2D_API int32_t i2d_world_get_joint_count(i2d_world_id world);

#endif
