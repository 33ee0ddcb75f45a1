// SPDX-License-Identifier: MIT
// What each joint kind has, as include/impulse2d/joint.h declares it: the settings of its
// def (each with a getter and setter i2d_<kind>_joint_get_/set_<field> in the library)
// and how each value crosses into the module. One table drives the def a creation writes
// and the accessors a joint gets, so the two cannot disagree on a name.

/** How a setting's value crosses: a float, a bool (one byte in a def), an i2d_vec2. */
export const FLOAT = 'float';
export const FLAG = 'flag';
export const POINT = 'point';

/** Kinds in i2d_joint_type order: a kind's index is its C enum value. */
export const JOINT_KIND_NAMES = ['distance', 'filter', 'motor', 'mouse', 'prismatic', 'revolute', 'weld', 'wheel'];

/** i2d_joint_base's settings, which every kind shares (i2d_joint_get_/set_<field>). */
export const BASE_SETTINGS = {
  local_anchor_a: POINT,
  local_anchor_b: POINT,
  collide_connected: FLAG,
  force_threshold: FLOAT,
  torque_threshold: FLOAT,
};

/** Each kind's own settings, in its def's order. */
export const KIND_SETTINGS = {
  distance: {
    length: FLOAT, enable_limit: FLAG, min_length: FLOAT, max_length: FLOAT, enable_spring: FLAG,
    hertz: FLOAT, damping_ratio: FLOAT, enable_motor: FLAG, motor_speed: FLOAT, max_motor_force: FLOAT,
  },
  filter: {},
  motor: {
    linear_offset: POINT, angular_offset: FLOAT, max_force: FLOAT, max_torque: FLOAT, correction_factor: FLOAT,
  },
  mouse: { target: POINT, hertz: FLOAT, damping_ratio: FLOAT, max_force: FLOAT },
  prismatic: {
    local_axis_a: POINT, reference_angle: FLOAT, enable_limit: FLAG, lower_translation: FLOAT,
    upper_translation: FLOAT, enable_motor: FLAG, motor_speed: FLOAT, max_motor_force: FLOAT,
    enable_spring: FLAG, hertz: FLOAT, damping_ratio: FLOAT, target_translation: FLOAT,
  },
  revolute: {
    reference_angle: FLOAT, enable_limit: FLAG, lower_angle: FLOAT, upper_angle: FLOAT, enable_motor: FLAG,
    motor_speed: FLOAT, max_motor_torque: FLOAT, enable_spring: FLAG, hertz: FLOAT, damping_ratio: FLOAT,
    target_angle: FLOAT,
  },
  weld: {
    reference_angle: FLOAT, linear_hertz: FLOAT, angular_hertz: FLOAT, linear_damping_ratio: FLOAT,
    angular_damping_ratio: FLOAT,
  },
  wheel: {
    local_axis_a: POINT, enable_spring: FLAG, hertz: FLOAT, damping_ratio: FLOAT, enable_limit: FLAG,
    lower_translation: FLOAT, upper_translation: FLOAT, enable_motor: FLAG, motor_speed: FLOAT,
    max_motor_torque: FLOAT,
  },
};

/** The JavaScript name of a C field: max_motor_torque -> maxMotorTorque. */
export function camelCase(field) {
  return field.replace(/_([a-z])/g, (_, letter) => letter.toUpperCase());
}
