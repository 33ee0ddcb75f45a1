// SPDX-License-Identifier: MIT
// The limits the C boundary holds input to, each with its unit and what lies beyond it.
// The core trusts them: a value past one never reaches it.
#pragma once

#include <cstdint>

namespace i2d {

/// Largest radius or half extent of a shape, m. Larger sizes make float precision
/// useless at the contact and let mass overflow.
constexpr float max_shape_extent = 100000.0f;

/// Smallest radius or half extent, m. Far below the contact slop (0.005 m) already;
/// smaller shapes have masses whose inverse overflows.
constexpr float min_shape_extent = 1.0e-4f;
/// The shortest edge a polygon in a world can have: a box of the smallest half extents,
/// less 1 % for the rounding of its length.
constexpr float min_box_edge = 0.99f * 2.0f * min_shape_extent;

/// Largest |coordinate| accepted for positions and points, m. Float has about 60 m of
/// resolution out there: beyond it geometry is meaningless.
constexpr float max_coordinate = 1.0e9f;

/// Longest translation of a ray or shape cast, m: the length, not each component, so
/// that a cast reaches no farther than a position may lie from the origin.
constexpr float max_cast_length = 1.0e9f;

/// A rotation given by a caller must have c^2 + s^2 within this of 1; it is then
/// normalised exactly. Looser input is more likely a bug than rounding.
constexpr float rotation_normalization_tolerance = 1.0e-3f;

/// Largest shape density, kg/m^2: keeps mass x offset finite for the largest shapes.
constexpr float max_density = 1.0e10f;

/// Largest mass (kg) and rotational inertia (kg m^2) a caller may set on a body: what
/// the densest largest shape could give it, so that mass x speed and inertia x spin stay
/// finite as they do for shapes' masses.
constexpr float max_mass = 1.0e20f;
constexpr float max_inertia = 1.0e30f;

/// Largest restitution and speed limit a world accepts: restitution x speed must stay
/// a finite impulse target.
constexpr float max_restitution = 100.0f;
constexpr float max_speed_limit = 1.0e5f;

/// Longest step, s. Longer steps only lose accuracy, and speed x step must stay far
/// from float overflow.
constexpr float max_time_step = 1000.0f;

/// Shortest step other than 0, s. The solver divides by the substep: a denormal step
/// (found by fuzzing: 1e-45 s) made its rates infinite and every touching body NaN.
/// A microsecond with the most substeps keeps every rate times speed far from overflow.
constexpr float min_time_step = 1.0e-6f;

/// Largest number of substeps a caller may ask for.
constexpr int32_t max_substeps = 1000;

/// Upper bound of unitless or per-second settings (stiffness, damping ratio, rolling
/// resistance, sleep time): far beyond any useful value, small enough to stay finite in
/// products with speeds and steps.
constexpr float max_setting = 1.0e5f;
/// A world's length unit, per metre (i2d_world_def.length_units_per_meter), and the
/// largest touching tolerance, m.
constexpr float min_length_units_per_meter = 1.0e-3f;
constexpr float max_length_units_per_meter = 1.0e4f;
constexpr float max_contact_slop = 1.0f;

/// Largest reach of an explosion (radius and falloff each), m: the size of the largest
/// level a query box spans with float precision to spare.
constexpr float max_explosion_reach = 1.0e6f;
/// Largest explosion impulse per length of outline, N s/m (either sign): with a shape's
/// width (at most 2 x max_shape_extent) and the lightest body, still a finite velocity.
constexpr float max_explosion_impulse_per_length = 1.0e6f;

/// Most points a chain may have: a million segments is a large level; more is more
/// likely a bad count than a level.
constexpr int32_t max_chain_points = 1000000;

/// Softest contact a world accepts, Hz: below it stacks sink visibly at rest.
constexpr float min_contact_hertz = 1.0e-3f;

}  // namespace i2d
