// SPDX-License-Identifier: MIT
// ContactSet: every contact, the pair set that finds them, the awake contact list and the
// narrowphase that updates their manifolds.
//
// Design note: a contact exists while its shapes' fat boxes overlap; it is in the awake
// list while one of its bodies is awake, and only awake contacts are updated, so that a
// sleeping pile costs nothing. The narrowphase runs once per step, before the solver,
// and records what the islands need to hear: contacts that began or stopped linking two
// bodies (link_changes(), which the world hands to the islands), bodies asleep that
// something reached (islands_to_wake()). The set holds no reference to the islands: a
// call that must wake a body at once (a pair found beside sleeping bodies, a contact
// destroyed between steps) is handed the world's `wake` for that call. Touching, for
// events, describes where the step left the bodies: the solver reports it per contact at
// the end of the step, and end_step turns changes into begin and end events.
//
// The work is in five files: contact_set.cpp (creation, destruction, the awake list),
// contact_pairs.cpp (new pairs from the broadphase), narrowphase.cpp (manifolds and
// links), contact_events.cpp (the end of the step: events and parted pairs) and
// contact_data.cpp (what touches what, read between steps).
//
// Threads: the narrowphase and the pair queries are shared by the world's workers. A
// contact's update writes only the contact; what the islands must hear it leaves in a
// flag byte per awake contact, and the pairs each block of queries finds go to that
// block's list. One thread then reads the flags and the lists in order, so the results
// are the same for any number of workers.
#pragma once

#include <cstdint>
#include <vector>

#include "broadphase/broad_phase.hpp"
#include "core/function_ref.hpp"
#include "core/hash_set.hpp"
#include "core/pool.hpp"
#include "core/stage_runner.hpp"
#include "core/task_system.hpp"
#include "dynamics/constants.hpp"
#include "dynamics/body/body.hpp"
#include "dynamics/body/shape.hpp"
#include "dynamics/contact/contact.hpp"
#include "dynamics/contact/contact_hooks.hpp"
#include "dynamics/island/link_change.hpp"
#include "dynamics/step_context.hpp"
#include "dynamics/world/events.hpp"
#include "dynamics/world/world_def.hpp"

namespace i2d {

class JointSet;
class LoadIo;
class SaveIo;

/// Wakes a body (and its island) at once; the world's, handed to a call that needs it.
using WakeBody = FunctionRef<void(int32_t body)>;

class ContactSet {
public:
    ContactSet(const WorldDef& settings, Pool<Body>& bodies, const Pool<Shape>& shapes, const JointSet& joints,
               EventRecorder& events, TaskSystem& tasks, const ContactHooks& hooks)
        : settings_(settings),
          bodies_(bodies),
          shapes_(shapes),
          joints_(joints),
          events_(events),
          tasks_(tasks),
          hooks_(hooks) {}

    /// The contacts; the solver writes their impulses and touching flags at the end of
    /// a step (contact_solver.hpp), nothing else writes them from outside.
    Pool<Contact>& pool() { return pool_; }
    const Pool<Contact>& pool() const { return pool_; }
    const std::vector<int32_t>& awake() const { return awake_; }
    /// The awake solid contacts with points, in awake order, from this step's narrowphase
    /// on (bodies woken after it add theirs): all the solver colours. Most awake contacts
    /// of a tumbling heap have none, and need not be read again.
    const std::vector<int32_t>& solvable() const { return solvable_; }
    /// Changes whenever what the solver's colouring reads changes: the awake list, a
    /// contact's point count, its bodies' solver states, its material (whether any
    /// contact is elastic). Equal versions, equal colours.
    uint64_t layout_version() const { return layout_version_; }

    /// New pairs from the broadphase's moved proxies; pairs that may not collide (one
    /// body, two bodies that cannot move each other, two sensors, filters) get none. A
    /// pair found while both bodies sleep wakes them.
    void find_new_contacts(const StepContext& step, BroadPhase& broad_phase, WakeBody wake);
    /// The narrowphase over the awake contacts; the time step predicts how far bodies can
    /// approach. Afterwards islands_to_wake() says which sleeping islands were reached.
    void collide(const StepContext& step);
    const std::vector<int32_t>& islands_to_wake() const { return islands_to_wake_; }
    /// After the islands woke: contacts that gained or lost points join or leave islands
    /// (link_changes()).
    void update_links();
    /// Begin and end events from the touching flags the solver left, and destruction of
    /// the contacts whose fat boxes parted.
    void end_step(const StepContext& step);
    /// The links begun and ended since clear_link_changes(), in order: the world hands
    /// them to the islands.
    const std::vector<LinkChange>& link_changes() const { return link_changes_; }
    void clear_link_changes() { link_changes_.clear(); }

    /// Destroys the shape's contacts between steps (all, or those its filter now forbids),
    /// waking the bodies each touched.
    void destroy_contacts_of_shape(int32_t shape, bool only_filtered_out, WakeBody wake);
    /// Called between steps when a joint starts keeping two bodies apart.
    void destroy_contacts_between(int32_t body_a, int32_t body_b, WakeBody wake);
    /// The body's centre of mass moved within it (its shapes changed): its manifolds'
    /// anchors are stale and must be made afresh.
    void forget_manifolds(int32_t body);
    /// The shape's material, geometry or hit-event flag changed: its contacts mix the
    /// materials again and take the flag.
    void refresh_contacts_of_shape(int32_t shape);
    /// A body woke: its contacts join the awake list, with its new solver state.
    void body_woke(int32_t body);
    /// A body fell asleep: its contacts with nothing awake leave the awake list.
    void body_slept(int32_t body);
    /// Calls visit(contact, other_body) for each contact of the body; visit must not
    /// destroy contacts.
    template <class Visit>
    void visit_contacts(int32_t body, Visit&& visit) const {
        for (int32_t key = bodies_[body].head_contact_key; key != null_index;) {
            const Contact& c = pool_[contact_of_key(key)];
            const int32_t next = c.edges[edge_of_key(key)].next_key;
            visit(contact_of_key(key), c.edges[edge_of_key(key) ^ 1].body);
            key = next;
        }
    }
    /// The contact's manifold as it stands: world points where A's anchors are.
    Manifold manifold_of(const Contact& contact) const;
    /// Calls visit(other_body) for each contact that links the body into its island.
    template <class Visit>
    void visit_links(int32_t body, Visit&& visit) const {
        visit_contacts(body, [&](int32_t contact, int32_t other) {
            if (pool_[contact].flags & contact_island_link) {
                visit(other);
            }
        });
    }

    /// Touching contacts (sensors excluded) after the last step.
    int32_t touching_count() const;
    /// Calls visit for each touching contact between solid shapes of the body, or only
    /// those of its shape `shape` unless that is null_index, in the body's contact list
    /// order (contact_data.cpp). Reads only: callers may be inside a query's callback.
    void visit_touching(int32_t body, int32_t shape, FunctionRef<void(const ContactData&)> visit) const;
    /// Calls visit(visitor shape) for each visit of the sensor shape that began and has
    /// not ended as of the last step, in its body's contact list order.
    void visit_sensor_visitors(int32_t sensor, FunctionRef<void(int32_t visitor)> visit) const;
    void validate() const;

    // Snapshots (snapshot/stage_snapshots.cpp): the contacts and the awake list saved,
    // loaded (the pair set made again), or swapped with another set's loaded ones.
    void save(SaveIo& io) const;
    void load(LoadIo& io);
    void swap_state(ContactSet& other) noexcept;

private:
    // contact_set.cpp
    void create_contact(int32_t shape_a, int32_t shape_b, WakeBody wake);
    void destroy_contact(int32_t contact, bool during_step);
    void add_awake(int32_t contact);
    void remove_awake(int32_t contact);
    void mix_material(Contact& contact, const Shape& a, const Shape& b) const;
    bool is_awake(int32_t body) const { return bodies_[body].awake_index != null_index; }
    // snapshot/stage_snapshots.cpp
    void derive_shape_fields(LoadIo& io);
    // contact_pairs.cpp
    // A pair-finding stage's argument: its list of each block's pairs.
    struct PairStage {
        int32_t list = 0;  // 0 the self search, 1 the queries
        int32_t items_per_block = 1;
    };
    template <bool SelfSearch>
    static void pair_range(const StepContext& step, ContactSet& set, const PairStage& arg, int32_t begin, int32_t end,
                           int32_t worker);
    bool may_pair(int32_t shape_a, int32_t shape_b) const;
    // narrowphase.cpp
    static void collide_range(const StepContext& step, ContactSet& set, const NoStageArg&, int32_t begin, int32_t end,
                              int32_t worker);
    void prefetch_for_collide(int32_t k, int32_t count) const;
    uint8_t collide_one(int32_t k, const StepContext& step);
    bool recycle(Contact& contact, const Body& a, const Body& b, const Tolerances& tolerances) const;
    void update_contact(Contact& contact, const Shape& a, const Shape& b, const StepContext& step);
    bool pre_solve_refuses(const Contact& contact) const;
    uint8_t point_change_flags(const Contact& contact, bool had_points) const;
    template <auto F>
    void run_over_awake(const StepContext& step);
    // contact_events.cpp
    static void end_range(const StepContext& step, ContactSet& set, const NoStageArg&, int32_t begin, int32_t end,
                          int32_t worker);
    void report_touch_changes(const Contact& contact, bool touching_now);
    void report_hit(const Contact& contact);
    /// Contact events name the pair in shape order; sensor events name the sensor first.
    PendingEnd pair_of(const Contact& contact) const;
    ShapePairEvent event_of(const Contact& contact) const;

    const WorldDef& settings_;
    Pool<Body>& bodies_;
    const Pool<Shape>& shapes_;
    const JointSet& joints_;
    EventRecorder& events_;
    TaskSystem& tasks_;
    const ContactHooks& hooks_;
    Pool<Contact> pool_;
    HashSet pair_set_;  // pair_key of the shapes of every contact
    std::vector<int32_t> awake_;
    std::vector<int32_t> solvable_;
    uint64_t layout_version_ = 0;
    std::vector<LinkChange> link_changes_;
    // The pair search's scratch, kept so that a steady state allocates nothing: new pairs
    // per block of each stage ([0] the self search, [1] the queries), then all of one
    // stage's in order, and the broadphase being searched while the queries run.
    struct PairSearch {
        std::vector<std::vector<ShapePairCandidate>> block_pairs[2];
        std::vector<ShapePairCandidate> pairs, sort_scratch;
        BroadPhase* broad_phase = nullptr;
    };
    PairSearch search_;
    // Step scratch, kept so that a steady state allocates nothing.
    std::vector<int32_t> islands_to_wake_;
    std::vector<int32_t> point_changes_;  // contacts that gained or lost all their points
    // Per awake contact, what its update found for the islands (CollideFlags), and at
    // the end of the step what must happen to it (EndFlags).
    enum CollideFlags : uint8_t { layout_changed = 1, points_changed = 2, wakes_a = 4, wakes_b = 8, has_points = 16 };
    enum EndFlags : uint8_t { ends = 1, reports = 2, hits = 4 };
    std::vector<uint8_t> collide_flags_;
    std::vector<Stage> stages_;
    StageRunner runner_;
};

// One stage over the awake contacts, shared by the workers when there are enough.
template <auto F>
void ContactSet::run_over_awake(const StepContext& step) {
    const int32_t count = int32_t(awake_.size());
    const bool parallel = tasks_.worker_count() > 1 && count >= parallel_min_contacts;
    stages_.assign(1, make_stage<F>(*this, NoStageArg{}, count, tasks_.worker_count(), parallel, contacts_per_work_block));
    runner_.run(tasks_, stages_, parallel, &step);
}

}  // namespace i2d
