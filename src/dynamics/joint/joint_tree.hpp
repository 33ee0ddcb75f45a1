// SPDX-License-Identifier: MIT
// JointTrees: the rigid rows of joints that join bodies into trees, solved exactly.
//
// Design note: a Gauss-Seidel sweep over soft rows leaves a hanging chain stretched by
// its load over each joint's stiffness, however many sweeps run (2.9 cm for 20 light
// links, 30 cm under a weight 100 times a link's, as in Box2D v3), and a stiffer row
// than a quarter of the substep rate makes the sweep itself unstable. Where joints and
// the moving bodies they join form a tree, their rigid rows can be solved exactly in time
// linear in their number: the matrix [M J^T; J 0] of a tree, ordered from the leaves up,
// factors with no fill-in (Baraff, "Linear-Time Dynamics using Lagrange Multipliers",
// SIGGRAPH 1996). So each solve pass ends, after the colours' sweep over contacts and the
// joints' other rows (limits, motors, springs), with that exact solve: the rigid rows
// hold when the pass ends, with a bias that pulls position errors back at the world's
// joint rate in the pushing pass and none when relaxing.
//
// A group of moving bodies joined by rigid rows is solved this way when a body that does
// not move holds it (the tree is rooted at that joint). A group that closes a few loops
// (a bridge hung at both ends, a second hanger, a ring) is solved exactly too: its
// spanning tree is factored as above, and the joints that close the loops (the cuts) get
// their impulses from the small dense system of their rows' compliance through the tree,
// W = J_cut A^-1 J_cut^T, one tree solve per cut row (substructuring). A group with more
// cuts than max_cut_joints (a grid), and a free group (a ragdoll, a vehicle), are left to
// the sweep whole (joint_tree.cpp says why for free groups).
//
// Every node holds 3 unknowns: a body's (vx, vy, w), a joint's impulses on its rows
// (point x, point y, angle), unused rows padded so that every block is 3 x 3. The matrix
// is factored afresh for each pass, with the anchors where the bodies are then. Factors
// kept from an earlier pass solve a joint that turned since with the wrong effective mass
// and let the impulses do work: kept for a step, a pendulum swinging at 60 degrees gained
// four times its energy in a minute; kept from a substep's pushing pass for its relax
// pass, a chain with a 100 kg weight released level whipped its links to 140 m/s.
#pragma once

#include <cstdint>
#include <vector>

#include "core/pool.hpp"
#include "dynamics/body/body.hpp"
#include "dynamics/solver/body_state.hpp"
#include "dynamics/joint/joint.hpp"
#include "dynamics/joint/joint_constraint.hpp"

namespace i2d {

/// The rows a joint gives the exact solve (bits of JointConstraint::exact_rows).
enum ExactRows : uint8_t { exact_point_rows = 1, exact_angle_row = 2 };

/// Which rows of this joint are rigid and may be solved exactly: the revolute joint's
/// point, the weld's point and angle where their stiffness is 0 (rigid).
uint8_t exact_rows_of(const JointDef& def);

/// Joints that close loops in one group solved exactly; a group with more is left to the
/// sweep. Each costs a tree solve per row in every pass, and a grid of N bodies closes
/// about N loops.
constexpr int32_t max_cut_joints = 4;
constexpr int32_t max_cut_rows = 3 * max_cut_joints;

class JointTrees {
public:
    /// Finds the trees among the step's joints (laid out: each constraint knows its joint),
    /// each with the joints that close its loops, and marks in each constraint the rows
    /// the exact solve takes from it. Rebuilt only when a joint, its rows or its bodies'
    /// places changed. One thread, before the joints are prepared.
    /// `may_hold`: false when the caller knows that no joint joins a moving body to one
    /// that does not move (then nothing is solved exactly, and nothing is read).
    void build(std::vector<JointConstraint>& constraints, const Pool<Joint>& joints, const Pool<Body>& bodies,
               int32_t state_count, bool may_hold);
    int32_t tree_count() const { return int32_t(tree_starts_.size()) - 1; }
    /// Joints that close loops, over all trees.
    int32_t cut_count() const { return int32_t(cuts_.size()); }

    /// One exact pass over trees [begin, end): the rows' impulses that leave them at the
    /// bias (use_bias) or at rest, added to the joints and the bodies' velocities.
    void solve(int32_t begin, int32_t end, std::vector<JointConstraint>& constraints, BodyState* states,
               const BodyMotion* motions, const JointStep& step, bool use_bias);

    /// After the step's last pass: moves the bodies of the trees that close loops so that
    /// their rigid rows' position errors close, damped where the rows barely see a
    /// direction; velocities and impulses are left as they are.
    void project(int32_t begin, int32_t end, std::vector<JointConstraint>& constraints, BodyState* states,
                 const BodyMotion* motions, float linear_slop);

    struct Vec3 {
        float x = 0.0f, y = 0.0f, z = 0.0f;
    };
    /// Row major.
    struct Mat33 {
        float m[9] = {};
    };

private:
    // `compliant`: the projection's rows (joint_tree.cpp), else rigid.
    void factor(int32_t tree, const std::vector<JointConstraint>& constraints, const BodyState* states,
                const BodyMotion* motions, bool compliant);
    struct Node {
        int32_t parent;  // node index, or null_index for a tree's root
        int32_t item;    // a body's state, or a joint's constraint
        bool is_joint;
        bool parent_is_b;  // the body of the edge to the parent is the joint's body B
    };
    // Per constraint: [joint, state A or null when A cannot move, the same for B, rows].
    static constexpr int32_t key_width = 4;
    // A joint that closes a loop, with the nodes of its moving bodies (null for one that
    // does not move).
    struct Cut {
        int32_t constraint;
        int32_t node_a;
        int32_t node_b;
    };
    void find_groups(int32_t state_count);
    void forget_trees(std::vector<JointConstraint>& constraints);
    void clear_trees();
    void finish_trees(int32_t responses);
    void add_tree(int32_t root_joint);
    int32_t cut_row_count(const std::vector<JointConstraint>& constraints, int32_t first_cut) const;
    void set_right_side(int32_t tree, const std::vector<JointConstraint>& constraints, const BodyState* states,
                        float bias_rate);
    // Solves the factored tree for the right side in x (indexed from the tree's first node).
    void substitute(int32_t tree, Vec3* x) const;
    // `projecting`: the rows the last velocity solve found dependent stay dropped.
    void solve_cuts(int32_t tree, const std::vector<JointConstraint>& constraints, const BodyState* states,
                    float bias_rate, bool projecting);
    void apply(int32_t tree, std::vector<JointConstraint>& constraints, BodyState* states, const JointStep& step);
    bool projects(int32_t tree, const std::vector<JointConstraint>& constraints, const BodyState* states,
                  float gap_limit) const;
    void move_bodies(int32_t first, int32_t last, BodyState* states, float gap_limit) const;
    // The exact pass's guard, over the body nodes [first, last) of one tree.
    void save_velocities(int32_t first, int32_t last, const BodyState* states);
    bool bodies_within_limits(int32_t first, int32_t last, const BodyState* states, const JointStep& step) const;
    void undo_pass(int32_t first, int32_t last, std::vector<JointConstraint>& constraints, BodyState* states) const;

    // The layout the trees were built for: per constraint its states and exact rows.
    std::vector<int32_t> built_key_;
    std::vector<int32_t> key_scratch_;
    std::vector<Node> nodes_;           // tree by tree, each root first, parents before children
    std::vector<int32_t> tree_starts_;  // per tree its first node; one more at the end
    std::vector<Mat33> inverse_pivots_;  // per node: the inverse of its pivot block
    std::vector<Mat33> gains_;           // per node: inverse pivot x the block to its parent
    std::vector<Vec3> work_;             // per node: right side, then solution
    std::vector<Vec3> saved_;            // per body node: its velocities before the pass
    std::vector<Cut> cuts_;              // tree by tree
    std::vector<int32_t> cut_starts_;    // per tree its first cut; one more at the end
    std::vector<Vec3> cut_impulses_;     // per cut: the pass's impulse on its rows
    std::vector<uint8_t> cut_rows_dropped_;  // per cut, 3 rows: dependent in the last velocity solve
    std::vector<int32_t> response_starts_;  // per tree: its first response in responses_
    std::vector<Vec3> responses_;        // per tree, per cut row: the tree's answer to a unit impulse on it
    // Build scratch: union-find over states with each group's holds (joints to a body
    // that does not move) and loops, each state's exact joints, and the search's marks.
    std::vector<int32_t> set_of_, joint_starts_, joint_list_, queue_;
    std::vector<int32_t> group_holds_, group_loops_, node_of_state_;
    std::vector<uint8_t> group_started_, joint_seen_;
    bool rows_cleared_ = false;  // every constraint's exact_rows is 0 (forget_trees)
};

}  // namespace i2d
