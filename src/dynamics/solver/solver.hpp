// SPDX-License-Identifier: MIT
// Solver: the soft step over the awake bodies, their joints and their contacts, from
// gathering the bodies' states to writing them back.
//
// Design note: the substeps touch only dense arrays the solver owns, indexed by a body's
// place in the awake list: the states (velocities and motion since the step began) and
// the motions (what integration needs), plus one shared "fixed" state at the end that
// stands in for every static or sleeping body. Joints and contacts are coloured together
// (constraint_colors.hpp, joints first), laid out colour by colour, the order they are
// solved in, and kept while nothing they depend on changes; within a colour the joints
// come before the contacts, and a colour's stage covers both. The stage loop is Box2D v3's: per substep
// integrate velocities, warm start, solve with push-out, integrate positions, relax;
// then one more relax, restitution, impulses back to the contacts, and the bodies' final
// pose, bounds, rest time and move event in one pass over them. Each solve or relax
// sweep over the colours is followed by the exact pass over hanging joint trees
// (joint_tree.hpp), which holds their rigid rows where the sweep left off.
//
// Threads: the step is a list of stages (stage_runner.hpp) that the world's workers
// share: bodies in blocks, each colour's contact blocks, the overflow colour whole on one
// worker. Within a stage no two items write the same memory (a colour's contacts share
// no moving body), so any split gives the same bits. What the final pass would write
// outside its own body (the broadphase, the islands' rest times) it leaves in per-body
// slots, which one thread then applies in awake order; move events are numbered in awake
// order on one thread and written by all.
#pragma once

#include <cstdint>
#include <vector>

#include "broadphase/broad_phase.hpp"
#include "core/pool.hpp"
#include "core/stage_runner.hpp"
#include "core/task_system.hpp"
#include "dynamics/body/body.hpp"
#include "dynamics/solver/body_regions.hpp"
#include "dynamics/solver/body_state.hpp"
#include "dynamics/solver/constraint_colors.hpp"
#include "dynamics/solver/contact_solver.hpp"
#include "dynamics/world/events.hpp"
#include "dynamics/joint/joint_set.hpp"
#include "dynamics/solver/joint_solver.hpp"
#include "dynamics/body/shape.hpp"
#include "dynamics/solver/simd/simd_path.hpp"
#include "dynamics/world/world_def.hpp"

namespace i2d {

class ContactSet;
class Islands;

/// What the solver reads and writes outside its own arrays; the world owns all of it.
struct SolverLinks {
    const WorldDef& settings;
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
    explicit Solver(const SolverLinks& links)
        : links_(links),
          simd_path_(links.settings.simd_path == SimdPath::automatic ? widest_simd_path() : links.settings.simd_path) {
        contact_solver_.set_kernels(contact_kernels_for(simd_path_));
        joint_solver_.set_kernels(contact_kernels_for(simd_path_));
    }
    SimdPath simd_path() const { return simd_path_; }

    /// Steps the awake bodies by time_step in substep_count substeps and leaves them at
    /// their new poses, with new bounds, rest times and move events; contacts get their
    /// impulses and touching flags.
    void step(float time_step, int32_t substep_count);
    /// The dynamic bodies the last step moved far for their size, in awake order: the
    /// continuous stage sweeps them.
    const std::vector<int32_t>& fast_bodies() const { return fast_bodies_; }
    /// The bodies whose solved state was not finite, in awake order: the last step left
    /// them where it found them, at rest, for the world to quarantine.
    const std::vector<int32_t>& non_finite_bodies() const { return non_finite_bodies_; }

private:
    bool color_constraints();
    bool joints_changed();
    void color_joints();
    void color_contacts(int32_t regions);
    void lay_out_color_runs();
    void build_stages(int32_t substep_count);
    bool stages_changed(int32_t substep_count);
    void add_stage(Stage::Fn fn, int32_t item_count, int32_t min_items_per_block, int32_t arg0 = 0,
                   int32_t arg1 = 0);
    void add_body_stage(Stage::Fn fn);
    template <Stage::Fn fn, bool with_joints>
    void add_color_stages(int32_t pass, const bool* run_if = nullptr);
    template <Stage::Fn fn, bool with_joints>
    static void run_group(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t worker);
    int32_t run_items(int32_t run, bool with_joints) const;
    bool run_is_small(int32_t run, bool with_joints) const;
    int32_t min_items_of(int32_t run) const;
    int32_t min_contact_items() const;
    ContactLayout contact_layout() const;
    void finish_bodies();
    void order_by_body();
    void split_colors_by_region();
    void split_runs_by_region();
    void point_stages_at_shares();
    // Items [begin, end) of a colour run: its joints first, then its contact items.
    struct RunSplit {
        int32_t joint_begin, joint_end, contact_begin, contact_end;
    };
    RunSplit split_run(int32_t run, int32_t begin, int32_t end) const;
    void store_contacts(int32_t color_run, const RunSplit& split);

    // The stages; `begin` and `end` index the stage's items.
    static void gather_bodies(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t worker);
    static void solve_joint_trees(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t worker);
    static void prepare_color(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t worker);
    static void prepare_and_warm_start(void* solver, const Stage& stage, int32_t begin, int32_t end,
                                       int32_t worker);
    static void relax_and_store(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t worker);
    static void store_color(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t worker);
    static void store_joints(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t worker);
    static void integrate_velocities(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t worker);
    // What integrating a velocity reads besides the body, the same for every body.
    struct IntegrationTerms {
        float h;  // the substep, s
        Vec2 gravity;
        float max_speed, max_spin;  // m/s, rad/s
    };
    IntegrationTerms integration_terms() const;
    void integrate_velocity(int32_t awake_index, const IntegrationTerms& terms);
    static void warm_start(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t worker);
    static void solve(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t worker);
    static void integrate_positions(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t worker);
    static void check_bounce(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t worker);
    static void restitution(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t worker);
    static void finalize_bodies(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t worker);
    static void count_move_events(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t worker);
    static void place_move_events(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t worker);
    static void write_move_events(void* solver, const Stage& stage, int32_t begin, int32_t end, int32_t worker);
    void finalize_body(int32_t awake_index);
    void share_kinematic_rest(int32_t body);

    SolverLinks links_;
    SimdPath simd_path_;
    ContactSolver contact_solver_;
    JointSolver joint_solver_;
    ConstraintColors colors_;
    // The joints to solve this step, and per joint what its colour depends on (index and
    // the two states it moves, or -1), as last coloured.
    std::vector<int32_t> awake_joints_;
    bool gathered_ = false;
    bool joints_regathered_ = false;  // this step gathered the joints again (build the trees)
    uint64_t gathered_joint_version_ = 0, gathered_awake_version_ = 0;
    std::vector<int32_t> joint_key_, colored_joint_key_;
    std::vector<int8_t> joint_colors_;  // per awake joint, or -1 when it moves nothing
    std::vector<int32_t> joint_color_starts_;  // per colour: its first slot in ordered_joints_
    std::vector<int32_t> ordered_joints_;
    // Per colour that has joints or contacts, in solve order, the overflow colour last.
    struct ColorRun {
        int32_t joint_begin = 0, joint_count = 0;  // in ordered_joints_
        int32_t contact_run = -1;                  // the contact solver's run, or -1
        int32_t contact_items = 0;
        int32_t color = 0;
        bool sequential = false;
    };
    std::vector<ColorRun> color_runs_;
    struct ColoredContact {
        int32_t contact;
        int32_t key;   // sort_key(): colour, then region, then a single point after the pairs
        int32_t body;  // the lowest state it moves; the state count if it moves none
    };
    int32_t sort_key(int32_t color, int32_t region, bool single_point = false) const {
        return 2 * (color * regions_.count() + region) + (single_point ? 1 : 0);
    }
    std::vector<ColoredContact> colored_contacts_;  // in awake order
    std::vector<ColoredContact> body_ordered_;      // the same, by body
    std::vector<int32_t> key_starts_;               // per sort key: its first slot
    std::vector<int32_t> body_starts_;              // per state: its first slot in body_ordered_
    std::vector<int32_t> color_starts_;   // per colour: its first slot in ordered_contacts_
    std::vector<int32_t> ordered_contacts_;  // the contacts to solve, colour by colour
    std::vector<int32_t> scratch_starts_;
    bool any_elastic_contact_ = false;  // among the coloured contacts
    // The contact layout the colours above were made for.
    bool colored_ = false;
    uint64_t colored_version_ = 0;
    int32_t colored_body_count_ = 0;
    // Each worker's bodies, and in each colour the contacts of the region's lowest bodies
    // after those of the regions before (one region when the step runs on one thread).
    BodyRegions regions_;
    RegionBalance balance_;  // how much of the work each region gets
    std::vector<int32_t> color_parts_;  // per colour, workers + 1: ContactLayout::color_parts
    // Per colour run, worker_count + 1 entries: the item where each worker's share begins,
    // or -1 throughout where the run is split evenly; then the same for the body stages.
    std::vector<int32_t> run_shares_;
    std::vector<int32_t> stage_shares_;  // per stage: its run, bodies_share, or no_share
    static constexpr int32_t bodies_share = -1, no_share = -2;
    std::vector<BodyState> states_;       // per awake body, then the fixed state
    std::vector<BodyMotion> motions_;     // the same, the fixed one all zero
    // This step's settings and stages.
    float time_step_ = 0.0f, substep_ = 0.0f;
    std::vector<SolvePass> passes_;  // per substep: with push-out, then relaxing
    bool bounce_ = false;
    std::vector<Stage> stages_;
    std::vector<int32_t> stage_key_, stage_key_scratch_;  // what stages_ was built for
    StageRunner runner_;
    bool parallel_ = false;
    // What the final pass leaves per awake body for finish_bodies.
    enum FinalFlags : uint8_t {
        body_moved = 1,
        proxies_enlarged = 2,
        kinematic_rest = 4,
        fast_body = 8,
        non_finite_state = 16
    };
    std::vector<int32_t> fast_bodies_;
    std::vector<int32_t> non_finite_bodies_;
    std::vector<uint8_t> final_flags_;
    std::vector<int32_t> rest_islands_;  // the body's island's rest slot (Islands::rest_slot)
    std::vector<float> rest_times_;
    // Per awake body: its move event's index within its region, if it moved; per region,
    // the moved bodies, then where their events start (regions_.count() + 1).
    std::vector<int32_t> event_slots_;
    std::vector<int32_t> move_starts_;
};

}  // namespace i2d
