// SPDX-License-Identifier: MIT
// Distance joint: one row along the line between the anchors. Rigid (a rod at its
// length), or a spring toward its length, with a lower and upper limit (a rope is a
// spring of no stiffness with a limit) and a motor that lengthens or shortens it.
#include "dynamics/joint/joint_constraint.hpp"

#include "dynamics/constants.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

// The row's direction and the anchors' arms as they stand.
struct DistanceFrame {
    Vec2 ra, rb, axis;
    float length = 0.0f;
};

DistanceFrame distance_frame(const JointConstraint& c, const JointBodies& j) {
    DistanceFrame f;
    f.ra = rotate(j.dqa, c.anchor_a);
    f.rb = rotate(j.dqb, c.anchor_b);
    const Vec2 d = current_separation(c, j, f.ra, f.rb);
    f.length = length(d);
    // Anchors on top of each other have no direction: keep any, the row is at its length
    // only by accident then and its next push picks one.
    f.axis = f.length > 0.0f ? (1.0f / f.length) * d : Vec2{1.0f, 0.0f};
    return f;
}

float row_speed(const DistanceFrame& f, const JointBodies& j) { return dot(f.axis, relative_velocity(j, f.ra, f.rb)); }

bool is_rigid(const DistanceSettings& s) { return !s.enable_spring || s.min_length == s.max_length; }

}  // namespace

void prepare_distance(JointConstraint& c, const JointStep& step) {
    const DistanceSettings& s = c.def->distance;
    const DistanceFrame f = distance_frame(c, JointBodies{});
    const float cra = cross(f.ra, f.axis), crb = cross(f.rb, f.axis);
    c.axial_mass = inverse_or_zero(c.inv_mass_a + c.inv_mass_b + c.inv_inertia_a * cra * cra +
                                   c.inv_inertia_b * crb * crb);
    c.spring = s.enable_spring ? make_spring(s.hertz, s.damping_ratio, step.h) : SpringRow{};
}

namespace {

void warm_start_distance_bodies(const JointConstraint& c, JointBodies& j) {
    const JointImpulses& p = c.impulses;
    const DistanceFrame f = distance_frame(c, j);
    apply_linear(c, j, f.ra, f.rb, (p.axial + p.motor + p.lower - p.upper) * f.axis);
}

void solve_distance_bodies(JointConstraint& c, JointBodies& j, const JointStep& step, bool use_bias) {
    const DistanceSettings& s = c.def->distance;
    JointImpulses& p = c.impulses;
    const DistanceFrame f = distance_frame(c, j);
    const float rest = clamp(s.length, s.min_length, s.max_length);
    if (is_rigid(s)) {
        const Softness soft = rigid_pass(step, use_bias);
        const float bias = use_bias ? soft.bias_rate * (f.length - rest) : 0.0f;
        const float impulse = -c.axial_mass * soft.mass_scale * (row_speed(f, j) + bias) - soft.impulse_scale * p.axial;
        p.axial += impulse;
        apply_linear(c, j, f.ra, f.rb, impulse * f.axis);
    } else if (s.hertz > 0.0f) {
        const float impulse = spring_impulse(f.length - rest, row_speed(f, j), c.axial_mass, c.spring, p.axial,
                                              use_bias);
        apply_linear(c, j, f.ra, f.rb, impulse * f.axis);
    }
    if (s.enable_motor && !is_rigid(s)) {  // a rod holds its length against any motor
        const float max_impulse = step.h * s.max_motor_force;
        const float impulse = motor_impulse(row_speed(f, j), s.motor_speed, c.axial_mass, max_impulse, p.motor);
        apply_linear(c, j, f.ra, f.rb, impulse * f.axis);
    }
    if (s.enable_limit && !is_rigid(s)) {
        const float lower = limit_impulse(f.length - s.min_length, row_speed(f, j), c.axial_mass, p.lower, step,
                                          use_bias);
        apply_linear(c, j, f.ra, f.rb, lower * f.axis);
        const float upper = limit_impulse(s.max_length - f.length, -row_speed(f, j), c.axial_mass, p.upper, step,
                                          use_bias);
        apply_linear(c, j, f.ra, f.rb, -upper * f.axis);
    }
}

}  // namespace

void warm_start_distance(JointConstraint& c, BodyState* states, const JointStep& step) {
    guarded_pass(c, states, step, [&c](JointBodies& j) { warm_start_distance_bodies(c, j); });
}

void solve_distance(JointConstraint& c, BodyState* states, const JointStep& step, bool use_bias) {
    guarded_pass(c, states, step, [&](JointBodies& j) { solve_distance_bodies(c, j, step, use_bias); });
}

}  // namespace i2d
