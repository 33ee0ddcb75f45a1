// SPDX-License-Identifier: MIT
// Shape bounds: the tight box of each shape and the fat box its broadphase proxy keeps.
//
// Static shapes never move, so their fat box is their tight box. A moving shape's fat box
// grows by the margin; its box ahead stretches that along the displacement expected over
// one step, so that its pairs with static and kinematic shapes exist before it arrives
// (the narrowphase then gives the solver speculative points to stop at: a ball does not
// sink into the floor it falls on, nor pass a one-sided chain). Two dynamic shapes pair
// by their fat boxes alone, as in Box2D v3: a fast body may meet another within a step
// before their contact exists, and the contact then pushes them apart. Stretching those
// as well doubled the pairs of the spinner, whose blade flings its loads at up to 100 m/s
// (41 323 against 19 834 after 500 steps; its step three tenths longer), and left the
// tumbler 9 108 pairs against 8 036 (a tenth longer). Kinematic bodies and bullets
// keep the stretch in their fat box: other bodies meet them by it (a bullet's sweep reads
// the boxes of the dynamic tree).
#pragma once

#include <cmath>

#include "broadphase/broad_phase.hpp"
#include "core/pool.hpp"
#include "dynamics/body/body.hpp"
#include "dynamics/body/shape.hpp"

namespace i2d {

ProxyKind proxy_kind_of(BodyType type);

/// The margin of a shape of this geometry (aabb_margin_fraction of its size), at most
/// `max_margin` (the world's max_aabb_margin, Tolerances), m.
float aabb_margin_of(const Geometry& geometry, float max_margin);

/// The proxy boxes of a shape.
struct ProxyBoxes {
    AABB fat;    // the tight box grown by the margin (and stretched, for kinematic bodies and bullets)
    AABB ahead;  // the fat box stretched along the displacement: what static and kinematic shapes meet
};

/// Whether the body's fat boxes take the stretch along its motion (see above).
inline bool stretches_fat_box(const Body& b) { return b.type == BodyType::kinematic || b.is_bullet; }

/// Whether the proxies of two shapes overlap the way the broadphase pairs them: two
/// dynamic shapes by their fat boxes, any other two by their boxes ahead.
inline bool proxies_meet(const Shape& a, const Shape& b) {
    const bool both_dynamic = proxy_kind(a.proxy_key) == ProxyKind::dynamic_proxy &&
                              proxy_kind(b.proxy_key) == ProxyKind::dynamic_proxy;
    return both_dynamic ? overlaps(a.fat_aabb, b.fat_aabb) : overlaps(a.ahead_aabb, b.ahead_aabb);
}

/// The proxy boxes of the shape's tight box: grown by its margin, stretched along the
/// displacement; reach: how far the body's turn can carry the box besides, m (turn_reach).
ProxyBoxes fatten(const Shape& shape, const Body& body, Vec2 displacement, float reach = 0.0f);

/// How far a kinematic body's turn over a step can carry its shapes, m: their fat boxes
/// cover it, so that a paddle turning a third of a radian per step has its pairs (and the
/// continuous stage its candidates) before it sweeps over them. Dynamic bodies leave
/// their turns to the margin: a contact stops a dynamic body's spin, not a kinematic's.
inline float turn_reach(const Body& b, float time_step) {
    return b.type == BodyType::kinematic ? std::fabs(b.angular_velocity) * time_step * b.max_extent : 0.0f;
}

/// Recomputes the tight boxes of the body's shapes from its transform; a shape whose fat
/// box no longer holds its tight box, or whose box ahead no longer holds it moved by
/// `displacement` as well if ahead is true, is re-inserted (at the broadphase's next
/// commit) with new boxes. `reach` grows the box ahead by what the body's turn may add
/// (turn_reach).
void update_shape_bounds(const Body& body, Pool<Shape>& shapes, BroadPhase& broad_phase, Vec2 displacement,
                         bool ahead, float reach = 0.0f);

/// The same in two halves, for workers that may not touch the broadphase: the first
/// writes only the body's shapes (marking those that need a new proxy box `enlarged`)
/// and returns whether any does; the second, on one thread, moves their proxies.
bool refit_shape_bounds(const Body& body, Pool<Shape>& shapes, Vec2 displacement, bool ahead, float reach = 0.0f);
void move_enlarged_proxies(const Body& body, Pool<Shape>& shapes, BroadPhase& broad_phase);

/// The body's shapes marked `enlarged`, each unmarked and handed to take(shape): what
/// move_enlarged_proxies moves, for a caller that hands the moves on later.
template <class Take>
void take_enlarged_shapes(const Body& body, Pool<Shape>& shapes, Take&& take) {
    for (int32_t s = body.head_shape; s != null_index; s = shapes[s].next_in_body) {
        Shape& shape = shapes[s];
        if (shape.enlarged) {
            shape.enlarged = false;
            take(static_cast<const Shape&>(shape));
        }
    }
}

/// Only the tight boxes, from the body's transform: the shapes of a disabled body, which
/// have no proxies (their fat boxes are made when it is enabled).
void update_tight_boxes(const Body& body, Pool<Shape>& shapes);

}  // namespace i2d
