// SPDX-License-Identifier: MIT
// Closest points between segments and distances between small convex point sets.
#pragma once

#include <cstdint>

#include "math/vec2.hpp"

namespace i2d {

struct SegmentDistance {
    Vec2 closest1, closest2;
    float fraction1 = 0.0f, fraction2 = 0.0f;  // exactly 0 or 1 at an endpoint
    float distance_squared = 0.0f;
};

/// Closest points of segments p1-q1 and p2-q2 (either may be a point).
SegmentDistance segment_distance(Vec2 p1, Vec2 q1, Vec2 p2, Vec2 q2);

/// Closest point to p on the segment a-b.
Vec2 closest_point_on_segment(Vec2 a, Vec2 b, Vec2 p);

/// Distance between the convex hulls of two small point sets given as convex outlines
/// (counter-clockwise for 3 or more points; 1 or 2 points are a point or a segment).
/// Zero when they intersect. Exact but O(n m): meant for n, m <= 8.
float convex_distance(const Vec2* a, int32_t count_a, const Vec2* b, int32_t count_b);

}  // namespace i2d
