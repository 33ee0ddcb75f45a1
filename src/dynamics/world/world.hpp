// SPDX-License-Identifier: MIT
// World: owns bodies and shapes, the rules for creating, changing and destroying them,
// and the step that runs its stages in order.
//
// Design note: bodies and shapes live in pools (contiguous, free-listed, generation per
// slot) linked by indices. Each stage of the step owns its data: the broadphase its
// trees (broadphase/), the contact set its contacts (contact_set.hpp), the islands the
// awake lists and sleep (island.hpp), the solver its per-step arrays (solver.hpp). The
// world wires them and keeps the step short and top-down (world_step.cpp). Queries are
// in world_query.cpp and the cross-checks in world_validate.cpp.
#pragma once

#include <cstdint>
#include <vector>

#include "broadphase/broad_phase.hpp"
#include "collision/shape_proxy.hpp"
#include "core/pool.hpp"
#include "dynamics/body/body.hpp"
#include "dynamics/body/chain.hpp"
#include "dynamics/contact/contact_set.hpp"
#include "dynamics/solver/continuous.hpp"
#include "dynamics/world/events.hpp"
#include "dynamics/island/island.hpp"
#include "dynamics/joint/joint_set.hpp"
#include "dynamics/body/shape.hpp"
#include "dynamics/solver/solver.hpp"
#include "dynamics/world/world_def.hpp"

namespace i2d {

struct WorldCounters {
    int32_t body_count = 0;
    int32_t shape_count = 0;
    int32_t contact_count = 0;  // touching, sensors excluded
    int32_t pair_count = 0;     // contacts alive
    int32_t tree_heights[int32_t(ProxyKind::count)] = {};
    int32_t awake_body_count = 0;
    int32_t sleeping_island_count = 0;
};

/// Where the last step's time went, ms (summed over its substeps).
struct StepProfile {
    float step = 0.0f;
    float pairs = 0.0f;        // broadphase: new pairs from the move buffer
    float collide = 0.0f;      // narrowphase: every contact's manifold
    float solve = 0.0f;        // the soft step: integration, impulses, restitution
    float update_bounds = 0.0f;  // tight and fat boxes, tree re-insertions
    float sleep = 0.0f;        // islands and sleep timers
    float events = 0.0f;       // begin/end and body move events
    float continuous = 0.0f;   // sweeping fast bodies
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
/// Called per ray hit; returns -1 (ignore), 0 (stop), a fraction (clip) or 1 (go on).
using RayVisitor = float (*)(int32_t shape, Vec2 point, Vec2 normal, float fraction, void* context);

class World {
public:
    explicit World(const WorldDef& def);
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    /// Returns null_index when the body pool is full.
    int32_t create_body(const BodyDef& def);
    void destroy_body(int32_t body);
    /// Returns null_index when the shape pool is full.
    int32_t create_shape(int32_t body, const ShapeDef& def, const Geometry& geometry);
    void destroy_shape(int32_t shape);
    /// Creates the chain's segments as shapes of the body (static or kinematic; the
    /// caller checked the points). Returns null_index, creating nothing, when a pool is
    /// full.
    int32_t create_chain(int32_t body, const ChainDef& def);
    /// Destroys the chain and its segments.
    void destroy_chain(int32_t chain);

    // Joints. The def must be valid (two live, different bodies, settings in range: the
    // C boundary checks). Creating and destroying wake both bodies; a joint that keeps
    // its bodies from colliding ends their contacts, and destroying it lets them meet
    // again from the next step. Returns null_index when the joint pool is full.
    int32_t create_joint(const JointDef& def);
    void destroy_joint(int32_t joint);
    /// The joint's settings after a caller changed them in joints[joint].def: wakes both
    /// bodies and applies a changed collide_connected.
    void joint_changed(int32_t joint);
    /// The joint's angle, translation, speed and length as its bodies stand now.
    JointMeasures measure_joint(int32_t joint) const { return joints_.measure(joint); }
    /// Joints whose reaction passed a threshold in the last step.
    const std::vector<JointEvent>& joint_events() const { return events_.current.joint_events; }

    // Changing a body. Each wakes what it must: the body, and for a new transform what
    // touches it too. Velocities of static bodies stay zero; a fixed-rotation body never
    // turns.
    void set_transform(int32_t body, const Transform& xf);
    /// Makes the body static, kinematic or dynamic between steps: its contacts go (the
    /// next step finds the pairs its new type may have), its shapes' proxies move to the
    /// new type's tree, its mass follows, a static body stops, and it wakes with what
    /// touched it.
    void set_type(int32_t body, BodyType type);
    /// The same for many bodies, in list order, to the same result as set_transform
    /// called for each in turn.
    void set_transforms(const int32_t* bodies, const Transform* transforms, int32_t count);
    void set_linear_velocity(int32_t body, Vec2 v);
    void set_angular_velocity(int32_t body, float w);
    /// v scaled down to the world's maximum_linear_speed, w clamped to max_angular_speed.
    Vec2 limited_linear_velocity(Vec2 v) const;
    float limited_angular_velocity(float w) const;
    // Forces and torques accumulate until the end of the next step; impulses change the
    // velocities at once. Only dynamic bodies respond, and one left asleep (wake false)
    // ignores them (Box2D's rule: forces do not pile up while a body sleeps). Each
    // returns false, changing nothing, when the result would overflow.
    bool apply_force(int32_t body, Vec2 force, Vec2 point, bool wake);
    bool apply_force_to_center(int32_t body, Vec2 force, bool wake);
    bool apply_torque(int32_t body, float torque, bool wake);
    bool apply_linear_impulse(int32_t body, Vec2 impulse, Vec2 point, bool wake);
    bool apply_angular_impulse(int32_t body, float impulse, bool wake);

    bool is_awake(int32_t body) const { return islands_.is_awake(body); }
    bool is_quarantined(int32_t body) const { return bodies[body].quarantined; }
    /// Wakes the body's island (and resets its rest timer); a no-op for static bodies.
    void wake_body(int32_t body);
    /// Puts the body and everything touching it to sleep now.
    void sleep_body(int32_t body);
    void wake_all();
    void set_gravity(Vec2 gravity);
    /// Changes a shape's material; its contacts mix it in at once (asleep or not).
    void set_friction(int32_t shape, float friction);
    void set_restitution(int32_t shape, float restitution);
    /// Changes a shape's filter; its contacts are rebuilt at the next step.
    void set_filter(int32_t shape, const Filter& filter);
    void step(float time_step, int32_t substep_count);

    void overlap_aabb(const AABB& box, const QueryFilter& filter, ShapeVisitor visit, void* context) const;
    void overlap_point(Vec2 point, const QueryFilter& filter, ShapeVisitor visit, void* context) const;
    void cast_ray(Vec2 origin, Vec2 translation, const QueryFilter& filter, RayVisitor visit, void* context) const;
    RayResult cast_ray_closest(Vec2 origin, Vec2 translation, const QueryFilter& filter) const;
    /// A proxy (world space) swept along translation: each shape it would touch, with the
    /// fraction, the point on the shape and the shape's normal there; visit as for rays.
    void cast_shape(const ShapeProxy& proxy, Vec2 translation, const QueryFilter& filter, RayVisitor visit,
                    void* context) const;
    RayResult cast_shape_closest(const ShapeProxy& proxy, Vec2 translation, const QueryFilter& filter) const;
    /// Every shape the proxy (world space) overlaps or touches.
    void overlap_shape(const ShapeProxy& proxy, const QueryFilter& filter, ShapeVisitor visit, void* context) const;
    void rebuild_static_tree() { broad_phase_.tree(ProxyKind::static_proxy).rebuild(); }

    /// Installs the C boundary's id encoding for the ids inside events.
    void set_id_encoder(const IdEncoder& ids) { events_.ids = ids; }
    WorldCounters counters() const;
    /// The bits of every body's transform and velocities and every contact's impulses,
    /// in pool order.
    uint64_t state_hash() const;
    int32_t worker_count() const { return tasks_.worker_count(); }
    /// The contact kernels' instruction set (automatic resolved).
    SimdPath simd_path() const { return solver_.simd_path(); }
    const WorldEvents& events() const { return events_.current; }
    /// The last step's stage times. Timing costs nothing until it is asked for: reading
    /// the profile (or the def's enable_profile) turns it on from the next step.
    const StepProfile& profile() const {
        profiling_ = true;
        return profile_;
    }
    bool is_locked() const { return lock_depth_ > 0; }
    /// Inside step: only a job system's enqueue and finish callbacks run user code then,
    /// and the C API refuses them every call that names this world.
    bool is_stepping() const { return stepping_; }
    /// Aborts on a broken internal invariant; does nothing unless built with I2D_VALIDATE.
    /// Runs after every step (a whole-world check per creation would make building a
    /// large scene quadratic in validating builds).
    void validate() const;

    WorldDef settings;
    Pool<Body> bodies;
    Pool<Shape> shapes;
    /// The joints (joint.hpp); change a def through joint_changed.
    Pool<Joint> joints;
    Pool<Chain> chains;

private:
    friend class QueryLock;

    void update_mass(int32_t body);
    void link_joint(int32_t joint);
    void unlink_joint(int32_t joint);
    void link_joints(int32_t body);
    void unlink_joints(int32_t body);
    void let_bodies_meet(int32_t body_a, int32_t body_b);
    int32_t attach_shape(int32_t body, const ShapeDef& def, const Geometry& geometry);
    void detach_shape(int32_t shape);
    void create_proxy(int32_t shape, bool query_now);
    void cover_step_ahead(float time_step);
    void mark_for_cover(int32_t body);
    bool accumulate(int32_t body, Vec2 force, float torque, bool wake);
    bool change_velocity(int32_t body, Vec2 dv, float dw, bool wake);
    bool prepare_to_receive(int32_t body, bool wake);
    void report_falling_asleep(int32_t body);
    void quarantine_non_finite_bodies();
    void forget_joint_impulses(int32_t body);
    void report_sensor_crossings();
    // The islands and the contact set hold no reference to each other: the world hands
    // each what the other changed.
    void follow_woken_bodies();
    void apply_link_changes();
    void destroy_contacts_of_shape(int32_t shape, bool only_filtered_out);
    void destroy_contacts_between(int32_t body_a, int32_t body_b);
    void visit_island_links(int32_t body, FunctionRef<void(int32_t other)> follow) const;
    void validate_body(int32_t body) const;

    TaskSystem tasks_;
    BroadPhase broad_phase_;
    EventRecorder events_;
    JointSet joints_;
    ContactSet contacts_;
    Islands islands_;
    Solver solver_;
    Continuous continuous_;
    std::vector<int32_t> to_cover_;  // bodies whose boxes must cover the next step afresh
    float last_time_step_ = 0.0f;
    StepProfile profile_;
    mutable bool profiling_ = false;
    mutable int32_t lock_depth_ = 0;
    bool stepping_ = false;
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
