// SPDX-License-Identifier: MIT
// Continuous: the step's continuous collision stage. Fast bodies are swept from where
// the step began to where the solver left them; one that would have passed through
// something is moved back to its time of impact, where the impact's impulse is solved
// (impact.hpp): no approach is left into what it met, or its restitution's bounce, and
// friction has acted, as a contact would have done. (Box2D v3 keeps the velocity and
// leaves the impact to the next step's speculative contact.)
//
// Design note: every fast dynamic body is swept against static and kinematic shapes,
// kinematic ones along their own motion over the step (the relative motion: a wall
// moving towards a ball cannot jump over it). Bullets are swept after the others, also
// against dynamic bodies along their motion, bullets included: two bullets that meet
// head-on are both moved back to the time they touch. Sensors the fast body crossed
// within the step are remembered, so that they report it. With nothing fast the stage
// costs one empty loop (the solver's final pass already picked the fast bodies).
//
// A free body (one no joint holds) that starts a step fast meets what it is swept
// against here and nowhere else: their contact keeps the world's speculative distance
// instead of reaching as far as the step's approach (narrowphase.cpp), since a point
// made that far off has the wrong normal and anchor for the impact (a fast ball ended
// 14 cm short of a wall, or slid off its end still drifting into it). A jointed body
// keeps the long reach: moving it back alone would pull its joints apart.
//
// Threads: a body that is not a bullet sweeps only against static and kinematic shapes,
// which nothing in this stage moves, so those sweeps are independent and the workers
// share them (Box2D v3 does them as it finalizes bodies). Each leaves its impact and the
// sensors it crossed in its own slot; moving the bodies back, which writes the
// broadphase, and listing the crossings happen on one thread in awake order. Bullets,
// which meet each other where the others were left, are swept one after another. The
// results do not depend on the worker count.
// Alternative rejected: sweeping every pair of fast bodies (bullet or not) like bullets
// would couple them all and need an order-dependent fix-point; only bullets opt in.
#pragma once

#include <cstdint>
#include <vector>

#include "broadphase/broad_phase.hpp"
#include "collision/toi.hpp"
#include "core/pool.hpp"
#include "core/stage_runner.hpp"
#include "core/task_system.hpp"
#include "dynamics/body/body.hpp"
#include "dynamics/contact/contact_hooks.hpp"
#include "dynamics/world/events.hpp"
#include "dynamics/body/shape.hpp"
#include "dynamics/step_context.hpp"

namespace i2d {

/// A sensor a fast body passed within the step.
struct SensorCrossing {
    int32_t sensor_shape, visitor_shape;
};

class Continuous {
public:
    Continuous(Pool<Body>& bodies, Pool<Shape>& shapes, BroadPhase& broad_phase, EventRecorder& events,
               TaskSystem& tasks, const ContactHooks& hooks)
        : bodies_(bodies), shapes_(shapes), broad_phase_(broad_phase), events_(events), tasks_(tasks), hooks_(hooks) {}

    /// Sweeps the fast bodies (awake order); moved ones get new bounds (their proxies
    /// move at the broadphase's next commit) and their move events the new pose.
    void run(const StepContext& step, const std::vector<int32_t>& fast_bodies);
    /// Sensors crossed in the last run, in the order they were found.
    const std::vector<SensorCrossing>& sensor_crossings() const { return crossings_; }

private:
    // The shape being swept.
    struct FastShape {
        int32_t body = null_index, shape = null_index;
        bool bullet_pass = false;
        Sweep sweep;
        Transform start;  // the body's pose at the start of the step
        ShapeProxy proxy;
        float slop = 0.0f;    // the world's linear slop (Tolerances): impacts stop within it
        float margin = 0.0f;  // the world's speculative distance: a manifold's reach
    };
    // The earliest impact found so far: where along the sweep, and the fast body's shape
    // and the other body and shape it met.
    struct Impact {
        float fraction = 1.0f;
        int32_t body = null_index;
        int32_t shape = null_index, other_shape = null_index;
    };
    struct SensorCandidate {
        SensorCrossing crossing;
        float fraction;
    };
    // What one body's sweep found: its first impact, and where in its worker's found_
    // list the sensors it crossed (before or after that impact) are.
    struct SweepResult {
        Impact first;
        int32_t worker = 0, candidates_begin = 0, candidates_end = 0;
    };

    static void sweep_range(const StepContext& step, Continuous& continuous, const NoStageArg&, int32_t begin,
                            int32_t end, int32_t worker);
    void sweep_non_bullets(const StepContext& step);
    Impact sweep(int32_t body, bool bullet_pass, const Tolerances& tolerances, std::vector<SensorCandidate>& found);
    bool pre_solve_refuses(const FastShape& fast, int32_t other_index, const Sweep& other_sweep, float fraction) const;
    void apply(const StepContext& step, int32_t body, const Impact& first, const SensorCandidate* found_begin,
               const SensorCandidate* found_end);
    void test_candidate(const FastShape& fast, int32_t other_shape, Impact& first,
                        std::vector<SensorCandidate>& found);
    Sweep sweep_of(int32_t body) const;
    bool swept_against(const Body& fast, const Body& other, bool bullet_pass) const;
    void move_to(const StepContext& step, int32_t body, float fraction, int32_t carrier);
    void resolve(const StepContext& step, int32_t body, const Impact& impact);
    void rewind_gravity(const StepContext& step, int32_t body, float fraction);

    Pool<Body>& bodies_;
    Pool<Shape>& shapes_;
    BroadPhase& broad_phase_;
    EventRecorder& events_;
    TaskSystem& tasks_;
    const ContactHooks& hooks_;
    std::vector<SensorCrossing> crossings_;
    std::vector<int32_t> non_bullets_;     // this step's fast bodies that are not bullets
    std::vector<SweepResult> results_;     // per non-bullet
    std::vector<std::vector<SensorCandidate>> found_;  // per worker, of the bodies it swept
    std::vector<Stage> stages_;
    StageRunner runner_;
};

}  // namespace i2d
