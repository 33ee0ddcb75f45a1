// SPDX-License-Identifier: MIT
// Tolerances: the step's length-bearing tolerances in a world's own length unit.
//
// Design note: the tuning constants (collision_constants.hpp, constants.hpp) are in
// metres, as Box2D's are. A world whose def counts length_units_per_meter of its units to
// the metre (a game in pixels, say 50) gets each of them times that number, so that its
// scene moves as the same scene in metres, scaled. Box2D keeps one such scale for the
// whole process (b2SetLengthUnitsPerMeter); here each world has its own. The values are
// made from the def where they are needed (once per step in the StepContext, once per
// shape or mass change) rather than stored beside it, so that they can never disagree
// with the def that a snapshot, a restore or a recording brings. At 1 unit per metre each
// is its constant's own bits (x * 1.0f is x): worlds in metres step exactly as before.
//
// What stays in metres: the pure public functions (i2d_collide_*, i2d_make_polygon's
// welding, i2d_make_proxy, the hull), which know no world, and the C boundary's limits on
// input (shape extents, core and edge lengths, coordinates).
#pragma once

#include "collision/collision_constants.hpp"
#include "dynamics/constants.hpp"

namespace i2d {

struct Tolerances {
    float linear_slop;                // collision_constants.hpp
    float speculative_distance;       // collision_constants.hpp
    float max_aabb_margin;            // constants.hpp
    float recycle_touching_distance;  // constants.hpp
    float recycle_apart_distance;     // constants.hpp

    /// The tolerances of a world of `units_per_meter` length units to the metre.
    explicit Tolerances(float units_per_meter)
        : linear_slop(units_per_meter * i2d::linear_slop),
          speculative_distance(units_per_meter * i2d::speculative_distance),
          max_aabb_margin(units_per_meter * i2d::max_aabb_margin),
          recycle_touching_distance(units_per_meter * i2d::recycle_touching_distance),
          recycle_apart_distance(units_per_meter * i2d::recycle_apart_distance) {}
};

}  // namespace i2d
