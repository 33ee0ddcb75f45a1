// SPDX-License-Identifier: MIT
// The joints' settings as one table: for every field of every kind, the rule that checks a
// caller's value, stores it in the core's JointDef and reads it back.
//
// Design note: the defaults, the def checks and conversions, and the 130 getters and
// setters are all generated from the field lists below (X-macros), so a field is named
// once with its rule and every path that touches it applies the same check. What spans
// two fields (lower <= upper, min <= max) is checked by ordered_bounds on the whole
// settings after the change, so a single-bound setter is held to the current other bound.
#pragma once

#include <cfloat>
#include <cmath>

#include "boundary.hpp"
#include "convert.hpp"
#include "limits.hpp"
#include "dynamics/joint/joint.hpp"
#include "math/trig.hpp"

namespace i2d::capi::joint_rules {

static_assert(int(I2D_JOINT_DISTANCE) == int(JointType::distance) && int(I2D_JOINT_FILTER) == int(JointType::filter) &&
                  int(I2D_JOINT_MOTOR) == int(JointType::motor) && int(I2D_JOINT_MOUSE) == int(JointType::mouse) &&
                  int(I2D_JOINT_PRISMATIC) == int(JointType::prismatic) &&
                  int(I2D_JOINT_REVOLUTE) == int(JointType::revolute) && int(I2D_JOINT_WELD) == int(JointType::weld) &&
                  int(I2D_JOINT_WHEEL) == int(JointType::wheel),
              "the public joint types are the core's");

constexpr float pi = 3.14159265f;
/// Revolute limits stay short of half a turn either way: at +-pi the measured angle wraps,
/// so a limit there would flip from one side to the other.
constexpr float max_revolute_limit = 0.99f * pi;
/// Shortest distance joint length, m: the contact slop. Below it the direction between
/// the anchors, along which the joint pushes, is rounding noise.
constexpr float min_distance_length = 0.005f;
/// Longest distance joint length, m: max_shape_extent, the reach of a body's anchors.
constexpr float max_distance_length = 1.0e5f;
/// Shortest axis a caller may give before it is normalised; shorter is taken to be a zero
/// axis by mistake (its direction would be rounding noise).
constexpr double min_axis_length = 1.0e-6;

// Each rule: Public (the C type), check (the caller's value, message naming `what`), store
// (into the core) and out (back to the caller).

/// Any finite number: speeds, targets, translations.
struct Finite {
    using Public = float;
    static bool check(Call& call, float v, const char* what) { return call.finite(v, what); }
    static float store(float v) { return v; }
    static float out(float v) { return v; }
};

/// An angle a joint holds relative to: any finite number, stored wound into (-pi, pi]
/// (wind_angle: the same pose, and the getter reads that). The solver winds angle minus
/// this once (unwind_angle), which lands in (-pi, pi] only when both were there; angles
/// already in range keep every bit. Defs and setters alike store through here.
struct Angle : Finite {
    static float store(float v) { return wind_angle(v); }
};

/// Forces, torques and thresholds: [0, FLT_MAX] (FLT_MAX: unlimited).
struct NonNegative : Finite {
    static bool check(Call& call, float v, const char* what) { return call.in_range(v, 0.0f, FLT_MAX, what); }
};

/// Stiffness (Hz) and damping ratios: [0, max_setting], as the world's contact settings.
struct Spring : Finite {
    static bool check(Call& call, float v, const char* what) { return call.in_range(v, 0.0f, max_setting, what); }
};

/// Share of an error removed per step: [0, 1].
struct Share : Finite {
    static bool check(Call& call, float v, const char* what) { return call.in_range(v, 0.0f, 1.0f, what); }
};

struct RevoluteBound : Finite {
    static bool check(Call& call, float v, const char* what) {
        return call.in_range(v, -max_revolute_limit, max_revolute_limit, what);
    }
};

/// A distance joint's rest length.
struct DistanceLength : Finite {
    static bool check(Call& call, float v, const char* what) {
        return call.in_range(v, min_distance_length, max_distance_length, what);
    }
};

/// A distance joint's min or max length: any finite value >= 0 (FLT_MAX: no maximum),
/// clamped into the lengths the joint can hold.
struct DistanceBound : Finite {
    static bool check(Call& call, float v, const char* what) { return call.in_range(v, 0.0f, FLT_MAX, what); }
    static float store(float v) { return std::fmin(std::fmax(v, min_distance_length), max_distance_length); }
};

struct Flag {
    using Public = bool;
    static bool check(Call&, bool, const char*) { return true; }
    static bool store(bool v) { return v; }
    static bool out(bool v) { return v; }
};

/// A world point or offset: finite and within max_coordinate.
struct Point {
    using Public = i2d_vec2;
    static bool check(Call& call, i2d_vec2 v, const char* what) { return call.coordinate(v, what); }
    static Vec2 store(i2d_vec2 v) { return capi::to_core(v); }
    static i2d_vec2 out(Vec2 v) { return to_public(v); }
};

/// A direction: finite and not zero; stored at unit length.
struct Axis : Point {
    static bool check(Call& call, i2d_vec2 v, const char* what) {
        if (!call.finite(v, what)) {
            return false;
        }
        // In double: the square of a large finite float overflows float.
        if (std::hypot(double(v.x), double(v.y)) < min_axis_length) {
            return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s (%g, %g) is zero; it must give a direction", what,
                             static_cast<double>(v.x), static_cast<double>(v.y));
        }
        return true;
    }
    static Vec2 store(i2d_vec2 v) {
        const double length = std::hypot(double(v.x), double(v.y));
        return {float(double(v.x) / length), float(double(v.y) / length)};
    }
};

/// How far from unit length a stored axis may be: store() divides in double, so its float
/// result is unit to within an ulp or two.
constexpr float stored_axis_tolerance = 1.0e-6f;

/// Whether a core value is one the rule's store() gives (a snapshot's value is checked by
/// the rule's check on out(v), then by this).
template <class Rule, class T>
bool stored_form(const T& v) {
    return Rule::store(Rule::out(v)) == v;
}
template <>
inline bool stored_form<Axis, Vec2>(const Vec2& v) {
    return std::fabs(length(v) - 1.0f) <= stored_axis_tolerance;
}

// X(kind, field, Rule) for every setting of each kind, in the public def's order.
#define I2D_REVOLUTE_FIELDS(X)                  \
    X(revolute, reference_angle, Angle)         \
    X(revolute, enable_limit, Flag)             \
    X(revolute, lower_angle, RevoluteBound)     \
    X(revolute, upper_angle, RevoluteBound)     \
    X(revolute, enable_motor, Flag)             \
    X(revolute, motor_speed, Finite)            \
    X(revolute, max_motor_torque, NonNegative)  \
    X(revolute, enable_spring, Flag)            \
    X(revolute, hertz, Spring)                  \
    X(revolute, damping_ratio, Spring)          \
    X(revolute, target_angle, Angle)

#define I2D_PRISMATIC_FIELDS(X)                  \
    X(prismatic, local_axis_a, Axis)             \
    X(prismatic, reference_angle, Angle)         \
    X(prismatic, enable_limit, Flag)             \
    X(prismatic, lower_translation, Finite)      \
    X(prismatic, upper_translation, Finite)      \
    X(prismatic, enable_motor, Flag)             \
    X(prismatic, motor_speed, Finite)            \
    X(prismatic, max_motor_force, NonNegative)   \
    X(prismatic, enable_spring, Flag)            \
    X(prismatic, hertz, Spring)                  \
    X(prismatic, damping_ratio, Spring)          \
    X(prismatic, target_translation, Finite)

#define I2D_DISTANCE_FIELDS(X)                  \
    X(distance, length, DistanceLength)         \
    X(distance, enable_limit, Flag)             \
    X(distance, min_length, DistanceBound)      \
    X(distance, max_length, DistanceBound)      \
    X(distance, enable_spring, Flag)            \
    X(distance, hertz, Spring)                  \
    X(distance, damping_ratio, Spring)          \
    X(distance, enable_motor, Flag)             \
    X(distance, motor_speed, Finite)            \
    X(distance, max_motor_force, NonNegative)

#define I2D_WELD_FIELDS(X)                   \
    X(weld, reference_angle, Angle)          \
    X(weld, linear_hertz, Spring)            \
    X(weld, angular_hertz, Spring)           \
    X(weld, linear_damping_ratio, Spring)    \
    X(weld, angular_damping_ratio, Spring)

#define I2D_WHEEL_FIELDS(X)                  \
    X(wheel, local_axis_a, Axis)             \
    X(wheel, enable_spring, Flag)            \
    X(wheel, hertz, Spring)                  \
    X(wheel, damping_ratio, Spring)          \
    X(wheel, enable_limit, Flag)             \
    X(wheel, lower_translation, Finite)      \
    X(wheel, upper_translation, Finite)      \
    X(wheel, enable_motor, Flag)             \
    X(wheel, motor_speed, Finite)            \
    X(wheel, max_motor_torque, NonNegative)

#define I2D_MOTOR_FIELDS(X)                  \
    X(motor, linear_offset, Point)           \
    X(motor, angular_offset, Angle)          \
    X(motor, max_force, NonNegative)         \
    X(motor, max_torque, NonNegative)        \
    X(motor, correction_factor, Share)

#define I2D_MOUSE_FIELDS(X)            \
    X(mouse, target, Point)            \
    X(mouse, hertz, Spring)            \
    X(mouse, damping_ratio, Spring)    \
    X(mouse, max_force, NonNegative)

#define I2D_FILTER_FIELDS(X)

/// The checks that span two fields of a kind's settings (already stored): a lower bound
/// not above its upper one. `prefix` starts the message ("revolute_joint_def: " or "").
inline bool ordered_bounds(Call& call, const JointDef& def, const char* prefix) {
    auto ordered = [&](float lower, float upper, const char* lower_name, const char* upper_name) {
        return lower <= upper ? true
                              : call.fail(I2D_ERR_INVALID_ARGUMENT, "%s%s (%g) is above %s (%g)", prefix, lower_name,
                                          static_cast<double>(lower), upper_name, static_cast<double>(upper));
    };
    switch (def.type) {
        case JointType::revolute:
            return ordered(def.revolute.lower_angle, def.revolute.upper_angle, "lower_angle", "upper_angle");
        case JointType::prismatic:
            return ordered(def.prismatic.lower_translation, def.prismatic.upper_translation, "lower_translation",
                           "upper_translation");
        case JointType::distance:
            return ordered(def.distance.min_length, def.distance.max_length, "min_length", "max_length");
        case JointType::wheel:
            return ordered(def.wheel.lower_translation, def.wheel.upper_translation, "lower_translation",
                           "upper_translation");
        default:
            return true;
    }
}

/// The kind's name as the C API spells it, for messages.
inline const char* kind_name(JointType type) {
    switch (type) {
        case JointType::distance: return "distance";
        case JointType::filter: return "filter";
        case JointType::motor: return "motor";
        case JointType::mouse: return "mouse";
        case JointType::prismatic: return "prismatic";
        case JointType::revolute: return "revolute";
        case JointType::weld: return "weld";
        case JointType::wheel: return "wheel";
        default: return "unknown";
    }
}

}  // namespace i2d::capi::joint_rules
