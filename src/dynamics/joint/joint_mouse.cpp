// SPDX-License-Identifier: MIT
// Mouse joint: a damped spring of at most max_force pulls a point of B toward a target
// in the world. Body A plays no part: the solver gives it the fixed state, and the
// joint's start offset is B's centre minus the target (joint_solver.cpp).
#include "dynamics/joint/joint_constraint.hpp"

#include "math/math.hpp"

namespace i2d {

void prepare_mouse(JointConstraint& c, const JointStep& step) {
    const MouseSettings& s = c.def->mouse;
    c.spring = s.hertz > 0.0f ? make_spring(s.hertz, s.damping_ratio, step.h) : SpringRow{};
}

namespace {

void warm_start_mouse_bodies(const JointConstraint& c, JointBodies& j) {
    const Vec2 rb = rotate(j.dqb, c.anchor_b);
    apply_linear(c, j, Vec2{}, rb, c.impulses.linear);
}

void solve_mouse_bodies(JointConstraint& c, JointBodies& j, const JointStep& step, bool use_bias) {
    const MouseSettings& s = c.def->mouse;
    const SpringRow& row = c.spring;
    if (!use_bias && !row.relaxes) {
        return;
    }
    JointImpulses& p = c.impulses;
    const Vec2 rb = rotate(j.dqb, c.anchor_b);
    const Vec2 rate = row.position_rate * current_separation(c, j, Vec2{}, rb) +
                      row.speed_scale * relative_velocity(j, Vec2{}, rb);
    Vec2 wanted = p.linear - solve22(point_mass_matrix(c, Vec2{}, rb), rate) - row.impulse_scale * p.linear;
    const float max_impulse = step.h * s.max_force;
    const float size = length(wanted);
    if (size > max_impulse) {
        wanted = (max_impulse / size) * wanted;
    }
    apply_linear(c, j, Vec2{}, rb, wanted - p.linear);
    p.linear = wanted;
}

}  // namespace

void warm_start_mouse(JointConstraint& c, BodyState* states, const JointStep& step) {
    guarded_pass(c, states, step, [&c](JointBodies& j) { warm_start_mouse_bodies(c, j); });
}

void solve_mouse(JointConstraint& c, BodyState* states, const JointStep& step, bool use_bias) {
    guarded_pass(c, states, step, [&](JointBodies& j) { solve_mouse_bodies(c, j, step, use_bias); });
}

}  // namespace i2d
