// SPDX-License-Identifier: MIT
// The solver's colour stages: each colour's joints and contacts prepared, warm started,
// solved, relaxed, bounced and stored, over any split of the colour's items.
#include <algorithm>

#include "dynamics/contact/contact_set.hpp"
#include "dynamics/solver/solver.hpp"

namespace i2d {

// The colours [arg.run, arg.group_end), each whole and in order, as their own stages would.
template <auto F, bool with_joints>
void Solver::run_group(const StepContext& step, Solver& self, const ColorPass& arg, int32_t, int32_t, int32_t worker) {
    for (int32_t run = arg.run; run < arg.group_end; ++run) {
        const int32_t items = self.run_items(run, with_joints);
        if (items > 0) {
            F(step, self, ColorPass{run, arg.pass, run + 1}, 0, items, worker);
        }
    }
}

// The stages' group instantiations, which solver.cpp plans.
template void Solver::run_group<&Solver::prepare_and_warm_start, true>(const StepContext&, Solver&, const ColorPass&,
                                                                         int32_t, int32_t, int32_t);
template void Solver::run_group<&Solver::warm_start, true>(const StepContext&, Solver&, const ColorPass&, int32_t,
                                                             int32_t, int32_t);
template void Solver::run_group<&Solver::solve, true>(const StepContext&, Solver&, const ColorPass&, int32_t, int32_t,
                                                        int32_t);
template void Solver::run_group<&Solver::relax_and_store, true>(const StepContext&, Solver&, const ColorPass&, int32_t,
                                                                  int32_t, int32_t);
template void Solver::run_group<&Solver::restitution, false>(const StepContext&, Solver&, const ColorPass&, int32_t,
                                                               int32_t, int32_t);
template void Solver::run_group<&Solver::store_color, true>(const StepContext&, Solver&, const ColorPass&, int32_t,
                                                              int32_t, int32_t);

// Items [begin, end) of a colour run: its joints first, then its contact items. Where a
// piece's joints begin or end inside the colour's joints, the edge moves down to a whole
// number of SIMD blocks of hinges from the colour's first joint, which every piece rounds
// alike, so the pieces still cover each joint once. A colour of joints and contacts is
// split evenly by items, and each piece used to end in a few hinges solved one lane at a
// time: with 2 workers, 2 % of rain's step. The joints of a colour are independent of
// one another, so which piece solves one, and in which lanes, moves no bit.
Solver::RunSplit Solver::split_run(int32_t run, int32_t begin, int32_t end) const {
    const ColorRun& r = plan_.color_runs[std::size_t(run)];
    const int32_t joints = r.joint_count;
    const int32_t width = contact_solver_.kernels().width;
    const auto joint_edge = [joints, width](int32_t item) { return item >= joints ? joints : item / width * width; };
    return {r.joint_begin + joint_edge(begin), r.joint_begin + joint_edge(end), std::max(begin, joints) - joints,
            std::max(end, joints) - joints};
}

// What one pass over the contacts reads: the substep's rates and the softness of its
// push-out (solve passes) or none (relax passes).
SolvePass Solver::solve_pass(const StepContext& step, int32_t pass) {
    const Softness& soft = step.contact_softness;
    const Softness& fixed = step.fixed_contact_softness;
    const float inv_h = step.inv_substep;
    return SolvePass{inv_h,
                     step.settings.contact_push_max_speed,
                     float(pass / 2 + 1) * step.substep,
                     pass % 2 == 0,
                     friction_anchor_share * inv_h,
                     {soft.bias_rate, soft.mass_scale, soft.impulse_scale},
                     {fixed.bias_rate, fixed.mass_scale, fixed.impulse_scale}};
}

// A colour's joints prepared and its contacts packed, and at the end of the step their
// impulses stored, in the colour's own stages, split as its solve stages are: the worker
// that solves a constraint in every pass is the one that wrote its data, so the data
// stays in that core's cache. Packed in one stage split evenly, each worker's contacts
// were another worker's in every colour: with 2 workers, large_pyramid steps in 0.89 of
// the time that took and many_pyramids in 0.87 (paired runs).
void Solver::prepare_color(const StepContext& step, int32_t run, int32_t begin, int32_t end) {
    const RunSplit split = split_run(run, begin, end);
    joint_solver_.prepare(step.joint_step, links_.joints, links_.bodies, body_pass_.fixed_state(), split.joint_begin,
                          split.joint_end);
    if (split.contact_begin < split.contact_end) {
        const int32_t contact_run = plan_.color_runs[std::size_t(run)].contact_run;
        contact_solver_.pack(contact_layout(), contact_run, split.contact_begin, split.contact_end);
    }
}

void Solver::prepare_and_warm_start(const StepContext& step, Solver& self, const ColorPass& arg, int32_t begin,
                                    int32_t end, int32_t worker) {
    self.prepare_color(step, arg.run, begin, end);
    warm_start(step, self, arg, begin, end, worker);
}

void Solver::warm_start(const StepContext& step, Solver& self, const ColorPass& arg, int32_t begin, int32_t end,
                        int32_t) {
    const RunSplit split = self.split_run(arg.run, begin, end);
    const ColorRun& r = self.plan_.color_runs[std::size_t(arg.run)];
    BodyState* states = self.body_pass_.states();
    self.joint_solver_.warm_start(step.joint_step, split.joint_begin, split.joint_end, states, !r.sequential);
    if (split.contact_begin < split.contact_end) {
        self.contact_solver_.warm_start(r.contact_run, split.contact_begin, split.contact_end, states);
    }
}

void Solver::solve(const StepContext& step, Solver& self, const ColorPass& arg, int32_t begin, int32_t end, int32_t) {
    const SolvePass pass = solve_pass(step, arg.pass);
    const RunSplit split = self.split_run(arg.run, begin, end);
    const ColorRun& r = self.plan_.color_runs[std::size_t(arg.run)];
    BodyState* states = self.body_pass_.states();
    self.joint_solver_.solve(step.joint_step, split.joint_begin, split.joint_end, states, pass.use_bias,
                             !r.sequential);
    if (split.contact_begin < split.contact_end) {
        self.contact_solver_.solve(r.contact_run, split.contact_begin, split.contact_end, states, pass);
    }
}

// The last relax, then the contacts' impulses back (joints wait for their trees' pass).
void Solver::relax_and_store(const StepContext& step, Solver& self, const ColorPass& arg, int32_t begin, int32_t end,
                             int32_t worker) {
    solve(step, self, arg, begin, end, worker);
    self.store_contacts(step, arg.run, self.split_run(arg.run, begin, end));
}

void Solver::store_color(const StepContext& step, Solver& self, const ColorPass& arg, int32_t begin, int32_t end,
                         int32_t) {
    const RunSplit split = self.split_run(arg.run, begin, end);
    self.joint_solver_.store(step.joint_step, self.links_.joints, self.body_pass_.states(), split.joint_begin,
                             split.joint_end);
    self.store_contacts(step, arg.run, split);
}

void Solver::store_contacts(const StepContext& step, int32_t run, const RunSplit& split) {
    if (split.contact_begin < split.contact_end) {
        const int32_t contact_run = plan_.color_runs[std::size_t(run)].contact_run;
        contact_solver_.store(links_.contacts.pool(), body_pass_.states(), step.settings.contact_slop, contact_run,
                              split.contact_begin, split.contact_end);
    }
}

void Solver::store_joints(const StepContext& step, Solver& self, const NoStageArg&, int32_t begin, int32_t end,
                          int32_t) {
    self.joint_solver_.store(step.joint_step, self.links_.joints, self.body_pass_.states(), begin, end);
}

void Solver::solve_joint_trees(const StepContext& step, Solver& self, const ColorPass& arg, int32_t begin, int32_t end,
                               int32_t) {
    const bool use_bias = arg.pass % 2 == 0;
    self.joint_solver_.solve_trees(step.joint_step, begin, end, self.body_pass_.states(), self.body_pass_.motions(),
                                   use_bias);
}

void Solver::project_joint_trees(const StepContext& step, Solver& self, const NoStageArg&, int32_t begin, int32_t end,
                                 int32_t) {
    self.joint_solver_.project_trees(begin, end, self.body_pass_.states(), self.body_pass_.motions(),
                                     step.tolerances.linear_slop);
}

void Solver::check_bounce(const StepContext& step, Solver& self, const NoStageArg&, int32_t, int32_t, int32_t) {
    self.plan_.bounce = self.contact_solver_.any_bounce(step.settings.restitution_threshold);
}

// Only when something bounces (the stages run if plan_.bounce), and then over every
// contact that pushed, a few times.
void Solver::restitution(const StepContext& step, Solver& self, const ColorPass& arg, int32_t begin, int32_t end,
                         int32_t) {
    const int32_t contact_run = self.plan_.color_runs[std::size_t(arg.run)].contact_run;
    self.contact_solver_.apply_restitution(contact_run, begin, end, self.body_pass_.states(),
                                           step.settings.restitution_threshold);
}

}  // namespace i2d
