// SPDX-License-Identifier: MIT
// BodyPass: the solver's dense per-step copies of the awake bodies (body_state.hpp) and
// the passes over them: gathering them from the body pool, integrating velocities and
// positions each substep, and writing them back.
//
// Design note: the substeps touch only the states and motions, indexed by a body's place
// in the awake list, plus one shared "fixed" state at the end that stands in for every
// static or sleeping body. The final pass writes each body's pose, bounds and rest time;
// what it would write outside its own body (the broadphase, the islands' rest times) it
// leaves in per-body slots that finish() applies on one thread in awake order, so that the
// workers never write shared memory and the result is the same for any worker count.
#pragma once

#include <cstdint>
#include <vector>

#include "broadphase/broad_phase.hpp"
#include "core/pool.hpp"
#include "core/stage_runner.hpp"
#include "dynamics/body/body.hpp"
#include "dynamics/body/shape.hpp"
#include "dynamics/solver/body_state.hpp"
#include "dynamics/step_context.hpp"

namespace i2d {

class ContactSet;
class Islands;
class JointSet;

/// What the body pass reads and writes outside its own arrays; the world owns all of it.
struct BodyPassLinks {
    Pool<Body>& bodies;
    Pool<Shape>& shapes;
    Islands& islands;
    const ContactSet& contacts;
    const JointSet& joints;
    BroadPhase& broad_phase;
};

class BodyPass {
public:
    explicit BodyPass(const BodyPassLinks& links) : links_(links) {}

    /// Room for the awake bodies' states, the shared fixed state after them (one thread).
    void begin(int32_t awake_count);
    /// No body is awake: nothing is fast or broken.
    void clear_results();
    int32_t fixed_state() const { return int32_t(states_.size()) - 1; }
    BodyState* states() { return states_.data(); }
    const BodyState* states() const { return states_.data(); }
    const BodyMotion* motions() const { return motions_.data(); }
    /// Whether the final pass moved the k-th awake body.
    bool moved(int32_t k) const { return (final_flags_[std::size_t(k)] & body_moved) != 0; }

    // Stages over the awake bodies [begin, end).
    /// One state per awake body in awake order, its velocity integrated for the first
    /// substep.
    static void gather(const StepContext& step, BodyPass& pass, const NoStageArg&, int32_t begin, int32_t end,
                       int32_t worker);
    static void integrate_velocities(const StepContext& step, BodyPass& pass, const NoStageArg&, int32_t begin,
                                     int32_t end, int32_t worker);
    static void integrate_positions(const StepContext& step, BodyPass& pass, const NoStageArg&, int32_t begin,
                                    int32_t end, int32_t worker);
    /// Each body's new pose, its shapes' bounds and its rest time.
    static void finalize(const StepContext& step, BodyPass& pass, const NoStageArg&, int32_t begin, int32_t end,
                         int32_t worker);

    /// After finalize: the proxies it enlarged, in parts of the awake list (move_parts of
    /// them, whichever worker takes which part), for finish() to hand on in awake order.
    static void gather_moves(const StepContext& step, BodyPass& pass, const NoStageArg&, int32_t begin, int32_t end,
                             int32_t worker);
    static constexpr int32_t move_parts = 16;

    /// After gather_moves, on one thread in awake order: proxies to move, rest times to
    /// share with the islands, the fast and the broken bodies listed.
    void finish(const StepContext& step);
    /// The dynamic bodies the last step moved far for their size, in awake order: the
    /// continuous stage sweeps them.
    const std::vector<int32_t>& fast_bodies() const { return fast_bodies_; }
    /// The bodies whose solved state was not finite, in awake order: the last step left
    /// them where it found them, at rest, for the world to quarantine.
    const std::vector<int32_t>& non_finite_bodies() const { return non_finite_bodies_; }

private:
    // What integrating a velocity reads besides the body, the same for every body.
    struct IntegrationTerms {
        float h;  // the substep, s
        Vec2 gravity;
        float max_speed, max_spin;  // m/s, rad/s
    };
    static IntegrationTerms integration_terms(const StepContext& step);
    void integrate_velocity(int32_t k, const IntegrationTerms& terms);
    // What the final pass reads besides the body, read once per block: through the
    // context, each body's stores would make the compiler read them again.
    struct FinalTerms {
        float time_step;  // s
        bool enable_sleep, enable_continuous;
    };
    void finalize_body(const FinalTerms& terms, int32_t k);
    void share_kinematic_rest(int32_t body);

    // What the final pass leaves per awake body for finish().
    enum FinalFlags : uint8_t {
        body_moved = 1,
        proxies_enlarged = 2,
        kinematic_rest = 4,
        fast_body = 8,
        non_finite_state = 16
    };

    // An enlarged proxy's move, as move_proxy takes it.
    struct ProxyMove {
        int32_t key;
        AABB fat_aabb, ahead_aabb;
    };

    BodyPassLinks links_;
    std::vector<BodyState> states_;    // per awake body, then the fixed state
    std::vector<BodyMotion> motions_;  // the same, the fixed one all zero
    std::vector<uint8_t> final_flags_;
    std::vector<int32_t> rest_islands_;  // the body's island's rest slot (Islands::rest_slot)
    std::vector<float> rest_times_;
    std::vector<int32_t> fast_bodies_;
    std::vector<int32_t> non_finite_bodies_;
    std::vector<ProxyMove> moves_[move_parts];  // per part of the awake list, in awake order
};

}  // namespace i2d
