// SPDX-License-Identifier: MIT
// i2d_<kind>_joint_get_* and _set_*: every kind's settings, generated from the field
// table (joint_rules.hpp), and the measures and motor outputs read from the core.
//
// Every getter: a live joint of the right kind, else 0 and a status (INVALID_HANDLE or
// INVALID_ARGUMENT). Every setter: a live joint, an unlocked world, the right kind, the
// value by its field's rule, then the kind's cross-field checks on the changed settings;
// only then stored, and the world told (which wakes both bodies).
#include "boundary.hpp"
#include "convert.hpp"
#include "joint_rules.hpp"

using namespace i2d;
using namespace i2d::capi;
using namespace i2d::capi::joint_rules;

namespace {

bool of_kind(Call& call, const JointRef& j, JointType kind) {
    const JointType type = j.joint().def.type;
    if (type != kind) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "the joint is a %s joint, not a %s joint", kind_name(type),
                         kind_name(kind));
    }
    return true;
}

template <class R, class Read>
R read_setting(const char* function, JointType kind, i2d_joint_id id, Read&& read) {
    return guarded(function, R{}, [&](Call& call) -> R {
        JointRef j;
        return call.joint(id, j) && of_kind(call, j, kind) ? read(j) : R{};
    });
}

template <class Change>
i2d_status change_setting(const char* function, JointType kind, i2d_joint_id id, Change&& change) {
    return guarded(function, I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        JointRef j;
        if (!call.joint(id, j) || !call.unlocked(*j.world) || !of_kind(call, j, kind)) {
            return last_status();
        }
        // Changed on a copy, so that a refused value leaves the joint as it was.
        JointDef def = j.joint().def;
        if (!change(call, def) || !ordered_bounds(call, def, "")) {
            return last_status();
        }
        j.world->set_joint_def(j.index, def);
        return I2D_OK;
    });
}

}  // namespace

#define I2D_SETTING_ACCESSORS(kind, field, Rule)                                                                \
    I2D_API Rule::Public i2d_##kind##_joint_get_##field(i2d_joint_id id) {                                      \
        return read_setting<Rule::Public>("i2d_" #kind "_joint_get_" #field, JointType::kind, id,               \
                                          [](const JointRef& j) { return Rule::out(j.joint().def.kind.field); }); \
    }                                                                                                           \
    I2D_API i2d_status i2d_##kind##_joint_set_##field(i2d_joint_id id, Rule::Public value) {                   \
        return change_setting("i2d_" #kind "_joint_set_" #field, JointType::kind, id,                           \
                              [&](Call& call, JointDef& def) {                                                 \
                                  if (!Rule::check(call, value, #field)) {                                      \
                                      return false;                                                             \
                                  }                                                                             \
                                  def.kind.field = Rule::store(value);                                          \
                                  return true;                                                                  \
                              });                                                                               \
    }

I2D_REVOLUTE_FIELDS(I2D_SETTING_ACCESSORS)
I2D_PRISMATIC_FIELDS(I2D_SETTING_ACCESSORS)
I2D_DISTANCE_FIELDS(I2D_SETTING_ACCESSORS)
I2D_WELD_FIELDS(I2D_SETTING_ACCESSORS)
I2D_WHEEL_FIELDS(I2D_SETTING_ACCESSORS)
I2D_MOTOR_FIELDS(I2D_SETTING_ACCESSORS)
I2D_MOUSE_FIELDS(I2D_SETTING_ACCESSORS)

#undef I2D_SETTING_ACCESSORS

// Both bounds at once, so that a range can move past its old other bound in one call.
#define I2D_RANGE_SETTER(name, kind, lower, upper, Rule)                                       \
    I2D_API i2d_status name(i2d_joint_id id, float lower_value, float upper_value) {          \
        return change_setting(#name, JointType::kind, id, [&](Call& call, JointDef& def) {    \
            if (!Rule::check(call, lower_value, #lower) || !Rule::check(call, upper_value, #upper)) { \
                return false;                                                                   \
            }                                                                                   \
            def.kind.lower = Rule::store(lower_value);                                          \
            def.kind.upper = Rule::store(upper_value);                                          \
            return true;                                                                        \
        });                                                                                     \
    }

I2D_RANGE_SETTER(i2d_revolute_joint_set_limits, revolute, lower_angle, upper_angle, RevoluteBound)
I2D_RANGE_SETTER(i2d_prismatic_joint_set_limits, prismatic, lower_translation, upper_translation, Finite)
I2D_RANGE_SETTER(i2d_wheel_joint_set_limits, wheel, lower_translation, upper_translation, Finite)
I2D_RANGE_SETTER(i2d_distance_joint_set_length_range, distance, min_length, max_length, DistanceBound)

#undef I2D_RANGE_SETTER

// Measures (as the bodies stand now) and the motors' output over the last step.
#define I2D_JOINT_MEASURE(name, kind, expression)                                                     \
    I2D_API float name(i2d_joint_id id) {                                                           \
        return read_setting<float>(#name, JointType::kind, id, [](const JointRef& j) { return expression; }); \
    }

I2D_JOINT_MEASURE(i2d_revolute_joint_get_angle, revolute, j.world->measure_joint(j.index).angle)
I2D_JOINT_MEASURE(i2d_revolute_joint_get_motor_torque, revolute, j.joint().motor_output)
I2D_JOINT_MEASURE(i2d_prismatic_joint_get_translation, prismatic, j.world->measure_joint(j.index).translation)
I2D_JOINT_MEASURE(i2d_prismatic_joint_get_speed, prismatic, j.world->measure_joint(j.index).speed)
I2D_JOINT_MEASURE(i2d_prismatic_joint_get_motor_force, prismatic, j.joint().motor_output)
I2D_JOINT_MEASURE(i2d_distance_joint_get_current_length, distance, j.world->measure_joint(j.index).length)
I2D_JOINT_MEASURE(i2d_distance_joint_get_motor_force, distance, j.joint().motor_output)
I2D_JOINT_MEASURE(i2d_wheel_joint_get_motor_torque, wheel, j.joint().motor_output)
I2D_JOINT_MEASURE(i2d_wheel_joint_get_translation, wheel, j.world->measure_joint(j.index).translation)

#undef I2D_JOINT_MEASURE
