// SPDX-License-Identifier: MIT
// The impulse of one impact, solved at once where the continuous stage stopped a fast body;
// and of several contacts' impacts together, for the chains of impacts within a step
// (impact_chain.hpp).
//
// Design note: the continuous stage moves a fast body back to where its sweep first met
// something. It used to keep the body's velocity and leave the impact to the next step's
// speculative contact (Box2D v3's scheme). That contact measures its separation within
// the step by turning its anchors with the bodies: a spinning ball's anchor turns away
// from the wall (up to its diameter in a step at the quarter turn per substep the
// integrator allows), the contact sees a gap that is not there, and its relax pass lets
// the ball keep up to gap / substep of its speed into the wall. The ball then slides
// along the wall still pushing into it and leaves its end drifting sideways. So the
// impact is solved where it happens instead: the manifold at the time of impact, and on
// its touching points the velocity change a rigid contact would make (no approach left,
// or -restitution times the approach above the restitution threshold; Coulomb friction
// bounded by friction times the normal impulse). The next step's contact then starts from
// no approach, and whatever it sees, its relax can only give back what it pushed.
//
// Alternative rejected: measuring a round shape's separation from its core (its centre
// for a circle), which does not turn away. It is exact but costs every contact point of
// every substep a second pair of anchors, for an error that matters only to fast spins.
#pragma once

#include <cstdint>

#include "collision/shapes.hpp"
#include "math/vec2.hpp"

namespace i2d {

/// A body as the impact sees it: its centre of mass at the time of impact, its velocities
/// (changed in place) and inverse mass (0 for a body the impact cannot move).
struct ImpactBody {
    Vec2 center;
    Vec2 linear_velocity;
    float angular_velocity = 0.0f;
    float inv_mass = 0.0f, inv_inertia = 0.0f;
};

/// The pair's mixed material and the world's thresholds.
struct ImpactMaterial {
    float friction = 0.0f;
    float restitution = 0.0f;
    float restitution_threshold = 0.0f;  // m/s: slower approaches do not bounce
    float tangent_speed = 0.0f;          // m/s: the surfaces' own sliding speed (conveyors)
};

/// What the impact did: the fastest approach among the points that took part (m/s, > 0
/// when they approached) and where it was; point_index is -1 when no point took part.
struct ImpactResult {
    float approach_speed = 0.0f;
    int32_t point_index = -1;
};

/// Solves the impact of B on A over the manifold's points (normal from A to B) whose
/// separation is at most `touching` (m): the ones that touch where the sweep stopped.
ImpactResult resolve_impact(const Manifold& manifold, float touching, const ImpactMaterial& material, ImpactBody& a,
                            ImpactBody& b);

/// The most contacts one simultaneous impact solves together.
constexpr int32_t max_simultaneous_impacts = 8;
/// Sweeps over a simultaneous impact's contacts: a ball struck at two points converges
/// by the square of their coupling each sweep (1/16 for a rack's apex), so 32 leave
/// nothing of it in float.
constexpr int32_t simultaneous_impact_iterations = 32;

/// One contact of a simultaneous impact: all its manifold's points take part.
struct ImpactContact {
    Manifold manifold;  // normal from A to B
    ImpactMaterial material;
    int32_t body_a, body_b;  // in the bodies array
};

/// Solves several contacts' impacts together (count at most max_simultaneous_impacts), the
/// bodies' velocities changed in place; one result per contact.
void resolve_impacts(const ImpactContact* contacts, int32_t count, ImpactBody* bodies, ImpactResult* results);

}  // namespace i2d
