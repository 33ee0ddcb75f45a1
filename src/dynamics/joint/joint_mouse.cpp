// SPDX-License-Identifier: MIT
// Mouse joint: a damped spring of at most max_force pulls a point of B toward a target
// in the world. Body A plays no part: the solver gives it the fixed state, and the
// joint's start offset is B's centre minus the target (joint_solver.cpp).
//
// Design note: the spring is k = m (2 pi f)^2 with damping c = 2 m zeta (2 pi f), m the
// mass of B, the same in every direction wherever B is held (Box2D 2.4's mouse joint):
// so B hangs g / (2 pi f)^2 below the target, and a box dragged over a floor of friction
// mu stops within mu g / (2 pi f)^2 of it, wherever it was grabbed. It acts at the anchor
// through the anchor's effective mass K (a 2x2 matrix, rotation included), implicitly in
// the damping (and in the stretch too when the spring is fast for the substep), so it is
// stable at any hertz.
// Alternative rejected (Box2D v3's, and this joint's until issue 43): the soft constraint
// k = K^-1 (2 pi f)^2, the anchor's effective mass for the spring's mass. Held away from
// its centre, a box resting on a floor (which keeps it from turning) felt a spring softer
// than its hertz, by up to 1 / 0.625 for a unit box grabbed at a corner: it stopped up to
// 12.6 % farther from the target than mu g / (2 pi f)^2.
#include "dynamics/joint/joint_constraint.hpp"

#include "math/math.hpp"

namespace i2d {

namespace {

// The largest eigenvalue of the anchor's K times B's mass: how much faster than w the
// spring's stiffest motion is, squared. 1 for an anchor at the centre of mass; a rod
// held at its end swings about it twice as fast as it moves along (4), a small disc held
// far outside itself faster still.
float stiffest_mode_share(const JointConstraint& c) {
    const Mat22 k = point_mass_matrix(c, Vec2{}, c.anchor_b);
    const float half_trace = 0.5f * (k.col1.x + k.col2.y);
    const float half_gap = 0.5f * (k.col1.x - k.col2.y);
    return (half_trace + std::sqrt(half_gap * half_gap + k.col1.y * k.col1.y)) * inverse_or_zero(c.inv_mass_b);
}

}  // namespace

// The mouse's spring row per kilogram of B, over the substep h: position_rate is h w^2
// (the stretch's impulse per metre), speed_scale h 2 zeta w, plus h^2 w^2 when the
// spring's stiffest motion is too fast for the substep (past symplectic_limit) and its
// stretch is taken implicitly too; then it also acts in the relax pass, as make_spring's
// implicit rows do. A spring of 0 Hz keeps the plain row (position_rate 0, speed_scale
// 1): it holds the anchor's velocity at zero.
void prepare_mouse(JointConstraint& c, const JointStep& step) {
    const MouseSettings& s = c.def->mouse;
    if (!(s.hertz > 0.0f)) {
        c.spring = SpringRow{};
        return;
    }
    const float h = step.h;
    const float omega = 2.0f * 3.14159265f * s.hertz;
    const float fastest = h * omega;
    const bool implicit = fastest * fastest * stiffest_mode_share(c) > symplectic_limit * symplectic_limit;
    const float stretch = h * omega * omega;
    c.spring.position_rate = stretch;
    c.spring.speed_scale = h * 2.0f * s.damping_ratio * omega + (implicit ? h * stretch : 0.0f);
    c.spring.impulse_scale = 1.0f;
    c.spring.relaxes = implicit;
}

namespace {

void warm_start_mouse_bodies(const JointConstraint& c, JointBodies& j) {
    const Vec2 rb = rotate(j.dqb, c.anchor_b);
    apply_linear(c, j, Vec2{}, rb, c.impulses.linear);
}

// The impulse P of the substep, with x the anchor's offset from the target, v0 its
// velocity without P and K its effective mass: P = -(h k x + a (v0 + K P)), a = h c (or
// h (c + h k)); with v the velocity now (the accumulated impulse L applied) and P = L + dL,
// (1 + a K) dL = -(h k x + a v + L).
Vec2 spring_change(const JointConstraint& c, const SpringRow& row, Vec2 rb, Vec2 offset, Vec2 speed, Vec2 accumulated) {
    const float mass = inverse_or_zero(c.inv_mass_b);
    const float a = mass * row.speed_scale;
    const Mat22 k = point_mass_matrix(c, Vec2{}, rb);
    const Mat22 lhs{{1.0f + a * k.col1.x, a * k.col1.y}, {a * k.col2.x, 1.0f + a * k.col2.y}};
    const Vec2 rhs = (mass * row.position_rate) * offset + a * speed + accumulated;
    return -solve22(lhs, rhs);
}

void solve_mouse_bodies(JointConstraint& c, JointBodies& j, const JointStep& step, bool use_bias) {
    const MouseSettings& s = c.def->mouse;
    const SpringRow& row = c.spring;
    if (!use_bias && !row.relaxes) {
        return;
    }
    JointImpulses& p = c.impulses;
    const Vec2 rb = rotate(j.dqb, c.anchor_b);
    const Vec2 offset = current_separation(c, j, Vec2{}, rb);
    const Vec2 speed = relative_velocity(j, Vec2{}, rb);
    Vec2 wanted;
    if (s.hertz > 0.0f) {
        wanted = p.linear + spring_change(c, row, rb, offset, speed, p.linear);
    } else {
        wanted = p.linear - solve22(point_mass_matrix(c, Vec2{}, rb), row.speed_scale * speed);
    }
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
