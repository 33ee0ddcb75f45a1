// SPDX-License-Identifier: MIT
// Shape geometry (circle, axis-aligned box) and the contact manifold, in the core's terms.
#pragma once

#include <cstdint>

#include "math/vec2.hpp"

namespace i2d {

enum class ShapeType : uint8_t { circle, box, count };

struct Circle {
    Vec2 center;  // body frame
    float radius = 0.0f;
};

/// A box centred on the body origin, axis-aligned in the body frame.
struct Box {
    Vec2 half_extents;
};

/// Geometry of one shape; which member is meaningful follows the ShapeType.
struct Geometry {
    ShapeType type = ShapeType::circle;
    Circle circle;
    Box box;
};

struct ManifoldPoint {
    Vec2 point;               // world, midway between the surfaces
    float penetration = 0.0f; // > 0 overlapping, 0 touching
    uint32_t id = 0;          // feature key
};

struct Manifold {
    Vec2 normal;  // unit, from A to B
    int32_t point_count = 0;
    ManifoldPoint points[2];
};

struct MassData {
    float mass = 0.0f;
    Vec2 center;  // centroid in the body frame
};

}  // namespace i2d
