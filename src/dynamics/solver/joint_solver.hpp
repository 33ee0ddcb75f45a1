// SPDX-License-Identifier: MIT
// JointSolver: the step's joints, laid out in the colours' order, and the solver passes
// over ranges of them (prepare, warm start, solve, store).
//
// Design note: like the contact solver, its work comes in ranges that workers share
// (stage_runner.hpp): the joints of one colour share no body the solver moves, so any
// split of a colour's range gives the same bits; the overflow colour's joints are done
// in order on one worker. Each joint is a JointConstraint (joint_constraint.hpp), solved
// by its kind's functions through a switch, except the revolute joints (hinges): they
// are solved from columns (hinge_columns.hpp) by the world's SIMD kernels, W consecutive
// hinges of a colour at a time, one at a time in the overflow colour.
#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

#include "core/pool.hpp"
#include "dynamics/body/body.hpp"
#include "dynamics/solver/body_state.hpp"
#include "dynamics/solver/simd/contact_block.hpp"
#include "dynamics/world/events.hpp"
#include "dynamics/joint/joint.hpp"
#include "dynamics/joint/joint_constraint.hpp"
#include "dynamics/joint/joint_tree.hpp"

namespace i2d {

class JointSolver {
public:
    /// Takes the joints to solve, in solve order (one thread).
    void lay_out(const int32_t* ordered, int32_t count);
    int32_t count() const { return int32_t(constraints_.size()); }
    /// The instruction set's kernels for the hinges (the contacts' path).
    void set_kernels(const ContactKernels& kernels) { kernels_ = &kernels; }

    // Each pass reads the step's JointStep (step_context.hpp).
    /// Anchors, masses, softness and last step's impulses of joints [begin, end).
    void prepare(const JointStep& step, const Pool<Joint>& joints, const Pool<Body>& bodies, int32_t fixed_state,
                 int32_t begin, int32_t end);
    /// `independent`: the range's joints share no body the solver moves (any colour but
    /// the overflow), so that hinges may be solved side by side.
    void warm_start(const JointStep& step, int32_t begin, int32_t end, BodyState* states, bool independent);
    void solve(const JointStep& step, int32_t begin, int32_t end, BodyState* states, bool use_bias, bool independent);

    /// The trees whose rigid rows are solved exactly (joint_tree.hpp): found after
    /// lay_out, before prepare (one thread); one exact pass after each sweep, over ranges
    /// of trees.
    void build_trees(const Pool<Joint>& joints, const Pool<Body>& bodies, int32_t state_count, bool may_hold) {
        trees_.build(constraints_, joints, bodies, state_count, may_hold);
    }
    int32_t tree_count() const { return trees_.tree_count(); }
    int32_t cut_count() const { return trees_.cut_count(); }
    void solve_trees(const JointStep& step, int32_t begin, int32_t end, BodyState* states, const BodyMotion* motions,
                     bool use_bias) {
        trees_.solve(begin, end, constraints_, states, motions, step, use_bias);
    }
    /// After the last pass: the loops' position errors closed (JointTrees::project).
    void project_trees(int32_t begin, int32_t end, BodyState* states, const BodyMotion* motions, float linear_slop) {
        trees_.project(begin, end, constraints_, states, motions, linear_slop);
    }
    /// Impulses back to the joints, and their reactions over the last substep; notes
    /// whether any passed its threshold.
    void store(const JointStep& step, Pool<Joint>& joints, const BodyState* states, int32_t begin, int32_t end);
    /// Joints whose reaction passed a threshold, in solve order (one thread); nothing to
    /// read unless store noted one.
    void report_breaking(const Pool<Joint>& joints, const IdEncoder& ids, std::vector<JointEvent>& out) const;

private:
    void prepare_one(const JointStep& step, JointConstraint& c, const Joint& joint, const Pool<Body>& bodies,
                     int32_t fixed_state) const;
    void load_hinge(const JointStep& step, int32_t k, const JointConstraint& c);
    /// The run of hinges [begin, end): whole chunks of the kernels' width, the rest
    /// one at a time.
    void run_hinges(HingeKernel ContactKernels::*kernel, int32_t begin, int32_t end, BodyState* states,
                    const HingePass& pass, bool independent) const;
    /// Where the run of hinges from `begin` ends, at most at `end`.
    int32_t hinge_run_end(int32_t begin, int32_t end) const;
    static HingePass hinge_pass(const JointStep& step, bool use_bias);
    void take_hinge_impulses(int32_t k, JointConstraint& c) const;

    std::vector<JointConstraint> constraints_;
    // Per constraint: whether the hinge kernels solve it this step (set by prepare), and the
    // columns (HingeColumns) that hold what its kernels read, column by column.
    std::vector<uint8_t> lane_hinge_;
    std::vector<int32_t> hinge_states_;
    std::vector<float> hinge_values_;
    HingeColumns hinges_{};
    const ContactKernels* kernels_ = &scalar_contact_kernels();
    JointTrees trees_;
    // Set by any worker's store range, read after the stage's barrier.
    std::atomic<bool> breaking_seen_{false};
};

}  // namespace i2d
