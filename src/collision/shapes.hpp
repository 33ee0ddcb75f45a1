// SPDX-License-Identifier: MIT
// Shape geometry (circle, capsule, segment, polygon), mass data and the contact manifold.
//
// Design note: Geometry is a tagged struct with one member per kind rather than a union
// or a class hierarchy. It stays a plain copyable value (the world keeps it inline in
// Shape), and the dispatch is a switch or a table, never a virtual call. The cost is a
// few unused bytes per shape, which is small next to a polygon's 8 vertices.
#pragma once

#include <cstdint>

#include "collision/collision_constants.hpp"
#include "math/vec2.hpp"

namespace i2d {

/// The order matters: pair tables and the public i2d_shape_type follow it.
enum class ShapeType : uint8_t { circle, capsule, segment, polygon, chain_segment, count };

struct Circle {
    Vec2 center;  // body frame
    float radius = 0.0f;
};

/// Two half discs joined by a rectangle: every point within radius of the segment
/// center1-center2.
struct Capsule {
    Vec2 center1, center2;
    float radius = 0.0f;
};

/// A two-sided line segment with no thickness and no mass (static geometry).
struct Segment {
    Vec2 point1, point2;
};

/// One segment of a chain (chain.hpp): one-sided, solid from the right of point1 ->
/// point2 (where right_perp points), with the chain's neighbouring points as ghosts so
/// that contacts at its ends take the neighbours into account and nothing catches on a
/// seam. No mass.
struct ChainSegment {
    Vec2 ghost1;  // the point before point1 in the chain
    Vec2 point1, point2;
    Vec2 ghost2;  // the point after point2
};

/// A convex polygon, counter-clockwise, with outward unit edge normals: normals[i] is the
/// normal of the edge from vertices[i] to vertices[i + 1]. A radius > 0 rounds it: the
/// shape is every point within radius of the polygon. Build it with make_polygon or
/// make_box so that the invariants hold.
struct Polygon {
    Vec2 vertices[max_polygon_vertices];
    Vec2 normals[max_polygon_vertices];
    Vec2 centroid;
    float radius = 0.0f;
    int32_t count = 0;
};

/// Geometry of one shape; which member is meaningful follows the ShapeType.
struct Geometry {
    ShapeType type = ShapeType::circle;
    Circle circle;
    Capsule capsule;
    Segment segment;
    Polygon polygon;
    ChainSegment chain_segment;
};

struct ManifoldPoint {
    Vec2 point;                // world, midway between the surfaces
    float penetration = 0.0f;  // > 0 overlapping, 0 touching, down to minus the speculative margin
    uint32_t id = 0;           // feature key, stable while the same features touch
};

struct Manifold {
    Vec2 normal;  // unit, from A to B
    int32_t point_count = 0;
    ManifoldPoint points[2];
};

struct MassData {
    float mass = 0.0f;
    Vec2 center;                     // centroid in the body frame
    float rotational_inertia = 0.0f; // about the centroid, kg m^2
};

}  // namespace i2d
