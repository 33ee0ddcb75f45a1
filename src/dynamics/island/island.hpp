// SPDX-License-Identifier: MIT
// Islands: bodies that touch one another, kept from step to step, and sleep.
//
// Design note: every moving body belongs to an island, a list of bodies threaded through
// the bodies themselves. A solid contact with points between two dynamic bodies links
// their islands, and so does a joint between two dynamic bodies: they merge at once,
// the smaller into the larger. A link that goes (the contact separated, a contact or
// joint was destroyed) only counts against its island, which may now be
// in pieces; islands are split lazily, when one wants to sleep, at most one per step
// (Box2D v3 keeps its islands the same way). A pile that rests costs one search over its
// bodies when it falls asleep, where this engine used to run a union-find over every
// awake contact at every step. Static bodies belong to no island; kinematic bodies each
// keep an island of their own (they would chain everything they touch into one) but
// keep the islands they touch awake while they move.
//
// An island sleeps when every body in it has rested for time_to_sleep: its bodies leave
// the awake list (the solver's arrays) and their contacts with nothing awake leave the
// awake contact list, so that a sleeping pile costs nothing per step. The awake lists
// are dense and each item knows its place, so adding and removing are O(1).
#pragma once

#include <cstdint>
#include <vector>

#include "core/pool.hpp"
#include "dynamics/body/body.hpp"

namespace i2d {

class ContactSet;
class JointSet;

struct Island {
    int32_t head_body = null_index, tail_body = null_index;
    int32_t body_count = 0;
    int32_t link_count = 0;     // contacts joining two of its bodies
    int32_t removed_links = 0;  // links lost since it was known to be connected
    int32_t awake_index = null_index;  // in the awake island list; null while asleep
};

class Islands {
public:
    Islands(Pool<Body>& bodies, ContactSet& contacts, const JointSet& joints)
        : bodies_(bodies), contacts_(contacts), joints_(joints) {}

    /// A new kinematic or dynamic body: an island of its own, awake.
    void add_body(int32_t body);
    /// A body about to be freed, its contacts already destroyed.
    void remove_body(int32_t body);
    /// A contact began joining two awake dynamic bodies, or a joint two dynamic bodies.
    void link(int32_t body_a, int32_t body_b);
    /// A contact or joint that joined this body to another stopped doing so.
    void unlink(int32_t body);

    bool is_awake(int32_t body) const { return bodies_[body].awake_index != null_index; }
    /// Resets the body's rest timer and wakes its island.
    void wake_body(int32_t body);
    void wake_island(int32_t island);
    void wake_all();
    /// Puts the body's island to sleep now (the API's sleep), split first if it may be in
    /// pieces, so that only what touches the body sleeps.
    void sleep_island_of(int32_t body);

    /// Kinematic and dynamic bodies that are awake, each at its awake_index.
    const std::vector<int32_t>& awake_bodies() const { return awake_bodies_; }
    /// Changes whenever a body joins or leaves the awake list (and so whenever an awake
    /// index may have changed).
    uint64_t awake_version() const { return awake_version_; }
    int32_t sleeping_island_count() const { return islands_.count() - int32_t(awake_islands_.size()); }

    // Each step: every awake island starts out rested; each body that has not rested
    // long enough keeps its island awake (the shortest rest time wins); then resting
    // islands fall asleep.
    void begin_rest_times();
    void note_rest_time(int32_t body, float rest_time) { note_rest_time_in_slot(rest_slot(body), rest_time); }
    /// The same in two halves, for workers: the slot of the body's island (read only),
    /// then, on one thread, the note.
    int32_t rest_slot(int32_t body) const { return islands_[bodies_[body].island].awake_index; }
    void note_rest_time_in_slot(int32_t slot, float rest_time) {
        float& rest = island_rest_[std::size_t(slot)];
        rest = rest < rest_time ? rest : rest_time;
    }
    /// Puts islands that rested for time_to_sleep to sleep, splitting at most one;
    /// fell_asleep(body) is called for each body that falls asleep, before it leaves the
    /// awake list.
    template <class FellAsleep>
    void sleep_rested_islands(float time_to_sleep, FellAsleep&& fell_asleep);

    void validate() const;

private:
    void append_body(int32_t island, int32_t body);
    void detach_body(int32_t body);
    void add_awake_body(int32_t body);
    void remove_awake_body(int32_t body);
    void add_awake_island(int32_t island);
    void remove_awake_island(int32_t island);
    void merge(int32_t from, int32_t into);
    /// Splits a possibly disconnected island into its connected pieces, which are left in
    /// island_pieces_. The first piece keeps the island's slot.
    void split(int32_t island);
    void put_to_sleep(int32_t island);

    Pool<Body>& bodies_;
    ContactSet& contacts_;
    const JointSet& joints_;
    Pool<Island> islands_;
    std::vector<int32_t> awake_bodies_;
    std::vector<int32_t> awake_islands_;
    std::vector<float> island_rest_;
    uint64_t awake_version_ = 0;  // per awake island: its shortest body rest time, s
    // Scratch kept between steps so that sleeping and splitting allocate nothing.
    std::vector<int32_t> members_, stack_, island_pieces_, resting_;
};

template <class FellAsleep>
void Islands::sleep_rested_islands(float time_to_sleep, FellAsleep&& fell_asleep) {
    // Candidates first: sleeping reorders the awake island list. The one to split is the
    // largest that may be in pieces (the first such in list order on a tie).
    resting_.clear();
    int32_t to_split = null_index;
    for (std::size_t k = 0; k < awake_islands_.size(); ++k) {
        if (island_rest_[k] < time_to_sleep) {
            continue;
        }
        const int32_t island = awake_islands_[k];
        if (islands_[island].removed_links == 0) {
            resting_.push_back(island);
        } else if (to_split == null_index || islands_[island].body_count > islands_[to_split].body_count) {
            to_split = island;
        }
    }
    if (to_split != null_index) {
        split(to_split);
        resting_.insert(resting_.end(), island_pieces_.begin(), island_pieces_.end());
    }
    for (const int32_t island : resting_) {
        for (int32_t body = islands_[island].head_body; body != null_index; body = bodies_[body].island_next) {
            fell_asleep(body);
        }
        put_to_sleep(island);
    }
}

}  // namespace i2d
