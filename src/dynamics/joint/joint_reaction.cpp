// SPDX-License-Identifier: MIT
// The force and torque each kind of joint applied to body B: its accumulated impulses
// of the last substep over the substep, along the directions they act in.
#include "dynamics/joint/joint_slide.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

JointReaction slide_reaction(const JointConstraint& c, const JointBodies& j, float axial, float angular,
                             float motor, float inv_h) {
    const JointImpulses& p = c.impulses;
    const SlideFrame f = slide_frame(c, j);
    return {inv_h * (p.linear.x * f.perp + axial * f.axis), inv_h * angular, inv_h * motor};
}

JointReaction distance_reaction(const JointConstraint& c, const JointBodies& j, float inv_h) {
    const JointImpulses& p = c.impulses;
    const Vec2 ra = rotate(j.dqa, c.anchor_a), rb = rotate(j.dqb, c.anchor_b);
    const Vec2 d = current_separation(c, j, ra, rb);
    const float size = length(d);
    const Vec2 axis = size > 0.0f ? (1.0f / size) * d : Vec2{};
    return {inv_h * (p.axial + p.motor + p.lower - p.upper) * axis, 0.0f, inv_h * p.motor};
}

}  // namespace

JointReaction joint_reaction(const JointConstraint& c, const JointBodies& j, float inv_h) {
    const JointImpulses& p = c.impulses;
    switch (c.type) {
        case JointType::revolute:
            return {inv_h * p.linear, inv_h * (p.spring + p.motor + p.lower - p.upper), inv_h * p.motor};
        case JointType::prismatic:
            return slide_reaction(c, j, p.axial + p.motor + p.lower - p.upper, p.linear.y, p.motor, inv_h);
        case JointType::wheel: return slide_reaction(c, j, p.axial + p.lower - p.upper, p.motor, p.motor, inv_h);
        case JointType::distance: return distance_reaction(c, j, inv_h);
        case JointType::weld:
        case JointType::motor: return {inv_h * p.linear, inv_h * p.angular, 0.0f};
        case JointType::mouse: return {inv_h * p.linear, 0.0f, 0.0f};
        default: return {};
    }
}

}  // namespace i2d
