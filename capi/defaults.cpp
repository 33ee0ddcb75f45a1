// SPDX-License-Identifier: MIT
// i2d_default_*: every def field's default, and the cookie that marks a def as initialised.
#include "boundary.hpp"
#include "convert.hpp"
#include "joint_rules.hpp"
#include "world_def.hpp"

using namespace i2d;
using namespace i2d::capi;

// The core's defaults, as a world made from a snapshot reports its settings.
I2D_API i2d_world_def i2d_default_world_def(void) {
    set_ok();
    return to_public(WorldDef{});
}

// Every length-bearing default scaled from metres: gravity and the speeds by the unit,
// the slop too; the rest (stiffness, times, ratios) has no length in it.
I2D_API i2d_world_def i2d_default_world_def_in_units(float length_units_per_meter) {
    return guarded("i2d_default_world_def_in_units", to_public(WorldDef{}), [&](Call& call) {
        WorldDef core;
        if (!call.in_range(length_units_per_meter, min_length_units_per_meter, max_length_units_per_meter,
                           "length_units_per_meter")) {
            return to_public(core);
        }
        const float units = length_units_per_meter;
        core.length_units_per_meter = units;
        core.gravity = units * core.gravity;
        core.contact_slop *= units;
        core.contact_push_max_speed *= units;
        core.restitution_threshold *= units;
        core.maximum_linear_speed *= units;
        core.sleep_speed_threshold *= units;
        core.hit_event_threshold *= units;
        return to_public(core);
    });
}

I2D_API i2d_body_def i2d_default_body_def(void) {
    set_ok();
    const BodyDef core;
    i2d_body_def def{};
    def.type = I2D_BODY_STATIC;
    def.position = to_public(core.position);
    def.rotation = to_public(core.rotation);
    def.linear_velocity = to_public(core.linear_velocity);
    def.angular_velocity = core.angular_velocity;
    def.linear_damping = core.linear_damping;
    def.angular_damping = core.angular_damping;
    def.gravity_scale = core.gravity_scale;
    def.fixed_rotation = core.fixed_rotation;
    def.enable_sleep = core.enable_sleep;
    def.is_bullet = core.is_bullet;
    def.user_data = nullptr;
    def.internal_cookie = def_cookie;
    return def;
}

I2D_API i2d_shape_def i2d_default_shape_def(void) {
    set_ok();
    const ShapeDef core;
    i2d_shape_def def{};
    def.density = core.density;
    def.friction = core.friction;
    def.restitution = core.restitution;
    def.rolling_resistance = core.rolling_resistance;
    def.tangent_speed = core.tangent_speed;
    def.is_sensor = core.is_sensor;
    def.enable_contact_events = core.enable_contact_events;
    def.enable_sensor_events = core.enable_sensor_events;
    def.enable_hit_events = core.enable_hit_events;
    def.enable_custom_filtering = core.enable_custom_filtering;
    def.enable_pre_solve_events = core.enable_pre_solve_events;
    def.filter = to_public(core.filter);
    def.user_data = nullptr;
    def.internal_cookie = def_cookie;
    return def;
}

I2D_API i2d_chain_def i2d_default_chain_def(void) {
    set_ok();
    const ChainDef core;
    i2d_chain_def def{};
    def.points = nullptr;
    def.count = 0;
    def.is_loop = core.is_loop;
    def.materials = nullptr;
    def.material_count = 0;
    def.filter = to_public(core.filter);
    def.enable_sensor_events = core.enable_sensor_events;
    def.user_data = nullptr;
    def.internal_cookie = def_cookie;
    return def;
}

I2D_API i2d_query_filter i2d_default_query_filter(void) {
    set_ok();
    const QueryFilter core;
    return {core.category_bits, core.mask_bits};
}

I2D_API i2d_filter i2d_default_filter(void) {
    set_ok();
    return to_public(Filter{});
}

// Joint defs: the base's and every setting's default is the core's, through the same
// rules (joint_rules.hpp) that read a setting back.
namespace {

i2d_joint_base default_joint_base() {
    const JointDef core;
    i2d_joint_base base{};
    base.body_a = I2D_NULL_BODY_ID;
    base.body_b = I2D_NULL_BODY_ID;
    base.local_anchor_a = to_public(core.local_anchor_a);
    base.local_anchor_b = to_public(core.local_anchor_b);
    base.collide_connected = core.collide_connected;
    base.force_threshold = core.force_threshold;
    base.torque_threshold = core.torque_threshold;
    base.user_data = nullptr;
    return base;
}

}  // namespace

#define I2D_DEFAULT_FIELD(kind, field, Rule) def.field = joint_rules::Rule::out(core.kind.field);
#define I2D_DEFAULT_JOINT_DEF(kind, FIELDS)                        \
    I2D_API i2d_##kind##_joint_def i2d_default_##kind##_joint_def(void) { \
        set_ok();                                                  \
        const JointDef core;                                       \
        static_cast<void>(core);                                   \
        i2d_##kind##_joint_def def{};                              \
        def.base = default_joint_base();                           \
        FIELDS(I2D_DEFAULT_FIELD)                                  \
        def.internal_cookie = def_cookie;                          \
        return def;                                                \
    }

I2D_DEFAULT_JOINT_DEF(revolute, I2D_REVOLUTE_FIELDS)
I2D_DEFAULT_JOINT_DEF(prismatic, I2D_PRISMATIC_FIELDS)
I2D_DEFAULT_JOINT_DEF(distance, I2D_DISTANCE_FIELDS)
I2D_DEFAULT_JOINT_DEF(weld, I2D_WELD_FIELDS)
I2D_DEFAULT_JOINT_DEF(wheel, I2D_WHEEL_FIELDS)
I2D_DEFAULT_JOINT_DEF(motor, I2D_MOTOR_FIELDS)
I2D_DEFAULT_JOINT_DEF(mouse, I2D_MOUSE_FIELDS)
I2D_DEFAULT_JOINT_DEF(filter, I2D_FILTER_FIELDS)

#undef I2D_DEFAULT_JOINT_DEF
#undef I2D_DEFAULT_FIELD
