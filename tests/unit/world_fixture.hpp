// SPDX-License-Identifier: MIT
// A fixture for unit tests of the core world: bodies and shapes in one line each.
#ifndef I2D_TESTS_UNIT_WORLD_FIXTURE_HPP
#define I2D_TESTS_UNIT_WORLD_FIXTURE_HPP

#include "collision/hull.hpp"
#include "dynamics/world/world.hpp"
#include "dynamics/world/world_stages.hpp"

namespace i2d {

/// The unit tests' window on what the world keeps to itself: a body to corrupt on purpose
/// (a NaN the C boundary would refuse), and the joint set.
class WorldProbe {
public:
    static Body& body(World& world, int32_t body) { return world.bodies_[body]; }
    static JointSet& joint_set(World& world) { return world.stages_->joints; }
};

}  // namespace i2d

namespace unit {

/// The default settings without gravity.
inline i2d::WorldDef without_gravity() {
    i2d::WorldDef def;
    def.gravity = {};
    return def;
}

inline int32_t add_body(i2d::World& world, i2d::BodyType type, i2d::Vec2 position) {
    i2d::BodyDef def;
    def.type = type;
    def.position = position;
    return world.create_body(def);
}

inline int32_t add_box(i2d::World& world, int32_t body, float hx, float hy, float density = 1.0f) {
    i2d::Geometry g;
    g.type = i2d::ShapeType::polygon;
    g.polygon = i2d::make_box(hx, hy);
    i2d::ShapeDef def;
    def.density = density;
    return world.create_shape(body, def, g);
}

inline int32_t add_circle(i2d::World& world, int32_t body, i2d::Vec2 center, float radius) {
    i2d::Geometry g;
    g.type = i2d::ShapeType::circle;
    g.circle = {center, radius};
    return world.create_shape(body, i2d::ShapeDef{}, g);
}

}  // namespace unit

#endif
