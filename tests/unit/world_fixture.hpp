// SPDX-License-Identifier: MIT
// The unit tests' fixture: shapes' geometry, bodies and shapes in one line each, and a
// world stepped at the engine's recommended rate. (brute_geometry.hpp holds the
// brute-force references the collision tests compare with, test_rng.hpp their random
// numbers.)
#ifndef I2D_TESTS_UNIT_WORLD_FIXTURE_HPP
#define I2D_TESTS_UNIT_WORLD_FIXTURE_HPP

#include <cmath>

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
    static const BroadPhase& broad_phase(const World& world) { return world.stages_->broad_phase; }
};

}  // namespace i2d

namespace unit {

/// Pi in double, for the closed forms the tests compute (i2d::pi is a float).
constexpr double pi_d = 3.14159265358979323846;

/// The engine's recommended rate: 60 steps a second, 4 substeps each.
constexpr float time_step = 1.0f / 60.0f;
constexpr int32_t substeps = 4;

// ---- Geometry ---------------------------------------------------------------------------

inline i2d::Geometry circle_geometry(i2d::Vec2 center, float radius) {
    i2d::Geometry g;
    g.type = i2d::ShapeType::circle;
    g.circle = {center, radius};
    return g;
}

inline i2d::Geometry capsule_geometry(i2d::Vec2 center1, i2d::Vec2 center2, float radius) {
    i2d::Geometry g;
    g.type = i2d::ShapeType::capsule;
    g.capsule = {center1, center2, radius};
    return g;
}

inline i2d::Geometry segment_geometry(i2d::Vec2 point1, i2d::Vec2 point2) {
    i2d::Geometry g;
    g.type = i2d::ShapeType::segment;
    g.segment = {point1, point2};
    return g;
}

inline i2d::Geometry polygon_geometry(const i2d::Polygon& polygon) {
    i2d::Geometry g;
    g.type = i2d::ShapeType::polygon;
    g.polygon = polygon;
    return g;
}

/// A box of half sizes hx x hy centred on the origin, rounded by `radius`.
inline i2d::Geometry box_geometry(float hx, float hy, float radius = 0.0f) {
    i2d::Polygon box = i2d::make_box(hx, hy);
    box.radius = radius;
    return polygon_geometry(box);
}

// ---- Worlds -----------------------------------------------------------------------------

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
    i2d::ShapeDef def;
    def.density = density;
    return world.create_shape(body, def, box_geometry(hx, hy));
}

inline int32_t add_circle(i2d::World& world, int32_t body, i2d::Vec2 center, float radius) {
    return world.create_shape(body, i2d::ShapeDef{}, circle_geometry(center, radius));
}

/// A body of `type` at `position` with one box of half sizes hx x hy (density 1).
inline int32_t add_box_body(i2d::World& world, i2d::BodyType type, i2d::Vec2 position, float hx, float hy) {
    const int32_t body = add_body(world, type, position);
    add_box(world, body, hx, hy);
    return body;
}

/// Steps `count` times at the recommended rate.
inline void step(i2d::World& world, int32_t count) {
    for (int32_t i = 0; i < count; ++i) {
        world.step(time_step, substeps);
    }
}

/// Steps `count` times, cross-checking every structure after each step (World::validate,
/// which asserts when the build defines I2D_VALIDATE, as Debug builds do).
inline void step_validated(i2d::World& world, int32_t count) {
    for (int32_t i = 0; i < count; ++i) {
        world.step(time_step, substeps);
        world.validate();
    }
}

/// Whether a body's pose, centre of mass and velocities are all finite numbers.
inline bool is_finite_body(const i2d::Body& b) {
    return i2d::is_finite(b.transform.p) && i2d::is_finite(b.transform.q) && i2d::is_finite(b.center) &&
           i2d::is_finite(b.linear_velocity) && std::isfinite(b.angular_velocity);
}

}  // namespace unit

#endif
