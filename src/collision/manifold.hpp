// SPDX-License-Identifier: MIT
// Contact manifolds for every pair of shape kinds, and the table that picks one per pair.
#pragma once

#include "collision/shapes.hpp"

namespace i2d {

// World-space tests; touching counts as contact (penetration 0).
Manifold collide_circles(Vec2 center_a, float radius_a, Vec2 center_b, float radius_b);
Manifold collide_aabbs(const AABB& a, const AABB& b);
Manifold collide_aabb_circle(const AABB& a, Vec2 center_b, float radius_b);

/// A pair of shapes placed by their body transforms. While bodies do not rotate, a
/// transform is a translation.
Manifold collide_shapes(const Geometry& a, const Transform& xf_a, const Geometry& b, const Transform& xf_b);

}  // namespace i2d
