// SPDX-License-Identifier: MIT
// i2d_body_*: a body's settings after creation: mass, target transform, bullet, sleep,
// gravity scale, damping, fixed rotation; and their getters.
#include <cfloat>

#include "boundary.hpp"
#include "convert.hpp"
#include "geometry_checks.hpp"
#include "limits.hpp"
#include "math/math.hpp"

using namespace i2d;
using namespace i2d::capi;

namespace {

// A getter's value from a live body, or `none` (with the status set) for a bad id.
template <class T, class Read>
T read_body(const char* function, i2d_body_id id, T none, Read&& read) {
    return guarded(function, none, [&](Call& call) {
        BodyRef b;
        return call.body(id, b) ? read(b.body()) : none;
    });
}

// A speed's upper limit is in the world's length units per second: scaled for Unit::speed.
enum class Unit { none, speed };

i2d_status set_body_setting(const char* function, i2d_body_id id, BodySetting setting, float value, float lo,
                            float hi, Unit unit = Unit::none) {
    return guarded(function, I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        BodyRef b;
        if (!mutable_body(call, id, b) ||
            !call.in_range(value, lo, unit == Unit::speed ? hi * b.world->settings().length_units_per_meter : hi,
                           "value")) {
            return last_status();
        }
        b.world->set_body_setting(b.index, setting, value);
        return I2D_OK;
    });
}

i2d_status set_body_flag(const char* function, i2d_body_id id, BodyFlag flag, bool value) {
    return guarded(function, I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        BodyRef b;
        if (!mutable_body(call, id, b)) {
            return last_status();
        }
        b.world->set_body_flag(b.index, flag, value);
        return I2D_OK;
    });
}

// The velocities that carry the body from where it is to target in time_step: the
// rotation's change as the angle between the two rotations, the shortest way round, by
// the engine's own atan2 (the same bits on every platform).
void velocities_to(const Body& b, const Transform& target, float time_step, Vec2& v, float& w) {
    const float inv_step = 1.0f / time_step;
    const Vec2 target_center = transform_point(target, b.local_center);
    v = inv_step * (target_center - b.center);
    w = inv_step * get_angle(inv_mul_rot(b.transform.q, target.q));
}

}  // namespace

I2D_API i2d_mass_data i2d_body_get_mass_data(i2d_body_id id) {
    return read_body("i2d_body_get_mass_data", id, i2d_mass_data{}, [](const Body& b) {
        return i2d_mass_data{b.mass, to_public(b.local_center), b.inertia};
    });
}

I2D_API i2d_status i2d_body_set_mass_data(i2d_body_id id, i2d_mass_data data) {
    return guarded("i2d_body_set_mass_data", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        BodyRef b;
        if (!mutable_body(call, id, b) || !call.in_range(data.mass, FLT_MIN, max_mass, "mass") ||
            !call.in_range(data.rotational_inertia, 0.0f, max_inertia, "rotational_inertia") ||
            !call.local_point(data.center, "center")) {
            return last_status();
        }
        if (b.body().type != BodyType::dynamic) {
            call.fail(I2D_ERR_INVALID_ARGUMENT, "only a dynamic body has a mass to set");
            return last_status();
        }
        b.world->set_mass_data(b.index, MassOverride{true, data.mass, to_core(data.center), data.rotational_inertia});
        return I2D_OK;
    });
}

I2D_API i2d_status i2d_body_apply_mass_from_shapes(i2d_body_id id) {
    return guarded("i2d_body_apply_mass_from_shapes", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        BodyRef b;
        if (!mutable_body(call, id, b)) {
            return last_status();
        }
        b.world->set_mass_data(b.index, MassOverride{});
        return I2D_OK;
    });
}

I2D_API i2d_status i2d_body_set_target_transform(i2d_body_id id, i2d_transform target, float time_step) {
    return guarded("i2d_body_set_target_transform", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        BodyRef b;
        Rot q;
        if (!mutable_body(call, id, b) || !call.coordinate(target.p, "target position") ||
            !normalized_rotation(call, target.q, "target rotation", q) ||
            !call.in_range(time_step, min_time_step, max_time_step, "time_step")) {
            return last_status();
        }
        if (b.body().type != BodyType::kinematic) {
            call.fail(I2D_ERR_INVALID_ARGUMENT, "only a kinematic body moves to a target (this one is %s)",
                      b.body().type == BodyType::static_body ? "static" : "dynamic");
            return last_status();
        }
        Vec2 v;
        float w = 0.0f;
        velocities_to(b.body(), Transform{to_core(target.p), q}, time_step, v, w);
        if (!call.finite(to_public(v), "the velocity to the target") || !call.finite(w, "the spin to the target")) {
            return last_status();
        }
        b.world->set_linear_velocity(b.index, v);
        b.world->set_angular_velocity(b.index, w);
        return I2D_OK;
    });
}

I2D_API i2d_status i2d_body_set_bullet(i2d_body_id id, bool flag) {
    return set_body_flag("i2d_body_set_bullet", id, BodyFlag::bullet, flag);
}

I2D_API bool i2d_body_is_bullet(i2d_body_id id) {
    return read_body("i2d_body_is_bullet", id, false, [](const Body& b) { return b.is_bullet; });
}

I2D_API i2d_status i2d_body_enable_sleep(i2d_body_id id, bool flag) {
    return set_body_flag("i2d_body_enable_sleep", id, BodyFlag::enable_sleep, flag);
}

I2D_API bool i2d_body_is_sleep_enabled(i2d_body_id id) {
    return read_body("i2d_body_is_sleep_enabled", id, false, [](const Body& b) { return b.enable_sleep; });
}

I2D_API i2d_status i2d_body_set_sleep_threshold(i2d_body_id id, float speed) {
    return set_body_setting("i2d_body_set_sleep_threshold", id, BodySetting::sleep_threshold, speed, 0.0f,
                            max_speed_limit, Unit::speed);
}

I2D_API float i2d_body_get_sleep_threshold(i2d_body_id id) {
    return read_body("i2d_body_get_sleep_threshold", id, 0.0f, [](const Body& b) { return b.sleep_threshold; });
}

I2D_API i2d_status i2d_body_set_gravity_scale(i2d_body_id id, float scale) {
    return set_body_setting("i2d_body_set_gravity_scale", id, BodySetting::gravity_scale, scale, -FLT_MAX, FLT_MAX);
}

I2D_API float i2d_body_get_gravity_scale(i2d_body_id id) {
    return read_body("i2d_body_get_gravity_scale", id, 0.0f, [](const Body& b) { return b.gravity_scale; });
}

I2D_API i2d_status i2d_body_set_linear_damping(i2d_body_id id, float damping) {
    return set_body_setting("i2d_body_set_linear_damping", id, BodySetting::linear_damping, damping, 0.0f, FLT_MAX);
}

I2D_API float i2d_body_get_linear_damping(i2d_body_id id) {
    return read_body("i2d_body_get_linear_damping", id, 0.0f, [](const Body& b) { return b.linear_damping; });
}

I2D_API i2d_status i2d_body_set_angular_damping(i2d_body_id id, float damping) {
    return set_body_setting("i2d_body_set_angular_damping", id, BodySetting::angular_damping, damping, 0.0f,
                            FLT_MAX);
}

I2D_API float i2d_body_get_angular_damping(i2d_body_id id) {
    return read_body("i2d_body_get_angular_damping", id, 0.0f, [](const Body& b) { return b.angular_damping; });
}

I2D_API i2d_status i2d_body_set_fixed_rotation(i2d_body_id id, bool flag) {
    return set_body_flag("i2d_body_set_fixed_rotation", id, BodyFlag::fixed_rotation, flag);
}

I2D_API bool i2d_body_is_fixed_rotation(i2d_body_id id) {
    return read_body("i2d_body_is_fixed_rotation", id, false, [](const Body& b) { return b.fixed_rotation; });
}
