// SPDX-License-Identifier: MIT
// Weld joint: B's pose held in A's frame by a point row and an angle row, each rigid or
// a spring of its own stiffness.
#include "dynamics/joint/joint_constraint.hpp"
#include "dynamics/joint/joint_tree.hpp"

namespace i2d {

namespace {

// A rigid row pushes its error out only in the biased pass, like every rigid row; a
// spring (hertz > 0) acts as its SpringRow says.
SpringRow weld_row(float hertz, const SpringRow& spring, const JointStep& step, bool use_bias) {
    if (hertz > 0.0f) {
        return spring;
    }
    return as_spring_row(rigid_pass(step, use_bias));
}

}  // namespace

void prepare_weld(JointConstraint& c, const JointStep& step) {
    const WeldSettings& s = c.def->weld;
    c.axial_mass = inverse_or_zero(c.inv_inertia_a + c.inv_inertia_b);
    c.spring = make_spring(s.linear_hertz, s.linear_damping_ratio, step.h);
    c.angular_spring = make_spring(s.angular_hertz, s.angular_damping_ratio, step.h);
}

namespace {

void warm_start_weld_bodies(const JointConstraint& c, JointBodies& j) {
    const Vec2 ra = rotate(j.dqa, c.anchor_a), rb = rotate(j.dqb, c.anchor_b);
    apply_linear(c, j, ra, rb, c.impulses.linear);
    apply_angular(c, j, c.impulses.angular);
}

void solve_weld_bodies(JointConstraint& c, JointBodies& j, const JointStep& step, bool use_bias) {
    const WeldSettings& s = c.def->weld;
    JointImpulses& p = c.impulses;
    if (c.axial_mass > 0.0f && (c.exact_rows & exact_angle_row) == 0) {
        const SpringRow row = weld_row(s.angular_hertz, c.angular_spring, step, use_bias);
        apply_angular(c, j, spring_impulse(current_angle(c, j), j.wb - j.wa, c.axial_mass, row, p.angular, use_bias));
    }
    const SpringRow row = weld_row(s.linear_hertz, c.spring, step, use_bias);
    if ((c.exact_rows & exact_point_rows) || (!use_bias && !row.relaxes)) {
        return;
    }
    const Vec2 ra = rotate(j.dqa, c.anchor_a), rb = rotate(j.dqb, c.anchor_b);
    const Vec2 rate = row.position_rate * current_separation(c, j, ra, rb) +
                      row.speed_scale * relative_velocity(j, ra, rb);
    const Vec2 impulse = -solve22(point_mass_matrix(c, ra, rb), rate) - row.impulse_scale * p.linear;
    p.linear += impulse;
    apply_linear(c, j, ra, rb, impulse);
}

}  // namespace

void warm_start_weld(JointConstraint& c, BodyState* states, const JointStep& step) {
    guarded_pass(c, states, step, [&c](JointBodies& j) { warm_start_weld_bodies(c, j); });
}

void solve_weld(JointConstraint& c, BodyState* states, const JointStep& step, bool use_bias) {
    guarded_pass(c, states, step, [&](JointBodies& j) { solve_weld_bodies(c, j, step, use_bias); });
}

}  // namespace i2d
