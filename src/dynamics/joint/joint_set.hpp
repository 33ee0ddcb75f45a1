// SPDX-License-Identifier: MIT
// JointSet: the joints' links to their bodies, which joints to solve, which bodies may
// not collide, and the measures and events callers read.
//
// Design note: each joint has two edges, one per body, threaded into a list per body
// (Body::head_joint_key), exactly as contacts are, so that everything a body needs of
// its joints (destroying them with it, the islands' links, waking, the collision
// filter) walks its own short list. The joints to solve are gathered each step from
// the awake bodies in awake order, so a sleeping world with many joints pays nothing
// and the order is the same whatever the worker count.
#pragma once

#include <cstdint>
#include <vector>

#include "core/pool.hpp"
#include "dynamics/body/body.hpp"
#include "dynamics/joint/joint.hpp"

namespace i2d {

class LoadIo;
class SaveIo;

class JointSet {
public:
    explicit JointSet(Pool<Body>& bodies) : bodies_(bodies) {}

    /// The joints. Their settings change through the world (World::set_joint_def), their
    /// impulses and reactions at the end of each step (joint_solver.hpp).
    Pool<Joint>& pool() { return pool_; }
    const Pool<Joint>& pool() const { return pool_; }
    Joint& joint(int32_t joint) { return pool_[joint]; }
    const Joint& joint(int32_t joint) const { return pool_[joint]; }

    /// Creates the joint and links it into both bodies' lists; null_index when full.
    int32_t create(const JointDef& def);
    /// Unlinks and frees it (island links are the caller's, see World::destroy_joint).
    void destroy(int32_t joint);

    /// visit(joint, other_body) for each joint of the body.
    template <class Visit>
    void visit_joints(int32_t body, Visit&& visit) const {
        for (int32_t key = bodies_[body].head_joint_key; key != null_index;) {
            const Joint& j = pool_[key >> 1];
            const int32_t next = j.edges[key & 1].next_key;
            visit(key >> 1, j.edges[(key & 1) ^ 1].body);
            key = next;
        }
    }
    /// visit(other_body) for each joint of the body that links the two islands.
    template <class Visit>
    void visit_links(int32_t body, Visit&& visit) const {
        visit_joints(body, [&](int32_t joint, int32_t other) {
            if (pool_[joint].island_link) {
                visit(other);
            }
        });
    }
    /// Whether a joint between the two bodies keeps them from colliding.
    bool keeps_apart(int32_t body_a, int32_t body_b) const;
    /// Whether this kind of joint joins its bodies' islands when both are dynamic.
    static bool links_islands(const Joint& joint) { return joint.def.type != JointType::filter; }
    /// Whether the joint joins its bodies' islands now: a kind that does, between two
    /// dynamic bodies, both enabled.
    bool should_link(const Joint& joint) const {
        const Body& a = bodies_[joint.def.body_a];
        const Body& b = bodies_[joint.def.body_b];
        return links_islands(joint) && a.type == BodyType::dynamic && b.type == BodyType::dynamic && a.enabled &&
               b.enabled;
    }

    /// The joints to solve this step: each once, gathered from the awake bodies in awake
    /// order; filter joints, joints with no moving body and joints to a disabled body
    /// are left out.
    void gather_awake(const std::vector<int32_t>& awake_bodies, std::vector<int32_t>& out) const;
    /// The same for the awake bodies [first, last) of that order, appended to `out`: the
    /// parts of a split awake list, joined in order, gather what the whole list does.
    void gather_awake(const int32_t* first, const int32_t* last, std::vector<int32_t>& out) const;

    JointMeasures measure(int32_t joint) const;

    int32_t count() const { return pool_.count(); }
    /// Changes whenever a joint is created or destroyed or a body of one changes type:
    /// with the islands' awake version, whether the joints to solve can have changed.
    uint64_t version() const { return version_; }
    void touch() { ++version_; }

    /// Aborts on a broken list or island link; does nothing unless built with I2D_VALIDATE.
    void validate() const;

    // Snapshots (snapshot/stage_snapshots.cpp): the joints saved, loaded, or swapped with
    // another set's loaded ones; the links between joints and bodies are checked by the
    // world (snapshot_checks.cpp).
    void save(SaveIo& io) const;
    void load(LoadIo& io);
    void swap_state(JointSet& other) noexcept;

private:
    void link_edge(int32_t joint, int32_t side);
    void unlink_edge(int32_t joint, int32_t side);

    Pool<Body>& bodies_;
    Pool<Joint> pool_;
    uint64_t version_ = 0;
};

}  // namespace i2d
