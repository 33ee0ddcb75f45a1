// SPDX-License-Identifier: MIT
// The soft step: gather, colour, substep, write back.
#include "dynamics/solver/solver.hpp"

#include <algorithm>
#include <cmath>

#include "core/assert.hpp"
#include "core/prefetch.hpp"
#include "dynamics/constants.hpp"
#include "dynamics/contact/contact_set.hpp"
#include "dynamics/island/island.hpp"
#include "dynamics/body/shape_bounds.hpp"
#include "dynamics/solver/softness.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

// The float update overflowed or broke the speed limit: redo it in double, where no
// finite float input can overflow, then scale down to the limit. Rare, so off the fast path.
Vec2 limited_velocity(const BodyMotion& m, Vec2 v, Vec2 gravity, float h, float max_speed) {
    double ax = 0.0, ay = 0.0, damping_factor = 1.0;
    if (m.is_dynamic) {
        ax = double(h) * (double(m.gravity_scale) * gravity.x + double(m.inv_mass) * m.force.x);
        ay = double(h) * (double(m.gravity_scale) * gravity.y + double(m.inv_mass) * m.force.y);
        damping_factor = 1.0 / (1.0 + double(h) * m.linear_damping);
    }
    const double vx = (v.x + ax) * damping_factor;
    const double vy = (v.y + ay) * damping_factor;
    const double speed = std::sqrt(vx * vx + vy * vy);
    const double scale = speed > max_speed ? max_speed / speed : 1.0;
    return {float(vx * scale), float(vy * scale)};
}

// Gravity and force over mass of a body the solver moves; zero for fixed ones. Only the
// restitution estimate reads it, which squares it times a gap: each component is held
// to `limit` (what takes a body from rest to the speed cap within the step; more would
// not move it further), so that the estimate stays finite whatever the force.
Vec2 free_acceleration(const Body& b, Vec2 gravity, float limit) {
    if (b.type != BodyType::dynamic || b.inv_mass == 0.0f) {
        return {};
    }
    const Vec2 a = b.gravity_scale * gravity + b.inv_mass * b.force;
    if (!is_finite(a)) {
        return {};
    }
    return {max_of(-limit, min_of(a.x, limit)), max_of(-limit, min_of(a.y, limit))};
}

// Whether the body's fastest point went far relative to its thinnest shape: then it may
// have passed through something thin, and the continuous stage sweeps it.
bool is_fast(const Body& b, const BodyState& s, float time_step) {
    if (b.type != BodyType::dynamic) {
        return false;
    }
    const float travel = length(s.delta_position) + time_step * std::fabs(s.angular_velocity) * b.max_extent;
    return travel > continuous_safety_factor * b.min_extent;
}

}  // namespace

void Solver::step(float time_step, int32_t substep_count) {
    const int32_t awake = int32_t(links_.islands.awake_bodies().size());
    time_step_ = time_step;
    substep_ = time_step / float(substep_count);
    if (awake == 0) {
        // Nothing moves, so no contact or joint is solved (each needs an awake body): an
        // empty or sleeping world's step skips the layouts and stages, half its cost.
        fast_bodies_.clear();
        non_finite_bodies_.clear();
        return;
    }
    states_.resize(std::size_t(awake) + 1);
    motions_.resize(std::size_t(awake) + 1);
    states_[std::size_t(awake)] = BodyState{};
    motions_[std::size_t(awake)] = BodyMotion{};
    final_flags_.resize(std::size_t(awake));
    rest_islands_.resize(std::size_t(awake));
    rest_times_.resize(std::size_t(awake));
    event_slots_.resize(std::size_t(awake));
    parallel_ = links_.tasks.worker_count() > 1 && awake >= parallel_min_bodies;
    if (color_constraints()) {
        contact_solver_.lay_out(contact_layout());
    }
    joint_solver_.lay_out(ordered_joints_.data(), int32_t(ordered_joints_.size()));
    if (joints_regathered_) {
        // What the trees depend on (the joints, their settings, their bodies' types, masses
        // and places) moves the joint set's or the islands' version.
        joint_solver_.build_trees(links_.joints, links_.bodies, awake);
    }
    lay_out_color_runs();
    split_runs_by_region();
    move_starts_.resize(std::size_t(regions_.count()) + 1);
    if (links_.settings.enable_sleep) {
        links_.islands.begin_rest_times();
    }
    build_stages(substep_count);
    point_stages_at_shares();
    runner_.run(links_.tasks, stages_, parallel_);
    const std::vector<StageRunner::WorkerTime>& times = runner_.worker_times();
    if (!times.empty()) {
        // How fast each worker ran its blocks, for the next cut of the regions.
        balance_.note_run(times.data(), int32_t(times.size()));
    }
    joint_solver_.report_breaking(links_.joints, links_.events.ids, links_.events.current.joint_events);
    finish_bodies();
}

ContactLayout Solver::contact_layout() const {
    ContactLayout layout{links_.contacts.pool(), ordered_contacts_.data(), color_starts_.data(),
                         ConstraintColors::count, motions_.data(),          int32_t(states_.size()) - 1,
                         any_elastic_contact_};
    if (!color_parts_.empty()) {
        layout.color_parts = color_parts_.data();
        layout.part_stride = links_.tasks.worker_count() + 1;
    }
    return layout;
}

void Solver::add_stage(Stage::Fn fn, int32_t item_count, int32_t min_items_per_block, int32_t arg0, int32_t arg1) {
    Stage stage = make_stage(fn, this, item_count, links_.tasks.worker_count(), parallel_, min_items_per_block);
    stage.arg0 = arg0;
    stage.arg1 = arg1;
    stages_.push_back(stage);
    stage_shares_.push_back(no_share);
}

// A stage over the awake bodies, split where the regions are.
void Solver::add_body_stage(Stage::Fn fn) {
    add_stage(fn, int32_t(states_.size()) - 1, bodies_per_work_block);
    stage_shares_.back() = bodies_share;
}

// One stage per colour, in solve order, over its joints and then its contacts; the
// overflow colour whole, on one worker. Restitution passes leave the joints out. Small
// colours next to each other (the overflow counts as one) share one stage that solves them
// in order on one worker: a scene's last colours often hold a few constraints each, and
// a stage apiece cost a wait between workers (hundreds of nanoseconds) for tens of
// nanoseconds of work.
template <Stage::Fn fn, bool with_joints>
void Solver::add_color_stages(int32_t pass, const bool* run_if) {
    const int32_t runs = int32_t(color_runs_.size());
    for (int32_t run = 0; run < runs;) {
        int32_t group_end = run;
        int32_t group_stages = 0;
        while (group_end < runs && run_is_small(group_end, with_joints)) {
            group_stages += run_items(group_end, with_joints) > 0 ? 1 : 0;
            ++group_end;
        }
        if (group_stages >= 2) {
            add_stage(&Solver::run_group<fn, with_joints>, 1, 1, run, pass);
            stages_.back().arg2 = group_end;
            stages_.back().run_if = run_if;
            run = group_end;
            continue;
        }
        const ColorRun& r = color_runs_[std::size_t(run)];
        const int32_t items = run_items(run, with_joints);
        if (items > 0) {
            const int32_t min_items = r.sequential ? items : min_items_of(run);
            add_stage(fn, items, min_items, run, pass);
            stages_.back().run_if = run_if;
            stage_shares_.back() = run;
        }
        ++run;
    }
}

// The colours [stage.arg0, stage.arg2), each whole and in order, as their own stages would.
template <Stage::Fn fn, bool with_joints>
void Solver::run_group(void* solver, const Stage& stage, int32_t, int32_t, int32_t worker) {
    Solver& self = *static_cast<Solver*>(solver);
    Stage one = stage;
    for (int32_t run = stage.arg0; run < stage.arg2; ++run) {
        const int32_t items = self.run_items(run, with_joints);
        if (items > 0) {
            one.arg0 = run;
            one.item_count = items;
            fn(solver, one, 0, items, worker);
        }
    }
}

int32_t Solver::run_items(int32_t run, bool with_joints) const {
    const ColorRun& r = color_runs_[std::size_t(run)];
    return (with_joints ? r.joint_count : 0) + r.contact_items;
}

// At most small_color_blocks work blocks of joints and as many of contacts: too little to
// share out between workers.
bool Solver::run_is_small(int32_t run, bool with_joints) const {
    const ColorRun& r = color_runs_[std::size_t(run)];
    const int32_t joints = with_joints ? r.joint_count : 0;
    return r.sequential || (joints <= small_color_blocks * joints_per_work_block &&
                            r.contact_items <= small_color_blocks * min_contact_items());
}

// Items per work block at least: SIMD blocks of contacts where the colour has contacts.
int32_t Solver::min_items_of(int32_t run) const {
    return color_runs_[std::size_t(run)].contact_items > 0 ? min_contact_items() : joints_per_work_block;
}

// SIMD blocks of contacts per work block.
int32_t Solver::min_contact_items() const {
    const int32_t width = contact_solver_.kernels().width;
    return (contacts_per_work_block + width - 1) / width;
}

Solver::RunSplit Solver::split_run(int32_t run, int32_t begin, int32_t end) const {
    const ColorRun& r = color_runs_[std::size_t(run)];
    const int32_t joints = r.joint_count;
    return {r.joint_begin + std::min(begin, joints), r.joint_begin + std::min(end, joints),
            std::max(begin, joints) - joints, std::max(end, joints) - joints};
}

// The colours that have joints or contacts, in solve order: the contact solver's runs
// are its colours that have contacts, in the same order, its overflow run last.
void Solver::lay_out_color_runs() {
    color_runs_.clear();
    int32_t contact_run = 0;
    for (int32_t color = 0; color < ConstraintColors::count; ++color) {
        const int32_t joints = joint_color_starts_[std::size_t(color) + 1] - joint_color_starts_[std::size_t(color)];
        const int32_t contacts = color_starts_[std::size_t(color) + 1] - color_starts_[std::size_t(color)];
        if (joints == 0 && contacts == 0) {
            continue;
        }
        ColorRun r;
        r.joint_begin = joint_color_starts_[std::size_t(color)];
        r.joint_count = joints;
        r.color = color;
        r.sequential = color == ConstraintColors::overflow;
        if (contacts > 0) {
            r.contact_run = contact_run++;
            r.contact_items = contact_solver_.run_items(r.contact_run);
        }
        color_runs_.push_back(r);
    }
}

// Box2D v3's stage loop: per substep integrate velocities, warm start, solve with
// push-out, integrate positions, relax. Then one more relax at the end: the velocities a
// step ends with are the ones the next step starts from (and the ones sleep tests). One
// sweep per substep leaves a tall stack's last velocities unconverged, and the residue
// kept a 100-row pyramid vibrating and wandering at centimetres per second; the second
// sweep lets it rest. Then restitution, impulses back to the contacts, final poses.
//
// Stages that touch the same items one after the other share a stage where nothing in
// between needs them: each stage boundary is a wait between workers, and each stage
// reads its items again. Gathering a body integrates its first substep's velocity; a
// colour's constraints are warm started as they are prepared; and when no contact is
// elastic (the restitution pass cannot run) a colour's contacts are stored as its last
// relax leaves them. The arithmetic and its order per body are unchanged: the same bits.
void Solver::build_stages(int32_t substep_count) {
    const WorldDef& s = links_.settings;
    const float h = substep_, inv_h = float(substep_count) / time_step_;
    // Stiffness is capped at a quarter of the substep rate, beyond which the implicit
    // spring stops being accurate; contacts with a fixed body get twice the frequency.
    const float hertz = min_of(s.contact_hertz, 0.25f / h);
    const Softness soft = make_softness(hertz, s.contact_damping_ratio, h);
    const Softness fixed_soft = make_softness(2.0f * hertz, s.contact_damping_ratio, h);
    passes_.resize(std::size_t(2 * substep_count));
    for (int32_t i = 0; i < substep_count; ++i) {
        for (int32_t relax = 0; relax < 2; ++relax) {
            passes_[std::size_t(2 * i + relax)] = SolvePass{inv_h,
                                                            s.contact_push_max_speed,
                                                            float(i + 1) * h,
                                                            relax == 0,
                                                            friction_anchor_share * inv_h,
                                                            {soft.bias_rate, soft.mass_scale, soft.impulse_scale},
                                                            {fixed_soft.bias_rate, fixed_soft.mass_scale,
                                                             fixed_soft.impulse_scale}};
        }
    }
    const float joint_hertz = min_of(s.joint_hertz, 0.25f / h);
    joint_solver_.set_step(JointStep(h, inv_h, make_softness(joint_hertz, s.joint_damping_ratio, h),
                                     s.maximum_linear_speed, max_rotation_per_substep / h));
    if (!stages_changed(substep_count)) {
        return;  // a steady scene: the same stages over the same counts as last step
    }
    const int32_t trees = joint_solver_.tree_count();
    const int32_t last_pass = 2 * substep_count - 1;
    stages_.clear();
    stage_shares_.clear();
    add_body_stage(&Solver::gather_bodies);
    for (int32_t i = 0; i < substep_count; ++i) {
        if (i == 0) {
            add_color_stages<&Solver::prepare_and_warm_start, true>(0);
        } else {
            add_body_stage(&Solver::integrate_velocities);
            add_color_stages<&Solver::warm_start, true>(0);
        }
        add_color_stages<&Solver::solve, true>(2 * i);
        add_stage(&Solver::solve_joint_trees, trees, joint_trees_per_work_block, 0, 2 * i);
        add_body_stage(&Solver::integrate_positions);
        add_color_stages<&Solver::solve, true>(2 * i + 1);
        add_stage(&Solver::solve_joint_trees, trees, joint_trees_per_work_block, 0, 2 * i + 1);
    }
    if (any_elastic_contact_) {
        add_color_stages<&Solver::solve, true>(last_pass);
    } else {
        add_color_stages<&Solver::relax_and_store, true>(last_pass);
    }
    add_stage(&Solver::solve_joint_trees, trees, joint_trees_per_work_block, 0, last_pass);
    if (any_elastic_contact_) {
        add_stage(&Solver::check_bounce, 1, 1);
        constexpr int32_t restitution_iterations = 4;
        for (int32_t iteration = 0; iteration < restitution_iterations; ++iteration) {
            add_color_stages<&Solver::restitution, false>(0, &bounce_);
        }
        add_color_stages<&Solver::store_color, true>(0);
    } else {
        add_stage(&Solver::store_joints, joint_solver_.count(), joints_per_work_block);
    }
    add_body_stage(&Solver::finalize_bodies);
    add_stage(&Solver::count_move_events, regions_.count(), 1);
    add_stage(&Solver::place_move_events, 1, 1);
    add_body_stage(&Solver::write_move_events);
}

// The stage list depends only on these counts; a small world's step would otherwise
// spend a tenth of its time building the same list again.
bool Solver::stages_changed(int32_t substep_count) {
    stage_key_scratch_.clear();
    stage_key_scratch_.push_back(substep_count);
    stage_key_scratch_.push_back(parallel_ ? links_.tasks.worker_count() : 1);
    stage_key_scratch_.push_back(int32_t(states_.size()));
    stage_key_scratch_.push_back(contact_solver_.block_count());
    stage_key_scratch_.push_back(contact_solver_.overflow_count());
    stage_key_scratch_.push_back(joint_solver_.count());
    stage_key_scratch_.push_back(joint_solver_.tree_count());
    stage_key_scratch_.push_back(any_elastic_contact_ ? 1 : 0);
    for (const ColorRun& r : color_runs_) {
        stage_key_scratch_.push_back(r.joint_count);
        stage_key_scratch_.push_back(r.contact_items);
    }
    if (stage_key_scratch_ == stage_key_) {
        return false;
    }
    stage_key_.swap(stage_key_scratch_);
    return true;
}

// One state per awake body in awake order (the shared fixed state is set already), its
// velocity integrated for the first substep.
void Solver::gather_bodies(void* solver, const Stage&, int32_t begin, int32_t end, int32_t) {
    Solver& self = *static_cast<Solver*>(solver);
    const std::vector<int32_t>& awake = self.links_.islands.awake_bodies();
    const Vec2 gravity = self.links_.settings.gravity;
    const float acceleration_limit = self.links_.settings.maximum_linear_speed / self.time_step_;
    const IntegrationTerms terms = self.integration_terms();
    for (int32_t k = begin; k < end; ++k) {
        const Body& b = self.links_.bodies[awake[std::size_t(k)]];
        const bool dynamic = b.type == BodyType::dynamic;
        self.states_[std::size_t(k)] = BodyState{b.linear_velocity, b.angular_velocity, dynamic ? 1.0f : 0.0f, Vec2{}, Rot{}};
        BodyMotion& m = self.motions_[std::size_t(k)];
        m.force = b.force;
        m.torque = b.torque;
        m.inv_mass = b.inv_mass;
        m.inv_inertia = b.inv_inertia;
        m.gravity_scale = b.gravity_scale;
        m.linear_damping = b.linear_damping;
        m.linear_damping_factor = 1.0f / (1.0f + self.substep_ * b.linear_damping);
        m.angular_damping_factor = 1.0f / (1.0f + self.substep_ * b.angular_damping);
        m.free_acceleration = free_acceleration(b, gravity, acceleration_limit);
        m.start_linear_velocity = b.linear_velocity;
        m.start_angular_velocity = b.angular_velocity;
        m.is_dynamic = dynamic;
        self.integrate_velocity(k, terms);
    }
}

void Solver::solve_joint_trees(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t) {
    Solver& self = *static_cast<Solver*>(solver);
    const SolvePass& pass = self.passes_[std::size_t(stage.arg1)];
    self.joint_solver_.solve_trees(begin, end, self.states_.data(), self.motions_.data(), pass.use_bias);
}

// A colour's joints prepared and its contacts packed, and at the end of the step their
// impulses stored, in the colour's own stages, split as its solve stages are: the worker
// that solves a constraint in every pass is the one that wrote its data, so the data
// stays in that core's cache. Packed in one stage split evenly, each worker's contacts
// were another worker's in every colour: with 2 workers, large_pyramid steps in 0.89 of
// the time that took and many_pyramids in 0.87 (paired runs).
void Solver::prepare_color(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t) {
    Solver& self = *static_cast<Solver*>(solver);
    const RunSplit split = self.split_run(stage.arg0, begin, end);
    self.joint_solver_.prepare(self.links_.joints, self.links_.bodies, int32_t(self.states_.size()) - 1,
                               split.joint_begin, split.joint_end);
    if (split.contact_begin < split.contact_end) {
        const int32_t run = self.color_runs_[std::size_t(stage.arg0)].contact_run;
        self.contact_solver_.pack(self.contact_layout(), run, split.contact_begin, split.contact_end);
    }
}

void Solver::prepare_and_warm_start(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t worker) {
    prepare_color(solver, stage, begin, end, worker);
    warm_start(solver, stage, begin, end, worker);
}

// The last relax, then the contacts' impulses back (joints wait for their trees' pass).
void Solver::relax_and_store(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t worker) {
    solve(solver, stage, begin, end, worker);
    Solver& self = *static_cast<Solver*>(solver);
    self.store_contacts(stage.arg0, self.split_run(stage.arg0, begin, end));
}

void Solver::store_joints(void* solver, const Stage&, int32_t begin, int32_t end, int32_t) {
    Solver& self = *static_cast<Solver*>(solver);
    self.joint_solver_.store(self.links_.joints, self.states_.data(), begin, end);
}

void Solver::store_color(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t) {
    Solver& self = *static_cast<Solver*>(solver);
    const RunSplit split = self.split_run(stage.arg0, begin, end);
    self.joint_solver_.store(self.links_.joints, self.states_.data(), split.joint_begin, split.joint_end);
    self.store_contacts(stage.arg0, split);
}

void Solver::store_contacts(int32_t color_run, const RunSplit& split) {
    if (split.contact_begin < split.contact_end) {
        const int32_t run = color_runs_[std::size_t(color_run)].contact_run;
        contact_solver_.store(links_.contacts.pool(), states_.data(), links_.settings.contact_slop, run,
                              split.contact_begin, split.contact_end);
    }
}

void Solver::warm_start(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t) {
    Solver& self = *static_cast<Solver*>(solver);
    const RunSplit split = self.split_run(stage.arg0, begin, end);
    const bool independent = !self.color_runs_[std::size_t(stage.arg0)].sequential;
    self.joint_solver_.warm_start(split.joint_begin, split.joint_end, self.states_.data(), independent);
    if (split.contact_begin < split.contact_end) {
        const int32_t run = self.color_runs_[std::size_t(stage.arg0)].contact_run;
        self.contact_solver_.warm_start(run, split.contact_begin, split.contact_end, self.states_.data());
    }
}

void Solver::solve(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t) {
    Solver& self = *static_cast<Solver*>(solver);
    const SolvePass& pass = self.passes_[std::size_t(stage.arg1)];
    const RunSplit split = self.split_run(stage.arg0, begin, end);
    const bool independent = !self.color_runs_[std::size_t(stage.arg0)].sequential;
    self.joint_solver_.solve(split.joint_begin, split.joint_end, self.states_.data(), pass.use_bias, independent);
    if (split.contact_begin < split.contact_end) {
        const int32_t run = self.color_runs_[std::size_t(stage.arg0)].contact_run;
        self.contact_solver_.solve(run, split.contact_begin, split.contact_end, self.states_.data(), pass);
    }
}

void Solver::check_bounce(void* solver, const Stage&, int32_t, int32_t, int32_t) {
    Solver& self = *static_cast<Solver*>(solver);
    self.bounce_ = self.contact_solver_.any_bounce(self.links_.settings.restitution_threshold);
}

// Only when something bounces (the stages run if bounce_), and then over every contact
// that pushed, a few times.
void Solver::restitution(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t) {
    Solver& self = *static_cast<Solver*>(solver);
    const int32_t run = self.color_runs_[std::size_t(stage.arg0)].contact_run;
    self.contact_solver_.apply_restitution(run, begin, end, self.states_.data(),
                                           self.links_.settings.restitution_threshold);
}

// Joints and contacts share one colouring, so that a colour's joints and contacts are
// independent of one another too; kept while nothing it depends on changed, and then so
// is the contact solver's layout, which the workers read (rewritten, it would leave their
// cores for the calling thread's). Returns whether the contacts were coloured anew.
bool Solver::color_constraints() {
    // The joints to solve change only with the joints or the awake list.
    const uint64_t joint_version = links_.joint_set.version(), awake_version = links_.islands.awake_version();
    bool joints_differ = false;
    joints_regathered_ = false;
    if (!gathered_ || joint_version != gathered_joint_version_ || awake_version != gathered_awake_version_) {
        gathered_ = true;
        joints_regathered_ = true;
        gathered_joint_version_ = joint_version;
        gathered_awake_version_ = awake_version;
        links_.joint_set.gather_awake(links_.islands.awake_bodies(), awake_joints_);
        joints_differ = joints_changed();
        if (joints_differ) {
            colored_joint_key_.swap(joint_key_);  // what color_joints colours
        }
    }
    const uint64_t version = links_.contacts.layout_version();
    const int32_t awake_bodies = int32_t(links_.islands.awake_bodies().size());
    const int32_t regions = parallel_ ? links_.tasks.worker_count() : 1;
    if (colored_ && version == colored_version_ && awake_bodies == colored_body_count_ && !joints_differ &&
        regions == regions_.count() && (regions == 1 || !balance_.wants_cut())) {
        return false;  // nothing the colours depend on changed: a resting pile keeps them
    }
    colored_ = true;
    colored_version_ = version;
    colored_body_count_ = awake_bodies;
    colors_.reset(awake_bodies);
    color_joints();
    color_contacts(regions);
    split_colors_by_region();
    return true;
}

// What a joint's colour depends on: which joint, and the states it moves (-1: none).
bool Solver::joints_changed() {
    joint_key_.clear();
    for (const int32_t joint : awake_joints_) {
        const JointDef& d = links_.joints[joint].def;
        const Body& a = links_.bodies[d.body_a];
        const Body& b = links_.bodies[d.body_b];
        const bool a_moves = d.type != JointType::mouse && a.type == BodyType::dynamic;
        const bool b_moves = b.type == BodyType::dynamic;
        joint_key_.push_back(joint);
        joint_key_.push_back(a_moves ? a.awake_index : null_index);
        joint_key_.push_back(b_moves ? b.awake_index : null_index);
    }
    return joint_key_ != colored_joint_key_;
}

// The joints' colours, before the contacts take theirs, laid out colour by colour in
// gathering order. A joint that moves no body (both sides fixed) is not solved.
void Solver::color_joints() {
    const std::vector<int32_t>& key = colored_joint_key_;
    const std::size_t count = key.size() / 3;
    joint_colors_.resize(count);
    joint_color_starts_.assign(ConstraintColors::count + 1, 0);
    for (std::size_t k = 0; k < count; ++k) {
        const int32_t a = key[3 * k + 1], b = key[3 * k + 2];
        int32_t color = -1;
        if (a != null_index || b != null_index) {
            color = colors_.assign(a != null_index ? a : ConstraintColors::null_state,
                                   b != null_index ? b : ConstraintColors::null_state);
            ++joint_color_starts_[std::size_t(color) + 1];
        }
        joint_colors_[k] = int8_t(color);
    }
    for (int32_t color = 0; color < ConstraintColors::count; ++color) {
        joint_color_starts_[std::size_t(color) + 1] += joint_color_starts_[std::size_t(color)];
    }
    ordered_joints_.resize(std::size_t(joint_color_starts_[ConstraintColors::count]));
    scratch_starts_.assign(joint_color_starts_.begin(), joint_color_starts_.end() - 1);
    for (std::size_t k = 0; k < count; ++k) {
        const int32_t color = joint_colors_[k];
        if (color >= 0) {
            ordered_joints_[std::size_t(scratch_starts_[std::size_t(color)]++)] = key[3 * k];
        }
    }
}

// A colour for every awake contact the solver will see, then the contacts laid out
// colour by colour, the order they are solved in. Within a colour, whose contacts are
// independent, the contacts of each worker's region (that of the lowest body a contact
// moves) come in the order of the regions, so that each worker's share of every colour
// moves its own bodies. Within a region, two-point contacts come first, so that SIMD
// blocks hold one kind and blocks of single points skip the second, and each kind is in
// the order of the lowest body it moves (order_by_body). The order within a colour changes
// no bit of the result. The overflow colour is solved in sequence and keeps awake order. A
// body the contact cannot move (static, kinematic, asleep) takes no colour slot. Only
// contacts with points are read (ContactSet::solvable): most of a tumbling heap's have none.
void Solver::color_contacts(int32_t regions) {
    const std::vector<int32_t>& solvable = links_.contacts.solvable();
    const Pool<Contact>& contacts = links_.contacts.pool();
    colored_contacts_.clear();
    body_starts_.assign(std::size_t(colored_body_count_) + 2, 0);
    any_elastic_contact_ = false;
    // The list jumps through the contact pool: ask for contacts ahead.
    constexpr std::size_t contacts_ahead = 32;
    for (std::size_t k = 0; k < solvable.size(); ++k) {
        if (k + contacts_ahead < solvable.size()) {
            prefetch_line(&contacts[solvable[k + contacts_ahead]]);
        }
        const Contact& contact = contacts[solvable[k]];
        I2D_ASSERT(is_solvable(contact));
        const int32_t color =
            colors_.assign((contact.flags & contact_moves_a) ? contact.state_a : ConstraintColors::null_state,
                           (contact.flags & contact_moves_b) ? contact.state_b : ConstraintColors::null_state);
        any_elastic_contact_ = any_elastic_contact_ || contact.restitution != 0.0f;
        const bool single_after_pairs = color != ConstraintColors::overflow && contact.point_count == 1;
        const int32_t a = (contact.flags & contact_moves_a) ? contact.state_a : colored_body_count_;
        const int32_t b = (contact.flags & contact_moves_b) ? contact.state_b : colored_body_count_;
        const int32_t lowest = a < b ? a : b;
        // The key until the regions are cut: the colour and the kind.
        colored_contacts_.push_back({solvable[k], 2 * color + (single_after_pairs ? 1 : 0), lowest});
        ++body_starts_[std::size_t(lowest) + 1];
    }
    for (int32_t k = 0; k <= colored_body_count_; ++k) {
        body_starts_[std::size_t(k) + 1] += body_starts_[std::size_t(k)];
    }
    regions_.cut(regions, body_starts_.data(), colored_body_count_, balance_.shares(regions));
    if (regions > 1) {
        balance_.cut_made();
    }
    const int32_t key_count = sort_key(ConstraintColors::count, 0);
    key_starts_.assign(std::size_t(key_count) + 1, 0);
    for (ColoredContact& c : colored_contacts_) {
        const int32_t color = c.key / 2;
        const int32_t region = color == ConstraintColors::overflow ? 0 : regions_.region_of(c.body);
        c.key = sort_key(color, region, (c.key & 1) != 0);
        ++key_starts_[std::size_t(c.key) + 1];
    }
    for (int32_t key = 0; key < key_count; ++key) {
        key_starts_[std::size_t(key) + 1] += key_starts_[std::size_t(key)];
    }
    color_starts_.resize(ConstraintColors::count + 1);
    for (int32_t color = 0; color <= ConstraintColors::count; ++color) {
        color_starts_[std::size_t(color)] = key_starts_[std::size_t(sort_key(color, 0))];
    }
    ordered_contacts_.resize(colored_contacts_.size());
    order_by_body();
    std::vector<int32_t>& next = scratch_starts_;
    next.assign(key_starts_.begin(), key_starts_.end() - 1);
    const int32_t overflow_key = sort_key(ConstraintColors::overflow, 0);
    for (const ColoredContact& c : body_ordered_) {
        if (c.key != overflow_key) {
            ordered_contacts_[std::size_t(next[std::size_t(c.key)]++)] = c.contact;
        }
    }
    for (const ColoredContact& c : colored_contacts_) {
        if (c.key == overflow_key) {
            ordered_contacts_[std::size_t(next[std::size_t(c.key)]++)] = c.contact;
        }
    }
}

// The coloured contacts by the lowest body each moves (the scatter of a counting sort
// whose counts color_contacts made). Each worker solves a contiguous share of every
// colour, so in this order its shares of all colours move mostly the same bodies, whose
// states then stay in its core's cache. In awake order, 2 workers both moved 1237 of the
// tumbler's 1969 touched bodies, 4285 of the spinner's 6013 and 1233 of rain's 2739; in
// this order 170, 1235 and 181. The spinner steps 4 % faster with 1 worker and with 2
// (paired runs).
void Solver::order_by_body() {
    std::vector<int32_t>& next = scratch_starts_;
    next.assign(body_starts_.begin(), body_starts_.end() - 1);
    body_ordered_.resize(colored_contacts_.size());
    for (const ColoredContact& c : colored_contacts_) {
        body_ordered_[std::size_t(next[std::size_t(c.body)]++)] = c;
    }
}

// Where each worker's part of each colour begins, in its contacts: the first contact of
// the worker's region. Colours with joints (their runs are ordered by joint, not by body)
// and the overflow colour are kept whole, and so are all when the step runs on one thread.
void Solver::split_colors_by_region() {
    const int32_t workers = links_.tasks.worker_count();
    const std::size_t stride = std::size_t(workers) + 1;
    color_parts_.clear();
    if (!parallel_ || regions_.count() != workers) {
        return;
    }
    color_parts_.assign(std::size_t(ConstraintColors::count) * stride, -1);
    for (int32_t color = 0; color < ConstraintColors::overflow; ++color) {
        const int32_t first = key_starts_[std::size_t(sort_key(color, 0))];
        const int32_t count = key_starts_[std::size_t(sort_key(color + 1, 0))] - first;
        const bool has_joints = joint_color_starts_[std::size_t(color) + 1] > joint_color_starts_[std::size_t(color)];
        if (count == 0 || has_joints) {
            continue;
        }
        int32_t* starts = color_parts_.data() + std::size_t(color) * stride;
        for (int32_t w = 0; w <= workers; ++w) {
            starts[w] = key_starts_[std::size_t(sort_key(color, w))] - first;
        }
    }
}

// Each stage's shares of each colour run: where its colour's parts begin, or -1 (split
// evenly).
void Solver::split_runs_by_region() {
    const int32_t workers = links_.tasks.worker_count();
    const std::size_t stride = std::size_t(workers) + 1;
    run_shares_.assign((color_runs_.size() + 1) * stride, -1);
    if (color_parts_.empty()) {
        return;
    }
    for (std::size_t run = 0; run < color_runs_.size(); ++run) {
        const ColorRun& r = color_runs_[run];
        // Colours with joints were kept whole (split_colors_by_region): no parts.
        if (r.sequential || r.contact_items == 0 || contact_solver_.part_first_item(r.contact_run, 0) < 0) {
            continue;
        }
        int32_t* starts = run_shares_.data() + run * stride;
        for (int32_t w = 0; w < workers; ++w) {
            starts[w] = contact_solver_.part_first_item(r.contact_run, w);
        }
        starts[workers] = r.contact_items;
    }
    std::copy(regions_.starts(), regions_.starts() + stride, run_shares_.data() + color_runs_.size() * stride);
}

// The stages' shares, which follow this step's colours even when the stage list is kept.
void Solver::point_stages_at_shares() {
    const std::size_t stride = std::size_t(links_.tasks.worker_count()) + 1;
    for (std::size_t s = 0; s < stages_.size(); ++s) {
        const int32_t share = stage_shares_[s];
        const int32_t* starts = nullptr;
        if (share != no_share) {
            const std::size_t run = share == bodies_share ? color_runs_.size() : std::size_t(share);
            starts = run_shares_.data() + run * stride;
        }
        stages_[s].share_starts = starts != nullptr && starts[0] >= 0 ? starts : nullptr;
    }
}

void Solver::integrate_velocities(void* solver, const Stage&, int32_t begin, int32_t end, int32_t) {
    Solver& self = *static_cast<Solver*>(solver);
    const IntegrationTerms terms = self.integration_terms();
    for (int32_t k = begin; k < end; ++k) {
        self.integrate_velocity(k, terms);
    }
}

Solver::IntegrationTerms Solver::integration_terms() const {
    return {substep_, links_.settings.gravity, links_.settings.maximum_linear_speed,
            max_rotation_per_substep / substep_};
}

// Gravity, forces and damping for dynamic bodies; the speed limit for every moving body
// (kinematic ones too: a caller may set any finite velocity).
void Solver::integrate_velocity(int32_t k, const IntegrationTerms& t) {
    const float h = t.h;
    const Vec2 gravity = t.gravity;
    const float max_speed = t.max_speed;
    const float max_spin = t.max_spin;
    const BodyMotion& m = motions_[std::size_t(k)];
    BodyState& s = states_[std::size_t(k)];
    Vec2 v = s.linear_velocity;
    float w = s.angular_velocity;
    if (m.is_dynamic) {
        v += h * (m.gravity_scale * gravity + m.inv_mass * m.force);
        w += h * m.inv_inertia * m.torque;
        // Implicit damping: stable for any damping and step.
        v = m.linear_damping_factor * v;
        w = m.angular_damping_factor * w;
    }
    // NaN-safe: an overflow anywhere above fails this test too.
    s.linear_velocity =
        length_squared(v) <= max_speed * max_speed ? v : limited_velocity(m, s.linear_velocity, gravity, h, max_speed);
    // At most a quarter turn per substep: faster spins alias and tunnel. A NaN passes
    // through, to be quarantined, rather than becoming a full spin.
    s.angular_velocity = w > max_spin ? max_spin : (w < -max_spin ? -max_spin : w);
}

void Solver::integrate_positions(void* solver, const Stage&, int32_t begin, int32_t end, int32_t) {
    Solver& self = *static_cast<Solver*>(solver);
    const float h = self.substep_;
    for (int32_t k = begin; k < end; ++k) {
        BodyState& s = self.states_[std::size_t(k)];
        s.delta_position += h * s.linear_velocity;
        if (s.angular_velocity != 0.0f) {
            s.delta_rotation = integrate_rotation(s.delta_rotation, h * s.angular_velocity);
        }
    }
}

void Solver::finalize_bodies(void* solver, const Stage&, int32_t begin, int32_t end, int32_t) {
    Solver& self = *static_cast<Solver*>(solver);
    for (int32_t k = begin; k < end; ++k) {
        self.finalize_body(k);
    }
}

// The body's new pose (bodies that did not turn keep their rotation's exact bits), its
// shapes' bounds and its rest time. What reaches beyond the body waits in its slots for
// finish_bodies.
void Solver::finalize_body(int32_t k) {
    const int32_t index = links_.islands.awake_bodies()[std::size_t(k)];
    Body& b = links_.bodies[index];
    // A state that overflowed is not written: the body stays where the step found it,
    // at rest, and the world quarantines it (no NaN reaches the bounds or the trees).
    static const BodyState at_rest{};
    const BodyState& solved = states_[std::size_t(k)];
    const bool finite = is_finite(solved.linear_velocity) && is_finite(solved.angular_velocity) &&
                        is_finite(b.center + solved.delta_position) && is_finite(solved.delta_rotation);
    const BodyState& s = finite ? solved : at_rest;
    const Transform start = b.transform;
    b.linear_velocity = s.linear_velocity;
    b.angular_velocity = s.angular_velocity;
    b.center0 = b.center;
    b.rotation0 = start.q;
    b.center += s.delta_position;
    if (s.delta_rotation.c != 1.0f || s.delta_rotation.s != 0.0f) {
        b.transform.q = normalize(mul_rot(s.delta_rotation, b.transform.q));
    }
    b.transform.p = b.center - rotate(b.transform.q, b.local_center);
    b.force = {};
    b.torque = 0.0f;
    // Fattened for the next step too, assuming the same time step (the world checks).
    uint8_t flags = refit_shape_bounds(b, links_.shapes, time_step_ * b.linear_velocity, true,
                                       turn_reach(b, time_step_)) ? proxies_enlarged : 0;

    const WorldDef& settings = links_.settings;
    if (settings.enable_sleep) {
        // A body rests while its fastest point (spin x extent) and its centre stay slow.
        const float threshold = settings.sleep_speed_threshold;
        const bool resting = b.enable_sleep && length(b.linear_velocity) <= threshold &&
                             std::fabs(b.angular_velocity) * b.max_extent <= threshold;
        b.sleep_time = resting ? b.sleep_time + time_step_ : 0.0f;
        rest_islands_[std::size_t(k)] = links_.islands.rest_slot(index);
        rest_times_[std::size_t(k)] = b.sleep_time;
        flags |= b.type == BodyType::kinematic ? kinematic_rest : 0;
    }
    const bool moved = !(b.transform.p == start.p && b.transform.q.c == start.q.c && b.transform.q.s == start.q.s);
    flags |= moved ? body_moved : 0;
    flags |= settings.enable_continuous && is_fast(b, s, time_step_) ? fast_body : 0;
    flags |= finite ? 0 : non_finite_state;
    final_flags_[std::size_t(k)] = flags;
}

// Each moved body's event gets the next index in awake order: each region's moved bodies
// are numbered from 0 on their own worker (regions [begin, end)), the regions' counts
// then become where their events start, and writing an event adds its region's start.
// Numbered on one thread, it cost large_pyramid 13 to 16 microseconds a step at 2 workers
// while the other worker waited.
void Solver::count_move_events(void* solver, const Stage&, int32_t begin, int32_t end, int32_t) {
    Solver& self = *static_cast<Solver*>(solver);
    const int32_t* starts = self.regions_.starts();
    for (int32_t r = begin; r < end; ++r) {
        int32_t moved_here = 0;
        for (int32_t k = starts[r]; k < starts[r + 1]; ++k) {
            const bool moved = (self.final_flags_[std::size_t(k)] & body_moved) != 0;
            self.event_slots_[std::size_t(k)] = moved ? moved_here : null_index;
            moved_here += moved ? 1 : 0;
        }
        self.move_starts_[std::size_t(r) + 1] = moved_here;
    }
}

void Solver::place_move_events(void* solver, const Stage&, int32_t, int32_t, int32_t) {
    Solver& self = *static_cast<Solver*>(solver);
    std::vector<BodyMoveEvent>& moves = self.links_.events.current.body_moves;
    self.move_starts_[0] = int32_t(moves.size());
    for (int32_t r = 0; r < self.regions_.count(); ++r) {
        self.move_starts_[std::size_t(r) + 1] += self.move_starts_[std::size_t(r)];
    }
    moves.resize(std::size_t(self.move_starts_[std::size_t(self.regions_.count())]));
}

void Solver::write_move_events(void* solver, const Stage&, int32_t begin, int32_t end, int32_t) {
    Solver& self = *static_cast<Solver*>(solver);
    const std::vector<int32_t>& awake = self.links_.islands.awake_bodies();
    const EventRecorder& events = self.links_.events;
    BodyMoveEvent* moves = self.links_.events.current.body_moves.data();
    const int32_t* region_starts = self.regions_.starts();
    int32_t region = self.regions_.region_of(begin);
    for (int32_t k = begin; k < end; ++k) {
        while (k >= region_starts[region + 1]) {
            ++region;
        }
        const int32_t local = self.event_slots_[std::size_t(k)];
        const int32_t slot = local != null_index ? self.move_starts_[std::size_t(region)] + local : null_index;
        const int32_t index = awake[std::size_t(k)];
        Body& b = self.links_.bodies[index];
        b.move_event = slot;
        if (slot != null_index) {
            moves[slot] = {b.transform, events.ids.body_id(index, self.links_.bodies.generation(index)), b.user_data,
                           false};
        }
    }
}

// On one thread, in awake order: proxies to move, rest times to share with the islands.
void Solver::finish_bodies() {
    const std::vector<int32_t>& awake = links_.islands.awake_bodies();
    const bool sleep = links_.settings.enable_sleep;
    fast_bodies_.clear();
    non_finite_bodies_.clear();
    for (std::size_t k = 0; k < awake.size(); ++k) {
        const uint8_t flags = final_flags_[k];
        if (sleep) {
            links_.islands.note_rest_time_in_slot(rest_islands_[k], rest_times_[k]);
        }
        if (flags & fast_body) {
            fast_bodies_.push_back(awake[k]);
        }
        if (flags & non_finite_state) {
            non_finite_bodies_.push_back(awake[k]);
        }
        if ((flags & (proxies_enlarged | kinematic_rest)) == 0) {
            continue;
        }
        const int32_t index = awake[k];
        if (flags & proxies_enlarged) {
            move_enlarged_proxies(links_.bodies[index], links_.shapes, links_.broad_phase);
        }
        if (flags & kinematic_rest) {
            share_kinematic_rest(index);
        }
    }
}

// A moving kinematic body keeps what it touches or holds by a joint awake: those islands
// rest no longer than it does.
void Solver::share_kinematic_rest(int32_t body) {
    const float rest = links_.bodies[body].sleep_time;
    const Pool<Contact>& contacts = links_.contacts.pool();
    links_.contacts.visit_contacts(body, [&](int32_t contact, int32_t other) {
        const Contact& c = contacts[contact];
        const Body& o = links_.bodies[other];
        if (is_solvable(c) && o.type == BodyType::dynamic && o.awake_index != null_index) {
            links_.islands.note_rest_time(other, rest);
        }
    });
    links_.joint_set.visit_joints(body, [&](int32_t, int32_t other) {
        const Body& o = links_.bodies[other];
        if (o.type == BodyType::dynamic && o.awake_index != null_index) {
            links_.islands.note_rest_time(other, rest);
        }
    });
}

}  // namespace i2d
