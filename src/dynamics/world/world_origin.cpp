// SPDX-License-Identifier: MIT
// World::shift_origin: every position the world keeps, seen from a new origin.
//
// Design note: what is stored relative to a body (shape geometry, contact anchors and the
// poses recycling compares, joint anchors) stays as it is; what is stored in world
// coordinates moves: the bodies' transforms and centres (center0 too, where the continuous
// stage's sweep starts), the shapes' tight, fat and ahead boxes, the broadphase's boxes
// (trees, boxes ahead, moves waiting for their commit), the mouse joints' targets, and the
// points and poses of the last step's events, which callers may still be reading. Each
// becomes its old value less the new origin, as float subtraction rounds it: one rounding
// per coordinate, and since subtraction rounds monotonically every box still holds what it
// held and every tree node is still the exact union of its children. Nothing wakes and no
// pair changes, so the next step goes on as the old one would have, seen from the new
// origin (up to the rounding of positions, which is the point: far from the origin floats
// are coarse). Box2D 2.4's b2World::ShiftOrigin did the same.
#include "dynamics/recording/recorder.hpp"
#include "dynamics/world/world.hpp"
#include "dynamics/world/world_stages.hpp"

namespace i2d {

namespace {

// The mouse joint pulls toward a target in the world: the only joint setting in world
// coordinates.
void shift_mouse_targets(Pool<Joint>& joints, Vec2 new_origin) {
    for (int32_t j = 0; j < joints.capacity(); ++j) {
        if (joints.is_live(j) && joints[j].def.type == JointType::mouse) {
            joints[j].def.mouse.target -= new_origin;
        }
    }
}

// The last step's events stay valid until the next step: their world points and poses
// move with everything else.
void shift_events(WorldEvents& events, Vec2 new_origin) {
    for (ContactBeginEvent& e : events.contact_begin) {
        for (int32_t i = 0; i < e.manifold.point_count; ++i) {
            e.manifold.points[i].point -= new_origin;
        }
    }
    for (ContactHitEvent& e : events.contact_hits) {
        e.point -= new_origin;
    }
    for (BodyMoveEvent& e : events.body_moves) {
        e.transform.p -= new_origin;
    }
    for (BodyQuarantineEvent& e : events.body_quarantines) {
        e.transform.p -= new_origin;
    }
}

}  // namespace

void World::shift_origin(Vec2 new_origin) {
    RecordScope record(recorder_.get(), RecordedOp::shift_origin);
    record.write(new_origin);
    ++structure_version_;  // a rollback state saved before holds positions of the old origin
    for (int32_t i = 0; i < bodies_.capacity(); ++i) {
        if (bodies_.is_live(i)) {
            Body& b = bodies_[i];
            b.transform.p -= new_origin;
            b.center -= new_origin;
            b.center0 -= new_origin;
        }
    }
    for (int32_t i = 0; i < shapes_.capacity(); ++i) {
        if (shapes_.is_live(i)) {
            Shape& s = shapes_[i];
            s.aabb = relative_to(s.aabb, new_origin);
            s.fat_aabb = relative_to(s.fat_aabb, new_origin);
            s.ahead_aabb = relative_to(s.ahead_aabb, new_origin);
        }
    }
    stages_->broad_phase.shift_origin(new_origin);
    shift_mouse_targets(stages_->joints.pool(), new_origin);
    shift_events(stages_->events.current, new_origin);
}

}  // namespace i2d
