// SPDX-License-Identifier: MIT
// Per-shape geometry: mass, bounds, point and box overlap, ray casts.
#pragma once

#include "collision/shapes.hpp"

namespace i2d {

/// Mass, centroid and rotational inertia about the centroid for a uniform density
/// (kg/m^2). Segments have no area and no mass.
MassData compute_mass(const Geometry& g, float density);
float area(const Geometry& g);
/// Tight world-space bounds of the shape placed by xf.
AABB compute_aabb(const Geometry& g, const Transform& xf);

/// Farthest distance of the shape's points from a point of the body frame, m.
float extent_from(const Geometry& g, Vec2 local_point);
/// Smallest distance from the shape's centroid to its surface, m (a circle's radius, a
/// box's half thickness plus rounding): how far the shape may move in a step before it
/// could pass through something thin. Segments have none (0).
float inner_radius(const Geometry& g);
/// Radius of the shape's rounding (circle and capsule radius, polygon rounding), m:
/// the lever arm of rolling resistance.
float rounding_radius(const Geometry& g);

/// Exact tests, boundary included. Segments contain no point.
bool contains_point(const Geometry& g, const Transform& xf, Vec2 p);
bool overlaps_aabb(const Geometry& g, const Transform& xf, const AABB& box);

struct RayHit {
    Vec2 point;
    Vec2 normal;  // unit, facing the incoming ray
    float fraction = 0.0f;
    bool hit = false;
};

/// First entry of origin + t * translation, t in [0, max_fraction]. A shape that
/// strictly contains the origin is not hit. Segments are hit from either side.
RayHit ray_cast(const Geometry& g, const Transform& xf, Vec2 origin, Vec2 translation, float max_fraction);

}  // namespace i2d
