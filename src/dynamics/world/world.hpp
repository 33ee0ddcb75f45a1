// SPDX-License-Identifier: MIT
// World: owns bodies, shapes, chains and the stages of the step; every change to them
// goes through its functions, which keep the stages in step with one another.
//
// Design note: bodies, shapes and chains live in pools (contiguous, free-listed,
// generation per slot) linked by indices; the joints live in the joint set and the
// contacts in the contact set. Each stage of the step owns its data (world_stages.hpp)
// and the world wires them: it hands the islands the contact set's link changes and the
// contact set the bodies the islands woke, and keeps the step short and top-down
// (world_step.cpp). Callers read the pools; they change them only through the world, so
// that a change is never half made. The work is split by what it changes:
// world.cpp (creation and the wiring between stages), world_bodies.cpp,
// world_body_enable.cpp, world_shapes.cpp, world_joints.cpp, world_step.cpp,
// world_query.cpp, world_mover.cpp, world_draw.cpp, world_origin.cpp and world_validate.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "broadphase/proxy_key.hpp"
#include "collision/mover_contact.hpp"
#include "collision/shape_proxy.hpp"
#include "core/function_ref.hpp"
#include "core/pool.hpp"
#include "dynamics/body/body.hpp"
#include "dynamics/body/chain.hpp"
#include "dynamics/body/shape.hpp"
#include "dynamics/contact/contact.hpp"
#include "dynamics/contact/contact_hooks.hpp"
#include "dynamics/joint/joint.hpp"
#include "dynamics/recording/recording_format.hpp"
#include "dynamics/tolerances.hpp"
#include "dynamics/world/events.hpp"
#include "dynamics/world/world_def.hpp"

namespace i2d {

class Recorder;
struct DebugDraw;
struct SnapshotHeader;

struct WorldStages;

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
    ~World();
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    // What callers read. Indices come from the create functions; a pool says which are live.
    const WorldDef& settings() const { return settings_; }
    /// The step's length tolerances in the world's unit (its def's length_units_per_meter).
    Tolerances tolerances() const { return Tolerances(settings_.length_units_per_meter); }
    const Pool<Body>& bodies() const { return bodies_; }
    const Pool<Shape>& shapes() const { return shapes_; }
    const Pool<Joint>& joints() const;
    const Pool<Chain>& chains() const { return chains_; }

    // Bodies (world_bodies.cpp).
    /// Returns null_index when the body pool is full.
    int32_t create_body(const BodyDef& def);
    void destroy_body(int32_t body);
    // Changing a body. Each wakes what it must: the body, and for a new transform what
    // touches it too. Velocities of static bodies stay zero; a fixed-rotation body never
    // turns.
    void set_transform(int32_t body, const Transform& xf);
    /// Makes the body static, kinematic or dynamic between steps: its contacts go (the
    /// next step finds the pairs its new type may have), its shapes' proxies move to the
    /// new type's tree, its mass follows, a static body stops, and it wakes with what
    /// touched it. A disabled body joins the stages as its new type when enabled.
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
    // ignores them (Box2D's rule: forces do not pile up while a body sleeps). A disabled
    // body keeps them whatever `wake` says: impulses change the velocity it keeps, forces
    // act in the first step after it is enabled. Each returns false, changing nothing,
    // when the result would overflow.
    bool apply_force(int32_t body, Vec2 force, Vec2 point, bool wake);
    bool apply_force_to_center(int32_t body, Vec2 force, bool wake);
    bool apply_torque(int32_t body, float torque, bool wake);
    bool apply_linear_impulse(int32_t body, Vec2 impulse, Vec2 point, bool wake);
    bool apply_angular_impulse(int32_t body, float impulse, bool wake);
    /// Pushes the dynamic bodies whose shapes the blast reaches (world_explode.cpp),
    /// waking them; recorded as the impulses it applies.
    void explode(const ExplosionDef& def);
    void set_user_data(int32_t body, void* user_data);
    void set_mass_data(int32_t body, const MassOverride& mass);
    void set_body_setting(int32_t body, BodySetting setting, float value);
    void set_body_flag(int32_t body, BodyFlag flag, bool value);
    /// Takes the body out of the world or brings it back (world_body_enable.cpp); a no-op,
    /// not recorded, when it is so already.
    void set_body_enabled(int32_t body, bool enabled);
    bool is_enabled(int32_t body) const { return bodies_[body].enabled; }

    bool is_awake(int32_t body) const { return bodies_[body].awake_index != null_index; }
    bool is_quarantined(int32_t body) const { return bodies_[body].quarantined; }
    /// Wakes the body's island (and resets its rest timer); a no-op for static bodies.
    void wake_body(int32_t body);
    /// Puts the body and everything touching it to sleep now.
    void sleep_body(int32_t body);
    void wake_all();

    // Shapes and chains (world_shapes.cpp).
    /// Returns null_index when the shape pool is full.
    int32_t create_shape(int32_t body, const ShapeDef& def, const Geometry& geometry);
    void destroy_shape(int32_t shape);
    /// Creates the chain's segments as shapes of the body (static or kinematic; the
    /// caller checked the points). Returns null_index, creating nothing, when a pool is
    /// full.
    int32_t create_chain(int32_t body, const ChainDef& def);
    /// Destroys the chain and its segments.
    void destroy_chain(int32_t chain);
    /// Changes a shape's material; its contacts mix it in at once (asleep or not).
    void set_friction(int32_t shape, float friction);
    void set_restitution(int32_t shape, float restitution);
    /// Changes a shape's filter; its contacts are rebuilt at the next step.
    void set_filter(int32_t shape, const Filter& filter);
    void set_geometry(int32_t shape, const Geometry& geometry);
    void set_density(int32_t shape, float density, bool update_body_mass);
    void set_material(int32_t shape, const SurfaceMaterial& material);
    void set_shape_flag(int32_t shape, ShapeFlag flag, bool value);
    /// The host's contact hooks (contact_hooks.hpp): wiring, neither saved nor recorded.
    void set_custom_filter(const ContactHooks::CustomFilter& filter);
    void set_pre_solve(const ContactHooks::PreSolve& pre_solve);
    void set_shape_user_data(int32_t shape, void* user_data);

    // Joints (world_joints.cpp). The def must be valid (two live, different bodies,
    // settings in range: the C boundary checks). Creating and destroying wake both
    // bodies; a joint that keeps its bodies from colliding ends their contacts, and
    // destroying it lets them meet again from the next step. Returns null_index when the
    // joint pool is full.
    int32_t create_joint(const JointDef& def);
    void destroy_joint(int32_t joint);
    /// New settings for the joint (same kind and bodies): wakes both bodies and applies a
    /// changed collide_connected.
    void set_joint_def(int32_t joint, const JointDef& def);
    void set_joint_user_data(int32_t joint, void* user_data);
    /// The joint's angle, translation, speed and length as its bodies stand now.
    JointMeasures measure_joint(int32_t joint) const;
    /// Joints whose reaction passed a threshold in the last step.
    const std::vector<JointEvent>& joint_events() const;

    // The world (world.cpp, world_step.cpp, world_origin.cpp).
    void set_gravity(Vec2 gravity);
    /// The simulation's settings (not the host's wiring: workers, tasks, SIMD path,
    /// profiling; nor the length unit, which the world's tolerances were made for).
    void set_settings(const WorldDef& settings);
    void set_user_data(void* user_data) { user_data_ = user_data; }
    void* user_data() const { return user_data_; }
    /// Moves the world's origin to `new_origin`: every position and box the world keeps in
    /// world coordinates (bodies, shapes, trees, mouse targets, the last step's events)
    /// becomes itself less new_origin; nothing wakes, and the simulation goes on as it
    /// would have, seen from there. A rollback state saved before is refused after it.
    void shift_origin(Vec2 new_origin);
    void step(float time_step, int32_t substep_count);
    /// Installs the C boundary's id encoding for the ids inside events.
    void set_id_encoder(const IdEncoder& ids);
    WorldCounters counters() const;
    /// The bits of every body's transform and velocities and every contact's impulses,
    /// in pool order.
    uint64_t state_hash() const;
    int32_t worker_count() const;
    /// The contact kernels' instruction set (automatic resolved).
    SimdPath simd_path() const;
    const WorldEvents& events() const;
    /// The last step's stage times. Timing costs nothing until it is asked for: reading
    /// the profile (or the def's enable_profile) turns it on from the next step.
    const StepProfile& profile() const {
        profiling_ = true;
        return profile_;
    }
    bool is_locked() const { return lock_depth_ > 0; }
    /// Inside step: only a job system's enqueue and finish callbacks run user code then,
    /// and the C API refuses them every call that names this world.
    bool is_stepping() const { return in_batch_ || stepping_; }
    /// Set for the whole of a batch step (world_batch.hpp): the world counts as stepping
    /// before and after its own step, while other workers step the batch's other worlds.
    /// Tested first by is_stepping, so that a call from another worker never reads
    /// stepping_ while this world's worker writes it.
    void set_in_batch(bool flag) { in_batch_ = flag; }
    /// Aborts on a broken internal invariant; does nothing unless built with I2D_VALIDATE.
    /// Runs after every step (a whole-world check per creation would make building a
    /// large scene quadratic in validating builds).
    void validate() const;

    // Queries (world_query.cpp).
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
    void rebuild_static_tree();

    // The character mover's queries (world_mover.cpp): a capsule in world space, moved by
    // game code rather than by the solver. They see no sensors and call no user code.
    /// The mover's touching tolerance, length units: the contact slop, at least the linear
    /// slop (a mover needs a band to stop in and find again).
    float mover_slop() const;
    /// The fraction in [0, 1] of translation the capsule goes before it comes within the
    /// mover slop of a shape (mover_cast: touched shapes stop it only moving deeper).
    float cast_mover(const Capsule& mover, Vec2 translation, const QueryFilter& filter) const;
    /// Calls visit for every shape within the mover slop of the capsule, with its plane.
    void collide_mover(const Capsule& mover, const QueryFilter& filter,
                       FunctionRef<void(int32_t shape, const MoverContact& contact)> visit) const;
    /// Calls visit(shape) for every shape but sensors that the filter sees and whose tight
    /// box overlaps box, in the trees' fixed order; visit returns false to stop.
    void visit_mover_shapes(const AABB& box, const QueryFilter& filter, FunctionRef<bool(int32_t shape)> visit) const;
    /// The shape's proxy placed where its body is.
    ShapeProxy placed_proxy(int32_t shape) const;

    /// The touching contacts of the body (of one of its shapes, unless shape is
    /// null_index) and the shapes visiting a sensor shape, as the last step left them
    /// (ContactSet::visit_touching, visit_sensor_visitors). They read only: allowed while
    /// the world is locked.
    void visit_touching_contacts(int32_t body, int32_t shape, FunctionRef<void(const ContactData&)> visit) const;
    void visit_sensor_overlaps(int32_t sensor, FunctionRef<void(int32_t visitor)> visit) const;

    // Drawing (world_draw.cpp).
    /// Hands the world's pictures to draw's sink, as its options ask (debug_draw.hpp). The
    /// world is locked while the sink runs, as for a query: it may read the world (and
    /// draw it again), never change it.
    void draw(const DebugDraw& draw) const;

    // Snapshots (snapshot/world_snapshot.cpp, snapshot_format.hpp).
    /// The bytes a full snapshot of the world takes now, its header included.
    std::size_t snapshot_size() const;
    /// Writes a full snapshot into [buffer, buffer + capacity); returns its size, or 0
    /// (having written nothing useful) when the capacity is short.
    std::size_t save_snapshot(void* buffer, std::size_t capacity) const;
    /// Replaces the world's state with a snapshot's, keeping its host wiring (workers,
    /// task callbacks, SIMD path, profiling); returns null, or what is wrong with the
    /// snapshot, and then the world is as it was.
    const char* restore_snapshot(const void* data, std::size_t size);
    /// A new world from a snapshot, with runtime's host wiring; null, with *problem set,
    /// when the snapshot is refused.
    static std::unique_ptr<World> from_snapshot(const void* data, std::size_t size, const WorldDef& runtime,
                                                const char** problem);
    /// Takes the state of a world loaded from a snapshot (which gets this one's), keeping
    /// this world's host wiring. Swaps containers only: cannot fail.
    void take_state_of(World& loaded) noexcept;

    // Rollback states (snapshot/rollback_state.cpp): what a step changes, for this world
    // while its structure (bodies, shapes, joints, chains, settings) stays as it was.
    /// The bytes a rollback state of the world takes now, its header included.
    std::size_t state_size() const;
    /// Writes a rollback state into [buffer, buffer + capacity); returns its size, or 0
    /// when the capacity is short.
    std::size_t save_state(void* buffer, std::size_t capacity) const;
    /// Brings the world back to a rollback state saved from it since its last structural
    /// change; returns null, or what is wrong with the state (then the world is as it was).
    /// A state the world did not save itself is checked as a snapshot is: its structure
    /// here, its values by `values_valid` (the C API's rules for its calls); when that
    /// says false, the state is refused as state_values_refused.
    const char* restore_state(const void* data, std::size_t size, FunctionRef<bool(const World&)> values_valid);
    // An array, not a pointer to a literal: one object, so its address tells it from other
    // problems (equal literals in two files need not share an address, and in Debug did not).
    static constexpr char state_values_refused[] = "it holds a value no call could have set";
    /// Changes with every structural change: a state saved before it is refused.
    uint64_t structure_version() const { return structure_version_; }

    // Recording (recording/world_recording.cpp): from here on, every public call above
    // that changes the world, and every step with the hash it produced, goes to `write`
    // (recording_format.hpp), after the header and a snapshot of the world as it is now.
    // The world is locked while `write` runs. Starting again replaces the writer.
    void start_recording(RecordWriter write, void* context);
    void stop_recording();
    bool is_recording() const { return recorder_ != nullptr; }

private:
    friend class QueryLock;
    friend class WorldProbe;  // the unit tests' window on the stages (tests/unit/world_fixture.hpp)

    // world_bodies.cpp
    void update_mass(int32_t body);
    void cover_step_ahead(float time_step);
    void mark_for_cover(int32_t body);
    bool accumulate(int32_t body, Vec2 force, float torque, bool wake);
    bool change_velocity(int32_t body, Vec2 dv, float dw, bool wake);
    bool prepare_to_receive(int32_t body, bool wake);
    // world_body_enable.cpp
    void disable_body(int32_t body);
    void enable_body(int32_t body);
    void leave_stages(int32_t body);
    void join_stages(int32_t body);
    // world_shapes.cpp
    int32_t attach_shape(int32_t body, const ShapeDef& def, const Geometry& geometry);
    void detach_shape(int32_t shape);
    void create_proxy(int32_t shape, bool query_now);
    // world_joints.cpp
    void link_joint(int32_t joint);
    void unlink_joint(int32_t joint);
    void link_joints(int32_t body);
    void unlink_joints(int32_t body);
    void let_bodies_meet(int32_t body_a, int32_t body_b);
    void forget_joint_impulses(int32_t body);
    // recording/world_recording.cpp
    void record_snapshot();
    // world_step.cpp
    void run_step(float time_step, int32_t substep_count);
    void report_falling_asleep(int32_t body);
    void quarantine_non_finite_bodies();
    void report_sensor_crossings();
    // world.cpp: the islands and the contact set hold no reference to each other; the
    // world hands each what the other changed.
    void follow_woken_bodies();
    void apply_link_changes();
    void destroy_contacts_of_shape(int32_t shape, bool only_filtered_out);
    void destroy_contacts_between(int32_t body_a, int32_t body_b);
    void visit_island_links(int32_t body, FunctionRef<void(int32_t other)> follow) const;
    // world_validate.cpp
    void validate_body(int32_t body) const;
    // snapshot/world_snapshot.cpp, snapshot/snapshot_checks.cpp
    template <class Io, class Self>
    static void transfer(Io& io, Self& world);
    template <class Io, class Self>
    static void transfer_stages(Io& io, Self& world);
    template <class Io, class Self>
    static void transfer_state(Io& io, Self& world);
    const char* load_state(const void* data, std::size_t size);
    std::size_t save_state_quietly(void* buffer, std::size_t capacity, uint64_t* checksum) const;
    bool saved_here(const SnapshotHeader& header, std::size_t size) const;
    void save_backup();
    void load_state_unchecked(const void* data, std::size_t size);
    const char* load_snapshot(const void* data, std::size_t size);
    /// What is wrong with a world just loaded from a snapshot, or null: whatever the step
    /// follows (lists, links, indices) leads where it should.
    const char* check_loaded() const;
    const char* check_loaded_islands(int32_t island_members) const;
    const char* check_loaded_island_links() const;
    const char* check_loaded_shapes() const;

    WorldDef settings_;
    Pool<Body> bodies_;
    Pool<Shape> shapes_;
    Pool<Chain> chains_;
    std::unique_ptr<WorldStages> stages_;
    std::vector<int32_t> to_cover_;  // bodies whose boxes must cover the next step afresh
    float covered_time_step_ = 0.0f;  // the time step the moving fat boxes were made for, s
    uint64_t serial_ = 0;             // this world's, unique in the process: a state names it
    uint64_t structure_version_ = 0;  // see structure_version()
    std::vector<unsigned char> rollback_backup_;  // the state a refused restore goes back to
    // The checksums and sizes of the last states this world saved: a state that matches
    // one is this world's own bytes, restored without the checks and the backup a
    // stranger's state needs (rollback_state.cpp).
    struct SavedStateMark {
        uint64_t checksum = 0, size = 0, structure_version = 0;
    };
    static constexpr int32_t saved_state_marks = 64;
    mutable SavedStateMark saved_states_[saved_state_marks];
    mutable int32_t next_saved_state_ = 0;
    std::unique_ptr<Recorder> recorder_;          // while recording: host wiring, kept by restores
    StepProfile profile_;
    void* user_data_ = nullptr;  // the host's, never read; not in snapshots
    mutable bool profiling_ = false;
    mutable int32_t lock_depth_ = 0;
    bool stepping_ = false;
    bool in_batch_ = false;
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
