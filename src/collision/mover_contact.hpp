// SPDX-License-Identifier: MIT
// How a mover (a capsule moved by game code, as a proxy in world space) meets one shape:
// the plane the shape presents to it, and how far it can move before touching it.
//
// Design note: both work on the exact core distance (shape_proxy.hpp), so a plane's
// offset is the true separation, and on the time of impact (toi.hpp), which never steps
// past a contact however fast the mover goes. The cast stops a little short of touching:
// at a gap in [target, target + tolerance), so that the plane of what stopped it is found
// again by a collide within that reach (Box2D's b2World_CastMover stops at the linear
// slop for the same reason). A shape the mover already touches (within target +
// tolerance) stops it only when the move runs deeper into it: the distance between two
// convex shapes along a straight move is a convex function of the move, so a move that
// starts tangent to the shape or away from it never comes closer (Box2D calls the
// same idea encroachment; it ignores every shape the cast starts in).
#pragma once

#include "collision/shape_proxy.hpp"

namespace i2d {

struct MoverContact {
    Vec2 normal;             // unit, from the shape toward the mover
    float separation = 0.0f; // of the surfaces along normal, m; negative when overlapping
    Vec2 point;              // on the shape's surface (inside both when overlapping)
};

/// The plane the shape presents to the mover (both proxies in world space). Cores that
/// overlap take the normal along which the mover leaves soonest and the depth it must go.
MoverContact mover_contact(const ShapeProxy& shape, const ShapeProxy& mover);

/// A move that runs deeper into a touched shape than this fraction of its length along
/// the normal stops at once; less is rounding of a move meant to slide.
constexpr float mover_deeper_tolerance = 1.0e-4f;

/// Where a mover's cast stops, as shares of the slop it works to (the world's contact
/// slop): at a gap in [0.5, 0.75) of it, inside the slop, so that a collide within the
/// slop finds again what stopped it.
constexpr float mover_stop_share = 0.5f;
constexpr float mover_stop_tolerance_share = 0.25f;

/// The capsule as a proxy (its two centres and radius).
ShapeProxy capsule_proxy(const Capsule& capsule);

/// The fraction in [0, max_fraction] of translation the mover goes before its surface
/// comes within `target` (+ tolerance, m) of the shape's; max_fraction when it never does
/// (or starts within it and does not move deeper, see the design note).
float mover_cast(const ShapeProxy& shape, const ShapeProxy& mover, Vec2 translation, float target, float tolerance,
                 float max_fraction);

}  // namespace i2d
