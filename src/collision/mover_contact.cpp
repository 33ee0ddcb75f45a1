// SPDX-License-Identifier: MIT
// A mover against one shape: its plane and its cast (mover_contact.hpp).
#include "collision/mover_contact.hpp"

#include <cfloat>

#include "collision/overlap_exit.hpp"
#include "collision/toi.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

// How far the mover's core must go along unit n to clear the shape's core: the shape's
// reach along n less the mover's, both from a point of the mover so the products stay small.
float core_depth(const ShapeProxy& shape, const ShapeProxy& mover, Vec2 n) {
    const Vec2 origin = mover.points[0];
    float reach_shape = -FLT_MAX, reach_mover = FLT_MAX;
    for (int32_t i = 0; i < shape.count; ++i) {
        reach_shape = max_of(reach_shape, dot(shape.points[i] - origin, n));
    }
    for (int32_t j = 0; j < mover.count; ++j) {
        reach_mover = min_of(reach_mover, dot(mover.points[j] - origin, n));
    }
    return max_of(0.0f, reach_shape - reach_mover);
}

// Only two cores that are one and the same point leave the exit direction open; a
// mover's core is a segment, so this is never more than a tie-break.
constexpr Vec2 exit_fallback{0.0f, 1.0f};

}  // namespace

ShapeProxy capsule_proxy(const Capsule& capsule) {
    ShapeProxy p;
    p.points[0] = capsule.center1;
    p.points[1] = capsule.center2;
    p.count = 2;
    p.radius = capsule.radius;
    return p;
}

MoverContact mover_contact(const ShapeProxy& shape, const ShapeProxy& mover) {
    const ProxyDistance core = core_distance(shape, mover);
    const float radii = shape.radius + mover.radius;
    MoverContact contact;
    if (core.distance > 0.0f) {
        contact.normal = core.normal;
        contact.separation = core.distance - radii;
        contact.point = core.point_a + shape.radius * core.normal;
        return contact;
    }
    const OverlapExit exit = overlap_exit(shape, mover, exit_fallback);
    contact.normal = exit.normal;
    contact.separation = -(core_depth(shape, mover, exit.normal) + radii);
    contact.point = exit.point;
    return contact;
}

float mover_cast(const ShapeProxy& shape, const ShapeProxy& mover, Vec2 translation, float target, float tolerance,
                 float max_fraction) {
    const float radii = shape.radius + mover.radius;
    const ProxyDistance core = core_distance(shape, mover);
    if (core.distance <= 0.0f || core.distance - radii < target + tolerance) {
        // Touching already: only a move deeper in is stopped, at once.
        const Vec2 normal =
            core.distance > 0.0f ? core.normal : overlap_exit(shape, mover, exit_fallback).normal;
        const bool deeper = dot(translation, normal) < -mover_deeper_tolerance * length(translation);
        return deeper ? 0.0f : max_fraction;
    }
    const Sweep fixed{Vec2{}, Vec2{}, Vec2{}, Rot{}, Rot{}};
    const Sweep moved{Vec2{}, Vec2{}, translation, Rot{}, Rot{}};
    const ToiResult r = time_of_impact(shape, fixed, mover, moved, max_fraction, radii + target, tolerance);
    return r.state == ToiState::separated ? max_fraction : r.fraction;
}

}  // namespace i2d
