// SPDX-License-Identifier: MIT
// JointConstraint: what the solver keeps of one joint for one step, and the small pieces
// of arithmetic every kind shares.
//
// Design note: a joint is solved the way contacts are (contact_solver.hpp): anchors are
// fixed at the step's start, relative to the centres of mass, and turned by each body's
// rotation since then, so the separation a constraint sees is measured from the bodies'
// motion in the step (BodyState's delta position and rotation) without touching the
// body pool. The rigid rows are soft constraints: pushed back with the world's joint
// softness in the biased pass, and relaxed without bias after; springs, motors and limits
// are rows of their own that share the bodies' velocities. Each kind has its own file
// (joint_<kind>.cpp) with prepare, warm start, solve and reaction; joint_solver.cpp
// dispatches on the kind with a switch.
#pragma once

#include <cmath>
#include <cstdint>

#include "dynamics/solver/body_state.hpp"
#include "dynamics/joint/joint.hpp"
#include "dynamics/solver/softness.hpp"
#include "math/vec2.hpp"

namespace i2d {

/// How far past the speed limits a joint's pass may leave a body before it counts as
/// running away.
constexpr float joint_runaway_factor = 16.0f;
/// The guard (within_limits) adds the magnitudes of both bodies' velocity components,
/// which come to at most 2 sqrt(2) times the faster body's speed.
constexpr float component_sum_per_speed = 2.0f * 1.41421356f;

/// What every joint's step shares.
struct JointStep {
    float h = 0.0f, inv_h = 0.0f;  // the substep and its inverse
    Softness rigid;                // the rigid rows: the world's joint_hertz and damping ratio
    // Past these a joint's pass runs away: |va.x| + |va.y| + |vb.x| + |vb.y| in m/s and
    // |wa| + |wb| in rad/s, from the speed limits (m/s, rad/s) that no joint may push a
    // body far past.
    float runaway_speed_sum = 0.0f;
    float runaway_spin_sum = 0.0f;

    JointStep() = default;
    JointStep(float substep, float inv_substep, Softness rigid_rows, float max_speed, float max_spin)
        : h(substep),
          inv_h(inv_substep),
          rigid(rigid_rows),
          runaway_speed_sum(component_sum_per_speed * joint_runaway_factor * max_speed),
          runaway_spin_sum(2.0f * joint_runaway_factor * max_spin) {}
};

/// The optional rows a joint has this step (JointConstraint::rows), so that a plain
/// hinge never reads its settings.
enum JointRows : uint8_t { spring_row = 1, motor_row = 2, limit_row = 4 };

struct JointConstraint {
    const JointDef* def = nullptr;
    int32_t joint = null_index;
    JointType type = JointType::filter;
    uint8_t rows = 0;  // JointRows
    uint8_t exact_rows = 0;  // ExactRows (joint_tree.hpp): rows the exact tree solve holds,
                             // which the sweep then leaves alone; set by JointTrees::build
    bool breakable = false;  // a threshold below FLT_MAX (never): store checks the reaction
    int32_t state_a = 0, state_b = 0;  // solver states; the fixed one for a body that cannot move
    bool moves_a = false, moves_b = false;  // whether this joint may change the body's velocity
    float inv_mass_a = 0.0f, inv_mass_b = 0.0f;
    float inv_inertia_a = 0.0f, inv_inertia_b = 0.0f;
    Vec2 anchor_a, anchor_b;  // from each centre of mass, world frame, at the step's start
    Vec2 delta_center;        // centre B - centre A at the step's start (mouse: centre B - target)
    float delta_angle = 0.0f; // angle B - angle A - reference at the step's start, unwound
    Vec2 axis;                // prismatic, wheel: A's axis in the world at the step's start
    float axial_mass = 0.0f;  // effective mass of the kind's axial row
    SpringRow spring;          // the kind's spring (weld: linear; mouse: its pull)
    SpringRow angular_spring;  // weld: angular
    JointImpulses impulses;
};

/// The two bodies' velocities and motion in the step, as one joint sees them.
struct JointBodies {
    Vec2 va, vb;
    float wa = 0.0f, wb = 0.0f;
    Vec2 dpa, dpb;  // delta positions
    Rot dqa, dqb;   // delta rotations
};

inline JointBodies load_bodies(const JointConstraint& c, const BodyState* states) {
    const BodyState& a = states[c.state_a];
    const BodyState& b = states[c.state_b];
    return {a.linear_velocity, b.linear_velocity, a.angular_velocity, b.angular_velocity,
            a.delta_position,  b.delta_position,  a.delta_rotation,   b.delta_rotation};
}

/// Only the sides the joint may move are written: a fixed or kinematic state is shared
/// by many joints of one colour and must stay read-only.
inline void store_bodies(const JointConstraint& c, const JointBodies& j, BodyState* states) {
    if (c.moves_a) {
        states[c.state_a].linear_velocity = j.va;
        states[c.state_a].angular_velocity = j.wa;
    }
    if (c.moves_b) {
        states[c.state_b].linear_velocity = j.vb;
        states[c.state_b].angular_velocity = j.wb;
    }
}

/// How a rigid row acts in this pass: pushed back toward no error with the world's joint
/// softness in the biased pass, and plainly rigid, without bias, when relaxing.
inline Softness rigid_pass(const JointStep& step, bool use_bias) { return use_bias ? step.rigid : Softness{}; }

/// An angle brought into (-pi, pi]: one turn added or taken, enough for what it gets, a
/// difference of two angles in (-pi, pi] (a rotation's, and a reference or target that
/// the C boundary stores wound: wind_angle, trig.hpp), so within (-2 pi, 2 pi).
inline float unwind_angle(float angle) {
    constexpr float pi = 3.14159265f, two_pi = 6.28318531f;
    if (angle <= -pi) {
        return angle + two_pi;
    }
    return angle > pi ? angle - two_pi : angle;
}

/// atan2 within 1e-5 rad, from +, -, *, / only (the same bits everywhere), for the angle
/// rows the solver evaluates every iteration; the exact one (trig.hpp) costs ten times more.
inline float joint_atan2(float y, float x) {
    const float ax = x < 0.0f ? -x : x, ay = y < 0.0f ? -y : y;
    const float big = ax > ay ? ax : ay, small = ax > ay ? ay : ax;
    if (big == 0.0f) {
        return 0.0f;
    }
    const float t = small / big, t2 = t * t;
    // Abramowitz and Stegun 4.4.49 on [0, 1].
    float r = ((((0.0208351f * t2 - 0.0851330f) * t2 + 0.1801410f) * t2 - 0.3302995f) * t2 + 0.9998660f) * t;
    r = ay > ax ? 1.57079633f - r : r;
    r = x < 0.0f ? 3.14159265f - r : r;
    return y < 0.0f ? -r : r;
}

/// The same to within 1 ulp (trig.hpp), for the angles read once per step.
inline float exact_relative_angle(Rot a, Rot b) { return get_angle(inv_mul_rot(a, b)); }

/// The angle that turns a into b, in (-pi, pi].
inline float relative_angle(Rot a, Rot b) {
    return joint_atan2(a.c * b.s - a.s * b.c, a.c * b.c + a.s * b.s);
}

/// The joint angle now: the start's, plus how far B turned relative to A in the step.
inline float current_angle(const JointConstraint& c, const JointBodies& j) {
    return unwind_angle(c.delta_angle + relative_angle(j.dqa, j.dqb));
}

/// Anchor B's offset from anchor A now.
inline Vec2 current_separation(const JointConstraint& c, const JointBodies& j, Vec2 ra, Vec2 rb) {
    return (j.dpb - j.dpa) + c.delta_center + (rb - ra);
}

/// Velocity of anchor B relative to anchor A.
inline Vec2 relative_velocity(const JointBodies& j, Vec2 ra, Vec2 rb) {
    return (j.vb + cross(j.wb, rb)) - (j.va + cross(j.wa, ra));
}

/// Applies a linear impulse P at the anchors: -P on A, +P on B.
inline void apply_linear(const JointConstraint& c, JointBodies& j, Vec2 ra, Vec2 rb, Vec2 p) {
    j.va -= c.inv_mass_a * p;
    j.wa -= c.inv_inertia_a * cross(ra, p);
    j.vb += c.inv_mass_b * p;
    j.wb += c.inv_inertia_b * cross(rb, p);
}

inline void apply_angular(const JointConstraint& c, JointBodies& j, float impulse) {
    j.wa -= c.inv_inertia_a * impulse;
    j.wb += c.inv_inertia_b * impulse;
}

/// The 2x2 effective mass of a point constraint at the anchors.
struct Mat22 {
    Vec2 col1, col2;
};

inline Mat22 point_mass_matrix(const JointConstraint& c, Vec2 ra, Vec2 rb) {
    const float m = c.inv_mass_a + c.inv_mass_b, ia = c.inv_inertia_a, ib = c.inv_inertia_b;
    const float k11 = m + ra.y * ra.y * ia + rb.y * rb.y * ib;
    const float k12 = -ra.y * ra.x * ia - rb.y * rb.x * ib;
    const float k22 = m + ra.x * ra.x * ia + rb.x * rb.x * ib;
    return {{k11, k12}, {k12, k22}};
}

/// x with K x = b; zero when K is singular (both bodies fixed).
inline Vec2 solve22(const Mat22& k, Vec2 b) {
    float det = k.col1.x * k.col2.y - k.col2.x * k.col1.y;
    det = det != 0.0f ? 1.0f / det : 0.0f;
    return {det * (k.col2.y * b.x - k.col2.x * b.y), det * (k.col1.x * b.y - k.col1.y * b.x)};
}

inline float inverse_or_zero(float k) { return k > 0.0f ? 1.0f / k : 0.0f; }

/// One side of a limit on a row with effective mass `mass`: `gap` is how far the row is
/// inside the limit (negative past it), `cdot` the row's speed toward the inside. While
/// inside, the row may approach up to closing the gap within the substep (speculative,
/// so it stops at the limit without bouncing); past it, pushed back like a rigid row.
/// Returns the impulse to apply; `accumulated` never pulls.
inline float limit_impulse(float gap, float cdot, float mass, float& accumulated, const JointStep& step,
                           bool use_bias) {
    float bias = 0.0f, mass_scale = 1.0f, impulse_scale = 0.0f;
    if (gap > 0.0f) {
        bias = gap * step.inv_h;
    } else if (use_bias) {
        bias = step.rigid.bias_rate * gap;
        mass_scale = step.rigid.mass_scale;
        impulse_scale = step.rigid.impulse_scale;
    }
    const float impulse = -mass * mass_scale * (cdot + bias) - impulse_scale * accumulated;
    const float updated = accumulated + impulse > 0.0f ? accumulated + impulse : 0.0f;
    const float applied = updated - accumulated;
    accumulated = updated;
    return applied;
}

/// A motor row: drives `cdot` to `speed` with at most max_impulse accumulated.
inline float motor_impulse(float cdot, float speed, float mass, float max_impulse, float& accumulated) {
    const float wanted = accumulated + mass * (speed - cdot);
    const float clamped = wanted < -max_impulse ? -max_impulse : (wanted > max_impulse ? max_impulse : wanted);
    const float applied = clamped - accumulated;
    accumulated = clamped;
    return applied;
}

/// A spring row toward error 0: `error` is the row's position error, `cdot` its speed.
/// Nothing in the relax pass for a spring that acts once per substep.
inline float spring_impulse(float error, float cdot, float mass, const SpringRow& spring, float& accumulated,
                            bool use_bias) {
    if (!use_bias && !spring.relaxes) {
        return 0.0f;
    }
    const float impulse =
        -mass * (spring.position_rate * error + spring.speed_scale * cdot) - spring.impulse_scale * accumulated;
    accumulated += impulse;
    return impulse;
}

/// Whether the joint left both bodies short of running away (NaN fails). A joint
/// fighting another on one body (two that cannot both hold) drives the velocities and
/// its impulses up without end, doubling within a few passes; a sound joint may pass the
/// speed limits for a pass (integration brings the body back under them) but never by
/// this much, and stopping it there would tear ragdolls landing fast.
/// Sums of magnitudes, not each body's speed: two comparisons instead of four, and no
/// squares, in the pass every joint runs 13 times a step (with the four, joint_grid's
/// step took a tenth longer than with no guard at all; with these, 4 to 6 % longer). A
/// pass the per-body test accepted passes this one.
inline bool within_limits(const JointBodies& j, const JointStep& step) {
    const float speeds = (std::fabs(j.va.x) + std::fabs(j.va.y)) + (std::fabs(j.vb.x) + std::fabs(j.vb.y));
    const float spins = std::fabs(j.wa) + std::fabs(j.wb);
    // Combined without short circuits: one branch per pass.
    return (int(speeds <= step.runaway_speed_sum) & int(spins <= step.runaway_spin_sum)) != 0;
}

/// The same for one body, as the exact tree pass checks its bodies: half of each sum.
inline bool body_within_limits(Vec2 v, float w, const JointStep& step) {
    const float speeds = std::fabs(v.x) + std::fabs(v.y);
    return (int(2.0f * speeds <= step.runaway_speed_sum) & int(2.0f * std::fabs(w) <= step.runaway_spin_sum)) != 0;
}

/// One joint's pass over its bodies' states: load, `pass`, store; a pass that would
/// leave a body running away is undone and the joint gives up its impulses, starting
/// over.
template <class Pass>
inline void guarded_pass(JointConstraint& c, BodyState* states, const JointStep& step, Pass&& pass) {
    JointBodies j = load_bodies(c, states);
    pass(j);
    if (!within_limits(j, step)) {
        j = load_bodies(c, states);  // the states are untouched until store_bodies
        c.impulses = {};
    }
    store_bodies(c, j, states);
}

// The kinds (joint_<kind>.cpp). prepare fills what the kind needs beyond the common
// fields; warm start and solve run one guarded pass (use_bias: the pass that pushes
// errors out).
void prepare_revolute(JointConstraint& c, const JointStep& step);
void warm_start_revolute(JointConstraint& c, BodyState* states, const JointStep& step);
void solve_revolute(JointConstraint& c, BodyState* states, const JointStep& step, bool use_bias);

void prepare_prismatic(JointConstraint& c, const JointStep& step);
void warm_start_prismatic(JointConstraint& c, BodyState* states, const JointStep& step);
void solve_prismatic(JointConstraint& c, BodyState* states, const JointStep& step, bool use_bias);

void prepare_distance(JointConstraint& c, const JointStep& step);
void warm_start_distance(JointConstraint& c, BodyState* states, const JointStep& step);
void solve_distance(JointConstraint& c, BodyState* states, const JointStep& step, bool use_bias);

void prepare_weld(JointConstraint& c, const JointStep& step);
void warm_start_weld(JointConstraint& c, BodyState* states, const JointStep& step);
void solve_weld(JointConstraint& c, BodyState* states, const JointStep& step, bool use_bias);

void prepare_wheel(JointConstraint& c, const JointStep& step);
void warm_start_wheel(JointConstraint& c, BodyState* states, const JointStep& step);
void solve_wheel(JointConstraint& c, BodyState* states, const JointStep& step, bool use_bias);

void prepare_motor(JointConstraint& c, const JointStep& step);
void warm_start_motor(JointConstraint& c, BodyState* states, const JointStep& step);
void solve_motor(JointConstraint& c, BodyState* states, const JointStep& step, bool use_bias);

void prepare_mouse(JointConstraint& c, const JointStep& step);
void warm_start_mouse(JointConstraint& c, BodyState* states, const JointStep& step);
void solve_mouse(JointConstraint& c, BodyState* states, const JointStep& step, bool use_bias);

/// What the joint did to body B in the last substep, as a force and torque (N, N m),
/// and its motor's force or torque, with the bodies where the step left them.
struct JointReaction {
    Vec2 force;
    float torque = 0.0f;
    float motor = 0.0f;
};
JointReaction joint_reaction(const JointConstraint& c, const JointBodies& j, float inv_h);

}  // namespace i2d
