// SPDX-License-Identifier: MIT
// World: creating, changing and destroying bodies: types, poses, velocities, forces, mass,
// and the fat boxes that must cover the step ahead.
#include <cmath>

#include "dynamics/body/body_rules.hpp"
#include "dynamics/body/shape_bounds.hpp"
#include "dynamics/recording/recorder.hpp"
#include "dynamics/world/world.hpp"
#include "dynamics/world/world_stages.hpp"
#include "math/math.hpp"

namespace i2d {

int32_t World::create_body(const BodyDef& def) {
    RecordScope record(recorder_.get(), RecordedOp::create_body);
    record.write(def);
    ++structure_version_;
    const int32_t index = bodies_.allocate();
    if (index == null_index) {
        return null_index;
    }
    Body& b = bodies_[index];
    b.type = def.type;
    b.transform = {def.position, def.rotation};
    b.linear_velocity = def.type == BodyType::static_body ? Vec2{} : limited_linear_velocity(def.linear_velocity);
    b.angular_velocity = def.type == BodyType::static_body ? 0.0f : limited_angular_velocity(def.angular_velocity);
    b.linear_damping = def.linear_damping;
    b.angular_damping = def.angular_damping;
    b.gravity_scale = def.gravity_scale;
    b.fixed_rotation = def.fixed_rotation;
    b.enable_sleep = def.enable_sleep;
    b.sleep_threshold = settings_.sleep_speed_threshold;
    b.is_bullet = def.is_bullet;
    b.user_data = def.user_data;
    update_mass(index);
    if (b.type != BodyType::static_body) {
        stages_->islands.add_body(index);
        mark_for_cover(index);
    }
    return index;
}

void World::destroy_body(int32_t body) {
    RecordScope record(recorder_.get(), RecordedOp::destroy_body);
    record.write(body);
    ++structure_version_;
    wake_body(body);  // the island it slept in loses a member
    while (bodies_[body].head_joint_key != null_index) {
        destroy_joint(bodies_[body].head_joint_key >> 1);
    }
    // Shapes first: each takes its contacts (and their end events) with it; a chain's
    // segments go with their chain.
    while (bodies_[body].head_shape != null_index) {
        const int32_t shape = bodies_[body].head_shape;
        if (shapes_[shape].chain != null_index) {
            destroy_chain(shapes_[shape].chain);
        } else {
            destroy_shape(shape);
        }
    }
    if (bodies_[body].type != BodyType::static_body && bodies_[body].enabled) {
        stages_->islands.remove_body(body);
        follow_woken_bodies();
    }
    bodies_.free(body);
}

void World::set_type(int32_t body, BodyType type) {
    RecordScope record(recorder_.get(), RecordedOp::set_type);
    record.write(body, type);
    ++structure_version_;
    if (bodies_[body].type == type) {
        bodies_[body].quarantined = false;  // a quarantined body kept static on purpose
        return;
    }
    // The body leaves the stages as its old type and joins them as its new one
    // (world_body_enable.cpp); a disabled body is in none, and joins them when enabled.
    const bool enabled = bodies_[body].enabled;
    if (enabled) {
        leave_stages(body);
    }
    change_type(bodies_[body], type);
    update_mass(body);
    if (enabled) {
        join_stages(body);
    }
}

// Whatever read the old mass learns of the new: the joints' trees (a body that can no
// longer turn gives them no angle rows) and the body's manifolds (anchored at the old
// centre of mass).
void World::update_mass(int32_t body) {
    stages_->joints.touch();
    update_mass_from_shapes(bodies_[body], shapes_, tolerances().linear_slop);
    stages_->contacts.forget_manifolds(body);
}

// Before pairs are found, every moving shape's fat box must cover the step ahead, or a
// fast body could pass through a thin wall before its pair exists. The last step's
// bounds update fattened the boxes for its own time step and final velocities; only
// bodies the caller changed since (created, moved, given a velocity or an impulse)
// need checking again, unless the time step changed.
void World::cover_step_ahead(float time_step) {
    const bool same_step = time_step == covered_time_step_;
    covered_time_step_ = time_step;
    const auto cover = [&](int32_t body) {
        Body& b = bodies_[body];
        b.needs_cover = false;
        update_shape_bounds(b, shapes_, stages_->broad_phase, time_step * b.linear_velocity, true, turn_reach(b, time_step));
    };
    if (same_step) {
        for (const int32_t body : to_cover_) {
            if (bodies_.is_live(body) && bodies_[body].needs_cover && is_awake(body)) {
                cover(body);
            }
        }
    } else {
        for (const int32_t body : stages_->islands.awake_bodies()) {
            cover(body);
        }
    }
    to_cover_.clear();
    stages_->broad_phase.commit_moves_in_place();
}

// A disabled body has no proxies to cover; enabling it marks it.
void World::mark_for_cover(int32_t body) {
    Body& b = bodies_[body];
    if (b.type != BodyType::static_body && b.enabled && !b.needs_cover) {
        b.needs_cover = true;
        to_cover_.push_back(body);
    }
}

// Moving a body wakes it and whatever touches it (a static floor moved away from under a
// sleeping pile, say).
void World::set_transform(int32_t body, const Transform& xf) { set_transforms(&body, &xf, 1); }

// Waking was most of what a bulk write cost (each contact a cache miss, and each body it
// leads to), and it mostly changes nothing: while no island sleeps, waking a body only
// restarts its rest timer, and only a world that sleeps reads the timers. So the contacts
// are walked only when an island may wake or the timers count; either way every body
// ends as wake_body would leave it.
void World::set_transforms(const int32_t* list, const Transform* transforms, int32_t count) {
    RecordScope record(recorder_.get(), RecordedOp::set_transforms);
    record.write(count);
    for (int32_t k = 0; k < count; ++k) {
        record.write(list[k], transforms[k]);
    }
    const bool may_wake = stages_->islands.sleeping_island_count() > 0;
    const bool timers_count = settings_.enable_sleep;
    for (int32_t i = 0; i < count; ++i) {
        const int32_t body = list[i];
        if (may_wake) {
            wake_body(body);
            stages_->contacts.visit_contacts(body, [this](int32_t, int32_t other) { wake_body(other); });
        } else {
            bodies_[body].sleep_time = 0.0f;
            if (timers_count) {
                stages_->contacts.visit_contacts(body, [this](int32_t, int32_t other) { bodies_[other].sleep_time = 0.0f; });
            }
        }
        Body& b = bodies_[body];
        b.transform = transforms[i];
        b.center = transform_point(transforms[i], b.local_center);
        if (!b.enabled) {
            update_tight_boxes(b, shapes_);  // no proxies: enabling makes them where it stands
            continue;
        }
        // Proxies that must move are re-inserted before the next body moves, as when
        // set_transform is called for each body in turn: the trees, and so the pairs
        // and every later step, come out the same. (One commit at the end, in storage
        // order, was about 12 % faster when every body was teleported, but its trees
        // and later steps differed from the per-body calls'.)
        if (refit_shape_bounds(b, shapes_, Vec2{}, false)) {
            move_enlarged_proxies(b, shapes_, stages_->broad_phase);
            stages_->broad_phase.commit_moves();
        }
        mark_for_cover(body);
    }
}

Vec2 World::limited_linear_velocity(Vec2 v) const {
    return i2d::limited_linear_velocity(v, settings_.maximum_linear_speed);
}

float World::limited_angular_velocity(float w) const { return i2d::limited_angular_velocity(w); }

void World::set_linear_velocity(int32_t body, Vec2 v) {
    RecordScope record(recorder_.get(), RecordedOp::set_linear_velocity);
    record.write(body, v);
    Body& b = bodies_[body];
    if (b.type == BodyType::static_body) {
        return;
    }
    if (v.x != 0.0f || v.y != 0.0f) {
        wake_body(body);
    }
    b.linear_velocity = limited_linear_velocity(v);
    mark_for_cover(body);
}

void World::set_angular_velocity(int32_t body, float w) {
    RecordScope record(recorder_.get(), RecordedOp::set_angular_velocity);
    record.write(body, w);
    Body& b = bodies_[body];
    if (!can_turn(b)) {
        return;
    }
    if (w != 0.0f) {
        wake_body(body);
    }
    b.angular_velocity = limited_angular_velocity(w);
    if (b.type == BodyType::kinematic) {
        mark_for_cover(body);  // its boxes must reach as far as it now turns
    }
}

// Wakes the body if asked; a body left asleep ignores what it is given. A disabled body
// neither sleeps nor wakes: it keeps what it is given for when it is enabled.
bool World::prepare_to_receive(int32_t body, bool wake) {
    if (bodies_[body].type != BodyType::dynamic) {
        return false;
    }
    if (!bodies_[body].enabled) {
        return true;
    }
    if (wake) {
        wake_body(body);
    }
    return is_awake(body);
}

bool World::accumulate(int32_t body, Vec2 force, float torque, bool wake) {
    Body& b = bodies_[body];
    const Vec2 total_force = b.force + force;
    const float total_torque = b.torque + torque;
    if (!is_finite(total_force) || !std::isfinite(total_torque)) {
        return false;
    }
    if (prepare_to_receive(body, wake)) {
        b.force = total_force;
        b.torque = total_torque;
    }
    return true;
}

bool World::change_velocity(int32_t body, Vec2 dv, float dw, bool wake) {
    Body& b = bodies_[body];
    const Vec2 v = b.linear_velocity + dv;
    const float w = b.angular_velocity + dw;
    if (!is_finite(v) || !std::isfinite(w)) {
        return false;
    }
    if (prepare_to_receive(body, wake)) {
        b.linear_velocity = limited_linear_velocity(v);
        b.angular_velocity = limited_angular_velocity(w);
        mark_for_cover(body);
    }
    return true;
}

bool World::apply_force(int32_t body, Vec2 force, Vec2 point, bool wake) {
    RecordScope record(recorder_.get(), RecordedOp::apply_force);
    record.write(body, force, point, wake);
    return accumulate(body, force, cross(point - bodies_[body].center, force), wake);
}

bool World::apply_force_to_center(int32_t body, Vec2 force, bool wake) {
    RecordScope record(recorder_.get(), RecordedOp::apply_force_to_center);
    record.write(body, force, wake);
    return accumulate(body, force, 0.0f, wake);
}

bool World::apply_torque(int32_t body, float torque, bool wake) {
    RecordScope record(recorder_.get(), RecordedOp::apply_torque);
    record.write(body, torque, wake);
    return accumulate(body, Vec2{}, torque, wake);
}

bool World::apply_linear_impulse(int32_t body, Vec2 impulse, Vec2 point, bool wake) {
    RecordScope record(recorder_.get(), RecordedOp::apply_linear_impulse);
    record.write(body, impulse, point, wake);
    const Body& b = bodies_[body];
    return change_velocity(body, b.inv_mass * impulse, b.inv_inertia * cross(point - b.center, impulse), wake);
}

bool World::apply_angular_impulse(int32_t body, float impulse, bool wake) {
    RecordScope record(recorder_.get(), RecordedOp::apply_angular_impulse);
    record.write(body, impulse, wake);
    return change_velocity(body, Vec2{}, bodies_[body].inv_inertia * impulse, wake);
}

void World::set_user_data(int32_t body, void* user_data) {
    RecordScope record(recorder_.get(), RecordedOp::set_body_user_data);
    record.write(body, user_data);
    bodies_[body].user_data = user_data;
}

}  // namespace i2d
