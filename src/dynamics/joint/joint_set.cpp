// SPDX-License-Identifier: MIT
// JointSet: edges, gathering, the collision filter, measures.
#include "dynamics/joint/joint_set.hpp"

#include <cstddef>

#include "core/assert.hpp"
#include "core/prefetch.hpp"
#include "dynamics/joint/joint_constraint.hpp"
#include "math/math.hpp"

namespace i2d {

void JointSet::link_edge(int32_t joint, int32_t side) {
    JointEdge& edge = pool_[joint].edges[side];
    Body& body = bodies_[edge.body];
    const int32_t key = joint * 2 + side;
    edge.prev_key = null_index;
    edge.next_key = body.head_joint_key;
    if (body.head_joint_key != null_index) {
        pool_[body.head_joint_key >> 1].edges[body.head_joint_key & 1].prev_key = key;
    }
    body.head_joint_key = key;
    ++body.joint_count;
}

void JointSet::unlink_edge(int32_t joint, int32_t side) {
    const JointEdge& edge = pool_[joint].edges[side];
    Body& body = bodies_[edge.body];
    if (edge.prev_key != null_index) {
        pool_[edge.prev_key >> 1].edges[edge.prev_key & 1].next_key = edge.next_key;
    } else {
        body.head_joint_key = edge.next_key;
    }
    if (edge.next_key != null_index) {
        pool_[edge.next_key >> 1].edges[edge.next_key & 1].prev_key = edge.prev_key;
    }
    --body.joint_count;
}

int32_t JointSet::create(const JointDef& def) {
    const int32_t index = pool_.allocate();
    if (index == null_index) {
        return null_index;
    }
    Joint& j = pool_[index];
    j.def = def;
    j.edges[0].body = def.body_a;
    j.edges[1].body = def.body_b;
    link_edge(index, 0);
    link_edge(index, 1);
    ++version_;
    return index;
}

void JointSet::destroy(int32_t joint) {
    unlink_edge(joint, 0);
    unlink_edge(joint, 1);
    pool_.free(joint);
    ++version_;
}

// Walks the shorter list: a ragdoll's bodies have two or three joints each.
bool JointSet::keeps_apart(int32_t body_a, int32_t body_b) const {
    const Body& a = bodies_[body_a];
    const Body& b = bodies_[body_b];
    if (a.joint_count == 0 || b.joint_count == 0) {
        return false;
    }
    const int32_t from = a.joint_count <= b.joint_count ? body_a : body_b;
    const int32_t to = from == body_a ? body_b : body_a;
    for (int32_t key = bodies_[from].head_joint_key; key != null_index;) {
        const Joint& j = pool_[key >> 1];
        if (j.edges[(key & 1) ^ 1].body == to && !j.def.collide_connected) {
            return true;
        }
        key = j.edges[key & 1].next_key;
    }
    return false;
}

// A joint is taken from the first of its bodies that is awake: body A if it is, else B.
// An awake body is enabled; the other end may not be, and then the joint waits for it.
void JointSet::gather_awake(const std::vector<int32_t>& awake_bodies, std::vector<int32_t>& out) const {
    out.clear();
    gather_awake(awake_bodies.data(), awake_bodies.data() + awake_bodies.size(), out);
}

// The awake list jumps through the body pool and each body's joints through the joint
// pool: in rain, 80 % of the gathering waited on those reads. The bodies' joint lists
// are asked for this far ahead, and once a body is close, its first joint's edges.
constexpr std::ptrdiff_t gather_bodies_ahead = 8, gather_joints_ahead = 4;

void JointSet::gather_awake(const int32_t* first, const int32_t* last, std::vector<int32_t>& out) const {
    for (const int32_t* it = first; it != last; ++it) {
        if (last - it > gather_bodies_ahead) {
            prefetch_line(reinterpret_cast<const char*>(&bodies_[it[gather_bodies_ahead]]) +
                          offsetof(Body, head_joint_key));
        }
        if (last - it > gather_joints_ahead) {
            const int32_t key = bodies_[it[gather_joints_ahead]].head_joint_key;
            if (key != null_index) {
                prefetch_line(reinterpret_cast<const char*>(&pool_[key >> 1]) + offsetof(Joint, edges));
            }
        }
        const int32_t body = *it;
        for (int32_t key = bodies_[body].head_joint_key; key != null_index;) {
            const Joint& j = pool_[key >> 1];
            const int32_t side = key & 1;
            const bool a_awake = bodies_[j.edges[0].body].awake_index != null_index;
            const bool mine = side == 0 || !a_awake;
            const bool other_enabled = bodies_[j.edges[side ^ 1].body].enabled;
            if (mine && other_enabled && j.def.type != JointType::filter) {
                out.push_back(key >> 1);
            }
            key = j.edges[side].next_key;
        }
    }
}

JointMeasures JointSet::measure(int32_t joint) const {
    const Joint& j = pool_[joint];
    const JointDef& d = j.def;
    const Body& a = bodies_[d.body_a];
    const Body& b = bodies_[d.body_b];
    const Vec2 anchor_a = transform_point(a.transform, d.local_anchor_a);
    const Vec2 anchor_b = transform_point(b.transform, d.local_anchor_b);
    const Vec2 separation = anchor_b - anchor_a;
    JointMeasures m;
    m.length = length(separation);
    float reference = 0.0f;
    Vec2 local_axis;
    switch (d.type) {
        case JointType::revolute: reference = d.revolute.reference_angle; break;
        case JointType::weld: reference = d.weld.reference_angle; break;
        case JointType::prismatic:
            reference = d.prismatic.reference_angle;
            local_axis = d.prismatic.local_axis_a;
            break;
        case JointType::wheel: local_axis = d.wheel.local_axis_a; break;
        default: break;
    }
    m.angle = unwind_angle(exact_relative_angle(a.transform.q, b.transform.q) - reference);
    if (local_axis.x != 0.0f || local_axis.y != 0.0f) {
        const Vec2 axis = rotate(a.transform.q, local_axis);
        m.translation = dot(axis, separation);
        // d/dt of dot(axis, separation): the axis turns with A, the anchors move.
        const Vec2 va = a.linear_velocity + cross(a.angular_velocity, anchor_a - a.center);
        const Vec2 vb = b.linear_velocity + cross(b.angular_velocity, anchor_b - b.center);
        m.speed = dot(cross(a.angular_velocity, axis), separation) + dot(axis, vb - va);
    }
    return m;
}

bool angles_wound(const JointDef& d) {
    auto wound = [](float angle) { return angle > -pi && angle <= pi; };
    return wound(d.revolute.reference_angle) && wound(d.revolute.target_angle) &&
           wound(d.prismatic.reference_angle) && wound(d.weld.reference_angle) && wound(d.motor.angular_offset);
}

// Every body's list holds exactly its joints' edges, a joint links islands exactly when it
// should (between two enabled dynamic bodies, which then share an island), and its angles
// are wound.
void JointSet::validate() const {
#if defined(I2D_VALIDATE)
    int32_t edges_seen = 0;
    for (int32_t i = 0; i < bodies_.capacity(); ++i) {
        if (!bodies_.is_live(i)) {
            continue;
        }
        int32_t count = 0, prev_key = null_index;
        for (int32_t key = bodies_[i].head_joint_key; key != null_index;) {
            const JointEdge& edge = pool_[key >> 1].edges[key & 1];
            I2D_ASSERT(pool_.is_live(key >> 1) && edge.body == i && edge.prev_key == prev_key);
            I2D_ASSERT(count <= bodies_[i].joint_count);  // no cycle
            prev_key = key;
            key = edge.next_key;
            ++count;
        }
        I2D_ASSERT(count == bodies_[i].joint_count);
        edges_seen += count;
    }
    I2D_ASSERT(edges_seen == 2 * pool_.count());
    for (int32_t j = 0; j < pool_.capacity(); ++j) {
        if (!pool_.is_live(j)) {
            continue;
        }
        const Joint& joint = pool_[j];
        const bool links = should_link(joint);
        I2D_ASSERT(joint.island_link == links);
        I2D_ASSERT(angles_wound(joint.def));
        I2D_ASSERT(!links || bodies_[joint.def.body_a].island == bodies_[joint.def.body_b].island);
    }
#endif
}

}  // namespace i2d
