// SPDX-License-Identifier: MIT
// Motor joint: drives B's origin to an offset in A's frame and B's angle to an offset
// from A's, removing a share of the error per substep, with at most a force and a torque.
// The joint's anchors are set up for it (joint_solver.cpp): A's is the offset point, B's
// its origin, and the angular offset is its reference angle.
#include "dynamics/joint/joint_constraint.hpp"

#include "math/math.hpp"

namespace i2d {

void prepare_motor(JointConstraint& c, const JointStep&) {
    c.axial_mass = inverse_or_zero(c.inv_inertia_a + c.inv_inertia_b);
}

namespace {

void warm_start_motor_bodies(const JointConstraint& c, JointBodies& j) {
    const Vec2 ra = rotate(j.dqa, c.anchor_a), rb = rotate(j.dqb, c.anchor_b);
    apply_linear(c, j, ra, rb, c.impulses.linear);
    apply_angular(c, j, c.impulses.angular);
}

// Both passes: the correction is the joint's behaviour, not an error to relax away.
void solve_motor_bodies(JointConstraint& c, JointBodies& j, const JointStep& step, bool) {
    const MotorSettings& s = c.def->motor;
    JointImpulses& p = c.impulses;
    const float rate = s.correction_factor * step.inv_h;
    if (c.axial_mass > 0.0f) {
        const float max_impulse = step.h * s.max_torque;
        const float wanted = p.angular - c.axial_mass * (j.wb - j.wa + rate * current_angle(c, j));
        const float clamped = clamp(wanted, -max_impulse, max_impulse);
        apply_angular(c, j, clamped - p.angular);
        p.angular = clamped;
    }
    const Vec2 ra = rotate(j.dqa, c.anchor_a), rb = rotate(j.dqb, c.anchor_b);
    const Vec2 cdot = relative_velocity(j, ra, rb) + rate * current_separation(c, j, ra, rb);
    Vec2 wanted = p.linear - solve22(point_mass_matrix(c, ra, rb), cdot);
    const float max_impulse = step.h * s.max_force;
    const float size = length(wanted);
    if (size > max_impulse) {
        wanted = (max_impulse / size) * wanted;
    }
    apply_linear(c, j, ra, rb, wanted - p.linear);
    p.linear = wanted;
}

}  // namespace

void warm_start_motor(JointConstraint& c, BodyState* states, const JointStep& step) {
    guarded_pass(c, states, step, [&c](JointBodies& j) { warm_start_motor_bodies(c, j); });
}

void solve_motor(JointConstraint& c, BodyState* states, const JointStep& step, bool use_bias) {
    guarded_pass(c, states, step, [&](JointBodies& j) { solve_motor_bodies(c, j, step, use_bias); });
}

}  // namespace i2d
