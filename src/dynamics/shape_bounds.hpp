// SPDX-License-Identifier: MIT
// Shape bounds: the tight box of each shape and the fat box its broadphase proxy keeps.
//
// Static shapes never move, so their fat box is their tight box. A moving shape's fat box
// grows by the margin and stretches along the displacement expected over one step, so
// that a falling body is re-inserted about once a step rather than every substep, and so
// that its pairs exist before it arrives (the narrowphase then gives the solver
// speculative points to stop at).
#pragma once

#include "broadphase/broad_phase.hpp"
#include "core/pool.hpp"
#include "dynamics/body.hpp"
#include "dynamics/shape.hpp"

namespace i2d {

ProxyKind proxy_kind_of(BodyType type);

AABB fatten(const AABB& box, BodyType type, Vec2 displacement);

/// Recomputes the tight boxes of the body's shapes from its transform; a shape whose fat
/// box no longer holds its tight box, moved by `displacement` as well if ahead is true,
/// is re-inserted (at the broadphase's next commit) with a new fat box.
void update_shape_bounds(const Body& body, Pool<Shape>& shapes, BroadPhase& broad_phase, Vec2 displacement,
                         bool ahead);

/// The same in two halves, for workers that may not touch the broadphase: the first
/// writes only the body's shapes (marking those that need a new proxy box `enlarged`)
/// and returns whether any does; the second, on one thread, moves their proxies.
bool refit_shape_bounds(const Body& body, Pool<Shape>& shapes, Vec2 displacement, bool ahead);
void move_enlarged_proxies(const Body& body, Pool<Shape>& shapes, BroadPhase& broad_phase);

}  // namespace i2d
