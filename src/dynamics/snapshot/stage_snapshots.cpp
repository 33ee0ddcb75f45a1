// SPDX-License-Identifier: MIT
// The step's stages saved and loaded (world_fields.hpp gives each struct's fields), and
// swapped into a world whole once a load has passed every check.
//
// A load checks what a stage can check alone (its own lists and counts); what joins the
// stages (a contact's bodies, a shape's proxy) is checked once everything is loaded
// (snapshot_checks.cpp). A stage's caches are not saved: they are made again from what
// is, and the same state makes the same caches.
#include "core/reserve.hpp"
#include "dynamics/contact/contact_set.hpp"
#include "dynamics/island/island.hpp"
#include "dynamics/joint/joint_set.hpp"
#include "dynamics/snapshot/world_fields.hpp"
#include "dynamics/solver/solver.hpp"

namespace i2d {

namespace {

// Room for one contact's fields (contact_fields writes under 200 bytes; the stage asserts it).
constexpr std::size_t contact_saved_bytes = 256;

// Each entry of an awake list is a live item that knows its place.
template <class T>
bool check_awake_list(LoadIo& io, const std::vector<int32_t>& list, const Pool<T>& pool, const char* problem) {
    int32_t awake_items = 0;
    for (int32_t i = 0; i < pool.capacity(); ++i) {
        awake_items += pool.is_live(i) && pool[i].awake_index != null_index ? 1 : 0;
    }
    if (!io.check(awake_items == int32_t(list.size()), problem)) {
        return false;
    }
    for (std::size_t k = 0; k < list.size(); ++k) {
        const int32_t item = list[k];
        if (!io.check(pool.is_live(item) && pool[item].awake_index == int32_t(k), problem)) {
            return false;
        }
    }
    return true;
}

}  // namespace

void JointSet::save(SaveIo& io) const {
    pool_.save(io, [](SaveIo& out, const Joint& j) { joint_fields(out, j, SnapshotPart::whole); });
}

void JointSet::load(LoadIo& io) {
    pool_.load(io, [](LoadIo& in, Joint& j) {
        joint_fields(in, j, SnapshotPart::whole);
        j.solver_index = null_index;  // set by each step's layout
    });
    ++version_;
}

void JointSet::swap_state(JointSet& other) noexcept {
    pool_.swap(other.pool_);
    ++version_;
    ++other.version_;
}

void ContactSet::save(SaveIo& io) const {
    pool_.save(io, [](SaveIo& out, const Contact& c) {
        save_staged<contact_saved_bytes>(out, [&c](auto& staged) { contact_fields(staged, c); });
    });
    list_fields(io, awake_, 0, "");
}

void ContactSet::load(LoadIo& io) {
    pool_.load(io, [](LoadIo& in, Contact& c) { contact_fields(in, c); });
    if (io.has_version(6)) {
        derive_shape_fields(io);
    }
    list_fields(io, awake_, Pool<Contact>::max_slots, "the awake contacts are more than the bytes left could hold");
    check_awake_list(io, awake_, pool_, "the awake contact list and the contacts disagree");
    pair_set_.clear();
    for (int32_t i = 0; i < pool_.capacity() && !io.failed(); ++i) {
        if (pool_.is_live(i)) {
            const Contact& c = pool_[i];
            io.check(c.shape_a >= 0 && c.shape_a < c.shape_b && pair_set_.insert(pair_key(c.shape_a, c.shape_b)),
                     "two contacts join the same shapes, or a contact's shapes are out of order");
        }
    }
    // Waking never allocates: room for every contact in the awake list.
    reserve_room(awake_, std::size_t(pool_.capacity()) + 1);
    solvable_.clear();
    link_changes_.clear();
    ++layout_version_;
}

// What format 6 leaves out because the shapes say it: each edge's body and the mixed
// material, for contacts whose shapes are there (check_loaded refuses the rest).
void ContactSet::derive_shape_fields(LoadIo& io) {
    for (int32_t i = 0; i < pool_.capacity() && !io.failed(); ++i) {
        if (!pool_.is_live(i)) {
            continue;
        }
        Contact& c = pool_[i];
        if (io.check(shapes_.is_live(c.shape_a) && shapes_.is_live(c.shape_b), "a contact names a missing shape")) {
            const Shape& a = shapes_[c.shape_a];
            const Shape& b = shapes_[c.shape_b];
            c.edges[0].body = a.body;
            c.edges[1].body = b.body;
            mix_material(c, a, b);
        }
    }
}

void ContactSet::swap_state(ContactSet& other) noexcept {
    pool_.swap(other.pool_);
    std::swap(pair_set_, other.pair_set_);
    awake_.swap(other.awake_);
    solvable_.swap(other.solvable_);
    link_changes_.clear();
    other.link_changes_.clear();
    ++layout_version_;
    ++other.layout_version_;
}

void Islands::save(SaveIo& io) const {
    islands_.save(io, [](SaveIo& out, const Island& island) { island_fields(out, island); });
    list_fields(io, awake_bodies_, 0, "");
    list_fields(io, awake_islands_, 0, "");
}

void Islands::load(LoadIo& io) {
    islands_.load(io, [](LoadIo& in, Island& island) { island_fields(in, island); });
    list_fields(io, awake_bodies_, Pool<Body>::max_slots, "the awake bodies are more than the bytes left could hold");
    list_fields(io, awake_islands_, Pool<Island>::max_slots, "the awake islands are more than the bytes left could hold");
    check_awake_list(io, awake_islands_, islands_, "the awake island list and the islands disagree");
    // Waking never allocates: room for every body and island in the awake lists.
    reserve_room(awake_bodies_, std::size_t(bodies_.capacity()) + 1);
    reserve_room(awake_islands_, std::size_t(islands_.capacity()) + 1);
    island_rest_.clear();
    woken_.clear();
    ++awake_version_;
}

void Islands::swap_state(Islands& other) noexcept {
    islands_.swap(other.islands_);
    awake_bodies_.swap(other.awake_bodies_);
    awake_islands_.swap(other.awake_islands_);
    island_rest_.clear();
    woken_.clear();
    ++awake_version_;
    ++other.awake_version_;
}

}  // namespace i2d
