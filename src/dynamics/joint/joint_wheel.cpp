// SPDX-License-Identifier: MIT
// Wheel joint: B (the wheel) rides on a spring along an axis of A (the suspension), kept
// on that line by a rigid row, free to turn, with a motor on the turning and limits on
// the travel.
#include "dynamics/joint/joint_slide.hpp"

namespace i2d {

void prepare_wheel(JointConstraint& c, const JointStep& step) {
    const WheelSettings& s = c.def->wheel;
    c.axial_mass = slide_axial_mass(c);
    c.spring = s.enable_spring ? make_spring(s.hertz, s.damping_ratio, step.h) : SpringRow{};
}

namespace {

void warm_start_wheel_bodies(const JointConstraint& c, JointBodies& j) {
    const JointImpulses& p = c.impulses;
    const SlideFrame f = slide_frame(c, j);
    apply_axial(c, j, f, p.axial + p.lower - p.upper);
    apply_perpendicular(c, j, f, p.linear.x);  // the perpendicular row's impulse
    apply_angular(c, j, p.motor);
}

void solve_wheel_bodies(JointConstraint& c, JointBodies& j, const JointStep& step, bool use_bias) {
    const WheelSettings& s = c.def->wheel;
    JointImpulses& p = c.impulses;
    const float turn_mass = inverse_or_zero(c.inv_inertia_a + c.inv_inertia_b);
    if (s.enable_motor && turn_mass > 0.0f) {
        const float max_impulse = step.h * s.max_motor_torque;
        apply_angular(c, j, motor_impulse(j.wb - j.wa, s.motor_speed, turn_mass, max_impulse, p.motor));
    }
    const SlideFrame f = slide_frame(c, j);
    if (s.enable_spring && s.hertz > 0.0f) {
        apply_axial(c, j, f,
                    spring_impulse(f.translation, axial_speed(f, j), c.axial_mass, c.spring, p.axial, use_bias));
    }
    if (s.enable_limit) {
        solve_slide_limits(c, j, f, s.lower_translation, s.upper_translation, step, use_bias);
    }
    // On the line: the perpendicular offset, rigid.
    const float k = c.inv_mass_a + c.inv_mass_b + c.inv_inertia_a * f.s1 * f.s1 + c.inv_inertia_b * f.s2 * f.s2;
    const float cdot = dot(f.perp, j.vb - j.va) + f.s2 * j.wb - f.s1 * j.wa;
    const Softness soft = rigid_pass(step, use_bias);
    const float bias = use_bias ? soft.bias_rate * f.perp_offset : 0.0f;
    const float impulse = -inverse_or_zero(k) * soft.mass_scale * (cdot + bias) - soft.impulse_scale * p.linear.x;
    p.linear.x += impulse;
    apply_perpendicular(c, j, f, impulse);
}

}  // namespace

void warm_start_wheel(JointConstraint& c, BodyState* states, const JointStep& step) {
    guarded_pass(c, states, step, [&c](JointBodies& j) { warm_start_wheel_bodies(c, j); });
}

void solve_wheel(JointConstraint& c, BodyState* states, const JointStep& step, bool use_bias) {
    guarded_pass(c, states, step, [&](JointBodies& j) { solve_wheel_bodies(c, j, step, use_bias); });
}

}  // namespace i2d
