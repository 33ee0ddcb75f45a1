// SPDX-License-Identifier: MIT
// JointTrees: finding the trees, factoring them leaves first, and the exact passes.
#include "dynamics/joint/joint_tree.hpp"

#include <algorithm>
#include <cmath>

namespace i2d {

namespace {

using Vec3 = JointTrees::Vec3;
using Mat33 = JointTrees::Mat33;

Vec3 mul(const Mat33& a, const Vec3& v) {
    return {a.m[0] * v.x + a.m[1] * v.y + a.m[2] * v.z, a.m[3] * v.x + a.m[4] * v.y + a.m[5] * v.z,
            a.m[6] * v.x + a.m[7] * v.y + a.m[8] * v.z};
}

// Transpose(a) v.
Vec3 mul_transposed(const Mat33& a, const Vec3& v) {
    return {a.m[0] * v.x + a.m[3] * v.y + a.m[6] * v.z, a.m[1] * v.x + a.m[4] * v.y + a.m[7] * v.z,
            a.m[2] * v.x + a.m[5] * v.y + a.m[8] * v.z};
}

Mat33 mul(const Mat33& a, const Mat33& b) {
    Mat33 r;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            r.m[3 * i + j] = a.m[3 * i] * b.m[j] + a.m[3 * i + 1] * b.m[3 + j] + a.m[3 * i + 2] * b.m[6 + j];
        }
    }
    return r;
}

// a -= transpose(b) c.
void subtract_transposed_product(Mat33& a, const Mat33& b, const Mat33& c) {
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            a.m[3 * i + j] -= b.m[i] * c.m[j] + b.m[3 + i] * c.m[3 + j] + b.m[6 + i] * c.m[6 + j];
        }
    }
}

Mat33 transposed(const Mat33& a) {
    return {{a.m[0], a.m[3], a.m[6], a.m[1], a.m[4], a.m[7], a.m[2], a.m[5], a.m[8]}};
}

// By cofactors; zero when singular or not finite (the node's rows then stay as the sweep
// left them).
Mat33 inverse(const Mat33& a) {
    const float* m = a.m;
    const float c00 = m[4] * m[8] - m[5] * m[7], c01 = m[5] * m[6] - m[3] * m[8], c02 = m[3] * m[7] - m[4] * m[6];
    const float det = m[0] * c00 + m[1] * c01 + m[2] * c02;
    if (!(det != 0.0f && std::isfinite(det))) {
        return Mat33{};
    }
    const float d = 1.0f / det;
    return {{d * c00, d * (m[2] * m[7] - m[1] * m[8]), d * (m[1] * m[5] - m[2] * m[4]), d * c01,
             d * (m[0] * m[8] - m[2] * m[6]), d * (m[2] * m[3] - m[0] * m[5]), d * c02,
             d * (m[1] * m[6] - m[0] * m[7]), d * (m[0] * m[4] - m[1] * m[3])}};
}

// The joint's velocity rows as one of its bodies moves them, with its anchor where the
// body is now: rows (point x, point y, angle) over that body's (vx, vy, w); B counts
// plus, A minus; rows the exact solve does not take are zero, and so is the spin column
// of a body that cannot turn.
Mat33 joint_jacobian(const JointConstraint& c, const BodyState* states, bool body_b) {
    const float s = body_b ? 1.0f : -1.0f;
    const Vec2 r = rotate(states[body_b ? c.state_b : c.state_a].delta_rotation, body_b ? c.anchor_b : c.anchor_a);
    const bool turns = (body_b ? c.inv_inertia_b : c.inv_inertia_a) > 0.0f;
    Mat33 j;
    if (c.exact_rows & exact_point_rows) {
        j.m[0] = s;
        j.m[2] = turns ? -s * r.y : 0.0f;
        j.m[4] = s;
        j.m[5] = turns ? s * r.x : 0.0f;
    }
    if ((c.exact_rows & exact_angle_row) && turns) {
        j.m[8] = s;
    }
    return j;
}

// A node's own block: a body's mass (a body that cannot turn gets 1 for its spin, whose
// coupling column is zero), a joint's rows minus their compliance (0: rigid), padding
// rows -1 (they solve to 0).
Mat33 own_block(bool is_joint, uint8_t rows, float inv_mass, float inv_inertia, Vec3 compliance) {
    Mat33 d;
    if (!is_joint) {
        const float mass = 1.0f / inv_mass;
        d.m[0] = mass;
        d.m[4] = mass;
        d.m[8] = inv_inertia > 0.0f ? 1.0f / inv_inertia : 1.0f;
        return d;
    }
    d.m[0] = (rows & exact_point_rows) ? -compliance.x : -1.0f;
    d.m[4] = (rows & exact_point_rows) ? -compliance.y : -1.0f;
    d.m[8] = (rows & exact_angle_row) ? -compliance.z : -1.0f;
    return d;
}

// What each exact row's velocity must become minus what it is: the rows' velocity plus
// the bias's pull on their position error (point x, point y, angle); rows not taken are 0.
Vec3 row_targets(const JointConstraint& c, const BodyState* states, float bias_rate) {
    const JointBodies j = load_bodies(c, states);
    Vec3 target;
    if (c.exact_rows & exact_point_rows) {
        const Vec2 ra = rotate(j.dqa, c.anchor_a), rb = rotate(j.dqb, c.anchor_b);
        const Vec2 point = relative_velocity(j, ra, rb) + bias_rate * current_separation(c, j, ra, rb);
        target.x = point.x;
        target.y = point.y;
    }
    if (c.exact_rows & exact_angle_row) {
        target.z = (j.wb - j.wa) + bias_rate * current_angle(c, j);
    }
    return target;
}

// The impulse on a joint's exact rows (point x, point y, angle), applied to its bodies
// through the anchors where they are now and, when `keep`, added to its own.
void apply_impulse(JointConstraint& c, BodyState* states, const Vec3& impulse, bool keep = true) {
    JointBodies j = load_bodies(c, states);
    if (c.exact_rows & exact_point_rows) {
        const Vec2 linear{impulse.x, impulse.y};
        if (keep) {
            c.impulses.linear += linear;
        }
        apply_linear(c, j, rotate(j.dqa, c.anchor_a), rotate(j.dqb, c.anchor_b), linear);
    }
    if (c.exact_rows & exact_angle_row) {
        if (keep) {
            c.impulses.angular += impulse.z;
        }
        apply_angular(c, j, impulse.z);
    }
    store_bodies(c, j, states);
}

// Row r (0: point x, 1: point y, 2: angle) of a joint's three.
float& row_of(Vec3& v, int32_t r) { return r == 0 ? v.x : r == 1 ? v.y : v.z; }

// A cut row whose pivot falls below this fraction of the largest compliance among the
// cut rows depends on the rows before it, or the tree holds it already (a joint doubling
// another on the same anchors): it takes no impulse.
constexpr float dependent_row_fraction = 1e-5f;
// The loops' position projection (JointTrees::project). Its compliance on each rigid row,
// as a fraction of the inverse masses (or inertias, for an angle row) of the row's two
// bodies: what keeps a pose where the rows barely see a direction (a taut bridge,
// straight) from being thrown along it. Undamped, the taut bridge under its box opened
// 19 mm; at a thousandth of its planks' inverse mass, 0.3 mm.
constexpr float projection_compliance = 1e-3f;
// Damped, one projection closes part of an error along a direction the rows barely see;
// a second takes the rest of it on the pose the first left. The taut bridge opened 1.4
// mm with one and 0.3 mm with two.
constexpr int32_t projection_iterations = 2;
// A loop is projected while every joint in it is within these of closed: a few
// millimetres of drift, not a loop held to what it cannot do.
constexpr float projection_gap_slops = 10.0f;  // linear slops (0.05 m at the default 0.005 m)
constexpr float projection_angle_limit = 0.1f;  // rad

// Solves w x = b (w symmetric, positive semi-definite: the cut rows' compliance) by
// elimination in order; a dependent row gets 0. w and b are overwritten. The rows found
// dependent are written to `dropped` unless `decided`: then that decision stands (the
// projection's rows are compliant, so a dependent row looks less so there: judged
// afresh, the taut bridge's horizontal cut row was dropped and its joints opened 4 mm).
void solve_dense(float (&w)[max_cut_rows][max_cut_rows], float (&b)[max_cut_rows], float (&x)[max_cut_rows],
                 int32_t n, uint8_t* dropped, bool decided) {
    float largest = 0.0f;
    for (int32_t i = 0; i < n; ++i) {
        largest = std::max(largest, w[i][i]);
    }
    for (int32_t i = 0; i < n; ++i) {
        for (int32_t k = 0; k < i; ++k) {
            if (!dropped[k]) {
                const float f = w[i][k] / w[k][k];
                for (int32_t j = k + 1; j < n; ++j) {
                    w[i][j] -= f * w[k][j];
                }
                b[i] -= f * b[k];
            }
        }
        const bool usable = w[i][i] > 0.0f && std::isfinite(w[i][i]);
        dropped[i] = decided ? uint8_t(dropped[i] || !usable) : uint8_t(!(w[i][i] > dependent_row_fraction * largest && usable));
    }
    for (int32_t i = n - 1; i >= 0; --i) {
        float sum = b[i];
        for (int32_t j = i + 1; j < n; ++j) {
            sum -= w[i][j] * x[j];
        }
        x[i] = dropped[i] ? 0.0f : sum / w[i][i];
    }
}

}  // namespace

uint8_t exact_rows_of(const JointDef& def) {
    switch (def.type) {
        case JointType::revolute: return exact_point_rows;
        case JointType::weld:
            return uint8_t((def.weld.linear_hertz == 0.0f ? exact_point_rows : 0) |
                           (def.weld.angular_hertz == 0.0f ? exact_angle_row : 0));
        default: return 0;
    }
}

void JointTrees::build(std::vector<JointConstraint>& constraints, const Pool<Joint>& joints,
                       const Pool<Body>& bodies, int32_t state_count, bool may_hold) {
    if (!may_hold) {
        // The caller saw no joint between a moving body and one that does not move, so
        // every group is free and none is solved exactly: the key and the grouping below
        // would find that at a cost in the joints and awake bodies, every step the awake
        // list changes (rain's ragdolls, as they land and fall asleep).
        built_key_.clear();
        forget_trees(constraints);
        return;
    }
    const int32_t count = int32_t(constraints.size());
    key_scratch_.resize(std::size_t(key_width) * std::size_t(count));
    const auto state_if_moving = [](const Body& b) {
        return b.type == BodyType::dynamic && b.awake_index != null_index ? b.awake_index : null_index;
    };
    for (int32_t k = 0; k < count; ++k) {
        const JointDef& d = joints[constraints[std::size_t(k)].joint].def;
        const Body& a = bodies[d.body_a];
        const Body& b = bodies[d.body_b];
        int32_t* key = &key_scratch_[std::size_t(key_width * k)];
        key[0] = constraints[std::size_t(k)].joint;
        key[1] = d.type == JointType::mouse ? null_index : state_if_moving(a);
        key[2] = state_if_moving(b);
        // An angle row neither body can turn (fixed rotation, or fixed) has nothing to solve.
        const bool turns =
            (key[1] != null_index && a.inv_inertia > 0.0f) || (key[2] != null_index && b.inv_inertia > 0.0f);
        key[3] = exact_rows_of(d) & (turns ? 0xff : ~uint8_t(exact_angle_row));
    }
    if (key_scratch_ == built_key_ && !tree_starts_.empty()) {
        return;  // the same joints between the same states: the trees and marks hold
    }
    built_key_.swap(key_scratch_);
    rows_cleared_ = false;
    find_groups(state_count);
    // A group's rows are exact when a body that does not move holds it and it closes no
    // more loops than the cuts allow (each hold past the first closes one through the
    // fixed world). A free group (a ragdoll, a vehicle) is left to the sweep: solved
    // exactly after the contacts, a heap of 100 ragdolls kept a limb trembling at 8 Hz
    // and 0.05 m/s, never falling asleep, in about one landing of three; its widest joint
    // gap on landing fell only from 73 to 39 mm, since the continuous stage moves a fast
    // limb back alone. Nor does projecting a free tree after the step hold it: the moves
    // put limbs into what they lie on, contacts push them out, the soft rows open again,
    // and the heap's widest gap stayed at 32 to 113 mm, its bottom layers kept awake
    // (bench/results/epyc-2vcpu/2026-11-29-experiments-free-tree-projection-and-narrow-kernels.txt).
    const auto group_of = [this](const int32_t* key) {
        return set_of_[std::size_t(key[1] != null_index ? key[1] : key[2])];
    };
    const auto solved_exactly = [this](int32_t group) {
        const int32_t holds = group_holds_[std::size_t(group)];
        return holds >= 1 && group_loops_[std::size_t(group)] + holds - 1 <= max_cut_joints;
    };
    joint_starts_.assign(std::size_t(state_count) + 1, 0);
    for (int32_t k = 0; k < count; ++k) {
        const int32_t* key = &built_key_[std::size_t(key_width * k)];
        uint8_t rows = 0;
        if (key[3] != 0 && (key[1] != null_index || key[2] != null_index)) {
            rows = solved_exactly(group_of(key)) ? uint8_t(key[3]) : 0;
        }
        constraints[std::size_t(k)].exact_rows = rows;
        for (int32_t side = 1; side <= 2 && rows != 0; ++side) {
            if (key[side] != null_index) {
                ++joint_starts_[std::size_t(key[side]) + 1];
            }
        }
    }
    // Each state's exact joints, in solve order.
    for (int32_t s = 0; s < state_count; ++s) {
        joint_starts_[std::size_t(s) + 1] += joint_starts_[std::size_t(s)];
    }
    joint_list_.resize(std::size_t(joint_starts_[std::size_t(state_count)]));
    queue_.assign(joint_starts_.begin(), joint_starts_.end() - 1);  // fill positions
    for (int32_t k = 0; k < count; ++k) {
        const int32_t* key = &built_key_[std::size_t(key_width * k)];
        for (int32_t side = 1; side <= 2 && constraints[std::size_t(k)].exact_rows != 0; ++side) {
            if (key[side] != null_index) {
                joint_list_[std::size_t(queue_[std::size_t(key[side])]++)] = k;
            }
        }
    }
    // The trees, each rooted at its group's first joint (in solve order) to a body that
    // does not move.
    clear_trees();
    group_started_.assign(std::size_t(state_count), 0);
    joint_seen_.assign(std::size_t(count), 0);
    node_of_state_.assign(std::size_t(state_count), null_index);
    int32_t responses = 0;
    for (int32_t k = 0; k < count; ++k) {
        const int32_t* key = &built_key_[std::size_t(key_width * k)];
        if (constraints[std::size_t(k)].exact_rows == 0 || (key[1] != null_index && key[2] != null_index)) {
            continue;
        }
        uint8_t& started = group_started_[std::size_t(group_of(key))];
        if (started) {
            continue;
        }
        started = 1;
        tree_starts_.push_back(int32_t(nodes_.size()));
        cut_starts_.push_back(int32_t(cuts_.size()));
        response_starts_.push_back(responses);
        const int32_t first_node = int32_t(nodes_.size());
        add_tree(k);
        responses += cut_row_count(constraints, cut_starts_.back()) * (int32_t(nodes_.size()) - first_node);
    }
    finish_trees(responses);
}

// No trees, and no rows marked exact. The marks are cleared once: only a full build sets
// them, and lay_out keeps each slot's mark (new slots start cleared).
void JointTrees::forget_trees(std::vector<JointConstraint>& constraints) {
    if (!rows_cleared_) {
        for (JointConstraint& c : constraints) {
            c.exact_rows = 0;
        }
        rows_cleared_ = true;
    }
    clear_trees();
    finish_trees(0);
}

void JointTrees::clear_trees() {
    nodes_.clear();
    tree_starts_.clear();
    cuts_.clear();
    cut_starts_.clear();
    response_starts_.clear();
}

// Closes the lists of the trees added since clear_trees, which hold `responses` in all,
// and sizes the factors' room for their nodes.
void JointTrees::finish_trees(int32_t responses) {
    tree_starts_.push_back(int32_t(nodes_.size()));
    cut_starts_.push_back(int32_t(cuts_.size()));
    response_starts_.push_back(responses);
    inverse_pivots_.resize(nodes_.size());
    gains_.resize(nodes_.size());
    work_.resize(nodes_.size());
    saved_.resize(nodes_.size());
    cut_impulses_.resize(cuts_.size());
    cut_rows_dropped_.assign(3 * cuts_.size(), 0);
    responses_.resize(std::size_t(responses));
}

// The rows the cuts from `first_cut` on take.
int32_t JointTrees::cut_row_count(const std::vector<JointConstraint>& constraints, int32_t first_cut) const {
    int32_t rows = 0;
    for (std::size_t c = std::size_t(first_cut); c < cuts_.size(); ++c) {
        const uint8_t exact = constraints[std::size_t(cuts_[c].constraint)].exact_rows;
        rows += ((exact & exact_point_rows) ? 2 : 0) + ((exact & exact_angle_row) ? 1 : 0);
    }
    return rows;
}

// Groups the moving bodies joined by candidate joints (union-find), counting each
// group's holds and the loops among its moving bodies.
void JointTrees::find_groups(int32_t state_count) {
    set_of_.resize(std::size_t(state_count));
    group_holds_.assign(std::size_t(state_count), 0);
    group_loops_.assign(std::size_t(state_count), 0);
    for (int32_t s = 0; s < state_count; ++s) {
        set_of_[std::size_t(s)] = s;
    }
    const auto find = [this](int32_t s) {
        while (set_of_[std::size_t(s)] != s) {
            set_of_[std::size_t(s)] = set_of_[std::size_t(set_of_[std::size_t(s)])];
            s = set_of_[std::size_t(s)];
        }
        return s;
    };
    const int32_t count = int32_t(built_key_.size()) / key_width;
    for (int32_t k = 0; k < count; ++k) {
        const int32_t* key = &built_key_[std::size_t(key_width * k)];
        if (key[3] == 0 || (key[1] == null_index && key[2] == null_index)) {
            continue;
        }
        if (key[1] == null_index || key[2] == null_index) {
            ++group_holds_[std::size_t(find(key[1] != null_index ? key[1] : key[2]))];
            continue;
        }
        const int32_t root_a = find(key[1]), root_b = find(key[2]);
        if (root_a == root_b) {
            ++group_loops_[std::size_t(root_a)];
            continue;
        }
        set_of_[std::size_t(root_a)] = root_b;
        group_holds_[std::size_t(root_b)] += group_holds_[std::size_t(root_a)];
        group_loops_[std::size_t(root_b)] += group_loops_[std::size_t(root_a)];
    }
    // Flattened: each state names its group's root.
    for (int32_t s = 0; s < state_count; ++s) {
        set_of_[std::size_t(s)] = find(s);
    }
}

// Breadth first from the root joint: a joint's moving body below it, then a body's joints
// but the one it hangs from. A body is claimed by the first joint that reaches it; a
// later joint to it, or a second joint to a body that does not move, closes a loop and
// becomes a cut. Parents come before their children.
void JointTrees::add_tree(int32_t root_joint) {
    const int32_t first = int32_t(nodes_.size());
    const std::size_t first_cut = cuts_.size();
    nodes_.push_back({null_index, root_joint, true, false});
    joint_seen_[std::size_t(root_joint)] = 1;
    const int32_t* root_key = &built_key_[std::size_t(key_width * root_joint)];
    node_of_state_[std::size_t(root_key[1] != null_index ? root_key[1] : root_key[2])] = first;  // claimed
    for (int32_t n = first; n < int32_t(nodes_.size()); ++n) {
        const Node node = nodes_[std::size_t(n)];
        if (node.is_joint) {
            const int32_t* key = &built_key_[std::size_t(key_width * node.item)];
            const int32_t from = node.parent == null_index ? null_index : nodes_[std::size_t(node.parent)].item;
            for (int32_t side = 1; side <= 2; ++side) {
                const int32_t body = key[side];
                if (body != null_index && body != from) {
                    node_of_state_[std::size_t(body)] = int32_t(nodes_.size());
                    nodes_.push_back({n, body, false, side == 2});
                }
            }
            continue;
        }
        for (int32_t e = joint_starts_[std::size_t(node.item)]; e < joint_starts_[std::size_t(node.item) + 1]; ++e) {
            const int32_t k = joint_list_[std::size_t(e)];
            if (joint_seen_[std::size_t(k)]) {
                continue;
            }
            joint_seen_[std::size_t(k)] = 1;
            const int32_t* key = &built_key_[std::size_t(key_width * k)];
            const int32_t other = key[1] == node.item ? key[2] : key[1];
            if (other == null_index || node_of_state_[std::size_t(other)] != null_index) {
                cuts_.push_back({k, null_index, null_index});
                continue;
            }
            node_of_state_[std::size_t(other)] = n;  // claimed: its own node follows the joint's
            nodes_.push_back({n, k, true, key[2] == node.item});
        }
    }
    for (std::size_t c = first_cut; c < cuts_.size(); ++c) {
        const int32_t* key = &built_key_[std::size_t(key_width * cuts_[c].constraint)];
        cuts_[c].node_a = key[1] == null_index ? null_index : node_of_state_[std::size_t(key[1])];
        cuts_[c].node_b = key[2] == null_index ? null_index : node_of_state_[std::size_t(key[2])];
    }
}
// Leaves first: each node's pivot is its own block less what its children's elimination
// left in it; its gain carries its solution into its parent's.
void JointTrees::factor(int32_t tree, const std::vector<JointConstraint>& constraints, const BodyState* states,
                        const BodyMotion* motions, bool compliant) {
    const int32_t first = tree_starts_[std::size_t(tree)], last = tree_starts_[std::size_t(tree) + 1];
    for (int32_t n = first; n < last; ++n) {
        const Node& node = nodes_[std::size_t(n)];
        const BodyMotion& m = motions[node.is_joint ? 0 : node.item];
        const uint8_t rows = node.is_joint ? constraints[std::size_t(node.item)].exact_rows : 0;
        Vec3 compliance;
        if (node.is_joint && compliant) {
            const JointConstraint& c = constraints[std::size_t(node.item)];
            const float linear = projection_compliance * (c.inv_mass_a + c.inv_mass_b);
            compliance = {linear, linear, projection_compliance * (c.inv_inertia_a + c.inv_inertia_b)};
        }
        inverse_pivots_[std::size_t(n)] = own_block(node.is_joint, rows, m.inv_mass, m.inv_inertia, compliance);
    }
    for (int32_t n = last - 1; n >= first; --n) {
        const Node& node = nodes_[std::size_t(n)];
        const Mat33 pivot_inverse = inverse(inverse_pivots_[std::size_t(n)]);
        inverse_pivots_[std::size_t(n)] = pivot_inverse;
        if (node.parent == null_index) {
            continue;
        }
        // The block between the node and its parent: J of the joint for the body.
        const Node& parent = nodes_[std::size_t(node.parent)];
        const JointConstraint& c = constraints[std::size_t(node.is_joint ? node.item : parent.item)];
        const Mat33 j = joint_jacobian(c, states, node.parent_is_b);
        const Mat33 to_parent = node.is_joint ? j : transposed(j);
        const Mat33 gain = mul(pivot_inverse, to_parent);
        gains_[std::size_t(n)] = gain;
        subtract_transposed_product(inverse_pivots_[std::size_t(node.parent)], to_parent, gain);
    }
}

void JointTrees::solve(int32_t begin, int32_t end, std::vector<JointConstraint>& constraints, BodyState* states,
                       const BodyMotion* motions, const JointStep& step, bool use_bias) {
    const float bias_rate = use_bias ? step.rigid.bias_rate : 0.0f;
    for (int32_t t = begin; t < end; ++t) {
        factor(t, constraints, states, motions, false);
        set_right_side(t, constraints, states, bias_rate);
        substitute(t, &work_[std::size_t(tree_starts_[std::size_t(t)])]);
        solve_cuts(t, constraints, states, bias_rate, false);
        apply(t, constraints, states, step);
    }
}

// The exact solve of a displacement instead of a velocity change: with the bodies taken
// at rest and the rows' targets their position errors, the velocities the solve leaves
// are the moves that close the errors (M^-1 J^T lambda, J dx = -C), made good on the
// poses while the velocities and the joints' impulses stay as they were.
void JointTrees::project(int32_t begin, int32_t end, std::vector<JointConstraint>& constraints, BodyState* states,
                         const BodyMotion* motions, float linear_slop) {
    const float gap_limit = projection_gap_slops * linear_slop;
    for (int32_t t = begin; t < end; ++t) {
        if (!projects(t, constraints, states, gap_limit)) {
            continue;
        }
        const int32_t first = tree_starts_[std::size_t(t)], last = tree_starts_[std::size_t(t) + 1];
        for (int32_t iteration = 0; iteration < projection_iterations; ++iteration) {
            save_velocities(first, last, states);
            for (int32_t n = first; n < last; ++n) {
                if (!nodes_[std::size_t(n)].is_joint) {
                    states[nodes_[std::size_t(n)].item].linear_velocity = {0.0f, 0.0f};
                    states[nodes_[std::size_t(n)].item].angular_velocity = 0.0f;
                }
            }
            factor(t, constraints, states, motions, true);
            set_right_side(t, constraints, states, 1.0f);
            substitute(t, &work_[std::size_t(first)]);
            solve_cuts(t, constraints, states, 1.0f, true);
            for (int32_t n = first; n < last; ++n) {
                const Node& node = nodes_[std::size_t(n)];
                if (node.is_joint) {
                    const Vec3& x = work_[std::size_t(n)];
                    apply_impulse(constraints[std::size_t(node.item)], states, {-x.x, -x.y, -x.z}, false);
                }
            }
            for (int32_t k = cut_starts_[std::size_t(t)]; k < cut_starts_[std::size_t(t) + 1]; ++k) {
                apply_impulse(constraints[std::size_t(cuts_[std::size_t(k)].constraint)], states,
                              cut_impulses_[std::size_t(k)], false);
            }
            move_bodies(first, last, states, gap_limit);
        }
    }
}

// A tree without loops is held together by the velocity solve. A loop with a joint pulled
// far apart is not drifting but held to what it cannot do (a body held at two places that
// cannot both hold) or torn by a blow: moving its bodies would trade one joint's error
// for another's.
bool JointTrees::projects(int32_t tree, const std::vector<JointConstraint>& constraints, const BodyState* states,
                          float gap_limit) const {
    const int32_t cut_begin = cut_starts_[std::size_t(tree)], cut_end = cut_starts_[std::size_t(tree) + 1];
    if (cut_begin == cut_end) {
        return false;
    }
    const auto near = [&](const JointConstraint& c) {
        const JointBodies j = load_bodies(c, states);
        if ((c.exact_rows & exact_point_rows) &&
            !(length(current_separation(c, j, rotate(j.dqa, c.anchor_a), rotate(j.dqb, c.anchor_b))) <=
              gap_limit)) {
            return false;
        }
        return !(c.exact_rows & exact_angle_row) || std::fabs(current_angle(c, j)) <= projection_angle_limit;
    };
    for (int32_t n = tree_starts_[std::size_t(tree)]; n < tree_starts_[std::size_t(tree) + 1]; ++n) {
        const Node& node = nodes_[std::size_t(n)];
        if (node.is_joint && !near(constraints[std::size_t(node.item)])) {
            return false;
        }
    }
    for (int32_t k = cut_begin; k < cut_end; ++k) {
        if (!near(constraints[std::size_t(cuts_[std::size_t(k)].constraint)])) {
            return false;
        }
    }
    return true;
}

// The projection's moves (left in the velocities) onto the poses; the velocities back.
// Moves larger than the errors they close could be (the gap limit, the angle limit) come
// from factors too ill-conditioned for floats, and are not made.
void JointTrees::move_bodies(int32_t first, int32_t last, BodyState* states, float gap_limit) const {
    bool bounded = true;
    for (int32_t n = first; n < last; ++n) {
        if (!nodes_[std::size_t(n)].is_joint) {
            const BodyState& s = states[nodes_[std::size_t(n)].item];
            bounded = bounded && length(s.linear_velocity) <= gap_limit &&
                      std::fabs(s.angular_velocity) <= projection_angle_limit;
        }
    }
    for (int32_t n = first; n < last; ++n) {
        const Node& node = nodes_[std::size_t(n)];
        if (node.is_joint) {
            continue;
        }
        BodyState& s = states[node.item];
        if (bounded) {
            s.delta_position += s.linear_velocity;
            s.delta_rotation = integrate_rotation(s.delta_rotation, s.angular_velocity);
        }
        const Vec3& v = saved_[std::size_t(n)];
        s.linear_velocity = {v.x, v.y};
        s.angular_velocity = v.z;
    }
}

// Each joint's rows, driven to the bias (or to rest); the bodies' momentum is unchanged.
void JointTrees::set_right_side(int32_t tree, const std::vector<JointConstraint>& constraints,
                                const BodyState* states, float bias_rate) {
    const int32_t first = tree_starts_[std::size_t(tree)], last = tree_starts_[std::size_t(tree) + 1];
    for (int32_t n = first; n < last; ++n) {
        const Node& node = nodes_[std::size_t(n)];
        const Vec3 target = node.is_joint ? row_targets(constraints[std::size_t(node.item)], states, bias_rate) : Vec3{};
        work_[std::size_t(n)] = {-target.x, -target.y, -target.z};
    }
}

// Leaves up, then down from the root.
void JointTrees::substitute(int32_t tree, Vec3* x) const {
    const int32_t first = tree_starts_[std::size_t(tree)], last = tree_starts_[std::size_t(tree) + 1];
    for (int32_t n = last - 1; n > first; --n) {
        const Vec3 carried = mul_transposed(gains_[std::size_t(n)], x[n - first]);
        Vec3& parent = x[nodes_[std::size_t(n)].parent - first];
        parent.x -= carried.x;
        parent.y -= carried.y;
        parent.z -= carried.z;
    }
    for (int32_t n = first; n < last; ++n) {
        const Node& node = nodes_[std::size_t(n)];
        Vec3 v = mul(inverse_pivots_[std::size_t(n)], x[n - first]);
        if (node.parent != null_index) {
            const Vec3 down = mul(gains_[std::size_t(n)], x[node.parent - first]);
            v.x -= down.x;
            v.y -= down.y;
            v.z -= down.z;
        }
        x[n - first] = v;
    }
}

// The impulses on the cut rows that leave them at their targets too: with the tree's
// answer to a unit impulse on each cut row, W lambda = -(target + J_cut dv), solved
// densely, and the answers added to the tree's solution in proportion.
void JointTrees::solve_cuts(int32_t tree, const std::vector<JointConstraint>& constraints, const BodyState* states,
                            float bias_rate, bool projecting) {
    const int32_t cut_begin = cut_starts_[std::size_t(tree)], cut_end = cut_starts_[std::size_t(tree) + 1];
    if (cut_begin == cut_end) {
        return;
    }
    const int32_t first = tree_starts_[std::size_t(tree)], size = tree_starts_[std::size_t(tree) + 1] - first;
    Vec3* base = &work_[std::size_t(first)];
    Vec3* responses = &responses_[std::size_t(response_starts_[std::size_t(tree)])];
    // Each cut row: its cut, its row, and its Jacobian row over each moving body.
    struct CutRow {
        int32_t cut, row;
        Vec3 over_a, over_b;
    };
    CutRow rows[max_cut_rows];
    int32_t row_count = 0;
    for (int32_t c = cut_begin; c < cut_end; ++c) {
        const JointConstraint& joint = constraints[std::size_t(cuts_[std::size_t(c)].constraint)];
        const Mat33 ja = joint_jacobian(joint, states, false), jb = joint_jacobian(joint, states, true);
        for (int32_t r = 0; r < 3; ++r) {
            const bool taken = r < 2 ? (joint.exact_rows & exact_point_rows) : (joint.exact_rows & exact_angle_row);
            if (taken) {
                rows[row_count++] = {c, r, {ja.m[3 * r], ja.m[3 * r + 1], ja.m[3 * r + 2]},
                                     {jb.m[3 * r], jb.m[3 * r + 1], jb.m[3 * r + 2]}};
            }
        }
    }
    const auto dot = [](const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; };
    // The row's velocity change in a solution x.
    const auto row_change = [&](const CutRow& row, const Vec3* x) {
        const Cut& cut = cuts_[std::size_t(row.cut)];
        float change = 0.0f;
        change += cut.node_a == null_index ? 0.0f : dot(row.over_a, x[cut.node_a - first]);
        change += cut.node_b == null_index ? 0.0f : dot(row.over_b, x[cut.node_b - first]);
        return change;
    };
    const auto add_to = [](Vec3& a, const Vec3& b, float scale) {
        a.x += scale * b.x;
        a.y += scale * b.y;
        a.z += scale * b.z;
    };
    float w[max_cut_rows][max_cut_rows];
    float rhs[max_cut_rows];
    for (int32_t i = 0; i < row_count; ++i) {
        Vec3* answer = responses + std::size_t(i) * std::size_t(size);
        std::fill(answer, answer + size, Vec3{});
        const Cut& cut = cuts_[std::size_t(rows[i].cut)];
        if (cut.node_a != null_index) {
            add_to(answer[cut.node_a - first], rows[i].over_a, 1.0f);
        }
        if (cut.node_b != null_index) {
            add_to(answer[cut.node_b - first], rows[i].over_b, 1.0f);
        }
        substitute(tree, answer);
        for (int32_t j = 0; j < row_count; ++j) {
            w[j][i] = row_change(rows[j], answer);
        }
    }
    for (int32_t i = 0; i < row_count; ++i) {
        Vec3 target = row_targets(constraints[std::size_t(cuts_[std::size_t(rows[i].cut)].constraint)], states,
                                  bias_rate);
        rhs[i] = -row_of(target, rows[i].row) - row_change(rows[i], base);
    }
    float lambda[max_cut_rows];
    solve_dense(w, rhs, lambda, row_count, &cut_rows_dropped_[std::size_t(3 * cut_begin)], projecting);
    for (int32_t c = cut_begin; c < cut_end; ++c) {
        cut_impulses_[std::size_t(c)] = {};
    }
    for (int32_t i = 0; i < row_count; ++i) {
        const Vec3* answer = responses + std::size_t(i) * std::size_t(size);
        for (int32_t n = 0; n < size; ++n) {
            add_to(base[n], answer[n], lambda[i]);
        }
        row_of(cut_impulses_[std::size_t(rows[i].cut)], rows[i].row) = lambda[i];
    }
}

// The impulses (the joints' unknowns, negated) act through the anchors where the bodies
// are now, as the sweep's do: the factors are the step start's, and a body's own
// unknowns, which follow them, would let a turned joint do work (a swinging pendulum
// gained four times its energy in a minute). Guarded as the sweep's passes are: a tree
// whose factors are too ill-conditioned for floats (masses and lever arms apart by a
// dozen orders of magnitude) can throw a body from a few m/s to 1e19 in one pass; then
// the pass is undone and the tree's joints give up their impulses.
void JointTrees::apply(int32_t tree, std::vector<JointConstraint>& constraints, BodyState* states,
                       const JointStep& step) {
    const int32_t first = tree_starts_[std::size_t(tree)], last = tree_starts_[std::size_t(tree) + 1];
    save_velocities(first, last, states);
    for (int32_t n = first; n < last; ++n) {
        const Node& node = nodes_[std::size_t(n)];
        if (!node.is_joint) {
            continue;
        }
        const Vec3& x = work_[std::size_t(n)];
        apply_impulse(constraints[std::size_t(node.item)], states, {-x.x, -x.y, -x.z});
    }
    for (int32_t k = cut_starts_[std::size_t(tree)]; k < cut_starts_[std::size_t(tree) + 1]; ++k) {
        apply_impulse(constraints[std::size_t(cuts_[std::size_t(k)].constraint)], states,
                      cut_impulses_[std::size_t(k)]);
    }
    if (!bodies_within_limits(first, last, states, step)) {
        undo_pass(first, last, constraints, states);
        for (int32_t k = cut_starts_[std::size_t(tree)]; k < cut_starts_[std::size_t(tree) + 1]; ++k) {
            constraints[std::size_t(cuts_[std::size_t(k)].constraint)].impulses = {};
        }
    }
}

void JointTrees::save_velocities(int32_t first, int32_t last, const BodyState* states) {
    for (int32_t n = first; n < last; ++n) {
        const Node& node = nodes_[std::size_t(n)];
        if (!node.is_joint) {
            const BodyState& s = states[node.item];
            saved_[std::size_t(n)] = {s.linear_velocity.x, s.linear_velocity.y, s.angular_velocity};
        }
    }
}

bool JointTrees::bodies_within_limits(int32_t first, int32_t last, const BodyState* states,
                                      const JointStep& step) const {
    bool within = true;
    for (int32_t n = first; n < last; ++n) {
        const Node& node = nodes_[std::size_t(n)];
        if (!node.is_joint) {
            const BodyState& s = states[node.item];
            within = within && body_within_limits(s.linear_velocity, s.angular_velocity, step);
        }
    }
    return within;
}

void JointTrees::undo_pass(int32_t first, int32_t last, std::vector<JointConstraint>& constraints,
                           BodyState* states) const {
    for (int32_t n = first; n < last; ++n) {
        const Node& node = nodes_[std::size_t(n)];
        if (node.is_joint) {
            constraints[std::size_t(node.item)].impulses = {};
        } else {
            const Vec3& v = saved_[std::size_t(n)];
            states[node.item].linear_velocity = {v.x, v.y};
            states[node.item].angular_velocity = v.z;
        }
    }
}

}  // namespace i2d
