// SPDX-License-Identifier: MIT
// World: disabling and enabling a body, and the two halves they share with a change of
// type: taking a body out of the stages and putting it back in.
//
// Design note: a disabled body stays in the body pool with its shapes, joints, settings,
// velocity and user data, so that its ids, getters and setters keep working; it is only
// out of the stages, as if none of them had heard of it: its shapes have no proxies (no
// pairs, no queries, no sensor visits), it has no contacts, it is in no island and no
// awake list (the solver never moves it, it never sleeps), and its joints are neither
// solved (JointSet::gather_awake) nor island links. Body::enabled says so to the few
// calls that would otherwise reach for what it lacks (a proxy to move, an island to
// leave). Box2D v3 moves such a body into a solver set of its own; the alternative of
// keeping its proxies and contacts and skipping them in the step would cost every step
// a test per pair for a body meant to cost nothing.
#include "dynamics/body/shape_bounds.hpp"
#include "dynamics/recording/recorder.hpp"
#include "dynamics/world/world.hpp"
#include "dynamics/world/world_stages.hpp"

namespace i2d {

// A no-op changes nothing, so it is not recorded and rollback states saved before it
// still restore.
void World::set_body_enabled(int32_t body, bool enabled) {
    if (bodies_[body].enabled == enabled) {
        return;
    }
    RecordScope record(recorder_.get(), RecordedOp::set_body_enabled);
    record.write(body, enabled);
    ++structure_version_;
    if (enabled) {
        enable_body(body);
    } else {
        disable_body(body);
    }
}

// What touched it wakes, and its contacts end with end events, as when its shapes are
// destroyed; what it keeps (velocity, forces) waits for it to come back.
void World::disable_body(int32_t body) {
    leave_stages(body);
    Body& b = bodies_[body];
    b.enabled = false;
    // A mark left from before would keep mark_for_cover from queueing it once enabled.
    b.needs_cover = false;
}

// It comes back where it stands now, awake: its proxies are queried for pairs at the next
// step, its joints are solved and link islands again. The proxies are made from tight
// boxes taken afresh from its pose, whatever a snapshot brought for them.
void World::enable_body(int32_t body) {
    Body& b = bodies_[body];
    b.enabled = true;
    b.sleep_time = 0.0f;
    update_tight_boxes(b, shapes_);
    join_stages(body);
}

// Between steps: whatever touched the body wakes (it loses a support or meets one
// less obstacle), its contacts go, its shapes leave the broadphase, its joints stop
// linking islands (and, gathered again, stop being solved while it is away) and it
// leaves its island and the awake lists.
void World::leave_stages(int32_t body) {
    wake_body(body);
    stages_->contacts.visit_contacts(body, [this](int32_t, int32_t other) { wake_body(other); });
    for (int32_t s = bodies_[body].head_shape; s != null_index; s = shapes_[s].next_in_body) {
        destroy_contacts_of_shape(s, false);
        stages_->broad_phase.destroy_proxy(shapes_[s].proxy_key);
        shapes_[s].proxy_key = null_index;
    }
    stages_->joints.touch();
    unlink_joints(body);
    if (bodies_[body].type != BodyType::static_body) {
        stages_->islands.remove_body(body);
        follow_woken_bodies();
    }
}

// The body as its type now is: proxies in its type's tree (queried at once, so that even
// a static shape finds the bodies resting on it), an awake island of its own if it moves,
// and its joints linked (waking the bodies at their other ends).
void World::join_stages(int32_t body) {
    for (int32_t s = bodies_[body].head_shape; s != null_index; s = shapes_[s].next_in_body) {
        create_proxy(s, true);
    }
    if (bodies_[body].type != BodyType::static_body) {
        stages_->islands.add_body(body);
        mark_for_cover(body);
    }
    link_joints(body);
}

}  // namespace i2d
