// SPDX-License-Identifier: MIT
// World: creating, changing and destroying joints, and keeping islands and contacts in
// step with them.
#include "dynamics/world/world.hpp"

namespace i2d {

int32_t World::create_joint(const JointDef& def) {
    const int32_t joint = joints_.create(def);
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
    const JointDef& def = joints[joint].def;
    const int32_t body_a = def.body_a, body_b = def.body_b;
    const bool kept_apart = !def.collide_connected;
    wake_body(body_a);
    wake_body(body_b);
    unlink_joint(joint);
    joints_.destroy(joint);
    if (kept_apart) {
        let_bodies_meet(body_a, body_b);
    }
}

void World::joint_changed(int32_t joint) {
    const JointDef& def = joints[joint].def;
    joints_.touch();  // a setting may change which rows the tree pass takes
    wake_body(def.body_a);
    wake_body(def.body_b);
    if (def.collide_connected) {
        let_bodies_meet(def.body_a, def.body_b);  // a no-op for pairs that have a contact
    } else {
        destroy_contacts_between(def.body_a, def.body_b);
    }
}

// Overlapping proxies of the two bodies were skipped while the joint kept them apart;
// queried again at the next step, they pair now.
void World::let_bodies_meet(int32_t body_a, int32_t body_b) {
    const int32_t body = bodies[body_a].shape_count <= bodies[body_b].shape_count ? body_a : body_b;
    for (int32_t s = bodies[body].head_shape; s != null_index; s = shapes[s].next_in_body) {
        broad_phase_.requery_proxy(shapes[s].proxy_key);
    }
}

// Two dynamic bodies held by a joint share an island, so that they sleep and wake
// together; static and kinematic bodies join no island.
void World::link_joint(int32_t joint) {
    Joint& j = joints[joint];
    const bool both_dynamic = bodies[j.def.body_a].type == BodyType::dynamic &&
                              bodies[j.def.body_b].type == BodyType::dynamic;
    if (!j.island_link && both_dynamic && JointSet::links_islands(j)) {
        j.island_link = true;
        islands_.link(j.def.body_a, j.def.body_b);
    }
}

void World::unlink_joint(int32_t joint) {
    Joint& j = joints[joint];
    if (j.island_link) {
        j.island_link = false;
        islands_.unlink(j.def.body_a);
    }
}

void World::link_joints(int32_t body) {
    joints_.touch();  // the body's type changed: its joints may move it, or no longer
    joints_.visit_joints(body, [this](int32_t joint, int32_t other) {
        wake_body(other);
        link_joint(joint);
    });
}

void World::forget_joint_impulses(int32_t body) {
    joints_.visit_joints(body, [this](int32_t joint, int32_t) {
        Joint& j = joints[joint];
        j.impulses = JointImpulses{};
        j.reaction_force = Vec2{};
        j.reaction_torque = 0.0f;
        j.motor_output = 0.0f;
    });
}

void World::unlink_joints(int32_t body) {
    joints_.visit_joints(body, [this](int32_t joint, int32_t other) {
        wake_body(other);
        unlink_joint(joint);
    });
}

}  // namespace i2d
