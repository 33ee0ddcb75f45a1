// SPDX-License-Identifier: MIT
// Solver: the step, and the plan of stages it runs.
#include "dynamics/solver/solver.hpp"

#include <algorithm>

#include "dynamics/constants.hpp"
#include "dynamics/contact/contact_set.hpp"
#include "dynamics/island/island.hpp"

namespace i2d {

Solver::Solver(const SolverLinks& links, SimdPath simd_path)
    : links_(links),
      simd_path_(simd_path == SimdPath::automatic ? widest_simd_path() : simd_path),
      graph_(GraphLinks{links.joints, links.bodies, links.joint_set, links.contacts, links.islands, links.tasks}),
      body_pass_(BodyPassLinks{links.bodies, links.shapes, links.islands, links.contacts, links.joint_set,
                               links.broad_phase}),
      move_events_(MoveEventLinks{links.bodies, links.islands, links.events, body_pass_, shares_}) {
    contact_solver_.set_kernels(contact_kernels_for(simd_path_));
    joint_solver_.set_kernels(contact_kernels_for(simd_path_));
}

void Solver::step(const StepContext& step) {
    const int32_t awake = int32_t(links_.islands.awake_bodies().size());
    if (awake == 0) {
        // Nothing moves, so no contact or joint is solved (each needs an awake body): an
        // empty or sleeping world's step skips the layouts and stages, half its cost.
        body_pass_.clear_results();
        return;
    }
    body_pass_.begin(awake);
    const int32_t workers = links_.tasks.worker_count();
    plan_.parallel = workers > 1 && awake >= parallel_min_bodies;
    if (graph_.update(plan_.parallel ? workers : 1, workers, plan_.parallel, shares_, balance_)) {
        contact_solver_.lay_out(contact_layout());
    }
    if (step.settings.enable_impact_chains && graph_.max_restitution() >= chain_min_restitution) {
        // Before the bodies are gathered: the substeps start from the chains' velocities.
        impact_chains_.run(step, links_.bodies, links_.contacts);
    }
    const std::vector<int32_t>& ordered_joints = graph_.ordered_joints();
    joint_solver_.lay_out(ordered_joints.data(), int32_t(ordered_joints.size()));
    if (graph_.joints_regathered()) {
        // What the trees depend on (the joints, their settings, their bodies' types, masses
        // and places) moves the joint set's or the islands' version.
        joint_solver_.build_trees(links_.joints, links_.bodies, awake, graph_.any_joint_to_fixed());
    }
    lay_out_color_runs();
    split_runs_by_share();
    move_events_.begin(awake, shares_.count());
    if (step.settings.enable_sleep) {
        links_.islands.begin_rest_times();
    }
    build_stages(step);
    point_stages_at_shares();
    runner_.run(links_.tasks, plan_.stages, plan_.parallel, &step);
    const std::vector<StageRunner::WorkerTime>& times = runner_.worker_times();
    if (!times.empty()) {
        // How fast each worker ran its blocks, for the next cut of the shares.
        balance_.note_run(times.data(), int32_t(times.size()));
    }
    joint_solver_.report_breaking(links_.joints, links_.events.ids, links_.events.current.joint_events);
    body_pass_.finish(step);
}

void Solver::forget_caches() {
    graph_.forget();
    plan_.key.clear();
}

ContactLayout Solver::contact_layout() const {
    ContactLayout layout{links_.contacts.pool(),        graph_.ordered_contacts().data(),
                         graph_.color_starts().data(),  ConstraintColors::count,
                         body_pass_.motions(),          body_pass_.fixed_state(),
                         graph_.any_elastic_contact()};
    if (!graph_.color_parts().empty()) {
        layout.color_parts = graph_.color_parts().data();
        layout.part_stride = links_.tasks.worker_count() + 1;
    }
    return layout;
}

template <auto F>
void Solver::add_stage(typename StageFn<F>::OwnerType& owner, const typename StageFn<F>::ArgType& arg,
                       int32_t item_count, int32_t min_items_per_block) {
    plan_.stages.push_back(
        make_stage<F>(owner, arg, item_count, links_.tasks.worker_count(), plan_.parallel, min_items_per_block));
    plan_.stage_shares.push_back(no_share);
}

// A stage over the awake bodies, split where the shares are.
template <auto F>
void Solver::add_body_stage(typename StageFn<F>::OwnerType& owner) {
    add_stage<F>(owner, NoStageArg{}, body_pass_.fixed_state(), bodies_per_work_block);
    plan_.stage_shares.back() = bodies_share;
}

// One stage per colour, in solve order, over its joints and then its contacts; the
// overflow colour whole, on one worker. Restitution passes leave the joints out. Small
// colours next to each other (the overflow counts as one) share one stage that solves them
// in order on one worker: a scene's last colours often hold a few constraints each, and
// a stage apiece cost a wait between workers (hundreds of nanoseconds) for tens of
// nanoseconds of work.
template <auto F, bool with_joints>
void Solver::add_color_stages(int32_t pass, const bool* run_if) {
    const int32_t runs = int32_t(plan_.color_runs.size());
    for (int32_t run = 0; run < runs;) {
        int32_t group_end = run;
        int32_t group_stages = 0;
        while (group_end < runs && run_is_small(group_end, with_joints)) {
            group_stages += run_items(group_end, with_joints) > 0 ? 1 : 0;
            ++group_end;
        }
        if (group_stages >= 2) {
            add_stage<&Solver::run_group<F, with_joints>>(*this, ColorPass{run, pass, group_end}, 1, 1);
            plan_.stages.back().run_if = run_if;
            run = group_end;
            continue;
        }
        const ColorRun& r = plan_.color_runs[std::size_t(run)];
        const int32_t items = run_items(run, with_joints);
        if (items > 0) {
            const int32_t min_items = r.sequential ? items : min_items_of(run);
            add_stage<F>(*this, ColorPass{run, pass, run + 1}, items, min_items);
            plan_.stages.back().run_if = run_if;
            plan_.stage_shares.back() = run;
        }
        ++run;
    }
}

int32_t Solver::run_items(int32_t run, bool with_joints) const {
    const ColorRun& r = plan_.color_runs[std::size_t(run)];
    return (with_joints ? r.joint_count : 0) + r.contact_items;
}

// At most small_color_blocks work blocks of joints and as many of contacts: too little to
// share out between workers.
bool Solver::run_is_small(int32_t run, bool with_joints) const {
    const ColorRun& r = plan_.color_runs[std::size_t(run)];
    const int32_t joints = with_joints ? r.joint_count : 0;
    return r.sequential || (joints <= small_color_blocks * joints_per_work_block &&
                            r.contact_items <= small_color_blocks * min_contact_items());
}

// Items per work block at least: SIMD blocks of contacts where the colour has contacts.
int32_t Solver::min_items_of(int32_t run) const {
    return plan_.color_runs[std::size_t(run)].contact_items > 0 ? min_contact_items() : joints_per_work_block;
}

// SIMD blocks of contacts per work block.
int32_t Solver::min_contact_items() const {
    const int32_t width = contact_solver_.kernels().width;
    return (contacts_per_work_block + width - 1) / width;
}

// The colours that have joints or contacts, in solve order: the contact solver's runs
// are its colours that have contacts, in the same order, its overflow run last.
void Solver::lay_out_color_runs() {
    const std::vector<int32_t>& joint_starts = graph_.joint_color_starts();
    const std::vector<int32_t>& contact_starts = graph_.color_starts();
    plan_.color_runs.clear();
    int32_t contact_run = 0;
    for (int32_t color = 0; color < ConstraintColors::count; ++color) {
        const int32_t joints = joint_starts[std::size_t(color) + 1] - joint_starts[std::size_t(color)];
        const int32_t contacts = contact_starts[std::size_t(color) + 1] - contact_starts[std::size_t(color)];
        if (joints == 0 && contacts == 0) {
            continue;
        }
        ColorRun r;
        r.joint_begin = joint_starts[std::size_t(color)];
        r.joint_count = joints;
        r.sequential = color == ConstraintColors::overflow;
        if (contacts > 0) {
            r.contact_run = contact_run++;
            r.contact_items = contact_solver_.run_items(r.contact_run);
        }
        plan_.color_runs.push_back(r);
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
void Solver::build_stages(const StepContext& step) {
    if (!stages_changed(step)) {
        return;  // a steady scene: the same stages over the same counts as last step
    }
    const bool elastic = graph_.any_elastic_contact();
    const int32_t substeps = step.substep_count;
    const int32_t trees = joint_solver_.tree_count();
    const int32_t last_pass = 2 * substeps - 1;
    plan_.stages.clear();
    plan_.stage_shares.clear();
    add_body_stage<&BodyPass::gather>(body_pass_);
    for (int32_t i = 0; i < substeps; ++i) {
        if (i == 0) {
            add_color_stages<&Solver::prepare_and_warm_start, true>(0);
        } else {
            add_body_stage<&BodyPass::integrate_velocities>(body_pass_);
            add_color_stages<&Solver::warm_start, true>(0);
        }
        add_color_stages<&Solver::solve, true>(2 * i);
        add_stage<&Solver::solve_joint_trees>(*this, ColorPass{0, 2 * i, 0}, trees, joint_trees_per_work_block);
        add_body_stage<&BodyPass::integrate_positions>(body_pass_);
        add_color_stages<&Solver::solve, true>(2 * i + 1);
        add_stage<&Solver::solve_joint_trees>(*this, ColorPass{0, 2 * i + 1, 0}, trees, joint_trees_per_work_block);
    }
    if (elastic) {
        add_color_stages<&Solver::solve, true>(last_pass);
    } else {
        add_color_stages<&Solver::relax_and_store, true>(last_pass);
    }
    add_stage<&Solver::solve_joint_trees>(*this, ColorPass{0, last_pass, 0}, trees, joint_trees_per_work_block);
    if (joint_solver_.cut_count() > 0) {
        add_stage<&Solver::project_joint_trees>(*this, NoStageArg{}, trees, joint_trees_per_work_block);
    }
    if (elastic) {
        add_stage<&Solver::check_bounce>(*this, NoStageArg{}, 1, 1);
        constexpr int32_t restitution_iterations = 4;
        for (int32_t iteration = 0; iteration < restitution_iterations; ++iteration) {
            add_color_stages<&Solver::restitution, false>(0, &plan_.bounce);
        }
        add_color_stages<&Solver::store_color, true>(0);
    } else {
        add_stage<&Solver::store_joints>(*this, NoStageArg{}, joint_solver_.count(), joints_per_work_block);
    }
    add_body_stage<&BodyPass::finalize>(body_pass_);
    add_stage<&BodyPass::gather_moves>(body_pass_, NoStageArg{}, BodyPass::move_parts, 1);
    add_stage<&MoveEvents::count>(move_events_, NoStageArg{}, shares_.count(), 1);
    add_stage<&MoveEvents::place>(move_events_, NoStageArg{}, 1, 1);
    add_body_stage<&MoveEvents::write>(move_events_);
}

// The stage list depends only on these counts; a small world's step would otherwise
// spend a tenth of its time building the same list again.
bool Solver::stages_changed(const StepContext& step) {
    std::vector<int32_t>& key = plan_.key_scratch;
    key.clear();
    key.push_back(step.substep_count);
    key.push_back(plan_.parallel ? links_.tasks.worker_count() : 1);
    key.push_back(body_pass_.fixed_state() + 1);
    key.push_back(contact_solver_.block_count());
    key.push_back(contact_solver_.overflow_count());
    key.push_back(joint_solver_.count());
    key.push_back(joint_solver_.tree_count());
    key.push_back(joint_solver_.cut_count() > 0 ? 1 : 0);
    key.push_back(graph_.any_elastic_contact() ? 1 : 0);
    for (const ColorRun& r : plan_.color_runs) {
        key.push_back(r.joint_count);
        key.push_back(r.contact_items);
    }
    if (key == plan_.key) {
        return false;
    }
    plan_.key.swap(key);
    return true;
}

// Each stage's shares of each colour run: where its colour's parts begin, or -1 (split
// evenly).
void Solver::split_runs_by_share() {
    const int32_t workers = links_.tasks.worker_count();
    const std::size_t stride = std::size_t(workers) + 1;
    const std::vector<ColorRun>& runs = plan_.color_runs;
    plan_.run_shares.assign((runs.size() + 1) * stride, -1);
    if (graph_.color_parts().empty()) {
        return;
    }
    for (std::size_t run = 0; run < runs.size(); ++run) {
        const ColorRun& r = runs[run];
        // Colours with joints were kept whole (ConstraintGraph::split_colors_by_share): no parts.
        if (r.sequential || r.contact_items == 0 || contact_solver_.part_first_item(r.contact_run, 0) < 0) {
            continue;
        }
        int32_t* starts = plan_.run_shares.data() + run * stride;
        for (int32_t w = 0; w < workers; ++w) {
            starts[w] = contact_solver_.part_first_item(r.contact_run, w);
        }
        starts[workers] = r.contact_items;
    }
    std::copy(shares_.starts(), shares_.starts() + stride, plan_.run_shares.data() + runs.size() * stride);
}

// The stages' shares, which follow this step's colours even when the stage list is kept.
void Solver::point_stages_at_shares() {
    const std::size_t stride = std::size_t(links_.tasks.worker_count()) + 1;
    for (std::size_t s = 0; s < plan_.stages.size(); ++s) {
        const int32_t share = plan_.stage_shares[s];
        const int32_t* starts = nullptr;
        if (share != no_share) {
            const std::size_t run = share == bodies_share ? plan_.color_runs.size() : std::size_t(share);
            starts = plan_.run_shares.data() + run * stride;
        }
        plan_.stages[s].share_starts = starts != nullptr && starts[0] >= 0 ? starts : nullptr;
    }
}

}  // namespace i2d
