// SPDX-License-Identifier: MIT
// ShapeProxy: a convex shape as the hull of up to 8 core points and a rounding radius,
// the form that distance, shape casts and time of impact work on (Box2D's b2ShapeProxy).
#pragma once

#include <cstdint>

#include "collision/shapes.hpp"

namespace i2d {

struct ShapeProxy {
    Vec2 points[max_polygon_vertices];  // convex outline of the core, counter-clockwise
    int32_t count = 0;                  // 1 (a disc), 2 (a capsule or segment), 3..8
    float radius = 0.0f;                // m, around the core
};

/// The proxy of a shape in its body frame.
ShapeProxy make_shape_proxy(const Geometry& g);

/// A proxy from 1 to 8 finite points (any order) and a radius >= 0: their convex hull,
/// counter-clockwise; points that lie along a line (or within linear_slop of one
/// another) give a segment (or a point).
ShapeProxy make_query_proxy(const Vec2* points, int32_t count, float radius);

/// The proxy's bounds, radius included.
AABB proxy_aabb(const ShapeProxy& proxy);

/// The proxy's core points placed by xf.
ShapeProxy transformed(const ShapeProxy& proxy, const Transform& xf);

/// Closest points of two proxies' cores (radii not subtracted), in world space.
struct ProxyDistance {
    float distance = 0.0f;  // between the cores, m; 0 when they overlap
    Vec2 normal;            // unit, from A towards B (arbitrary when they overlap)
    Vec2 point_a, point_b;  // closest core points
};

/// Exact distance between two world-space cores by testing every vertex against every
/// edge: O(n m), at most 128 point-segment tests for two octagons, no iteration to
/// converge (a GJK would be faster on large counts, which 8 vertices never reach).
ProxyDistance core_distance(const ShapeProxy& a, const ShapeProxy& b);

/// Closest points of two proxies' surfaces (cores grown by their radii), each placed by
/// its transform (Box2D's b2ShapeDistance with radii).
struct SurfaceDistance {
    Vec2 point_a, point_b;  // world; the same point when the shapes overlap (see the .cpp)
    Vec2 normal;            // unit, from A towards B; zero when the shapes overlap
    float distance = 0.0f;  // between the surfaces, m; 0 when they touch or overlap
};
SurfaceDistance surface_distance(const ShapeProxy& a, const Transform& xa, const ShapeProxy& b, const Transform& xb);

/// The point of the proxy (placed by xf, radius included) closest to target: target
/// itself when the proxy holds it.
Vec2 closest_point(const ShapeProxy& proxy, const Transform& xf, Vec2 target);

}  // namespace i2d
