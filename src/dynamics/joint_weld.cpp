// SPDX-License-Identifier: MIT
// Weld joint: B's pose held in A's frame by a point row and an angle row, each rigid or
// a spring of its own stiffness.
#include "dynamics/joint_constraint.hpp"

namespace i2d {

void prepare_weld(JointConstraint& c, const JointStep& step) {
    const WeldSettings& s = c.def->weld;
    c.axial_mass = inverse_or_zero(c.inv_inertia_a + c.inv_inertia_b);
    c.spring = s.linear_hertz > 0.0f ? make_softness(s.linear_hertz, s.linear_damping_ratio, step.h) : step.rigid;
    c.angular_spring =
        s.angular_hertz > 0.0f ? make_softness(s.angular_hertz, s.angular_damping_ratio, step.h) : step.rigid;
}

void warm_start_weld(const JointConstraint& c, JointBodies& j) {
    const Vec2 ra = rotate(j.dqa, c.anchor_a), rb = rotate(j.dqb, c.anchor_b);
    apply_linear(c, j, ra, rb, c.impulses.linear);
    apply_angular(c, j, c.impulses.angular);
}

// A spring acts in both passes (it is the joint's behaviour); a rigid row pushes its
// error out only in the biased pass, like every rigid row.
void solve_weld(JointConstraint& c, JointBodies& j, const JointStep&, bool use_bias) {
    const WeldSettings& s = c.def->weld;
    JointImpulses& p = c.impulses;
    if (c.axial_mass > 0.0f) {
        const bool pushes = use_bias || s.angular_hertz > 0.0f;
        const Softness soft = pushes ? c.angular_spring : Softness{};
        const float error = pushes ? current_angle(c, j) : 0.0f;
        apply_angular(c, j, spring_impulse(error, j.wb - j.wa, c.axial_mass, soft, p.angular));
    }
    const Vec2 ra = rotate(j.dqa, c.anchor_a), rb = rotate(j.dqb, c.anchor_b);
    const bool pushes = use_bias || s.linear_hertz > 0.0f;
    const Softness soft = pushes ? c.spring : Softness{};
    const Vec2 bias = pushes ? soft.bias_rate * current_separation(c, j, ra, rb) : Vec2{};
    const Vec2 b = solve22(point_mass_matrix(c, ra, rb), relative_velocity(j, ra, rb) + bias);
    const Vec2 impulse = -soft.mass_scale * b - soft.impulse_scale * p.linear;
    p.linear += impulse;
    apply_linear(c, j, ra, rb, impulse);
}

}  // namespace i2d
