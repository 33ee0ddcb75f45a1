// SPDX-License-Identifier: MIT
// Contact manifolds for every pair of shape kinds, and the table that picks one per pair.
//
// Shapes are given in their body frame and placed by a transform. Every function returns
// world points midway between the surfaces, a unit normal from A to B, and includes
// speculative points whose separation is within `speculative` (penetration down to
// -speculative), m, >= 0, by default speculative_distance. A solver that collides once
// per step passes a margin grown by the approach speed, so that a fast body gets its
// point before it tunnels. The margin only decides which points are kept: a larger one
// adds farther points (the far end of a tilted incident edge) and leaves the normal, the
// reference face and the other points bit for bit, except within 0.01 slop of the
// margin's edge, where a clip whose points were all too far gives way to one closest
// point. Segment against segment never collides. The functions of shapes with corners
// or cores also take `slop`, the length their tie-breaks are measured in (which face is
// the reference, when a clip is as close as the closest points), m, by default
// linear_slop: a world passes its own, scaled to its length unit with the margin, so
// that a scene in other units gets the same manifolds, scaled.
#pragma once

#include "collision/shapes.hpp"

namespace i2d {

// World-space tests of the seed's part 1, kept for the public i2d_collide_circles/aabbs/
// aabb_circle: touching counts as contact (penetration 0), no speculative points.
Manifold collide_circles(Vec2 center_a, float radius_a, Vec2 center_b, float radius_b);
Manifold collide_aabbs(const AABB& a, const AABB& b);
Manifold collide_aabb_circle(const AABB& a, Vec2 center_b, float radius_b);

// One function per pair of kinds in its primary order (Box2D's set).
Manifold collide_circles(const Circle& a, const Transform& xf_a, const Circle& b, const Transform& xf_b,
                         float speculative = speculative_distance);
Manifold collide_capsule_circle(const Capsule& a, const Transform& xf_a, const Circle& b, const Transform& xf_b,
                                float speculative = speculative_distance);
Manifold collide_segment_circle(const Segment& a, const Transform& xf_a, const Circle& b, const Transform& xf_b,
                                float speculative = speculative_distance);
Manifold collide_polygon_circle(const Polygon& a, const Transform& xf_a, const Circle& b, const Transform& xf_b,
                                float speculative = speculative_distance);
Manifold collide_capsules(const Capsule& a, const Transform& xf_a, const Capsule& b, const Transform& xf_b,
                          float speculative = speculative_distance, float slop = linear_slop);
Manifold collide_segment_capsule(const Segment& a, const Transform& xf_a, const Capsule& b, const Transform& xf_b,
                                 float speculative = speculative_distance, float slop = linear_slop);
Manifold collide_polygon_capsule(const Polygon& a, const Transform& xf_a, const Capsule& b, const Transform& xf_b,
                                 float speculative = speculative_distance, float slop = linear_slop);
Manifold collide_segment_polygon(const Segment& a, const Transform& xf_a, const Polygon& b, const Transform& xf_b,
                                 float speculative = speculative_distance, float slop = linear_slop);
/// Polygons with 2 to 8 vertices (a 2-gon is a capsule's or segment's core).
Manifold collide_polygons(const Polygon& a, const Transform& xf_a, const Polygon& b, const Transform& xf_b,
                          float speculative = speculative_distance, float slop = linear_slop);

/// Chain segments (manifold_chain.cpp): one-sided, and no contact at a seam with a normal
/// that the neighbouring segment's face covers. `held`: the shape touched the free side
/// before; pushed behind the segment since, it gets a contact on the face that pushes it
/// back instead of none.
Manifold collide_chain_segment_circle(const ChainSegment& a, const Transform& xf_a, const Circle& b,
                                      const Transform& xf_b, float speculative = speculative_distance,
                                      bool held = false);
Manifold collide_chain_segment_capsule(const ChainSegment& a, const Transform& xf_a, const Capsule& b,
                                       const Transform& xf_b, float speculative = speculative_distance,
                                       bool held = false, float slop = linear_slop);
Manifold collide_chain_segment_polygon(const ChainSegment& a, const Transform& xf_a, const Polygon& b,
                                       const Transform& xf_b, float speculative = speculative_distance,
                                       bool held = false, float slop = linear_slop);
/// A chain segment (either side, A or B) and a shape it holds, as collide_shapes orders
/// them: the normal from A to B.
Manifold collide_held_by_chain(const Geometry& a, const Transform& xf_a, const Geometry& b, const Transform& xf_b,
                               float speculative = speculative_distance, float slop = linear_slop);

/// A pair of shapes of any kinds, through the pair table; the reversed order of a
/// primary pair is computed as (B, A) with the normal flipped.
Manifold collide_shapes(const Geometry& a, const Transform& xf_a, const Geometry& b, const Transform& xf_b,
                        float speculative = speculative_distance, float slop = linear_slop);

// ---- Shared by the manifold sources -------------------------------------------------

/// Feature key of a contact point: the reference feature and the incident feature, and
/// whether B gave the reference face, so keys from A-faces and B-faces never collide.
inline uint32_t make_feature_id(int32_t reference, int32_t incident, bool flip = false) {
    return (flip ? 1u << 16 : 0u) | (static_cast<uint32_t>(reference) & 0xffu) << 8 |
           (static_cast<uint32_t>(incident) & 0xffu);
}

/// Moves a manifold computed in `frame` (points and normal local to it) to world space.
inline Manifold to_world(Manifold m, const Transform& frame) {
    m.normal = rotate(frame.q, m.normal);
    for (int32_t i = 0; i < m.point_count; ++i) {
        m.points[i].point = transform_point(frame, m.points[i].point);
    }
    return m;
}

/// One contact point between a point on A's core and one on B's core, `distance` apart
/// along the unit normal, each surface `radius_*` out from its core.
inline Manifold single_contact(Vec2 core_a, Vec2 core_b, Vec2 normal, float distance, float radius_a,
                               float radius_b, uint32_t id) {
    Manifold m;
    m.normal = normal;
    m.point_count = 1;
    const Vec2 surface_a = core_a + radius_a * normal;
    const Vec2 surface_b = core_b - radius_b * normal;
    m.points[0].point = 0.5f * (surface_a + surface_b);
    m.points[0].penetration = radius_a + radius_b - distance;
    m.points[0].id = id;
    return m;
}

}  // namespace i2d
