// SPDX-License-Identifier: MIT
// Convex hulls of small point sets and the polygons built from them (boxes included).
#pragma once

#include <cstdint>

#include "collision/shapes.hpp"

namespace i2d {

/// Why a point set gives no usable hull; the C API turns it into a message.
enum class HullStatus : uint8_t {
    ok,
    bad_count,          // fewer than 3 or more than max_polygon_vertices points
    duplicate_points,   // fewer than 3 points remain once points within linear_slop are welded
    collinear_points,   // the points lie within linear_slop of one line
    area_too_small,     // a hull whose area is below linear_slop^2
    count
};

/// A convex hull, counter-clockwise, without collinear or welded points.
struct Hull {
    Vec2 points[max_polygon_vertices];
    int32_t count = 0;
};

/// Computes the hull of 3..8 points. On failure out_hull.count is 0.
HullStatus compute_hull(const Vec2* points, int32_t count, Hull& out_hull);
const char* hull_status_message(HullStatus status);

/// Area-weighted centroid of a CCW polygon outline (2 points give the midpoint).
Vec2 polygon_centroid(const Vec2* vertices, int32_t count);

/// A polygon from a valid hull, rounded by radius >= 0.
Polygon make_polygon(const Hull& hull, float radius);
/// A box centred on the origin, half sizes hx, hy > 0.
Polygon make_box(float hx, float hy);
Polygon make_square(float half_size);
/// A box centred on `center` and turned by `rotation` (body frame).
Polygon make_offset_box(float hx, float hy, Vec2 center, Rot rotation);
/// A capsule or segment as a 2-gon with both side normals, for the polygon clipper.
Polygon make_capsule_polygon(Vec2 p1, Vec2 p2, float radius);

}  // namespace i2d
