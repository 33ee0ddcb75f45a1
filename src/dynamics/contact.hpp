// SPDX-License-Identifier: MIT
// Contact: one per pair of shapes whose fat boxes overlap, kept from step to step.
//
// Design note: contacts live in a pool and are found by shape pair through a hash set of
// pair keys (the world's), so that the broadphase can skip known pairs in O(1). Each
// body links its contacts through two edges per contact (index links, Box2D's contact
// edges), so destroying a body or shape finds its contacts without a scan. The manifold
// carries the accumulated impulses of each point, matched by feature id when the
// manifold is updated, which is what warm starting feeds on. A contact is in the world's
// awake set while one of its bodies is awake; contacts among sleeping and static bodies
// are left out, so that a sleeping pile costs nothing.
#pragma once

#include <cstdint>

#include "collision/shapes.hpp"
#include "core/pool.hpp"

namespace i2d {

enum ContactFlags : uint32_t {
    contact_touching = 1u << 0,       // within the contact slop when the last step ended
    contact_sensor = 1u << 1,         // one shape is a sensor: overlap only, never solved
    contact_report_events = 1u << 2,  // both shapes enable contact events (or, for a
                                      // sensor contact, the visitor enables sensor events)
    contact_touching_at_start = 1u << 3,  // touching when the step began
    contact_disjoint = 1u << 4,           // fat boxes apart: destroyed at the end of the step
};

/// A contact's link in one of its bodies' contact lists; keys are (contact << 1) | edge.
struct ContactEdge {
    int32_t body = null_index;
    int32_t prev_key = null_index;
    int32_t next_key = null_index;
};

struct ContactImpulse {
    float normal = 0.0f;
    float tangent = 0.0f;
};

struct Contact {
    int32_t shape_a = null_index, shape_b = null_index;  // shape_a < shape_b
    ContactEdge edges[2];                                // [0] body of A, [1] body of B
    Manifold manifold;
    ContactImpulse impulses[2];                          // per manifold point
    float rolling_impulse = 0.0f;
    // Material, mixed from the shapes' at every narrowphase update so that changing a
    // shape's friction or restitution takes effect on contacts it already has.
    float friction = 0.0f, restitution = 0.0f;
    float rolling_resistance = 0.0f;  // torque arm, m
    float tangent_speed = 0.0f;       // m/s along left_perp(manifold normal)
    uint32_t flags = 0;
    int32_t awake_index = null_index;  // in the world's awake contact set, if there
};

/// Replaces the manifold and carries each point's impulses over from the old point with
/// the same feature id (new points start from zero).
void update_manifold(Contact& contact, const Manifold& fresh);

}  // namespace i2d
