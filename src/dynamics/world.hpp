// SPDX-License-Identifier: MIT
// World: owns bodies, shapes and contacts, creates and destroys them, and runs the step.
//
// Design note: bodies, shapes and contacts live in pools (contiguous, free-listed,
// generation per slot) linked by indices; shapes sit in the broadphase's trees and
// contacts persist while their shapes' fat boxes overlap. Nothing is allocated per
// object beyond pool growth, and the step reuses its scratch arrays. The step lives in
// world.cpp, contact bookkeeping in world_contacts.cpp, queries in world_query.cpp,
// checks in world_validate.cpp.
#pragma once

#include <cstdint>
#include <vector>

#include "broadphase/broad_phase.hpp"
#include "core/hash_set.hpp"
#include "core/pool.hpp"
#include "dynamics/body.hpp"
#include "dynamics/body_state.hpp"
#include "dynamics/constraint_colors.hpp"
#include "dynamics/contact.hpp"
#include "dynamics/contact_solver.hpp"
#include "dynamics/events.hpp"
#include "dynamics/mixing.hpp"
#include "dynamics/shape.hpp"

namespace i2d {

class Timer;

struct WorldDef {
    Vec2 gravity{0.0f, -10.0f};
    float contact_slop = 0.005f;
    float contact_hertz = 60.0f;
    float contact_damping_ratio = 10.0f;
    float contact_push_max_speed = 3.0f;
    float restitution_threshold = 1.0f;
    float maximum_linear_speed = 400.0f;
    MixingRule friction_mixing = MixingRule::geometric_mean;
    MixingRule restitution_mixing = MixingRule::minimum;
    bool enable_sleep = true;
    float sleep_speed_threshold = 0.05f;
    float time_to_sleep = 0.5f;
};

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
};

/// Bodies that fall asleep together, linked through Body::next_in_island.
struct SleepingIsland {
    int32_t head_body = null_index;
    int32_t body_count = 0;
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

    /// Returns null_index when the body pool is full.
    int32_t create_body(const BodyDef& def);
    void destroy_body(int32_t body);
    /// Returns null_index when the shape pool is full.
    int32_t create_shape(int32_t body, const ShapeDef& def, const Geometry& geometry);
    void destroy_shape(int32_t shape);

    void set_transform(int32_t body, const Transform& xf);
    /// Wakes the body's island (and resets its rest timer); a no-op for static bodies.
    void wake_body(int32_t body);
    /// Puts the body and everything touching it to sleep now.
    void sleep_body(int32_t body);
    bool is_awake(int32_t body) const { return bodies[body].awake_index != null_index; }
    void wake_all();
    /// Changes a shape's filter; its contacts are rebuilt at the next step.
    void set_filter(int32_t shape, const Filter& filter);
    void step(float time_step, int32_t substep_count);

    void overlap_aabb(const AABB& box, const QueryFilter& filter, ShapeVisitor visit, void* context) const;
    void overlap_point(Vec2 point, const QueryFilter& filter, ShapeVisitor visit, void* context) const;
    void cast_ray(Vec2 origin, Vec2 translation, const QueryFilter& filter, RayVisitor visit, void* context) const;
    RayResult cast_ray_closest(Vec2 origin, Vec2 translation, const QueryFilter& filter) const;
    void rebuild_static_tree() { broad_phase_.tree(ProxyKind::static_proxy).rebuild(); }

    WorldCounters counters() const;
    const WorldEvents& events() const { return events_; }
    const StepProfile& profile() const { return profile_; }
    bool is_locked() const { return lock_depth_ > 0; }
    /// Aborts on a broken internal invariant; does nothing unless built with I2D_VALIDATE.
    /// Runs after every step (a whole-world check per creation would make building a
    /// large scene quadratic in validating builds).
    void validate() const;

    WorldDef settings;
    IdEncoder id_encoder;
    Pool<Body> bodies;
    Pool<Shape> shapes;
    Pool<Contact> contacts;

private:
    friend class QueryLock;

    /// Calls visit(contact, other_body) for each contact of the body; visit must not
    /// destroy contacts.
    template <class Visit>
    void visit_contacts(int32_t body, Visit visit) {
        for (int32_t key = bodies[body].head_contact_key; key != null_index;) {
            const Contact& c = contacts[key >> 1];
            const int32_t next = c.edges[key & 1].next_key;
            visit(key >> 1, c.edges[(key & 1) ^ 1].body);
            key = next;
        }
    }
    // Bodies and shapes.
    void update_mass(int32_t body);
    void create_proxy(int32_t shape, bool query_now);
    void sync_proxies(int32_t body);
    void cover_step_ahead(float time_step);
    // Contacts (world_contacts.cpp).
    void create_contact(int32_t shape_a, int32_t shape_b);
    ShapePairEvent event_of(const Contact& contact) const;
    /// during_step: the narrowphase dropped it; otherwise the caller changed the world.
    void destroy_contact(int32_t contact, bool during_step);
    void report_touch_changes(const Contact& contact, bool touching_now);
    void begin_contact_step();
    void end_contact_step();
    void destroy_contacts_of_shape(int32_t shape, bool only_filtered_out);
    void find_new_contacts();
    void update_contacts();
    void update_contact(Contact& contact, const Shape& a, const Shape& b);
    void update_touching();
    void add_awake_contact(int32_t contact);
    void remove_awake_contact(int32_t contact);
    // The soft step (world_solve.cpp).
    void solve(float time_step, int32_t substep_count);
    void gather_bodies();
    void gather_constraints(float h);
    void color_constraints();
    ContactConstraint make_constraint(int32_t contact, const Softness& soft, const Softness& fixed_soft) const;
    Vec2 free_acceleration(const Body& body, float inv_mass) const;
    void integrate_velocities(float h);
    void integrate_positions(float h);
    void store_impulses();
    void finalize_bodies();
    // Islands and sleep (world_sleep.cpp).
    void add_awake_body(int32_t body);
    void remove_awake_body(int32_t body);
    void wake_island(int32_t island);
    void update_sleep_timers(float time_step);
    void find_islands_to_sleep();
    void put_marked_islands_to_sleep();
    void put_to_sleep(const int32_t* members, int32_t count);
    void drop_sleeping_contacts();
    int32_t island_root(int32_t awake_index);
    void validate_sleep_state(int32_t body) const;
    void report_body_moves();
    uint64_t shape_id(int32_t shape) const;
    uint64_t body_id(int32_t body) const;

    BroadPhase broad_phase_;
    HashSet pair_set_;  // pair_key of the shapes of every contact
    WorldEvents events_;
    std::vector<ShapePairEvent> pending_contact_ends_;  // caused between steps
    std::vector<ShapePairEvent> pending_sensor_ends_;
    // Step scratch, kept between steps so that a steady state allocates nothing.
    std::vector<ShapePairCandidate> new_pairs_;
    std::vector<ContactConstraint> constraints_;  // in solve order: by colour
    ConstraintColors colors_;
    std::vector<int8_t> contact_colors_;  // per awake contact, or -1 when it is not solved
    std::vector<int32_t> color_starts_;   // per colour: its first slot in constraints_
    std::vector<BodyState> states_;    // per awake body, then one fixed state at the end
    std::vector<BodyMotion> motions_;  // per awake body
    std::vector<int32_t> islands_to_wake_;
    std::vector<int32_t> island_parent_;  // union-find over awake indices
    std::vector<float> island_rest_;      // shortest rest time per island root
    std::vector<int32_t> island_members_;
    std::vector<int32_t> island_head_;  // per island root: first member (awake index)
    std::vector<int32_t> island_next_;  // per awake index: next member of its island
    std::vector<uint8_t> falls_asleep_;   // per awake index, this step
    // Awake sets: dense lists of indices; each object knows its place (awake_index).
    std::vector<int32_t> awake_bodies_;
    std::vector<int32_t> awake_contacts_;
    Pool<SleepingIsland> sleeping_islands_;
    StepProfile profile_;
    float last_time_step_ = 0.0f;  // predicts how far bodies move in a step
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
