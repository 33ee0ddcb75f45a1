// SPDX-License-Identifier: MIT
// Prismatic joint: B slides along an axis fixed in A and keeps its angle to A. The
// perpendicular offset and the angle are one 2x2 rigid block; along the axis there are a
// spring, a motor and a limit, one row each.
#include "dynamics/joint/joint_slide.hpp"

namespace i2d {

namespace {

// impulse.x along the perpendicular, impulse.y about the angle.
void apply_block(const JointConstraint& c, JointBodies& j, const SlideFrame& f, Vec2 impulse) {
    apply_perpendicular(c, j, f, impulse.x);
    apply_angular(c, j, impulse.y);
}

}  // namespace

void prepare_prismatic(JointConstraint& c, const JointStep& step) {
    const PrismaticSettings& s = c.def->prismatic;
    c.axial_mass = slide_axial_mass(c);
    c.spring = s.enable_spring ? make_spring(s.hertz, s.damping_ratio, step.h) : SpringRow{};
}

namespace {

void warm_start_prismatic_bodies(const JointConstraint& c, JointBodies& j) {
    const JointImpulses& p = c.impulses;
    const SlideFrame f = slide_frame(c, j);
    apply_axial(c, j, f, p.axial + p.motor + p.lower - p.upper);
    apply_block(c, j, f, p.linear);
}

void solve_prismatic_bodies(JointConstraint& c, JointBodies& j, const JointStep& step, bool use_bias) {
    const PrismaticSettings& s = c.def->prismatic;
    JointImpulses& p = c.impulses;
    const SlideFrame f = slide_frame(c, j);
    if (s.enable_spring && s.hertz > 0.0f) {
        const float error = f.translation - s.target_translation;
        apply_axial(c, j, f, spring_impulse(error, axial_speed(f, j), c.axial_mass, c.spring, p.axial, use_bias));
    }
    if (s.enable_motor) {
        const float max_impulse = step.h * s.max_motor_force;
        apply_axial(c, j, f, motor_impulse(axial_speed(f, j), s.motor_speed, c.axial_mass, max_impulse, p.motor));
    }
    if (s.enable_limit) {
        solve_slide_limits(c, j, f, s.lower_translation, s.upper_translation, step, use_bias);
    }
    // The perpendicular offset and the angle, together.
    const Vec2 cdot{dot(f.perp, j.vb - j.va) + f.s2 * j.wb - f.s1 * j.wa, j.wb - j.wa};
    const Softness soft = rigid_pass(step, use_bias);
    const Vec2 bias = use_bias ? soft.bias_rate * Vec2{f.perp_offset, current_angle(c, j)} : Vec2{};
    const float ma = c.inv_mass_a, mb = c.inv_mass_b, ia = c.inv_inertia_a, ib = c.inv_inertia_b;
    const float k11 = ma + mb + ia * f.s1 * f.s1 + ib * f.s2 * f.s2;
    const float k12 = ia * f.s1 + ib * f.s2;
    float k22 = ia + ib;
    k22 = k22 > 0.0f ? k22 : 1.0f;  // neither body turns: the angle row is satisfied already
    const Vec2 b = solve22(Mat22{{k11, k12}, {k12, k22}}, cdot + bias);
    const Vec2 impulse = -soft.mass_scale * b - soft.impulse_scale * p.linear;
    p.linear += impulse;
    apply_block(c, j, f, impulse);
}

}  // namespace

void warm_start_prismatic(JointConstraint& c, BodyState* states, const JointStep& step) {
    guarded_pass(c, states, step, [&c](JointBodies& j) { warm_start_prismatic_bodies(c, j); });
}

void solve_prismatic(JointConstraint& c, BodyState* states, const JointStep& step, bool use_bias) {
    guarded_pass(c, states, step, [&](JointBodies& j) { solve_prismatic_bodies(c, j, step, use_bias); });
}

}  // namespace i2d
