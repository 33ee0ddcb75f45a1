// SPDX-License-Identifier: MIT
// Shape bounds: the tight box of each shape and the fat box its broadphase proxy keeps.
//
// Static shapes never move, so their fat box is their tight box. A moving shape's fat box
// grows by the margin and stretches along the displacement expected over one step, so
// that a falling body is re-inserted about once a step rather than every substep, and so
// that its pairs exist before it arrives (the narrowphase then gives the solver
// speculative points to stop at).
#pragma once

#include <cmath>

#include "broadphase/broad_phase.hpp"
#include "core/pool.hpp"
#include "dynamics/body.hpp"
#include "dynamics/shape.hpp"

namespace i2d {

ProxyKind proxy_kind_of(BodyType type);

/// The margin of a shape of this geometry, m (aabb_margin_fraction).
float aabb_margin_of(const Geometry& geometry);

/// The fat box of the shape's tight box: grown by its margin, stretched along the
/// displacement; reach: how far the body's turn can carry the box besides, m (turn_reach).
AABB fatten(const Shape& shape, BodyType type, Vec2 displacement, float reach = 0.0f);

/// How far a kinematic body's turn over a step can carry its shapes, m: their fat boxes
/// cover it, so that a paddle turning a third of a radian per step has its pairs (and the
/// continuous stage its candidates) before it sweeps over them. Dynamic bodies leave
/// their turns to the margin: a contact stops a dynamic body's spin, not a kinematic's.
inline float turn_reach(const Body& b, float time_step) {
    return b.type == BodyType::kinematic ? std::fabs(b.angular_velocity) * time_step * b.max_extent : 0.0f;
}

/// Recomputes the tight boxes of the body's shapes from its transform; a shape whose fat
/// box no longer holds its tight box, moved by `displacement` as well if ahead is true,
/// is re-inserted (at the broadphase's next commit) with a new fat box. `reach` grows the
/// box ahead by what the body's turn may add (turn_reach).
void update_shape_bounds(const Body& body, Pool<Shape>& shapes, BroadPhase& broad_phase, Vec2 displacement,
                         bool ahead, float reach = 0.0f);

/// The same in two halves, for workers that may not touch the broadphase: the first
/// writes only the body's shapes (marking those that need a new proxy box `enlarged`)
/// and returns whether any does; the second, on one thread, moves their proxies.
bool refit_shape_bounds(const Body& body, Pool<Shape>& shapes, Vec2 displacement, bool ahead, float reach = 0.0f);
void move_enlarged_proxies(const Body& body, Pool<Shape>& shapes, BroadPhase& broad_phase);

}  // namespace i2d
