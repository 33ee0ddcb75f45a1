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
//
// Islands hold no reference to the contacts or joints that link bodies: the contact set
// hands them its link changes as a list (LinkChange), the world passes the links to
// follow when an island is split (LinkVisitor), and the bodies whose island woke or fell
// asleep are told back (woken_bodies(), the `slept` callbacks) for the world to move
// their contacts in or out of the awake contact list.
#pragma once

#include <cstdint>
#include <vector>

#include "core/function_ref.hpp"
#include "core/pool.hpp"
#include "dynamics/body/body.hpp"
#include "dynamics/island/link_change.hpp"

namespace i2d {

class LoadIo;
class SaveIo;

/// Calls follow(other) for each body that a contact or joint links `body` to.
using LinkVisitor = FunctionRef<void(int32_t body, FunctionRef<void(int32_t other)> follow)>;

// Only whether an island lost links matters (it may be in pieces), so the count stops
// here: an island that never sleeps loses links for as long as it runs. Half the range,
// so that two islands' counts add without overflow when they merge.
constexpr int32_t max_removed_links = INT32_MAX / 2;

struct Island {
    int32_t head_body = null_index, tail_body = null_index;
    int32_t body_count = 0;
    int32_t link_count = 0;     // contacts and joints joining two of its bodies
    int32_t removed_links = 0;  // links lost since it was known to be connected, up to max_removed_links
    int32_t awake_index = null_index;  // in the awake island list; null while asleep
};

class Islands {
public:
    explicit Islands(Pool<Body>& bodies) : bodies_(bodies) {}

    /// A new kinematic or dynamic body: an island of its own, awake.
    void add_body(int32_t body);
    /// A body about to be freed or disabled, its contacts already destroyed (it is woken
    /// first).
    void remove_body(int32_t body);
    /// A contact began joining two awake dynamic bodies, or a joint two dynamic bodies.
    void link(int32_t body_a, int32_t body_b);
    /// A contact or joint that joined this body to another stopped doing so.
    void unlink(int32_t body);
    /// The contacts' link changes, in order.
    void apply(const std::vector<LinkChange>& changes);

    bool is_awake(int32_t body) const { return bodies_[body].awake_index != null_index; }
    /// Resets the body's rest timer and wakes its island.
    void wake_body(int32_t body);
    void wake_island(int32_t island);
    void wake_all();
    /// The bodies that joined the awake list since clear_woken(), in the order they did.
    const std::vector<int32_t>& woken_bodies() const { return woken_; }
    void clear_woken() { woken_.clear(); }
    /// Puts the body's island to sleep now (the API's sleep), split first if it may be in
    /// pieces, so that only what touches the body sleeps; slept(body) is called for each
    /// body that fell asleep, after they all left the awake list.
    template <class Slept>
    void sleep_island_of(int32_t body, LinkVisitor links, Slept&& slept);

    const Pool<Island>& pool() const { return islands_; }
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
    /// awake list, and slept(body) for each once its island has left it, island by island.
    template <class FellAsleep, class Slept>
    void sleep_rested_islands(float time_to_sleep, LinkVisitor links, FellAsleep&& fell_asleep, Slept&& slept);

    void validate() const;

    // Snapshots (snapshot/stage_snapshots.cpp): the islands and the awake lists saved,
    // loaded, or swapped with another's loaded ones.
    void save(SaveIo& io) const;
    void load(LoadIo& io);
    void swap_state(Islands& other) noexcept;

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
    void split(int32_t island, LinkVisitor links);
    void put_to_sleep(int32_t island);
    template <class Slept>
    void tell_slept(int32_t island, Slept&& slept) const {
        for (int32_t body = islands_[island].head_body; body != null_index; body = bodies_[body].island_next) {
            slept(body);
        }
    }

    Pool<Body>& bodies_;
    Pool<Island> islands_;
    std::vector<int32_t> awake_bodies_;
    std::vector<int32_t> awake_islands_;
    std::vector<float> island_rest_;
    uint64_t awake_version_ = 0;  // per awake island: its shortest body rest time, s
    std::vector<int32_t> woken_;
    // Scratch kept between steps so that sleeping and splitting allocate nothing.
    std::vector<int32_t> members_, stack_, island_pieces_, resting_;
};

template <class Slept>
void Islands::sleep_island_of(int32_t body, LinkVisitor links, Slept&& slept) {
    if (!is_awake(body)) {
        return;
    }
    int32_t island = bodies_[body].island;
    if (islands_[island].removed_links > 0) {
        split(island, links);
        island = bodies_[body].island;
    }
    put_to_sleep(island);
    tell_slept(island, slept);
}

template <class FellAsleep, class Slept>
void Islands::sleep_rested_islands(float time_to_sleep, LinkVisitor links, FellAsleep&& fell_asleep, Slept&& slept) {
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
        split(to_split, links);
        resting_.insert(resting_.end(), island_pieces_.begin(), island_pieces_.end());
    }
    for (const int32_t island : resting_) {
        for (int32_t body = islands_[island].head_body; body != null_index; body = bodies_[body].island_next) {
            fell_asleep(body);
        }
        put_to_sleep(island);
        tell_slept(island, slept);
    }
}

}  // namespace i2d
