// SPDX-License-Identifier: MIT
// ContactSolver: contacts of the soft step (Box2D v3's solver, after Catto's Solver2D).
//
// Every normal impulse is the seed's j = -(vn - vn_target) / K with the full effective
// mass K = invMassA + invMassB + (rA x n)^2 invIA + (rB x n)^2 invIB, clamped so that the
// accumulated impulse never pulls. What changed from the seed is where vn_target comes
// from and when it is applied:
// - Overlap is pushed out by a soft constraint (softness.hpp) instead of moving
//   positions: at most push_max_speed, with no jitter.
// - A gap (a speculative point) allows approach up to closing it within the substep,
//   so that fast bodies stop at the surface instead of passing through.
// - Each substep solves with that push-out, then relaxes (solves again without it), so
//   that the push-out velocity does not become bounce.
// - Restitution is one pass after the substeps, towards -e times the normal speed the
//   pair had at impact: exactly the seed's (1 + e) impulse for an isolated pair.
// Friction is clamped to mu times the normal impulse; rolling resistance clamps a torque
// the same way. Impulses accumulated in one substep warm-start the next, and the last
// ones are kept in the contact (by feature id) to warm-start the next step.
#pragma once

#include <cstdint>
#include <vector>

#include "collision/shapes.hpp"
#include "dynamics/body_state.hpp"
#include "dynamics/softness.hpp"

namespace i2d {

struct ContactConstraintPoint {
    Vec2 anchor_a, anchor_b;         // from each centre of mass to the point, when prepared
    float base_separation = 0.0f;    // separation minus dot(anchor_b - anchor_a, normal)
    float relative_velocity = 0.0f;  // normal speed at impact, for restitution
    float normal_mass = 0.0f, tangent_mass = 0.0f;
    float normal_impulse = 0.0f, tangent_impulse = 0.0f;
    float max_normal_impulse = 0.0f;  // did the point push at all during the step?
    float start_speed = 0.0f;         // normal speed when the step began
};

struct ContactConstraint {
    int32_t contact = 0;
    int32_t state_a = 0, state_b = 0;  // in the state array; fixed bodies share one
    float inv_mass_a = 0.0f, inv_mass_b = 0.0f;
    float inv_inertia_a = 0.0f, inv_inertia_b = 0.0f;
    Vec2 normal;
    float friction = 0.0f, restitution = 0.0f;
    float tangent_speed = 0.0f;       // surface speed, m/s, along left_perp(normal)
    float rolling_resistance = 0.0f;  // torque arm, m: coefficient x radius
    float rolling_mass = 0.0f, rolling_impulse = 0.0f;
    float approach_acceleration = 0.0f;  // m/s^2 along -normal from gravity and forces, >= 0
    Softness softness;
    int32_t point_count = 0;
    ContactConstraintPoint points[2];
};

struct ContactSolverSettings {
    float push_max_speed;
    float restitution_threshold;
};

/// Effective masses and restitution speeds from the states' velocities before the step.
void prepare_contacts(std::vector<ContactConstraint>& constraints, const std::vector<BodyState>& states);
void warm_start_contacts(const std::vector<ContactConstraint>& constraints, std::vector<BodyState>& states);
/// One pass over every contact; use_bias pushes overlap out, without it the pass relaxes.
/// elapsed: time since the step began, s.
void solve_contacts(std::vector<ContactConstraint>& constraints, std::vector<BodyState>& states, float inv_h,
                    const ContactSolverSettings& settings, bool use_bias, float elapsed);
/// Separation of a point where the substeps left the two bodies, m.
float separation_of(const ContactConstraint& c, const ContactConstraintPoint& p, const std::vector<BodyState>& states);
void apply_restitution(std::vector<ContactConstraint>& constraints, std::vector<BodyState>& states,
                       const ContactSolverSettings& settings);

}  // namespace i2d
