// SPDX-License-Identifier: MIT
// The rules of a body's own state: its mass from its shapes, the speed limits a velocity
// enters the world under, and what a change of type does to it. What a change means for
// the rest of the world (contacts, islands, the broadphase) is the world's to wire
// (world/world_bodies.cpp).
#pragma once

#include "core/pool.hpp"
#include "dynamics/body/body.hpp"
#include "dynamics/body/shape.hpp"
#include "math/vec2.hpp"

namespace i2d {

/// Mass, centre of mass, rotational inertia and extents from the body's shapes, and its
/// centre in the world. Static and kinematic bodies have infinite mass and inertia
/// (inverses 0); a dynamic body with no mass gets 1 kg at its origin so that it still
/// responds, rather than an infinite mass that would make it static in disguise. A
/// static body's extents are 0 and cost nothing: the time is constant in its shapes.
/// `slop`: the world's linear slop (Tolerances), the least thickness a shape counts with
/// in min_extent.
void update_mass_from_shapes(Body& body, const Pool<Shape>& shapes, float slop);

/// v scaled down to max_speed, its direction kept. The length is taken in double so that
/// no finite float input overflows on the way.
Vec2 limited_linear_velocity(Vec2 v, float max_speed);
/// w clamped to max_angular_speed.
float limited_angular_velocity(float w);

/// The body becomes static, kinematic or dynamic: a static body stops, only a dynamic
/// one keeps forces, its rest time starts again and a quarantine ends. The caller wires
/// the rest (proxies, islands, joints) and updates the mass.
void change_type(Body& body, BodyType type);

/// Whether the body can turn when given a spin: kinematic, or dynamic with finite inertia.
bool can_turn(const Body& body);

}  // namespace i2d
