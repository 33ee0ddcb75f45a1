// SPDX-License-Identifier: MIT
// Contact: one per pair of shapes whose fat boxes overlap, kept from step to step.
//
// Design note: contacts live in the contact set's pool and are found by shape pair
// through its hash set of pair keys, so that the broadphase can skip known pairs in
// O(1). Each body links its contacts through two edges per contact (index links, Box2D's
// contact edges), so destroying a body or shape finds its contacts without a scan. A
// contact's points keep their anchors on the two bodies (from each centre of mass, in
// world orientation, when the manifold was made) and the accumulated impulses, matched
// by feature id when the manifold is remade, which is what warm starting feeds on. The
// narrowphase also caches what the solver needs of the bodies (their places in the
// solver's state array, whether the contact can move them), so that colouring and
// preparing constraints read the contact and nothing else.
#pragma once

#include <cstddef>
#include <cstdint>

#include "collision/shapes.hpp"
#include "dynamics/body/body.hpp"
#include "core/pool.hpp"

namespace i2d {

enum ContactFlags : uint32_t {
    contact_touching = 1u << 0,       // within the contact slop when the last step ended
    contact_sensor = 1u << 1,         // one shape is a sensor: overlap only, never solved
    contact_report_events = 1u << 2,  // both shapes enable contact events (or, for a
                                      // sensor contact, the visitor enables sensor events)
    contact_touching_at_start = 1u << 3,  // touching when the step began
    contact_disjoint = 1u << 4,           // fat boxes apart: destroyed at the end of the step
    contact_island_link = 1u << 5,        // joins its two bodies' islands (solid, has points,
                                          // both bodies dynamic)
    contact_moves_a = 1u << 6,            // the solver may move body A (dynamic and awake)
    contact_moves_b = 1u << 7,
    contact_recyclable = 1u << 8,         // the poses below are those the manifold was made at
    contact_hit_events = 1u << 9,         // either shape enables hit events
    contact_held_by_chain = 1u << 10,     // a chain segment's contact that had points at the
                                          // last manifold: the segment holds the shape from its
                                          // free side, even once pushed behind it
    contact_pre_solve = 1u << 11,         // either shape enables pre-solve events
};

/// A contact's link in one of its bodies' contact lists; keys are (contact << 1) | edge.
struct ContactEdge {
    int32_t body = null_index;
    int32_t prev_key = null_index;
    int32_t next_key = null_index;
};

inline int32_t contact_of_key(int32_t key) { return key >> 1; }
inline int32_t edge_of_key(int32_t key) { return key & 1; }

/// What the solver reads and writes of a point every step.
struct ContactPoint {
    Vec2 anchor_a, anchor_b;      // from each centre of mass to the point, m, world orientation
    float separation = 0.0f;      // m, negative when overlapping, at the start of the step
    float normal_impulse = 0.0f;  // accumulated, N s
    float tangent_impulse = 0.0f;
};

/// A contact's layout follows who reads it: what the solver packs and stores every step
/// fills the first two cache lines, which are all it asks for ahead; what only the
/// narrowphase and the bookkeeping read follows.
struct alignas(64) Contact {
    // Solver data.
    Vec2 normal;  // unit, from A to B
    int32_t point_count = 0;
    uint32_t flags = 0;
    // The bodies' places in the solver's state array this step (null when fixed).
    int32_t state_a = null_index, state_b = null_index;
    float rolling_impulse = 0.0f;
    // Material, mixed from the shapes' when the contact is made and when they change.
    float friction = 0.0f, restitution = 0.0f;
    float rolling_resistance = 0.0f;  // torque arm, m
    float tangent_speed = 0.0f;       // m/s along left_perp(normal)
    int32_t awake_index = null_index;  // in the awake contact list, if there
    // Hit events: the fastest impact the solver pushed against this step, m/s (0: none),
    // and the point it was at. In the first line with the flags: the end of the step
    // reads both for every awake contact.
    float hit_speed = 0.0f;
    int32_t hit_point = 0;
    ContactPoint points[2];
    // Narrowphase and bookkeeping.
    int32_t shape_a = null_index, shape_b = null_index;  // shape_a < shape_b
    ContactEdge edges[2];                                // [0] body of A, [1] body of B
    uint32_t point_ids[2] = {};  // feature keys, stable while the same features touch
    // Separation minus dot(centre offset + anchor_b - anchor_a, normal) when the manifold
    // was made, m: what recycling adds the bodies' motion to.
    float base_separations[2] = {};
    // The bodies' rotations and B's pose seen from A when the manifold was made.
    Rot made_rotation_a, made_rotation_b;
    Transform made_relative_pose;
};

static_assert(offsetof(Contact, points) + sizeof(ContactPoint[2]) <= 128, "solver data in two cache lines");
static_assert(offsetof(Contact, hit_point) + sizeof(int32_t) <= 64, "the end of the step reads one line");

/// A touching contact as a caller reads it between steps (contact_data.cpp): what the
/// C API's i2d_contact_data holds, with shapes as pool indices.
struct ContactData {
    int32_t shape_a = null_index, shape_b = null_index;  // shape_a < shape_b
    Manifold manifold;  // world points, normal from A to B, as a begin event shows it
    float normal_impulses[2] = {};   // accumulated in the last substep, N s
    float tangent_impulses[2] = {};
};

/// A contact between solid shapes: no sensor among them.
inline bool is_solid(const Contact& c) { return (c.flags & contact_sensor) == 0; }

/// What the solver takes: a contact between solid shapes with points.
inline bool is_solvable(const Contact& c) { return is_solid(c) && c.point_count > 0; }

/// Sets the contact's solver state on one side (0: A, 1: B) from its body: the body's
/// awake index, and whether the solver moves it (dynamic and awake). Returns whether
/// anything the colouring reads changed.
inline bool set_solver_state(Contact& c, int32_t edge, const Body& b) {
    int32_t& state = edge == 0 ? c.state_a : c.state_b;
    const uint32_t flag = edge == 0 ? contact_moves_a : contact_moves_b;
    const bool moves = b.type == BodyType::dynamic && b.awake_index != null_index;
    const uint32_t flags = (c.flags & ~flag) | (moves ? flag : 0u);
    const bool changed = state != b.awake_index || flags != c.flags;
    state = b.awake_index;
    c.flags = flags;
    return changed;
}

/// Replaces the contact's points by those of a fresh world-space manifold, anchored at the
/// bodies' centres of mass, and carries each point's impulses over from the old point
/// with the same feature id (new points start from zero).
void update_points(Contact& contact, const Manifold& fresh, Vec2 center_a, Vec2 center_b);

/// Contact recycling (after Box2D v3's): while two bodies barely moved relative to each
/// other since the manifold was made, the manifold is kept, its anchors ride the bodies
/// and only the separations follow their motion, the way the substeps measure it. This
/// saves the narrowphase for resting stacks. The margin bounds how far the kept points
/// may be from the manifold the narrowphase would make now.
struct RecycleLimits {
    float touching_distance;  // m: relative travel of the farthest point, touching before
    float apart_distance;     // m: the same for contacts that were not touching
    float min_cos;            // cosine of the largest turn of either body
};

/// Remembers the bodies' poses and centres of mass a fresh manifold was made at.
void remember_poses(Contact& contact, const Transform& xf_a, Vec2 center_a, const Transform& xf_b, Vec2 center_b);
/// Keeps the manifold if the bodies moved within the limits since it was made, updating
/// the separations; returns false (changing nothing) when a fresh manifold is needed.
/// extent: the farthest shape point of either moving body from its centre of mass, m.
bool recycle_manifold(Contact& contact, const Transform& xf_a, Vec2 center_a, const Transform& xf_b, Vec2 center_b,
                      float extent, const RecycleLimits& limits);

}  // namespace i2d
