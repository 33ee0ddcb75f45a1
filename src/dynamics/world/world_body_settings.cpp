// SPDX-License-Identifier: MIT
// World: a body's settings changed after creation: its mass, damping, gravity scale,
// sleep and bullet settings, fixed rotation.
//
// Each is a structural change (a rollback state saved before is refused, as for any
// setting) and is recorded. A change that makes a resting body move (its mass, gravity,
// rotation freedom, or its leave to sleep) wakes it; one that only changes how it will
// behave once moving (damping, the sleep threshold, the bullet flag) does not.
#include "dynamics/body/body_rules.hpp"
#include "dynamics/recording/recorder.hpp"
#include "dynamics/world/world.hpp"
#include "dynamics/world/world_stages.hpp"

namespace i2d {

void World::set_mass_data(int32_t body, const MassOverride& mass) {
    RecordScope record(recorder_.get(), RecordedOp::set_mass_data);
    record.write(body, mass.overridden, mass.mass, mass.local_center, mass.inertia);
    ++structure_version_;
    Body& b = bodies_[body];
    b.mass_overridden = mass.overridden;
    if (mass.overridden) {
        b.mass = mass.mass;
        b.local_center = mass.local_center;
        b.override_inertia = mass.inertia;
    }
    update_mass(body);
    mark_for_cover(body);  // the centre of mass moved: the boxes' reach changed
    wake_body(body);
}

void World::set_body_setting(int32_t body, BodySetting setting, float value) {
    RecordScope record(recorder_.get(), RecordedOp::set_body_setting);
    record.write(body, setting, value);
    ++structure_version_;
    Body& b = bodies_[body];
    switch (setting) {
        case BodySetting::gravity_scale:
            b.gravity_scale = value;
            wake_body(body);  // a resting body must feel its new weight
            break;
        case BodySetting::linear_damping: b.linear_damping = value; break;
        case BodySetting::angular_damping: b.angular_damping = value; break;
        case BodySetting::sleep_threshold: b.sleep_threshold = value; break;
        case BodySetting::count: break;
    }
}

void World::set_body_flag(int32_t body, BodyFlag flag, bool value) {
    RecordScope record(recorder_.get(), RecordedOp::set_body_flag);
    record.write(body, flag, value);
    ++structure_version_;
    Body& b = bodies_[body];
    switch (flag) {
        case BodyFlag::bullet: b.is_bullet = value; break;
        case BodyFlag::enable_sleep:
            b.enable_sleep = value;
            if (!value && b.type != BodyType::static_body) {
                wake_body(body);  // it may not rest from now on, nor may its island
            }
            break;
        case BodyFlag::fixed_rotation:
            if (b.fixed_rotation != value) {
                b.fixed_rotation = value;
                update_mass(body);  // inertia to or from zero; a fixed body stops turning
                wake_body(body);
            }
            break;
        case BodyFlag::count: break;
    }
}

}  // namespace i2d
