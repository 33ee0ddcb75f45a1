// SPDX-License-Identifier: MIT
// Revolute joint: the anchors held together (a rigid 2D point row), plus a spring toward
// a target angle, a motor and a limit on the relative angle (one angular row each).
#include "dynamics/joint/joint_constraint.hpp"
#include "dynamics/joint/joint_tree.hpp"

namespace i2d {

void prepare_revolute(JointConstraint& c, const JointStep& step) {
    const RevoluteSettings& s = c.def->revolute;
    c.axial_mass = inverse_or_zero(c.inv_inertia_a + c.inv_inertia_b);
    c.spring = s.enable_spring ? make_spring(s.hertz, s.damping_ratio, step.h) : SpringRow{};
    const bool turns = c.axial_mass > 0.0f;
    c.rows = uint8_t((s.enable_spring && s.hertz > 0.0f && turns ? spring_row : 0) |
                     (s.enable_motor && turns ? motor_row : 0) | (s.enable_limit && turns ? limit_row : 0));
}

namespace {

void warm_start_revolute_bodies(const JointConstraint& c, JointBodies& j) {
    const JointImpulses& p = c.impulses;
    const Vec2 ra = rotate(j.dqa, c.anchor_a), rb = rotate(j.dqb, c.anchor_b);
    apply_linear(c, j, ra, rb, p.linear);
    apply_angular(c, j, p.spring + p.motor + p.lower - p.upper);
}

// The spring, motor and limit rows, those the joint has.
void solve_revolute_rows(JointConstraint& c, JointBodies& j, const JointStep& step, bool use_bias) {
    const RevoluteSettings& s = c.def->revolute;
    JointImpulses& p = c.impulses;
    // The rows change velocities only: the angle is the same for all of them.
    const float angle = (c.rows & (spring_row | limit_row)) ? current_angle(c, j) : 0.0f;
    if (c.rows & spring_row) {
        const float error = unwind_angle(angle - s.target_angle);
        apply_angular(c, j, spring_impulse(error, j.wb - j.wa, c.axial_mass, c.spring, p.spring, use_bias));
    }
    if (c.rows & motor_row) {
        const float max_impulse = step.h * s.max_motor_torque;
        apply_angular(c, j, motor_impulse(j.wb - j.wa, s.motor_speed, c.axial_mass, max_impulse, p.motor));
    }
    if (c.rows & limit_row) {
        apply_angular(c, j, limit_impulse(angle - s.lower_angle, j.wb - j.wa, c.axial_mass, p.lower, step, use_bias));
        apply_angular(c, j, -limit_impulse(s.upper_angle - angle, j.wa - j.wb, c.axial_mass, p.upper, step, use_bias));
    }
}

void solve_revolute_bodies(JointConstraint& c, JointBodies& j, const JointStep& step, bool use_bias) {
    JointImpulses& p = c.impulses;
    if (c.rows != 0) {
        solve_revolute_rows(c, j, step, use_bias);
    }
    if (c.exact_rows & exact_point_rows) {
        return;  // the tree's exact pass holds it
    }
    // The point row last: it is the one that must hold.
    const Vec2 ra = rotate(j.dqa, c.anchor_a), rb = rotate(j.dqb, c.anchor_b);
    const Softness soft = rigid_pass(step, use_bias);
    const Vec2 bias = use_bias ? soft.bias_rate * current_separation(c, j, ra, rb) : Vec2{};
    const Vec2 b = solve22(point_mass_matrix(c, ra, rb), relative_velocity(j, ra, rb) + bias);
    const Vec2 impulse = -soft.mass_scale * b - soft.impulse_scale * p.linear;
    p.linear += impulse;
    apply_linear(c, j, ra, rb, impulse);
}

}  // namespace

void warm_start_revolute(JointConstraint& c, BodyState* states, const JointStep& step) {
    guarded_pass(c, states, step, [&c](JointBodies& j) { warm_start_revolute_bodies(c, j); });
}

void solve_revolute(JointConstraint& c, BodyState* states, const JointStep& step, bool use_bias) {
    guarded_pass(c, states, step, [&](JointBodies& j) { solve_revolute_bodies(c, j, step, use_bias); });
}

}  // namespace i2d
