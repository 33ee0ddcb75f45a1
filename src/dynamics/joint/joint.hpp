// SPDX-License-Identifier: MIT
// Joint: a constraint between two bodies, its settings per kind, and what it keeps from
// step to step (accumulated impulses for warm starting, the last reaction).
//
// Design note: joints live in the joint set's pool (joint_set.hpp) and are linked to
// their bodies by two edges each, as contacts are, so that a body finds its joints and
// the islands follow them. The settings of all kinds share one record, one member per
// kind, so that the pool stays a plain array and the solver dispatches on `type` with
// a switch, never a virtual call.
#pragma once

#include <cfloat>
#include <cstdint>

#include "core/pool.hpp"
#include "math/vec2.hpp"

namespace i2d {

enum class JointType : uint8_t { distance, filter, motor, mouse, prismatic, revolute, weld, wheel, count };

struct RevoluteSettings {
    float reference_angle = 0.0f;
    bool enable_limit = false;
    float lower_angle = 0.0f, upper_angle = 0.0f;
    bool enable_motor = false;
    float motor_speed = 0.0f, max_motor_torque = 0.0f;
    bool enable_spring = false;
    float hertz = 0.0f, damping_ratio = 0.0f, target_angle = 0.0f;
};

struct PrismaticSettings {
    Vec2 local_axis_a{1.0f, 0.0f};  // unit length
    float reference_angle = 0.0f;
    bool enable_limit = false;
    float lower_translation = 0.0f, upper_translation = 0.0f;
    bool enable_motor = false;
    float motor_speed = 0.0f, max_motor_force = 0.0f;
    bool enable_spring = false;
    float hertz = 0.0f, damping_ratio = 0.0f, target_translation = 0.0f;
};

struct DistanceSettings {
    float length = 1.0f;
    bool enable_limit = false;
    float min_length = 0.0f, max_length = 1e5f;
    bool enable_spring = false;
    float hertz = 0.0f, damping_ratio = 0.0f;
    bool enable_motor = false;
    float motor_speed = 0.0f, max_motor_force = 0.0f;
};

struct WeldSettings {
    float reference_angle = 0.0f;
    float linear_hertz = 0.0f, angular_hertz = 0.0f;
    float linear_damping_ratio = 1.0f, angular_damping_ratio = 1.0f;
};

struct WheelSettings {
    Vec2 local_axis_a{0.0f, 1.0f};  // unit length
    bool enable_spring = true;
    float hertz = 1.0f, damping_ratio = 0.7f;
    bool enable_limit = false;
    float lower_translation = 0.0f, upper_translation = 0.0f;
    bool enable_motor = false;
    float motor_speed = 0.0f, max_motor_torque = 0.0f;
};

struct MotorSettings {
    Vec2 linear_offset;
    float angular_offset = 0.0f;
    float max_force = 1.0f, max_torque = 1.0f;
    float correction_factor = 0.3f;
};

struct MouseSettings {
    Vec2 target;
    float hertz = 4.0f, damping_ratio = 1.0f, max_force = 1000.0f;
};

/// What a joint was created with (the C API's def, checked and converted). Its angles
/// (reference_angle, target_angle, angular_offset) lie in (-pi, pi]: the C boundary winds
/// them (wind_angle), and the solver's single unwind_angle of a difference relies on it.
struct JointDef {
    JointType type = JointType::filter;
    int32_t body_a = null_index, body_b = null_index;
    Vec2 local_anchor_a, local_anchor_b;  // in each body's frame, from its origin
    bool collide_connected = false;
    float force_threshold = FLT_MAX, torque_threshold = FLT_MAX;
    void* user_data = nullptr;
    // The member of `type`'s kind is the one read.
    RevoluteSettings revolute;
    PrismaticSettings prismatic;
    DistanceSettings distance;
    WeldSettings weld;
    WheelSettings wheel;
    MotorSettings motor;
    MouseSettings mouse;
};

/// A joint's link from one of its bodies: the body's joints form a list through these.
struct JointEdge {
    int32_t body = null_index;
    int32_t prev_key = null_index, next_key = null_index;  // key = joint * 2 + side
};

/// Impulses accumulated over the last substep, N s: the warm start of the next step and,
/// over h, the reaction.
struct JointImpulses {
    Vec2 linear;          // point constraint (revolute, weld, motor, mouse), or
                          // (perpendicular, angular) of prismatic and wheel
    float angular = 0.0f;  // weld and motor angle; mouse spin damping
    float axial = 0.0f;    // distance rod or spring; prismatic/wheel spring
    float spring = 0.0f;   // revolute spring
    float motor = 0.0f;
    float lower = 0.0f, upper = 0.0f;
};

// Line-aligned, with what every step writes first: the solver's prepare and store then
// touch the first two lines of a plain hinge (its impulses, kind, bodies, anchors,
// thresholds and settings flags) and no other.
struct alignas(64) Joint {
    JointImpulses impulses;
    Vec2 reaction_force;           // on body B over the last step, N
    float reaction_torque = 0.0f;  // N m
    float motor_output = 0.0f;     // the motor's force (N) or torque (N m) over the last step
    JointDef def;
    JointEdge edges[2];
    int32_t solver_index = null_index;  // in this step's solver list; null when not solved
    bool island_link = false;  // joins the islands of its two bodies
};

/// Whether the def's angles lie in (-pi, pi], as the solver's single unwind_angle needs
/// (joint_constraint.hpp): the C boundary stores them wound (joint_set.cpp).
bool angles_wound(const JointDef& def);

/// What a caller reads of a joint as its bodies stand (not as the solver last saw them).
struct JointMeasures {
    float angle = 0.0f;        // rad, B relative to A minus the reference, in (-pi, pi]
    float translation = 0.0f;  // m along the axis (prismatic, wheel)
    float speed = 0.0f;        // m/s along the axis (prismatic, wheel)
    float length = 0.0f;       // m between the anchors
};

}  // namespace i2d
