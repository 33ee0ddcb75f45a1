// SPDX-License-Identifier: MIT
// ContactSolver: the seed's impulse resolution as sequential impulses, with angular
// terms, friction, warm starting and the seed's positional correction.
//
// Every normal impulse is the seed's j = -(vn - vn_target) / K with the full effective
// mass K = invMassA + invMassB + (rA x n)^2 invIA + (rB x n)^2 invIB, where vn is the
// relative normal velocity at the contact point and vn_target = -e * vn_before for
// impacts faster than the restitution threshold (else 0): the first pass over an
// isolated contact is exactly j = -(1 + e) vn / K. Iterating over all contacts lets
// impulses travel through stacks; clamping the accumulated normal impulse at zero keeps
// contacts from pulling. Friction is clamped to mu times the normal impulse.
//
// Warm starting: a contact that persists from the previous substep starts from the
// impulses it accumulated there (kept in the contact, matched by feature id) instead of
// zero. Without it, ten iterations leave a 20-box column sinking 1.8 m in 500 steps,
// because Gauss-Seidel needs far more passes than that to carry weight down a chain.
#pragma once

#include <cstdint>
#include <vector>

#include "collision/shapes.hpp"
#include "core/pool.hpp"
#include "dynamics/body.hpp"
#include "dynamics/contact.hpp"

namespace i2d {

struct ContactPointConstraint {
    Vec2 anchor_a, anchor_b;              // from each centre of mass to the point, world frame
    Vec2 local_anchor_a, local_anchor_b;  // the same in each body's frame
    float penetration = 0.0f;             // when the manifold was computed
    float normal_mass = 0.0f, tangent_mass = 0.0f;
    float normal_impulse = 0.0f;  // accumulated over the iterations
    float tangent_impulse = 0.0f;
    float target_normal_speed = 0.0f;  // restitution target, m/s
};

struct ContactConstraint {
    int32_t contact = null_index;  // where the impulses come from and go back to
    int32_t body_a = 0, body_b = 0;
    float inv_mass_a = 0.0f, inv_mass_b = 0.0f;
    float inv_inertia_a = 0.0f, inv_inertia_b = 0.0f;
    Vec2 normal;
    float friction = 0.0f, restitution = 0.0f;
    int32_t point_count = 0;
    ContactPointConstraint points[2];
};

struct SolverSettings {
    float restitution_threshold;
    float contact_slop;
    float correction_percent;
    int32_t velocity_iterations;
};

/// One constraint per touching, non-sensor contact, in contact order, with anchors from
/// the bodies' current centres and the contact's accumulated impulses to start from.
void gather_constraints(const Pool<Contact>& contacts, const Pool<Body>& bodies,
                        std::vector<ContactConstraint>& out);
/// Writes the accumulated impulses back into the contacts for the next substep.
void scatter_impulses(const std::vector<ContactConstraint>& constraints, Pool<Contact>& contacts);

/// Effective masses and restitution targets from the bodies' velocities before solving.
void prepare_contacts(std::vector<ContactConstraint>& constraints, const Pool<Body>& bodies,
                      const SolverSettings& settings);
/// Applies the carried impulses so that the iterations start near the last answer.
void warm_start_contacts(const std::vector<ContactConstraint>& constraints, Pool<Body>& bodies);
void solve_contact_velocities(std::vector<ContactConstraint>& constraints, Pool<Body>& bodies,
                              const SolverSettings& settings);
/// The seed's linear projection, per contact point: pushes the pair apart by a share of
/// the penetration beyond the slop, split by the effective mass (so also turning the
/// bodies). The penetration is the manifold's, updated for how far the anchors moved
/// since, so that the points of one manifold do not correct twice.
void correct_contact_positions(const std::vector<ContactConstraint>& constraints, Pool<Body>& bodies,
                               const SolverSettings& settings);

}  // namespace i2d
