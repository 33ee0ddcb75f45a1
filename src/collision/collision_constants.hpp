// SPDX-License-Identifier: MIT
// Tolerances of the collision code, with their units, in one place (Box2D constants.h).
// In metres: the pure functions use them as they are; a world passes its own, scaled to
// its length unit (dynamics/tolerances.hpp).
#pragma once

#include <cstdint>

namespace i2d {

/// Collision and constraint tolerance, m. Usually 0.5 cm: points closer than this are
/// welded by the hull and separations within it count as touching. Larger values make
/// resting contacts visibly sink or hover; much smaller ones fight float precision.
constexpr float linear_slop = 0.005f;

/// How far apart two shapes may be and still get manifold points, m (4 x linear_slop).
/// Speculative points let the solver stop an approaching body before it penetrates.
/// Larger values add contact points that never touch; zero makes stacks jitter.
constexpr float speculative_distance = 4.0f * linear_slop;

/// Most vertices of a polygon. The public i2d_polygon has room for exactly this many.
constexpr int32_t max_polygon_vertices = 8;

}  // namespace i2d
