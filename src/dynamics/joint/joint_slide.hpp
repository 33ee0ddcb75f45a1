// SPDX-License-Identifier: MIT
// SlideFrame: the axis, its perpendicular and their lever arms, shared by the joints
// that slide along an axis of body A (prismatic, wheel).
#pragma once

#include "dynamics/joint/joint_constraint.hpp"

namespace i2d {

// The axis and lever arms as they stand: the axis turns with A, and A's arm reaches to
// B's anchor (d + ra), so that turning A moves the slide.
struct SlideFrame {
    Vec2 axis, perp;
    float translation = 0.0f, perp_offset = 0.0f;
    float a1 = 0.0f, a2 = 0.0f;  // arms of the axial row on A and B
    float s1 = 0.0f, s2 = 0.0f;  // arms of the perpendicular row
};

inline SlideFrame slide_frame(const JointConstraint& c, const JointBodies& j) {
    const Vec2 ra = rotate(j.dqa, c.anchor_a), rb = rotate(j.dqb, c.anchor_b);
    const Vec2 d = current_separation(c, j, ra, rb);
    SlideFrame f;
    f.axis = rotate(j.dqa, c.axis);
    f.perp = {-f.axis.y, f.axis.x};
    f.translation = dot(f.axis, d);
    f.perp_offset = dot(f.perp, d);
    f.a1 = cross(d + ra, f.axis);
    f.a2 = cross(rb, f.axis);
    f.s1 = cross(d + ra, f.perp);
    f.s2 = cross(rb, f.perp);
    return f;
}

inline float axial_speed(const SlideFrame& f, const JointBodies& j) {
    return dot(f.axis, j.vb - j.va) + f.a2 * j.wb - f.a1 * j.wa;
}

inline void apply_axial(const JointConstraint& c, JointBodies& j, const SlideFrame& f, float impulse) {
    j.va -= (c.inv_mass_a * impulse) * f.axis;
    j.wa -= c.inv_inertia_a * impulse * f.a1;
    j.vb += (c.inv_mass_b * impulse) * f.axis;
    j.wb += c.inv_inertia_b * impulse * f.a2;
}

inline void apply_perpendicular(const JointConstraint& c, JointBodies& j, const SlideFrame& f, float impulse) {
    j.va -= (c.inv_mass_a * impulse) * f.perp;
    j.wa -= c.inv_inertia_a * impulse * f.s1;
    j.vb += (c.inv_mass_b * impulse) * f.perp;
    j.wb += c.inv_inertia_b * impulse * f.s2;
}

/// The lower and upper limits on the translation along the axis.
inline void solve_slide_limits(JointConstraint& c, JointBodies& j, const SlideFrame& f, float lower, float upper,
                               const JointStep& step, bool use_bias) {
    JointImpulses& p = c.impulses;
    apply_axial(c, j, f, limit_impulse(f.translation - lower, axial_speed(f, j), c.axial_mass, p.lower, step, use_bias));
    apply_axial(c, j, f,
                -limit_impulse(upper - f.translation, -axial_speed(f, j), c.axial_mass, p.upper, step, use_bias));
}

/// The axial row's effective mass at the step's start.
inline float slide_axial_mass(const JointConstraint& c) {
    const SlideFrame f = slide_frame(c, JointBodies{});
    return inverse_or_zero(c.inv_mass_a + c.inv_mass_b + c.inv_inertia_a * f.a1 * f.a1 +
                           c.inv_inertia_b * f.a2 * f.a2);
}

}  // namespace i2d
