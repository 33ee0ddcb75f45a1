// SPDX-License-Identifier: MIT
// Solver: the soft step over the awake bodies, their joints and their contacts, as a
// plan of stages that the world's workers share.
//
// Design note: the stage loop is Box2D v3's: per substep integrate velocities, warm
// start, solve with push-out, integrate positions, relax; then one more relax,
// restitution, impulses back to the contacts, and the bodies' final pose, bounds, rest
// time and move event in one pass over them. Each solve or relax sweep over the colours is
// followed by the exact pass over hanging joint trees (joint_tree.hpp), which holds their
// rigid rows where the sweep left off. The pieces each own their data: the body pass the
// bodies' states (body_pass.hpp), the constraint graph the colours (constraint_graph.hpp),
// the shares which worker moves which bodies (body_shares.hpp), the contact and joint
// solvers their constraints, the move events their numbering (move_events.hpp). The
// solver plans the stages over them and runs the plan; the colour stages are in
// color_stages.cpp.
//
// Threads: the step is a list of stages (stage_runner.hpp): bodies in blocks, each
// colour's joints and contact blocks, the overflow colour whole on one worker. Within a
// stage no two items write the same memory (a colour's constraints share no moving body),
// so any split gives the same bits. Every stage over bodies or a colour is split where
// the workers' shares of the bodies are, so that each worker keeps moving its own bodies.
#pragma once

#include <cstdint>
#include <vector>

#include "broadphase/broad_phase.hpp"
#include "core/pool.hpp"
#include "core/stage_runner.hpp"
#include "core/task_system.hpp"
#include "dynamics/body/body.hpp"
#include "dynamics/body/shape.hpp"
#include "dynamics/joint/joint.hpp"
#include "dynamics/solver/body_pass.hpp"
#include "dynamics/solver/body_shares.hpp"
#include "dynamics/solver/constraint_graph.hpp"
#include "dynamics/solver/contact_solver.hpp"
#include "dynamics/solver/impact_chain.hpp"
#include "dynamics/solver/joint_solver.hpp"
#include "dynamics/solver/move_events.hpp"
#include "dynamics/solver/simd/simd_path.hpp"
#include "dynamics/step_context.hpp"
#include "dynamics/world/events.hpp"

namespace i2d {

class ContactSet;
class Islands;
class JointSet;

/// What the solver reads and writes outside its own arrays; the world owns all of it.
struct SolverLinks {
    Pool<Body>& bodies;
    Pool<Shape>& shapes;
    Pool<Joint>& joints;
    const JointSet& joint_set;
    ContactSet& contacts;
    Islands& islands;
    BroadPhase& broad_phase;
    EventRecorder& events;
    TaskSystem& tasks;
};

class Solver {
public:
    /// simd_path: the contact kernels' instruction set, supported here (automatic: the widest).
    Solver(const SolverLinks& links, SimdPath simd_path);
    SimdPath simd_path() const { return simd_path_; }

    /// Steps the awake bodies by the step's time step in its substeps and leaves them at
    /// their new poses, with new bounds, rest times and move events; contacts get their
    /// impulses and touching flags.
    void step(const StepContext& step);
    /// The dynamic bodies the last step moved far for their size, in awake order: the
    /// continuous stage sweeps them.
    const std::vector<int32_t>& fast_bodies() const { return body_pass_.fast_bodies(); }
    /// The bodies whose solved state was not finite, in awake order: the last step left
    /// them where it found them, at rest, for the world to quarantine.
    const std::vector<int32_t>& non_finite_bodies() const { return body_pass_.non_finite_bodies(); }
    /// The world's state was replaced (a snapshot restored): colour, gather and plan
    /// again at the next step.
    void forget_caches();
    /// The constraint graph as the last step coloured it (the debug draw's graph colours).
    const ConstraintGraph& graph() const { return graph_; }

private:
    // A colour that has joints or contacts, in solve order, the overflow colour last.
    struct ColorRun {
        int32_t joint_begin = 0, joint_count = 0;  // in the graph's ordered joints
        int32_t contact_run = -1;                  // the contact solver's run, or -1
        int32_t contact_items = 0;
        bool sequential = false;
    };
    // A colour stage's argument: its colour run (or the first of a group of small runs
    // solved in order, up to group_end) and its pass (substep * 2 + relax).
    struct ColorPass {
        int32_t run = 0, pass = 0, group_end = 0;
    };
    // Items [begin, end) of a colour run: its joints first, then its contact items.
    struct RunSplit {
        int32_t joint_begin, joint_end, contact_begin, contact_end;
    };
    // What the stages were built for, and the shares they are split by.
    struct Plan {
        std::vector<ColorRun> color_runs;
        std::vector<Stage> stages;
        std::vector<int32_t> key, key_scratch;  // the counts the stage list depends on
        // Per colour run, worker_count + 1 entries: the item where each worker's share
        // begins, or -1 throughout where the run is split evenly; then the same for the
        // body stages.
        std::vector<int32_t> run_shares;
        std::vector<int32_t> stage_shares;  // per stage: its run, bodies_share, or no_share
        bool parallel = false;
        bool bounce = false;  // set by check_bounce: the restitution stages run
    };
    static constexpr int32_t bodies_share = -1, no_share = -2;

    // The plan (solver.cpp).
    void lay_out_color_runs();
    void build_stages(const StepContext& step);
    bool stages_changed(const StepContext& step);
    template <auto F>
    void add_stage(typename StageFn<F>::OwnerType& owner, const typename StageFn<F>::ArgType& arg,
                   int32_t item_count, int32_t min_items_per_block);
    template <auto F>
    void add_body_stage(typename StageFn<F>::OwnerType& owner);
    template <auto F, bool with_joints>
    void add_color_stages(int32_t pass, const bool* run_if = nullptr);
    int32_t run_items(int32_t run, bool with_joints) const;
    bool run_is_small(int32_t run, bool with_joints) const;
    int32_t min_items_of(int32_t run) const;
    int32_t min_contact_items() const;
    void split_runs_by_share();
    void point_stages_at_shares();
    ContactLayout contact_layout() const;
    RunSplit split_run(int32_t run, int32_t begin, int32_t end) const;

    // The colour stages (color_stages.cpp); `begin` and `end` index the stage's items.
    template <auto F, bool with_joints>
    static void run_group(const StepContext& step, Solver& solver, const ColorPass& arg, int32_t begin, int32_t end,
                          int32_t worker);
    static void prepare_and_warm_start(const StepContext& step, Solver& solver, const ColorPass& arg, int32_t begin,
                                       int32_t end, int32_t worker);
    static void warm_start(const StepContext& step, Solver& solver, const ColorPass& arg, int32_t begin, int32_t end,
                           int32_t worker);
    static void solve(const StepContext& step, Solver& solver, const ColorPass& arg, int32_t begin, int32_t end,
                      int32_t worker);
    static void relax_and_store(const StepContext& step, Solver& solver, const ColorPass& arg, int32_t begin,
                                int32_t end, int32_t worker);
    static void store_color(const StepContext& step, Solver& solver, const ColorPass& arg, int32_t begin, int32_t end,
                            int32_t worker);
    static void restitution(const StepContext& step, Solver& solver, const ColorPass& arg, int32_t begin, int32_t end,
                            int32_t worker);
    static void solve_joint_trees(const StepContext& step, Solver& solver, const ColorPass& arg, int32_t begin,
                                  int32_t end, int32_t worker);
    static void project_joint_trees(const StepContext& step, Solver& solver, const NoStageArg&, int32_t begin,
                                    int32_t end, int32_t worker);
    static void store_joints(const StepContext& step, Solver& solver, const NoStageArg&, int32_t begin, int32_t end,
                             int32_t worker);
    static void check_bounce(const StepContext& step, Solver& solver, const NoStageArg&, int32_t begin, int32_t end,
                             int32_t worker);
    void prepare_color(const StepContext& step, int32_t run, int32_t begin, int32_t end);
    void store_contacts(const StepContext& step, int32_t run, const RunSplit& split);
    static SolvePass solve_pass(const StepContext& step, int32_t pass);

    SolverLinks links_;
    SimdPath simd_path_;
    ContactSolver contact_solver_;
    ImpactChains impact_chains_;
    JointSolver joint_solver_;
    BodyShares shares_;     // each worker's bodies: every stage is split where they are
    ShareBalance balance_;  // how much of the work each share gets
    ConstraintGraph graph_;
    BodyPass body_pass_;
    MoveEvents move_events_;
    Plan plan_;
    StageRunner runner_;
};

}  // namespace i2d
