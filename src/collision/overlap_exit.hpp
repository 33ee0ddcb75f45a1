// SPDX-License-Identifier: MIT
// How two overlapping convex proxies come apart soonest: the direction, and a point
// inside both. A shape cast that starts inside a shape reports these.
//
// Design note: B clears A along a unit direction n once it has moved
// max_a(a.n) - min_b(b.n) + r_a + r_b along it; the overlap comes apart soonest along
// the n that makes this least. When the cores are apart (only the radii overlap) that is
// the direction of their closest points. When they overlap, the least lies along a facet
// normal of their Minkowski difference, which is perpendicular to two points of one core
// (an edge) or, where the difference is flat (points and segments), along two of them;
// trying both for every pair of points of each core (at most 28 pairs of 4 directions
// per octagon, each against 16 points) finds it exactly, with no iteration to converge
// as EPA would need. Only two cores that are one and the same point leave every
// direction alike: then the caller's fallback decides.
#pragma once

#include "collision/shape_proxy.hpp"

namespace i2d {

struct OverlapExit {
    Vec2 normal;  // unit, from A toward B: the way B leaves A soonest (A's outward normal)
    Vec2 point;   // a point inside both
};

/// For two proxies (world space) that overlap or touch. `fallback` gives the normal when
/// no direction is better than another (both cores the same single point): any vector,
/// normalised however short it is; (0, 1) when it is zero.
OverlapExit overlap_exit(const ShapeProxy& a, const ShapeProxy& b, Vec2 fallback);

}  // namespace i2d
