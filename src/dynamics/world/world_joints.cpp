// SPDX-License-Identifier: MIT
// World: creating, changing and destroying joints, and keeping islands and contacts in
// step with them.
#include "dynamics/recording/recorder.hpp"
#include "dynamics/world/world.hpp"
#include "dynamics/world/world_stages.hpp"

namespace i2d {

int32_t World::create_joint(const JointDef& def) {
    RecordScope record(recorder_.get(), RecordedOp::create_joint);
    record.write(def);
    ++structure_version_;
    const int32_t joint = stages_->joints.create(def);
    if (joint == null_index) {
        return null_index;
    }
    wake_body(def.body_a);
    wake_body(def.body_b);
    if (!def.collide_connected) {
        destroy_contacts_between(def.body_a, def.body_b);
    }
    link_joint(joint);
    return joint;
}

void World::destroy_joint(int32_t joint) {
    RecordScope record(recorder_.get(), RecordedOp::destroy_joint);
    record.write(joint);
    ++structure_version_;
    const JointDef& def = stages_->joints.joint(joint).def;
    const int32_t body_a = def.body_a, body_b = def.body_b;
    const bool kept_apart = !def.collide_connected;
    wake_body(body_a);
    wake_body(body_b);
    unlink_joint(joint);
    stages_->joints.destroy(joint);
    if (kept_apart) {
        let_bodies_meet(body_a, body_b);
    }
}

void World::set_joint_def(int32_t joint, const JointDef& def) {
    RecordScope record(recorder_.get(), RecordedOp::set_joint_def);
    record.write(joint, def);
    ++structure_version_;
    stages_->joints.joint(joint).def = def;
    stages_->joints.touch();  // a setting may change which rows the tree pass takes
    wake_body(def.body_a);
    wake_body(def.body_b);
    if (def.collide_connected) {
        let_bodies_meet(def.body_a, def.body_b);  // a no-op for pairs that have a contact
    } else {
        destroy_contacts_between(def.body_a, def.body_b);
    }
}

void World::set_joint_user_data(int32_t joint, void* user_data) {
    RecordScope record(recorder_.get(), RecordedOp::set_joint_user_data);
    record.write(joint, user_data);
    stages_->joints.joint(joint).def.user_data = user_data;
}

JointMeasures World::measure_joint(int32_t joint) const { return stages_->joints.measure(joint); }

const std::vector<JointEvent>& World::joint_events() const { return stages_->events.current.joint_events; }

// Overlapping proxies of the two bodies were skipped while the joint kept them apart;
// queried again at the next step, they pair now. A disabled body has no proxies, and
// enabling it queries them anyway.
void World::let_bodies_meet(int32_t body_a, int32_t body_b) {
    if (!bodies_[body_a].enabled || !bodies_[body_b].enabled) {
        return;
    }
    const int32_t body = bodies_[body_a].shape_count <= bodies_[body_b].shape_count ? body_a : body_b;
    for (int32_t s = bodies_[body].head_shape; s != null_index; s = shapes_[s].next_in_body) {
        stages_->broad_phase.requery_proxy(shapes_[s].proxy_key);
    }
}

// Two dynamic bodies held by a joint share an island, so that they sleep and wake
// together; static and kinematic bodies join no island, and a disabled body none at all
// (its joints link again when it is enabled).
void World::link_joint(int32_t joint) {
    Joint& j = stages_->joints.joint(joint);
    if (!j.island_link && stages_->joints.should_link(j)) {
        j.island_link = true;
        stages_->islands.link(j.def.body_a, j.def.body_b);
    }
}

void World::unlink_joint(int32_t joint) {
    Joint& j = stages_->joints.joint(joint);
    if (j.island_link) {
        j.island_link = false;
        stages_->islands.unlink(j.def.body_a);
    }
}

void World::link_joints(int32_t body) {
    stages_->joints.touch();  // the body's type changed: its joints may move it, or no longer
    stages_->joints.visit_joints(body, [this](int32_t joint, int32_t other) {
        wake_body(other);
        link_joint(joint);
    });
}

void World::forget_joint_impulses(int32_t body) {
    stages_->joints.visit_joints(body, [this](int32_t joint, int32_t) {
        Joint& j = stages_->joints.joint(joint);
        j.impulses = JointImpulses{};
        j.reaction_force = Vec2{};
        j.reaction_torque = 0.0f;
        j.motor_output = 0.0f;
    });
}

void World::unlink_joints(int32_t body) {
    stages_->joints.visit_joints(body, [this](int32_t joint, int32_t other) {
        wake_body(other);
        unlink_joint(joint);
    });
}

}  // namespace i2d
