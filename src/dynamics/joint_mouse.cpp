// SPDX-License-Identifier: MIT
// Mouse joint: a damped spring of at most max_force pulls a point of B toward a target
// in the world. Body A plays no part: the solver gives it the fixed state, and the
// joint's start offset is B's centre minus the target (joint_solver.cpp).
#include "dynamics/joint_constraint.hpp"

#include "math/math.hpp"

namespace i2d {

void prepare_mouse(JointConstraint& c, const JointStep& step) {
    const MouseSettings& s = c.def->mouse;
    c.spring = make_softness(s.hertz, s.damping_ratio, step.h);
}

void warm_start_mouse(const JointConstraint& c, JointBodies& j) {
    const Vec2 rb = rotate(j.dqb, c.anchor_b);
    apply_linear(c, j, Vec2{}, rb, c.impulses.linear);
}

// Both passes: the spring is the joint's behaviour.
void solve_mouse(JointConstraint& c, JointBodies& j, const JointStep& step, bool) {
    const MouseSettings& s = c.def->mouse;
    JointImpulses& p = c.impulses;
    const Vec2 rb = rotate(j.dqb, c.anchor_b);
    const Vec2 error = current_separation(c, j, Vec2{}, rb);
    const Vec2 cdot = relative_velocity(j, Vec2{}, rb) + c.spring.bias_rate * error;
    const Vec2 rigid = solve22(point_mass_matrix(c, Vec2{}, rb), cdot);
    Vec2 wanted = p.linear - c.spring.mass_scale * rigid - c.spring.impulse_scale * p.linear;
    const float max_impulse = step.h * s.max_force;
    const float size = length(wanted);
    if (size > max_impulse) {
        wanted = (max_impulse / size) * wanted;
    }
    apply_linear(c, j, Vec2{}, rb, wanted - p.linear);
    p.linear = wanted;
}

}  // namespace i2d
