// SPDX-License-Identifier: MIT
// World: owns bodies and shapes, creates and destroys them, and runs the step.
//
// Design note: bodies and shapes live in pools (contiguous, free-listed, generation per
// slot); a body links its shapes through index links in Shape, so nothing is allocated
// per object beyond pool growth, and the step reuses its scratch arrays from step to
// step. Queries live in world_query.cpp.
#pragma once

#include <cstdint>
#include <vector>

#include "broadphase/sweep_and_prune.hpp"
#include "core/pool.hpp"
#include "dynamics/body.hpp"
#include "dynamics/contact_solver.hpp"
#include "dynamics/shape.hpp"

namespace i2d {

struct WorldDef {
    Vec2 gravity{0.0f, -10.0f};
    float contact_slop = 0.005f;
    float contact_correction_percent = 0.8f;
    float restitution_threshold = 1.0f;
    float maximum_linear_speed = 400.0f;
    int32_t velocity_iterations = 10;
    bool enable_sleep = true;
};

struct WorldCounters {
    int32_t body_count = 0;
    int32_t shape_count = 0;
    int32_t contact_count = 0;
    int32_t pair_count = 0;
};

struct RayResult {
    int32_t shape = null_index;
    Vec2 point;
    Vec2 normal;
    float fraction = 0.0f;
    bool hit = false;
};

/// Called per query result; return false to stop.
using ShapeVisitor = bool (*)(int32_t shape, void* context);

class World {
public:
    explicit World(const WorldDef& def);

    /// Returns null_index when the body pool is full.
    int32_t create_body(const BodyDef& def);
    void destroy_body(int32_t body);
    /// Returns null_index when the shape pool is full.
    int32_t create_shape(int32_t body, const ShapeDef& def, const Geometry& geometry);
    void destroy_shape(int32_t shape);

    void set_transform(int32_t body, const Transform& xf);
    void step(float time_step, int32_t substep_count);

    void overlap_aabb(const AABB& box, const QueryFilter& filter, ShapeVisitor visit, void* context) const;
    void overlap_point(Vec2 point, const QueryFilter& filter, ShapeVisitor visit, void* context) const;
    RayResult cast_ray_closest(Vec2 origin, Vec2 translation, const QueryFilter& filter) const;

    WorldCounters counters() const;
    /// Aborts on a broken internal invariant; does nothing unless built with I2D_VALIDATE.
    void validate() const;
    bool is_locked() const { return lock_depth_ > 0; }

    WorldDef settings;
    Pool<Body> bodies;
    Pool<Shape> shapes;

private:
    friend class QueryLock;

    void update_mass(int32_t body);
    void update_shape_bounds(int32_t body);
    void integrate_velocities(float h);
    void integrate_positions(float h);
    void find_contacts();
    void substep(float h);

    // Step scratch, kept between steps so that a steady state allocates nothing.
    SweepAndPrune broadphase_;
    std::vector<AABB> proxy_bounds_;
    std::vector<int32_t> proxy_shapes_;
    std::vector<BroadphasePair> pairs_;
    std::vector<ContactConstraint> contacts_;
    std::vector<ContactConstraint> previous_contacts_;  // last substep's, for warm starting
    int32_t last_pair_count_ = 0;
    mutable int32_t lock_depth_ = 0;
};

/// Locks the world while a query's callbacks run, so that they cannot change it.
class QueryLock {
public:
    explicit QueryLock(const World& world) : world_(world) { ++world_.lock_depth_; }
    ~QueryLock() { --world_.lock_depth_; }
    QueryLock(const QueryLock&) = delete;
    QueryLock& operator=(const QueryLock&) = delete;

private:
    const World& world_;
};

}  // namespace i2d
