// SPDX-License-Identifier: MIT
// Time of impact of two moving convex shapes by conservative advancement, and shape casts.
//
// Conservative advancement (Mirtich; Box2D's b2TimeOfImpact solves the same problem by
// root finding on separating axes instead): at time t take the distance d between the
// two cores and the normal n of their closest points. No point of B can approach A
// faster than the relative velocity of the centres along n plus each body's turn times
// its farthest core point, so the shapes cannot reach the target distance before
// t + (d - target) / that bound. Advancing by exactly that never steps past the impact;
// each step lands on a time at which the shapes are still apart. The cost is a few
// distance evaluations for sliding or spinning shapes; pure translation converges in
// one or two.
#pragma once

#include <cstdint>

#include "collision/shape_proxy.hpp"

namespace i2d {

/// A body's motion over a step, linear in the centre of mass and in the rotation
/// (normalised linear interpolation), t in [0, 1].
struct Sweep {
    Vec2 local_center;  // centre of mass in the body frame
    Vec2 c1, c2;        // centre of mass in the world at t = 0 and t = 1
    Rot q1, q2;
};

/// A body that does not move over the step.
Sweep still_sweep(const Transform& xf, Vec2 local_center);
Transform sweep_transform(const Sweep& sweep, float t);

enum class ToiState : uint8_t { separated, hit, overlapped };

struct ToiResult {
    ToiState state = ToiState::separated;
    float fraction = 1.0f;  // of the sweep, when hit (0 when overlapped at the start)
    Vec2 normal;            // unit, from A towards B at the impact
    Vec2 point_a, point_b;  // closest core points at the impact
};

/// When the cores of A and B, moving along their sweeps, first come within `target`
/// (+ tolerance) of each other, t in [0, max_fraction]. Overlapped: within it at t = 0.
/// The result never lies past the true impact.
ToiResult time_of_impact(const ShapeProxy& a, const Sweep& sweep_a, const ShapeProxy& b, const Sweep& sweep_b,
                         float max_fraction, float target, float tolerance);

/// A proxy (world space) translated by `translation` against a shape placed by xf: the
/// first fraction at which their surfaces touch (within a quarter of `slop`, m: the
/// linear slop, or a world's, scaled to its length unit),
/// with the point on the shape's surface and the shape's outward normal there. Overlap
/// at the start is a hit at fraction 0 with a point inside both and the unit normal
/// along which the proxy leaves the shape soonest (overlap_exit.hpp; back along the
/// translation when both cores are one and the same point), for any translation.
struct CastHit {
    Vec2 point;
    Vec2 normal;
    float fraction = 0.0f;
    bool hit = false;
};
CastHit shape_cast(const ShapeProxy& shape, const Transform& xf, const ShapeProxy& moving, Vec2 translation,
                   float max_fraction, float slop = linear_slop);

}  // namespace i2d
