// SPDX-License-Identifier: MIT
// The character mover's planes: solving a move against them and clipping a velocity by
// them (pure: no world, lengths in metres).
//
// Design note: a mover touching shapes sees each as a plane, normal pointing at the mover
// and offset its separation, so that the mover moved by d keeps clear of the shape while
// offset + dot(normal, d) >= 0 (to first order: the plane stands in for the surface).
// solve_planes finds the d nearest the move asked for that keeps every such constraint:
// projected Gauss-Seidel on the push of each plane along its normal, the push
// accumulated per plane and clamped to [0, push_limit], so that a plane only ever pushes
// (never pulls) and a soft one pushes no farther than its limit; sweeps stop when a whole
// sweep changes the pushes by less than a tolerance. Box2D v3.1's b2SolvePlanes solves
// the same problem the same way (it aims at a separation of minus the linear slop); this
// one aims at zero, so that a caller's gap (skin) is exactly the offset it passes.
// Rejected: an exact quadratic program (active sets over all planes) gives the same
// answer for the few planes a mover touches at a cost it never needs.
//
// clip_vector removes from a velocity the part that runs into the clipping planes: its
// projection onto the cone of directions that run into none of them. In 2D that
// projection is the vector itself, its projection onto one plane's line, or zero; the
// nearest of these that runs into no plane is it (see the .cpp). Box2D clips plane by
// plane in order, which can leave a part that runs into an earlier plane in a corner.
#pragma once

#include <cfloat>
#include <cstdint>

#include "math/vec2.hpp"

namespace i2d {

/// The plane of points x with dot(normal, x) = offset; normal is unit.
struct Plane {
    Vec2 normal;
    float offset = 0.0f;
};

/// A plane the mover touches: offset is its separation along normal, m (negative when
/// overlapping); push_limit how far the plane may push (FLT_MAX: rigid); push the solver's
/// output; clip_velocity whether clip_vector clips against it. Layout-identical to
/// i2d_collision_plane.
struct CollisionPlane {
    Plane plane;
    float push_limit = FLT_MAX;
    float push = 0.0f;
    bool clip_velocity = true;
};

struct PlaneSolution {
    Vec2 translation;
    int32_t iteration_count = 0;  // sweeps over the planes; 0 without planes
};

/// Most Gauss-Seidel sweeps of solve_planes. Two planes at an angle converge by a factor
/// of cos^2 of it per sweep, so 30 degrees apart lose 0.75 per sweep: 32 sweeps take a
/// 1 m overlap below 0.1 mm. A corner that runs out leaves the last plane swept exact and
/// the others within the last sweep's change.
constexpr int32_t max_plane_sweeps = 32;

/// A sweep that changes the pushes by less than this in total ends the solve, m: far
/// below the contact slop (5 mm), far above float rounding of metre-sized moves.
constexpr float plane_solve_tolerance = 1.0e-6f;

/// The move nearest target_delta with offset + dot(normal, move) >= 0 for every rigid
/// plane (soft ones push at most push_limit); fills each plane's push (>= 0).
PlaneSolution solve_planes(Vec2 target_delta, CollisionPlane* planes, int32_t count);

/// The vector less the part that runs into planes with clip_velocity set (see the design
/// note). Cost: O(count) when the vector runs into no plane, up to O(count^2) in a corner.
Vec2 clip_vector(Vec2 vector, const CollisionPlane* planes, int32_t count);

}  // namespace i2d
